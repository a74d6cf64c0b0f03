// The L1 geodesic Voronoi diagram (router/voronoi.h): the shortest path map's pieces of each
// site, joined by cancelling shared boundary, exactly.
#include "router/voronoi.h"

#include <algorithm>
#include <map>
#include <optional>
#include <stdexcept>
#include <tuple>

namespace taut::router {
namespace {

using Int = boost::multiprecision::mpz_int;

Rational cross(const RPoint& o, const RPoint& a, const RPoint& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// The supporting line of a segment: the primitive integer direction u (u.x > 0, or u.x == 0
// and u.y > 0) and the offset n . p with n = (-u.y, u.x).
struct LineKey {
  Int ux, uy;
  Rational offset;
  bool operator<(const LineKey& o) const { return std::tie(ux, uy, offset) < std::tie(o.ux, o.uy, o.offset); }
};

// Direction of p -> q as the line's key, +1 when it runs along u and -1 against it.
std::pair<LineKey, int> line_of(const RPoint& p, const RPoint& q) {
  const Rational dx = q.x - p.x, dy = q.y - p.y;
  const Int l = boost::multiprecision::lcm(denominator(dx), denominator(dy));
  Int ix = numerator(dx) * (l / denominator(dx)), iy = numerator(dy) * (l / denominator(dy));
  const Int g = boost::multiprecision::gcd(abs(ix), abs(iy));
  ix /= g;
  iy /= g;
  int sign = 1;
  if (ix < 0 || (ix == 0 && iy < 0)) {
    ix = -ix;
    iy = -iy;
    sign = -1;
  }
  LineKey k{ix, iy, Rational(-iy) * p.x + Rational(ix) * p.y};
  return {std::move(k), sign};
}

// Counter-clockwise angle class of v seen from reference r: smaller is first going ccw from r
// (r itself first).
bool ccw_before(const RPoint& r, const RPoint& u, const RPoint& v) {
  auto half = [&](const RPoint& w) {
    const Rational c = r.x * w.y - r.y * w.x, d = r.x * w.x + r.y * w.y;
    return (c > 0 || (c == 0 && d > 0)) ? 0 : 1;
  };
  const int hu = half(u), hv = half(v);
  if (hu != hv) return hu < hv;
  return u.x * v.y - u.y * v.x > 0;
}

bool in_bbox(const RPoint& p, const RPoint& a, const RPoint& b) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

// 1 inside, 0 on the boundary, -1 outside.
int where(const std::vector<RPoint>& ring, const RPoint& p) {
  bool in = false;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const RPoint &a = ring[i], &b = ring[(i + 1) % n];
    if (cross(a, b, p) == 0 && in_bbox(p, a, b)) return 0;
    if ((a.y > p.y) != (b.y > p.y)) {
      // p.x < x of the edge at p.y, without dividing by a negative
      const Rational lhs = (p.x - a.x) * (b.y - a.y), rhs = (p.y - a.y) * (b.x - a.x);
      if (b.y > a.y ? lhs < rhs : lhs > rhs) in = !in;
    }
  }
  return in ? 1 : -1;
}

struct Bounds {
  Rational x0, y0, x1, y1;
  explicit Bounds(const std::vector<RPoint>& r) : x0(r[0].x), y0(r[0].y), x1(r[0].x), y1(r[0].y) {
    for (const RPoint& p : r) {
      x0 = std::min(x0, p.x);
      y0 = std::min(y0, p.y);
      x1 = std::max(x1, p.x);
      y1 = std::max(y1, p.y);
    }
  }
  bool contains(const RPoint& p) const { return x0 <= p.x && p.x <= x1 && y0 <= p.y && p.y <= y1; }
};

// The boundary of the union of one site's pieces, as directed segments (region on the left).
std::vector<std::pair<RPoint, RPoint>> boundary(const std::vector<const L1Map::Piece*>& pieces) {
  struct Mark {
    Rational tau;
    int delta;
    RPoint at;
  };
  std::map<LineKey, std::vector<Mark>> lines;
  for (const L1Map::Piece* piece : pieces) {
    const auto& ring = piece->ring;
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      const RPoint &p = ring[i], &q = ring[(i + 1) % n];
      auto [key, sign] = line_of(p, q);
      const Rational tp = Rational(key.ux) * p.x + Rational(key.uy) * p.y;
      const Rational tq = Rational(key.ux) * q.x + Rational(key.uy) * q.y;
      auto& marks = lines[std::move(key)];
      // Along u the segment starts at the smaller parameter.
      if (sign > 0) {
        marks.push_back({tp, +1, p});
        marks.push_back({tq, -1, q});
      } else {
        marks.push_back({tq, -1, q});
        marks.push_back({tp, +1, p});
      }
    }
  }
  std::vector<std::pair<RPoint, RPoint>> out;
  for (auto& [key, marks] : lines) {
    std::sort(marks.begin(), marks.end(), [](const Mark& a, const Mark& b) { return a.tau < b.tau; });
    // Coverage between consecutive parameters; a +1 stretch runs along u, -1 against it.
    int cover = 0;
    std::optional<RPoint> start;
    int start_cover = 0;
    for (std::size_t i = 0; i < marks.size();) {
      std::size_t j = i;
      const Rational& tau = marks[i].tau;
      const RPoint at = marks[i].at;
      int next = cover;
      for (; j < marks.size() && marks[j].tau == tau; ++j) next += marks[j].delta;
      // marks at one parameter: delta of +1 for a segment starting along u, and so on; a
      // segment against u contributes -1 where it starts (its larger end) and +1 where it ends.
      if (next != cover) {
        if (start) out.push_back(start_cover > 0 ? std::pair{*start, at} : std::pair{at, *start});
        start.reset();
        if (next != 0) {
          if (next > 1 || next < -1) throw std::logic_error("voronoi: pieces of one site overlap");
          start = at;
          start_cover = next;
        }
        cover = next;
      }
      i = j;
    }
    if (cover != 0) throw std::logic_error("voronoi: unbalanced boundary");
  }
  return out;
}

}  // namespace

