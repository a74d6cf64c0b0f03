// Polygon validity. One pass over candidate edge pairs from a packed R-tree decides, exactly,
// self-intersections of each ring and how rings meet each other; the relations between rings
// (hole inside shell, holes disjoint, interior connected) then follow from the recorded
// intersections plus one point location per ring pair (see the argument in check_relations).
#include "geom/validate.h"

#include <algorithm>
#include <boost/geometry/index/rtree.hpp>
#include <map>
#include <numeric>
#include <set>
#include <string>

#include "geom/bg.h"
#include "geom/predicates.h"

namespace taut::geom {
namespace {

namespace bgi = boost::geometry::index;

std::string str(Point p) { return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")"; }
std::string ring_name(int r) { return r < 0 ? std::string("outer ring") : "hole " + std::to_string(r); }

struct RingData {
  int id = -1;                 // -1 outer, k hole k
  std::vector<Point> v;        // vertices without consecutive repeats
  bool usable = false;         // passed 0001/0002/0007: its edges are indexed
  bool simple = false;         // usable and no 0003/0004
  // Smallest intersecting non-adjacent edge pair (by position) and how many there are.
  std::size_t bad_i = 0, bad_j = 0, bad_count = 0;
  SegmentIntersection bad_kind = SegmentIntersection::None;
};

// How the boundaries of two rings meet.
struct PairData {
  bool cross = false;          // a Proper crossing or an Overlap
  Segment cross_a, cross_b;    // the first such edge pair
  std::vector<Point> touches;  // distinct touch points, at most 2 kept
};

void add(std::vector<PolygonProblem>& out, const char* code, std::string message, int ring) {
  out.push_back({code, std::move(message), ring});
}

// Checks that need only the ring itself (0007, 0001, 0002, 0004). Fills r.v and r.usable.
void check_alone(const Ring& ring, RingData& r, std::vector<PolygonProblem>& out) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    if (!in_range(ring[i].x) || !in_range(ring[i].y)) {
      add(out, "GEOM-0007",
          ring_name(r.id) + ": coordinate out of range at vertex " + std::to_string(i) + " " +
              str(ring[i]) + " (|v| must be <= " + std::to_string(kMaxCoord) + ")",
          r.id);
      return;
    }
  }
  for (Point p : ring)
    if (r.v.empty() || r.v.back() != p) r.v.push_back(p);
  while (r.v.size() > 1 && r.v.back() == r.v.front()) r.v.pop_back();
  // Fewer than 3 distinct vertices: every vertex is v[0] or one other point.
  const auto other = std::find_if(r.v.begin(), r.v.end(), [&](Point p) { return p != r.v[0]; });
  const bool two_or_less =
      other == r.v.end() ||
      std::all_of(r.v.begin(), r.v.end(), [&](Point p) { return p == r.v[0] || p == *other; });
  if (two_or_less) {
    add(out, "GEOM-0001", ring_name(r.id) + " has fewer than 3 distinct vertices", r.id);
    return;
  }
  const Point a = r.v[0], b = *other;
  if (std::all_of(r.v.begin(), r.v.end(), [&](Point p) { return orientation(a, b, p) == 0; })) {
    add(out, "GEOM-0002",
        ring_name(r.id) + " has zero area: all vertices lie on the line through " + str(a) +
            " and " + str(b),
        r.id);
    return;
  }
  r.usable = true;
  r.simple = true;
  const std::size_t n = r.v.size();
  std::size_t spikes = 0;
  Point first{};
  for (std::size_t k = 0; k < n; ++k) {
    const Point p = r.v[(k + n - 1) % n], q = r.v[k], s = r.v[(k + 1) % n];
    if (orientation(p, q, s) == 0 && dot(p, q, q, s) < 0) {
      if (spikes++ == 0) first = q;
    }
  }
  if (spikes > 0) {
    r.simple = false;
    add(out, "GEOM-0004",
        ring_name(r.id) + " has a spike at " + str(first) + ": the boundary turns back on itself" +
            (spikes > 1 ? " (" + std::to_string(spikes) + " spikes)" : ""),
        r.id);
  }
}

