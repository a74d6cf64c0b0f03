// The octilinear reference (oracle/oct_oracle.h) against a second, independent reference:
// Dijkstra on the integer lattice with the eight unit moves (cost 1 along an axis, sqrt(2)
// diagonally), blocked cells rasterized straight from the input rectangles (not from
// normalize_obstacles or the oracle's visibility graph). Plus hand cases with their lengths
// worked out in the comments, free space, and metamorphic checks on sloped obstacles.
//
// The lattice model, and how it matches the oracle's rules (l1_oracle.h). Cell c is the open
// unit square with lower-left corner c; it is free iff it lies in the domain and no input
// rectangle covers it. With integer corners every open cell, open unit edge and lattice point is
// wholly inside an obstacle or wholly not, so the open set O of l1_oracle.h is the union of the
// free open cells, the open unit edges between two free cells, and the lattice points whose
// four cells are free. Around a lattice point p the four cells NE, NW, SW, SE (counter-clockwise)
// are its sectors; two neighbours in that cycle are joined (one wedge) iff both are free: the
// unit edge between them is then in O. So the groups of free cells around p are exactly the
// oracle's wedges at p (two diagonal free cells with the other two blocked: a pinch; a cell
// outside the domain counts as blocked, which is the domain-as-a-wall rule). A state is (p,
// wedge). A diagonal move p -> p + (+-1, +-1) runs through the open cell between them and is
// allowed iff that cell is free; it leaves p in that cell's wedge at p and arrives in that cell's
// wedge at the other end. An axis move runs along a unit edge and is allowed iff a cell beside
// it is free (an edge with both cells blocked is inside an obstacle, or flush against the domain
// side); it goes from that cell's wedge to that cell's wedge (both free cells beside an edge are
// in one wedge at each end). A lattice path is therefore an allowed path of l1_oracle.h, and
// the oracle's distance is at most the lattice distance.
//
// Why the lattice distance is not larger (so the two must agree exactly). A shortest path of the
// oracle is a visibility path whose bends are obstacle vertices: integer points. Take one of its
// segments a -> b and (by symmetry) 0 <= dy <= dx, slope m = dy/dx. In the column
// [i, i+1] x R (a.x <= i < b.x) the segment runs from height y(i) to y(i) + m; the lattice path
// through (i, floor(y(i))) makes dx - dy axis moves and dy diagonal moves (floor(y) rises by 0 or
// 1 per column since m <= 1): its length is d8(b - a). Each move is allowed: where floor(y)
// stays k, the segment lies in the closed cell [i,i+1] x [k,k+1] and either runs along its bottom
// edge (the move is that piece of the segment) or passes through the open cell, which is then
// free, and the move runs along the free cell's bottom edge; where floor(y) rises, the segment
// passes through the open cell [i,i+1] x [k,k+1] (free) unless it is that cell's diagonal, which
// is the move. At a lattice point (i, k) with k < y(i) the segment crosses the open unit edge
// above it, so the cells on both sides of that edge are free and the moves in and out (through
// those cells or the free cell below-left) lie in one wedge; at k == y(i) the segment itself
// passes through (i, k), inside one wedge (the oracle's rule), and the moves in and out lie in
// the closures of the cells the segment itself leaves and enters by. At a bend the two segments
// share a wedge, and so do the moves. So every shortest visibility path has a lattice path of the
// same length: the distances are equal, exactly (both are sums of 1 and sqrt(2), compared as
// Root2).
#include "oracle/oct_oracle.h"
#include "support/random_shapes.h"
#include "support/sanitized.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <functional>
#include <optional>
#include <queue>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "geom/normalize.h"
#include "geom/predicates.h"
#include "oracle/union_oracle.h"

namespace oct_oracle_test {

using taut::geom::Box;
using taut::geom::NormalizedObstacles;
using taut::geom::octilinear_length;
using taut::geom::Point;
using taut::geom::Polygon;
using taut::geom::Ring;
using taut::geom::Root2;
using taut::oracle::OctilinearReference;
using Len = std::optional<Root2>;
using i64 = std::int64_t;

constexpr Root2 kOne{1, 0}, kDiag{0, 1};

std::string str(Point p) { return "(" + std::to_string(p.x) + "," + std::to_string(p.y) + ")"; }
std::string str(const std::vector<Point>& path) {
  std::string s;
  for (const Point p : path) s += str(p);
  return s;
}
std::string str(const Len& d) {
  if (!d) return "unreachable";
  std::ostringstream os;
  os << *d;
  return os.str();
}

// The union of the rectangles clipped to the domain, as the oracle takes its obstacles.
NormalizedObstacles normalized(const Box& domain, const std::vector<Box>& rects) {
  std::vector<Polygon> in;
  for (const Box& r : rects) in.push_back({{r.lo, {r.hi.x, r.lo.y}, r.hi, {r.lo.x, r.hi.y}}, {}});
  return taut::geom::normalize_obstacles(in, domain);
}

// ---------------------------------------------------------------------------------------------
// The lattice reference described at the top.
class Lattice {
 public:
  Lattice(const Box& domain, const std::vector<Box>& rects) : domain_(domain) {
    nx_ = domain.hi.x - domain.lo.x;
    ny_ = domain.hi.y - domain.lo.y;
    blocked_.assign(static_cast<std::size_t>(nx_ * ny_), false);
    for (const Box& r : rects)
      for (int y = std::max(r.lo.y, domain.lo.y); y < std::min(r.hi.y, domain.hi.y); ++y)
        for (int x = std::max(r.lo.x, domain.lo.x); x < std::min(r.hi.x, domain.hi.x); ++x)
          blocked_[cell_index({x, y})] = true;
    for (int y = domain.lo.y; y <= domain.hi.y; ++y)
      for (int x = domain.lo.x; x <= domain.hi.x; ++x) wedges_.push_back(group_cells({x, y}));
  }

