// The CDEM model's state in parts: plain structs, no behaviour. The step's
// phases (lib/cdem/src/model_*.cpp) are free functions over these parts;
// dda::cdem::Model holds one ModelSetup and one ModelState and runs the
// phases in order (model.cpp).
//
// The full state of a run between two steps, everything a step reads, is
// ModelState:
//   clock ............ time, step_t0, steps
//   blocks ........... BlockState per block (its node ids, outline, material,
//                      fixed flag, initial mean position)
//   nodes ............ NodeState: positions x, velocities v, the step-start
//                      positions xs, forces f (the last evaluation, read by
//                      the next step's first half-kick), the patch interface
//                      forces iface / iface0 / iimp, lumped masses m and
//                      inv_m, block, kind, hanging-node ties, clone counts,
//                      release times
//   mesh ............. MeshState: elements (corners, stress, reference
//                      positions `last`, mass, level, lattice), the in-place
//                      lattices, the edge map, the coarse boundary; and lists
//                      derived from those and the node kinds (rebuild_lists,
//                      rebuild_boundary; a reader may store or rebuild them)
//   clones ........... Clone per clone node (ties, weights, A_c, sliding,
//                      the interaction force lambda)
//   patches .......... Patches: the in-place refinement's k and n
//   submodels ........ SubModels: the live sub-models (sub-node positions,
//                      velocities, forces, masses, ties to the coarse nodes,
//                      sub-elements with stress and reference positions), the
//                      element owners and every sub-model's record
//   penalty_contacts . the node-to-edge penalty's springs of the last force
//                      evaluation (its energy reads them)
//   energy ........... EnergyLedger: E0 and the accumulated losses
//   log .............. ContactLog: touches, separations, slips (the step
//                      reads the number of touches for its records)
// Empty between steps (scratch of one step): step_touch_count,
// submodels.requests, submodels.request_touch, nodes.scratch.
// ModelSetup is derived from the scene at construction and never changes
// (elastic matrices, wave speeds, critical steps, the penalty's kn); a
// reader can rebuild it from the scene or keep it.
#pragma once
#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "dda/block.hpp"
#include "dda/cdem/options.hpp"
#include "dda/cdem/records.hpp"
#include "dda/vec2.hpp"

namespace dda::cdem {

// A constant-strain triangle: a coarse element (level 0) or a patch element
// of the in-place refinement (level 1, SubdivisionMode::kInPlace).
struct Element {
  std::array<int, 3> n{};
  int block = 0;
  int level = 0;     // 0 coarse, 1 patch
  int parent = -1;   // for patch elements
  int lattice = -1;  // for refined coarse elements: index into MeshState::lattices
  bool active = true;
  Vec3 stress = Vec3::Zero();
  std::array<Vec2, 3> last{};  // node positions at the last force evaluation
  double mass = 0.0;
};

// A coarse element refined k x k in place.
struct Lattice {
  int elem = -1, k = 0;
  std::vector<int> nodes;     // lattice_index -> node
  std::vector<int> children;  // element ids
};

// An edge of the coarse mesh.
struct MeshEdge {
  int lo = -1, hi = -1;  // coarse node ids, lo < hi
  std::array<int, 2> elems{-1, -1};
  std::vector<int> nodes;  // k - 1 nodes from lo to hi while refined on a side
};

// A boundary edge, CCW (outward normal perp_right(b - a)).
struct BoundaryEdge {
  int a = -1, b = -1, block = 0;
  bool fine = false;  // a sub-edge of a refined element
};

struct BlockState {
  std::vector<int> nodes;    // every node ever made for the block
  std::vector<int> outline;  // coarse outline vertex nodes, CCW
  int material = 0;
  bool fixed = false;
  Vec2 initial_mean{};
};

// The nodes, structure of arrays. x, v: position and velocity; xs: coarse
// position at the step start; f: force of the last evaluation at the node's
// level; iface: force of the patch-evaluated elements on coarse nodes (last
// patch evaluation); iface0: its value in the first half-kick of the step;
// iimp: its impulse integrated over the patch steps of the current step.
struct NodeState {
  std::vector<Vec2> x, v, xs, f, iface, iface0, iimp;
  std::vector<double> m, inv_m;
  std::vector<int> block;
  std::vector<NodeKind> kind;
  std::vector<int> hang_a, hang_b;
  std::vector<double> hang_w;  // weight of hang_b
  std::vector<int> clone_count;
  std::vector<double> released_at;  // time the node's last clone was removed
  std::vector<Vec2> scratch;         // workspace of the clone solve, not state
  std::size_t size() const { return x.size(); }
};

// The elements, the in-place lattices and the edges; then lists derived
// from them and the node kinds.
struct MeshState {
  std::vector<Element> elems;
  std::vector<Lattice> lattices;
  std::unordered_map<std::uint64_t, MeshEdge> edges;  // key edge_key(lo, hi)
  std::vector<BoundaryEdge> coarse_bedges;            // outline edges of the coarse mesh
  std::vector<int> coarse_bedge_elem;
  // derived (rebuild_boundary): the current boundary, per block, its nodes
  std::vector<BoundaryEdge> bedges;
  std::vector<std::vector<int>> block_bedges;  // indices into bedges per block
  std::vector<int> bnodes;
  // derived (rebuild_lists): active coarse / patch elements; elements
  // evaluated at the coarse step (all corners coarse) and at the patch steps
  // (patch elements and coarse elements with a patch-integrated corner);
  // the integrated nodes of each level and the hanging nodes
  std::vector<int> coarse_elems, fine_elems, coarse_eval, patch_eval;
  std::vector<int> coarse_dofs, fine_dofs, hanging;