// The intersection point of two segments that Touch or Overlap: an endpoint on the other one.
Point common_point(const Segment& s, const Segment& t) {
  if (on_segment(s.a, t.a, t.b)) return s.a;
  if (on_segment(s.b, t.a, t.b)) return s.b;
  if (on_segment(t.a, s.a, s.b)) return t.a;
  return t.b;
}

std::string describe(const Segment& s, const Segment& t, SegmentIntersection k) {
  std::string m = "edges " + str(s.a) + "-" + str(s.b) + " and " + str(t.a) + "-" + str(t.b);
  switch (k) {
    case SegmentIntersection::Proper: return m + " cross";
    case SegmentIntersection::Touch: return m + " touch at " + str(common_point(s, t));
    default: return m + " overlap from " + str(common_point(s, t));
  }
}

using Tree = bgi::rtree<std::pair<Box, std::uint32_t>, bgi::rstar<16>>;

struct Edges {
  std::vector<Segment> seg;
  std::vector<std::int32_t> ring;  // index into rings (0 = outer, k + 1 = hole k)
  std::vector<std::uint32_t> pos;  // position in the ring
  Tree tree;
};

Box box_of(const Segment& s) {
  return {{std::min(s.a.x, s.b.x), std::min(s.a.y, s.b.y)}, {std::max(s.a.x, s.b.x), std::max(s.a.y, s.b.y)}};
}

// Crossing-number location of p in the shell, visiting only the shell edges the R-tree finds
// on the horizontal ray from p to the right (the only ones that can cross it or contain p).
Location locate_in_shell(const Tree& shell, const std::vector<Segment>& seg, Point p, Coord max_x) {
  std::vector<std::pair<Box, std::uint32_t>> found;
  shell.query(bgi::intersects(Box{p, {max_x, p.y}}), std::back_inserter(found));
  bool inside = false;
  for (const auto& [b, id] : found) {
    const Point a = seg[id].a, c = seg[id].b;
    if (on_segment(p, a, c)) return Location::Boundary;
    if ((a.y > p.y) != (c.y > p.y)) {
      const int o = orientation(a, c, p);
      if ((c.y > a.y) ? (o > 0) : (o < 0)) inside = !inside;
    }
  }
  return inside ? Location::Inside : Location::Outside;
}

struct UnionFind {
  std::vector<std::size_t> parent;
  std::size_t find(std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  bool unite(std::size_t a, std::size_t b) {  // false when already connected (a cycle)
    a = find(a);
    b = find(b);
    if (a == b) return false;
    parent[a] = b;
    return true;
  }
};

std::vector<PolygonProblem> validate(const Ring& outer, const std::vector<Ring>& holes) {
  std::vector<PolygonProblem> out;
  std::vector<RingData> rings(1 + holes.size());
  for (std::size_t k = 0; k < rings.size(); ++k) {
    rings[k].id = static_cast<int>(k) - 1;
    check_alone(k == 0 ? outer : holes[k - 1], rings[k], out);
  }

  // Index the edges of every usable ring.
  Edges e;
  Coord max_x = -kMaxCoord;
  std::vector<std::pair<Box, std::uint32_t>> values;
  for (std::size_t k = 0; k < rings.size(); ++k) {
    if (!rings[k].usable) continue;
    const auto& v = rings[k].v;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const Segment s{v[i], v[(i + 1) % v.size()]};
      values.emplace_back(box_of(s), static_cast<std::uint32_t>(e.seg.size()));
      e.seg.push_back(s);
      e.ring.push_back(static_cast<std::int32_t>(k));
      e.pos.push_back(static_cast<std::uint32_t>(i));
      max_x = std::max(max_x, v[i].x);
    }
  }
  e.tree = Tree(values.begin(), values.end());  // packed construction
  // The shell's edges alone, for locating hole vertices in the shell without visiting holes.
  const std::size_t shell_edges = rings[0].usable ? rings[0].v.size() : 0;
  const Tree shell_tree(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(shell_edges));
  values = {};

