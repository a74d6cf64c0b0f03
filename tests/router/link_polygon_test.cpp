// router::LinkPolygon and router::free_space_polygon (router/link_polygon.h: de Berg's
// rectilinear link distance in a simple rectilinear polygon, and the link diameter) against the
// exhaustive reference oracle::LinkPolygonReference (tests/oracle/link_polygon_oracle.h: 0-1 BFS
// on the Hanan grid x orientation, the diameter over every pair of Hanan grid points), which
// shares nothing with the router but geom's types and predicates; the L1 lengths against the L1
// reference (tests/oracle/l1_oracle.h).
//
// Seeded random polygons: polyominoes grown on grids of side 2..9 and thin random walks of unit
// cells (support/random_shapes.h), rows and columns stretched by 1, 1..3 or 1..60 (1..20 for walks) (shared x and y, collinear edges, long thin
// corridors), some moved to the coordinate limit. For each:
//   - the diameter equals the reference's over all Hanan grid points, its two ends are convex
//     vertices that far apart, and its path is legal: every segment axis-parallel and in the
//     polygon, exactly that many links, and L1-shortest (the length equals the L1 reference);
//   - query pairs (vertices, random lattice points inside, points on edges, points outside):
//     distance() and distances() equal the reference, path() has that many links and is legal,
//     and its length is the L1 distance (de Berg, Lemma 8: in a simple polygon some path is
//     shortest in links and in L1 at once); outside points give nothing;
//   - free_space_polygon() of the same polygon written two ways: a frame blockage whose hole is
//     the polygon (the boundary some way outside), and the complement cut into touching
//     rectangles (the boundary the polygon's box): the same ring back; an island inside it is
//     named (Island), a wall across it gives Pieces.
// A failure prints the seed and the ring; TAUT_LINK_SEED=N runs only seed N.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "geom/normalize.h"
#include "geom/predicates.h"
#include "io/generate.h"
#include "io/layout_geometry.h"
#include "io/movingai.h"
#include "oracle/l1_oracle.h"
#include "oracle/link_polygon_oracle.h"
#include "router/link_polygon.h"
#include "support/polygon_frame.h"
#include "support/random_shapes.h"
#include "support/run.h"
#include "support/sanitized.h"

