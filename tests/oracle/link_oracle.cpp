#include "oracle/link_oracle.h"

#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <optional>
#include <tuple>
#include <type_traits>

namespace taut::oracle {

using geom::Point;

namespace {

QPoint q(Point p) { return {mpq_class(static_cast<long>(p.x)), mpq_class(static_cast<long>(p.y))}; }
template <class Pt>
Pt lift(Point p) {
  if constexpr (std::is_same_v<Pt, QPoint>) return q(p);
  else return q3(p);
}
int sgn(const Q3& v) { return v.sign(); }
mpq_class cross(const mpq_class& ax, const mpq_class& ay, const mpq_class& bx, const mpq_class& by) {
  return ax * by - ay * bx;
}
Q3 cross(const Q3& ax, const Q3& ay, const Q3& bx, const Q3& by) { return ax * by - ay * bx; }

std::optional<QPoint> meet(const QPoint& a, const QPoint& b, const QPoint& c, const QPoint& d) {
  const mpq_class den = cross(b.x - a.x, b.y - a.y, d.x - c.x, d.y - c.y);
  if (den == 0) return std::nullopt;
  const mpq_class t = cross(c.x - a.x, c.y - a.y, d.x - c.x, d.y - c.y) / den;
  return QPoint{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
}

// p on the closed segment cd
template <class Pt>
bool on_edge(const Pt& p, const Pt& c, const Pt& d) {
  if (cross(d.x - c.x, d.y - c.y, p.x - c.x, p.y - c.y) != 0) return false;
  return std::min(c.x, d.x) <= p.x && p.x <= std::max(c.x, d.x) && std::min(c.y, d.y) <= p.y &&
         p.y <= std::max(c.y, d.y);
}

// -1 outside, 0 on the boundary, 1 strictly inside the region of a simple ring
template <class Pt>
int locate(const Pt& p, const geom::Ring& r) {
  using N = decltype(Pt::x);
  bool in = false;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Pt c = lift<Pt>(r[i]), d = lift<Pt>(r[(i + 1) % r.size()]);
    if (on_edge(p, c, d)) return 0;
    // crossing number: edges straddling the horizontal through p, crossed to the right of p
    if ((c.y > p.y) != (d.y > p.y)) {
      const N x = c.x + (p.y - c.y) * (d.x - c.x) / (d.y - c.y);
      if (x > p.x) in = !in;
    }
  }
  return in ? 1 : -1;
}

template <class Pt>
bool in_material(const Pt& p, std::span<const geom::Polygon> obstacles) {
  for (const auto& o : obstacles) {
    if (locate(p, o.outer) != 1) continue;
    bool in_hole = false;
    for (const auto& h : o.holes) in_hole = in_hole || locate(p, h) >= 0;
    if (!in_hole) return true;
  }
  return false;
}

template <class Pt>
bool segment_free_of(const Pt& a, const Pt& b, const geom::Box& D, std::span<const geom::Polygon> obstacles) {
  using N = decltype(Pt::x);
  for (const Pt* p : {&a, &b})
    if (p->x < D.lo.x || p->x > D.hi.x || p->y < D.lo.y || p->y > D.hi.y) return false;
  const N rx = b.x - a.x, ry = b.y - a.y;
  if (rx == 0 && ry == 0) return !in_material(a, obstacles);
  std::vector<N> ts{N(0), N(1)};
  auto edge = [&](Point c0, Point d0) {
    const Pt c = lift<Pt>(c0), d = lift<Pt>(d0);
    const N sx = d.x - c.x, sy = d.y - c.y;
    const N den = cross(rx, ry, sx, sy);
    const N cax = c.x - a.x, cay = c.y - a.y;
    if (den != 0) {
      const N t = cross(cax, cay, sx, sy) / den, u = cross(cax, cay, rx, ry) / den;
      if (t >= 0 && t <= 1 && u >= 0 && u <= 1) ts.push_back(t);
    } else if (cross(cax, cay, rx, ry) == 0) {
      for (const Pt* e : {&c, &d}) {
        const N t = ((e->x - a.x) * rx + (e->y - a.y) * ry) / (rx * rx + ry * ry);
        if (t >= 0 && t <= 1) ts.push_back(t);
      }
    }
  };
  for (const auto& o : obstacles) {
    std::vector<const geom::Ring*> rs{&o.outer};
    for (const auto& h : o.holes) rs.push_back(&h);
    for (const geom::Ring* r : rs)
      for (std::size_t i = 0; i < r->size(); ++i) edge((*r)[i], (*r)[(i + 1) % r->size()]);
  }
  std::sort(ts.begin(), ts.end());
  ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
  // An obstacle vertex strictly inside the segment with material on both sides of it (an edge
  // leaving on each side, or an edge along the segment whose material lies on the other side):
  // the segment either enters material there or, where obstacle corners touch (a pinch), slips
  // between touching blockages (FORMAT.md forbids it); either way it is not free.
  for (const auto& o : obstacles) {
    std::vector<const geom::Ring*> rs{&o.outer};
    for (const auto& h : o.holes) rs.push_back(&h);
    for (const geom::Ring* r : rs)
      for (std::size_t i = 0; i < r->size(); ++i) {
        const Pt v = lift<Pt>((*r)[i]);
        if (!on_edge(v, a, b) || (v.x == a.x && v.y == a.y) || (v.x == b.x && v.y == b.y)) continue;
        bool left = false, right = false;
        for (const auto& o2 : obstacles) {
          std::vector<const geom::Ring*> rs2{&o2.outer};
          for (const auto& h : o2.holes) rs2.push_back(&h);
          for (const geom::Ring* r2 : rs2)
            for (std::size_t k = 0; k < r2->size(); ++k) {
              if ((*r2)[k] != (*r)[i]) continue;
              // material lies left of each directed ring edge: prev -> v and v -> next
              const Point prev = (*r2)[(k + r2->size() - 1) % r2->size()], next = (*r2)[(k + 1) % r2->size()];
              for (int e = 0; e < 2; ++e) {
                const Pt w = lift<Pt>(e == 0 ? prev : next);
                const int sg = sgn(cross(rx, ry, w.x - v.x, w.y - v.y));
                left = left || sg > 0;
                right = right || sg < 0;
                if (sg == 0) {
                  // an edge along the segment: its material side, seen along the segment
                  const N ux = e == 0 ? N(v.x - w.x) : N(w.x - v.x), uy = e == 0 ? N(v.y - w.y) : N(w.y - v.y);
                  const bool along = ux * rx + uy * ry > 0;  // the edge runs the segment's way
                  left = left || along;
                  right = right || !along;
                }
              }
            }
        }
        if (left && right) return false;
      }
  }
  for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
    const N m = (ts[i] + ts[i + 1]) / N(2);
    if (in_material(Pt{a.x + m * rx, a.y + m * ry}, obstacles)) return false;
  }
  return true;
}

}  // namespace