  std::map<std::pair<int, int>, PairData> pairs;
  std::vector<std::pair<Box, std::uint32_t>> found;
  // Visit edges in the tree's leaf order: consecutive queries then touch the same nodes.
  for (const auto& [box_i, i] : e.tree) {
    found.clear();
    e.tree.query(bgi::intersects(box_i), std::back_inserter(found));
    for (const auto& [b, j] : found) {
      if (j <= i) continue;
      const Segment& s = e.seg[i];
      const Segment& t = e.seg[j];
      if (e.ring[i] == e.ring[j]) {
        RingData& r = rings[e.ring[i]];
        const std::size_t n = r.v.size(), pi = e.pos[i], pj = e.pos[j];
        const bool adjacent = (pi + 1) % n == pj || (pj + 1) % n == pi;
        if (adjacent) continue;  // they share a vertex; overlapping is a spike (0004)
        const SegmentIntersection k = intersect(s, t);
        if (k == SegmentIntersection::None) continue;
        const auto [lo, hi] = std::minmax(pi, pj);
        if (r.bad_count++ == 0 || std::pair(lo, hi) < std::pair(r.bad_i, r.bad_j)) {
          r.bad_i = lo;
          r.bad_j = hi;
          r.bad_kind = k;
        }
        continue;
      }
      const SegmentIntersection k = intersect(s, t);
      if (k == SegmentIntersection::None) continue;
      const auto key = std::minmax(e.ring[i], e.ring[j]);
      PairData& pd = pairs[{key.first, key.second}];
      if (k == SegmentIntersection::Touch) {
        const Point q = common_point(s, t);
        if (pd.touches.size() < 2 && std::find(pd.touches.begin(), pd.touches.end(), q) == pd.touches.end())
          pd.touches.push_back(q);
      } else if (!pd.cross) {
        pd.cross = true;
        pd.cross_a = s;
        pd.cross_b = t;
      }
    }
  }
  for (RingData& r : rings) {
    if (r.bad_count == 0) continue;
    r.simple = false;
    const std::size_t n = r.v.size();
    const Segment s{r.v[r.bad_i], r.v[(r.bad_i + 1) % n]}, t{r.v[r.bad_j], r.v[(r.bad_j + 1) % n]};
    add(out, "GEOM-0003",
        ring_name(r.id) + " intersects itself: " + describe(s, t, r.bad_kind) +
            (r.bad_count > 1 ? " (" + std::to_string(r.bad_count) + " intersecting edge pairs)" : ""),
        r.id);
  }

