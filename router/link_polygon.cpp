#include "router/link_polygon.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <utility>

#include "geom/normalize.h"
#include "geom/predicates.h"
#include "geom/validate.h"
#include "router/link_reach.h"

namespace taut::router {

using geom::Box;
using geom::Point;
using geom::Polygon;
using geom::Ring;

namespace {

bool rectilinear(const Ring& r) {
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Point a = r[i], b = r[(i + 1) % r.size()];
    if (a.x != b.x && a.y != b.y) return false;
  }
  return true;
}

// Lowest, then leftmost, first.
bool lower(Point a, Point b) { return a.y != b.y ? a.y < b.y : a.x < b.x; }

Point lowest(const Ring& r) { return *std::min_element(r.begin(), r.end(), lower); }

// A box around `b` grown by one: the frame's shell. It may reach 2^30, one past the coordinate
// limit, which the union's integer arithmetic handles; it is clipped away again.
Box grown(const Box& b) { return {{b.lo.x - 1, b.lo.y - 1}, {b.hi.x + 1, b.hi.y + 1}}; }

Ring box_ring(const Box& b) { return {b.lo, {b.hi.x, b.lo.y}, b.hi, {b.lo.x, b.hi.y}}; }

}  // namespace

FreeSpacePolygon free_space_polygon(const Box& domain, std::span<const Polygon> blockages) {
  FreeSpacePolygon out;
  // The blockages together with a frame around the domain (its shell one unit outside, its hole
  // the domain): one obstacle holds the frame and everything that reaches the domain side; its
  // holes are the pieces of free space (the union links each piece's boundary into a ring of its
  // own, also where two pieces meet at a point). Any other obstacle is an island.
  std::vector<Polygon> inputs(blockages.begin(), blockages.end());
  Ring hole = box_ring(domain);
  std::reverse(hole.begin(), hole.end());
  inputs.push_back(Polygon{box_ring(grown(domain)), {hole}});
  const std::size_t frame = inputs.size() - 1;
  const geom::NormalizedObstacles norm = geom::normalize_obstacles(inputs, grown(domain));
  const Polygon* wall = nullptr;
  for (std::size_t k = 0; k < norm.obstacles.size(); ++k) {
    const auto& src = norm.sources[k];
    if (std::find(src.begin(), src.end(), frame) != src.end()) {
      wall = &norm.obstacles[k];
    } else if (out.status != FreeSpacePolygon::Status::Island) {
      out.status = FreeSpacePolygon::Status::Island;
      out.blockage = src.front();
    }
  }
  if (out.status == FreeSpacePolygon::Status::Island) return out;
  if (!wall) throw std::logic_error("free_space_polygon: the frame is missing from the union");
  if (wall->holes.empty()) {
    out.status = FreeSpacePolygon::Status::Empty;
    return out;
  }
  std::vector<Ring> pieces;
  for (const Ring& h : wall->holes) {
    Ring r = clean_ring(h);
    std::reverse(r.begin(), r.end());
    pieces.push_back(std::move(r));
  }
  if (pieces.size() > 1) {
    out.status = FreeSpacePolygon::Status::Pieces;
    for (const Ring& r : pieces) out.pieces.push_back(lowest(r));
    std::sort(out.pieces.begin(), out.pieces.end(), lower);
    return out;
  }
  // one piece whose boundary passes a point twice: it touches itself where blockages meet
  std::vector<Point> v = pieces[0];
  std::sort(v.begin(), v.end(), lower);
  if (const auto twice = std::adjacent_find(v.begin(), v.end()); twice != v.end()) {
    out.status = FreeSpacePolygon::Status::Pieces;
    out.pieces = {*twice};
    return out;
  }
  // a sloped edge of free space (sloped blockage edges outside the boundary, or covered by other
  // blockages, do not matter): name a blockage ring with a sloped edge that meets it
  const Ring& r = pieces[0];
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Point a = r[i], b = r[(i + 1) % r.size()];
    if (a.x == b.x || a.y == b.y) continue;
    out.status = FreeSpacePolygon::Status::Sloped;
    out.at = a;
    for (std::size_t k = 0; k < blockages.size(); ++k) {
      for (int h = -1; h < static_cast<int>(blockages[k].holes.size()); ++h) {
        const Ring& br = h < 0 ? blockages[k].outer : blockages[k].holes[static_cast<std::size_t>(h)];
        for (std::size_t j = 0; j < br.size(); ++j) {
          const Point c = br[j], d = br[(j + 1) % br.size()];
          if (c.x == d.x || c.y == d.y) continue;
          if (geom::intersect({a, b}, {c, d}) != geom::SegmentIntersection::None) {
            out.blockage = k, out.sloped_ring = h;
            return out;
          }
        }
      }
    }
    // (rounding moved the edge off every input edge: name the first blockage with a sloped edge)
    for (std::size_t k = 0; k < blockages.size(); ++k) {
      if (!rectilinear(blockages[k].outer)) {
        out.blockage = k, out.sloped_ring = -1;
        return out;
      }
      for (std::size_t h = 0; h < blockages[k].holes.size(); ++h)
        if (!rectilinear(blockages[k].holes[h])) {
          out.blockage = k, out.sloped_ring = static_cast<int>(h);
          return out;
        }
    }
    return out;
  }
  out.status = FreeSpacePolygon::Status::Ok;
  out.ring = std::move(pieces[0]);
  return out;
}

