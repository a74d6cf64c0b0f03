#include "geom/normalize.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geom/predicates.h"
#include "geom/union_sweep.h"

namespace taut::geom {

namespace {

using detail::RPoint;

struct CleanCounts {
  std::int64_t repeated = 0;
  std::int64_t collinear = 0;
};

bool straight(Point a, Point b, Point c) {  // b continues a -> c without turning
  return orient(a, b, c) == 0 && dot(a, b, b, c) > 0;
}

// Drops consecutive repeats and straight vertices (except those in `keep`, sorted).
Ring clean_ring(const Ring& ring, CleanCounts& counts, const std::vector<Point>* keep) {
  auto removable = [&](Point a, Point b, Point c) {
    return straight(a, b, c) && (keep == nullptr || !std::binary_search(keep->begin(), keep->end(), b));
  };
  Ring out;
  out.reserve(ring.size());
  for (Point p : ring) {
    if (!out.empty() && out.back() == p) {
      ++counts.repeated;
      continue;
    }
    while (out.size() >= 2 && removable(out[out.size() - 2], out.back(), p)) {
      out.pop_back();
      ++counts.collinear;
    }
    out.push_back(p);
  }
  while (out.size() >= 2 && out.back() == out.front()) {
    out.pop_back();
    ++counts.repeated;
  }
  bool changed = true;
  while (changed && out.size() >= 3) {
    changed = false;
    const std::size_t n = out.size();
    if (removable(out[n - 2], out[n - 1], out[0])) {
      out.pop_back();
      ++counts.collinear;
      changed = true;
    } else if (removable(out[n - 1], out[0], out[1])) {
      out.erase(out.begin());
      ++counts.collinear;
      changed = true;
    }
  }
  return out;
}

// Rotates to start at the smallest vertex; when it occurs more than once (a ring touching
// itself there), at the occurrence giving the lexicographically smallest sequence.
void rotate_canonical(Ring& ring) {
  if (ring.empty()) return;
  const Point m = *std::min_element(ring.begin(), ring.end());
  const std::size_t n = ring.size();
  std::size_t best = n;
  for (std::size_t i = 0; i < n; ++i) {
    if (ring[i] != m) continue;
    if (best == n) {
      best = i;
      continue;
    }
    for (std::size_t k = 0; k < n; ++k) {
      const Point a = ring[(i + k) % n], b = ring[(best + k) % n];
      if (a != b) {
        if (a < b) best = i;
        break;
      }
    }
  }
  std::rotate(ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(best), ring.end());
}

void orient_ring(Ring& ring, bool ccw) {
  const i128 a = twice_area(ring);
  if ((ccw && a < 0) || (!ccw && a > 0)) std::reverse(ring.begin(), ring.end());
}

Polygon canonical(const Polygon& polygon, CleanCounts& counts, const std::vector<Point>* keep) {
  Polygon out;
  out.outer = clean_ring(polygon.outer, counts, keep);
  orient_ring(out.outer, true);
  rotate_canonical(out.outer);
  for (const Ring& h : polygon.holes) {
    Ring r = clean_ring(h, counts, keep);
    orient_ring(r, false);
    rotate_canonical(r);
    out.holes.push_back(std::move(r));
  }
  std::sort(out.holes.begin(), out.holes.end());
  return out;
}

bool in_box(Point q, const Box& b) {
  return b.lo.x <= q.x && q.x <= b.hi.x && b.lo.y <= q.y && q.y <= b.hi.y;
}

Point direction(const Segment& s) { return {s.b.x - s.a.x, s.b.y - s.a.y}; }

// Replaces every rational vertex of a union ring by an integer point on the free side of both
// its edges (the rule in normalize.h). Returns the integer ring.
Ring round_ring(const detail::UnionRing& ring, const Box& domain, std::int64_t& rounded) {
  // Rational vertices where the ring goes straight on are simply dropped (same line).
  std::vector<RPoint> cur;
  std::vector<Segment> lines;
  const std::size_t n0 = ring.vertices.size();
  for (std::size_t i = 0; i < n0; ++i) {
    const Segment& in = ring.lines[(i + n0 - 1) % n0];
    const Segment& out = ring.lines[i];
    const Point din = direction(in), dout = direction(out);
    const bool straight_on = i64{din.x} * dout.y - i64{din.y} * dout.x == 0 &&
                             i64{din.x} * dout.x + i64{din.y} * dout.y > 0;
    if (!ring.vertices[i].is_integer() && straight_on) continue;
    cur.push_back(ring.vertices[i]);
    lines.push_back(out);  // the edge leaving this vertex lies on `out` until the next kept one
  }
  const std::size_t m = cur.size();
  if (m == 0) return {};
  std::size_t start = m;
  for (std::size_t i = 0; i < m && start == m; ++i)
    if (cur[i].is_integer()) start = i;
  for (std::size_t i = 0; i < m && start == m; ++i) {
    const Point din = direction(lines[(i + m - 1) % m]), dout = direction(lines[i]);
    if (i64{din.x} * dout.y - i64{din.y} * dout.x > 0) start = i;  // convex: domain side
  }
  if (start == m) start = 0;

  for (std::size_t k = 0; k < m; ++k) {
    const std::size_t i = (start + k) % m;
    if (cur[i].is_integer()) continue;
    const RPoint p = cur[i];
    const RPoint prev = cur[(i + m - 1) % m], next = cur[(i + 1) % m];
    const Segment& lin_prev = lines[(i + m - 1) % m];
    const Segment& lin_next = lines[i];
    bool outside_ok = false;  // the last resort below: q may leave the domain
    auto feasible = [&](Point q) {
      if (!outside_ok && !in_box(q, domain)) return false;
      // orient(prev, p, q) = orient(q, prev, p); orient(p, next, q) = orient(next, q, p).
      const int sp = prev.is_integer() ? detail::orient_sign(q, prev.floor(), p)
                                       : orientation(lin_prev.a, lin_prev.b, q);
      if (sp > 0) return false;
      const int sn = next.is_integer() ? detail::orient_sign(next.floor(), q, p)
                                       : orientation(lin_next.a, lin_next.b, q);
      return sn <= 0;
    };
    // Ranking among feasible points only (feasibility above is exact): the added region lies
    // within max(distance of q to the two edge lines) of the old ring, so minimise that, then
    // the distance to p. Long double is used for this ranking and nothing else.
    using ld = long double;
    const ld px = p.xi + static_cast<ld>(p.xf) / static_cast<ld>(p.d);
    const ld py = p.yi + static_cast<ld>(p.yf) / static_cast<ld>(p.d);
    auto line_dist = [&](ld ax, ld ay, ld bx, ld by, Point q) {
      const ld dx = bx - ax, dy = by - ay, len = std::sqrt(dx * dx + dy * dy);
      return len == 0 ? ld{0} : std::fabs(dx * (q.y - ay) - dy * (q.x - ax)) / len;
    };
    auto score = [&](Point q) {
      const ld d1 = prev.is_integer()
                        ? line_dist(prev.xi, prev.yi, px, py, q)
                        : line_dist(lin_prev.a.x, lin_prev.a.y, lin_prev.b.x, lin_prev.b.y, q);
      const ld d2 = next.is_integer()
                        ? line_dist(px, py, next.xi, next.yi, q)
                        : line_dist(lin_next.a.x, lin_next.a.y, lin_next.b.x, lin_next.b.y, q);
      const ld dp = std::hypot(q.x - px, q.y - py);
      return std::max(d1, d2) + dp * ld{1e-3};
    };
    auto search = [&](int radius, Point& best) {
      bool found = false;
      ld best_s = 0;
      for (int dx = -radius + 1; dx <= radius; ++dx)
        for (int dy = -radius + 1; dy <= radius; ++dy) {
          const i64 x = i64{p.xi} + dx, y = i64{p.yi} + dy;
          if (!in_range(x) || !in_range(y)) continue;
          const Point q{static_cast<Coord>(x), static_cast<Coord>(y)};
          if (!feasible(q)) continue;
          const ld sc = score(q);
          if (!found || sc < best_s || (sc == best_s && q < best)) {
            best = q;
            best_s = sc;
            found = true;
          }
        }
      return found;
    };
    Point q;
    bool ok = search(8, q);
    if (!ok) ok = search(32, q);
    if (!ok) {
      // A very thin free wedge: walk along its bisector to the first cell with a valid corner;
      // the wedge is about one unit wide there, so the growth stays that thin.
      auto unit_to = [&](ld x, ld y) {
        const ld dx = x - px, dy = y - py, len = std::hypot(dx, dy);
        return std::pair<ld, ld>{dx / len, dy / len};
      };
      const auto u1 = prev.is_integer() ? unit_to(prev.xi, prev.yi)
                                        : unit_to(lin_prev.a.x, lin_prev.a.y);
      const auto u2 = next.is_integer() ? unit_to(next.xi, next.yi)
                                        : unit_to(lin_next.b.x, lin_next.b.y);
      ld bx = u1.first + u2.first, by = u1.second + u2.second;
      const ld bl = std::hypot(bx, by);
      if (bl > 0) {
        bx /= bl, by /= bl;
        for (i64 t = 8; !ok && t < (i64{1} << 22); t += 1 + t / 64) {
          const ld sx = px + bx * static_cast<ld>(t), sy = py + by * static_cast<ld>(t);
          if (std::fabs(sx) > kMaxCoord || std::fabs(sy) > kMaxCoord) break;
          ld best_s = 0;
          for (int cx = 0; cx <= 1; ++cx)
            for (int cy = 0; cy <= 1; ++cy) {
              const Point c{static_cast<Coord>(std::floor(sx)) + cx, static_cast<Coord>(std::floor(sy)) + cy};
              if (!in_range(c.x) || !in_range(c.y) || !feasible(c)) continue;
              const ld sc = score(c);
              if (!ok || sc < best_s) q = c, best_s = sc, ok = true;
            }
        }
      }
    }
    if (!ok && prev.is_integer() && feasible(prev.floor())) q = prev.floor(), ok = true;
    if (!ok && next.is_integer() && feasible(next.floor())) q = next.floor(), ok = true;
    for (int radius = 64; !ok && radius <= 512; radius *= 2) ok = search(radius, q);
    // Last resort: a vertex so near the domain side that the free wedge beyond it leaves the
    // domain before it holds a lattice point (a sharp spike tip pointing at the side). q may
    // then lie outside the domain: the next union pass clips the grown ring to the domain box,
    // and the vertices that leaves on the side are rounded along the side (their wedge holds
    // the side's lattice points), so the ring still only grows and ends inside the domain.
    if (!ok) {
      outside_ok = true;
      ok = search(8, q) || search(32, q);
      for (int radius = 64; !ok && radius <= 512; radius *= 2) ok = search(radius, q);
    }
    if (!ok) throw std::logic_error("normalize_obstacles: no integer point to round a vertex to");
    cur[i] = detail::to_rpoint(q);
    ++rounded;
  }
  Ring out;
  for (const RPoint& v : cur)
    if (out.empty() || out.back() != v.floor()) out.push_back(v.floor());
  while (out.size() >= 2 && out.back() == out.front()) out.pop_back();
  return out;
}

}  // namespace

Polygon normalize_polygon(const Polygon& polygon) {
  CleanCounts counts;
  return canonical(polygon, counts, nullptr);
}

NormalizedObstacles normalize_obstacles(std::span<const Polygon> inputs,
                                        std::optional<Box> boundary) {
  std::vector<const Polygon*> at(inputs.size());
  for (std::size_t i = 0; i < inputs.size(); ++i) at[i] = &inputs[i];
  return normalize_obstacle_refs(at, boundary);
}

NormalizedObstacles normalize_obstacle_refs(std::span<const Polygon* const> inputs,
                                            std::optional<Box> boundary) {
  NormalizedObstacles result;
  NormalizeStats& st = result.stats;
  st.input_polygons = static_cast<std::int64_t>(inputs.size());

  // Inputs as loops with the inside on the left: shells counter-clockwise, holes clockwise.
  std::vector<detail::Loop> loops;
  CleanCounts counts;
  bool any = false;
  Point lo{kMaxCoord, kMaxCoord}, hi{-kMaxCoord, -kMaxCoord};
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    st.input_vertices += static_cast<std::int64_t>(inputs[i]->outer.size());
    for (const Ring& h : inputs[i]->holes) st.input_vertices += static_cast<std::int64_t>(h.size());
    Polygon p = canonical(*inputs[i], counts, nullptr);
    if (p.outer.size() < 3 || twice_area(p.outer) == 0) continue;
    for (Point v : p.outer) {
      lo = {std::min(lo.x, v.x), std::min(lo.y, v.y)};
      hi = {std::max(hi.x, v.x), std::max(hi.y, v.y)};
      any = true;
    }
    loops.push_back({std::move(p.outer), static_cast<std::int64_t>(i)});
    for (Ring& h : p.holes)
      if (h.size() >= 3) loops.push_back({std::move(h), static_cast<std::int64_t>(i)});
  }
  st.removed_repeated = counts.repeated;
  st.removed_collinear = counts.collinear;
  if (boundary) {
    result.domain = *boundary;
  } else if (any) {
    auto grow = [](Coord v, i64 by) {
      return static_cast<Coord>(std::clamp<i64>(v + by, -kMaxCoord, kMaxCoord));
    };
    result.domain = {{grow(lo.x, -kDomainMargin), grow(lo.y, -kDomainMargin)},
                     {grow(hi.x, kDomainMargin), grow(hi.y, kDomainMargin)}};
  }

