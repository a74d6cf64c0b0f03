#include "router/link_approx.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace taut::router {
namespace {

// A chord of the horizontal decomposition seen from one of its two cells: the cell across it and
// its extent in x ranks.
struct Chord {
  std::int32_t cell = -1;
  std::int32_t lo = 0, hi = 0;
};

// One horizontal side of a cell, left to right: at most two chords, and whether a polygon edge
// lies on it too. In general position a side is [edge], [chord], [edge, chord], [chord, edge] or
// [chord, edge, chord]; only the count of chords and the edge flag matter below.
struct Side {
  std::array<Chord, 2> chord{};
  int chords = 0;
  bool edge = false;
  void add(Chord c) {
    if (chords == 2) throw std::invalid_argument("approximate_link_diameter: a cell side with three chords (not a simple polygon)");
    chord[static_cast<std::size_t>(chords++)] = c;
  }
};

struct Cell {
  std::int32_t xl = 0, xr = 0;  // x ranks of its walls
  std::array<Side, 2> side;     // 0 bottom, 1 top
};

// The horizontal decomposition of the moved polygon (see the header), by one upward sweep over
// its horizontal edges, one per height.
std::vector<Cell> decompose(const geom::Ring& ring, std::int32_t& root) {
  const std::size_t n = ring.size();
  if (n < 4 || n % 2 != 0) throw std::invalid_argument("approximate_link_diameter: not a rectilinear ring");
  // Edge k runs from ring[k] to ring[k + 1]; edges alternate between horizontal and vertical.
  auto next = [&](std::size_t k) { return (k + 1) % n; };
  const bool first_horizontal = ring[0].y == ring[1].y;
  for (std::size_t k = 0; k < n; ++k) {
    const geom::Point a = ring[k], b = ring[next(k)];
    const bool horizontal = (k % 2 == 0) == first_horizontal;
    if (horizontal ? (a.y != b.y || a.x == b.x) : (a.x != b.x || a.y == b.y))
      throw std::invalid_argument("approximate_link_diameter: edge " + std::to_string(k) +
                                  " breaks the alternation of horizontal and vertical edges");
  }
  // Ranks. Horizontal edge going +x has the interior above (counter-clockwise): moved down, so at
  // one height it sorts before those going -x (moved up); each by its own amount (its index).
  // Vertical edge going +y has the interior to its left: moved +x; going -y: moved -x.
  struct Key {
    std::int64_t v;
    std::int64_t tie;
    std::size_t edge;
  };
  std::vector<Key> hs, vs;
  for (std::size_t k = 0; k < n; ++k) {
    const geom::Point a = ring[k], b = ring[next(k)];
    const auto tag = static_cast<std::int64_t>(k) + 1;
    if (a.y == b.y) hs.push_back({a.y, b.x > a.x ? -tag : tag, k});
    else vs.push_back({a.x, b.y > a.y ? tag : -tag, k});
  }
  auto by_key = [](const Key& p, const Key& q) { return p.v != q.v ? p.v < q.v : p.tie < q.tie; };
  std::sort(hs.begin(), hs.end(), by_key);
  std::sort(vs.begin(), vs.end(), by_key);
  std::vector<std::int32_t> rank(n);  // per edge: its y rank (horizontal) or x rank (vertical)
  for (std::size_t i = 0; i < hs.size(); ++i) rank[hs[i].edge] = static_cast<std::int32_t>(i);
  for (std::size_t i = 0; i < vs.size(); ++i) rank[vs[i].edge] = static_cast<std::int32_t>(i);

  std::vector<Cell> cells;
  std::map<std::int32_t, std::int32_t> active;  // left wall's x rank -> cell
  auto open = [&](std::int32_t xl, std::int32_t xr) {
    cells.push_back({xl, xr, {}});
    const auto id = static_cast<std::int32_t>(cells.size() - 1);
    if (!active.emplace(xl, id).second) throw std::invalid_argument("approximate_link_diameter: two cells share a wall (not a simple polygon)");
    return id;
  };
  auto take = [&](std::int32_t xl) {  // the active cell whose left wall is xl
    const auto it = active.find(xl);
    if (it == active.end()) throw std::invalid_argument("approximate_link_diameter: the sweep lost a cell (not a simple, counter-clockwise polygon)");
    const std::int32_t id = it->second;
    active.erase(it);
    return id;
  };
  auto take_left_of = [&](std::int32_t x) {  // the active cell whose left wall is the last one before x
    auto it = active.lower_bound(x);
    if (it == active.begin()) throw std::invalid_argument("approximate_link_diameter: the sweep lost a cell (not a simple, counter-clockwise polygon)");
    --it;
    const std::int32_t id = it->second;
    active.erase(it);
    return id;
  };
  auto link = [&](std::int32_t below, std::int32_t above, std::int32_t lo, std::int32_t hi) {
    cells[static_cast<std::size_t>(below)].side[1].add({above, lo, hi});
    cells[static_cast<std::size_t>(above)].side[0].add({below, lo, hi});
  };
  root = -1;
  for (const Key& h : hs) {
    const std::size_t k = h.edge;
    const bool interior_above = ring[next(k)].x > ring[k].x;
    // The vertical edges at the two ends: edge k - 1 ends at ring[k], edge k + 1 starts at ring[k + 1].
    const std::size_t before = (k + n - 1) % n, after = next(k);
    const bool before_goes_up = ring[before].y > ring[k].y;              // from ring[k], the other end
    const bool after_goes_up = ring[next(after)].y > ring[after].y;      // from ring[k + 1]
    const std::int32_t xa = rank[before], xb = rank[after];
    const bool left_is_start = ring[k].x < ring[next(k)].x;
    const std::int32_t a = left_is_start ? xa : xb, b = left_is_start ? xb : xa;
    const bool a_up = left_is_start ? before_goes_up : after_goes_up;
    const bool b_up = left_is_start ? after_goes_up : before_goes_up;
    // Convex: with the interior above, the wall goes up from the end; with it below, down.
    const bool ca = a_up == interior_above, cb = b_up == interior_above;
    if (interior_above) {
      if (ca && cb) {  // a new cell starts on the edge
        const std::int32_t c = open(a, b);
        cells[static_cast<std::size_t>(c)].side[0].edge = true;
        if (root < 0) root = c;
      } else if (ca) {  // widens to the left: [b, R] -> [a, R]
        const std::int32_t old = take(b);
        const std::int32_t r = cells[static_cast<std::size_t>(old)].xr;
        const std::int32_t c = open(a, r);
        cells[static_cast<std::size_t>(c)].side[0].edge = true;
        link(old, c, b, r);
      } else if (cb) {  // widens to the right: [L, a] -> [L, b]
        const std::int32_t old = take_left_of(a);
        const std::int32_t l = cells[static_cast<std::size_t>(old)].xl;
        if (cells[static_cast<std::size_t>(old)].xr != a) throw std::invalid_argument("approximate_link_diameter: walls out of order (not a simple polygon)");
        const std::int32_t c = open(l, b);
        link(old, c, l, a);
        cells[static_cast<std::size_t>(c)].side[0].edge = true;
      } else {  // two cells merge over a bump: [L, a] + [b, R] -> [L, R]
        const std::int32_t right = take(b);
        const std::int32_t left = take_left_of(a);
        const std::int32_t l = cells[static_cast<std::size_t>(left)].xl, r = cells[static_cast<std::size_t>(right)].xr;
        if (cells[static_cast<std::size_t>(left)].xr != a) throw std::invalid_argument("approximate_link_diameter: walls out of order (not a simple polygon)");
        const std::int32_t c = open(l, r);
        link(left, c, l, a);
        cells[static_cast<std::size_t>(c)].side[0].edge = true;
        link(right, c, b, r);
      }
    } else {
      if (ca && cb) {  // the edge closes a cell
        const std::int32_t old = take(a);
        if (cells[static_cast<std::size_t>(old)].xr != b) throw std::invalid_argument("approximate_link_diameter: walls out of order (not a simple polygon)");
        cells[static_cast<std::size_t>(old)].side[1].edge = true;
      } else if (ca) {  // narrows from the left: [a, R] -> [b, R]
        const std::int32_t old = take(a);
        const std::int32_t r = cells[static_cast<std::size_t>(old)].xr;
        cells[static_cast<std::size_t>(old)].side[1].edge = true;
        const std::int32_t c = open(b, r);
        link(old, c, b, r);
      } else if (cb) {  // narrows from the right: [L, b] -> [L, a]
        const std::int32_t old = take_left_of(a);
        const std::int32_t l = cells[static_cast<std::size_t>(old)].xl;
        if (cells[static_cast<std::size_t>(old)].xr != b) throw std::invalid_argument("approximate_link_diameter: walls out of order (not a simple polygon)");
        const std::int32_t c = open(l, a);
        link(old, c, l, a);
        cells[static_cast<std::size_t>(old)].side[1].edge = true;
      } else {  // a tooth hangs into a cell and splits it: [L, R] -> [L, a] + [b, R]
        const std::int32_t old = take_left_of(a);
        const std::int32_t l = cells[static_cast<std::size_t>(old)].xl, r = cells[static_cast<std::size_t>(old)].xr;
        if (r < b) throw std::invalid_argument("approximate_link_diameter: walls out of order (not a simple polygon)");
        const std::int32_t left = open(l, a);
        link(old, left, l, a);
        cells[static_cast<std::size_t>(old)].side[1].edge = true;
        const std::int32_t right = open(b, r);
        link(old, right, b, r);
      }
    }
  }
  if (!active.empty() || root < 0) throw std::invalid_argument("approximate_link_diameter: the sweep ended with open cells (not a simple, counter-clockwise polygon)");
  return cells;
}

// One call of MAXDIST: a cell entered through its side `near` (0 bottom, 1 top), its case, and
// the calls it makes: the cells across its far side's chords ('3', 'v'), or the cell across the
// widening chord and the pocket under that cell's near side ('2', '4'). Calls come after their
// parent in `calls`. Each call also answers M for other pieces s of its near side (`asked`).
struct Call {
  std::int32_t cell = 0;
  int near = 0;
  char kind = 'i';
  std::array<std::int32_t, 2> child{-1, -1};
  std::array<Chord, 2> chord{};  // per child: the chord (its full piece s)
  std::vector<std::array<std::int32_t, 2>> asked;  // the pieces s asked for, sorted (lo, hi)
  std::vector<int> m;                              // M for each
  int d = 0;
};

}  // namespace

