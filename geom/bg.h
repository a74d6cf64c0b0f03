// Boost.Geometry registration of taut's geometry types, so bg::area, bg::within, bg::is_valid,
// bg::envelope and bg::index::rtree accept Point, Segment, Box, Ring and Polygon directly.
//
//   Point   cartesian, int32 coordinates (x, y)
//   Segment a, b          Box lo (min corner), hi (max corner)
//   Ring    std::vector<Point>, OPEN (no repeated closing vertex, as in types.h) and
//           counter-clockwise (the normalized orientation: outer CCW, holes CW)
//   Polygon outer + holes
//
// Boost.Geometry's own strategies are not guaranteed exact on 31-bit integer coordinates (some
// promote to double); use them for convenience and cross-checks, never for a decision that
// predicates.h can make exactly.
#pragma once

#include <boost/geometry.hpp>
#include <boost/geometry/geometries/register/box.hpp>
#include <boost/geometry/geometries/register/point.hpp>
#include <boost/geometry/geometries/register/ring.hpp>
#include <boost/geometry/geometries/register/segment.hpp>
#include <vector>

#include "geom/types.h"

BOOST_GEOMETRY_REGISTER_POINT_2D(taut::geom::Point, taut::geom::Coord, boost::geometry::cs::cartesian, x, y)
BOOST_GEOMETRY_REGISTER_SEGMENT(taut::geom::Segment, taut::geom::Point, a, b)
BOOST_GEOMETRY_REGISTER_BOX(taut::geom::Box, taut::geom::Point, lo, hi)
BOOST_GEOMETRY_REGISTER_RING(taut::geom::Ring)

namespace boost::geometry::traits {

template <>
struct closure<taut::geom::Ring> {
  static const closure_selector value = open;
};
template <>
struct point_order<taut::geom::Ring> {
  static const order_selector value = counterclockwise;
};

template <>
struct tag<taut::geom::Polygon> {
  using type = polygon_tag;
};
template <>
struct ring_const_type<taut::geom::Polygon> {
  using type = const taut::geom::Ring&;
};
template <>
struct ring_mutable_type<taut::geom::Polygon> {
  using type = taut::geom::Ring&;
};
template <>
struct interior_const_type<taut::geom::Polygon> {
  using type = const std::vector<taut::geom::Ring>&;
};
template <>
struct interior_mutable_type<taut::geom::Polygon> {
  using type = std::vector<taut::geom::Ring>&;
};
template <>
struct exterior_ring<taut::geom::Polygon> {
  static taut::geom::Ring& get(taut::geom::Polygon& p) { return p.outer; }
  static const taut::geom::Ring& get(const taut::geom::Polygon& p) { return p.outer; }
};
template <>
struct interior_rings<taut::geom::Polygon> {
  static std::vector<taut::geom::Ring>& get(taut::geom::Polygon& p) { return p.holes; }
  static const std::vector<taut::geom::Ring>& get(const taut::geom::Polygon& p) { return p.holes; }
};

}  // namespace boost::geometry::traits
