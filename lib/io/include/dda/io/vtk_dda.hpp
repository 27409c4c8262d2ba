// Paper A's state (dda::Simulation) as model-neutral VTK meshes
// (vtk_series.hpp): the blocks as polygons, the contacts as points.
#pragma once
#include "dda/io/vtk_series.hpp"
#include "dda/simulation.hpp"

namespace dda::io {

// One polygon cell per block (the scene's blocks, then, with
// `with_boundaries`, the boundary polygons), its vertices counter-clockwise;
// the points are the vertices, block by block. Cell data, in this order:
//   block         block index (Int64)
//   fixed         1 for a fixed block or a boundary polygon (Int64)
//   speed         |centroid velocity|, m/s
//   rotation      rotation r0 since t = 0, rad (counter-clockwise)
//   velocity      (vx, vy, 0), centroid velocity, m/s
//   displacement  (dx, dy, 0), centroid displacement since t = 0, m
//   boundary      1 for a boundary polygon (Int64)
//   spin          angular velocity, rad/s (counter-clockwise)
//   centroid      (x, y, 0), m
//   stress        (sxx, syy, sxy), the block's constant stress, Pa
VtkMesh block_mesh(const Simulation& sim, bool with_boundaries = true);

// The contacts of the last force evaluation (Simulation::contacts()), one
// point (VTK_VERTEX cell) each at the loading point pg. Point data:
//   block          the contact polygon CP, on which the forces act (Int64)
//   target         the target polygon TP (Int64)
//   normal_force   (fx, fy, 0), normal force on CP, N/m
//   shear_force    (fx, fy, 0), tangential (friction) force on CP, N/m
//   penetration    overlap_area / contact_length: the intersection
//                  polygon's mean thickness, m
//   overlap_area   area of the intersection polygon, m^2
//   contact_length half the intersection polygon's perimeter, m
//   couple         moment on CP besides the forces at pg, N m/m
//   sliding        1 if the contact slides (Int64)
VtkMesh contact_mesh(const Simulation& sim);

}  // namespace dda::io