  bool in_domain(Point p) const {
    return domain_.lo.x <= p.x && p.x <= domain_.hi.x && domain_.lo.y <= p.y &&
           p.y <= domain_.hi.y;
  }
  // The open cell with lower-left corner c.
  bool free_cell(Point c) const {
    if (c.x < domain_.lo.x || c.y < domain_.lo.y || c.x >= domain_.hi.x || c.y >= domain_.hi.y)
      return false;
    return !blocked_[cell_index(c)];
  }
  // Quadrant (0 NE, 1 NW, 2 SW, 3 SE) of cell c around its corner p.
  static int quadrant(Point p, Point c) {
    const bool west = c.x < p.x, south = c.y < p.y;
    return south ? (west ? 2 : 3) : (west ? 1 : 0);
  }
  static Point cell_at(Point p, int quadrant) {
    return {p.x - (quadrant == 1 || quadrant == 2), p.y - (quadrant == 2 || quadrant == 3)};
  }
  // Wedge of each quadrant's cell at p in the domain (the smallest quadrant of its group); -1
  // if blocked.
  const std::array<int, 4>& wedges(Point p) const { return wedges_[point_index(p)]; }
  int wedge_count(Point p) const {
    if (!in_domain(p)) return 0;
    const auto w = wedges(p);
    int n = 0;
    for (int k = 0; k < 4; ++k) n += w[k] == k;
    return n;
  }

  struct Result {
    std::vector<Len> dist;          // per state (lattice point, wedge)
    std::vector<std::size_t> prev;  // per state; npos at the source
  };
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

  // From s to every state; with `stop`, only until the first state at `stop` is settled (the
  // best one there: states leave the queue in order of distance).
  Result dijkstra(Point s, std::optional<Point> stop = std::nullopt) const {
    Result r;
    r.dist.assign(state_count(), std::nullopt);
    r.prev.assign(state_count(), npos);
    using Item = std::pair<Root2, std::size_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
    if (in_domain(s)) {
      const auto w = wedges(s);
      for (int k = 0; k < 4; ++k)
        if (w[k] == k) {
          r.dist[state(s, k)] = Root2{};
          queue.push({Root2{}, state(s, k)});
        }
    }
    while (!queue.empty()) {
      const auto [d, st] = queue.top();
      queue.pop();
      if (d != *r.dist[st]) continue;  // stale
      const Point p = point_of(st);
      if (p == stop) break;
      const int wedge = static_cast<int>(st % 4);
      const auto& wp = wedges(p);
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy) {
          const Point q{p.x + dx, p.y + dy};
          if ((dx == 0 && dy == 0) || !in_domain(q)) continue;
          const auto& wq = wedges(q);
          // The cells the move runs through (diagonal: one) or beside (axis: two).
          const Point lo{std::min(p.x, q.x), std::min(p.y, q.y)};
          const bool diagonal = dx != 0 && dy != 0;
          const std::array<Point, 2> cells = {
              lo, dx != 0 ? Point{lo.x, lo.y - 1} : Point{lo.x - 1, lo.y}};
          const Root2 nd = d + (diagonal ? kDiag : kOne);
          for (std::size_t i = 0; i < (diagonal ? 1u : 2u); ++i) {
            const Point c = cells[i];
            if (!free_cell(c) || wp[quadrant(p, c)] != wedge) continue;
            const std::size_t next = state(q, wq[quadrant(q, c)]);
            if (!r.dist[next] || nd < *r.dist[next]) {
              r.dist[next] = nd;
              r.prev[next] = st;
              queue.push({nd, next});
            }
          }
        }
    }
    return r;
  }
  // The best state at t, npos when t is not reached.
  std::size_t best_state(const Result& r, Point t) const {
    if (!in_domain(t)) return npos;
    const auto w = wedges(t);
    std::size_t best = npos;
    for (int k = 0; k < 4; ++k) {
      const std::size_t st = state(t, k);
      if (w[k] == k && r.dist[st] && (best == npos || *r.dist[st] < *r.dist[best])) best = st;
    }
    return best;
  }
  Len distance(const Result& r, Point t) const {
    const std::size_t st = best_state(r, t);
    return st == npos ? Len{} : r.dist[st];
  }
  Len distance(Point s, Point t) const { return distance(dijkstra(s, t), t); }
  // The unit moves of a shortest lattice path to t (empty when unreachable).
  std::vector<Point> path(const Result& r, Point t) const {
    std::vector<Point> out;
    for (std::size_t st = best_state(r, t); st != npos; st = r.prev[st])
      out.push_back(point_of(st));
    std::reverse(out.begin(), out.end());
    return out;
  }

