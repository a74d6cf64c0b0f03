#include "oracle/homotopy.h"

#include <gmpxx.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <stdexcept>

namespace taut::oracle {

using geom::Point;
using i64 = std::int64_t;

namespace {

// The height of a segment at x = X + sigma e: y0 + s e (s already times sigma).
template <class N>
struct HeightOf {
  N y0, s;
};
using Height = HeightOf<mpq_class>;
template <class A, class B>
bool less(const HeightOf<A>& a, const HeightOf<B>& b) {
  return a.y0 != b.y0 ? a.y0 < b.y0 : a.s < b.s;
}

std::optional<Height> crossing(Point a, Point b, i64 X, int sigma) {
  const i64 lo = sigma > 0 ? X : X - 1;  // the line lies strictly between lo and lo + 1
  const bool crosses = (a.x <= lo && b.x >= lo + 1) || (b.x <= lo && a.x >= lo + 1);
  if (!crosses) return std::nullopt;
  const mpq_class slope(mpz_class(static_cast<long>(i64{b.y} - a.y)), mpz_class(static_cast<long>(i64{b.x} - a.x)));
  mpq_class s = slope;
  s.canonicalize();
  Height h{mpq_class(static_cast<long>(a.y)) + mpq_class(static_cast<long>(X - a.x)) * s, sigma > 0 ? s : mpq_class(-s)};
  return h;
}

std::optional<Height> crossing(const QPoint& a, const QPoint& b, i64 X, int sigma) {
  const mpq_class x(static_cast<long>(X));
  const bool crosses = sigma > 0 ? ((a.x <= x && b.x > x) || (b.x <= x && a.x > x))
                                 : ((a.x < x && b.x >= x) || (b.x < x && a.x >= x));
  if (!crosses) return std::nullopt;
  const mpq_class s = (b.y - a.y) / (b.x - a.x);
  return Height{a.y + (x - a.x) * s, sigma > 0 ? s : mpq_class(-s)};
}

// The same for ends in Q(sqrt3).
std::optional<HeightOf<Q3>> crossing(const Q3Point& a, const Q3Point& b, i64 X, int sigma) {
  const Q3 x(static_cast<long>(X));
  const bool crosses = sigma > 0 ? ((a.x <= x && b.x > x) || (b.x <= x && a.x > x))
                                 : ((a.x < x && b.x >= x) || (b.x < x && a.x >= x));
  if (!crosses) return std::nullopt;
  const Q3 s = (b.y - a.y) / (b.x - a.x);
  return HeightOf<Q3>{a.y + (x - a.x) * s, sigma > 0 ? s : -s};
}

std::vector<const geom::Ring*> rings_of(const geom::Polygon& p) {
  std::vector<const geom::Ring*> rs{&p.outer};
  for (const auto& h : p.holes) rs.push_back(&h);
  return rs;
}

}  // namespace

struct HomotopyWords::Impl {
  struct Cut {
    i64 X;
    int sigma;
    Height base, end;
  };
  std::vector<Cut> cuts;
};

HomotopyWords::HomotopyWords(const geom::Box& domain, std::span<const geom::Polygon> obstacles) {
  auto impl = std::make_unique<Impl>();  // not leaked when the constructor throws
  std::vector<std::pair<Point, Point>> edges;
  for (const auto& p : obstacles)
    for (const geom::Ring* r : rings_of(p))
      for (std::size_t i = 0; i < r->size(); ++i) edges.push_back({(*r)[i], (*r)[(i + 1) % r->size()]});
  for (const auto& p : obstacles) {
    const geom::Ring& r = p.outer;
    if (r.empty()) throw std::invalid_argument("HomotopyWords: an obstacle with an empty outer ring");
    Point v = r[0];
    for (const Point q : r)
      if (q.y > v.y || (q.y == v.y && q.x > v.x)) v = q;
    // The cut's base is the obstacle's topmost crossing of the line x = v.x + sigma e, found
    // among all of its edges: the ring may pass through v more than once (lobes pinched at v),
    // in either orientation, with repeated or collinear vertices, so v's ring neighbours say
    // nothing. The base is at v (height v.y) iff an edge through v reaches that side; then
    // free space lies just above it (nothing of the obstacle is above v), and on the right
    // side when an edge through v reaches x > v.x, else on the left.
    std::optional<Impl::Cut> cut;
    for (const int sigma : {1, -1}) {
      std::optional<Height> base;
      for (const geom::Ring* ring : rings_of(p))
        for (std::size_t i = 0; i < ring->size(); ++i) {
          const auto h = crossing((*ring)[i], (*ring)[(i + 1) % ring->size()], v.x, sigma);
          if (h && (!base || less(*base, *h))) base = h;
        }
      if (base && base->y0 == v.y) {
        cut = Impl::Cut{v.x, sigma, *base, Height{mpq_class(static_cast<long>(domain.hi.y)), 0}};
        break;
      }
    }
    if (!cut)  // only vertical edges at v: a zero-width spike, not a valid polygon
      throw std::invalid_argument("HomotopyWords: an obstacle's top vertex has no edge to either side");
    for (const auto& [a, b] : edges) {
      const auto h = crossing(a, b, cut->X, cut->sigma);
      if (h && less(cut->base, *h) && less(*h, cut->end)) cut->end = *h;
    }
    impl->cuts.push_back(*cut);
  }
  impl_ = impl.release();
}

HomotopyWords::~HomotopyWords() { delete impl_; }

std::size_t HomotopyWords::cut_count() const { return impl_->cuts.size(); }

template <class P>
std::vector<int> HomotopyWords::word_of(std::span<const P> path) const {
  std::vector<int> w;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const P& a = path[i];
    const P& b = path[i + 1];
    if (a.x == b.x) continue;
    const int dir = b.x > a.x ? 1 : -1;
    struct Hit {
      i64 X;
      int sigma;
      std::size_t k;
    };
    std::vector<Hit> hits;
    for (std::size_t k = 0; k < impl_->cuts.size(); ++k) {
      const auto& c = impl_->cuts[k];
      const auto h = crossing(a, b, c.X, c.sigma);
      if (!h || less(*h, c.base) || less(c.end, *h)) continue;
      hits.push_back({c.X, c.sigma, k});
    }
    // in the order the segment meets the lines x = X + sigma e
    std::sort(hits.begin(), hits.end(), [&](const Hit& p, const Hit& q) {
      if (p.X != q.X || p.sigma != q.sigma) return (p.X != q.X ? p.X < q.X : p.sigma < q.sigma) == (dir > 0);
      return p.k < q.k;
    });
    for (const Hit& h : hits) {
      const int letter = dir * static_cast<int>(h.k + 1);
      if (!w.empty() && w.back() == -letter)
        w.pop_back();
      else
        w.push_back(letter);
    }
  }
  return w;
}

std::vector<int> HomotopyWords::word(std::span<const Point> path) const { return word_of(path); }
std::vector<int> HomotopyWords::word(std::span<const QPoint> path) const { return word_of(path); }
std::vector<int> HomotopyWords::word(std::span<const Q3Point> path) const { return word_of(path); }

}  // namespace taut::oracle
