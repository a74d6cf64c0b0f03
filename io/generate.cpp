// Seeded layout generators (`taut gen`).
//
// Portability: the only source of randomness is std::mt19937_64 (its output sequence is fixed by
// the standard) mapped to ranges by hand (rejection sampling below); no floating point and no
// std::uniform_*_distribution, whose algorithms differ between standard libraries. Hence the same
// options give the same bytes everywhere.
//
// Validity by construction:
//  - star polygons: integer directions sorted exactly by angle around a centre with every
//    consecutive turn strictly counter-clockwise, which makes the fan of triangles, hence the
//    polygon, simple with non-zero area; holes lie in a disk that is checked (exactly) to be
//    strictly inside the outer ring.
//  - every pin is tested against the blockages near it with geom::locate (bucket grid), and the
//    boundary keeps an empty margin around the content so a free spot always exists.
#include "io/generate.h"

#include <algorithm>
#include <random>
#include <map>
#include <set>
#include <string>

#include "geom/predicates.h"

namespace taut::io {
namespace {

using geom::i128;
using geom::i64;

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}
  // Uniform in [0, n), n > 0: reject the low 2^64 mod n raw values so each residue is equally
  // likely.
  std::uint64_t below(std::uint64_t n) {
    const std::uint64_t threshold = (0 - n) % n;
    while (true) {
      const std::uint64_t r = engine_();
      if (r >= threshold) return r % n;
    }
  }
  // Uniform in [lo, hi] (inclusive), lo <= hi.
  i64 range(i64 lo, i64 hi) {
    return lo + static_cast<i64>(below(static_cast<std::uint64_t>(hi - lo) + 1));
  }
  bool chance(int percent) { return below(100) < static_cast<std::uint64_t>(percent); }

 private:
  std::mt19937_64 engine_;
};

i64 isqrt64(i64 v) {
  if (v <= 0) return 0;
  i64 x = v, y = (x + 1) / 2;
  while (y < x) {
    x = y;
    y = (x + v / x) / 2;
  }
  return x;
}

Shape rect_shape(i64 x0, i64 y0, i64 x1, i64 y1) {
  Shape s;
  s.kind = Shape::Kind::Rect;
  s.rect = Box{{static_cast<geom::Coord>(x0), static_cast<geom::Coord>(y0)},
               {static_cast<geom::Coord>(x1), static_cast<geom::Coord>(y1)}};
  return s;
}

Shape polygon_shape(geom::Ring outer, std::vector<geom::Ring> holes = {}) {
  Shape s;
  s.kind = Shape::Kind::Polygon;
  s.polygon.outer = std::move(outer);
  s.polygon.holes = std::move(holes);
  return s;
}

Point pt(i64 x, i64 y) { return {static_cast<geom::Coord>(x), static_cast<geom::Coord>(y)}; }

// Upper half-plane (angle in [0, pi)) first, then lower; within a half by cross product.
bool angle_less(Point a, Point b) {
  const bool ha = a.y > 0 || (a.y == 0 && a.x > 0);
  const bool hb = b.y > 0 || (b.y == 0 && b.x > 0);
  if (ha != hb) return ha;
  return i64{a.x} * b.y - i64{a.y} * b.x > 0;
}

// k >= 3 integer direction vectors d with r_in^2 <= |d|^2 <= r^2, pairwise different angles,
// sorted counter-clockwise, every consecutive pair (cyclically) a strict left turn.
std::vector<Point> star_directions(Rng& rng, int k, i64 r) {
  const i64 r_in = std::max<i64>(1, r / 3);
  while (true) {
    std::vector<Point> d;
    d.reserve(static_cast<std::size_t>(k));
    while (static_cast<int>(d.size()) < k) {
      const i64 x = rng.range(-r, r), y = rng.range(-r, r);
      const i64 n2 = x * x + y * y;
      if (n2 < r_in * r_in || n2 > r * r) continue;
      d.push_back(pt(x, y));
    }
    std::sort(d.begin(), d.end(), angle_less);
    bool ok = true;
    for (int i = 0; i < k && ok; ++i) {
      const Point a = d[static_cast<std::size_t>(i)], b = d[static_cast<std::size_t>((i + 1) % k)];
      if (i64{a.x} * b.y - i64{a.y} * b.x <= 0) ok = false;  // same angle, or gap >= pi
    }
    if (ok) return d;
  }
}