 private:
  std::array<int, 4> group_cells(Point p) const {
    std::array<int, 4> w{};
    for (int k = 0; k < 4; ++k) w[k] = free_cell(cell_at(p, k)) ? k : -1;
    for (int pass = 0; pass < 2; ++pass)
      for (int k = 0; k < 4; ++k) {
        const int j = (k + 1) % 4;
        if (w[k] >= 0 && w[j] >= 0) w[k] = w[j] = std::min(w[k], w[j]);
      }
    return w;
  }
  std::size_t point_index(Point p) const {
    return static_cast<std::size_t>((p.y - domain_.lo.y) * (nx_ + 1) + (p.x - domain_.lo.x));
  }
  std::size_t cell_index(Point c) const {
    return static_cast<std::size_t>((c.y - domain_.lo.y) * nx_ + (c.x - domain_.lo.x));
  }
  std::size_t state_count() const { return static_cast<std::size_t>((nx_ + 1) * (ny_ + 1) * 4); }
  std::size_t state(Point p, int wedge) const {
    return point_index(p) * 4 + static_cast<std::size_t>(wedge);
  }
  Point point_of(std::size_t st) const {
    const int i = static_cast<int>(st / 4);
    return {domain_.lo.x + i % (nx_ + 1), domain_.lo.y + i / (nx_ + 1)};
  }

  Box domain_;
  int nx_ = 0, ny_ = 0;
  std::vector<bool> blocked_;
  std::vector<std::array<int, 4>> wedges_;  // per lattice point of the domain
};

// ---------------------------------------------------------------------------------------------
// Random rectangle layouts: overlapping, aligned (a shared x or y, slits one unit wide),
// touching along edges and at corners (pinches), some sticking out of the domain (clipped).
std::vector<Box> random_rects(std::mt19937& rng, const Box& domain) {
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  std::vector<Box> out;
  const int n = uni(1, 6);
  for (int i = 0; i < n; ++i) {
    const int w = uni(1, 4), h = uni(1, 4);
    Box b;
    const int kind = out.empty() ? 0 : uni(0, 3);
    const Box o = out.empty() ? Box{} : out.back();
    if (kind == 1) {
      // Diagonally at a corner of the previous one (a pinch, unless something fills it).
      const int cx = uni(0, 1), cy = uni(0, 1);
      const Point c{cx ? o.hi.x : o.lo.x, cy ? o.hi.y : o.lo.y};
      b.lo = {cx ? c.x : c.x - w, cy ? c.y : c.y - h};
    } else if (kind == 2) {
      // Beside the previous one, touching it or one unit away, sharing a bottom or top line.
      const int gap = uni(0, 1);
      b.lo.x = uni(0, 1) ? o.hi.x + gap : o.lo.x - gap - w;
      b.lo.y = uni(0, 1) ? o.lo.y : o.hi.y - h;
    } else {
      b.lo = {uni(domain.lo.x - 1, domain.hi.x - 1), uni(domain.lo.y - 1, domain.hi.y - 1)};
    }
    b.hi = {b.lo.x + w, b.lo.y + h};
    out.push_back(b);
  }
  return out;
}

// "domain [x,y X,Y] rect [...] ...": what a failing seed's SCOPED_TRACE shows.
std::string describe(const Box& domain, const std::vector<Box>& rects) {
  std::ostringstream os;
  const auto box = [&](const char* what, const Box& b) -> std::ostringstream& {
    os << what << "[" << b.lo.x << "," << b.lo.y << " " << b.hi.x << "," << b.hi.y << "]";
    return os;
  };
  box("domain ", domain);
  for (const Box& r : rects) box(" rect ", r);
  return os.str();
}

std::string lines(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += x + "\n";
  return s;
}

// One layout of rectangles, seen by both references.
struct Layout {
  Layout(const Box& domain, const std::vector<Box>& rects)
      : scene(normalized(domain, rects)),
        ref(scene.domain, scene.obstacles),
        lattice(domain, rects) {}
  NormalizedObstacles scene;
  OctilinearReference ref;
  Lattice lattice;

  // Valid input for the oracle (union_oracle's checks) and no inconsistency seen by it.
  testing::AssertionResult sound() const {
    const std::string bad =
        lines(taut::oracle::check_obstacles(scene.obstacles, scene.domain)) + lines(ref.problems());
    if (bad.empty()) return testing::AssertionSuccess();
    return testing::AssertionFailure() << bad;
  }
  // The oracle's distances from s (`got`) equal the lattice's (`lr`, from s).
  testing::AssertionResult agree(Point s, const std::vector<Point>& targets,
                                 const std::vector<Len>& got, const Lattice::Result& lr) const {
    for (std::size_t k = 0; k < targets.size(); ++k) {
      const Len want = lattice.distance(lr, targets[k]);
      if (got[k] != want)
        return testing::AssertionFailure() << "s " << str(s) << " t " << str(targets[k])
                                           << ": oracle " << str(got[k]) << ", lattice "
                                           << str(want);
    }
    return testing::AssertionSuccess();
  }
};

