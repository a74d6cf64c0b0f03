// Free-space constrained Delaunay triangulation (see triangulation.h). CGAL lives only here.
#include "geom/triangulation.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <mutex>
#include <numeric>
#include <sstream>
#include <utility>

#include "geom/predicates.h"

namespace taut::geom {
namespace {

// Face labels while classifying. Obstacle k is labelled k >= 0.
constexpr std::int32_t kUnknown = -3;
constexpr std::int32_t kOutside = -2;
constexpr std::int32_t kFree = -1;

struct VertexInfo {
  std::int32_t id = -1;  // index into vertices; -1 for a vertex CGAL created (never valid)
};
struct FaceInfo {
  std::int32_t label = kUnknown;
  std::int32_t index = -1;  // index into triangles when free
  // Owner of CGAL edge i (opposite vertex i) when constrained: kDomainEdge or an obstacle.
  std::array<std::int32_t, 3> owner{kUnconstrained, kUnconstrained, kUnconstrained};
};

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, K>;
using Fbb = CGAL::Triangulation_face_base_with_info_2<FaceInfo, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbb>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
// Exact_predicates_tag: constraints through an input vertex are split there without any
// construction; only a proper crossing would construct a point, which we detect and refuse.
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
using VertexHandle = Cdt::Vertex_handle;
using FaceHandle = Cdt::Face_handle;

std::string str(Point p) {
  return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
}

std::string label_name(std::int32_t label) {
  if (label == kOutside) return "outside the domain";
  if (label == kFree) return "free space";
  return "inside obstacle " + std::to_string(label);
}

// Which side of the domain boundary the segment pq (p != q) lies on, counting the sides
// counter-clockwise from the bottom (0 bottom, 1 right, 2 top, 3 left), or -1.
int boundary_side(const Box& d, Point p, Point q) {
  if (p.y == d.lo.y && q.y == d.lo.y) return 0;
  if (p.x == d.hi.x && q.x == d.hi.x) return 1;
  if (p.y == d.hi.y && q.y == d.hi.y) return 2;
  if (p.x == d.lo.x && q.x == d.lo.x) return 3;
  return -1;
}
// Position of p along side s in the counter-clockwise direction, and the side's range.
i64 side_param(int s, Point p) {
  switch (s) {
    case 0: return p.x;
    case 1: return p.y;
    case 2: return -i64{p.x};
    default: return -i64{p.y};
  }
}
std::pair<i64, i64> side_range(int s, const Box& d) {
  switch (s) {
    case 0: return {d.lo.x, d.hi.x};
    case 1: return {d.lo.y, d.hi.y};
    case 2: return {-i64{d.hi.x}, -i64{d.lo.x}};
    default: return {-i64{d.hi.y}, -i64{d.lo.y}};
  }
}

bool inside_box(const Box& d, Point p) {
  return d.lo.x <= p.x && p.x <= d.hi.x && d.lo.y <= p.y && p.y <= d.hi.y;
}

std::int32_t index_of(const std::vector<Point>& sorted, Point p) {  // -1 when absent
  const auto it = std::lower_bound(sorted.begin(), sorted.end(), p);
  return (it != sorted.end() && *it == p) ? static_cast<std::int32_t>(it - sorted.begin()) : -1;
}

Diagnostic error(const char* code, std::string message) {
  Diagnostic d;
  d.code = code;
  d.message = std::move(message);
  return d;
}

// One ring of the input, stored flat: ring_points[begin, end) of obstacle `obstacle`.
struct RingRef {
  std::size_t begin, end;
  std::int32_t obstacle;
  bool hole;
};

}  // namespace

struct FreeSpaceTriangulation::Impl {
  Box domain;
  std::size_t obstacle_count = 0;
  std::vector<Point> ring_points;  // the input rings, kept for check()
  std::vector<RingRef> rings;
  std::vector<Point> vertices;
  std::vector<FreeTriangle> triangles;
  std::vector<Diagnostic> diagnostics;
  Cdt cdt;
  std::vector<FaceHandle> faces;  // triangle index -> CGAL face
  // Start faces for locate() without a hint: a grid of cells over the domain, each holding a
  // face near its centre, so the walk is short (O(1) expected for evenly spread vertices).
  std::int64_t grid_nx = 0, grid_ny = 0;
  std::vector<FaceHandle> grid;
  std::mutex mutex;  // CGAL's locate() draws from the triangulation's own RNG

