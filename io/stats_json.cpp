// Lengths, bends and layout statistics.
//
// format_length is exact up to the printed precision: each segment length sqrt(d2) is computed
// in fixed point as floor(sqrt(d2) * 2^32) with an exact integer square root (d2 < 2^63, so
// d2 * 2^64 < 2^127 fits unsigned __int128); the sum of n floors is below the true sum by less
// than n * 2^-32, far below the 0.0005 that decides the third decimal.
#include "io/stats_json.h"

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>

#include "geom/predicates.h"

namespace taut::io {
namespace {

using u128 = unsigned __int128;
using geom::i128;
using geom::i64;

constexpr int kFracBits = 32;

// floor(sqrt(v)) exactly for any v < 2^127.
u128 isqrt(u128 v) {
  if (v == 0) return 0;
  // Start above the root (Newton from above decreases monotonically to floor(sqrt(v))).
  u128 x = static_cast<u128>(std::sqrt(static_cast<double>(v))) + 2;
  if (x * x < v) x = v;  // defensive; never taken for v < 2^127 but keeps the loop correct
  while (true) {
    const u128 y = (x + v / x) / 2;
    if (y >= x) break;
    x = y;
  }
  while (x * x > v) --x;
  while ((x + 1) * (x + 1) <= v) ++x;
  return x;
}

struct LengthSum {
  bool all_axis = true;
  i128 integer = 0;  // exact sum while every segment is axis-parallel
  u128 fixed = 0;    // sum of floor(len * 2^32) over every segment
  void add(const std::vector<Point>& pl) {
    for (std::size_t i = 1; i < pl.size(); ++i) {
      const i64 dx = i64{pl[i].x} - pl[i - 1].x, dy = i64{pl[i].y} - pl[i - 1].y;
      if (dx != 0 && dy != 0) all_axis = false;
      integer += dx < 0 ? -dx : dx;
      integer += dy < 0 ? -dy : dy;
      const u128 d2 = static_cast<u128>(dx * dx + dy * dy);  // < 2^63
      fixed += isqrt(d2 << (2 * kFracBits));
    }
  }
  std::string text() const {
    if (all_axis) return to_string(integer);
    // Round to thousandths, half up.
    const u128 q = (fixed * 1000 + (u128{1} << (kFracBits - 1))) >> kFracBits;
    std::string frac = to_string(static_cast<i128>(q % 1000));
    return to_string(static_cast<i128>(q / 1000)) + "." + std::string(3 - frac.size(), '0') + frac;
  }
  static std::string to_string(i128 v) {
    if (v == 0) return "0";
    const bool neg = v < 0;
    std::string s;
    u128 u = neg ? static_cast<u128>(-v) : static_cast<u128>(v);
    while (u) {
      s += static_cast<char>('0' + static_cast<int>(u % 10));
      u /= 10;
    }
    if (neg) s += '-';
    return {s.rbegin(), s.rend()};
  }
};

std::int64_t shape_vertices(const Shape& s) {
  if (s.kind == Shape::Kind::Rect) return 4;
  std::int64_t v = static_cast<std::int64_t>(s.polygon.outer.size());
  for (const auto& h : s.polygon.holes) v += static_cast<std::int64_t>(h.size());
  return v;
}

// A length string as a JSON number: integers stay integers; decimals go through double, which
// nlohmann prints as the shortest representation that reads back the same, i.e. "123.456".
nlohmann::ordered_json length_json(const std::string& s) {
  if (s.find('.') == std::string::npos) {
    try {
      return std::stoll(s);
    } catch (...) {
      return s;  // beyond int64: keep the exact text
    }
  }
  return std::stod(s);
}

}  // namespace

std::string format_length(const std::vector<Point>& polyline) {
  LengthSum sum;
  sum.add(polyline);
  return sum.text();
}

std::string format_total_length(const std::vector<std::vector<Point>>& polylines) {
  LengthSum sum;
  for (const auto& pl : polylines) sum.add(pl);
  return sum.text();
}

long count_bends(const std::vector<Point>& polyline) {
  return static_cast<long>(geom::count_bends(polyline));
}

std::string layout_stats_json(const Layout& layout, int indent) {
  using json = nlohmann::ordered_json;
  json j;
  std::int64_t vertices = 0, pins = 0, unroutable = 0;
  for (const Blockage& b : layout.blockages)
    for (const Shape& s : b.shapes) vertices += shape_vertices(s);
  std::map<std::string, const Net*> net_by_name;
  for (const Net& n : layout.nets) {
    pins += static_cast<std::int64_t>(n.pins.size());
    if (n.pins.size() < 2) ++unroutable;
    net_by_name.emplace(n.name, &n);
  }
  j["layout"] = layout.name;
  j["blockages"] = layout.blockages.size();
  j["blockage_vertices"] = vertices;
  j["nets"] = layout.nets.size();
  j["pins"] = pins;
  j["nets_unroutable"] = unroutable;

  if (layout.routes) {
    json per_net = json::object();
    std::int64_t routed = 0, failed = 0, missing = 0, wires = 0, bends = 0;
    std::vector<std::vector<Point>> all;
    std::map<std::string, bool> seen;
    for (const Route& r : layout.routes->routes) {
      if (per_net.contains(r.net)) continue;  // duplicate entries: keep the first
      seen[r.net] = true;
      json e;
      e["status"] = r.status;
      std::vector<std::vector<Point>> pls;
      long b = 0;
      for (const Wire& w : r.wires) {
        pls.push_back(w.points);
        b += count_bends(w.points);
      }
      if (r.status == "routed") {
        ++routed;
        e["length"] = length_json(format_total_length(pls));
        e["bends"] = b;
        e["wires"] = r.wires.size();
        all.insert(all.end(), pls.begin(), pls.end());
      } else {
        ++failed;
      }
      auto it = net_by_name.find(r.net);
      e["pins"] = it == net_by_name.end() ? 0 : it->second->pins.size();
      if (r.reason) e["reason"] = *r.reason;
      if (r.status == "routed") {
        wires += static_cast<std::int64_t>(r.wires.size());
        bends += b;
      }
      per_net[r.net] = std::move(e);
    }
    for (const Net& n : layout.nets) {
      if (seen.count(n.name)) continue;
      ++missing;
      json e;
      e["status"] = "missing";
      e["pins"] = n.pins.size();
      e["reason"] = "no <route> for this net";
      per_net[n.name] = std::move(e);
    }
    j["routes"] = std::move(per_net);
    json t;
    t["routed"] = routed;
    t["failed"] = failed;
    t["missing"] = missing;
    t["wires"] = wires;
    t["length"] = length_json(format_total_length(all));
    t["bends"] = bends;
    // the share of the layout's nets routed (1 when it has none)
    const std::int64_t all_nets = routed + failed + missing;
    t["completion"] = all_nets == 0 ? 1.0 : static_cast<double>(routed) / static_cast<double>(all_nets);
    j["totals"] = std::move(t);
  }
  return j.dump(indent) + "\n";
}

}  // namespace taut::io