// Largest h (halving from r_min / 2) such that the closed disk of radius h around the centre
// lies strictly inside the star polygon with directions d; 0 when there is none worth using.
i64 inner_radius(const std::vector<Point>& d) {
  i64 h2_limit_num = -1;  // track via exact comparisons below
  (void)h2_limit_num;
  i64 rmin2 = INT64_MAX;
  for (Point p : d) rmin2 = std::min(rmin2, i64{p.x} * p.x + i64{p.y} * p.y);
  for (i64 h = isqrt64(rmin2) / 2; h >= 8; h /= 2) {
    bool ok = true;
    for (std::size_t i = 0; i < d.size() && ok; ++i) {
      const Point a = d[i], b = d[(i + 1) % d.size()];
      // Distance from the origin to segment ab exceeds h: either the endpoints (already
      // > h since h < rmin) or the foot of the perpendicular: cross^2 > h^2 * |b - a|^2.
      const i128 cross = i128{a.x} * b.y - i128{a.y} * b.x;
      const i128 ex = i128{b.x} - a.x, ey = i128{b.y} - a.y;
      if (cross * cross <= i128{h} * h * (ex * ex + ey * ey)) ok = false;
    }
    if (ok) return h;
  }
  return 0;
}

struct Builder {
  Layout layout;
  i64 vertices = 0;
  i64 lo_x = INT64_MAX, lo_y = INT64_MAX, hi_x = INT64_MIN, hi_y = INT64_MIN;

  void grow(i64 x, i64 y) {
    lo_x = std::min(lo_x, x);
    lo_y = std::min(lo_y, y);
    hi_x = std::max(hi_x, x);
    hi_y = std::max(hi_y, y);
  }
  void add(const char* prefix, std::vector<Shape> shapes) {
    Blockage b;
    b.id = prefix + std::to_string(layout.blockages.size());
    for (const Shape& s : shapes) {
      if (s.kind == Shape::Kind::Rect) {
        vertices += 4;
        grow(s.rect.lo.x, s.rect.lo.y);
        grow(s.rect.hi.x, s.rect.hi.y);
      } else {
        vertices += static_cast<i64>(s.polygon.outer.size());
        for (const auto& h : s.polygon.holes) vertices += static_cast<i64>(h.size());
        for (Point p : s.polygon.outer) grow(p.x, p.y);
      }
    }
    b.shapes = std::move(shapes);
    layout.blockages.push_back(std::move(b));
  }
};

// ---- rects -------------------------------------------------------------------------------
// Rectangles with corners on a 50-DBU grid in a square sized for about 30% coverage, so they
// overlap, touch and share coordinates now and then.
void gen_rects(Builder& b, Rng& rng, i64 size) {
  const i64 n = std::max<i64>(1, (size + 2) / 4);
  const i64 side = std::max<i64>(2, isqrt64(n) + 1) * 1000;
  b.layout.blockages.reserve(static_cast<std::size_t>(n));
  for (i64 i = 0; i < n; ++i) {
    const i64 w = rng.range(2, 20) * 50, h = rng.range(2, 20) * 50;
    const i64 x = rng.range(0, side / 50) * 50, y = rng.range(0, side / 50) * 50;
    b.add("b", {rect_shape(x, y, x + w, y + h)});
  }
}

