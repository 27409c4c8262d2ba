// Constant-strain-triangle meshes of convex polygons for the CDEM body model
// (Paper B Sect. 2: in CDEM each block is a finite-element mesh). Pure
// functions, no I/O.
#pragma once
#include <array>
#include <vector>

#include "dda/vec2.hpp"

namespace dda::cdem {

struct TriMesh {
  std::vector<Vec2> nodes;
  std::vector<std::array<int, 3>> triangles;  // node indices, counter-clockwise
};

// Nodes of the regular lattice of a triangle split k times per edge:
// (k + 1)(k + 2) / 2 points P(i, j) = v0 + i/k (v1 - v0) + j/k (v2 - v0),
// i, j >= 0, i + j <= k, numbered row by row (j outer, i inner).
inline constexpr int lattice_count(int k) { return (k + 1) * (k + 2) / 2; }
inline constexpr int lattice_index(int i, int j, int k) { return j * (k + 1) - j * (j - 1) / 2 + i; }

// The node at lattice point (i, j) of a triangle split k times when it lies
// on the triangle's boundary: a corner c[q] or a node of the edge lists
// e01, e12, e02 (k - 1 nodes each, ordered from the first to the second
// named corner); -1 for an interior point.
inline int lattice_boundary_node(int i, int j, int k, const std::array<int, 3>& c, const std::vector<int>& e01,
                                 const std::vector<int>& e12, const std::vector<int>& e02) {
  if (i == 0 && j == 0) return c[0];
  if (i == k) return c[1];
  if (j == k) return c[2];
  if (j == 0) return e01[static_cast<std::size_t>(i - 1)];
  if (i == 0) return e02[static_cast<std::size_t>(j - 1)];
  if (i + j == k) return e12[static_cast<std::size_t>(j - 1)];
  return -1;
}

// The k^2 sub-triangles of that lattice as lattice indices, each with the
// orientation of the parent: for every (i, j) the 'up' triangle
// (i,j),(i+1,j),(i,j+1) and, where it fits, the 'down' triangle
// (i+1,j),(i+1,j+1),(i,j+1).
std::vector<std::array<int, 3>> lattice_triangles(int k);

// Meshes a convex CCW polygon (check it with dda::validate_polygon first).
// A triangle is split directly into divisions^2 similar triangles (its
// vertices and, for even divisions, its edge midpoints are nodes); any other
// polygon is fanned from its centroid and each fan triangle split the same
// way. Edges shared by two fan triangles get the same nodes (conforming).
// Throws std::invalid_argument for fewer than 3 points or divisions < 1.
TriMesh mesh_convex_polygon(const std::vector<Vec2>& outline, int divisions);

// A structured mesh of the rectangle [lo.x, lo.x + lx] x [lo.y, lo.y + ly]:
// nx x ny cells, each cut into two triangles along a diagonal that
// alternates from cell to cell (a checkerboard, so that the mesh has no
// preferred shear direction). Nodes 0-3 are the corners, counter-clockwise
// from lo (the outline of a CdemBlock with this mesh); the other nodes
// follow. For slender bodies (bars) whose fan mesh of mesh_convex_polygon
// would be long thin spokes. Throws std::invalid_argument for nx or ny < 1
// or a non-positive size.
TriMesh mesh_rectangle(Vec2 lo, double lx, double ly, int nx, int ny);

}  // namespace dda::cdem