  // Union passes: round rational vertices outward and union again until none is left.
  std::vector<std::vector<std::size_t>> src;  // per component of the last pass
  detail::UnionResult u;
  for (int pass = 0;; ++pass) {
    if (pass == 32) throw std::logic_error("normalize_obstacles: rounding did not settle");
    u = detail::union_loops(loops, result.domain);
    ++st.passes;
    if (pass == 0) st.crossings = u.proper_crossings;
    std::vector<std::vector<std::size_t>> next_src(u.components);
    for (const auto& [tag, c] : u.tag_components) {
      if (pass == 0) {
        next_src[c].push_back(static_cast<std::size_t>(tag));
      } else {
        const auto& s = src[static_cast<std::size_t>(tag)];
        next_src[c].insert(next_src[c].end(), s.begin(), s.end());
      }
    }
    for (auto& s : next_src) {
      std::sort(s.begin(), s.end());
      s.erase(std::unique(s.begin(), s.end()), s.end());
    }
    src = std::move(next_src);
    if (u.rational_vertices == 0) break;
    loops.clear();
    for (const auto& ring : u.rings) {
      Ring r = round_ring(ring, result.domain, st.rounded);
      if (r.size() >= 3) loops.push_back({std::move(r), ring.component});
    }
  }

  // Assemble obstacles: one counter-clockwise shell and its clockwise holes per component.
  std::vector<Polygon> polys(u.components);
  std::vector<int> shells(u.components, 0);
  for (const auto& ring : u.rings) {
    Ring r;
    r.reserve(ring.vertices.size());
    for (const RPoint& v : ring.vertices) r.push_back(v.floor());
    const i128 a = twice_area(r);
    if (a > 0) {
      polys[ring.component].outer = std::move(r);
      ++shells[ring.component];
    } else {
      polys[ring.component].holes.push_back(std::move(r));
    }
  }
  std::vector<std::size_t> order;
  for (int c = 0; c < u.components; ++c) {
    if (shells[c] != 1) throw std::logic_error("normalize_obstacles: component without one shell");
    std::vector<Point> all, keep;
    all.insert(all.end(), polys[c].outer.begin(), polys[c].outer.end());
    for (const Ring& h : polys[c].holes) all.insert(all.end(), h.begin(), h.end());
    std::sort(all.begin(), all.end());
    for (std::size_t i = 0; i + 1 < all.size(); ++i)
      if (all[i] == all[i + 1] && (keep.empty() || keep.back() != all[i])) keep.push_back(all[i]);
    CleanCounts ignored;
    polys[c] = canonical(polys[c], ignored, &keep);
    order.push_back(static_cast<std::size_t>(c));
  }
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return polys[a].outer < polys[b].outer; });
  for (std::size_t c : order) {
    st.output_vertices += static_cast<std::int64_t>(polys[c].outer.size());
    for (const Ring& h : polys[c].holes) st.output_vertices += static_cast<std::int64_t>(h.size());
    if (!src[c].empty()) st.merges += static_cast<std::int64_t>(src[c].size()) - 1;
    result.obstacles.push_back(std::move(polys[c]));
    result.sources.push_back(std::move(src[c]));
  }
  st.output_obstacles = static_cast<std::int64_t>(result.obstacles.size());
  return result;
}