// ---- polygons ----------------------------------------------------------------------------
void gen_polygons(Builder& b, Rng& rng, i64 size) {
  const i64 target = std::max<i64>(3, size);
  const i64 count_estimate = std::max<i64>(1, target / 12);
  const i64 side = std::max<i64>(2, isqrt64(count_estimate) + 1) * 1000;
  i64 left = target;
  while (left > 0) {
    const i64 r = rng.range(150, 700);
    const i64 cx = rng.range(0, side), cy = rng.range(0, side);
    int k = static_cast<int>(rng.range(3, 16));
    bool hole = k >= 6 && rng.chance(25);
    i64 hole_k = hole ? rng.range(3, 6) : 0;
    if (left < k + hole_k + 3) {  // last polygon: use up exactly what is left
      hole = false;
      hole_k = 0;
      k = static_cast<int>(std::max<i64>(3, left));
    }
    std::vector<Point> d = star_directions(rng, k, r);
    geom::Ring outer;
    outer.reserve(d.size());
    for (Point p : d) outer.push_back(pt(cx + p.x, cy + p.y));
    std::vector<geom::Ring> holes;
    if (hole) {
      const i64 h = inner_radius(d);
      if (h >= 8) {
        std::vector<Point> hd = star_directions(rng, static_cast<int>(hole_k), h);
        geom::Ring ring;
        // Holes clockwise, the usual convention (either orientation is valid).
        for (auto it = hd.rbegin(); it != hd.rend(); ++it) ring.push_back(pt(cx + it->x, cy + it->y));
        holes.push_back(std::move(ring));
      }
    }
    left -= k;
    for (const auto& hr : holes) left -= static_cast<i64>(hr.size());
    b.add("p", {polygon_shape(std::move(outer), std::move(holes))});
  }
}

// ---- maze --------------------------------------------------------------------------------
// A perfect maze (iterative depth-first search) on a W x H grid of 1000-DBU cells. Walls are
// 100 DBU thick: a pillar rect at every grid node and a wall rect between two nodes touching
// the pillars along their edges. A perfect maze keeps (W+1)(H+1) - 2 walls (with an entrance and
// an exit), so the vertex count is about 8 (W+1)(H+1).
void gen_maze(Builder& b, Rng& rng, i64 size) {
  constexpr i64 kCell = 1000, kWall = 100;
  const i64 nodes = std::max<i64>(4, size / 8);
  const i64 a = std::max<i64>(2, isqrt64(nodes));
  const i64 c = std::max<i64>(2, (nodes + a / 2) / a);
  const i64 w = a - 1, h = c - 1;  // cells
  // Walls still standing: east[y*(w+1)+x] is the vertical wall on the west side of cell x
  // (x in 0..w), north[y*w+x] the horizontal wall below cell row y (y in 0..h).
  std::vector<char> vert(static_cast<std::size_t>((w + 1) * h), 1);
  std::vector<char> horz(static_cast<std::size_t>(w * (h + 1)), 1);
  std::vector<char> seen(static_cast<std::size_t>(w * h), 0);
  std::vector<i64> stack{0};
  seen[0] = 1;
  while (!stack.empty()) {
    const i64 cell = stack.back();
    const i64 x = cell % w, y = cell / w;
    i64 options[4];
    int n = 0;
    if (x > 0 && !seen[static_cast<std::size_t>(cell - 1)]) options[n++] = 0;
    if (x + 1 < w && !seen[static_cast<std::size_t>(cell + 1)]) options[n++] = 1;
    if (y > 0 && !seen[static_cast<std::size_t>(cell - w)]) options[n++] = 2;
    if (y + 1 < h && !seen[static_cast<std::size_t>(cell + w)]) options[n++] = 3;
    if (n == 0) {
      stack.pop_back();
      continue;
    }
    const i64 dir = options[rng.below(static_cast<std::uint64_t>(n))];
    i64 next = cell;
    switch (dir) {
      case 0: vert[static_cast<std::size_t>(y * (w + 1) + x)] = 0; next = cell - 1; break;
      case 1: vert[static_cast<std::size_t>(y * (w + 1) + x + 1)] = 0; next = cell + 1; break;
      case 2: horz[static_cast<std::size_t>(y * w + x)] = 0; next = cell - w; break;
      default: horz[static_cast<std::size_t>((y + 1) * w + x)] = 0; next = cell + w; break;
    }
    seen[static_cast<std::size_t>(next)] = 1;
    stack.push_back(next);
  }
  vert[0] = 0;                                                        // entrance: west of (0,0)
  vert[static_cast<std::size_t>((h - 1) * (w + 1) + w)] = 0;          // exit: east of top right
  for (i64 y = 0; y <= h; ++y)
    for (i64 x = 0; x <= w; ++x)
      b.add("w", {rect_shape(x * kCell, y * kCell, x * kCell + kWall, y * kCell + kWall)});
  for (i64 y = 0; y <= h; ++y)
    for (i64 x = 0; x < w; ++x)
      if (horz[static_cast<std::size_t>(y * w + x)])
        b.add("w", {rect_shape(x * kCell + kWall, y * kCell, (x + 1) * kCell, y * kCell + kWall)});
  for (i64 y = 0; y < h; ++y)
    for (i64 x = 0; x <= w; ++x)
      if (vert[static_cast<std::size_t>(y * (w + 1) + x)])
        b.add("w", {rect_shape(x * kCell, y * kCell + kWall, x * kCell + kWall, (y + 1) * kCell)});
}