std::vector<VoronoiRegion> l1_voronoi(const L1Map& map) {
  std::vector<L1Map::Piece> pieces = map.pieces(L1Map::Detail::BySource);
  // A shape site's region holds the shape itself (distance 0 there): one more piece each.
  const auto shapes = map.shape_sources();
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    L1Map::Piece p;
    for (const geom::Point v : shapes[k].outer) p.ring.push_back({Rational(v.x), Rational(v.y)});
    p.source = map.shape_source_index(k);
    p.root = shapes[k].outer[0];
    pieces.push_back(std::move(p));
  }
  return l1_voronoi(pieces);
}

std::vector<VoronoiRegion> l1_voronoi(std::span<const L1Map::Piece> pieces) {
  std::map<std::size_t, std::vector<const L1Map::Piece*>> by_site;
  for (const L1Map::Piece& p : pieces) by_site[p.source].push_back(&p);
  std::vector<VoronoiRegion> out;
  for (const auto& [site, mine] : by_site) {
    VoronoiRegion region;
    region.site = site;
    for (const L1Map::Piece* p : mine) region.area += twice_signed_area(p->ring);
    region.area /= 2;
    const auto segs = boundary(mine);
    // Link into rings: at a vertex, leave by the first outgoing segment clockwise from the way
    // back (the sharpest left turn), so a region touching itself at a point gives two rings.
    std::map<RPoint, std::vector<std::size_t>> leaving;
    for (std::size_t i = 0; i < segs.size(); ++i) leaving[segs[i].first].push_back(i);
    std::vector<bool> used(segs.size(), false);
    std::vector<std::vector<RPoint>> outers, holes;
    for (std::size_t s0 = 0; s0 < segs.size(); ++s0) {
      if (used[s0]) continue;
      std::vector<RPoint> ring;
      std::size_t s = s0;
      while (!used[s]) {
        used[s] = true;
        ring.push_back(segs[s].first);
        const RPoint& at = segs[s].second;
        const RPoint back{segs[s].first.x - at.x, segs[s].first.y - at.y};
        auto it = leaving.find(at);
        if (it == leaving.end()) throw std::logic_error("voronoi: a boundary segment leads nowhere");
        std::size_t best = segs.size();
        RPoint best_dir;
        for (std::size_t c : it->second) {
          const RPoint dir{segs[c].second.x - at.x, segs[c].second.y - at.y};
          // first clockwise from `back` = last counter-clockwise from it
          if (best == segs.size() || ccw_before(back, best_dir, dir)) {
            best = c;
            best_dir = dir;
          }
        }
        if (used[best] && best != s0) throw std::logic_error("voronoi: boundary rings cross");
        s = best;
      }
      if (s != s0) throw std::logic_error("voronoi: a boundary ring closes off its start");
      // Drop vertices where the ring goes straight on (two segments of one line meeting at a
      // vertex of another site's boundary).
      std::vector<RPoint> clean;
      for (std::size_t i = 0, n = ring.size(); i < n; ++i)
        if (cross(ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n]) != 0) clean.push_back(ring[i]);
      const Rational a2 = twice_signed_area(clean);
      if (a2 > 0)
        outers.push_back(std::move(clean));
      else if (a2 < 0)
        holes.push_back(std::move(clean));
      else
        throw std::logic_error("voronoi: a boundary ring without area");
    }
    std::vector<Rational> outer_area;
    std::vector<Bounds> outer_box;
    for (const auto& o : outers) {
      outer_area.push_back(twice_signed_area(o));
      outer_box.emplace_back(o);
    }
    for (const auto& o : outers) region.polygons.push_back({o, {}});
    for (auto& h : holes) {
      std::size_t owner = outers.size();
      if (outers.size() == 1) {
        owner = 0;
      } else {
        // A test point on the hole that lies on no candidate's boundary: the middle of one of
        // its edges (a hole shares no stretch of boundary with an outer ring of its site).
        for (std::size_t e = 0; e < h.size() && owner == outers.size(); ++e) {
          const RPoint mid{(h[e].x + h[(e + 1) % h.size()].x) / 2, (h[e].y + h[(e + 1) % h.size()].y) / 2};
          bool touches = false;
          std::size_t best = outers.size();
          for (std::size_t o = 0; o < outers.size() && !touches; ++o) {
            if (!outer_box[o].contains(mid)) continue;
            const int w = where(outers[o], mid);
            if (w == 0) touches = true;
            if (w == 1 && (best == outers.size() || outer_area[o] < outer_area[best])) best = o;
          }
          if (!touches) owner = best;
        }
      }
      if (owner == outers.size()) throw std::logic_error("voronoi: a hole lies in no outer ring");
      region.polygons[owner].holes.push_back(std::move(h));
    }
    out.push_back(std::move(region));
  }
  return out;
}

}  // namespace taut::router