namespace {
// cut_beyond's ring: empty when the ring lies strictly beyond a side of d.
Ring cut_ring_beyond(const Ring& ring, const Box& d) {
  Ring r = ring;
  for (int side = 0; side < 4; ++side) {
    const std::size_t n = r.size();
    if (n < 4) break;  // a triangle has no run of three
    auto beyond = [&](Point p) {
      switch (side) {
        case 0: return p.x < d.lo.x;
        case 1: return p.x > d.hi.x;
        case 2: return p.y < d.lo.y;
        default: return p.y > d.hi.y;
      }
    };
    std::vector<char> b(n);
    std::size_t count = 0;
    for (std::size_t i = 0; i < n; ++i) count += b[i] = beyond(r[i]);
    if (count == n) return {};
    if (count < 3) continue;
    Ring out;
    out.reserve(n);
    for (std::size_t i = 0; i < n; ++i)
      if (!(b[i] && b[(i + n - 1) % n] && b[(i + 1) % n])) out.push_back(r[i]);
    if (out.size() == n) continue;
    if (sign(twice_area(out)) != sign(twice_area(r))) continue;  // keep this side's run
    r = std::move(out);
  }
  return r;
}
}  // namespace

bool cut_leaves(const Polygon& polygon, const Box& d) {
  return std::all_of(polygon.outer.begin(), polygon.outer.end(), [&](Point p) { return in_box(p, d); });
}