  std::span<const Point> ring(const RingRef& r) const {
    return std::span<const Point>(ring_points).subspan(r.begin, r.end - r.begin);
  }
  std::optional<std::int32_t> locate(Point p, FaceHandle start);
  FaceHandle grid_start(Point p) const;
  void build_grid();
};

namespace {

const FreeSpaceTriangulation::Impl& empty_impl();

// Builds the triangulation into `m`; on failure appends diagnostics and returns false.
class Builder {
 public:
  using Impl = FreeSpaceTriangulation::Impl;
  explicit Builder(Impl& m) : m_(m) {}

  bool run() {
    if (m_.ring_points.size() > std::size_t{1} << 30) {  // vertex indices are int32
      add("GEOM-0040", "more than 2^30 obstacle vertices");
      return false;
    }
    if (!check_input()) return false;
    collect_vertices();
    insert_into_cgal();
    if (!m_.diagnostics.empty()) return false;
    if (!verify_vertices()) return false;
    if (!label_constraints()) return false;
    if (!flood()) return false;
    copy_out();
    return check_area();
  }

 private:
  struct InputEdge {
    std::int32_t a, b;   // vertex indices, a != b
    std::int32_t owner;  // obstacle index or kDomainEdge
  };

  void add(const char* code, std::string message) {
    constexpr std::size_t kMaxDiagnostics = 20;
    if (m_.diagnostics.size() < kMaxDiagnostics)
      m_.diagnostics.push_back(error(code, std::move(message)));
  }

  bool check_input() {
    const Box& d = m_.domain;
    if (!in_range(d.lo.x) || !in_range(d.lo.y) || !in_range(d.hi.x) || !in_range(d.hi.y) ||
        d.lo.x >= d.hi.x || d.lo.y >= d.hi.y) {
      add("GEOM-0040", "domain " + str(d.lo) + " - " + str(d.hi) +
                           " is empty, degenerate or beyond the coordinate limit");
      return false;
    }
    for (std::size_t ri = 0; ri < m_.rings.size(); ++ri) {
      const RingRef& rr = m_.rings[ri];
      const std::span<const Point> ring = m_.ring(rr);
      auto name = [&] {  // built only when reporting
        std::size_t hole = 0;
        for (std::size_t j = ri; j > 0 && m_.rings[j].hole; --j) ++hole;
        return "obstacle " + std::to_string(rr.obstacle) +
               (rr.hole ? " hole " + std::to_string(hole - 1) : std::string(" outer ring"));
      };
      {
        if (ring.size() < 3) {
          add("GEOM-0041", name() + " has fewer than 3 vertices");
          continue;
        }
        bool coords_ok = true;
        for (Point p : ring) {
          if (!in_range(p.x) || !in_range(p.y)) {
            add("GEOM-0040", name() + " vertex " + str(p) + " exceeds the coordinate limit");
            coords_ok = false;
            break;
          }
          if (!inside_box(d, p)) {
            add("GEOM-0042", name() + " vertex " + str(p) + " lies outside the domain");
            coords_ok = false;
            break;
          }
        }
        if (!coords_ok) continue;
        const i128 area = twice_area(ring);
        if (area == 0)
          add("GEOM-0041", name() + " has zero area");
        else if ((area > 0) == rr.hole)
          add("GEOM-0041", name() + (rr.hole ? " is not clockwise" : " is not counter-clockwise"));
      }
    }
    return m_.diagnostics.empty();
  }

