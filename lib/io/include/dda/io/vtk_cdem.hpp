// Paper B's state (dda::cdem::Model) as model-neutral VTK meshes
// (vtk_series.hpp): the elements as triangles with their nodes, the contacts
// (clone nodes, or the penalty baseline's springs) as points.
#pragma once
#include "dda/cdem/model.hpp"
#include "dda/io/vtk_series.hpp"

namespace dda::io {

// One triangle cell per element Model::snapshot() draws (the active coarse
// and patch elements; a live sub-model's sub-elements instead of its parent
// elements). The points are the model's nodes that are corners of these
// elements (once each), then the sub-models' sub-nodes (once per position
// and block). Point data:
//   node      the model's node id; -1 for a sub-model's sub-node (Int64)
//   block     (Int64)
//   kind      0 coarse, 1 fine (patch), 2 hanging, 3 sub-model sub-node (Int64)
//   velocity  (vx, vy, 0), m/s
// Cell data:
//   block     (Int64)
//   fine      1 for a patch element or a sub-model's sub-element (Int64)
//   velocity  (vx, vy, 0), mean of the corner velocities, m/s
//   stress    (sxx, syy, sxy), the element's constant stress, Pa
VtkMesh element_mesh(const cdem::Model& model);

// The contacts as points (VTK_VERTEX cells), with the names of
// contact_mesh (vtk_dda.hpp) where they mean the same. Two-scale contact:
// one point per clone node (Model::clones()) at the main node:
//   node          the main node (Int64)
//   block         the main node's block (Int64)
//   target        the touched block (Int64)
//   force         (fx, fy, 0), interaction force on the main node (Eq. 11), N/m
//   normal_force  its part along the clone's normal, N/m
//   shear_force   the rest, N/m
//   penetration   depth of the main node behind the tied point along the
//                 normal (the clone constraint's drift), m; negative: a gap
//   fine          1 for a clone between patch nodes (Int64)
// Node-to-edge penalty baseline: one point per spring
// (Model::penalty_contacts()) at the node, the same arrays: force =
// normal_force = kn depth n (frictionless: shear_force 0), penetration =
// depth, fine 0.
VtkMesh contact_mesh(const cdem::Model& model);

}  // namespace dda::io