bool cut_beyond(Polygon& polygon, const Box& d) {
  if (cut_leaves(polygon, d)) return true;
  Ring outer = cut_ring_beyond(polygon.outer, d);
  if (outer.empty()) return false;
  polygon.outer = std::move(outer);
  std::vector<Ring> holes;
  for (const Ring& h : polygon.holes)
    if (Ring c = cut_ring_beyond(h, d); !c.empty()) holes.push_back(std::move(c));
  polygon.holes = std::move(holes);
  return true;
}

std::vector<Polygon> square_grown(std::span<const Polygon> polygons, Coord r) {
  if (r < 0) throw std::invalid_argument("square_grown: negative r");
  std::vector<Polygon> out;
  auto corner = [r](Point p, int sx, int sy) {
    const std::int64_t x = std::int64_t{p.x} + sx * std::int64_t{r}, y = std::int64_t{p.y} + sy * std::int64_t{r};
    if (!in_range(x) || !in_range(y)) throw std::domain_error("a blockage grown by its clearance passes the coordinate limit");
    return Point{static_cast<Coord>(x), static_cast<Coord>(y)};
  };
  for (const Polygon& poly : polygons) {
    out.push_back(poly);
    if (r == 0) continue;
    std::vector<const Ring*> rings{&poly.outer};
    for (const Ring& h : poly.holes) rings.push_back(&h);
    for (const Ring* ring : rings)
      for (std::size_t i = 0; i < ring->size(); ++i) {
        const Point a = (*ring)[i], b = (*ring)[(i + 1) % ring->size()];
        std::vector<Point> pts;
        for (Point p : {a, b})
          for (int sx : {-1, 1})
            for (int sy : {-1, 1}) pts.push_back(corner(p, sx, sy));
        out.push_back(Polygon{convex_hull(std::move(pts)), {}});
      }
  }
  return out;
}

