// taut spm FILE --source X,Y [--source X,Y ...] --query X,Y [--query X,Y ...] [--orientations
// rectilinear|octilinear] [--json]: for each query point, the exact distance to the nearest
// source among the layout's blockages, which source (0-based, in the order given) and a shortest
// path (the source, bends at obstacle vertices, the query point).
//
// The shortest path map of the sources (router/spm.h: L1Map, or OctMap for octilinear) is built
// once and each query is a point location in it (see spm.h for its cost). An octilinear domain
// too wide for OctMap's frames (OctMap::fits: width plus height above about 2^31) is answered by
// one multi-source wavefront run instead (router/wavefront.h: all sources at distance 0, the
// queries as targets): the same exact answers.
//
// --orientations any (here only: spm reports distances, not wires): epsilon-approximate
// Euclidean geodesic distances from a fixed-orientation norm (geom/fixed_norm.h, Mitchell §6)
// with 16, 32 or 48 directions, the fewest whose guaranteed epsilon is at most --epsilon
// (default 0.01): one router::NormWavefront run from all sources, exact integer N-lengths d,
// reported with the interval [d / Lambda, d / S] that holds the Euclidean geodesic distance.
#include <cmath>
#include <cstdio>
#include <utility>
#include <optional>
#include <stdexcept>
#include <iostream>
#include <numbers>

#include <nlohmann/json.hpp>

#include "geom/fixed_norm.h"
#include "router/spm.h"
#include "router/wavefront.h"
#include "tools/cli.h"
#include "tools/commands.h"
#include "tools/route_common.h"

