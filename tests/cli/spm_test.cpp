// `taut spm`: for several sources and query points, each query's distance to the nearest source,
// which source and a shortest path, checked against the brute-force references
// (tests/oracle/l1_oracle.h, oct_oracle.h): the distance is the least reference distance over
// the sources, the named source is at that distance, the path runs from it to the query with
// exactly that length in free space; unreachable or blocked queries get null and exit status 1.
#include <gtest/gtest.h>

#include <gmpxx.h>
#include <nlohmann/json.hpp>
#include <cmath>
#include <random>
#include <tuple>

#include "geom/fixed_norm.h"
#include "geom/normalize.h"
#include "io/layout_geometry.h"
#include "io/layout_reader.h"
#include "oracle/l1_oracle.h"
#include "oracle/oct_oracle.h"
#include "support/layout_reference.h"
#include "support/run.h"
#include "support/sanitized.h"

namespace taut::test {
namespace spm_test {

using geom::Point;
using geom::Root2;

// Returns how many queries were reachable (and so had their distance, source and path checked).
template <class Reference>
int check_spm_on(const std::string& file, const std::vector<Point>& sources, const std::vector<Point>& queries,
                  bool oct) {
  std::vector<std::string> args = {"spm", file, "--json", "-q"};
  for (const Point s : sources) args.insert(args.end(), {"--source", std::to_string(s.x) + "," + std::to_string(s.y)});
  for (const Point q : queries) args.insert(args.end(), {"--query", std::to_string(q.x) + "," + std::to_string(q.y)});
  if (oct) args.insert(args.end(), {"--orientations", "octilinear"});
  const auto r = run_taut(args);
  EXPECT_TRUE(r.status == 0 || r.status == 1) << r.err;
  if (r.status != 0 && r.status != 1) return 0;
  const auto j = nlohmann::json::parse(r.out);
  std::vector<Point> extra = sources;
  extra.insert(extra.end(), queries.begin(), queries.end());
  const auto lr = reference_for<Reference>(file, extra);
  if (!lr.ref) return 0;
  const Reference& ref = *lr.ref;
  EXPECT_EQ(j["queries"].size(), queries.size());
  if (j["queries"].size() != queries.size()) return 0;
  bool any_unreachable = false;
  int reachable = 0;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const auto& q = j["queries"][i];
    SCOPED_TRACE("query " + std::to_string(queries[i].x) + "," + std::to_string(queries[i].y));
    EXPECT_EQ(points_of(nlohmann::json::array({q["point"]}))[0], queries[i]);
    std::optional<Root2> best;
    std::vector<std::optional<Root2>> per_source;
    for (const Point s : sources) {
      std::optional<Root2> d;
      if constexpr (std::is_same_v<Reference, oracle::L1Reference>) {
        if (const auto l = ref.distance(s, queries[i])) d = Root2{*l, 0};
      } else {
        d = ref.distance(s, queries[i]);
      }
      per_source.push_back(d);
      if (d && (!best || *d < *best)) best = d;
    }
    if (!best) {
      any_unreachable = true;
      EXPECT_TRUE(q["distance"].is_null());
      EXPECT_TRUE(q["source"].is_null());
      EXPECT_TRUE(q.contains("reason"));
      continue;
    }
    ++reachable;
    if (q["distance"].is_null()) {
      ADD_FAILURE() << "null distance for a reachable query";
      continue;
    }
    const Root2 got = oct ? Root2{q["distance_exact"][0].get<std::int64_t>(), q["distance_exact"][1].get<std::int64_t>()}
                          : Root2{q["distance"].get<std::int64_t>(), 0};
    EXPECT_EQ(got, *best);
    if (oct) {  // the Euclidean bounds: [d cos(pi/8), d] (tests/router/euclid_approx_test.cpp checks the claim)
      EXPECT_TRUE(q.contains("euclidean_bounds"));
      if (!q.contains("euclidean_bounds")) continue;
      EXPECT_EQ(q["euclidean_bounds"][1].get<double>(), got.to_double());
      EXPECT_NEAR(q["euclidean_bounds"][0].get<double>(), got.to_double() * 0.92387953251128674, 1e-9 * (1 + got.to_double()));
    } else {
      EXPECT_FALSE(q.contains("euclidean_bounds"));
    }
    const std::size_t src = q["source"].get<std::size_t>();
    if (src >= sources.size()) {
      ADD_FAILURE() << "source " << src;
      continue;
    }
    EXPECT_EQ(per_source[src], best) << "the named source is not a nearest one";
    const auto path = points_of(q["points"]);
    if (path.empty()) {
      ADD_FAILURE() << "empty path";
      continue;
    }
    EXPECT_EQ(path.front(), sources[src]);
    EXPECT_EQ(path.back(), queries[i]);
    if (path.size() > 1) {
      if constexpr (std::is_same_v<Reference, oracle::L1Reference>)
        EXPECT_EQ(ref.check_path(path), best->a);
      else
        EXPECT_EQ(ref.check_path(path), best);
    }
  }
  EXPECT_EQ(r.status, any_unreachable ? 1 : 0);
  return reachable;
}

TEST(Spm, GeneratedLayoutsMatchTheReference) {
  const std::string dir = temp_dir("spm_gen");
  int reachable = 0;
  for (const char* kind : {"rects", "polygons", "maze", "degenerate"}) {
    for (int seed = 1; seed <= (kSanitized ? 1 : 2); ++seed) {  // each taut run costs seconds under ASan
      SCOPED_TRACE(std::string(kind) + " seed " + std::to_string(seed));
      const std::string in = dir + "/" + kind + std::to_string(seed) + ".xml";
      ASSERT_EQ(run_taut({"gen", kind, "-o", in, "--size", "300", "--nets", "0", "--seed", std::to_string(seed)}).status,
                0);
      io::ReadResult rr = io::read_layout(in);
      ASSERT_TRUE(rr.layout && rr.layout->boundary);
      const geom::Box b = rr.layout->boundary->box;
      std::mt19937_64 rng(static_cast<std::uint64_t>(seed) * 31 + kind[0]);
      auto pick = [&] {
        return Point{static_cast<int>(b.lo.x + static_cast<std::int64_t>(rng() % static_cast<std::uint64_t>(b.hi.x - b.lo.x + 1))),
                     static_cast<int>(b.lo.y + static_cast<std::int64_t>(rng() % static_cast<std::uint64_t>(b.hi.y - b.lo.y + 1)))};
      };
      std::vector<Point> sources, queries;
      for (int k = 0; k < 1 + seed * 2; ++k) sources.push_back(pick());
      for (int k = 0; k < 15; ++k) queries.push_back(pick());
      reachable += check_spm_on<oracle::L1Reference>(in, sources, queries, false);
      reachable += check_spm_on<oracle::OctilinearReference>(in, sources, queries, true);
    }
  }
  std::printf("%d reachable queries checked\n", reachable);
  EXPECT_GT(reachable, sanitized_share(120, 2));  // of 240 (fewer under the sanitizers)
}

TEST(Spm, DemoNamesBlockedAndWalledInQueries) {
  const std::string demo = std::string(TAUT_SOURCE_DIR) + "/designs/demo.xml";
  // (10000,9000) is inside dsp; (17000,7500) lies in ring's hole, which only the island shares
  const auto r = run_taut({"spm", demo, "--source", "500,500", "--source", "23000,13000", "--query", "18000,11500",
                           "--query", "10000,9000", "--query", "16500,7500", "--json"});
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("[ROUTE-0001] --query 10000,9000 lies inside blockage \"dsp\""), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("[ROUTE-0002] --query no source reaches 16500,7500"), std::string::npos) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["queries"][0]["distance"].get<std::int64_t>(), 6500);  // 5000 across, 1500 down
  EXPECT_EQ(j["queries"][0]["source"].get<int>(), 1);
  check_spm_on<oracle::L1Reference>(demo, {{500, 500}, {23000, 13000}}, {{18000, 11500}, {10000, 9000}, {16500, 7500}},
                                    false);
  // usage errors exit 2 and print nothing on stdout
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"spm", demo, "--query", "1,1"}, {"spm", demo, "--source", "1,1"},
        {"spm", demo, "--source", "1.5,1", "--query", "1,1"}}) {
    const auto u = run_taut(args);
    EXPECT_EQ(u.status, 2) << u.err;
    EXPECT_TRUE(u.out.empty()) << u.out;
  }
}