TEST(OctOracle, MatchesLatticeDijkstraOnRandomRectangles) {
  const unsigned base = 31000;
  int layouts = 0, compared = 0, reachable = 0, not_free = 0, pinch_queries = 0,
      layouts_with_pinch = 0, paths = 0, diagonal_answers = 0;
  // Under the sanitizers an eighth of the layouts (support/sanitized.h); the thresholds scale.
  const auto share = [](std::int64_t n) { return static_cast<int>(taut::test::sanitized_share(n, 4)); };
  for (int it = 0; it < share(2500); ++it) {
    const unsigned seed = base + static_cast<unsigned>(it);
    std::mt19937 rng(seed);
    auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    const Box domain{{uni(-2, 0), uni(-2, 0)}, {uni(4, 12), uni(4, 12)}};
    const std::vector<Box> rects = random_rects(rng, domain);
    SCOPED_TRACE("seed " + std::to_string(seed) + ": " + describe(domain, rects));
    const Layout layout(domain, rects);
    ASSERT_TRUE(layout.sound());
    const OctilinearReference& ref = layout.ref;
    const Lattice& lattice = layout.lattice;
    ++layouts;

    // Free space and wedges agree at every lattice point (and just outside the domain).
    std::vector<Point> all, pinches;
    for (int y = domain.lo.y - 1; y <= domain.hi.y + 1; ++y)
      for (int x = domain.lo.x - 1; x <= domain.hi.x + 1; ++x) {
        const Point p{x, y};
        const int wc = lattice.wedge_count(p);
        ASSERT_EQ(static_cast<int>(ref.wedges_at(p).size()), wc) << str(p);
        if (lattice.in_domain(p)) all.push_back(p);
        if (wc >= 2) pinches.push_back(p);
      }
    layouts_with_pinch += !pinches.empty();
    // Query points: obstacle vertices, pinches, any lattice point of the domain (free, on an
    // edge, inside an obstacle, walled in).
    std::vector<Point> vertices;
    for (const Polygon& p : layout.scene.obstacles) {
      vertices.insert(vertices.end(), p.outer.begin(), p.outer.end());
      for (const Ring& h : p.holes) vertices.insert(vertices.end(), h.begin(), h.end());
    }
    const std::array<const std::vector<Point>*, 6> kinds = {&vertices, &pinches, &all,
                                                            &all,      &all,     &all};
    auto pick = [&]() -> Point {
      const std::vector<Point>* from = kinds[rng() % kinds.size()];
      if (from->empty()) from = &all;
      return (*from)[rng() % from->size()];
    };

    for (int q = 0; q < 2; ++q) {
      const Point s = pick();
      std::vector<Point> targets;
      for (int k = 0; k < 10; ++k) targets.push_back(pick());
      const Lattice::Result lr = lattice.dijkstra(s);
      const std::vector<Len> got = ref.distances(s, targets);
      ASSERT_TRUE(layout.agree(s, targets, got, lr));
      for (std::size_t k = 0; k < targets.size(); ++k) {
        ++compared;
        reachable += got[k].has_value();
        not_free += !ref.is_free(s) || !ref.is_free(targets[k]);
        pinch_queries += lattice.wedge_count(targets[k]) >= 2;
        diagonal_answers += got[k] && got[k]->b != 0;
      }
      // The oracle's path: from s to t, as long as the distance, and every segment realizable
      // on the lattice with its own d8 length (else the oracle took a forbidden shortcut).
      const Point t = targets[0];
      const auto path = ref.path(s, t);
      ASSERT_EQ(path.has_value(), got[0].has_value()) << "s " << str(s) << " t " << str(t);
      if (!path) continue;
      ++paths;
      ASSERT_EQ(path->front(), s);
      ASSERT_EQ(path->back(), t);
      ASSERT_EQ(ref.check_path(*path), got[0]) << str(*path);
      Root2 len;
      for (std::size_t i = 0; i + 1 < path->size(); ++i) {
        const Point a = (*path)[i], b = (*path)[i + 1];
        const Root2 l = octilinear_length(i64{b.x} - a.x, i64{b.y} - a.y);
        len += l;
        ASSERT_EQ(lattice.distance(a, b), l) << "segment " << str(a) << str(b);
      }
      ASSERT_EQ(len, *got[0]);
      // The lattice's own shortest path, unit moves: the oracle accepts it as an octilinear
      // path of the same length.
      const std::vector<Point> moves = lattice.path(lr, t);
      ASSERT_FALSE(moves.empty());
      ASSERT_EQ(ref.check_octilinear_path(moves), got[0]) << str(moves);
    }
  }
  // The generator must exercise what it is meant to.
  EXPECT_EQ(layouts, share(2500));
  EXPECT_GT(compared, share(40000));
  EXPECT_GT(reachable, compared / 3);
  EXPECT_LT(reachable, compared - compared / 20);
  EXPECT_GT(not_free, share(1000));
  EXPECT_GT(diagonal_answers, compared / 4);
  EXPECT_GT(layouts_with_pinch, share(200));
  EXPECT_GT(pinch_queries, share(1000));
  EXPECT_GT(paths, share(3000));
  std::printf(
      "layouts %d, compared %d (reachable %d, diagonal part %d, s or t not free %d, at pinches "
      "%d), layouts with a pinch %d, paths %d\n",
      layouts, compared, reachable, diagonal_answers, not_free, pinch_queries,
      layouts_with_pinch, paths);
}