namespace taut::cli {
namespace {

// The Euclidean interval [d / Lambda, d / S] of a norm length d (geom/fixed_norm.h) as doubles
// rounded outwards: each end is checked exactly (GMP rationals: lo^2 Lambda^2 <= d^2, hi S >= d)
// and then moved one more step out, so that a decimal that reads back as the double (JSON's
// shortest form) lies outside the interval too.
std::pair<double, double> euclidean_interval(std::int64_t d, std::int64_t lambda_sq) {
  using router::Rational;
  const Rational dd(d), d2 = dd * dd;
  double lo = static_cast<double>(static_cast<long double>(d) / std::sqrt(static_cast<long double>(lambda_sq)));
  while (lo > 0 && Rational(lo) * Rational(lo) * lambda_sq > d2) lo = std::nextafter(lo, 0.0);
  if (lo > 0) lo = std::nextafter(lo, 0.0);
  double hi = static_cast<double>(d) / static_cast<double>(geom::kNormScale);
  while (Rational(hi) * geom::kNormScale < dd) hi = std::nextafter(hi, HUGE_VAL);
  hi = std::nextafter(hi, HUGE_VAL);
  return {lo, hi};
}

}  // namespace

void add_spm(CLI::App& app, int& status) {
  struct Args {
    std::string file;
    std::vector<std::string> sources, queries;
    std::string source_file, query_file;
    bool json = false;
    std::optional<double> epsilon;
    RoutingOptions routing;
    LoadOptions load;
  };
  auto args = std::make_shared<Args>();
  CLI::App* sub = app.add_subcommand(
      "spm", "Distance, nearest source and shortest path from several sources to query points");
  sub->add_option("--source", args->sources, "a source point X,Y (repeat the option for more)");
  sub->add_option("--query", args->queries, "a query point X,Y (repeat the option for more)");
  sub->add_option("--source-file", args->source_file,
                  "more sources: a text file with one X,Y per line (blank lines and # comments skipped)");
  sub->add_option("--query-file", args->query_file, "more query points, in the same format");
  sub->add_flag("--json", args->json, "print one JSON document on stdout");
  add_routing_options(sub, args->routing);
  args->routing.allow_any = true;
  sub->add_option("--epsilon", args->epsilon,
                  "with --orientations any: the largest relative width of each distance's Euclidean "
                  "interval, at least 0.0076 (default 0.01)");
  add_input_options(sub, args->file, args->load, "do not print warnings");
  sub->callback([args, &status, sub] {
    auto sub_count = [sub](const char* name) { return sub->count(name) > 0; };
    std::vector<geom::Point> sources, queries;
    for (const auto& [name, texts, out] : {std::tuple{"--source", &args->sources, &sources},
                                           std::tuple{"--query", &args->queries, &queries}})
      for (const std::string& text : *texts) {
        const auto p = parse_point_option(name, text);
        if (!p) {
          status = kInvalid;
          return;
        }
        out->push_back(*p);
      }
    for (const auto& [name, path, out] : {std::tuple{"--source-file", &args->source_file, &sources},
                                          std::tuple{"--query-file", &args->query_file, &queries}}) {
      if (!sub_count(name)) continue;
      if (path->empty()) {
        print_usage_error("CLI-0001", std::string(name) + " \"\": needs a file name");
        status = kInvalid;
        return;
      }
      if (!read_point_file(*path, *out)) {
        status = kInvalid;
        return;
      }
    }
    if (sources.empty() || queries.empty()) {
      print_usage_error("CLI-0001", sources.empty() ? "spm needs at least one source (--source or --source-file)"
                                                    : "spm needs at least one query (--query or --query-file)");
      status = kInvalid;
      return;
    }
    const auto layout = load_routing_layout(args->file, args->load, args->routing);
    if (!layout) {
      status = kInvalid;
      return;
    }
    const std::string orientations = routing_orientations(args->routing, *layout);
    const bool oct = orientations == "octilinear", any = orientations == "any";
    // --orientations any: the fewest directions whose epsilon is at most --epsilon
    int order = 0;
    if (args->epsilon && !any) {
      print_usage_error("CLI-0026", "--epsilon applies to --orientations any (epsilon-approximate "
                                    "Euclidean distances)");
      status = kInvalid;
      return;
    }
    if (any) {
      const double eps = args->epsilon.value_or(0.01);
      for (int o = 2; o <= 4 && order == 0; ++o)
        if (geom::fixed_norm_epsilon(o) <= eps) order = o;
      if (order == 0) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.4Lf", geom::fixed_norm_epsilon(4));
        print_usage_error("CLI-0026", "--epsilon " + std::to_string(eps) + ": the finest available is " + buf +
                                          " (48 directions)");
        status = kInvalid;
        return;
      }
    }
    std::vector<geom::Point> all = sources;
    all.insert(all.end(), queries.begin(), queries.end());
    const geom::NormalizedObstacles norm = routing_obstacles(*layout, all);

    // Per query: the distance a + b*sqrt2 (b = 0 for L1), the source, the path.
    struct Answer {
      std::optional<geom::Root2> distance;
      std::optional<std::size_t> source;
      std::vector<geom::Point> path;
      bool free = true;
    };
    std::vector<Answer> answers(queries.size());
    std::vector<std::int64_t> norm_lengths(queries.size(), 0);  // any: d, scaled by kNormScale
    auto collect = [&](auto& wf, auto to_root2) {
      wf.run(sources, queries, router::WavefrontStop::AllTargets);
      for (std::size_t i = 0; i < queries.size(); ++i) {
        if (const auto d = wf.target_distance(i))
          answers[i] = {to_root2(*d), wf.target_source(i), wf.target_path(i), true};
        else
          answers[i].free = wf.is_free(queries[i]);
      }
    };
    if (any) {
      std::optional<router::NormWavefront> wf;
      try {
        wf.emplace(norm.domain, norm.obstacles, order);
      } catch (const std::domain_error& e) {
        print_usage_error("CLI-0002", std::string("--orientations any: ") + e.what());
        status = kResource;
        return;
      }
      wf->run(sources, queries, router::WavefrontStop::AllTargets);
      for (std::size_t i = 0; i < queries.size(); ++i) {
        if (const auto d = wf->target_distance(i)) {
          answers[i] = {geom::Root2{*d, 0}, wf->target_source(i), wf->target_path(i), true};
          norm_lengths[i] = *d;
        } else {
          answers[i].free = wf->is_free(queries[i]);
        }
      }
    } else if (oct && !router::OctMap::fits(norm.domain)) {
      router::OctWavefront wf(norm.domain, norm.obstacles);
      collect(wf, [](const geom::Root2& d) { return d; });
    } else if (oct) {
      const router::OctMap map(norm.domain, norm.obstacles, sources);
      for (std::size_t i = 0; i < queries.size(); ++i) {
        if (const auto a = map.locate(queries[i]))
          answers[i] = {a->distance, a->source, map.path(queries[i], *a), true};
        else
          answers[i].free = map.is_free(queries[i]);
      }
    } else {
      // L1: the shortest path map, built once (one wavefront run and a vertical decomposition),
      // then a point location per query.
      const router::L1Map map(norm.domain, norm.obstacles, sources);
      for (std::size_t i = 0; i < queries.size(); ++i) {
        if (const auto a = map.locate(queries[i]))
          answers[i] = {geom::Root2{a->distance, 0}, a->source, map.path(queries[i], *a), true};
        else
          answers[i].free = map.is_free(queries[i]);
      }
    }

    nlohmann::ordered_json j;
    j["metric"] = any ? "euclidean" : "l1";
    if (oct) j["orientations"] = "octilinear";
    const long double scale = static_cast<long double>(geom::kNormScale);
    if (any) {
      j["orientations"] = "any";
      j["directions"] = order == 2 ? 16 : order == 3 ? 32 : 48;
      j["epsilon"] = static_cast<double>(geom::fixed_norm_epsilon(order));
    }
    auto rows = nlohmann::ordered_json::array();
    std::size_t unreachable = 0;
    for (std::size_t i = 0; i < queries.size(); ++i) {
      const Answer& a = answers[i];
      std::pair<double, double> bounds;  // --orientations any: the Euclidean interval
      nlohmann::ordered_json q;
      q["point"] = {queries[i].x, queries[i].y};
      if (a.distance && any) {
        // d / S is the N-length of a real path divided by S, at least its Euclidean length; the
        // Euclidean geodesic distance lies in [d / Lambda, d / S] (geom/fixed_norm.h)
        const long double d = static_cast<long double>(norm_lengths[i]);
        q["distance"] = static_cast<double>(d / scale);
        bounds = euclidean_interval(norm_lengths[i], geom::fixed_norm_lambda_max_sq(order));
        q["euclidean_bounds"] = {bounds.first, bounds.second};
        q["norm_length"] = norm_lengths[i];
        q["source"] = *a.source;
        auto pts = nlohmann::ordered_json::array();
        for (const geom::Point p : a.path) pts.push_back({p.x, p.y});
        q["points"] = pts;
      } else if (a.distance) {
        if (a.distance->b == 0)
          q["distance"] = a.distance->a;
        else
          q["distance"] = a.distance->to_double();
        if (oct) {
          q["distance_exact"] = {a.distance->a, a.distance->b};
          // The octilinear distance approximates the Euclidean geodesic one (Mitchell's fixed
          // orientations, k = 4): d_E <= d_8 <= sec(pi/8) d_E, so d_E lies in these bounds.
          const double d8 = a.distance->to_double();
          q["euclidean_bounds"] = {d8 * std::cos(std::numbers::pi / 8), d8};
        }
        q["source"] = *a.source;
        auto pts = nlohmann::ordered_json::array();
        for (const geom::Point p : a.path) pts.push_back({p.x, p.y});
        q["points"] = pts;
      } else {
        ++unreachable;
        q["distance"] = nullptr;
        q["source"] = nullptr;
        q["points"] = nlohmann::ordered_json::array();
        const std::string code = a.free ? "ROUTE-0002" : "ROUTE-0001";
        q["reason"] = a.free ? "no source reaches " + point_text(queries[i]) + ": blockages wall it in, or every source out"
                             : point_text(queries[i]) + " " + why_not_free(*layout, queries[i]);
        print_usage_error(code, "--query " + q["reason"].get<std::string>());
      }
      rows.push_back(q);
      if (!args->json && a.distance && any) {
        // the bounds to 6 decimals, rounded outwards (a step of 10^-6 more for the rounding of
        // the product)
        const auto [lo, hi] = bounds;
        char buf[128];
        std::snprintf(buf, sizeof buf, "%.6Lf (Euclidean in [%.6Lf, %.6Lf])",
                      static_cast<long double>(norm_lengths[i]) / scale,
                      (std::floor(static_cast<long double>(lo) * 1e6L) - 1) / 1e6L,
                      (std::ceil(static_cast<long double>(hi) * 1e6L) + 1) / 1e6L);
        std::cout << point_text(queries[i]) << ": distance " << buf << " from source " << *a.source << " ("
                  << point_text(sources[*a.source]) << "), path";
        for (const geom::Point p : a.path) std::cout << ' ' << point_text(p);
        std::cout << '\n';
      } else if (!args->json && a.distance) {
        std::cout << point_text(queries[i]) << ": distance " << length_text(*a.distance) << " from source "
                  << *a.source << " (" << point_text(sources[*a.source]) << "), path";
        for (const geom::Point p : a.path) std::cout << ' ' << point_text(p);
        std::cout << '\n';
      }
    }
    j["queries"] = rows;
    if (args->json) std::cout << j.dump() << '\n';
    status = unreachable ? kIncomplete : kOk;
  });
}

}  // namespace taut::cli