// Octilinear on a domain too wide for OctMap's frames (width plus height near 2^32): answered by
// a wavefront run instead, with the same exact numbers. A wall x in [-100, 100], y <= 10^9;
// source (-10^9, 0), query (10^9, 0): up the left to the corner (-100, 10^9) (10^9 - 100 across,
// 10^9 up: 100 straight, 10^9 - 100 diagonal), 200 across, down to the query the mirror.
TEST(Spm, OctilinearOnAVeryWideDomain) {
  const std::string dir = temp_dir("spm_wide");
  write_text(dir + "/wide.xml", R"(<?xml version="1.0"?>
<layout name="wide" version="1" dbu-per-micron="1000">
  <boundary x0="-1073741823" y0="-1073741823" x1="1073741823" y1="1073741823"/>
  <blockage id="wall"><rect x0="-100" y0="-1073741823" x1="100" y1="1000000000"/></blockage>
</layout>
)");
  const auto r = run_taut({"spm", dir + "/wide.xml", "--source", "-1000000000,0", "--query", "1000000000,0", "--query",
                           "-999999000,1000", "--orientations", "octilinear", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["queries"][0]["distance_exact"], nlohmann::json::array({100 + 200 + 100, 2 * (1000000000 - 100)}));
  EXPECT_EQ(points_of(j["queries"][0]["points"]),
            (std::vector<Point>{{-1000000000, 0}, {-100, 1000000000}, {100, 1000000000}, {1000000000, 0}}));
  EXPECT_EQ(j["queries"][1]["distance_exact"], nlohmann::json::array({0, 1000}));
  // The same layout through every command that builds free space: the frame obstacle around a
  // domain at +-(2^30 - 1) lies at +-2^30, whose differences need 64 bits (the union of the
  // frame overflowed an int under UBSan before).
  write_text(dir + "/wide_net.xml", R"(<?xml version="1.0"?>
<layout name="wide" version="1" dbu-per-micron="1000">
  <boundary x0="-1073741823" y0="-1073741823" x1="1073741823" y1="1073741823"/>
  <blockage id="wall"><rect x0="-100" y0="-1073741823" x1="100" y1="1000000000"/></blockage>
  <net name="n"><pin name="a" x="-1000000000" y="0"/><pin name="b" x="1000000000" y="0"/><pin name="c" x="1073741823" y="-1073741823"/></net>
</layout>
)");
  for (const char* o : {"rectilinear", "octilinear"}) {
    const std::string out = dir + "/wide." + o + ".xml";
    const auto route = run_taut({"route", dir + "/wide_net.xml", "-o", out, "--orientations", o, "-q"});
    EXPECT_EQ(route.status, 0) << o << ": " << route.err;
    EXPECT_EQ(run_taut({"check", out, "-q"}).status, 0) << o;
  }
  const auto v = run_taut({"voronoi", dir + "/wide_net.xml", "-q", "--json"});
  ASSERT_EQ(v.status, 0) << v.err;
  EXPECT_EQ(nlohmann::json::parse(v.out)["sites"].size(), 3u);
  // L1 from the top right corner to the bottom left: around the wall's top, 2 (2^31 - 2).
  const auto l1 = run_taut({"spm", dir + "/wide_net.xml", "--source", "1073741823,1073741823", "--query",
                            "-1073741823,-1073741823", "--json"});
  ASSERT_EQ(l1.status, 0) << l1.err;
  EXPECT_EQ(nlohmann::json::parse(l1.out)["queries"][0]["distance"].get<std::int64_t>(), 4294967292);
}

// --orientations any: epsilon-approximate Euclidean distances. Each query's "norm_length" is the
// least NormReference distance over the sources (exact integers, the norm --epsilon picks: 16,
// 32 or 48 directions), the named source is at that distance, the path has exactly that
// N-length, "distance" is d / 4096 and "euclidean_bounds" [d / Lambda, d / 4096] (the claim that
// they hold the Euclidean geodesic distance is tests/router/euclid_approx_test.cpp's).
TEST(Spm, EuclideanDistancesWithinEpsilon) {
  const std::string dir = temp_dir("spm_any");
  int reachable = 0;
  for (const auto& [kind, eps, order] : {std::tuple{"rects", "0.03", 2}, std::tuple{"polygons", "0.02", 3},
                                         std::tuple{"maze", "0.01", 4}, std::tuple{"degenerate", "0.008", 4}}) {
    SCOPED_TRACE(std::string(kind) + " epsilon " + eps);
    const std::string in = dir + "/" + kind + ".xml";
    ASSERT_EQ(run_taut({"gen", kind, "-o", in, "--size", "200", "--nets", "0", "--seed", "3"}).status, 0);
    io::ReadResult rr = io::read_layout(in);
    ASSERT_TRUE(rr.layout && rr.layout->boundary);
    const geom::Box b = rr.layout->boundary->box;
    std::mt19937_64 rng(static_cast<std::uint64_t>(order) * 77 + kind[0]);
    auto pick = [&] {
      return Point{static_cast<int>(b.lo.x + static_cast<std::int64_t>(rng() % static_cast<std::uint64_t>(b.hi.x - b.lo.x + 1))),
                   static_cast<int>(b.lo.y + static_cast<std::int64_t>(rng() % static_cast<std::uint64_t>(b.hi.y - b.lo.y + 1)))};
    };
    std::vector<Point> sources{pick(), pick()}, queries;
    for (int k = 0; k < 12; ++k) queries.push_back(pick());
    std::vector<std::string> args = {"spm", in, "--json", "-q", "--orientations", "any", "--epsilon", eps};
    for (const Point s : sources) args.insert(args.end(), {"--source", std::to_string(s.x) + "," + std::to_string(s.y)});
    for (const Point q : queries) args.insert(args.end(), {"--query", std::to_string(q.x) + "," + std::to_string(q.y)});
    const auto r = run_taut(args);
    ASSERT_TRUE(r.status == 0 || r.status == 1) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["metric"], "euclidean");
    EXPECT_EQ(j["orientations"], "any");
    EXPECT_EQ(j["directions"].get<int>(), order == 2 ? 16 : order == 3 ? 32 : 48);
    EXPECT_LE(j["epsilon"].get<double>(), std::stod(eps));
    std::vector<Point> extra = sources;
    extra.insert(extra.end(), queries.begin(), queries.end());
    const auto norm = geom::normalize_obstacles(io::blockage_polygons(*rr.layout), io::routing_domain(*rr.layout, extra));
    const oracle::NormReference ref(norm.domain, norm.obstacles, order);
    const double lambda = std::sqrt(static_cast<double>(geom::fixed_norm_lambda_max_sq(order)));
    ASSERT_EQ(j["queries"].size(), queries.size());
    bool unreachable = false;
    for (std::size_t i = 0; i < queries.size(); ++i) {
      const auto& q = j["queries"][i];
      std::optional<std::int64_t> best;
      std::vector<std::optional<std::int64_t>> per;
      for (const Point s : sources) {
        per.push_back(ref.distance(s, queries[i]));
        if (per.back() && (!best || *per.back() < *best)) best = per.back();
      }
      if (!best) {
        unreachable = true;
        EXPECT_TRUE(q["distance"].is_null());
        continue;
      }
      ++reachable;
      ASSERT_FALSE(q["distance"].is_null());
      const std::int64_t d = q["norm_length"].get<std::int64_t>();
      EXPECT_EQ(d, *best);
      EXPECT_DOUBLE_EQ(q["distance"].get<double>(), static_cast<double>(d) / 4096);
      // the printed bounds hold [d / Lambda, d / 4096] (exactly: lo^2 Lambda^2 <= d^2, hi 4096 >= d),
      // and are that interval to within 10^-12 relative
      const double lo = q["euclidean_bounds"][0].get<double>(), hi = q["euclidean_bounds"][1].get<double>();
      const mpq_class mlo(lo), mhi(hi), md(static_cast<double>(d));
      EXPECT_LE(mlo * mlo * mpq_class(static_cast<double>(geom::fixed_norm_lambda_max_sq(order))), md * md);
      EXPECT_GE(mhi * 4096, md);
      EXPECT_NEAR(lo, static_cast<double>(d) / lambda, 1e-12 * static_cast<double>(d) / lambda);
      EXPECT_NEAR(hi, static_cast<double>(d) / 4096, 1e-12 * static_cast<double>(d) / 4096);
      const std::size_t src = q["source"].get<std::size_t>();
      ASSERT_LT(src, sources.size());
      EXPECT_EQ(per[src], best);
      const auto path = points_of(q["points"]);
      ASSERT_FALSE(path.empty());
      EXPECT_EQ(path.front(), sources[src]);
      EXPECT_EQ(path.back(), queries[i]);
      if (path.size() > 1) {
        EXPECT_EQ(ref.check_path(path), best);
      }
    }
    EXPECT_EQ(r.status, unreachable ? 1 : 0);
  }
  EXPECT_GT(reachable, 20);  // of 48
  // --epsilon below the finest set, or without --orientations any: usage errors, nothing on stdout
  const std::string demo = std::string(TAUT_SOURCE_DIR) + "/designs/demo.xml";
  for (const std::vector<std::string>& a :
       {std::vector<std::string>{"spm", demo, "--source", "500,500", "--query", "19500,11500", "--orientations", "any",
                                 "--epsilon", "0.005"},
        {"spm", demo, "--source", "500,500", "--query", "19500,11500", "--epsilon", "0.05"}}) {
    const auto u = run_taut(a);
    EXPECT_EQ(u.status, 2) << u.err;
    EXPECT_NE(u.err.find("[CLI-0026]"), std::string::npos) << u.err;
    EXPECT_TRUE(u.out.empty()) << u.out;
  }
  // route and path still refuse free-angle wires
  const auto p = run_taut({"path", demo, "--from", "500,500", "--to", "19500,11500", "--orientations", "any"});
  EXPECT_EQ(p.status, 2);
  EXPECT_NE(p.err.find("[CLI-0021]"), std::string::npos) << p.err;
}