// One larger layout (about 300 vertices, the size the wavefront tests use) against the lattice.
TEST(OctOracle, LargerLayoutMatchesLattice) {
  const unsigned seed = 8111;
  std::mt19937 rng(seed);
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  const Box domain{{0, 0}, {100, 100}};
  std::vector<Box> rects(90);
  for (Box& r : rects) {
    r.lo = {uni(0, 96), uni(0, 96)};
    r.hi = {r.lo.x + uni(1, 8), r.lo.y + uni(1, 8)};
  }
  std::vector<Point> targets(150);
  for (Point& t : targets) t = {uni(0, 100), uni(0, 100)};
  SCOPED_TRACE("seed " + std::to_string(seed) + ": " + describe(domain, rects));
  const Layout layout(domain, rects);
  ASSERT_TRUE(layout.sound());
  EXPECT_GT(layout.ref.node_count(), 200u);
  int reachable = 0;
  for (std::size_t q = 0; q < 3; ++q) {
    const std::vector<Len> got = layout.ref.distances(targets[q], targets);
    ASSERT_TRUE(layout.agree(targets[q], targets, got, layout.lattice.dijkstra(targets[q])));
    for (const Len& d : got) reachable += d.has_value();
  }
  EXPECT_GT(reachable, 200);
  std::printf("%zu nodes, %zu visibility edges\n", layout.ref.node_count(),
              layout.ref.edge_count());
}