  // Relations between simple rings. For rings A, B whose boundaries neither cross nor overlap
  // and touch in at most one point T, boundary(B) minus T is connected and misses boundary(A),
  // so it lies wholly inside or wholly outside A: one vertex of B other than T decides.
  // Two or more touch points either cut the interior or let B pass outside through vertices;
  // both are invalid, so they are reported without further analysis.
  std::vector<std::pair<int, Point>> single_touches;  // (ring slot, point) for the cycle test
  auto sample = [&](const RingData& r, const PairData* pd) {
    for (Point p : r.v)
      if (!pd || pd->touches.empty() || p != pd->touches[0]) return p;
    return r.v[0];  // unreachable: a usable ring has >= 3 distinct vertices
  };
  auto find_pair = [&](int a, int b) -> const PairData* {
    const auto it = pairs.find({a, b});
    return it == pairs.end() ? nullptr : &it->second;
  };
  const bool shell_ok = rings[0].simple;
  for (std::size_t h = 1; h < rings.size() && shell_ok; ++h) {
    if (!rings[h].simple) continue;
    const int id = rings[h].id;
    const PairData* pd = find_pair(0, static_cast<int>(h));
    if (pd && pd->cross) {
      add(out, "GEOM-0005",
          "hole " + std::to_string(id) + " crosses its shell: " +
              describe(pd->cross_b, pd->cross_a, intersect(pd->cross_b, pd->cross_a)),
          id);
    } else if (pd && pd->touches.size() >= 2) {
      add(out, "GEOM-0005",
          "hole " + std::to_string(id) + " meets its shell at " + str(pd->touches[0]) + " and " +
              str(pd->touches[1]) + " (a hole may touch its shell at one point only)",
          id);
    } else {
      const Point p = sample(rings[h], pd);
      if (locate_in_shell(shell_tree, e.seg, p, max_x) == Location::Outside) {
        add(out, "GEOM-0005",
            "hole " + std::to_string(id) + " is not inside its shell: vertex " + str(p) +
                " lies outside",
            id);
      } else if (pd && pd->touches.size() == 1) {
        single_touches.emplace_back(0, pd->touches[0]);
        single_touches.emplace_back(static_cast<int>(h), pd->touches[0]);
      }
    }
  }
  // Hole pairs: candidates are holes with overlapping bounding boxes.
  std::vector<std::pair<Box, std::uint32_t>> hole_boxes;
  for (std::size_t h = 1; h < rings.size(); ++h) {
    if (!rings[h].simple) continue;
    Box b{rings[h].v[0], rings[h].v[0]};
    for (Point p : rings[h].v) {
      b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y)};
      b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y)};
    }
    hole_boxes.emplace_back(b, static_cast<std::uint32_t>(h));
  }
  const Tree hole_tree(hole_boxes.begin(), hole_boxes.end());
  for (const auto& [box, h1] : hole_boxes) {
    found.clear();
    hole_tree.query(bgi::intersects(box), std::back_inserter(found));
    std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
    for (const auto& [box2, h2] : found) {
      if (h2 <= h1) continue;
      const std::string names = "holes " + std::to_string(h1 - 1) + " and " + std::to_string(h2 - 1);
      const int id = static_cast<int>(h2) - 1;
      const PairData* pd = find_pair(static_cast<int>(h1), static_cast<int>(h2));
      if (pd && pd->cross) {
        add(out, "GEOM-0006",
            names + " cross: " + describe(pd->cross_a, pd->cross_b, intersect(pd->cross_a, pd->cross_b)), id);
        continue;
      }
      if (pd && pd->touches.size() >= 2) {
        add(out, "GEOM-0006",
            names + " touch at " + str(pd->touches[0]) + " and " + str(pd->touches[1]) +
                " (holes may touch at one point only)",
            id);
        continue;
      }
      const Point p1 = sample(rings[h1], pd), p2 = sample(rings[h2], pd);
      if (locate(p1, std::span<const Point>(rings[h2].v)) == Location::Inside) {
        add(out, "GEOM-0006", "hole " + std::to_string(h1 - 1) + " lies inside hole " + std::to_string(id), id);
      } else if (locate(p2, std::span<const Point>(rings[h1].v)) == Location::Inside) {
        add(out, "GEOM-0006", "hole " + std::to_string(id) + " lies inside hole " + std::to_string(h1 - 1), id);
      } else if (pd && pd->touches.size() == 1) {
        single_touches.emplace_back(static_cast<int>(h1), pd->touches[0]);
        single_touches.emplace_back(static_cast<int>(h2), pd->touches[0]);
      }
    }
  }
  // Interior connectivity (OGC): in the bipartite graph rings -- touch points, a cycle means
  // some part of the interior is enclosed by touching rings and cut off from the rest.
  std::sort(single_touches.begin(), single_touches.end());
  single_touches.erase(std::unique(single_touches.begin(), single_touches.end()), single_touches.end());
  std::map<Point, std::size_t> point_node;
  for (const auto& st : single_touches) point_node.emplace(st.second, rings.size() + point_node.size());
  UnionFind uf;
  uf.parent.resize(rings.size() + point_node.size());
  std::iota(uf.parent.begin(), uf.parent.end(), std::size_t{0});
  for (const auto& [r, p] : single_touches) {
    if (!uf.unite(static_cast<std::size_t>(r), point_node[p])) {
      add(out, "GEOM-0008",
          "the polygon's interior is disconnected: the shell and holes touching at " + str(p) +
              " enclose part of it",
          rings[r].id);
      break;
    }
  }
  return out;
}

}  // namespace

std::vector<PolygonProblem> validate_ring(const Ring& ring) { return validate(ring, {}); }

std::vector<PolygonProblem> validate_polygon(const Polygon& polygon) {
  return validate(polygon.outer, polygon.holes);
}

}  // namespace taut::geom
