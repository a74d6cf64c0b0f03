#include "router/tighten_nets.h"

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <utility>

#include "geom/predicates.h"
#include "geom/root2.h"
#include "geom/root3.h"
#include "router/radical_sum.h"
#include "router/rational_root.h"
#include "router/l1_router.h"

namespace taut::router {

using geom::Box;
using geom::Point;
using geom::Polygon;

SpaceTightener::SpaceTightener(const geom::NormalizedObstacles& norm, TightenOrientations orientations,
                               std::int64_t snap_scale)
    : orientations_(orientations), tri_(geom::triangulate_free_space(norm.domain, norm.obstacles)) {
  if (!tri_.ok()) {
    std::string why;
    for (const Diagnostic& d : tri_.diagnostics()) why += " [" + d.code + "] " + d.message;
    throw std::logic_error("the free space of normalized obstacles could not be triangulated:" + why);
  }
  tight_ = std::make_unique<Tightener>(tri_);
  if (orientations_.set) {
    StaircaseOptions so;
    so.snap_scale = snap_scale;
    sb_ = std::make_unique<StaircaseBuilder>(norm.domain, norm.obstacles, so);
  }
  if (orientations_.set30) sb30_ = std::make_unique<Root3StaircaseBuilder>(norm.domain, norm.obstacles);
}

bool TightenOrientations::runs_in(std::span<const Point> line) const {
  return set ? set->runs_along(line) : set30 ? set30->runs_within(line) : true;
}

std::string TightenOrientations::name() const { return set ? set->name() : set30 ? set30->name() : "any"; }

bool TightenOrientations::cones_leave_box() const {
  return (set && set->cones_leave_box()) || (set30 && set30->cones_leave_box());
}

bool SpaceTightener::is_loop(std::span<const Point> line) {
  if (line.size() < 3 || line.front() != line.back()) return false;
  for (Point p : line)
    if (p != line.front()) return true;
  return false;
}

SpaceTightener::Result SpaceTightener::run(std::span<const Point> line) const {
  Result r;
  if (is_loop(line)) {
    r.loop = true;
    const Tightener::Loop l = tight_->tighten_loop(line);
    r.taut.status = l.status;
    r.taut.segment = l.segment;
    r.taut.where = l.where;
    r.taut.sleeve = l.band;
    if (l.status != TightenStatus::Ok) return r;
    if (l.contractible) {
      r.contractible = true;
      return r;
    }
    r.taut.points = l.points;
  } else {
    r.taut = tight_->tighten(line);
    if (r.taut.status != TightenStatus::Ok) return r;
  }
  r.points = r.taut.points;
  if (sb_) {
    COriented c;
    try {
      c = c_oriented(*tight_, *sb_, r.taut.points, *orientations_.set);
    } catch (const StaircaseTooFine&) {  // (snap_scale > 1 only): taken as none
    }
    if (c.points.empty()) {
      r.no_staircase = true;
      r.points.clear();
      return r;
    }
    r.points = std::move(c.points);
  }
  if (sb30_) {
    // The exact wire rounded, checked by tightening it back to the taut wire
    Root3Wire w = c_oriented(*tight_, *sb30_, r.taut.points, *orientations_.set30);
    if (!w.ok()) {
      r.no_staircase = true;
      r.why = std::move(w.why);
      r.points.clear();
      return r;
    }
    r.points = std::move(w.points);
  }
  if (r.points.size() == 1) r.points.push_back(r.points[0]);
  return r;
}

namespace {

// Where along a wire a point lies: segment index, then the position along it (exact, as the
// dot product with the segment's direction).
struct Cut {
  std::size_t seg;
  std::int64_t along;
  Point p;
  bool operator<(const Cut& o) const { return seg != o.seg ? seg < o.seg : along < o.along; }
};

using geom::boxes_meet;

// Twelve times a polyline's length in the convex distance of a set at multiples of 30 degrees,
// a + b sqrt3, summed in __int128 (each segment's is below 2^47) and compared exactly
// (router::sign_wide: in __int128 below 2^61, in GMP past it).
struct Length30 {
  __int128 a = 0, b = 0;
  Length30(const geom::Root3Directions& set, std::span<const Point> line) {
    for (std::size_t j = 1; j < line.size(); ++j) {
      const geom::Root3 l = set.length12(std::int64_t{line[j].x} - line[j - 1].x, std::int64_t{line[j].y} - line[j - 1].y);
      a += l.a, b += l.b;
    }
  }
  friend auto operator<=>(const Length30& x, const Length30& y) { return sign_wide<3>(x.a - y.a, x.b - y.b) <=> 0; }
  friend bool operator==(const Length30& x, const Length30& y) { return x.a == y.a && x.b == y.b; }
};

}  // namespace

NetLines cut_at_joints(const NetLines& wires, std::span<const Polygon> pins, std::vector<char>* frozen) {
  // The fixed points: every wire's ends and the point pins; for every wire that touches a shape
  // pin other than at its ends, a vertex of it on the shape (it joins the net through the shape,
  // and must keep touching it), or, when it touches the shape mid-segment only, the whole wire
  // stays as it is.
  std::vector<Point> joints;
  for (const auto& w : wires)
    if (!w.empty()) joints.push_back(w.front()), joints.push_back(w.back());
  std::vector<char> freeze(wires.size(), 0);
  for (const Polygon& pin : pins) {
    if (pin.outer.size() == 1) {
      joints.push_back(pin.outer[0]);
      continue;
    }
    const Box pb = geom::bounding_box(pin.outer);
    auto on = [&](Point p) { return geom::locate(p, pin) != geom::Location::Outside; };
    for (std::size_t k = 0; k < wires.size(); ++k) {
      const auto& w = wires[k];
      if (w.empty() || !boxes_meet(geom::bounding_box(w), pb) || on(w.front()) || on(w.back())) continue;
      const auto v = std::find_if(w.begin(), w.end(), on);
      if (v != w.end()) {
        joints.push_back(*v);
        continue;
      }
      bool touches = false;
      for (std::size_t s = 0; s + 1 < w.size() && !touches; ++s)
        for (std::size_t e = 0; e < pin.outer.size() && !touches; ++e)
          touches = geom::intersect({w[s], w[s + 1]}, {pin.outer[e], pin.outer[(e + 1) % pin.outer.size()]}) !=
                    geom::SegmentIntersection::None;
      if (touches) freeze[k] = 1;
    }
  }
  std::sort(joints.begin(), joints.end());
  joints.erase(std::unique(joints.begin(), joints.end()), joints.end());

  NetLines out;
  std::vector<char> out_frozen;
  for (std::size_t k = 0; k < wires.size(); ++k) {
    const auto& w = wires[k];
    if (w.size() < 2 || SpaceTightener::is_loop(w)) {
      out.push_back(w);
      out_frozen.push_back(freeze[k]);
      continue;
    }
    std::vector<Cut> cuts;
    for (std::size_t s = 0; s + 1 < w.size(); ++s) {
      const Point a = w[s], b = w[s + 1];
      if (a == b) continue;
      const Box sb = geom::bounding_box(std::vector<Point>{a, b});
      auto lo = std::lower_bound(joints.begin(), joints.end(), Point{sb.lo.x, std::numeric_limits<geom::Coord>::min()});
      for (auto it = lo; it != joints.end() && it->x <= sb.hi.x; ++it) {
        const Point j = *it;
        if (j.y < sb.lo.y || j.y > sb.hi.y || !geom::on_segment(j, a, b)) continue;
        if (j == b || (j == a && s == 0)) continue;  // an end of the wire, or cut as the next segment's start
        cuts.push_back({s, geom::dot(a, b, a, j), j});
      }
    }
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end(), [](const Cut& x, const Cut& y) { return x.seg == y.seg && x.p == y.p; }),
               cuts.end());
    std::vector<Point> piece{w[0]};
    std::size_t c = 0;
    for (std::size_t s = 0; s + 1 < w.size(); ++s) {
      for (; c < cuts.size() && cuts[c].seg == s; ++c) {
        const Point j = cuts[c].p;
        if (j != piece.back()) piece.push_back(j);
        if (piece.size() >= 2) {
          out.push_back(piece);
          out_frozen.push_back(freeze[k]);
        }
        piece.assign(1, j);
      }
      if (w[s + 1] != piece.back()) piece.push_back(w[s + 1]);
    }
    if (piece.size() == 1) piece.push_back(piece[0]);  // a wire of zero-length segments only
    out.push_back(piece);
    out_frozen.push_back(freeze[k]);
  }
  if (frozen) *frozen = std::move(out_frozen);
  return out;
}