bool segment_free(const QPoint& a, const QPoint& b, const geom::Box& D, std::span<const geom::Polygon> obstacles) {
  return segment_free_of(a, b, D, obstacles);
}
bool segment_free(const Q3Point& a, const Q3Point& b, const geom::Box& D, std::span<const geom::Polygon> obstacles) {
  return segment_free_of(a, b, D, obstacles);
}

LinkSearch::LinkSearch(const geom::Box& domain, std::span<const geom::Polygon> obstacles, const HomotopyWords& words)
    : domain_(domain), obstacles_(obstacles.begin(), obstacles.end()), words_(words) {
  for (const auto& o : obstacles_) {
    vertices_.insert(vertices_.end(), o.outer.begin(), o.outer.end());
    for (const auto& h : o.holes) vertices_.insert(vertices_.end(), h.begin(), h.end());
  }
  std::sort(vertices_.begin(), vertices_.end());
  vertices_.erase(std::unique(vertices_.begin(), vertices_.end()), vertices_.end());
}

bool LinkSearch::path_ok(const std::vector<QPoint>& path, const std::vector<int>& word) const {
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    if (!segment_free(path[i], path[i + 1], domain_, obstacles_)) return false;
  return words_.word(std::span<const QPoint>(path)) == word;
}

int LinkSearch::fewest(Point p, Point q0, const std::vector<int>& word, int max_links, std::vector<QPoint>* out) const {
  const QPoint P = q(p), Q = q(q0);
  auto found = [&](std::vector<QPoint> path) {
    if (!path_ok(path, word)) return false;
    if (out) *out = std::move(path);
    return true;
  };
  if (max_links >= 1 && found({P, Q})) return 1;
  std::vector<Point> pts = vertices_;
  pts.push_back(p);
  pts.push_back(q0);
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  // lines as point pairs
  std::vector<std::pair<QPoint, QPoint>> through_p, through_q, all;
  for (Point s : pts) {
    if (s != p) through_p.push_back({P, q(s)});
    if (s != q0) through_q.push_back({Q, q(s)});
  }
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::size_t j = i + 1; j < pts.size(); ++j) all.push_back({q(pts[i]), q(pts[j])});
  if (max_links >= 2)
    for (const auto& l1 : through_p)
      for (const auto& l2 : through_q) {
        const auto x = meet(l1.first, l1.second, l2.first, l2.second);
        if (x && found({P, *x, Q})) return 2;
      }
  if (max_links >= 3)
    for (const auto& l1 : through_p)
      for (const auto& l2 : all) {
        const auto x = meet(l1.first, l1.second, l2.first, l2.second);
        if (!x || !segment_free(P, *x, domain_, obstacles_)) continue;
        for (const auto& l3 : through_q) {
          const auto y = meet(l2.first, l2.second, l3.first, l3.second);
          if (y && found({P, *x, *y, Q})) return 3;
        }
      }
  return 0;
}