// Many points from files: the same answers as the options give; a bad line is named with its
// file and line, and nothing is printed on stdout.
TEST(Spm, PointFiles) {
  const std::string demo = std::string(TAUT_SOURCE_DIR) + "/designs/demo.xml";
  const std::string dir = temp_dir("spm_files");
  write_text(dir + "/src.txt", "# sources\n500,500\n\n  23000,13000  \n");
  write_text(dir + "/q.txt", "18000,11500\n10000,10000\n");
  const auto f = run_taut({"spm", demo, "--source-file", dir + "/src.txt", "--query-file", dir + "/q.txt", "--json"});
  const auto o = run_taut({"spm", demo, "--source", "500,500", "--source", "23000,13000", "--query", "18000,11500",
                           "--query", "10000,10000", "--json"});
  EXPECT_EQ(f.status, 0) << f.err;
  EXPECT_EQ(f.out, o.out);
  // options and files add up: sources from the option first, then the file's
  const auto both = run_taut({"spm", demo, "--source", "1000,13500", "--source-file", dir + "/src.txt", "--query",
                              "1000,13000", "--json"});
  ASSERT_EQ(both.status, 0) << both.err;
  EXPECT_EQ(nlohmann::json::parse(both.out)["queries"][0]["source"].get<int>(), 0);
  write_text(dir + "/bad.txt", "500,500\n# fine\n23000;13000\n");
  const auto bad = run_taut({"spm", demo, "--source-file", dir + "/bad.txt", "--query", "1,1", "--json"});
  EXPECT_EQ(bad.status, 2);
  EXPECT_TRUE(bad.out.empty()) << bad.out;
  EXPECT_NE(bad.err.find(dir + "/bad.txt:3: error: [CLI-0025] \"23000;13000\""), std::string::npos) << bad.err;
  const auto missing = run_taut({"spm", demo, "--source", "1,1", "--query-file", dir + "/none.txt"});
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("[IO-0001]"), std::string::npos) << missing.err;
  const auto empty_q = run_taut({"spm", demo, "--source", "1,1", "--query-file", dir + "/src.txt", "--query-file",
                                 dir + "/q.txt"});
  EXPECT_EQ(empty_q.status, 2) << "the option is given twice";
  const auto no_name = run_taut({"spm", demo, "--source", "1,1", "--query-file", ""});
  EXPECT_EQ(no_name.status, 2);
  EXPECT_NE(no_name.err.find("--query-file \"\": needs a file name"), std::string::npos) << no_name.err;
}

}  // namespace spm_test
}  // namespace taut::test