  Element& elem(int e) { return elems[static_cast<std::size_t>(e)]; }
  const Element& elem(int e) const { return elems[static_cast<std::size_t>(e)]; }
};

// A clone node (Sect. 4): main node tied to the point sum w_q t_q.
struct Clone {
  int main = -1;
  std::array<int, 2> t{-1, -1};
  std::array<double, 2> w{0.0, 0.0};
  int ea = -1, eb = -1;  // the touched edge (for the normal)
  double area = 0.0;     // A_c
  bool fine = false;
  // Sliding (Eq. 10): the shear limit was reached; from then on only the
  // normal velocity is tied, the shear force is the one the tie demands
  // (stopping the slip) capped at the limit with its sign, and the tied
  // point follows the node along the target's boundary.
  bool sliding = false;
  Vec2 lambda{};
};

// The in-place refinement (SubdivisionMode::kInPlace): its lattices are in
// MeshState.
struct Patches {
  int k = 0;         // subdivision level of this run (0 until the first refinement)
  int substeps = 1;  // n of dt/n in patches
  std::int64_t substeps_taken = 0;
};

// SubdivisionMode::kSubModel (model_submodel.cpp): a sub-element.
struct SubElement {
  std::array<int, 3> n{};  // sub-node ids
  int parent = -1;         // coarse element
  Vec3 stress = Vec3::Zero();
  std::array<Vec2, 3> last{};
  double mass = 0.0;
};

// One live sub-model of the colliding elements.
struct SubModel {
  int record = -1;  // index into SubModels::records
  int k = 0, substeps = 1;
  std::vector<int> parents;
  std::vector<Vec2> x, v, f;     // sub-node state; f: force of the last evaluation
  std::vector<double> m, inv_m;  // lumped masses (inv_m 0 for prescribed nodes)
  std::vector<int> block;        // sub-node's block
  // prescribed sub-nodes follow (1 - w) X_a + w X_b of coarse nodes a, b
  std::vector<std::array<int, 2>> drive;
  std::vector<double> drive_w;
  std::vector<char> prescribed;
  // where each sub-node sits in a parent: x = X0 + a (X1 - X0) + b (X2 - X0)
  std::vector<int> home;
  std::vector<std::array<double, 2>> home_ab;
  std::vector<std::array<int, 3>> home_c;  // the home parent's corners: indices into coarse
  std::vector<SubElement> elems;
  std::vector<int> coarse;         // the coarse nodes that drive it
  std::vector<Vec2> coarse_x0;     // their positions at the last sync
  std::vector<Vec2> coarse_force;  // step 5: force returned to them, N/m
  std::vector<Vec2> bc;            // scratch: element forces on the returned sub-nodes, N/m
};

// A touch of the current step whose sub-model is built at the step end.
struct SubModelRequest {
  int main_node = -1, ea = -1, eb = -1;
  Vec2 point{};
  double dt2 = 0.0;
};

struct SubModels {
  std::vector<SubModel> live;
  std::vector<SubModelRecord> records;     // every sub-model made so far
  std::vector<SubModelRequest> requests;   // touches of the current step
  std::vector<int> request_touch;          // their index into ContactLog::touches
  std::vector<int> elem_owner;             // coarse element -> index into live, -1
  std::int64_t substeps_taken = 0;
};

// The energy account's accumulators, J/m (CdemEnergyAccount).
struct EnergyLedger {
  double initial = 0.0;
  double impact_loss = 0.0, remap_change = 0.0;
  double refine_loss = 0.0, deletion_loss = 0.0, touch_loss_eq5 = 0.0;
  double touch_loss_eq5_group = 0.0;
};

struct ContactLog {
  std::vector<TouchRecord> touches;
  std::vector<SeparationRecord> separations;
  std::vector<SeparationRecord> slips;  // clones that started sliding
};

// Derived from the scene at construction, constant over the run.
struct ModelSetup {
  CdemScene scene;
  CdemOptions opt;
  double dt = 0.0;
  std::vector<Mat3> d, c;          // per material: elastic and compliance matrices
  std::vector<double> wave_speed;  // per material sqrt(E / rho)
  double critical_dt = 0.0, element_critical_dt = 0.0, contact_critical_dt = 0.0;
  double penalty_kn = 0.0, penalty_max_depth = 0.0;  // kNodeToEdgePenalty
};

struct ModelState {
  double time = 0.0, step_t0 = 0.0;
  std::int64_t steps = 0;
  std::vector<BlockState> blocks;
  NodeState nodes;
  MeshState mesh;
  std::vector<Clone> clones;
  std::unordered_map<int, int> step_touch_count;  // touches per node in the current coarse step
  Patches patches;
  SubModels submodels;
  std::vector<PenaltyContact> penalty_contacts;
  EnergyLedger energy;
  ContactLog log;
};

}  // namespace dda::cdem