bool LinkSearch::triangle_loop(const std::function<bool(const std::vector<QPoint>&)>& in_class,
                               std::vector<QPoint>* loop) const {
  std::vector<Point> pts = vertices_;
  for (const Point c : {domain_.lo, Point{domain_.hi.x, domain_.lo.y}, domain_.hi, Point{domain_.lo.x, domain_.hi.y}})
    pts.push_back(c);
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  // the distinct lines through two candidate points, as a x + b y = c with (a, b, c) reduced
  struct Line {
    long a, b, c;
    bool operator<(const Line& o) const { return std::tie(a, b, c) < std::tie(o.a, o.b, o.c); }
    bool operator==(const Line& o) const { return a == o.a && b == o.b && c == o.c; }
  };
  std::vector<Line> lines;
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::size_t j = i + 1; j < pts.size(); ++j) {
      long a = static_cast<long>(pts[j].y) - pts[i].y, b = static_cast<long>(pts[i].x) - pts[j].x;
      long c = a * pts[i].x + b * pts[i].y;
      const long g = std::gcd(std::gcd(std::labs(a), std::labs(b)), std::labs(c));
      a /= g, b /= g, c /= g;
      if (a < 0 || (a == 0 && b < 0)) a = -a, b = -b, c = -c;
      lines.push_back({a, b, c});
    }
  std::sort(lines.begin(), lines.end());
  lines.erase(std::unique(lines.begin(), lines.end()), lines.end());
  const std::size_t L = lines.size();
  // the free meeting point of every two lines (inside the domain, not in material)
  std::vector<std::optional<QPoint>> at(L * L);
  for (std::size_t i = 0; i < L; ++i)
    for (std::size_t j = i + 1; j < L; ++j) {
      const Line &u = lines[i], &v = lines[j];
      const long den = u.a * v.b - u.b * v.a;
      if (den == 0) continue;
      QPoint y{mpq_class(u.c * v.b - u.b * v.c, den), mpq_class(u.a * v.c - u.c * v.a, den)};
      y.x.canonicalize();
      y.y.canonicalize();
      if (y.x < domain_.lo.x || y.x > domain_.hi.x || y.y < domain_.lo.y || y.y > domain_.hi.y) continue;
      if (in_material(y, obstacles_)) continue;
      at[i * L + j] = y;
      at[j * L + i] = y;
    }
  for (std::size_t i = 0; i < L; ++i)
    for (std::size_t j = i + 1; j < L; ++j) {
      const auto& A = at[i * L + j];
      if (!A) continue;
      for (std::size_t k = j + 1; k < L; ++k) {
        const auto &B = at[j * L + k], &C = at[k * L + i];
        if (!B || !C) continue;
        if (cross(B->x - A->x, B->y - A->y, C->x - A->x, C->y - A->y) == 0) continue;  // no triangle
        for (int turn = 0; turn < 2; ++turn) {  // both ways round
          std::vector<QPoint> t = turn == 0 ? std::vector<QPoint>{*A, *B, *C, *A} : std::vector<QPoint>{*A, *C, *B, *A};
          if (!in_class(t)) continue;
          bool free = true;
          for (std::size_t e = 0; e < 3 && free; ++e) free = segment_free(t[e], t[e + 1], domain_, obstacles_);
          if (!free) break;
          if (loop) *loop = std::move(t);
          return true;
        }
      }
    }
  return false;
}

}  // namespace taut::oracle