// No obstacles: the distance is the octilinear length of the difference, over the whole
// coordinate range, and the path is the straight segment.
TEST(OctOracle, FreeSpaceIsTheOctilinearLength) {
  const unsigned seed = 4242;
  std::mt19937 rng(seed);
  const int m = taut::geom::kMaxCoord;
  auto coord = [&]() { return std::uniform_int_distribution<int>(-m, m)(rng); };
  const Box domain{{-m, -m}, {m, m}};
  const OctilinearReference ref(domain, std::vector<Polygon>{});
  std::vector<Point> pts = {domain.lo, domain.hi, {-m, m}, {m, -m}, {0, 0}};
  // Random points, each with a partner straight above or below it and one on a diagonal.
  while (pts.size() < 200) {
    const Point p{coord(), coord()};
    pts.push_back(p);
    pts.push_back({p.x, coord()});
    const int d = std::uniform_int_distribution<int>(-1000, 1000)(rng);
    if (std::abs(i64{p.x} + d) <= m && std::abs(i64{p.y} - d) <= m)
      pts.push_back({p.x + d, p.y - d});
  }
  int checked = 0;
  for (std::size_t i = 0; i < pts.size(); i += 20) {
    SCOPED_TRACE("seed " + std::to_string(seed) + " s " + str(pts[i]));
    const std::vector<Len> got = ref.distances(pts[i], pts);
    for (std::size_t j = 0; j < pts.size(); ++j) {
      const Root2 want = octilinear_length(i64{pts[j].x} - pts[i].x, i64{pts[j].y} - pts[i].y);
      ASSERT_EQ(got[j], want) << str(pts[j]);
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000);
  const auto p = ref.path(domain.lo, domain.hi);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(*p, (std::vector<Point>{domain.lo, domain.hi}));
  EXPECT_EQ(ref.distance(domain.lo, domain.hi), (Root2{0, 2 * i64{m}}));
  EXPECT_EQ(ref.distance({-m, 0}, {m, 1}), (Root2{2 * i64{m} - 1, 1}));
  EXPECT_EQ(ref.distance({-m, 0}, {m, 0}), (Root2{2 * i64{m}, 0}));
  EXPECT_EQ(ref.distance({0, 0}, {m, 0}), ref.distance({m, 0}, {0, 0}));
  EXPECT_FALSE(ref.distance({0, 0}, {0, 0})->sign());
}

// ---------------------------------------------------------------------------------------------
// Hand cases.

TEST(OctOracle, SquareBetweenTwoPoints) {
  //   y=1  . . +---+ . .      square [2,4]x[-1,1]; s = (0,0), t = (6,0)
  //   y=0  s . |   | . t      over the top: s -> (2,1) -> (4,1) -> t
  //   y=-1 . . +---+ . .      = (1 + sqrt2) + 2 + (1 + sqrt2) = 4 + 2 sqrt2 (below: the same)
  // Lower bound: the path meets the line x = 3 at some P with |P.y| >= 1 (else inside the
  // square), so by the triangle inequality it is at least d8(3, 1) + d8(3, 1) = 4 + 2 sqrt2.
  const Box domain{{-3, -4}, {9, 4}};
  const NormalizedObstacles sc = normalized(domain, {{{2, -1}, {4, 1}}});
  const OctilinearReference ref(sc.domain, sc.obstacles);
  EXPECT_EQ(ref.distance({0, 0}, {6, 0}), (Root2{4, 2}));
  EXPECT_FALSE(ref.visible({0, 0}, {6, 0}));
  EXPECT_TRUE(ref.visible({0, 0}, {2, 1}));
  // Along the top edge: unchanged by the square.
  EXPECT_EQ(ref.distance({0, 1}, {6, 1}), (Root2{6, 0}));
  // (1,2) -> (5,-2): the diagonal runs through (3,0), inside. The square and the line
  // y = x - 3 through its corners (2,-1) and (4,1) separate s from t, so a path crosses that
  // line at (4+u, 1+u) or (2-u, -1-u), u >= 0; at (4+u, 1+u) the triangle inequality gives
  // d8(3+u, u-1) + d8(1-u, -3-u) = 4 + 2 sqrt2 + u (4 - 2 sqrt2) for u <= 1 (more beyond),
  // least at the corner itself; the other side is symmetric: 4 + 2 sqrt2.
  EXPECT_EQ(ref.distance({1, 2}, {5, -2}), (Root2{4, 2}));
  const auto p = ref.path({0, 0}, {6, 0});
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(ref.check_path(*p), (Root2{4, 2}));
  EXPECT_EQ(ref.check_octilinear_path(std::vector<Point>{{0, 0}, {1, 1}, {4, 1}, {5, 1}, {6, 0}}),
            (Root2{4, 2}));
  // A segment that is not at a multiple of 45 degrees: check_path measures it, the octilinear
  // check refuses it.
  const std::vector<Point> sloped{{0, 0}, {2, 1}, {4, 1}, {6, 0}};
  EXPECT_EQ(ref.check_path(sloped), (Root2{4, 2}));
  EXPECT_EQ(ref.check_octilinear_path(sloped), std::nullopt);
  EXPECT_EQ(ref.check_path(std::vector<Point>{{0, 0}, {6, 0}}), std::nullopt);  // through it
}

TEST(OctOracle, WallWithAGap) {
  //  y=10 .  t  .  .  .  .  .  .  .  .     walls [0,4]x[5,7] and [6,10]x[5,7], flush with the
  //  y=7  ####### .  .  #########           domain sides; gap x in [4,6]
  //  y=5  ####### .  .  #########           s = (1,1), t = (1,10): s -> (4,5) -> (4,7) -> t
  //  y=1  .  s  .  .  .  .  .  .  .  .     = (1 + 3 sqrt2) + 2 + 3 sqrt2 = 3 + 6 sqrt2
  // Lower bound: take P1, the last point at y = 5 before the path first reaches y = 7, and P2,
  // that first point at y = 7; in between the path is in the gap, so P1.x, P2.x >= 4, and
  // d8(P1 - s) + d8(P2 - P1) + d8(t - P2) >= d8(3, 4) + 2 + d8(3, 3) = 3 + 6 sqrt2.
  const Box domain{{0, 0}, {10, 11}};
  const NormalizedObstacles sc = normalized(domain, {{{0, 5}, {4, 7}}, {{6, 5}, {10, 7}}});
  const OctilinearReference ref(sc.domain, sc.obstacles);
  EXPECT_EQ(ref.distance({1, 1}, {1, 10}), (Root2{3, 6}));
  EXPECT_EQ(ref.distance({1, 10}, {1, 1}), (Root2{3, 6}));
  EXPECT_EQ(ref.distance({5, 0}, {5, 10}), (Root2{10, 0}));  // straight through the gap
  EXPECT_EQ(ref.distance({4, 4}, {6, 7}), (Root2{1, 2}));    // diagonally across the gap
  EXPECT_FALSE(ref.is_free({0, 6}));  // on the domain side where the wall is flush: no wedge
  EXPECT_TRUE(ref.is_free({0, 5}));   // the wall's corner on the side: free below
  EXPECT_FALSE(ref.is_free({2, 6}));  // inside the wall
  const auto p = ref.path({1, 1}, {1, 10});
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(ref.check_path(*p), (Root2{3, 6}));
  EXPECT_EQ(ref.check_octilinear_path(std::vector<Point>{{1, 1}, {4, 4}, {4, 5}, {4, 7}, {1, 10}}),
            (Root2{3, 6}));
  // The gap closed by a third block: no way up.
  const NormalizedObstacles closed =
      normalized(domain, {{{0, 5}, {4, 7}}, {{6, 5}, {10, 7}}, {{4, 5}, {6, 7}}});
  const OctilinearReference ref2(closed.domain, closed.obstacles);
  EXPECT_EQ(ref2.distance({1, 1}, {1, 10}), std::nullopt);
  EXPECT_EQ(ref2.distance({4, 5}, {4, 7}), std::nullopt);  // below the wall to above it
  EXPECT_EQ(ref2.distance({4, 5}, {7, 2}), (Root2{0, 3}));
}

TEST(OctOracle, PointWalledIn) {
  //  four bars 2 wide around [3,7]^2 (merged into the frame [1,9]^2 with that hole); s = (5,5)
  const Box domain{{0, 0}, {10, 10}};
  const NormalizedObstacles sc = normalized(domain, {{{1, 1}, {9, 3}},
                                             {{1, 7}, {9, 9}},
                                             {{1, 3}, {3, 7}},
                                             {{7, 3}, {9, 7}}});
  ASSERT_EQ(sc.obstacles.size(), 1u);
  ASSERT_EQ(sc.obstacles[0].holes.size(), 1u);
  const OctilinearReference ref(sc.domain, sc.obstacles);
  EXPECT_EQ(ref.distance({5, 5}, {0, 0}), std::nullopt);
  EXPECT_EQ(ref.distance({0, 0}, {5, 5}), std::nullopt);
  EXPECT_EQ(ref.distance({5, 5}, {10, 5}), std::nullopt);
  EXPECT_EQ(ref.distance({5, 5}, {2, 5}), std::nullopt);  // inside the wall: not free
  EXPECT_FALSE(ref.is_free({2, 5}));
  EXPECT_EQ(ref.distance({5, 5}, {3, 3}), (Root2{0, 2}));  // the hole's corner
  EXPECT_EQ(ref.distance({3, 4}, {7, 7}), (Root2{1, 3}));  // hole edge to hole corner
  EXPECT_EQ(ref.path({5, 5}, {0, 0}), std::nullopt);
  // Outside, round the frame: the first point of the path at x = 1 and the last at x = 9 are
  // at y >= 9 (over the top; below is symmetric), so the length is at least
  // d8(1, 4) + 8 + d8(1, 4) = 14 + 2 sqrt2, attained through the corners (1,9) and (9,9).
  EXPECT_EQ(ref.distance({0, 5}, {10, 5}), (Root2{14, 2}));
}

TEST(OctOracle, SourceOnAnObstacleEdge) {
  //  y=4  +--s--+      square [2,4]x[2,4]; s = (3,4) on its top edge, t = (3,0) below
  //       |     |      s -> (4,4) -> (4,1) -> t = 1 + 3 + sqrt2 = 4 + sqrt2
  //  y=2  +-----+      Lower bound: until the path first reaches x >= 4 (or x <= 2) it stays
  //  y=0     t         at y >= 4 (else it is inside), so it meets some Q = (4, y >= 4) after
  //                    d8 >= 1, and d8(t - Q) >= d8(1, 4) = 3 + sqrt2.
  const Box domain{{0, 0}, {6, 6}};
  const NormalizedObstacles sc = normalized(domain, {{{2, 2}, {4, 4}}});
  const OctilinearReference ref(sc.domain, sc.obstacles);
  EXPECT_EQ(ref.wedges_at({3, 4}).size(), 1u);
  EXPECT_EQ(ref.distance({3, 4}, {3, 0}), (Root2{4, 1}));
  EXPECT_EQ(ref.distance({3, 4}, {5, 5}), (Root2{1, 1}));   // straight up and away
  EXPECT_EQ(ref.distance({3, 4}, {4, 3}), (Root2{2, 0}));   // to the right edge: round (4,4)
  EXPECT_FALSE(ref.visible({3, 4}, {4, 3}));                // the diagonal cuts the corner
  EXPECT_EQ(ref.distance({3, 4}, {1, 4}), (Root2{2, 0}));   // along the edge and off it
  EXPECT_EQ(ref.distance({3, 4}, {3, 3}), std::nullopt);    // inside
  const auto p = ref.path({3, 4}, {3, 0});
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(ref.check_path(*p), (Root2{4, 1}));
  EXPECT_EQ(ref.check_octilinear_path(std::vector<Point>{{3, 4}, {4, 4}, {4, 1}, {3, 0}}),
            (Root2{4, 1}));
  EXPECT_EQ(ref.check_octilinear_path(std::vector<Point>{{3, 4}, {4, 3}, {4, 1}, {3, 0}}),
            std::nullopt);
}

TEST(OctOracle, PinchAtTouchingCorners) {
  //  y=4  s . . +---+      A = [0,2]^2, B = [2,4]^2 touch at (2,2): two wedges there
  //       . . . | B |      s = (0,4), t = (4,0): the diagonal through (2,2) (4 sqrt2) is
  //  y=2  +---*---+        not allowed. A path goes round A or B, crossing the line y = x
  //       | A | . .        outside A u B at (-u,-u) or (4+u,4+u), u >= 0:
  //  y=0  +---+ . t        d8(u, 4+u) + d8(4+u, u) = 8 + 2u sqrt2 >= 8, attained at u = 0.
  const Box domain{{-2, -2}, {6, 6}};
  const NormalizedObstacles sc = normalized(domain, {{{0, 0}, {2, 2}}, {{2, 2}, {4, 4}}});
  const OctilinearReference ref(sc.domain, sc.obstacles);
  ASSERT_EQ(lines(ref.problems()), "");
  EXPECT_EQ(ref.wedges_at({2, 2}).size(), 2u);
  EXPECT_FALSE(ref.visible({0, 4}, {4, 0}));
  EXPECT_EQ(ref.distance({0, 4}, {4, 0}), (Root2{8, 0}));
  // (1,3) -> (3,1): likewise d8(1+u, 3+u) + d8(3+u, 1+u) = 4 + (2 + 2u) sqrt2 >= 4 + 2 sqrt2.
  EXPECT_EQ(ref.distance({1, 3}, {3, 1}), (Root2{4, 2}));
  // A query at the pinch may start or end in either wedge; a path may not pass through it.
  EXPECT_EQ(ref.distance({1, 3}, {2, 2}), (Root2{0, 1}));
  EXPECT_EQ(ref.distance({2, 2}, {3, 1}), (Root2{0, 1}));
  EXPECT_EQ(ref.check_path(std::vector<Point>{{1, 3}, {2, 2}, {3, 1}}), std::nullopt);
  EXPECT_EQ(ref.check_octilinear_path(std::vector<Point>{{0, 4}, {2, 2}, {4, 0}}), std::nullopt);
  EXPECT_EQ(ref.check_octilinear_path(std::vector<Point>{{0, 4}, {0, 0}, {4, 0}}),
            (Root2{8, 0}));
  // Along A's top edge to the pinch and on along B's left edge: the same wedge (NW), allowed.
  EXPECT_EQ(ref.check_path(std::vector<Point>{{0, 2}, {2, 2}, {2, 4}}), (Root2{4, 0}));
  // From A's top edge (1,2) to its right edge (2,1), not through the pinch: round A, the path
  // crosses in turn the rays y = 2 (x <= 0), y = 0 (x <= 0) and x = 2 (y <= 0), at Q1, Q2, Q3;
  // as d8 >= max(|dx|, |dy|) the legs are at least 1 + |Q1.x|, 2, 2 + |Q2.x|, 1 + |Q3.y|:
  // 6, through (0,2), (0,0), (2,0). Round B is longer: (1 + sqrt2) + 2 + 2 + (1 + sqrt2).
  EXPECT_EQ(ref.distance({1, 2}, {2, 1}), (Root2{6, 0}));
  const auto p = ref.path({0, 4}, {4, 0});
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(ref.check_path(*p), (Root2{8, 0}));
}

// ---------------------------------------------------------------------------------------------
// Sloped obstacles: no second reference, so metamorphic checks: symmetry, the free-space lower
// bound and equality with it when the segment is allowed, the triangle inequality (not through a
// pinch), paths that check, and the scene scaled by 2 and mirrored (x, y) -> (y, x) (an
// isometry of d8) doubling every distance.
TEST(OctOracle, MetamorphicOnSlopedTriangles) {
  const unsigned base = 52000;
  int checked = 0, unreachable = 0;
  for (unsigned it = 0; it < 250; ++it) {
    const unsigned seed = base + it;
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937 rng(seed);
    auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    const Box domain{{0, 0}, {uni(6, 14), uni(6, 14)}};
    const std::vector<Polygon> in = taut::test::random_triangles(rng, domain, 4);
    // (Vertices rounded by normalization are integers too: the mirrored scene stays exact.)
    const auto nr = taut::geom::normalize_obstacles(in, domain);
    const OctilinearReference ref(nr.domain, nr.obstacles);
    ASSERT_EQ(lines(ref.problems()), "");
    // Mirror in y = x and scale by 2; the mirror reverses ring orientation, so reverse rings.
    auto mirror = [](Point p) { return Point{2 * p.y, 2 * p.x}; };
    std::vector<Polygon> mirrored;
    for (const Polygon& p : nr.obstacles) {
      Polygon q;
      for (auto v = p.outer.rbegin(); v != p.outer.rend(); ++v) q.outer.push_back(mirror(*v));
      for (const Ring& h : p.holes) {
        q.holes.emplace_back();
        for (auto v = h.rbegin(); v != h.rend(); ++v) q.holes.back().push_back(mirror(*v));
      }
      mirrored.push_back(q);
    }
    const OctilinearReference ref2({mirror(nr.domain.lo), mirror(nr.domain.hi)}, mirrored);
    ASSERT_EQ(lines(ref2.problems()), "");
    std::vector<Point> pts, pts2;
    for (int k = 0; k < 6; ++k) pts.push_back({uni(0, domain.hi.x), uni(0, domain.hi.y)});
    for (const Polygon& p : nr.obstacles) pts.push_back(p.outer[rng() % p.outer.size()]);
    for (const Point p : pts) pts2.push_back(mirror(p));
    std::vector<std::vector<Len>> d, d2;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      d.push_back(ref.distances(pts[i], pts));
      d2.push_back(ref2.distances(pts2[i], pts2));
    }
    for (std::size_t i = 0; i < pts.size(); ++i)
      for (std::size_t j = 0; j < pts.size(); ++j) {
        const Point s = pts[i], t = pts[j];
        SCOPED_TRACE("s " + str(s) + " t " + str(t));
        ASSERT_EQ(d[i][j], d[j][i]);
        ASSERT_EQ(d2[i][j].has_value(), d[i][j].has_value());
        if (!d[i][j]) {
          ++unreachable;
          continue;
        }
        ++checked;
        ASSERT_EQ(*d2[i][j], *d[i][j] + *d[i][j]);
        const Root2 free = octilinear_length(i64{t.x} - s.x, i64{t.y} - s.y);
        ASSERT_GE(*d[i][j], free);
        if (ref.visible(s, t)) {
          ASSERT_EQ(*d[i][j], free);
        }
        for (std::size_t k = 0; k < pts.size(); ++k) {
          // Not through a pinch: a query point there may switch wedges, a path may not.
          if (d[i][k] && d[k][j] && ref.wedges_at(pts[k]).size() == 1) {
            ASSERT_LE(*d[i][j], *d[i][k] + *d[k][j]) << "via " << str(pts[k]);
          }
        }
        const auto p = ref.path(s, t);
        ASSERT_TRUE(p.has_value());
        ASSERT_EQ(ref.check_path(*p), d[i][j]) << str(*p);
      }
  }
  EXPECT_GT(checked, 4000);
  EXPECT_GT(unreachable, 100);
  std::printf("checked %d pairs, %d unreachable\n", checked, unreachable);
}

}  // namespace oct_oracle_test