  // Distinct points sorted by (x, y); one sort also gives every ring vertex its index.
  void collect_vertices() {
    const Box& d = m_.domain;
    const std::size_t n = m_.ring_points.size();
    std::vector<std::pair<Point, std::uint32_t>> order;  // (point, position; corners at n..)
    order.reserve(n + 4);
    for (std::size_t i = 0; i < n; ++i) order.push_back({m_.ring_points[i], std::uint32_t(i)});
    const Point corners[4] = {d.lo, {d.hi.x, d.lo.y}, d.hi, {d.lo.x, d.hi.y}};
    for (std::uint32_t s = 0; s < 4; ++s) order.push_back({corners[s], std::uint32_t(n + s)});
    std::sort(order.begin(), order.end());
    std::vector<std::int32_t> id(n + 4);
    m_.vertices.reserve(order.size());
    for (const auto& [p, pos] : order) {
      if (m_.vertices.empty() || m_.vertices.back() != p) m_.vertices.push_back(p);
      id[pos] = static_cast<std::int32_t>(m_.vertices.size()) - 1;
    }
    edges_.reserve(n + 4);
    for (std::size_t s = 0; s < 4; ++s) edges_.push_back({id[n + s], id[n + (s + 1) % 4], kDomainEdge});
    for (const RingRef& rr : m_.rings) {
      for (std::size_t i = rr.begin; i < rr.end; ++i) {
        const std::int32_t a = id[i], b = id[i + 1 < rr.end ? i + 1 : rr.begin];
        if (a != b) edges_.push_back({a, b, rr.obstacle});
      }
    }
  }

  void insert_into_cgal() {
    try {
      std::vector<K::Point_2> pts;
      pts.reserve(m_.vertices.size());
      for (Point p : m_.vertices) pts.emplace_back(p.x, p.y);  // exact: |v| < 2^30 < 2^53
      std::vector<std::size_t> order(pts.size());
      std::iota(order.begin(), order.end(), std::size_t{0});
      using Pmap = CGAL::Pointer_property_map<K::Point_2>::const_type;
      const std::vector<K::Point_2>& cpts = pts;
      CGAL::Spatial_sort_traits_adapter_2<K, Pmap> traits(CGAL::make_property_map(cpts));
      CGAL::spatial_sort(order.begin(), order.end(), traits);
      handles_.resize(pts.size());
      FaceHandle hint;
      for (std::size_t i : order) {
        VertexHandle v = m_.cdt.insert(pts[i], hint);
        v->info().id = static_cast<std::int32_t>(i);
        handles_[i] = v;
        hint = v->face();
      }
      for (const InputEdge& e : edges_) m_.cdt.insert_constraint(handles_[e.a], handles_[e.b]);
    } catch (const std::exception& ex) {
      add("GEOM-0046", std::string("CGAL failed while triangulating: ") + ex.what());
    }
  }

  // A constraint crossing makes CGAL construct an intersection vertex; refuse the result.
  bool verify_vertices() {
    if (m_.cdt.number_of_vertices() == m_.vertices.size()) return true;
    for (auto v : m_.cdt.finite_vertex_handles()) {
      if (v->info().id >= 0) continue;
      std::ostringstream os;
      os.precision(17);
      os << "obstacle edges cross near (" << v->point().x() << ", " << v->point().y() << ")";
      add("GEOM-0043", os.str());
      break;
    }
    if (m_.diagnostics.empty()) add("GEOM-0043", "obstacle edges cross");
    return false;
  }

  // Sets `label` on face f; a different label already there means the input is contradictory.
  bool assign(FaceHandle f, std::int32_t label) {
    std::int32_t& cur = f->info().label;
    if (cur == label) return true;
    if (cur == kUnknown) {
      cur = label;
      stack_.push_back(f);
      return true;
    }
    conflict(f, cur, label);
    return false;
  }

  void conflict(FaceHandle f, std::int32_t a, std::int32_t b) {
    std::string where;
    for (int i = 0; i < 3; ++i) {
      const VertexHandle v = f->vertex(i);
      if (m_.cdt.is_infinite(v)) continue;
      where += (where.empty() ? "" : " ") + str(m_.vertices[v->info().id]);
    }
    add("GEOM-0044", "the region at triangle " + where + " would be both " + label_name(a) +
                         " and " + label_name(b) +
                         " (overlapping or nested obstacles, a shared edge, a spike, or an "
                         "obstacle outside the domain)");
  }

