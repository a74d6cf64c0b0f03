// The exact obstacle-avoiding rectilinear Steiner minimal tree length (OARSMT), by brute force:
// the quality reference for the net router's Steiner trees (issue #7). Shares only geom and the
// L1 reference's free-space rule (oracle::L1Reference::visible) with the code under test.
//
// Method. The extended Hanan grid: the lines through every terminal and every obstacle vertex
// (and the domain's sides). With rectilinear obstacles some Steiner minimal tree lies on it
// (Ganley and Cohoon, "Routing a multi-terminal critical net: Steiner tree construction in the
// presence of obstacles", 1994: the escape graph, a subgraph of this grid, holds one). Grid
// points that are free are nodes; two neighbours on a grid line are joined when the L1
// reference allows the segment between them, weighted by its length. Dreyfus-Wagner dynamic
// programming over subsets of terminals then gives the exact minimum: dp[S][v], the least tree
// joining S and v, is the least split dp[A][v] + dp[S - A][v] relaxed by one Dijkstra over the
// grid. O(3^k N + 2^k N log N) for k terminals and N grid nodes (k <= 8 here).
//
// Limits: rectilinear obstacles only (sloped ones would need more lines), and no pinches (a
// grid node at a point where obstacles touch would join its wedges); the tests generate
// rectangles that stay apart.
#pragma once

#include <cstdint>
#include <optional>
#include <span>

#include "geom/types.h"

namespace taut::oracle {

// std::nullopt when a terminal is not free or the terminals are not all connected in free
// space. Throws std::invalid_argument for more than 10 terminals or a sloped obstacle edge.
std::optional<std::int64_t> steiner_minimal_length(const geom::Box& domain, std::span<const geom::Polygon> obstacles,
                                                    std::span<const geom::Point> terminals);

// The same with rectangular terminals (pads; a point is a box of one point): a pad is metal, so
// the tree may touch it anywhere and carry a connection across it: each pad is a node of its own
// joined at no cost to every free grid node in its closed box, and Dreyfus-Wagner runs on that
// graph with the pads' nodes as terminals. The grid also takes the lines of every pad's sides: a
// tree touching a pad side can slide along it to one of them, as the Hanan argument slides
// segments.
std::optional<std::int64_t> steiner_minimal_length(const geom::Box& domain, std::span<const geom::Polygon> obstacles,
                                                    std::span<const geom::Box> terminals);

}  // namespace taut::oracle