// ---- channel -----------------------------------------------------------------------------
// Teeth from the bottom side (y = 0) and the top side (y = H) at increasing x, on a 100-DBU grid:
// a tooth is a rectangle or a step (an L of 6 vertices); the next tooth starts after a gap of
// 1..12 units, or right at the last one's side (gap 0, same side only: they touch along an edge).
// Teeth on opposite sides never share an x, and every tooth is shorter than H, so free space is
// one simple polygon that winds around them. Heights repeat now and then (collinear edges).
void gen_channel(Builder& b, Rng& rng, i64 size) {
  constexpr i64 g = 100, H = 120;  // units
  const i64 teeth = std::max<i64>(1, (size - 4) / 5);
  i64 x = rng.range(1, 8);
  bool top = false;
  i64 last_h = 60;
  for (i64 i = 0; i < teeth; ++i) {
    const i64 w = rng.range(2, 30);
    i64 h = rng.chance(20) ? last_h : rng.range(H / 5, H - H / 5);
    last_h = h;
    auto Y = [&](i64 y) { return top ? (H - y) * g : y * g; };
    if (rng.chance(35) && w >= 4) {
      // a step: full height on one part, lower on the other
      const i64 cut = rng.range(1, w - 1), low = rng.range(1, h - 1);
      const bool left_high = rng.chance(50);
      const i64 hl = left_high ? h : low, hr = left_high ? low : h;
      geom::Ring r = {pt(x * g, Y(0)), pt((x + w) * g, Y(0)), pt((x + w) * g, Y(hr)), pt((x + cut) * g, Y(hr)),
                      pt((x + cut) * g, Y(hl)), pt(x * g, Y(hl))};
      if (top) std::reverse(r.begin(), r.end());
      b.add("t", {polygon_shape(std::move(r))});
    } else {
      b.add("t", {top ? rect_shape(x * g, (H - h) * g, (x + w) * g, H * g) : rect_shape(x * g, 0, (x + w) * g, h * g)});
    }
    x += w;
    if (rng.chance(15)) continue;  // the next tooth touches this one, on the same side
    x += rng.range(1, 12);
    if (rng.chance(80)) top = !top;
  }
  b.grow(0, 0);
  b.grow((x + rng.range(1, 8)) * g, H * g);
}

