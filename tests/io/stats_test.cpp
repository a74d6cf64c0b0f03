// format_length against Pythagorean triples and a 256-bit GMP reference; count_bends against a
// reference that compares primitive direction vectors; layout_stats_json fields and key order.
#include <gtest/gtest.h>
#include <gmpxx.h>

#include <nlohmann/json.hpp>
#include <numeric>
#include <random>

#include "io/stats_json.h"

namespace taut::io {
namespace stats_test {

using Poly = std::vector<Point>;

// Sum of Euclidean lengths rounded half-up to 3 decimals, in 256-bit floating point.
std::string reference_length(const std::vector<Poly>& pls) {
  mpf_class sum(0, 256);
  bool axis = true;
  for (const Poly& pl : pls)
    for (std::size_t i = 1; i < pl.size(); ++i) {
      const long dx = long{pl[i].x} - pl[i - 1].x, dy = long{pl[i].y} - pl[i - 1].y;
      if (dx != 0 && dy != 0) axis = false;
      mpf_class d2(0, 256);
      d2 = mpz_class(dx) * dx + mpz_class(dy) * dy;
      sum += mpf_class(sqrt(d2), 256);
    }
  mpf_class scaled(sum * 1000 + 0.5, 256);
  mpz_class q(floor(scaled));
  if (axis) {
    mpz_class whole(floor(mpf_class(sum + 0.5, 256)));
    return whole.get_str();
  }
  mpz_class ip = q / 1000, fp = q % 1000;
  std::string f = fp.get_str();
  return ip.get_str() + "." + std::string(3 - f.size(), '0') + f;
}

TEST(FormatLength, AxisParallelIsInteger) {
  EXPECT_EQ(format_length({}), "0");
  EXPECT_EQ(format_length({{5, 5}}), "0");
  EXPECT_EQ(format_length({{5, 5}, {5, 5}}), "0");
  EXPECT_EQ(format_length({{500, 500}, {500, 9000}, {8000, 9000}}), "16000");
  EXPECT_EQ(format_length({{0, 0}, {10, 0}, {3, 0}}), "17");  // reversal still counts length
  const int m = geom::kMaxCoord;
  EXPECT_EQ(format_length({{-m, -m}, {m, -m}, {m, m}, {-m, m}, {-m, -m}}),
            std::to_string(8LL * m));
}

TEST(FormatLength, PythagoreanTriples) {
  const int triples[][3] = {{3, 4, 5}, {5, 12, 13}, {8, 15, 17}, {7, 24, 25}, {20, 21, 29},
                            {9, 40, 41}, {119, 120, 169}, {696, 697, 985}};
  for (const auto& t : triples)
    for (int k : {1, 7, 1000, 1000003}) {
      const int a = t[0] * k, b = t[1] * k;
      const long long c = static_cast<long long>(t[2]) * k;
      if (c > 2LL * geom::kMaxCoord) continue;
      SCOPED_TRACE(std::to_string(a) + "," + std::to_string(b));
      EXPECT_EQ(format_length({{0, 0}, {a, b}}), std::to_string(c) + ".000");
      EXPECT_EQ(format_length({{-a / 2, b / 2}, {a - a / 2, -(b - b / 2)}}),
                std::to_string(c) + ".000");
      // Mixed with an axis segment: still a decimal.
      EXPECT_EQ(format_length({{0, 0}, {a, b}, {a, b + 10}}), std::to_string(c + 10) + ".000");
    }
}

TEST(FormatLength, KnownIrrationals) {
  EXPECT_EQ(format_length({{0, 0}, {1, 1}}), "1.414");  // 1.41421356
  EXPECT_EQ(format_length({{0, 0}, {1, 2}}), "2.236");  // 2.23606797
  EXPECT_EQ(format_length({{0, 0}, {1, 1}, {2, 2}}), "2.828");  // 2.82842712
  EXPECT_EQ(format_length({{0, 0}, {2, 3}}), "3.606");  // 3.60555127 rounds up
  const int m = geom::kMaxCoord;  // longest possible segment, (2m) * sqrt(2)
  EXPECT_EQ(format_length({{-m, -m}, {m, m}}), reference_length({{{-m, -m}, {m, m}}}));
}

TEST(FormatLength, RandomAgainstGmpAndLongDouble) {
  const std::uint64_t base = 77001;
  for (std::uint64_t k = 0; k < 300; ++k) {
    const std::uint64_t seed = base + k;
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937_64 rng(seed);
    const int range = k % 3 == 0 ? 10 : (k % 3 == 1 ? 100000 : geom::kMaxCoord);
    auto c = [&] {
      return static_cast<int>(static_cast<long long>(rng() % (2ULL * range + 1)) - range);
    };
    std::vector<Poly> pls(1 + rng() % 3);
    long double ld = 0;
    for (Poly& pl : pls) {
      for (int n = 1 + rng() % 8; n > 0; --n) pl.push_back({c(), c()});
      for (std::size_t i = 1; i < pl.size(); ++i)
        ld += std::sqrt(static_cast<long double>(
            (long double)(pl[i].x - (long double)pl[i - 1].x) * (pl[i].x - (long double)pl[i - 1].x) +
            (long double)(pl[i].y - (long double)pl[i - 1].y) * (pl[i].y - (long double)pl[i - 1].y)));
    }
    const std::string ref = reference_length(pls);
    EXPECT_EQ(format_total_length(pls), ref);
    if (pls.size() == 1) {
      EXPECT_EQ(format_length(pls[0]), ref);
    }
    // Cross-check the reference itself against long double, away from rounding boundaries.
    if (ref.find('.') != std::string::npos) {
      const long double frac = ld * 1000 - std::floor(ld * 1000);
      if (std::fabs(frac - 0.5L) > 1e-3L) {
        EXPECT_NEAR(std::stold(ref), std::round(ld * 1000) / 1000, 1e-3L * (1 + ld * 1e-12L));
      }
    }
  }
}

// Reference: bends are changes of the primitive direction (dx, dy) / gcd between consecutive
// non-zero segments.
long reference_bends(const Poly& pl) {
  long bends = 0;
  bool have = false;
  long px = 0, py = 0;
  for (std::size_t i = 1; i < pl.size(); ++i) {
    long dx = long{pl[i].x} - pl[i - 1].x, dy = long{pl[i].y} - pl[i - 1].y;
    if (dx == 0 && dy == 0) continue;
    const long g = std::gcd(dx, dy);
    dx /= g;
    dy /= g;
    if (have && (dx != px || dy != py)) ++bends;
    px = dx, py = dy, have = true;
  }
  return bends;
}

TEST(CountBends, HandCases) {
  EXPECT_EQ(count_bends({}), 0);
  EXPECT_EQ(count_bends({{0, 0}}), 0);
  EXPECT_EQ(count_bends({{0, 0}, {5, 0}}), 0);
  EXPECT_EQ(count_bends({{0, 0}, {5, 0}, {9, 0}, {20, 0}}), 0);       // collinear continuation
  EXPECT_EQ(count_bends({{0, 0}, {5, 0}, {5, 5}}), 1);                // L
  EXPECT_EQ(count_bends({{0, 0}, {5, 0}, {5, 0}, {5, 0}, {5, 5}}), 1);  // zero-length in a corner
  EXPECT_EQ(count_bends({{0, 0}, {0, 0}, {5, 0}, {9, 0}}), 0);        // zero-length at the start
  EXPECT_EQ(count_bends({{0, 0}, {5, 0}, {2, 0}}), 1);                // 180-degree reversal
  EXPECT_EQ(count_bends({{0, 0}, {5, 0}, {5, 0}, {2, 0}}), 1);        // reversal via a repeat
  EXPECT_EQ(count_bends({{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}}), 3);  // staircase
  EXPECT_EQ(count_bends({{0, 0}, {1, 1}, {3, 3}, {4, 3}}), 1);        // diagonal then flat
  const int m = geom::kMaxCoord;
  EXPECT_EQ(count_bends({{-m, -m}, {m, m - 1}, {-m, -m + 1}}), 1);
  EXPECT_EQ(count_bends({{-m, -m}, {0, 0}, {m, m}}), 0);
}

TEST(CountBends, RandomAgainstPrimitiveDirections) {
  const std::uint64_t base = 9100;
  for (std::uint64_t k = 0; k < 2000; ++k) {
    const std::uint64_t seed = base + k;
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937_64 rng(seed);
    const int range = k % 2 ? 2 : 1000;  // tiny range: many repeats and collinear runs
    Poly pl;
    for (int n = rng() % 10; n > 0; --n)
      pl.push_back({static_cast<int>(rng() % (2 * range + 1)) - range,
                    static_cast<int>(rng() % (2 * range + 1)) - range});
    EXPECT_EQ(count_bends(pl), reference_bends(pl));
  }
}

Layout routed_layout() {
  Layout l;
  l.name = "t";
  Blockage b1{"r", {}, 0};
  Shape rect;
  rect.rect = {{0, 0}, {1, 1}};
  b1.shapes = {rect, rect};
  Blockage b2{"p", {}, 0};
  Shape poly;
  poly.kind = Shape::Kind::Polygon;
  poly.polygon.outer = {{0, 0}, {9, 0}, {9, 9}, {0, 9}, {0, 5}};
  poly.polygon.holes = {{{1, 1}, {1, 2}, {2, 2}}};
  b2.shapes = {poly};
  l.blockages = {b1, b2};
  Net a{"a", {{"p", Point{0, 0}, {}, 0}, {"q", Point{3, 4}, {}, 0}, {"r", Point{9, 9}, {}, 0}}, {}, 0};
  Net b{"b", {{"p", Point{0, 0}, {}, 0}, {"q", Point{7, 0}, {}, 0}}, {}, 0};
  Net c{"c", {{"only", Point{1, 1}, {}, 0}}, {}, 0};
  Net d{"d", {{"p", Point{0, 0}, {}, 0}, {"q", Point{1, 0}, {}, 0}}, {}, 0};
  l.nets = {a, b, c, d};
  Routes rs;
  rs.tool = "test";
  Route ra{"a", "routed", "13.000", 1, {}, {{{{0, 0}, {3, 4}}, 0}, {{{3, 4}, {3, 9}, {9, 9}}, 0}}, 0};
  Route rb{"b", "routed", "7", 0, {}, {{{{0, 0}, {0, 0}, {7, 0}}, 0}}, 0};
  Route rc{"c", "failed", {}, {}, std::string("net c has fewer than two pins"), {}, 0};
  rs.routes = {ra, rb, rc};
  l.routes = rs;
  return l;
}

TEST(LayoutStats, CountsAndKeyOrder) {
  Layout l = routed_layout();
  l.routes.reset();
  const auto j = nlohmann::ordered_json::parse(layout_stats_json(l));
  std::vector<std::string> keys;
  for (auto it = j.begin(); it != j.end(); ++it) keys.push_back(it.key());
  EXPECT_EQ(keys, (std::vector<std::string>{"layout", "blockages", "blockage_vertices", "nets",
                                            "pins", "nets_unroutable"}));
  EXPECT_EQ(j["layout"], "t");
  EXPECT_EQ(j["blockages"], 2);
  EXPECT_EQ(j["blockage_vertices"], 4 + 4 + 5 + 3);
  EXPECT_EQ(j["nets"], 4);
  EXPECT_EQ(j["pins"], 3 + 2 + 1 + 2);
  EXPECT_EQ(j["nets_unroutable"], 1);
  // indent = -1: one line.
  const std::string compact = layout_stats_json(l, -1);
  EXPECT_EQ(compact.find('\n'), compact.size() - 1);
}

TEST(LayoutStats, Routes) {
  const auto j = nlohmann::ordered_json::parse(layout_stats_json(routed_layout()));
  const auto& r = j.at("routes");
  // a: 5 (3-4-5) + 5 + 6 = 16, one bend (in the second wire); b: 7, no bend.
  EXPECT_EQ(r.at("a").at("status"), "routed");
  EXPECT_DOUBLE_EQ(r.at("a").at("length").get<double>(), 16.0);
  EXPECT_EQ(r.at("a").at("bends"), 1);
  EXPECT_EQ(r.at("a").at("pins"), 3);
  EXPECT_EQ(r.at("a").at("wires"), 2);
  EXPECT_EQ(r.at("b").at("length"), 7);
  EXPECT_TRUE(r.at("b").at("length").is_number_integer());
  EXPECT_EQ(r.at("b").at("bends"), 0);
  EXPECT_EQ(r.at("c").at("status"), "failed");
  EXPECT_EQ(r.at("c").at("reason"), "net c has fewer than two pins");
  EXPECT_FALSE(r.at("c").contains("length"));
  EXPECT_EQ(r.at("d").at("status"), "missing");
  const auto& t = j.at("totals");
  EXPECT_EQ(t.at("routed"), 2);
  EXPECT_EQ(t.at("failed"), 1);
  EXPECT_EQ(t.at("missing"), 1);
  EXPECT_EQ(t.at("wires"), 3);
  EXPECT_EQ(t.at("bends"), 1);
  EXPECT_DOUBLE_EQ(t.at("length").get<double>(), 23.0);
  // A decimal total prints with at most 3 fractional digits.
  Layout l = routed_layout();
  l.routes->routes[1].wires[0].points = {{0, 0}, {1, 1}};
  const std::string text = layout_stats_json(l);
  EXPECT_NE(text.find("\"length\": 1.414"), std::string::npos) << text;
  EXPECT_NE(text.find("\"length\": 17.414"), std::string::npos) << text;
}

}  // namespace stats_test
}  // namespace taut::io
