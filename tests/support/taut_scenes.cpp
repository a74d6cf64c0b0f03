#include "support/taut_scenes.h"

#include <algorithm>
#include <cmath>
#include <deque>

#include "geom/predicates.h"
#include "support/random_shapes.h"

namespace taut::test {

using geom::Point;

Scenery setup(const geom::Box& domain, const std::vector<geom::Polygon>& obstacles) {
  Scenery s;
  s.t = geom::triangulate_free_space(domain, obstacles);
  if (s.t.ok()) s.tight = std::make_unique<router::Tightener>(s.t);
  return s;
}

unsigned step_mask(const geom::LatticeDirections& set) {
  unsigned m = 0;
  for (const Point s : set.steps())
    for (unsigned k = 0; k < 8; ++k) m |= (s == LatticeSteps::kSteps[k]) ? 1u << k : 0u;
  return m;
}

namespace {

// The 0-1 BFS of fewest_bends_any_length (a to b) and fewest_bends_closed (closed: x to x, the
// first step kept in the state for the closing turn).
int lattice_bends_bfs(const oracle::L1Reference& ref, const oracle::HomotopyWords& h, const geom::Box& D, Point a,
                      Point b, const std::vector<int>& word, int cap, unsigned steps, bool closed) {
  LatticeSteps ls{ref, h, D, {}, {}};
  using State = std::tuple<Point, int, int, std::vector<int>>;  // point, last step, first step (closed), word
  std::map<State, int> dist;
  std::deque<std::pair<State, int>> queue;
  for (int d = 0; d < 8; ++d) {
    if (!((steps >> d) & 1)) continue;
    const auto& st = ls.step(a, d);
    if (!st.first) continue;
    const Point q{a.x + LatticeSteps::kSteps[d].x, a.y + LatticeSteps::kSteps[d].y};
    State s{q, d, closed ? d : -1, st.second};
    if (dist.emplace(s, 0).second) queue.emplace_back(std::move(s), 0);
  }
  while (!queue.empty()) {
    auto [s, c] = std::move(queue.front());
    queue.pop_front();
    if (dist.at(s) < c) continue;
    const auto& [p, dir, first, w] = s;
    // closed: back at x with a turn there that stays in one free wedge (or none)
    if (p == b && w == word && (!closed || dir == first || ls.turn_ok(b, dir, first))) return c;
    for (int d = 0; d < 8; ++d) {
      if (!((steps >> d) & 1)) continue;
      if ((d + 2) % 4 == dir % 4 && (d >= 4) == (dir >= 4)) continue;  // no reversal
      const int nc = c + (d != dir);
      if (nc > cap) continue;
      const auto& st = ls.step(p, d);
      if (!st.first || !ls.turn_ok(p, dir, d)) continue;
      const Point q{p.x + LatticeSteps::kSteps[d].x, p.y + LatticeSteps::kSteps[d].y};
      State n{q, d, first, LatticeSteps::append(w, st.second)};
      auto [it, fresh] = dist.emplace(n, nc);
      if (!fresh && it->second <= nc) continue;
      it->second = nc;
      if (nc == c) queue.emplace_front(std::move(n), nc);
      else queue.emplace_back(std::move(n), nc);
    }
  }
  return -1;
}

}  // namespace

int fewest_bends_any_length(const oracle::L1Reference& ref, const oracle::HomotopyWords& h, const geom::Box& D, Point a,
                            Point b, const std::vector<int>& word, int cap, unsigned steps) {
  if (a == b) return word.empty() ? 0 : -1;
  return lattice_bends_bfs(ref, h, D, a, b, word, cap, steps, false);
}

int fewest_bends_closed(const oracle::L1Reference& ref, const oracle::HomotopyWords& h, const geom::Box& D, Point x,
                        const std::vector<int>& word, int cap, unsigned steps) {
  return lattice_bends_bfs(ref, h, D, x, x, word, cap, steps, true);
}

std::optional<TautSketch> taut_sketch(Sketcher& sk, const router::Tightener& tight, int legs, bool loops) {
  TautSketch r{sk.walk(legs), {}};
  if (loops) sk.add_loops(r.sketch);
  if (r.sketch.size() < 2 || r.sketch.front() == r.sketch.back()) return std::nullopt;
  r.taut = tight.tighten(r.sketch);
  if (r.taut.status != router::TightenStatus::Ok) return std::nullopt;
  return r;
}

std::optional<TautLoop> taut_loop(Sketcher& sk, const router::Tightener& tight, bool loops) {
  TautLoop r{sk.walk(3 + static_cast<int>(sk.rng() % 4)), {}};
  if (r.loop.size() < 2) return std::nullopt;
  if (loops) sk.add_loops(r.loop);
  if (!sk.ref.visible(r.loop.back(), r.loop.front())) return std::nullopt;
  r.loop.push_back(r.loop.front());
  if (r.loop.size() < 4) return std::nullopt;
  r.taut = tight.tighten_loop(r.loop);
  if (r.taut.status != router::TightenStatus::Ok || r.taut.contractible) return std::nullopt;
  return r;
}

SquareLoop square_loop() {
  SquareLoop r{judge(normalized({{0, 0}, {100, 100}}, {rect(40, 40, 60, 60)})),
               {{20, 50}, {50, 10}, {90, 50}, {50, 90}, {20, 50}},
               {},
               {}};
  if (!r.j || !r.j->st.t.ok()) return r;
  r.taut = r.j->st.tight->tighten_loop(r.once);
  r.cyclic = cyclic_word(r.j->h.word(r.once));
  return r;
}

std::vector<Point> single_wedge_points(const oracle::L1Reference& ref, int N) {
  std::vector<Point> pts;
  for (int x = 0; x <= N; ++x)
    for (int y = 0; y <= N; ++y)
      if (ref.is_free({x, y}) && ref.wedges_at({x, y}).size() == 1) pts.push_back({x, y});
  return pts;
}

router::StaircaseBuilder many_slabs(const Scene& sc) {
  router::StaircaseOptions so;
  so.first_slab = 1;
  return router::StaircaseBuilder(sc.domain, sc.obstacles, so);
}

std::unique_ptr<Judged> judge(const Scene& sc) {
  auto j = std::make_unique<Judged>(sc);
  if (!j->ref.problems().empty()) return nullptr;
  return j;
}

geom::Polygon poly(std::vector<Point> r) {
  if (geom::twice_area(r) < 0) std::reverse(r.begin(), r.end());
  return {r, {}};
}

std::vector<geom::Polygon> degenerate_scene(std::mt19937& rng, int kind, int N) {
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  std::vector<geom::Polygon> out;
  const geom::Box dom{{0, 0}, {N, N}};
  if (kind == 0) return random_triangles(rng, dom, 4);
  if (kind == 1) {  // rects touching at corners / edges plus a triangle
    int x0 = uni(1, N - 5), y0 = uni(1, N - 5);
    int w = uni(1, 3), hh = uni(1, 3);
    out.push_back(rect(x0, y0, x0 + w, y0 + hh));
    for (int i = 0; i < uni(1, 3); ++i) {
      int c = uni(0, 3);
      int w2 = uni(1, 3), h2 = uni(1, 3);
      int cx = (c & 1) ? x0 + w : x0, cy = (c & 2) ? y0 + hh : y0;
      int nx = (c & 1) ? cx : cx - w2, ny = (c & 2) ? cy : cy - h2;
      if (nx < 0 || ny < 0 || nx + w2 > N || ny + h2 > N) continue;
      out.push_back(rect(nx, ny, nx + w2, ny + h2));
    }
    auto t = random_triangles(rng, dom, 2);
    out.insert(out.end(), t.begin(), t.end());
    return out;
  }
  if (kind == 2) {  // octilinear shapes
    for (int i = 0; i < uni(1, 4); ++i) {
      int cx = uni(1, N - 1), cy = uni(1, N - 1), r = uni(1, 2);
      int s = uni(0, 3);
      if (s == 0) out.push_back(poly({{cx - r, cy}, {cx, cy - r}, {cx + r, cy}, {cx, cy + r}}));
      else if (s == 1) out.push_back(poly({{cx, cy}, {cx + 2 * r, cy}, {cx, cy + 2 * r}}));
      else if (s == 2) out.push_back(poly({{cx, cy}, {cx + 2 * r, cy}, {cx + 2 * r, cy + 2 * r}}));
      else out.push_back(rect(cx, cy, cx + r, cy + r));
    }
    return out;
  }
  if (kind == 3) {  // T pinches: a triangle/diamond tip touching the middle of a rect edge
    int x0 = uni(2, N - 6), y0 = uni(2, N - 6), w = uni(2, 4), hh = uni(2, 4);
    out.push_back(rect(x0, y0, x0 + w, y0 + hh));
    for (int i = 0; i < uni(1, 3); ++i) {
      int side = uni(0, 3);
      Point tip;
      if (side == 0) tip = {uni(x0 + 1, x0 + w - 1), y0};
      else if (side == 1) tip = {uni(x0 + 1, x0 + w - 1), y0 + hh};
      else if (side == 2) tip = {x0, uni(y0 + 1, y0 + hh - 1)};
      else tip = {x0 + w, uni(y0 + 1, y0 + hh - 1)};
      int dx = side == 2 ? -1 : side == 3 ? 1 : 0, dy = side == 0 ? -1 : side == 1 ? 1 : 0;
      int L = uni(1, 3), a = uni(1, 3), b = uni(0, 2);
      Point base = {tip.x + dx * L, tip.y + dy * L};
      Point p1 = {base.x + (dy != 0 ? a : b), base.y + (dx != 0 ? a : b)};
      Point p2 = {base.x - (dy != 0 ? uni(1, 3) : b), base.y - (dx != 0 ? uni(1, 3) : b)};
      bool okp = true;
      for (Point p : {p1, p2}) okp = okp && p.x >= 0 && p.y >= 0 && p.x <= N && p.y <= N;
      if (!okp || geom::twice_area(geom::Ring{tip, p1, p2}) == 0) continue;
      out.push_back(poly({tip, p1, p2}));
    }
    auto t = random_triangles(rng, dom, 1);
    out.insert(out.end(), t.begin(), t.end());
    return out;
  }
  // kind 4: thin slivers and quads with sloped sides
  for (int i = 0; i < uni(2, 5); ++i) {
    std::vector<Point> r;
    int n = uni(3, 4);
    int cx = uni(1, N - 1), cy = uni(1, N - 1);
    for (int k = 0; k < n; ++k) r.push_back({std::clamp(cx + uni(-3, 3), 0, N), std::clamp(cy + uni(-3, 3), 0, N)});
    if (n == 4) {
      // ordered by angle around the centroid (normalization rejects what is still not simple)
      double mx = 0, my = 0;
      for (auto p : r) mx += p.x, my += p.y;
      mx /= 4, my /= 4;
      std::sort(r.begin(), r.end(), [&](Point a, Point b) { return std::atan2(a.y - my, a.x - mx) < std::atan2(b.y - my, b.x - mx); });
      bool simple = true;
      for (int k = 0; k < 4; ++k) simple = simple && !(r[k] == r[(k + 1) % 4]);
      if (!simple) continue;
    }
    if (geom::twice_area(r) == 0) continue;
    out.push_back(poly(r));
  }
  return out;
}

std::optional<Scene> small_scene(std::mt19937& rng, int kind, int N) {
  try {
    if (kind < 5) return normalized({{0, 0}, {N, N}}, degenerate_scene(rng, kind, N));
    std::vector<geom::Polygon> rects;
    for (int i = 0, k = 1 + static_cast<int>(rng() % 3); i < k; ++i) {
      const int x0 = 1 + static_cast<int>(rng() % 6), y0 = 1 + static_cast<int>(rng() % 6);
      rects.push_back(rect(x0, y0, x0 + 1 + static_cast<int>(rng() % 3), y0 + 1 + static_cast<int>(rng() % 3)));
    }
    return normalized({{0, 0}, {N, N}}, rects);
  } catch (const std::exception&) {
    return std::nullopt;  // not a valid layout
  }
}

}  // namespace taut::test