// ---- degenerate --------------------------------------------------------------------------
// Motifs on a coarse grid (unit 100 DBU) in 8x8-unit tiles: shapes share x and y, have
// collinear edges and extra collinear vertices, touch at corners and along edges (also across
// tiles: some motifs reach the tile border), and sit nested inside holes.
void gen_degenerate(Builder& b, Rng& rng, i64 size) {
  constexpr i64 g = 100, kTile = 8;
  const i64 tiles_estimate = std::max<i64>(1, size / 10);
  const i64 per_row = std::max<i64>(1, isqrt64(tiles_estimate) + 1);
  i64 tile = 0;
  while (b.vertices < size) {
    const i64 ox = (tile % per_row) * kTile * g, oy = (tile / per_row) * kTile * g;
    ++tile;
    auto P = [&](i64 x, i64 y) { return pt(ox + x * g, oy + y * g); };
    auto R = [&](i64 x0, i64 y0, i64 x1, i64 y1) {
      return rect_shape(ox + x0 * g, oy + y0 * g, ox + x1 * g, oy + y1 * g);
    };
    switch (rng.below(7)) {
      case 0:  // two rects touching along an edge, a third touching both at a corner point
        b.add("d", {R(0, 1, 3, 4)});
        b.add("d", {R(3, 1, 6, 3)});
        b.add("d", {R(6, 3, 8, 6)});
        break;
      case 1:  // L shape with a rect in its inner corner touching two edges
        b.add("d", {polygon_shape({P(1, 1), P(6, 1), P(6, 3), P(3, 3), P(3, 7), P(1, 7)})});
        b.add("d", {R(3, 3, 5, 5)});
        break;
      case 2:  // T shape with collinear extra vertices, touching the tile's top border
        b.add("d", {polygon_shape({P(3, 2), P(5, 2), P(5, 5), P(7, 5), P(7, 8), P(4, 8),
                                   P(1, 8), P(1, 5), P(3, 5)})});
        break;
      case 3: {  // square ring with a rect nested in its hole, touching the hole's edge
        b.add("d", {polygon_shape({P(1, 1), P(7, 1), P(7, 7), P(1, 7)},
                                  {{P(2, 2), P(2, 6), P(6, 6), P(6, 2)}})});
        b.add("d", {R(2, 3, 4, 5)});
        break;
      }
      case 4:  // two rects meeting at a corner only, plus a shared x with the tile border
        b.add("d", {R(0, 0, 4, 4)});
        b.add("d", {R(4, 4, 8, 7)});
        break;
      case 5:  // a blockage made of two shapes: an identical duplicate and a rect on its side
        b.add("d", {R(2, 2, 5, 5), R(2, 2, 5, 5), R(5, 2, 7, 3)});
        break;
      default:  // rectilinear U with collinear vertex on the bottom edge, and a rect inside
        b.add("d", {polygon_shape({P(1, 1), P(4, 1), P(7, 1), P(7, 6), P(5, 6), P(5, 3),
                                   P(3, 3), P(3, 6), P(1, 6)})});
        b.add("d", {R(3, 3, 5, 4)});
        break;
    }
  }
}

// ---- pins --------------------------------------------------------------------------------
// Buckets of blockage shapes by bounding box, for the free-space test of candidate pins.
class ShapeGrid {
 public:
  ShapeGrid(const Layout& layout, i64 lo_x, i64 lo_y, i64 hi_x, i64 hi_y) {
    std::size_t shapes = 0;
    for (const Blockage& bl : layout.blockages) shapes += bl.shapes.size();
    n_ = std::max<i64>(1, isqrt64(static_cast<i64>(shapes) / 4));  // about 4 shapes a cell
    lo_x_ = lo_x;
    lo_y_ = lo_y;
    cw_ = std::max<i64>(1, (hi_x - lo_x) / n_ + 1);
    ch_ = std::max<i64>(1, (hi_y - lo_y) / n_ + 1);
    cells_.resize(static_cast<std::size_t>(n_ * n_));
    for (const Blockage& bl : layout.blockages)
      for (const Shape& s : bl.shapes) {
        i64 x0, y0, x1, y1;
        if (s.kind == Shape::Kind::Rect) {
          x0 = s.rect.lo.x, y0 = s.rect.lo.y, x1 = s.rect.hi.x, y1 = s.rect.hi.y;
        } else {
          x0 = y0 = INT64_MAX;
          x1 = y1 = INT64_MIN;
          for (Point p : s.polygon.outer) {
            x0 = std::min<i64>(x0, p.x), y0 = std::min<i64>(y0, p.y);
            x1 = std::max<i64>(x1, p.x), y1 = std::max<i64>(y1, p.y);
          }
        }
        for (i64 cy = cell_y(y0); cy <= cell_y(y1); ++cy)
          for (i64 cx = cell_x(x0); cx <= cell_x(x1); ++cx)
            cells_[static_cast<std::size_t>(cy * n_ + cx)].push_back(&s);
      }
  }