  // Records owners on every constrained piece of every input edge and seeds the face labels
  // on both sides: obstacle on the left, free (or outside, on the domain boundary) on the right.
  bool label_constraints() {
    for (FaceHandle f : m_.cdt.all_face_handles())
      if (m_.cdt.is_infinite(f) && !assign(f, kOutside)) return false;
    for (const InputEdge& e : edges_) {
      const Point a = m_.vertices[e.a], b = m_.vertices[e.b];
      const bool on_boundary = boundary_side(m_.domain, a, b) >= 0;
      std::int32_t left = kUnknown, right = kOutside;
      if (e.owner >= 0) {
        left = e.owner;
        right = on_boundary ? kOutside : kFree;
      }
      VertexHandle cur = handles_[e.a];
      while (cur != handles_[e.b]) {
        const Point c = m_.vertices[cur->info().id];
        VertexHandle next;
        auto circ = m_.cdt.incident_vertices(cur), done = circ;
        do {
          if (!m_.cdt.is_infinite(circ)) {
            const Point w = m_.vertices[circ->info().id];
            if (w != c && on_segment(w, c, b)) {
              next = circ;
              break;
            }
          }
        } while (++circ != done);
        FaceHandle f;
        int i = 0;
        if (next == VertexHandle() || !m_.cdt.is_edge(cur, next, f, i) ||
            !m_.cdt.is_constrained({f, i})) {
          add("GEOM-0046", "constraint " + str(a) + " - " + str(b) + " is missing at " + str(c));
          return false;
        }
        const FaceHandle n = f->neighbor(i);
        const int j = m_.cdt.mirror_index(f, i);
        if (e.owner >= 0 || f->info().owner[i] == kUnconstrained) f->info().owner[i] = e.owner;
        if (e.owner >= 0 || n->info().owner[j] == kUnconstrained) n->info().owner[j] = e.owner;
        // CGAL edge i of f runs ccw(i) -> cw(i) counter-clockwise around f: f is on its left.
        const bool f_left = f->vertex(Cdt::ccw(i)) == cur;
        const FaceHandle lf = f_left ? f : n, rf = f_left ? n : f;
        if (left != kUnknown && !assign(lf, left)) return false;
        if (!assign(rf, right)) return false;
        cur = next;
      }
    }
    return true;
  }

  bool flood() {
    while (!stack_.empty()) {
      const FaceHandle f = stack_.back();
      stack_.pop_back();
      for (int i = 0; i < 3; ++i) {
        if (m_.cdt.is_constrained({f, i})) continue;
        if (!assign(f->neighbor(i), f->info().label)) return false;
      }
    }
    // A face no seed reached is bounded only by domain edges seen from inside: free.
    for (FaceHandle f : m_.cdt.finite_face_handles())
      if (f->info().label == kUnknown) f->info().label = kFree;
    return true;
  }

  void copy_out() {
    std::int32_t count = 0;
    for (FaceHandle f : m_.cdt.finite_face_handles())
      if (f->info().label == kFree) f->info().index = count++;
    m_.triangles.reserve(count);
    m_.faces.reserve(count);
    for (FaceHandle f : m_.cdt.finite_face_handles()) {
      if (f->info().label != kFree) continue;
      FreeTriangle t;
      for (int k = 0; k < 3; ++k) {
        t.v[k] = f->vertex(k)->info().id;
        // Our edge k (v[k] -> v[k+1]) is CGAL's edge opposite vertex k+2.
        const int ce = Cdt::cw(k);
        const bool constrained = m_.cdt.is_constrained({f, ce});
        t.constraint[k] = constrained ? f->info().owner[ce] : kUnconstrained;
        const FaceHandle n = f->neighbor(ce);
        t.neighbor[k] = (!constrained && n->info().label == kFree) ? n->info().index : -1;
      }
      m_.triangles.push_back(t);
      m_.faces.push_back(f);
    }
  }

  bool check_area() {
    const Box& d = m_.domain;
    i128 expected = i128{2} * (i128{d.hi.x} - d.lo.x) * (i128{d.hi.y} - d.lo.y);
    for (const RingRef& rr : m_.rings) expected -= twice_area(m_.ring(rr));  // holes add back
    i128 got = 0;
    for (const FreeTriangle& t : m_.triangles)
      got += orient(m_.vertices[t.v[0]], m_.vertices[t.v[1]], m_.vertices[t.v[2]]);
    if (got == expected) return true;
    add("GEOM-0045", "the free area does not add up (obstacles overlap or break the contract)");
    return false;
  }

