// The exact minimum length of an OCTILINEAR Steiner tree with integer vertices among obstacles,
// by brute force: the quality reference for octilinear Steiner trees. Shares only geom and the
// octilinear reference's free-space rule (oracle::OctilinearReference: is_free, wedges_at,
// visible; oct_oracle.h, l1_oracle.h) with the code under test.
//
// The class. A tree of wires in the four orientations 0, 45, 90 and 135 degrees whose vertices
// (ends, bends, branch points) are all integer points, allowed by the reference's rules (free
// space, one wedge per point passed: no passing through a pinch), measured as the length of its
// union (shared stretches once), exact in a + b*sqrt(2) (geom/root2.h).
//
// Method. The 8-connected integer lattice of the closed domain box. Nodes: (p, wedge) for every
// integer point p of the box and every wedge of the reference at p (one node for a point in the
// open free space or on an obstacle edge, one per wedge at a pinch, none for a point that is not
// free). Edges: p to p + d for the unit moves d = (+-1, 0), (0, +-1), (+-1, +-1), when the
// reference allows the unit segment (visible()), from p's wedge holding d to p + d's wedge
// holding -d, weighted 1 along an axis and sqrt(2) diagonally. Dreyfus-Wagner dynamic
// programming over subsets of terminals, rooted at the first terminal: dp[S][v], the least tree
// joining S and node v, is the least split dp[A][v] + dp[S - A][v] relaxed by one Dijkstra over
// the lattice; the answer is dp[all but the root][root]. O(3^k N + 2^k N log N) for k terminals
// and N lattice nodes (k <= 8, N <= 80 * 80 points here). Lengths are exact: a + b*sqrt2 with
// an integer key that orders them exactly (oct_steiner_oracle.cpp), so the Dijkstra needs no
// heap (one sorted queue per edge length). Measured (Release): a 31 x 31 lattice with up to 5
// rectangles, 6 terminals in about 3 ms (1.4 ms of it building the lattice, ~3,700 calls of the
// reference's visible()), 2 terminals in about 1.5 ms.
//
// Why the lattice is exact for the class. A horizontal or vertical wire between integer points
// passes through an integer point at every unit step, and so does a 45-degree one ((x, y) to
// (x + n, y +- n) passes (x + i, y +- i)): every wire of the class is a union of unit lattice
// segments, each allowed (a piece of an allowed segment is allowed) and each entering and leaving
// every lattice point it passes in one wedge (the reference's rule), so its unit pieces form a
// walk in the graph above of the same length. A tree of the class is therefore a connected
// subgraph holding every terminal, of the same length, and the least such subgraph is a tree of
// the class (its union of unit segments, each allowed; at a node all its segments lie in that
// node's one wedge, so nothing passes through a pinch). The least subgraph is what
// Dreyfus-Wagner finds. Note: the class excludes branch points off the lattice, e.g. two
// diagonals crossing at a half-integer point (the X joining (0,0), (1,1), (1,0), (0,1) is 2*sqrt2,
// the least integer tree 3); two lattice edges that cross that way are not joined there by the
// graph (a least subgraph using both could swap one for a side of their unit square, 1 <
// sqrt2, whenever that side is allowed).
//
// Pins. A terminal is metal: at a pinch (a point with two or more wedges) the terminal is a node
// of its own joined at no cost to each of its wedges' nodes, so wires arriving from different
// wedges meet at the pin (each wire ends there; none passes through the pinch). So a terminal
// added at a pinch can shorten the minimum, or join terminals that were not joined (elsewhere
// adding a terminal never shortens it: a tree for more terminals joins the fewer). A terminal that
// is not free (inside an obstacle, outside the domain, on an obstacle edge flush against the
// domain side) makes the answer std::nullopt.
//
// Limits: at most 8 distinct terminals and 80 * 80 lattice points in the domain box (brute
// force); obstacles as the reference takes them (geom::normalize_obstacles() output).
#pragma once

#include <optional>
#include <span>

#include "geom/root2.h"
#include "geom/types.h"

namespace taut::oracle {

// The least length of an octilinear tree with integer vertices joining the terminals in free
// space (the class above), exact. Repeated terminals count once; one terminal (or none): 0.
// std::nullopt when a terminal is not free or the terminals are not all connected in free space.
// Throws std::invalid_argument for more than 8 distinct terminals or a domain box with more than
// 80 * 80 integer points.
std::optional<geom::Root2> oct_steiner_minimal_length(const geom::Box& domain, std::span<const geom::Polygon> obstacles,
                                                       std::span<const geom::Point> terminals);

// The same with shape terminals (pads: a polygon with integer vertices; a point is a polygon of
// one vertex): a pad is metal, so the tree may touch it at any of its integer points and carry a
// connection across it: each shape is a node of its own joined at no cost to every node of every
// free lattice point in the closed shape (tested with geom::locate), and Dreyfus-Wagner takes
// those nodes as terminals. Exact for the class: a tree's vertices are integer points, so it
// meets a shape at lattice points. std::nullopt also when a shape holds no free lattice point.
// Shapes are not deduplicated.
std::optional<geom::Root2> oct_steiner_minimal_length(const geom::Box& domain, std::span<const geom::Polygon> obstacles,
                                                       std::span<const geom::Polygon> terminals);

}  // namespace taut::oracle