Polygon domain_frame(const Box& d) {
  const Box g{{d.lo.x - 1, d.lo.y - 1}, {d.hi.x + 1, d.hi.y + 1}};
  Polygon frame;
  frame.outer = {g.lo, {g.hi.x, g.lo.y}, g.hi, {g.lo.x, g.hi.y}};
  frame.holes.push_back({d.lo, {d.lo.x, d.hi.y}, d.hi, {d.hi.x, d.lo.y}});
  return frame;
}

Box grown_box(const Box& b, std::int64_t r) {
  auto c = [](std::int64_t v) { return static_cast<Coord>(std::clamp<std::int64_t>(v, -kMaxCoord, kMaxCoord)); };
  return {{c(std::int64_t{b.lo.x} - r), c(std::int64_t{b.lo.y} - r)}, {c(std::int64_t{b.hi.x} + r), c(std::int64_t{b.hi.y} + r)}};
}

Box bounding_box(std::span<const Point> pts) {
  Box b{pts[0], pts[0]};
  for (const Point p : pts) {
    b.lo.x = std::min(b.lo.x, p.x), b.lo.y = std::min(b.lo.y, p.y);
    b.hi.x = std::max(b.hi.x, p.x), b.hi.y = std::max(b.hi.y, p.y);
  }
  return b;
}

