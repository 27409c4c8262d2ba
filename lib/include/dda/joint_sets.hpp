// Block generation by persistent joint sets (for Paper A Sect. 6): a region
// is cut by families of parallel lines into convex blocks. Pure geometry.
#pragma once
#include <string>
#include <vector>

#include "dda/polygon.hpp"

namespace dda {

// A family of parallel joint lines. In the x-y section (x right, y up) a
// joint dips `dip_deg` below the horizontal toward +x (0 < dip < 180; a dip
// above 90 dips toward -x). Lines are spaced `spacing` apart (measured
// normal to the lines) and one of them passes through `origin`.
struct JointSet {
  double dip_deg = 45.0;
  double spacing = 1.0;  // m
  Vec2 origin{};
};

struct GeneratedBlocks {
  std::vector<Polygon> blocks;
  int dropped = 0;            // pieces below the area threshold (slivers)
  double dropped_area = 0.0;  // their total area, m^2
};

// Cuts the region (a simple polygon, CCW, convex or not) by every line of
// every joint set. A non-convex region is first split into convex parts
// (ear-clipping triangulation then merging of triangles across diagonals
// while the union stays convex). Pieces with area below `min_area` (m^2) are
// dropped and counted. Throws std::invalid_argument for a bad region or
// joint set (message names what is wrong), and if a piece would exceed
// kMaxBlockVertices.
GeneratedBlocks generate_blocks(const std::vector<Vec2>& region, const std::vector<JointSet>& sets, double min_area);

// Convex decomposition used above (exposed for tests).
std::vector<std::vector<Vec2>> convex_parts(const std::vector<Vec2>& simple_ccw_polygon);

}  // namespace dda