  // Worst location of p over all shapes: Inside beats Boundary beats Outside. `on_boundaries`
  // counts the shapes with p on their boundary.
  geom::Location locate(Point p, int* on_boundaries) const {
    geom::Location worst = geom::Location::Outside;
    *on_boundaries = 0;
    for (const Shape* s : cells_[static_cast<std::size_t>(cell_y(p.y) * n_ + cell_x(p.x))]) {
      geom::Location l;
      if (s->kind == Shape::Kind::Rect) {
        const Box& r = s->rect;
        if (p.x < r.lo.x || p.x > r.hi.x || p.y < r.lo.y || p.y > r.hi.y)
          l = geom::Location::Outside;
        else if (p.x == r.lo.x || p.x == r.hi.x || p.y == r.lo.y || p.y == r.hi.y)
          l = geom::Location::Boundary;
        else
          l = geom::Location::Inside;
      } else {
        l = geom::locate(p, s->polygon);
      }
      if (l == geom::Location::Inside) return l;
      if (l == geom::Location::Boundary) {
        worst = l;
        ++*on_boundaries;
      }
    }
    return worst;
  }

 private:
  i64 cell_x(i64 x) const { return std::clamp<i64>((x - lo_x_) / cw_, 0, n_ - 1); }
  i64 cell_y(i64 y) const { return std::clamp<i64>((y - lo_y_) / ch_, 0, n_ - 1); }
  i64 n_ = 1, lo_x_ = 0, lo_y_ = 0, cw_ = 1, ch_ = 1;
  std::vector<std::vector<const Shape*>> cells_;
};

}  // namespace

std::optional<GenKind> parse_gen_kind(const std::string& name) {
  if (name == "rects") return GenKind::Rects;
  if (name == "polygons") return GenKind::Polygons;
  if (name == "maze") return GenKind::Maze;
  if (name == "degenerate") return GenKind::Degenerate;
  if (name == "channel") return GenKind::Channel;
  return std::nullopt;
}

std::string gen_kind_name(GenKind kind) {
  switch (kind) {
    case GenKind::Rects: return "rects";
    case GenKind::Polygons: return "polygons";
    case GenKind::Maze: return "maze";
    case GenKind::Degenerate: return "degenerate";
    case GenKind::Channel: return "channel";
  }
  return "rects";
}

std::vector<std::string> gen_kind_names() { return {"rects", "polygons", "maze", "degenerate", "channel"}; }

