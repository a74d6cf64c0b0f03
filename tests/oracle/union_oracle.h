// Brute-force references for normalize_obstacles() (geom/normalize.h). They share only the
// predicates (predicates.h) with the code under test: membership by locate() on every polygon,
// invariants by testing every pair of edges.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "geom/predicates.h"
#include "geom/types.h"

namespace taut::oracle {

using geom::Box;
using geom::Point;
using geom::Polygon;

// p in the closed union of the inputs and in the closed box.
bool in_inputs(Point p, std::span<const Polygon> inputs, const Box& domain);
// p in the closed union of the obstacles.
bool in_obstacles(Point p, std::span<const Polygon> obstacles);
// Index of the obstacle containing p (closed), -1 if none.
int obstacle_at(Point p, std::span<const Polygon> obstacles);
// Squared Euclidean distance from p to the closed polygon is <= r2.
bool within(Point p, const Polygon& polygon, std::int64_t r2);
// Every coordinate multiplied by f.
Polygon scaled(const Polygon& polygon, geom::Coord f);
// Twice the area of the union the obstacles describe (shells minus holes).
geom::i128 twice_area(std::span<const Polygon> obstacles);
// Violations of the output invariants (empty when all hold): ring sizes and orientation, no
// repeated vertex, inside the domain, edges of one obstacle meet only at common vertices and
// never cross at a shared vertex, edges of distinct obstacles never meet, no obstacle inside
// another, holes inside their shell.
std::vector<std::string> check_obstacles(std::span<const Polygon> obstacles, const Box& domain);

}  // namespace taut::oracle