bool one_point(std::span<const Point> line) {
  return std::all_of(line.begin(), line.end(), [&](Point p) { return p == line.front(); });
}

NetLines join_at_twos(const NetLines& wires, std::span<const Polygon> pins) {
  std::map<Point, int> ends;
  for (const auto& w : wires)
    if (w.size() >= 2 && w.front() != w.back()) ++ends[w.front()], ++ends[w.back()];
  auto on_pin = [&](Point p) {
    for (const Polygon& g : pins)
      if (g.outer.size() == 1 ? g.outer[0] == p : geom::locate(p, g) != geom::Location::Outside) return true;
    return false;
  };
  auto joinable = [&](Point p) { return ends.count(p) && ends[p] == 2 && !on_pin(p); };
  std::vector<char> used(wires.size(), 0);
  // the other wire (not k) ending at p, unused
  auto partner = [&](std::size_t k, Point p) -> std::optional<std::size_t> {
    for (std::size_t j = 0; j < wires.size(); ++j)
      if (j != k && !used[j] && wires[j].size() >= 2 && wires[j].front() != wires[j].back() &&
          (wires[j].front() == p || wires[j].back() == p))
        return j;
    return std::nullopt;
  };
  NetLines out;
  for (std::size_t k = 0; k < wires.size(); ++k) {
    if (used[k]) continue;
    used[k] = 1;
    std::vector<Point> line = wires[k];
    if (line.size() < 2 || line.front() == line.back()) {
      out.push_back(std::move(line));
      continue;
    }
    for (int side = 0; side < 2; ++side) {  // forward from the back, then backward from the front
      while (joinable(line.back())) {
        const auto j = partner(k, line.back());
        if (!j) break;
        std::vector<Point> next = wires[*j];
        if (next.front() != line.back()) std::reverse(next.begin(), next.end());
        if (next.back() == line.front()) break;  // it would close a cycle: a wire stays open
        used[*j] = 1;
        line.insert(line.end(), next.begin() + 1, next.end());
      }
      std::reverse(line.begin(), line.end());
    }
    out.push_back(std::move(line));
  }
  return out;
}