Box clipped_box(Box w, const Box& dom) {
  w.lo.x = std::max(w.lo.x, dom.lo.x), w.lo.y = std::max(w.lo.y, dom.lo.y);
  w.hi.x = std::min(w.hi.x, dom.hi.x), w.hi.y = std::min(w.hi.y, dom.hi.y);
  return w;
}

Ring convex_hull(std::vector<Point> pts) {
  // monotone chain, exact
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() < 3) return pts;
  std::vector<Point> hull(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t j = 0; j < pts.size(); ++j) {
    while (k >= 2 && orient(hull[k - 2], hull[k - 1], pts[j]) <= 0) --k;
    hull[k++] = pts[j];
  }
  for (std::size_t j = pts.size() - 1, t = k + 1; j-- > 0;) {
    while (k >= t && orient(hull[k - 2], hull[k - 1], pts[j]) <= 0) --k;
    hull[k++] = pts[j];
  }
  hull.resize(k - 1);
  return hull;
}

Ring square_grown_segment(Point a, Point b, Coord r) {
  if (r < 0) throw std::invalid_argument("square_grown_segment: negative r");
  std::vector<Point> pts;
  for (Point p : {a, b})
    for (int sx : {-1, 1})
      for (int sy : {-1, 1}) {
        const std::int64_t x = std::int64_t{p.x} + sx * std::int64_t{r}, y = std::int64_t{p.y} + sy * std::int64_t{r};
        if (!in_range(x) || !in_range(y)) throw std::domain_error("a wire grown by its clearance passes the coordinate limit");
        pts.push_back({static_cast<Coord>(x), static_cast<Coord>(y)});
      }
  return convex_hull(std::move(pts));
}