LinkPolygon::LinkPolygon(const Ring& polygon) : ring_(clean_ring(polygon)) {
  if (ring_.size() < 4 || !rectilinear(ring_))
    throw std::invalid_argument("LinkPolygon: the ring is not a rectilinear polygon");
  // the ring as given (a spike that clean_ring() would fold away is an error, as in a layout file)
  if (!geom::validate_ring(polygon).empty() || !geom::validate_ring(ring_).empty())
    throw std::invalid_argument("LinkPolygon: the ring is not simple");
  if (geom::twice_area(ring_) < 0) std::reverse(ring_.begin(), ring_.end());
  // the complement of the polygon in its bounding box, as obstacles of the bend-aware router
  Box box{ring_[0], ring_[0]};
  for (const Point p : ring_) {
    box.lo = {std::min(box.lo.x, p.x), std::min(box.lo.y, p.y)};
    box.hi = {std::max(box.hi.x, p.x), std::max(box.hi.y, p.y)};
  }
  // The domain is the box grown by one and the frame fills it around the polygon, so every
  // polygon vertex is an obstacle vertex (a node of the graph; a corner of the box would
  // otherwise be a query point of its own in every search). At the coordinate limit the domain
  // reaches 2^30, one past it: the predicates' products stay below 2^63.
  Ring hole = ring_;
  std::reverse(hole.begin(), hole.end());
  const Polygon frame[1] = {Polygon{box_ring(grown(grown(box))), {hole}}};
  const geom::NormalizedObstacles norm = geom::normalize_obstacles(frame, grown(box));
  router_ = std::make_unique<BendRouter>(grown(box), norm.obstacles);
}

LinkPolygon::~LinkPolygon() = default;
LinkPolygon::LinkPolygon(LinkPolygon&&) noexcept = default;
LinkPolygon& LinkPolygon::operator=(LinkPolygon&&) noexcept = default;

bool LinkPolygon::contains(Point p) const { return geom::locate(p, ring_) != geom::Location::Outside; }

// The router's free space is the closed polygon (its complement's open interior and the rim
// outside the box are not free), so its status says when an end lies outside: no second
// point-in-polygon test per query.
std::optional<LinkPath> LinkPolygon::path(Point a, Point b) const {
  const BendPath p = router_->path(a, b, BendMetric::Link, 0);
  if (p.status == WireStatus::SourceNotFree || p.status == WireStatus::TargetNotFree) return std::nullopt;
  if (p.status != WireStatus::Ok)
    throw std::logic_error("LinkPolygon: no path between two points of a simple polygon");
  LinkPath out;
  out.links = a == b ? 0 : static_cast<int>(p.bends) + 1;
  out.length = p.length;
  out.points = p.points;
  return out;
}

std::optional<int> LinkPolygon::distance(Point a, Point b) const {
  const Point sinks[1] = {b};
  std::optional<std::vector<int>> d = search(a, sinks);
  if (!d) return std::nullopt;
  return (*d)[0];
}

std::vector<int> LinkPolygon::distances(Point a, std::span<const Point> targets) const {
  std::optional<std::vector<int>> d = search(a, targets);
  if (!d) throw std::invalid_argument("LinkPolygon::distances: a point lies outside the polygon");
  return std::move(*d);
}

std::optional<std::vector<int>> LinkPolygon::search(Point a, std::span<const Point> targets) const {
  WireStatus status = WireStatus::Ok;
  const std::vector<std::int64_t> c = router_->fewest_bends(a, targets, &status);
  if (status == WireStatus::SourceNotFree || status == WireStatus::TargetNotFree) return std::nullopt;
  std::vector<int> out;
  for (std::size_t i = 0; i < targets.size(); ++i) {
    if (c[i] < 0) throw std::logic_error("LinkPolygon: no path between two points of a simple polygon");
    out.push_back(targets[i] == a ? 0 : static_cast<int>(c[i]) + 1);
  }
  return out;
}