Layout generate_layout(const GenOptions& options) {
  Rng rng(options.seed);
  Builder b;
  const i64 size = std::max<i64>(1, options.size);
  switch (options.kind) {
    case GenKind::Rects: gen_rects(b, rng, size); break;
    case GenKind::Polygons: gen_polygons(b, rng, size); break;
    case GenKind::Maze: gen_maze(b, rng, size); break;
    case GenKind::Degenerate: gen_degenerate(b, rng, size); break;
    case GenKind::Channel: gen_channel(b, rng, size); break;
  }
  Layout& layout = b.layout;
  layout.name = gen_kind_name(options.kind) + "-" + std::to_string(options.size) + "-seed" +
                std::to_string(options.seed);
  // An empty margin around the content: the routing area has a way around everything and a
  // pin always finds a free spot.
  // (A channel's boundary is its teeth's box: the teeth cut into it.)
  const i64 kMargin = options.kind == GenKind::Channel ? 0 : 1000;
  if (b.lo_x > b.hi_x) b.lo_x = b.lo_y = b.hi_x = b.hi_y = 0;
  const i64 x0 = b.lo_x - kMargin, y0 = b.lo_y - kMargin;
  const i64 x1 = b.hi_x + kMargin, y1 = b.hi_y + kMargin;
  layout.boundary = Boundary{Box{pt(x0, y0), pt(x1, y1)}, 0};

  const ShapeGrid grid(layout, b.lo_x, b.lo_y, b.hi_x, b.hi_y);
  // Degenerate layouts place pins on the coarse half-grid, so they land on blockage boundaries
  // and corners (valid, and worth testing); the other kinds keep pins strictly in free space.
  // A pin on the boundary of exactly one shape (and outside all others, which are closed) has
  // free space next to it; on two touching shapes it could be enclosed by their union.
  const bool degenerate = options.kind == GenKind::Degenerate;
  std::set<Point> used;
  // With rules, pins of different nets keep 2(w + s) + 2 apart: a grid of cells that size holds
  // the pins placed so far, with their nets.
  const i64 gap = options.wire_width + options.spacing > 0 ? 2 * (options.wire_width + options.spacing) + 2 : 0;
  std::map<std::pair<i64, i64>, std::vector<std::pair<Point, int>>> near_cells;
  int current_net = 0;
  auto crowded = [&](Point p) {
    if (gap == 0) return false;
    const i64 cx = (i64{p.x} - x0) / gap, cy = (i64{p.y} - y0) / gap;
    for (i64 dx = -1; dx <= 1; ++dx)
      for (i64 dy = -1; dy <= 1; ++dy)
        if (auto it = near_cells.find({cx + dx, cy + dy}); it != near_cells.end())
          for (const auto& [q, net] : it->second)
            if (net != current_net && std::abs(i64{p.x} - q.x) < gap && std::abs(i64{p.y} - q.y) < gap) return true;
    return false;
  };
  auto remember = [&](Point p) {
    if (gap > 0) near_cells[{(i64{p.x} - x0) / gap, (i64{p.y} - y0) / gap}].push_back({p, current_net});
    return p;
  };
  // a local pin: within a square of a tenth of the layout's side round `c`
  const i64 reach = std::max<i64>((x1 - x0) / 20, 100);
  std::optional<Point> centre;
  auto pick = [&]() {
    for (int attempt = 0; attempt < 200; ++attempt) {
      Point p;
      if (degenerate)
        p = pt(x0 + 50 * rng.range(1, (x1 - x0) / 50 - 1), y0 + 50 * rng.range(1, (y1 - y0) / 50 - 1));
      else if (centre)
        p = pt(std::clamp(centre->x + rng.range(-reach, reach), x0 + 1, x1 - 1), std::clamp(centre->y + rng.range(-reach, reach), y0 + 1, y1 - 1));
      else
        p = pt(rng.range(x0 + 1, x1 - 1), rng.range(y0 + 1, y1 - 1));
      if (used.count(p) || crowded(p)) continue;
      int on_boundaries = 0;
      const geom::Location l = grid.locate(p, &on_boundaries);
      if (l == geom::Location::Inside) continue;
      if (l == geom::Location::Boundary && (!degenerate || on_boundaries > 1)) continue;
      used.insert(p);
      return remember(p);
    }
    // Crowded: fall back to the empty margin on the left (x0, x0 + kMargin); a channel has no
    // margin, but at least a third of its box is free: keep drawing.
    while (kMargin == 0) {
      const Point p = pt(rng.range(x0 + 1, x1 - 1), rng.range(y0 + 1, y1 - 1));
      int ignored = 0;
      if (used.count(p) || crowded(p) || grid.locate(p, &ignored) != geom::Location::Outside) continue;
      used.insert(p);
      return remember(p);
    }
    while (true) {
      const Point p = pt(rng.range(x0 + 1, x0 + kMargin - 1), rng.range(y0 + 1, y1 - 1));
      if (!crowded(p) && used.insert(p).second) return remember(p);
    }
  };
  if (options.wire_width > 0 || options.spacing > 0) layout.rules = Rules{options.wire_width, options.spacing, 0, "rectilinear", {}, 0};
  const bool multi = options.max_pins > 2;
  for (int i = 0; i < options.nets; ++i) {
    Net n;
    n.name = "n" + std::to_string(i);
    current_net = i;
    const int k = options.min_pins == options.max_pins ? options.min_pins
                                                        : static_cast<int>(rng.range(options.min_pins, options.max_pins));
    centre.reset();
    for (int j = 0; j < k; ++j) {
      Pin p;
      p.name = k == 2 && !multi ? std::string(j == 0 ? "a" : "b") : "p" + std::to_string(j);
      p.point = pick();
      if (multi && j == 0) centre = *p.point;
      n.pins.push_back(std::move(p));
    }
    layout.nets.push_back(std::move(n));
  }
  return std::move(b.layout);
}

}  // namespace taut::io