LinkDiameterEstimate approximate_link_diameter(const geom::Ring& polygon) {
  std::int32_t root = -1;
  const std::vector<Cell> cells = decompose(polygon, root);
  std::vector<Call> calls;
  calls.reserve(cells.size());
  calls.emplace_back();
  calls[0].cell = root;
  calls[0].asked.push_back({cells[static_cast<std::size_t>(root)].xl, cells[static_cast<std::size_t>(root)].xr});
  // Top down: each call's case and children, then the pieces it asks of them. M(C, s) needs, per
  // child across a far chord c_F, M(F, s projected onto c_F) or, when that is empty, M(F, c_F) + 2;
  // across a widening chord M(V, s); from a pocket M(W, c_W) + 2. The estimate needs M(C, s) for
  // the main piece (the root's edge projected down) and, at a tooth ('v'), both sides' M to their
  // whole chords: the paper's case (v) takes the sides' M to the projected pieces instead, which
  // can exceed those by 2 each and the diameter by 4 (random test seed 16380: diameter 5, 9).
  auto ask = [&](std::int32_t call, std::int32_t lo, std::int32_t hi) { calls[static_cast<std::size_t>(call)].asked.push_back({lo, hi}); };
  std::size_t asked = 0;
  for (std::size_t i = 0; i < calls.size(); ++i) {
    if (calls.size() > cells.size())  // the cells' adjacency has a cycle: not a simple polygon
      throw std::invalid_argument("approximate_link_diameter: the decomposition is not a tree (not a simple polygon)");
    {
      const Cell& u = cells[static_cast<std::size_t>(calls[i].cell)];
      const int far = 1 - calls[i].near;
      const Side& f = u.side[static_cast<std::size_t>(far)];
      auto make = [&](std::size_t slot, const Chord& ch, int near) {
        calls[i].child[slot] = static_cast<std::int32_t>(calls.size());
        calls[i].chord[slot] = ch;
        Call child;
        child.cell = ch.cell;
        child.near = near;
        calls.push_back(std::move(child));
      };
      if (f.chords == 0) {
        calls[i].kind = 'i';
      } else if (f.chords == 2) {
        calls[i].kind = 'v';
        make(0, f.chord[0], calls[i].near);
        make(1, f.chord[1], calls[i].near);
      } else if (f.edge) {
        calls[i].kind = '3';
        make(0, f.chord[0], calls[i].near);
      } else {
        // Widening: the cell v across takes s as it is; a second chord on v's near side leads to
        // a pocket on this cell's side of the line, entered through its far side.
        const Chord up = f.chord[0];
        const Side& vn = cells[static_cast<std::size_t>(up.cell)].side[static_cast<std::size_t>(calls[i].near)];
        calls[i].kind = '2';
        make(0, up, calls[i].near);
        for (int k = 0; k < vn.chords; ++k) {
          const Chord& p = vn.chord[static_cast<std::size_t>(k)];
          if (p.cell == calls[i].cell) continue;
          calls[i].kind = '4';
          make(1, p, far);
        }
      }
    }
    Call& c = calls[i];
    std::sort(c.asked.begin(), c.asked.end());
    c.asked.erase(std::unique(c.asked.begin(), c.asked.end()), c.asked.end());
    asked += c.asked.size();
    for (const auto& [lo, hi] : c.asked) {
      for (std::size_t k = 0; k < 2; ++k) {
        if (c.child[k] < 0) continue;
        const Chord& ch = c.chord[k];
        if (c.kind == '2' || (c.kind == '4' && k == 0)) {
          ask(c.child[k], lo, hi);
        } else {
          const std::int32_t a = std::max(lo, ch.lo), b = std::min(hi, ch.hi);
          if (a <= b) ask(c.child[k], a, b);
          else ask(c.child[k], ch.lo, ch.hi);
        }
      }
    }
    if (c.kind == 'v')
      for (std::size_t k = 0; k < 2; ++k) ask(c.child[k], c.chord[k].lo, c.chord[k].hi);
  }
  if (calls.size() != cells.size()) throw std::logic_error("approximate_link_diameter: the recursion did not visit every cell once");
  // Bottom up: M for every piece asked, then D for the main one (each call's first... the main
  // piece is the one its parent's main piece asked; found again by the same rule).
  auto m_of = [&](std::int32_t call, std::int32_t lo, std::int32_t hi) {
    const Call& c = calls[static_cast<std::size_t>(call)];
    const auto it = std::lower_bound(c.asked.begin(), c.asked.end(), std::array<std::int32_t, 2>{lo, hi});
    if (it == c.asked.end() || (*it)[0] != lo || (*it)[1] != hi) throw std::logic_error("approximate_link_diameter: a piece was not asked for");
    return c.m[static_cast<std::size_t>(it - c.asked.begin())];
  };
  // M(C, s) from the children's answers; `full` gives M(F, c_F) for the tooth's term.
  auto child_m = [&](const Call& c, std::size_t k, std::int32_t lo, std::int32_t hi) {
    const Chord& ch = c.chord[k];
    if (c.kind == '2' || (c.kind == '4' && k == 0)) return m_of(c.child[k], lo, hi);
    const std::int32_t a = std::max(lo, ch.lo), b = std::min(hi, ch.hi);
    return a <= b ? m_of(c.child[k], a, b) : m_of(c.child[k], ch.lo, ch.hi) + 2;
  };
  for (std::size_t i = calls.size(); i-- > 0;) {
    Call& c = calls[i];
    const Cell& u = cells[static_cast<std::size_t>(c.cell)];
    c.m.resize(c.asked.size());
    for (std::size_t q = 0; q < c.asked.size(); ++q) {
      const auto [lo, hi] = c.asked[q];
      int m = (lo == u.xl && hi == u.xr) ? 1 : 3;  // a point of the cell to s
      for (std::size_t k = 0; k < 2; ++k)
        if (c.child[k] >= 0) m = std::max(m, child_m(c, k, lo, hi));
      c.m[q] = m;
    }
  }
  // D along the main pieces, top down to find them, then bottom up.
  std::vector<std::array<std::int32_t, 2>> main(calls.size());
  main[0] = calls[0].asked.front();
  for (std::size_t i = 0; i < calls.size(); ++i) {
    const Call& c = calls[i];
    for (std::size_t k = 0; k < 2; ++k) {
      if (c.child[k] < 0) continue;
      const Chord& ch = c.chord[k];
      const auto [lo, hi] = main[i];
      std::array<std::int32_t, 2> s{lo, hi};
      if (!(c.kind == '2' || (c.kind == '4' && k == 0))) {
        const std::int32_t a = std::max(lo, ch.lo), b = std::min(hi, ch.hi);
        s = a <= b ? std::array<std::int32_t, 2>{a, b} : std::array<std::int32_t, 2>{ch.lo, ch.hi};
      }
      main[static_cast<std::size_t>(c.child[k])] = s;
    }
  }
  for (std::size_t i = calls.size(); i-- > 0;) {
    Call& c = calls[i];
    const int m = m_of(static_cast<std::int32_t>(i), main[i][0], main[i][1]);
    auto d_of = [&](std::size_t k) { return calls[static_cast<std::size_t>(c.child[k])].d; };
    auto m_main = [&](std::size_t k) { return m_of(c.child[k], main[static_cast<std::size_t>(c.child[k])][0], main[static_cast<std::size_t>(c.child[k])][1]); };
    auto m_full = [&](std::size_t k) { return m_of(c.child[k], c.chord[k].lo, c.chord[k].hi); };
    switch (c.kind) {
      case 'i':
        c.d = 3;
        break;
      case '2':
      case '3':
        c.d = std::max(d_of(0), m);
        break;
      case '4':
        c.d = std::max({d_of(0), d_of(1), m, m_main(0) + m_full(1) - 2});
        break;
      default:  // 'v'
        c.d = std::max({d_of(0), d_of(1), m, m_full(0) + m_full(1) - 1});
        break;
    }
  }
  LinkDiameterEstimate e;
  e.estimate = calls[0].d;
  e.cells = cells.size();
  e.pieces = asked;
  if (polygon.size() == 4) {  // a rectangle: MAXDIST says 3, the diameter is 2
    e.estimate = 2;
    e.lo = e.hi = 2;
  } else {
    e.lo = std::max(2, e.estimate - 3);
    e.hi = e.estimate + 3;
  }
  return e;
}

}  // namespace taut::router