LinkDiameter LinkPolygon::diameter(std::size_t search_budget) const {
  LinkDiameter out;
  out.vertices = ring_.size();
  const std::vector<Point> convex = convex_corners();
  out.convex_vertices = convex.size();
  // Exact by bounding eccentricities (Takes and Kosters, "Determining the diameter of small world
  // networks", 2011): link distance is a metric (two paths joined have at most the sum of their
  // links), so one search from v, giving e = ecc(v) and d(v, w) for every w, bounds every other
  // eccentricity: max(d(v, w), e - d(v, w)) <= ecc(w) <= e + d(v, w). A vertex whose upper bound
  // is at most the best eccentricity found can no longer raise the diameter (the lower bounds
  // never pass it: each is at most some eccentricity found); searches go on from the others
  // (alternately the largest upper bound and the smallest lower bound) until none is left. The answer is the largest eccentricity among the
  // convex vertices: exact whatever order is used; the bounds only skip searches.
  const std::size_t k = convex.size();
  constexpr int kUnknown = std::numeric_limits<int>::max();
  std::vector<int> lo(k, 0), hi(k, kUnknown);
  std::vector<char> open(k, 1);
  std::size_t left = k;
  out.from = out.to = convex.front();
  bool pick_high = true;
  while (left > 0) {
    if (out.searches >= search_budget) {  // the bounds are not pruning: de Berg's divide and conquer
      const LinkVertexQueries q(ring_);
      const LinkVertexQueries::Diameter d = q.diameter();
      out.links = d.links;
      out.from = ring_[d.from];
      out.to = ring_[d.to];
      out.cut_tree = true;
      break;
    }
    std::size_t v = k;
    for (std::size_t i = 0; i < k; ++i) {
      if (!open[i]) continue;
      if (v == k || (pick_high ? hi[i] > hi[v] : lo[i] < lo[v])) v = i;
    }
    pick_high = !pick_high;
    const std::vector<int> d = distances(convex[v], convex);
    ++out.searches;
    int ecc = 0;
    std::size_t far = v;
    for (std::size_t i = 0; i < k; ++i)
      if (d[i] > ecc) ecc = d[i], far = i;
    if (ecc > out.links) {
      out.links = ecc;
      out.from = convex[v];
      out.to = convex[far];
    }
    open[v] = 0, --left;
    for (std::size_t i = 0; i < k; ++i) {
      if (!open[i]) continue;
      lo[i] = std::max({lo[i], d[i], ecc - d[i]});
      hi[i] = std::min(hi[i], ecc + d[i]);
      if (hi[i] <= out.links) open[i] = 0, --left;
    }
  }
  out.path = *path(out.from, out.to);
  if (out.path.links != out.links) throw std::logic_error("LinkPolygon: the diameter's path disagrees with its search");
  return out;
}

std::vector<Point> LinkPolygon::convex_corners() const {
  std::vector<Point> convex;
  for (std::size_t i = 0; i < ring_.size(); ++i) {
    const Point a = ring_[(i + ring_.size() - 1) % ring_.size()], b = ring_[i], c = ring_[(i + 1) % ring_.size()];
    if (geom::orientation(a, b, c) > 0) convex.push_back(b);
  }
  return convex;
}

const BendGraphStats& LinkPolygon::graph_stats() const { return router_->stats(); }

// Repeated consecutive and collinear vertices dropped (for an axis-parallel ring every straight
// continuation is collinear; a 180-degree turn cannot occur in a simple ring).
Ring clean_ring(const Ring& in) {
  Ring r;
  for (const Point p : in)
    if (r.empty() || r.back() != p) r.push_back(p);
  while (r.size() > 1 && r.front() == r.back()) r.pop_back();
  bool changed = true;
  while (changed && r.size() >= 3) {
    changed = false;
    Ring out;
    for (std::size_t i = 0; i < r.size(); ++i) {
      const Point a = r[(i + r.size() - 1) % r.size()], b = r[i], c = r[(i + 1) % r.size()];
      if (geom::orientation(a, b, c) == 0) {
        changed = true;
        continue;
      }
      out.push_back(b);
    }
    r = std::move(out);
  }
  return r;
}

}  // namespace taut::router