namespace taut::test {
namespace link_polygon_test {

using geom::Box;
using geom::Coord;
using geom::Point;
using geom::Polygon;
using geom::Ring;
using router::FreeSpacePolygon;
using router::LinkPolygon;

std::string ring_text(const Ring& r) {
  std::ostringstream s;
  s << "{";
  for (const Point p : r) s << "{" << p.x << "," << p.y << "},";
  s << "}";
  return s.str();
}

// A path the router printed: from a to b, `links` segments, each axis-parallel and inside the
// polygon (the reference's distance of its two ends is 1: one free straight link), and of L1
// length `length`.
void expect_legal(const oracle::LinkPolygonReference& ref, const router::LinkPath& p, Point a, Point b) {
  ASSERT_FALSE(p.points.empty());
  EXPECT_EQ(p.points.front(), a);
  EXPECT_EQ(p.points.back(), b);
  if (a == b) {
    EXPECT_EQ(p.links, 0);
    return;
  }
  EXPECT_EQ(static_cast<int>(p.points.size()) - 1, p.links);
  std::int64_t len = 0;
  for (std::size_t i = 0; i + 1 < p.points.size(); ++i) {
    const Point u = p.points[i], v = p.points[i + 1];
    EXPECT_TRUE(u.x == v.x || u.y == v.y);
    EXPECT_NE(u, v);
    EXPECT_EQ(ref.distance(u, v), std::optional<int>(1)) << "segment " << u.x << "," << u.y << " " << v.x << "," << v.y;
    if (i > 0) {
      EXPECT_NE(geom::orientation(p.points[i - 1], u, v), 0) << "two links on one line";
    }
    len += std::abs(std::int64_t{v.x} - u.x) + std::abs(std::int64_t{v.y} - u.y);
  }
  EXPECT_EQ(len, p.length);
}

// The Hanan grid of a ring (its distinct vertex x's and y's) and the ring doubled, so a grid
// cell's centre is an integer point.
struct Hanan {
  std::vector<Coord> xs, ys;
  Ring twice;
  explicit Hanan(const Ring& ring) {
    for (const Point p : ring) xs.push_back(p.x), ys.push_back(p.y), twice.push_back({p.x * 2, p.y * 2});
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    std::sort(ys.begin(), ys.end());
    ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  }
  geom::Location cell(std::size_t i, std::size_t j) const {
    return geom::locate(Point{xs[i] + xs[i + 1], ys[j] + ys[j + 1]}, twice);
  }
};

// The complement of the polygon in its bounding box as rectangles of the Hanan grid (they touch
// along edges and at corners): another way a user writes the same free space.
std::vector<Polygon> complement_cells(const Ring& ring) {
  const Hanan h(ring);
  std::vector<Polygon> out;
  for (std::size_t i = 0; i + 1 < h.xs.size(); ++i)
    for (std::size_t j = 0; j + 1 < h.ys.size(); ++j)
      if (h.cell(i, j) == geom::Location::Outside)
        out.push_back(Polygon{box_ring({{h.xs[i], h.ys[j]}, {h.xs[i + 1], h.ys[j + 1]}}), {}});
  return out;
}

// A box strictly inside the polygon's interior: a Hanan cell inside it, shrunk by one on each
// side (nullopt when no cell is at least 3 by 3).
std::optional<Box> inner_box(const Ring& ring) {
  const Hanan h(ring);
  for (std::size_t i = 0; i + 1 < h.xs.size(); ++i)
    for (std::size_t j = 0; j + 1 < h.ys.size(); ++j)
      if (h.xs[i + 1] - h.xs[i] >= 3 && h.ys[j + 1] - h.ys[j] >= 3 && h.cell(i, j) == geom::Location::Inside)
        return Box{{h.xs[i] + 1, h.ys[j] + 1}, {h.xs[i + 1] - 1, h.ys[j + 1] - 1}};
  return std::nullopt;
}

std::optional<int> only_seed() {
  if (const char* s = std::getenv("TAUT_LINK_SEED")) return std::atoi(s);
  return std::nullopt;
}

TEST(LinkPolygon, RandomPolygonsMatchTheReference) {
  const int count = static_cast<int>(sanitized_share(2400, 12));
  int checked = 0, queries = 0, biggest = 0, pieces_checked = 0, islands_checked = 0;
  for (int seed = 1; seed <= count; ++seed) {
    if (only_seed() && *only_seed() != seed) continue;
    std::mt19937 rng(static_cast<unsigned>(seed));
    const int side = 2 + seed % 8;
    const int cells = 1 + static_cast<int>(rng() % static_cast<unsigned>(side * side * 2 / 3));
    const int stretch = seed % 3 == 0 ? 1 : seed % 3 == 1 ? 3 : 60;
    Point origin{static_cast<Coord>(rng() % 2001) - 1000, static_cast<Coord>(rng() % 2001) - 1000};
    const bool at_limit = seed % 50 == 7;
    if (at_limit) origin = {geom::kMaxCoord / 2 - 1000, -geom::kMaxCoord / 2};
    // compact polyominoes, and thin random walks (long corridors, large diameters) on odd seeds
    Ring ring;
    if (seed % 2) {
      ring = random_thin_polygon(rng, stretch == 60 ? 20 : stretch).ring;
      for (Point& p : ring) p = {p.x + origin.x, p.y + origin.y};
    } else {
      ring = random_rectilinear_polygon(rng, side, cells, stretch, origin);
    }
    SCOPED_TRACE("seed " + std::to_string(seed) + " ring " + ring_text(ring));
    const oracle::LinkPolygonReference ref(ring);
    const LinkPolygon poly(ring);
    EXPECT_EQ(canonical(poly.ring()), canonical(ref.corners()));

    // the diameter
    // (every third polygon by de Berg's divide and conquer from the start: search budget 0)
    const router::LinkDiameter d = poly.diameter(seed % 3 == 0 ? 0 : 32);
    const oracle::LinkPolygonReference::Diameter want = ref.diameter();
    ASSERT_EQ(d.links, want.links);
    biggest = std::max(biggest, d.links);
    EXPECT_EQ(ref.distance(d.from, d.to), std::optional<int>(d.links));
    EXPECT_EQ(d.cut_tree, seed % 3 == 0);
    if (d.cut_tree) {
      EXPECT_EQ(d.searches, 0u);  // budget 0: no search before the cut tree
    } else {
      EXPECT_GE(d.searches, 1u);
    }
    EXPECT_LE(d.searches, d.convex_vertices);
    const L1InPolygon l1(ring);
    expect_legal(ref, d.path, d.from, d.to);
    EXPECT_EQ(l1.ref->distance(d.from, d.to), std::optional<std::int64_t>(d.path.length));

    // query pairs
    const Box b = ring_box(ring);
    auto random_point = [&]() -> Point {
      switch (rng() % 4) {
        case 0: return ring[rng() % ring.size()];
        case 1: {  // a point on an edge
          const std::size_t i = rng() % ring.size();
          const Point u = ring[i], v = ring[(i + 1) % ring.size()];
          const std::int64_t t = static_cast<std::int64_t>(rng() % 5);
          return {static_cast<Coord>(u.x + (v.x - u.x) * t / 4), static_cast<Coord>(u.y + (v.y - u.y) * t / 4)};
        }
        default:  // anywhere in the box (outside now and then)
          return {static_cast<Coord>(b.lo.x + static_cast<Coord>(rng() % static_cast<unsigned>(b.hi.x - b.lo.x + 1))),
                  static_cast<Coord>(b.lo.y + static_cast<Coord>(rng() % static_cast<unsigned>(b.hi.y - b.lo.y + 1)))};
      }
    };
    std::vector<Point> inside;
    for (int q = 0; q < 6; ++q) {
      const Point s = random_point(), t = random_point();
      const std::optional<int> want_d = ref.distance(s, t);
      SCOPED_TRACE("query " + std::to_string(s.x) + "," + std::to_string(s.y) + " -> " + std::to_string(t.x) + "," +
                   std::to_string(t.y));
      EXPECT_EQ(poly.distance(s, t), want_d);
      const std::optional<router::LinkPath> p = poly.path(s, t);
      ASSERT_EQ(p.has_value(), want_d.has_value());
      ++queries;
      if (!p) continue;
      EXPECT_EQ(p->links, *want_d);
      expect_legal(ref, *p, s, t);
      EXPECT_EQ(l1.ref->distance(s, t), std::optional<std::int64_t>(p->length)) << "not L1-shortest";
      inside.push_back(s), inside.push_back(t);
    }
    if (inside.size() >= 2) {
      const std::vector<int> ds = poly.distances(inside[0], inside);
      for (std::size_t i = 0; i < inside.size(); ++i) EXPECT_EQ(std::optional<int>(ds[i]), ref.distance(inside[0], inside[i]));
    }

    // free space written two ways
    const Box dom{{b.lo.x - 1 - static_cast<Coord>(seed % 5), b.lo.y - 1}, {b.hi.x + 1, b.hi.y + 1 + static_cast<Coord>(seed % 3)}};
    Ring hole = ring;
    if (geom::twice_area(hole) > 0) std::reverse(hole.begin(), hole.end());
    const Polygon frame[1] = {Polygon{box_ring(dom), {hole}}};
    const FreeSpacePolygon f1 = router::free_space_polygon(dom, frame);
    ASSERT_EQ(f1.status, FreeSpacePolygon::Status::Ok);
    EXPECT_EQ(canonical(f1.ring), canonical(ref.corners()));
    std::vector<Polygon> cells_ = complement_cells(ring);
    const FreeSpacePolygon f2 = router::free_space_polygon(b, cells_);
    ASSERT_EQ(f2.status, FreeSpacePolygon::Status::Ok);
    EXPECT_EQ(canonical(f2.ring), canonical(ref.corners()));
    // an island: a box strictly inside the polygon's interior (a Hanan cell inside the polygon
    // shrunk by one), when a cell is wide enough: named; a wall across the bounding box, when it
    // is at least 3 wide: the polygon touches both sides of the box, so free space is left on
    // both sides of the wall
    if (const std::optional<Box> isle = inner_box(ring)) {
      std::vector<Polygon> with = cells_;
      with.push_back(Polygon{box_ring(*isle), {}});
      const FreeSpacePolygon f = router::free_space_polygon(b, with);
      EXPECT_EQ(f.status, FreeSpacePolygon::Status::Island);
      EXPECT_EQ(f.blockage, with.size() - 1);
      ++islands_checked;
    }
    if (b.hi.x - b.lo.x >= 3) {
      const Coord mx = b.lo.x + (b.hi.x - b.lo.x) / 2;
      std::vector<Polygon> with = cells_;
      with.push_back(Polygon{box_ring({{mx, b.lo.y}, {mx + 1, b.hi.y}}), {}});
      const FreeSpacePolygon f = router::free_space_polygon(b, with);
      EXPECT_EQ(f.status, FreeSpacePolygon::Status::Pieces);
      EXPECT_GE(f.pieces.size(), 2u);
      ++pieces_checked;
    }
    ++checked;
  }
  std::printf("checked %d polygons, %d queries, diameters up to %d links; %d islands and %d splits named\n", checked,
              queries, biggest, islands_checked, pieces_checked);
  if (!only_seed()) {
    EXPECT_GE(checked, count);
    EXPECT_GE(biggest, 12);
    EXPECT_GE(islands_checked, count / 10);
    EXPECT_GE(pieces_checked, count / 10);
  }
}

TEST(LinkPolygon, HandCases) {
  // a rectangle: 2 (1 between two points on a line)
  const LinkPolygon rect({{0, 0}, {10, 0}, {10, 4}, {0, 4}});
  EXPECT_EQ(rect.diameter().links, 2);
  EXPECT_EQ(rect.distance({0, 0}, {10, 0}), std::optional<int>(1));
  EXPECT_EQ(rect.distance({3, 3}, {3, 3}), std::optional<int>(0));
  EXPECT_EQ(rect.distance({3, 5}, {3, 3}), std::nullopt);
  // an L: 2 (from one arm into the corner square, then along the other arm); collinear input
  // vertices and clockwise order are accepted
  const LinkPolygon ell({{0, 0}, {0, 10}, {2, 10}, {2, 5}, {2, 2}, {10, 2}, {10, 0}, {5, 0}});
  EXPECT_EQ(ell.ring().size(), 6u);
  EXPECT_EQ(ell.diameter().links, 2);
  const std::optional<router::LinkPath> p = ell.path({1, 10}, {10, 1});
  ASSERT_TRUE(p);
  EXPECT_EQ(p->links, 2);
  EXPECT_EQ(p->length, 18);
  // at the coordinate limit (the frame around the boundary reaches one past it)
  const Coord M = geom::kMaxCoord;
  const LinkPolygon big({{-M, -M}, {M, -M}, {M, 0}, {0, 0}, {0, M}, {-M, M}});
  EXPECT_EQ(big.diameter().links, 2);
  EXPECT_EQ(big.path({M, -M}, {-M, M})->length, 4 * std::int64_t{M});
  const Polygon cut[1] = {Polygon{box_ring({{0, 0}, {M, M}}), {}}};
  const FreeSpacePolygon f = router::free_space_polygon({{-M, -M}, {M, M}}, cut);
  ASSERT_EQ(f.status, FreeSpacePolygon::Status::Ok);
  EXPECT_EQ(canonical(f.ring), canonical(big.ring()));
  // not rectilinear, not simple, a spike (which dropping collinear vertices would fold away)
  EXPECT_THROW(LinkPolygon({{0, 0}, {10, 0}, {10, 10}, {5, 10}, {5, 15}, {5, 10}, {0, 10}}), std::invalid_argument);
  EXPECT_THROW(LinkPolygon({{0, 0}, {10, 0}, {0, 10}}), std::invalid_argument);
  EXPECT_THROW(LinkPolygon({{0, 0}, {4, 0}, {4, 4}, {2, 4}, {2, 0}, {0, 0}, {0, -2}, {-2, -2}, {-2, 0}}),
               std::invalid_argument);
}

// The generated channels of `taut gen channel` (what the benchmark measures) against the
// reference, and their free space as one polygon.
TEST(LinkPolygon, GeneratedChannels) {
  for (const int seed : {1, 2, 3}) {
    for (const std::int64_t size : {10, 30, 60}) {
      io::GenOptions go;
      go.kind = io::GenKind::Channel;
      go.size = size;
      go.seed = static_cast<std::uint64_t>(seed);
      go.nets = 0;
      const io::Layout layout = io::generate_layout(go);
      const FreeSpacePolygon f = router::free_space_polygon(layout.boundary->box, io::blockage_polygons(layout));
      ASSERT_EQ(f.status, FreeSpacePolygon::Status::Ok) << seed << " " << size;
      SCOPED_TRACE("channel seed " + std::to_string(seed) + " size " + std::to_string(size));
      const LinkPolygon poly(f.ring);
      EXPECT_EQ(poly.diameter().links, oracle::LinkPolygonReference(f.ring).diameter().links);
    }
  }
}

// Windows of Moving AI maps (cells of 10 DBU that touch along edges and at corners everywhere):
// free_space_polygon() against a raster of the window's cells. Blocked cells touching even at a
// corner are one obstacle, so: a blocked 8-connected group that does not reach the window's side
// is an island; else free cells in two or more 4-connected groups are pieces; else a lattice point
// with blocked cells on one diagonal and free ones on the other is where free space touches
// itself; else the free cells' union is the polygon, and its diameter is the reference's.
TEST(LinkPolygon, MovingAiWindows) {
  TAUT_REQUIRE_SHARED_DATA();
  std::mt19937 rng(2026);
  int ok = 0, islands = 0, pieces = 0, touches = 0, empty = 0;
  for (const char* name : {"8room_000", "arena", "den520d", "maze-100-1", "random512-10-0"}) {
    const auto r = io::load_movingai_map(shared_data_dir() + "/movingai/" + name + ".map", 10);
    ASSERT_TRUE(r.layout && r.layout->boundary) << name;
    const std::vector<Polygon> all = io::blockage_polygons(*r.layout);
    const Box map = r.layout->boundary->box;
    for (int k = 0; k < sanitized_share(60, 6); ++k) {
      const int w = 3 + static_cast<int>(rng() % 12), h = 3 + static_cast<int>(rng() % 12);
      const int cx = static_cast<int>(rng() % static_cast<unsigned>((map.hi.x - map.lo.x) / 10 - w + 1));
      const int cy = static_cast<int>(rng() % static_cast<unsigned>((map.hi.y - map.lo.y) / 10 - h + 1));
      const Box win{{map.lo.x + 10 * cx, map.lo.y + 10 * cy}, {map.lo.x + 10 * (cx + w), map.lo.y + 10 * (cy + h)}};
      std::vector<Polygon> in;
      for (const Polygon& p : all) {
        const Box pb = ring_box(p.outer);
        if (pb.hi.x > win.lo.x && pb.lo.x < win.hi.x && pb.hi.y > win.lo.y && pb.lo.y < win.hi.y) in.push_back(p);
      }
      SCOPED_TRACE(std::string(name) + " window at cell " + std::to_string(cx) + "," + std::to_string(cy) + " size " +
                   std::to_string(w) + "x" + std::to_string(h));
      // the raster
      std::vector<char> blocked(static_cast<std::size_t>(w * h), 0);
      auto at = [&](int i, int j) -> char& { return blocked[static_cast<std::size_t>(j * w + i)]; };
      for (int i = 0; i < w; ++i)
        for (int j = 0; j < h; ++j) {
          const Point c{win.lo.x + 10 * i + 5, win.lo.y + 10 * j + 5};
          for (const Polygon& p : in) at(i, j) = at(i, j) || geom::locate(c, p) == geom::Location::Inside;
        }
      auto groups = [&](bool of_blocked, bool* island) {
        std::vector<int> seen(static_cast<std::size_t>(w * h), 0);
        int n = 0;
        for (int s = 0; s < w * h; ++s) {
          if (seen[static_cast<std::size_t>(s)] || (blocked[static_cast<std::size_t>(s)] != 0) != of_blocked) continue;
          ++n;
          bool border = false;
          std::vector<int> stack{s};
          seen[static_cast<std::size_t>(s)] = 1;
          while (!stack.empty()) {
            const int c = stack.back();
            stack.pop_back();
            const int i = c % w, j = c / w;
            border = border || i == 0 || j == 0 || i == w - 1 || j == h - 1;
            for (int di = -1; di <= 1; ++di)
              for (int dj = -1; dj <= 1; ++dj) {
                if ((di == 0 && dj == 0) || (!of_blocked && di != 0 && dj != 0)) continue;  // free: 4-neighbours
                const int ni = i + di, nj = j + dj;
                if (ni < 0 || nj < 0 || ni >= w || nj >= h) continue;
                const int nc = nj * w + ni;
                if (seen[static_cast<std::size_t>(nc)] || (blocked[static_cast<std::size_t>(nc)] != 0) != of_blocked) continue;
                seen[static_cast<std::size_t>(nc)] = 1;
                stack.push_back(nc);
              }
          }
          if (of_blocked && !border) *island = true;
        }
        return n;
      };
      bool island = false;
      groups(true, &island);
      const int free_groups = groups(false, nullptr);
      bool touch = false;
      for (int i = 1; i < w; ++i)
        for (int j = 1; j < h; ++j) {
          const bool a = at(i - 1, j - 1), b = at(i, j - 1), c = at(i - 1, j), d = at(i, j);
          touch = touch || (a && d && !b && !c) || (b && c && !a && !d);
        }
      const FreeSpacePolygon f = router::free_space_polygon(win, in);
      if (island) {
        EXPECT_EQ(f.status, FreeSpacePolygon::Status::Island);
        ++islands;
      } else if (free_groups == 0) {
        EXPECT_EQ(f.status, FreeSpacePolygon::Status::Empty);
        ++empty;
      } else if (free_groups > 1) {
        EXPECT_EQ(f.status, FreeSpacePolygon::Status::Pieces);
        EXPECT_EQ(f.pieces.size(), static_cast<std::size_t>(free_groups));
        ++pieces;
      } else if (touch) {
        EXPECT_EQ(f.status, FreeSpacePolygon::Status::Pieces);
        EXPECT_EQ(f.pieces.size(), 1u);
        ++touches;
      } else {
        ASSERT_EQ(f.status, FreeSpacePolygon::Status::Ok);
        std::vector<Box> cells;
        for (int i = 0; i < w; ++i)
          for (int j = 0; j < h; ++j)
            if (!at(i, j)) cells.push_back({{win.lo.x + 10 * i, win.lo.y + 10 * j}, {win.lo.x + 10 * (i + 1), win.lo.y + 10 * (j + 1)}});
        EXPECT_EQ(canonical(f.ring), canonical(union_ring(cells)));
        EXPECT_EQ(LinkPolygon(f.ring).diameter().links, oracle::LinkPolygonReference(f.ring).diameter().links);
        ++ok;
      }
    }
  }
  std::printf("Moving AI windows: %d simple polygons (diameters checked), %d with islands, %d in pieces, %d touching "
              "themselves, %d full\n", ok, islands, pieces, touches, empty);
  EXPECT_GE(ok, sanitized_share(40, 6));
  EXPECT_GE(islands + pieces + touches, sanitized_share(40, 6));
}

}  // namespace link_polygon_test
}  // namespace taut::test