namespace {

// The polyline without repeated points and without vertices where it goes straight on.
std::vector<Point> canonical(const std::vector<Point>& w) {
  std::vector<Point> out;
  for (const Point p : w) {
    if (!out.empty() && out.back() == p) continue;
    if (out.size() >= 2 && geom::orient(out[out.size() - 2], out.back(), p) == 0 &&
        geom::dot(out[out.size() - 2], out.back(), out.back(), p) > 0)
      out.back() = p;
    else
      out.push_back(p);
  }
  return out;
}

// Does the path have a vertex on a side of the window that lies inside the domain?
bool on_inner_side(std::span<const Point> path, const Box& w, const Box& dom) {
  for (const Point p : path)
    if ((p.x == w.lo.x && w.lo.x > dom.lo.x) || (p.x == w.hi.x && w.hi.x < dom.hi.x) ||
        (p.y == w.lo.y && w.lo.y > dom.lo.y) || (p.y == w.hi.y && w.hi.y < dom.hi.y))
      return true;
  return false;
}

Box hull_box(const std::optional<Box>& a, const Box& b) {
  if (!a) return b;
  return {{std::min(a->lo.x, b.lo.x), std::min(a->lo.y, b.lo.y)}, {std::max(a->hi.x, b.hi.x), std::max(a->hi.y, b.hi.y)}};
}

}  // namespace

namespace {

// The wires without repeats (two wires pulled onto the same path are the same metal: once).
NetLines once(const NetLines& wires) {
  NetLines out;
  for (const auto& w : wires) {
    const std::vector<Point> r(w.rbegin(), w.rend());
    if (std::find(out.begin(), out.end(), w) == out.end() && std::find(out.begin(), out.end(), r) == out.end())
      out.push_back(w);
  }
  return out;
}

// The wires without overlaps (without_overlaps), or, when that leaves nothing of wires that were
// there (each of zero length: pins that share a point, joined by a wire of one point), the first
// of them as it is (a net's metal must not vanish).
NetLines metal(const NetLines& wires) {
  NetLines m = without_overlaps(wires);
  if (m.empty() && !wires.empty()) m.push_back(wires.front());
  return m;
}

// A net's wires as they are written: without overlaps, joined where exactly two end.
NetLines written(const NetLines& wires) { return join_at_twos(once(metal(wires))); }

// A net's wires as they are tightened: without overlaps (where two were pulled along one path),
// cut at the joints, once, joined where two end off the pins
// (the frozen ones, reaching a shape pin mid-segment, stay as they are); frozen flags per wire.
NetLines prepare(const NetLines& wires, std::span<const Polygon> pins, std::vector<char>& frozen) {
  std::vector<char> fz;
  const NetLines cut = cut_at_joints(metal(wires), pins, &fz);
  NetLines loose, out;
  std::vector<Polygon> fixed(pins.begin(), pins.end());  // never joined at: pins, frozen wires' ends
  for (std::size_t k = 0; k < cut.size(); ++k)
    if (!fz[k])
      loose.push_back(cut[k]);
    else
      fixed.push_back(Polygon{{cut[k].front()}, {}}), fixed.push_back(Polygon{{cut[k].back()}, {}});
  out = join_at_twos(once(loose), fixed);
  frozen.assign(out.size(), 0);
  for (std::size_t k = 0; k < cut.size(); ++k)
    if (fz[k]) {
      out.push_back(cut[k]);
      frozen.push_back(1);
    }
  return out;
}

}  // namespace

NetsTightener::NetsTightener(NetSpace& space, NetsTightenOptions options) : space_(&space), options_(std::move(options)) {}