  Impl& m_;
  std::vector<InputEdge> edges_;
  std::vector<VertexHandle> handles_;
  std::vector<FaceHandle> stack_;
};

const FreeSpaceTriangulation::Impl& empty_impl() {
  static const FreeSpaceTriangulation::Impl kEmpty;
  return kEmpty;
}

}  // namespace

void FreeSpaceTriangulation::Impl::build_grid() {
  if (cdt.dimension() < 2) return;
  // About 4 vertices per cell; cells follow the domain's aspect ratio.
  const double w = static_cast<double>(i64{domain.hi.x} - domain.lo.x);
  const double h = static_cast<double>(i64{domain.hi.y} - domain.lo.y);
  const double cells = std::max(1.0, static_cast<double>(vertices.size()) / 4.0);
  grid_nx = std::clamp<i64>(static_cast<i64>(std::sqrt(cells * w / h)), 1, 4096);
  grid_ny = std::clamp<i64>(static_cast<i64>(std::sqrt(cells * h / w)), 1, 4096);
  grid.assign(static_cast<std::size_t>(grid_nx * grid_ny), FaceHandle());
  FaceHandle prev;
  for (i64 gy = 0; gy < grid_ny; ++gy) {
    for (i64 k = 0; k < grid_nx; ++k) {
      const i64 gx = gy % 2 == 0 ? k : grid_nx - 1 - k;  // serpentine: each walk is short
      const double cx = domain.lo.x + (static_cast<double>(gx) + 0.5) * w / grid_nx;
      const double cy = domain.lo.y + (static_cast<double>(gy) + 0.5) * h / grid_ny;
      // Only a start face for a walk: any face will do, so rounding is harmless here.
      FaceHandle f = cdt.locate(K::Point_2(std::floor(cx), std::floor(cy)), prev);
      if (cdt.is_infinite(f)) f = f->neighbor(f->index(cdt.infinite_vertex()));
      grid[static_cast<std::size_t>(gy * grid_nx + gx)] = f;
      prev = f;
    }
  }
}

FaceHandle FreeSpaceTriangulation::Impl::grid_start(Point p) const {
  if (grid.empty()) return FaceHandle();
  const i64 gx = std::min(grid_nx - 1, static_cast<i64>(i128{i64{p.x} - domain.lo.x} * grid_nx /
                                                         (i64{domain.hi.x} - domain.lo.x)));
  const i64 gy = std::min(grid_ny - 1, static_cast<i64>(i128{i64{p.y} - domain.lo.y} * grid_ny /
                                                         (i64{domain.hi.y} - domain.lo.y)));
  return grid[static_cast<std::size_t>(gy * grid_nx + gx)];
}

std::optional<std::int32_t> FreeSpaceTriangulation::Impl::locate(Point p, FaceHandle start) {
  if (triangles.empty() || !inside_box(domain, p) || cdt.dimension() < 2) return std::nullopt;
  if (start == FaceHandle()) start = grid_start(p);
  std::lock_guard<std::mutex> lock(mutex);
  Cdt::Locate_type lt;
  int li = 0;
  const FaceHandle f = cdt.locate(K::Point_2(p.x, p.y), lt, li, start);
  std::int32_t best = -1;
  auto consider = [&](FaceHandle g) {
    const std::int32_t i = g->info().index;
    if (i >= 0 && (best < 0 || i < best)) best = i;
  };
  switch (lt) {
    case Cdt::FACE:
      consider(f);
      break;
    case Cdt::EDGE:
      consider(f);
      consider(f->neighbor(li));
      break;
    case Cdt::VERTEX: {
      auto circ = cdt.incident_faces(f->vertex(li)), done = circ;
      do consider(circ);
      while (++circ != done);
      break;
    }
    default:
      break;
  }
  if (best < 0) return std::nullopt;
  return best;
}

FreeSpaceTriangulation::FreeSpaceTriangulation() : impl_(std::make_unique<Impl>()) {}
FreeSpaceTriangulation::~FreeSpaceTriangulation() = default;
FreeSpaceTriangulation::FreeSpaceTriangulation(FreeSpaceTriangulation&&) noexcept = default;
FreeSpaceTriangulation& FreeSpaceTriangulation::operator=(FreeSpaceTriangulation&&) noexcept =
    default;

bool FreeSpaceTriangulation::ok() const { return !impl_ || impl_->diagnostics.empty(); }
const std::vector<Diagnostic>& FreeSpaceTriangulation::diagnostics() const {
  return (impl_ ? *impl_ : empty_impl()).diagnostics;
}
const Box& FreeSpaceTriangulation::domain() const { return (impl_ ? *impl_ : empty_impl()).domain; }
const std::vector<Point>& FreeSpaceTriangulation::vertices() const {
  return (impl_ ? *impl_ : empty_impl()).vertices;
}
const std::vector<FreeTriangle>& FreeSpaceTriangulation::triangles() const {
  return (impl_ ? *impl_ : empty_impl()).triangles;
}

std::optional<std::int32_t> FreeSpaceTriangulation::locate(Point p) const {
  if (!impl_) return std::nullopt;
  return impl_->locate(p, FaceHandle());
}
std::optional<std::int32_t> FreeSpaceTriangulation::locate(Point p, std::int32_t hint) const {
  if (!impl_) return std::nullopt;
  const bool valid = hint >= 0 && static_cast<std::size_t>(hint) < impl_->faces.size();
  return impl_->locate(p, valid ? impl_->faces[hint] : FaceHandle());
}

FreeSpaceTriangulation triangulate_free_space(const Box& domain,
                                              std::span<const Polygon> obstacles) {
  FreeSpaceTriangulation out;
  FreeSpaceTriangulation::Impl& m = *out.impl_;
  m.domain = domain;
  m.obstacle_count = obstacles.size();
  std::size_t total = 0, ring_count = 0;
  for (const Polygon& poly : obstacles) {
    total += poly.outer.size();
    for (const Ring& h : poly.holes) total += h.size();
    ring_count += 1 + poly.holes.size();
  }
  m.ring_points.reserve(total);
  m.rings.reserve(ring_count);
  for (std::size_t k = 0; k < obstacles.size(); ++k) {
    for (std::size_t r = 0; r <= obstacles[k].holes.size(); ++r) {
      const Ring& ring = r == 0 ? obstacles[k].outer : obstacles[k].holes[r - 1];
      const std::size_t begin = m.ring_points.size();
      m.ring_points.insert(m.ring_points.end(), ring.begin(), ring.end());
      m.rings.push_back({begin, m.ring_points.size(), static_cast<std::int32_t>(k), r > 0});
    }
  }
  bool ok = false;
  try {  // CGAL signals broken preconditions by exceptions; never let one escape
    ok = Builder(m).run();
    if (ok) m.build_grid();
  } catch (const std::exception& ex) {
    m.diagnostics.push_back(error("GEOM-0046", std::string("triangulation failed: ") + ex.what()));
    ok = false;
  }
  if (!ok) {
    m.triangles.clear();
    m.faces.clear();
    m.cdt.clear();
  }
  return out;
}

// ---- check(): plain data only, independent of CGAL ------------------------------------------

std::vector<std::string> FreeSpaceTriangulation::check() const {
  std::vector<std::string> problems;
  if (!impl_) return problems;
  const Impl& m = *impl_;
  auto problem = [&](std::string s) {
    if (problems.size() < 50) problems.push_back(std::move(s));
  };
  const std::vector<Point>& vs = m.vertices;
  const std::vector<FreeTriangle>& ts = m.triangles;
  const std::int32_t nv = static_cast<std::int32_t>(vs.size());
  const std::int32_t nt = static_cast<std::int32_t>(ts.size());
  const std::int32_t no = static_cast<std::int32_t>(m.obstacle_count);
  const Box& d = m.domain;
  if (!m.diagnostics.empty()) {
    if (!ts.empty()) problem("a failed triangulation has triangles");
    return problems;
  }
  if (m.faces.size() != ts.size()) problem("face table and triangles differ in size");

  // Vertices: sorted, distinct, in the domain.
  for (std::int32_t i = 0; i < nv; ++i) {
    if (i > 0 && !(vs[i - 1] < vs[i])) problem("vertices not sorted/distinct at " + str(vs[i]));
    if (!inside_box(d, vs[i])) problem("vertex " + str(vs[i]) + " outside the domain");
  }

  // Triangles: valid indices, counter-clockwise, non-degenerate.
  i128 area = 0;
  std::vector<std::uint64_t> keys;  // directed edges (from << 32 | to)
  keys.reserve(std::size_t{3} * ts.size());
  for (std::int32_t t = 0; t < nt; ++t) {
    const FreeTriangle& tr = ts[t];
    if (!std::all_of(tr.v.begin(), tr.v.end(), [&](std::int32_t v) { return v >= 0 && v < nv; })) {
      problem("triangle " + std::to_string(t) + " has a bad vertex index");
      return problems;
    }
    const i64 o = orient(vs[tr.v[0]], vs[tr.v[1]], vs[tr.v[2]]);
    if (o <= 0) problem("triangle " + std::to_string(t) + " is not counter-clockwise");
    area += o;
    for (int k = 0; k < 3; ++k)
      keys.push_back(std::uint64_t(std::uint32_t(tr.v[k])) << 32 | std::uint32_t(tr.v[(k + 1) % 3]));
  }
  // A directed edge used twice means overlapping triangles.
  std::sort(keys.begin(), keys.end());
  if (std::adjacent_find(keys.begin(), keys.end()) != keys.end())
    problem("an edge is used twice in the same direction (overlapping triangles)");

  // Adjacency: symmetric, exactly across unconstrained edges. (A free triangle on the other
  // side of a constrained edge would either break symmetry or repeat a directed edge.)
  std::vector<std::int32_t> out_count(static_cast<std::size_t>(nv) + 1, 0);
  for (std::int32_t t = 0; t < nt; ++t) {
    const FreeTriangle& tr = ts[t];
    for (int k = 0; k < 3; ++k) {
      const std::int32_t a = tr.v[k], b = tr.v[(k + 1) % 3], n = tr.neighbor[k];
      if (tr.constraint[k] == kUnconstrained) {
        int j = 0;
        while (n >= 0 && n < nt && j < 3 && !(ts[n].v[j] == b && ts[n].v[(j + 1) % 3] == a)) ++j;
        if (n < 0 || n >= nt || j == 3)
          problem("triangle " + std::to_string(t) + ": unconstrained edge without neighbour");
        else if (ts[n].neighbor[j] != t || ts[n].constraint[j] != kUnconstrained)
          problem("triangle " + std::to_string(t) + ": adjacency is not symmetric");
      } else {
        if (n != -1) problem("triangle " + std::to_string(t) + ": constrained edge, neighbour");
        if (tr.constraint[k] < kDomainEdge || tr.constraint[k] >= no)
          problem("triangle " + std::to_string(t) + ": bad constraint owner");
        ++out_count[static_cast<std::size_t>(a) + 1];
      }
    }
  }

  // Area: free = domain - obstacles, exactly.
  i128 expected = i128{2} * (i128{d.hi.x} - d.lo.x) * (i128{d.hi.y} - d.lo.y);
  for (const RingRef& rr : m.rings) expected -= twice_area(m.ring(rr));
  if (area != expected) problem("free area does not add up");

  // Constrained free-triangle edges grouped by start vertex (counting sort).
  struct ConstrainedEdge {
    std::int32_t to, owner;
  };
  for (std::int32_t v = 0; v < nv; ++v) out_count[v + 1] += out_count[v];
  std::vector<ConstrainedEdge> ces(static_cast<std::size_t>(out_count[nv]));
  {
    std::vector<std::int32_t> fill(out_count.begin(), out_count.end() - 1);
    for (const FreeTriangle& tr : ts)
      for (int k = 0; k < 3; ++k)
        if (tr.constraint[k] != kUnconstrained)
          ces[fill[tr.v[k]]++] = {tr.v[(k + 1) % 3], tr.constraint[k]};
  }
  for (std::int32_t v = 0; v < nv; ++v)  // free on both sides of a constraint?
    for (std::int32_t i = out_count[v]; i < out_count[v + 1]; ++i)
      for (std::int32_t j = out_count[ces[i].to]; j < out_count[ces[i].to + 1]; ++j)
        if (ces[j].to == v) problem("constrained edge at " + str(vs[v]) + " is free on both sides");
  std::vector<char> used(ces.size(), 0);
  std::vector<std::vector<std::pair<i64, i64>>> tiles(4);
  for (std::int32_t v = 0; v < nv; ++v) {
    for (std::int32_t i = out_count[v]; i < out_count[v + 1]; ++i) {
      if (ces[i].owner != kDomainEdge) continue;
      const Point p = vs[v], q = vs[ces[i].to];
      const int s = boundary_side(d, p, q);
      if (s < 0 || side_param(s, p) >= side_param(s, q)) {
        problem("domain edge " + str(p) + " - " + str(q) + " is not on the boundary, CCW");
        continue;
      }
      tiles[s].push_back({side_param(s, p), side_param(s, q)});
      used[i] = 1;
    }
  }
  for (const RingRef& rr : m.rings) {
    const std::span<const Point> ring = m.ring(rr);
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Point a = ring[i], b = ring[(i + 1) % ring.size()];
      if (a == b) continue;
      const int s = boundary_side(d, a, b);
      if (s >= 0) {
        if (side_param(s, a) >= side_param(s, b))
          problem("obstacle edge " + str(a) + " - " + str(b) + " runs clockwise on the boundary");
        else
          tiles[s].push_back({side_param(s, a), side_param(s, b)});
        continue;
      }
      // The free side is on the right of a -> b: free triangles traverse it from b to a.
      std::int32_t cur = index_of(vs, b);
      const std::int32_t goal = index_of(vs, a);
      while (cur >= 0 && cur != goal) {
        std::int32_t next = -1;
        for (std::int32_t e = out_count[cur]; e < out_count[cur + 1]; ++e) {
          if (ces[e].owner != rr.obstacle || !on_segment(vs[ces[e].to], vs[cur], a)) continue;
          used[e] = 1;
          next = ces[e].to;
          break;
        }
        cur = next;
      }
      if (cur != goal)
        problem("obstacle " + std::to_string(rr.obstacle) + " edge " + str(a) + " - " + str(b) +
                " is not covered by constrained free edges");
    }
  }
  for (int s = 0; s < 4; ++s) {
    std::sort(tiles[s].begin(), tiles[s].end());
    auto [pos, end] = side_range(s, d);
    for (const auto& [lo, hi] : tiles[s]) {
      if (lo != pos) break;
      pos = hi;
    }
    if (pos != end) problem("domain side " + std::to_string(s) + " is not tiled exactly");
  }
  for (std::int32_t v = 0; v < nv; ++v)
    for (std::int32_t i = out_count[v]; i < out_count[v + 1]; ++i)
      if (!used[i])
        problem("constrained edge " + str(vs[v]) + " - " + str(vs[ces[i].to]) +
                " lies on no input edge of its owner");
  return problems;
}

VertexFans vertex_fans(const FreeSpaceTriangulation& t) {
  VertexFans f;
  const auto& tris = t.triangles();
  f.start.assign(t.vertices().size() + 1, 0);
  for (const FreeTriangle& tr : tris)
    for (std::int32_t v : tr.v) ++f.start[static_cast<std::size_t>(v) + 1];
  for (std::size_t i = 1; i < f.start.size(); ++i) f.start[i] += f.start[i - 1];
  f.triangles.assign(static_cast<std::size_t>(f.start.back()), 0);
  std::vector<std::int32_t> fill(f.start.begin(), f.start.end() - 1);
  for (std::size_t i = 0; i < tris.size(); ++i)
    for (std::int32_t v : tris[i].v)
      f.triangles[static_cast<std::size_t>(fill[static_cast<std::size_t>(v)]++)] = static_cast<std::int32_t>(i);
  return f;
}

}  // namespace taut::geom