namespace {

std::int64_t floor_div(std::int64_t n, std::int64_t d) {  // d > 0
  return n >= 0 ? n / d : -((-n + d - 1) / d);
}

// The convex polygon c (counter-clockwise, integer) intersected with the closed box r (lo <= hi),
// rounded outward along r's sides, as the hull of integer points (see convex_minus_box).
Ring clip_rounded(const Ring& c, std::int64_t x0, std::int64_t x1, std::int64_t y0, std::int64_t y1) {
  if (x0 > x1 || y0 > y1) return {};
  std::vector<Point> pts;
  auto inside_box = [&](std::int64_t x, std::int64_t y) { return x >= x0 && x <= x1 && y >= y0 && y <= y1; };
  for (const Point p : c)
    if (inside_box(p.x, p.y)) pts.push_back(p);
  // the box's corners inside c
  for (const std::int64_t x : {x0, x1})
    for (const std::int64_t y : {y0, y1}) {
      const Point q{static_cast<Coord>(x), static_cast<Coord>(y)};
      bool in = true;
      for (std::size_t i = 0; i < c.size() && in; ++i) in = orient(c[i], c[(i + 1) % c.size()], q) >= 0;
      if (in) pts.push_back(q);
    }
  // c's edges crossing the box's side lines strictly between their ends
  for (std::size_t i = 0; i < c.size(); ++i) {
    const Point a = c[i], b = c[(i + 1) % c.size()];
    for (const std::int64_t x : {x0, x1}) {
      if (!((a.x < x && x < b.x) || (b.x < x && x < a.x))) continue;
      const std::int64_t num = std::int64_t{a.y} * (b.x - a.x) + std::int64_t{b.y - a.y} * (x - a.x);  // y * (b.x - a.x)
      std::int64_t den = b.x - a.x, n = num;
      if (den < 0) den = -den, n = -n;
      const std::int64_t lo = floor_div(n, den), hi = lo + (lo * den == n ? 0 : 1);
      if (lo >= y0 && hi <= y1)  // the exact point is on the box's side (y0, y1 integer)
        for (const std::int64_t y : {lo, hi}) pts.push_back({static_cast<Coord>(x), static_cast<Coord>(y)});
    }
    for (const std::int64_t y : {y0, y1}) {
      if (!((a.y < y && y < b.y) || (b.y < y && y < a.y))) continue;
      const std::int64_t num = std::int64_t{a.x} * (b.y - a.y) + std::int64_t{b.x - a.x} * (y - a.y);
      std::int64_t den = b.y - a.y, n = num;
      if (den < 0) den = -den, n = -n;
      const std::int64_t lo = floor_div(n, den), hi = lo + (lo * den == n ? 0 : 1);
      if (lo >= x0 && hi <= x1)
        for (const std::int64_t x : {lo, hi}) pts.push_back({static_cast<Coord>(x), static_cast<Coord>(y)});
    }
  }
  return convex_hull(std::move(pts));
}

}  // namespace

std::vector<Ring> convex_minus_box(const Ring& convex, Box s) {
  std::int64_t cx0 = kMaxCoord, cx1 = -kMaxCoord, cy0 = kMaxCoord, cy1 = -kMaxCoord;
  for (const Point p : convex) {
    cx0 = std::min<std::int64_t>(cx0, p.x), cx1 = std::max<std::int64_t>(cx1, p.x);
    cy0 = std::min<std::int64_t>(cy0, p.y), cy1 = std::max<std::int64_t>(cy1, p.y);
  }
  // Does c meet the open box? Its closure does when c is not on the outer closed side of a
  // box side; then the interiors meet unless c touches the box only along its boundary, which
  // the clipped parts below decide anyway (they are c itself then, up to hull order).
  if (s.lo.x >= cx1 || s.hi.x <= cx0 || s.lo.y >= cy1 || s.hi.y <= cy0) return {convex};
  std::vector<Ring> out;
  auto keep = [&](Ring r) {
    if (r.size() >= 3) out.push_back(std::move(r));
  };
  keep(clip_rounded(convex, cx0, s.lo.x, cy0, cy1));                                                 // left
  keep(clip_rounded(convex, s.hi.x, cx1, cy0, cy1));                                                 // right
  const std::int64_t mx0 = std::max<std::int64_t>(cx0, s.lo.x), mx1 = std::min<std::int64_t>(cx1, s.hi.x);
  keep(clip_rounded(convex, mx0, mx1, cy0, s.lo.y));                                                 // below
  keep(clip_rounded(convex, mx0, mx1, s.hi.y, cy1));                                                 // above
  return out;
}

std::optional<Ring> octilinear_convex_ring(const Ring& in) {
  // without repeated vertices and vertices where the ring runs straight on
  Ring r;
  for (const Point p : in)
    if (r.empty() || !(r.back() == p)) r.push_back(p);
  while (r.size() > 1 && r.front() == r.back()) r.pop_back();
  for (bool changed = true; changed && r.size() >= 3;) {
    changed = false;
    for (std::size_t i = 0; i < r.size() && r.size() >= 3; ++i) {
      const Point a = r[(i + r.size() - 1) % r.size()], b = r[i], c = r[(i + 1) % r.size()];
      if (orientation(a, b, c) != 0) continue;
      if (dot(a, b, b, c) <= 0) return std::nullopt;  // a spike: not convex
      r.erase(r.begin() + static_cast<std::ptrdiff_t>(i));
      changed = true;
      break;
    }
  }
  if (r.size() < 3) return std::nullopt;
  int turn = 0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Point a = r[i], b = r[(i + 1) % r.size()], c = r[(i + 2) % r.size()];
    const std::int64_t dx = std::int64_t{b.x} - a.x, dy = std::int64_t{b.y} - a.y;
    if (dx != 0 && dy != 0 && dx != dy && dx != -dy) return std::nullopt;
    const int o = orientation(a, b, c);
    if (turn != 0 && o != turn) return std::nullopt;
    turn = o;
  }
  if (turn < 0) std::reverse(r.begin(), r.end());
  return r;
}