std::vector<NetTightenOutcome> NetsTightener::run(std::vector<NetLines>& wires, std::span<const Input> kind) {
  NetSpace& space = *space_;
  const std::size_t n = space.size();
  if (wires.size() != n) throw std::invalid_argument("NetsTightener::run: one entry of wires per net");
  // Sketch nets' lines are not metal: a sketch may run along itself (a spiral winding twice round
  // a core, and its taut wire too), so they are never cut, joined or cleared of overlaps.
  auto is_sketch = [&](std::size_t i) { return i < kind.size() && (kind[i] == Input::Sketch || kind[i] == Input::TautSketch); };
  auto as_drawn = [&](std::size_t i) { return i < kind.size() && kind[i] == Input::Sketch; };
  auto checked = [&](std::size_t i) { return as_drawn(i) || (i < kind.size() && kind[i] == Input::CheckedWires); };
  stats_ = {};
  std::vector<NetTightenOutcome> out(n);
  std::vector<std::vector<char>> frozen(n);
  std::vector<std::vector<std::string>> piece_why(n);  // per piece: why it has no wire in a 30-degree set
  // a closed piece of a router's wires (a tree with a cycle) is no loop sketch: kept as it is
  auto freeze_loops = [&](std::size_t i) {
    for (std::size_t k = 0; k < wires[i].size(); ++k) frozen[i][k] = frozen[i][k] || SpaceTightener::is_loop(wires[i][k]);
  };
  std::vector<std::vector<double>> taut_len(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (const auto& w : wires[i]) {
      out[i].length_before += euclidean_length(w);
      out[i].bends_before += geom::count_bends(w);
      out[i].loop = out[i].loop || SpaceTightener::is_loop(w);
    }
    const std::size_t before = wires[i].size();
    if (is_sketch(i)) {
      frozen[i].assign(wires[i].size(), 0);
    } else {
      wires[i] = prepare(wires[i], space.net(i).pins, frozen[i]);
      freeze_loops(i);
    }
    stats_.split += wires[i].size() > before ? wires[i].size() - before : 0;
    taut_len[i].resize(wires[i].size());
    out[i].kept.assign(frozen[i].begin(), frozen[i].end());
    for (std::size_t k = 0; k < wires[i].size(); ++k) taut_len[i][k] = euclidean_length(wires[i][k]);
    space.set_wires(i, wires[i]);
  }

  const std::int64_t margin0 = 2 * (space.blockage_clearance() + space.net_clearance()) + 64;
  const Box dom = space.domain();
  // The window round a line: its box grown by the margin, clipped to the domain; the whole domain
  // when that leaves no area (a line far outside the domain, as a hand-edited wire: its lift then
  // fails there, at the first point outside, as it does without windows; since 2026-12-06, before
  // which the empty window reached the triangulation and taut tighten --clearance exited 3;
  // found by fuzzing).
  auto window = [&](const std::vector<Point>& line, std::int64_t margin) {
    if (!options_.windows) return dom;
    const Box w = geom::clipped_box(geom::grown_box(geom::bounding_box(line), margin), dom);
    return w.lo.x < w.hi.x && w.lo.y < w.hi.y ? w : dom;
  };
  std::vector<std::pair<Box, std::size_t>> changed;  // boxes of every net's wires changed, with the net
  std::vector<std::size_t> since(n, 0);
  std::vector<std::optional<Box>> seen(n);  // the windows a net's last tightening used (their hull)
  std::vector<char> failed(n, 0), retry(n, 0);

  // One wire of net i in growing windows: the result and the window it was decided in.
  // In a set whose cones do not bracket a link's box (c:0,45, c:45,135:
  // LatticeDirections::cones_leave_box), a staircase leaves the box of its link's ends, by up to |dx| + |dy| (the
  // parallelogram of its two steps): the window starts that much larger than the line's box, and
  // grows while the staircase, not only the taut path, reaches one of its inner sides (its walls
  // would otherwise cost links: a zigzag of one bend per window width; found by fuzzing,
  // 2026-12-06). The second rule is a safety net: a probe (2026-12-06) never saw it decide a growth
  // that the taut path's own rule did not, over every design routed and tightened in the four sets
  // above with --clearance, 35 generated layouts (rects, polygons, maze, degenerate) likewise, and
  // every tightening test; each link's staircase lies in its parallelogram, which the first margin
  // holds when the taut path stays in the line's box.
  const bool wide_set = options_.orientations.cones_leave_box();
  auto tighten_one = [&](std::size_t i, const std::vector<Point>& line) {
    std::int64_t margin = margin0;
    if (wide_set) {
      const Box bb = geom::bounding_box(line);
      margin = std::min<std::int64_t>(margin0 + options_.orientations.box_growth() *
                                                    ((std::int64_t{bb.hi.x} - bb.lo.x) + (std::int64_t{bb.hi.y} - bb.lo.y)),
                                      4 * std::int64_t{geom::kMaxCoord});
    }
    while (true) {
      if (options_.stop && options_.stop()) throw NetRouterStopped();
      const Box w = window(line, margin);
      const bool whole = w == dom;
      ++stats_.windows;
      stats_.whole += whole;
      const SpaceTightener st(space.obstacles(i, NetSpaceLevel::Full, whole ? std::nullopt : std::optional<Box>(w)),
                              options_.orientations, options_.snap_scale);
      SpaceTightener::Result r = st.run(line);
      if (whole || r.taut.status != TightenStatus::Ok || r.contractible ||
          (!on_inner_side(r.taut.points, w, dom) && !(wide_set && on_inner_side(r.points, w, dom))))
        return std::make_pair(std::move(r), w);
      margin = std::min<std::int64_t>(4 * margin, 4 * std::int64_t{geom::kMaxCoord});
    }
  };
  // the lengths in a set at other angles (Root3Directions without a mask)
  std::optional<SetLength> other_angles;
  if (options_.orientations.set30 && options_.orientations.set30->mask() == 0) other_angles.emplace(*options_.orientations.set30);
  // Is the new wire taken in place of the old one?
  // A router's wire: no longer, no more bends, better in one. A sketch's wire (no bends promised):
  // shorter, or as long with fewer bends.
  auto better = [&](const std::vector<Point>& now, const std::vector<Point>& was, bool sketch_net) {
    const std::vector<Point> a = canonical(now), b = canonical(was);
    if (a == b) return false;
    const std::int64_t ba = geom::count_bends(a), bb = geom::count_bends(b);
    // c: the sign of the new length less the old, each decided once
    auto rule = [&](int c) {
      return sketch_net ? (c < 0 || (c == 0 && ba < bb)) : (c <= 0 && ba <= bb && (c < 0 || ba < bb));
    };
    auto sign = [](const auto& la, const auto& lb) { return la < lb ? -1 : lb < la ? 1 : 0; };
    // lengths in the set's convex distance (twice them: exact also with half steps)
    if (options_.orientations.set) return rule(sign(options_.orientations.set->length2(a), options_.orientations.set->length2(b)));
    // a set at multiples of 30 degrees: the rounded wires' lengths in its convex distance (twelve
    // times them, in Z[sqrt3]; a rounded segment is not exactly along the set, so this is the
    // length of the shortest path in the set between its ends, summed)
    if (options_.orientations.set30 && options_.orientations.set30->mask() != 0)
      return rule(sign(Length30(*options_.orientations.set30, a), Length30(*options_.orientations.set30, b)));
    // a set at other angles (steps of different lengths): sums of square roots, exact
    // (router/radical_sum.h; its table made once, above)
    if (other_angles) return rule(((*other_angles)(a) - (*other_angles)(b)).sign());
    return true;  // any angle: the class's shortest, and another path: strictly shorter
  };

  // Round 0: the sketches (inputs that are not wires of a router) must lie in their net's space as
  // they are, all of them as given (so a failure is the input's, not a neighbour's move). A net
  // that fails here is not tightened; its wires stay in the space as they are.
  // The lift of a line in net i's space as it is now, in a window round the line.
  auto lift_now = [&](std::size_t i, const std::vector<Point>& line, std::size_t* seg, Point* where) {
    if (options_.stop && options_.stop()) throw NetRouterStopped();
    const Box w = window(line, margin0);
    const SpaceTightener st(space.obstacles(i, NetSpaceLevel::Full, w == dom ? std::nullopt : std::optional<Box>(w)),
                            TightenOrientations::Any);
    const Tightener& t = st.tightener();
    if (SpaceTightener::is_loop(line)) {  // closed up at its start, which may be an obstacle's vertex
      std::vector<std::int32_t> cycle;
      return t.band(line, cycle, seg, where);
    }
    Sleeve sleeve;
    return t.lift(line, sleeve, seg, where);
  };
  // Pieces that must be replaced (sketch pieces, and wire pieces with a segment outside the
  // output's directions, as `taut tighten --orientations rectilinear` on octilinear wires gives)
  // and that no result has replaced yet: their first result is taken whatever it is, and one
  // left at the end is untightened (a wire kept as it was would be written in directions the
  // output does not have).
  std::vector<std::vector<char>> fresh(n);
  auto off_set = [&](const std::vector<Point>& line) { return !options_.orientations.runs_in(line); };
  auto mark_off_set = [&](std::size_t i) {  // a net of wires: its pieces outside the set, if any
    fresh[i].clear();
    for (std::size_t k = 0; k < wires[i].size(); ++k)
      if (off_set(wires[i][k])) {
        fresh[i].resize(wires[i].size(), 0);
        fresh[i][k] = 1;
      }
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (wires[i].empty()) continue;
    if (!as_drawn(i) && !is_sketch(i)) mark_off_set(i);
    if (!checked(i)) continue;
    if (as_drawn(i)) fresh[i].assign(wires[i].size(), 1);
    NetTightenOutcome& o = out[i];
    for (std::size_t k = 0; k < wires[i].size() && o.status == NetTightenOutcome::Status::Ok; ++k) {
      const std::vector<Point>& line = wires[i][k];
      if (!as_drawn(i) && one_point(line)) continue;  // a wire of one point (pins that meet): nothing to lift
      std::size_t seg = 0;
      Point where{};
      const TightenStatus st = lift_now(i, line, &seg, &where);
      if (st == TightenStatus::Ok) continue;
      o.status = NetTightenOutcome::Status::NotFree;
      o.round = 0;
      o.wire = k;
      o.lift.status = st;
      o.lift.segment = seg;
      o.lift.where = where;
      o.wire_blockers = space.wire_blockers(i, line);
      o.pin_blockers = space.pin_blockers(i, line);
      failed[i] = 2;  // stays in the space, not tightened
    }
  }

  // The sketches' first results, all against the space as given (so none depends on the order of
  // the nets): in round 1 each is taken when it still enters no other net's grown wires or pins as
  // they are then, else the piece is tightened among them as they are.
  using Decided = std::pair<SpaceTightener::Result, Box>;
  std::vector<std::vector<std::optional<Decided>>> first(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (fresh[i].empty() || failed[i]) continue;
    first[i].resize(wires[i].size());
    for (std::size_t k = 0; k < wires[i].size(); ++k)
      if (!frozen[i][k] && wires[i][k].size() >= 2) {
        ++stats_.tightenings;
        first[i][k] = tighten_one(i, wires[i][k]);
      }
  }

  // Net i's wires cut anew (prepare: `recut`, frozen flags `fz`) replace its pieces, tried in the
  // next round (fresh[i]: pieces outside the set, if any, marked again).
  auto adopt = [&](std::size_t i, NetLines recut, std::vector<char> fz) {
    wires[i] = std::move(recut);
    mark_off_set(i);
    frozen[i] = std::move(fz);
    freeze_loops(i);
    out[i].kept.assign(frozen[i].begin(), frozen[i].end());
    piece_why[i].clear();
    taut_len[i].clear();
    for (const auto& w : wires[i]) taut_len[i].push_back(euclidean_length(w));
    retry[i] = 1;
  };
  bool recut_tried = false;  // the last round ended the rounds' moves, and the pieces were cut again (below)
  for (int round = 1;; ++round) {
    bool moved = false;
    for (std::size_t i = 0; i < n; ++i) {
      if (wires[i].empty() || failed[i]) continue;
      if (round > 1 && !retry[i]) {
        bool touched = false;
        for (std::size_t k = since[i]; k < changed.size() && !touched; ++k)
          touched = changed[k].second != i && seen[i] && boxes_meet(changed[k].first, *seen[i]);
        if (!touched) continue;
      }
      // a net that takes a result computed against the space as given answers to every change
      // since then: round 1's moves of the nets before it are tried against in round 2
      since[i] = round == 1 && !first[i].empty() ? 0 : changed.size();
      seen[i].reset();
      retry[i] = 0;
      NetTightenOutcome& o = out[i];
      NetLines next = wires[i];
      bool net_moved = false;
      for (std::size_t k = 0; k < wires[i].size(); ++k) {
        if (frozen[i][k] || wires[i][k].size() < 2 || (wires[i][k].size() == 2 && wires[i][k][0] == wires[i][k][1]))
          continue;
        std::optional<Decided> d;
        if (round == 1 && !first[i].empty() && first[i][k]) {
          d = std::move(first[i][k]);
          const SpaceTightener::Result& f = d->first;
          // still apart from the others (touching allowed: a gap of exactly the clearance, which
          // a lift in the space would close, is legal)
          if (f.taut.status == TightenStatus::Ok && !f.contractible && !f.no_staircase &&
              (!space.wire_blockers(i, f.points).empty() || !space.pin_blockers(i, f.points).empty()))
            d.reset();  // the others moved into its way: tightened among them as they are
        }
        if (!d) {
          ++stats_.tightenings;
          d = tighten_one(i, wires[i][k]);
        }
        auto& [r, w] = *d;
        seen[i] = hull_box(seen[i], w);
        if (r.taut.status != TightenStatus::Ok || r.no_staircase) {
          // Kept as it is this time (it keeps the clearance): not free in its own space, where
          // the other nets' grown wires and pins and the grown blockages touch along it (a gap of
          // exactly the clearance, which the triangulated space closes), or no lattice staircase.
          // Tried again when a change meets its window.
          o.kept[k] = r.no_staircase ? 2 : 1;
          if (r.no_staircase) {
            piece_why[i].resize(wires[i].size());
            piece_why[i][k] = r.why;
          }
          if (o.status == NetTightenOutcome::Status::Ok) {
            o.status = r.no_staircase ? NetTightenOutcome::Status::NoStaircase : NetTightenOutcome::Status::NotFree;
            o.round = round;
            o.wire = k;
            o.lift = r.taut;
            if (!r.no_staircase) {
              o.wire_blockers = space.wire_blockers(i, wires[i][k]);
              o.pin_blockers = space.pin_blockers(i, wires[i][k]);
            }
          }
          continue;
        }
        if (r.contractible) {
          o.status = NetTightenOutcome::Status::Contractible;
          o.round = round;
          o.wire = k;
          continue;
        }
        o.kept[k] = 0;
        if (round == 1) {
          o.sleeve += r.taut.sleeve;
          o.crossings += r.taut.crossings;
        }
        taut_len[i][k] = euclidean_length(r.taut.points);
        if ((!fresh[i].empty() && fresh[i][k]) || better(r.points, wires[i][k], is_sketch(i))) {
          if (!fresh[i].empty()) fresh[i][k] = 0;
          next[k] = std::move(r.points);
          net_moved = true;
          ++o.moves;
          ++stats_.moved;
        }
      }
      if (o.status == NetTightenOutcome::Status::Contractible) {  // written as failed: out of the space
        failed[i] = 1;
        for (const Box& b : space.wire_boxes(i)) changed.push_back({b, i});
        space.set_wires(i, {});
        continue;
      }
      if (!net_moved) continue;
      moved = true;
      for (const Box& b : space.wire_boxes(i)) changed.push_back({b, i});
      wires[i] = std::move(next);
      if (!is_sketch(i)) {  // a piece pulled through a joint of its net (another wire's end, a pin) is cut there
        std::vector<char> fz;
        NetLines recut = prepare(wires[i], space.net(i).pins, fz);
        if (recut != wires[i]) adopt(i, std::move(recut), std::move(fz));
      }
      space.set_wires(i, wires[i]);
      for (const Box& b : space.wire_boxes(i)) changed.push_back({b, i});
    }
    stats_.rounds = round;
    if (!moved) {
      // The rounds tighten the pieces cut at the start (and again after a move through a joint),
      // but the wires are written joined where two end, on pins too (below), and such a line cut
      // anew may give other pieces that tighten further as one: a piece that ended at a shape
      // pin's corner and another that ran on along the pin to the wire's end, joined, go
      // straight to that end (found by the 30-degree sets' test, 2026-12-07: a second run
      // shortened wires in 5 of 150 layouts). So the rounds repeat "until no wire shortens" in
      // the pieces a second run would see: each net's wires as they would be written, cut again;
      // a net whose pieces differ is tried again with them. Once a re-cut moves nothing, done.
      if (recut_tried || round >= options_.max_rounds) break;  // (at the cap: left as they are, the rounds having ended)
      recut_tried = true;
      bool recut_any = false;
      for (std::size_t i = 0; i < n; ++i) {
        if (wires[i].empty() || failed[i] || is_sketch(i)) continue;
        std::vector<char> fz;
        NetLines recut = prepare(written(wires[i]), space.net(i).pins, fz);
        // (compared as they are: a piece reversed, or tried in another order, may get another
        // wire of the same length, and the test above found a second run taking one with fewer
        // bends that way: pieces equal only as a set are tried again too)
        if (recut == wires[i]) continue;
        recut_any = true;
        adopt(i, std::move(recut), std::move(fz));
        // (a problem of the old pieces is not the new ones': found again, if it is, in the next round)
        // (not failed, so not contractible)
        out[i].status = NetTightenOutcome::Status::Ok;
        out[i].wire_blockers.clear();
        out[i].pin_blockers.clear();
        space.set_wires(i, wires[i]);  // (the same metal)
      }
      if (!recut_any) break;
    } else {
      recut_tried = false;
    }
    if (round >= options_.max_rounds) {
      stats_.capped = true;
      break;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    NetTightenOutcome& o = out[i];
    if (failed[i] == 1) {  // a contractible loop
      wires[i].clear();
      continue;
    }
    if (failed[i] == 2) continue;  // not in its space as given
    for (std::size_t k = 0; k < fresh[i].size(); ++k)
      if (fresh[i][k]) {
        o.untightened = true;  // a sketch piece with no staircase, or the others left it no room
        o.wire = k;
        o.why = k < piece_why[i].size() ? piece_why[i][k] : std::string();
      }
    o.pieces = wires[i];
    for (std::size_t k = 0; k < wires[i].size(); ++k) {
      stats_.kept_shape_pin += frozen[i][k];
      stats_.kept += o.kept[k] != 0 && !frozen[i][k];
      stats_.kept_not_free += o.kept[k] == 1 && !frozen[i][k];
      o.length_taut += taut_len[i][k];
    }
    if (!is_sketch(i)) wires[i] = written(wires[i]);
    for (const auto& w : wires[i]) o.length_after += euclidean_length(w), o.bends_after += geom::count_bends(w);
  }
  return out;
}

std::pair<geom::Root2, std::int64_t> length_and_bends(const NetLines& wires) {
  std::int64_t bends = 0;
  for (const auto& w : wires) bends += geom::count_bends(w);
  return {oct_length(wires), bends};
}

std::optional<std::vector<NetLines>> tighten_scaled(const geom::Box& domain, std::span<const Polygon> obstacles,
                                                    std::vector<NetPins> nets, NetRules rules, std::int64_t k,
                                                    const std::vector<NetLines>& wires, std::span<const NetsTightener::Input> kind,
                                                    const NetsTightenOptions& options, NetsTightenStats* stats,
                                                    std::vector<NetTightenOutcome>* outcomes) {
  if (k <= 1) throw std::invalid_argument("tighten_scaled: the scale must be above 1");
  NetSpace space(Box{scaled(domain.lo, k), scaled(domain.hi, k)}, scaled(obstacles, k), scaled(std::move(nets), k),
                 with_scale(rules, k));
  std::vector<NetLines> kw;
  kw.reserve(wires.size());
  for (const NetLines& w : wires) kw.push_back(scaled_wires(w, k));
  NetsTightenOptions scaled_options = options;
  scaled_options.snap_scale = k;
  NetsTightener nt(space, scaled_options);
  std::vector<NetTightenOutcome> out = nt.run(kw, kind);
  if (stats) *stats = nt.stats();

  bool far = false;
  auto down = [&](geom::Coord v) {
    const geom::Coord q = snapped(v, k);
    far = far || std::abs(std::int64_t{v} - q) * 4 >= k;
    return static_cast<geom::Coord>(q / k);
  };
  std::vector<NetLines> back(kw.size());
  for (std::size_t i = 0; i < kw.size(); ++i)
    for (const auto& w : kw[i]) {
      std::vector<Point> s;
      for (const Point v : w) {
        const Point q{down(v.x), down(v.y)};
        if (s.empty() || s.back() != q) s.push_back(q);
      }
      if (s.size() == 1 && w.size() > 1) s.push_back(s[0]);
      back[i].push_back(std::move(s));
    }
  if (outcomes) {  // the lengths and bends of the wires given and of the snapped ones (the taut length scaled down)
    for (std::size_t i = 0; i < out.size(); ++i) {
      NetTightenOutcome& o = out[i];
      o.length_taut /= static_cast<double>(k);
      o.length_before = o.length_after = 0;
      o.bends_after = 0;
      for (const auto& w : wires[i]) o.length_before += euclidean_length(w);
      for (const auto& w : back[i]) o.length_after += euclidean_length(w), o.bends_after += geom::count_bends(w);
    }
    *outcomes = std::move(out);
  }
  if (far) return std::nullopt;
  // (a wire in the set's directions scaled must be so snapped: links shorter than k collapse or
  // turn; in a set at multiples of 30 degrees a rounded vertex snapped again may leave a segment
  // out of its rounding rule)
  for (std::size_t i = 0; i < kw.size(); ++i)
    for (std::size_t j = 0; j < kw[i].size(); ++j)
      if (options.orientations.runs_in(kw[i][j]) && !options.orientations.runs_in(back[i][j])) return std::nullopt;
  for (std::size_t i = 0; i < wires.size(); ++i)
    if (!wires[i].empty() && !(i < kind.size() && kind[i] == NetsTightener::Input::Sketch) &&
        (back[i].empty() || oct_length(wires[i]) < oct_length(back[i])))
      return std::nullopt;
  return back;
}

void tighten_attempt(NetAttempt& attempt, const NetPins& pins, const geom::NormalizedObstacles& obstacles,
                     const TightenOrientations& orientations, const std::function<bool()>& stop) {
  if (!attempt.routed || attempt.wires.empty()) return;
  NetSpace space(obstacles.domain, obstacles.obstacles, std::vector<NetPins>{pins}, NetRules{});
  NetsTightenOptions o;
  o.orientations = orientations;
  o.stop = stop;
  NetsTightener nt(space, o);
  std::vector<NetLines> w{attempt.wires};
  (void)nt.run(w);  // (a piece it could not move stays as routed, which the test below finds)
  if (w[0].empty()) return;
  if (!std::all_of(w[0].begin(), w[0].end(), [&](const auto& line) { return orientations.runs_in(line); })) return;
  attempt.wires = std::move(w[0]);
  attempt.distance.reset();
}

}  // namespace taut::router