namespace {

// The convex polygon c (counter-clockwise, integer) intersected with the closed convex polygon t
// (counter-clockwise, integer vertices, every edge horizontal, vertical or at 45 degrees), each
// crossing of c's edges with t's edges at a non-integer point replaced by its two integer
// neighbours along t's edge, as the hull of those points (see convex_minus_pad).
Ring clip_octilinear_rounded(const Ring& c, const Ring& t) {
  using i128 = __int128;
  auto inside = [](const Ring& r, Point q) {
    for (std::size_t i = 0; i < r.size(); ++i)
      if (orient(r[i], r[(i + 1) % r.size()], q) < 0) return false;
    return true;
  };
  std::vector<Point> pts;
  for (const Point p : c)
    if (inside(t, p)) pts.push_back(p);
  for (const Point p : t)
    if (inside(c, p)) pts.push_back(p);
  for (std::size_t j = 0; j < t.size(); ++j) {
    const Point P = t[j], Q = t[(j + 1) % t.size()];
    const std::int64_t ex = std::int64_t{Q.x} - P.x, ey = std::int64_t{Q.y} - P.y;
    const std::int64_t len = std::max(std::abs(ex), std::abs(ey));  // in unit lattice steps u
    const std::int64_t ux = ex / len, uy = ey / len;
    for (std::size_t i = 0; i < c.size(); ++i) {
      const Point a = c[i], b = c[(i + 1) % c.size()];
      const std::int64_t dx = std::int64_t{b.x} - a.x, dy = std::int64_t{b.y} - a.y;
      const i128 den = i128{ux} * dy - i128{uy} * dx;  // cross(u, b - a)
      if (den == 0) continue;  // parallel: their common points are vertices, taken above
      // P + s u on the line of ab: s = cross(a - P, b - a) / cross(u, b - a)
      i128 num = i128{std::int64_t{a.x} - P.x} * dy - i128{std::int64_t{a.y} - P.y} * dx;
      i128 d = den;
      if (d < 0) d = -d, num = -num;
      if (num <= 0 || num >= i128{len} * d) continue;  // not strictly inside t's edge
      // and within ab: the crossing's side of P's line along ab's normal (orientation tests)
      const int oP = orientation(a, b, P), oQ = orientation(a, b, Q);
      if (oP == oQ) continue;
      const int oa = orientation(P, Q, a), ob = orientation(P, Q, b);
      if (oa != 0 && oa == ob) continue;
      const i128 lo = num / d;  // floor (num > 0)
      const i128 hi = lo * d == num ? lo : lo + 1;
      for (const i128 k : {lo, hi})
        pts.push_back({static_cast<Coord>(P.x + k * ux), static_cast<Coord>(P.y + k * uy)});
    }
  }
  return convex_hull(std::move(pts));
}

}  // namespace

std::vector<Ring> convex_minus_pad(const Ring& convex, const Ring& pad) {
  std::vector<Ring> out = convex_minus_box(convex, bounding_box(pad));
  // the corners of the box that the pad's 45-degree edges cut off
  for (std::size_t i = 0; i < pad.size(); ++i) {
    const Point a = pad[i], b = pad[(i + 1) % pad.size()];
    if (a.x == b.x || a.y == b.y) continue;
    Point corner{a.x, b.y};
    if (orient(a, b, corner) >= 0) corner = {b.x, a.y};  // the one right of a -> b (outside)
    Ring tri = clip_octilinear_rounded(convex, Ring{a, corner, b});
    if (tri.size() >= 3) out.push_back(std::move(tri));
  }
  return out;
}

}  // namespace taut::geom
