// Paper B's two-scale contact model on node-based deformable blocks: a
// compact CDEM-style body model beside the 6-DOF DDA block (dda::Simulation).
//
// Bodies (Paper B Sect. 2): each block is a mesh of constant-strain
// triangles with lumped nodal masses, integrated by explicit central
// differences (Eq. 1, M u'' + C u' = F + P, C = alpha M) in kick-drift-kick
// form; element forces come from the strain matrix B of the current
// configuration, incrementally (Eqs. 2-3): d_eps = B d_u, d_sigma = D d_eps,
// sigma += d_sigma (rotated with the element's incremental rotation),
// F = -A B^T sigma.
//
// Contact, without any penalty spring:
//  * detection (Sect. 2, 2D): boundary nodes of one block against boundary
//    edges of another; a pair is a candidate when the node ends the step
//    closer to the edge than the contact tolerance d_tol;
//  * two time stages (Sect. 3): the touch time on the collision path (the
//    relative node-edge motion over the step, solved exactly) splits the step
//    into dt1 (free motion) and dt2 (contact);
//  * clone node (Sect. 4): the touching node and the touched point become one
//    node (summed mass and force; for a point inside an edge the edge's
//    nodes share it with their linear weights), its velocity set by
//    perfectly inelastic momentum conservation (Eq. 4, energy loss Eq. 5);
//    the interaction force (Eq. 11) is checked against the tensile limit
//    (Eq. 6) and the Mohr-Coulomb shear limit (Eqs. 7-10) for separation;
//  * local subdivision (Sect. 5), two modes (CdemOptions::subdivision_mode):
//    - kSubModel (the default), Sect. 5 steps 1-5 (Eq. 12; model_submodel.cpp):
//      the coarse model stays as it is (contact, clone and Eqs. 4-11 at
//      coarse nodes with coarse masses, exactly as without subdivision). At
//      a touch the colliding elements (within c dt2 of the contact point,
//      c = sqrt(E/rho), and at least those holding the touching node and
//      the touched point) get a separate sub-model, each split k x k (k =
//      ceil(h_e / (c dt2)), clamped; one k per sub-model), built at the end
//      of the touch's step. Its sub-nodes at the coarse nodes and on edges
//      shared with elements outside it follow the coarse nodes' motion over
//      each step (velocity boundary conditions, step 3); the others
//      (inside, on edges between colliding elements, on the free boundary)
//      are free. It is integrated with n = ceil(dt / (substep_safety x the
//      sub-elements' element-bound critical step)) substeps per coarse step
//      (step 4); at the step end its element forces are returned to the
//      coarse nodes with linear weights and replace the colliding elements'
//      own force (step 5), by one of two readings of the under-specified
//      step (CdemOptions::submodel_transfer): the forces on every sub-node
//      (the default: the coarse nodes keep their masses, momentum exact) or
//      only those on the prescribed sub-nodes (the literal reading: the
//      free sub-nodes' inertia enters the returned forces, momentum is
//      lost while a sub-model lives). Deleted when no clone ties its
//      parents' corners (the contact points separated): the parents take
//      the area-averaged stress. Interpretations: the shared edges are
//      prescribed too (conforming with the coarse neighbours); the force at
//      the step end, not the substep average (centred for the coarse
//      kick-drift-kick).
//    - kInPlace (an option beyond the paper): at a touch, the elements within c dt2 of
//      the contact point are refined k x k in place
//      (k = ceil(h_e / (c dt2)), clamped), mass and momentum moved exactly;
//      the patch (its elements and the coarse elements touching its nodes)
//      is integrated with steps dt/n, the coarse nodes around it moving
//      with their coarse-step velocity (the velocity boundary condition of
//      Eq. 12); the patch forces on those coarse nodes are returned to them
//      (centred kicks plus an O(dt^3) correction at the step end, so that
//      momentum stays exact). Edges between refined and unrefined elements
//      carry hanging nodes tied linearly to the edge. The clone is formed
//      between patch nodes, so its masses (Eq. 5 loss) are the small patch
//      masses. The patch is deleted (restricted back to the coarse
//      elements, momentum exact, stress area-averaged) when its clone nodes
//      separated. This differs from Sect. 5 as written: the coarse elements
//      are replaced while the patch lives and its state must be restricted
//      back when it is deleted (the deletion loss of the energy account).
//
// Approximations relative to Paper B (which gives no algorithm tables):
// the tie is node-to-node or node-to-edge-point (the point shares its mass
// and force with the edge's nodes by their linear weights); a clone whose
// shear reaches the limit slides (Eq. 10: normal velocity tied, shear force
// the one the tie demands to stop the slip within the step, reduced to the
// limit with its sign, so friction never reverses a slip; the tied point
// following the node along the target's face) instead of being removed as Sect. 4.2's last sentence
// says: removed, the pressed node touches again at once, and each re-touch's
// inelastic impact takes the tangential velocity (a frictionless face stuck
// or, with the re-touch delayed, was passed through); a released node may
// touch again from the next patch step (coarse level: later in the same
// step); every boundary node is checked at each interval's start against
// the other blocks at any depth; touches inside a patch step split that
// step's drift for all patch nodes (all drift to the touch time, the touch is
// processed, the drift goes on), while the kicks stay on the uniform grid
// t0 + j dt/n (cutting the kick-drift-kick step itself at each touch makes
// the steps irregular, and leapfrog with irregular steps pumps energy into
// the patch's top modes); the coarse step is split for the touching nodes
// only, as in Sect. 3; one k per run.
//
// The library does no I/O. Errors: dda::SceneError for a bad scene (also
// when dt exceeds the mesh's critical step), dda::SimulationError for a run
// that goes wrong (inverted element, non-finite state), and its subclass
// ContactError for a contact that cannot be resolved (a node deeper than
// d_tol inside another block, a touch that does not let the step advance).
//
// Layout: the scene and options (dda/cdem/options.hpp), what a run reports
// (dda/cdem/records.hpp), the model's state in plain parts
// (dda/cdem/model_state.hpp, with the list of everything a step reads);
// Model holds the set-up and the state, and its step (model.cpp) reads as
// the list of the method's phases, each a free function over the parts it
// needs (lib/cdem/src/model_ops.hpp).
#pragma once
#include <cstdint>
#include <vector>

#include "dda/cdem/model_state.hpp"
#include "dda/cdem/options.hpp"
#include "dda/cdem/records.hpp"
#include "dda/vec2.hpp"

namespace dda {
class ByteWriter;
class ByteReader;
}  // namespace dda

namespace dda::cdem {

class Model {
 public:
  explicit Model(const CdemScene& scene);

  void step();
  void advance_to(double t);  // steps until time() >= t - dt/2

  double time() const { return state_.time; }
  double dt() const { return setup_.dt; }
  std::int64_t step_count() const { return state_.steps; }
  const CdemScene& scene() const { return setup_.scene; }

  // Critical step of the coarse mesh: 2 / omega_max of M^-1 K (power
  // iteration), and the element bound min_e 2 / omega_max(e) (Irons).
  double critical_dt() const { return setup_.critical_dt; }
  double element_critical_dt() const { return setup_.element_critical_dt; }
  // kNodeToEdgePenalty: 2 / sqrt(omega_max^2 + 6 kn max(1/m) of the boundary
  // nodes), the mesh's critical step with up to three penalty springs per
  // node (model_penalty.cpp); critical_dt() otherwise.
  double contact_critical_dt() const { return setup_.contact_critical_dt; }
  // kNodeToEdgePenalty: the springs of the last force evaluation.
  using PenaltyContact = cdem::PenaltyContact;
  const std::vector<PenaltyContact>& penalty_contacts() const { return state_.penalty_contacts; }
  double penalty_kn() const { return setup_.penalty_kn; }  // Pa, resolved (0 in the two-scale mode)

  int block_count() const { return static_cast<int>(state_.blocks.size()); }
  double block_mass(int b) const;
  Vec2 block_momentum(int b) const;
  Vec2 block_velocity(int b) const;          // momentum / mass
  Vec2 block_mean_position(int b) const;     // mass-weighted mean node position
  Vec2 block_displacement(int b) const;      // mean position minus its initial value
  double block_max_velocity_x(int b) const;  // largest nodal x-velocity
  double block_min_velocity_x(int b) const;
  std::vector<Vec2> block_outline(int b) const;  // current positions of the outline vertices

  Vec2 momentum() const;
  CdemEnergy energy() const;
  double impact_energy_loss() const { return state_.energy.impact_loss; }    // sum over touches, measured
  double remap_energy_change() const { return state_.energy.remap_change; }  // refine + delete patches
  CdemEnergyAccount energy_account() const;

  const std::vector<TouchRecord>& touches() const { return state_.log.touches; }
  const std::vector<SeparationRecord>& separations() const { return state_.log.separations; }
  const std::vector<SeparationRecord>& slips() const { return state_.log.slips; }  // clones that started sliding
  std::vector<CloneView> clones() const;
  int subdivision_level() const { return state_.patches.k; }
  int patch_substeps() const { return state_.patches.substeps; }
  int active_elements(bool fine) const;
  std::int64_t patch_substeps_taken() const { return state_.patches.substeps_taken; }
  // SubdivisionMode::kSubModel: every sub-model made so far, and how many live.
  const std::vector<SubModelRecord>& submodels() const { return state_.submodels.records; }
  int live_submodels() const { return static_cast<int>(state_.submodels.live.size()); }

  int node_count() const { return static_cast<int>(state_.nodes.x.size()); }
  Vec2 node_position(int i) const { return state_.nodes.x[i]; }
  Vec2 node_velocity(int i) const { return state_.nodes.v[i]; }
  double node_mass(int i) const { return state_.nodes.m[i]; }
  NodeKind node_kind(int i) const { return state_.nodes.kind[i]; }
  int node_block(int i) const { return state_.nodes.block[i]; }

  Snapshot snapshot() const;

  // The model's full state and its set-up (model_state.hpp).
  const ModelState& state() const { return state_; }
  const ModelSetup& setup() const { return setup_; }

  // Saves the full state by its bits (dda/state_bytes.hpp; state.cpp), and
  // restores it into a model built from the same scene: it then runs on to
  // the same bits as the model that saved it. restore_state throws
  // dda::StateError, the model unchanged, for a stream that is truncated,
  // inconsistent, of another layout or of another scene (blocks, meshes,
  // materials, gravity, dt or options; the name and duration may differ).
  void save_state(ByteWriter& out) const;
  void restore_state(ByteReader& in);

 private:
  ModelSetup setup_;
  ModelState state_;
};

// The stream of Model::save_state for a state and the set-up it runs with,
// and back (the state read whole and its ids checked; StateError).
void write_state(ByteWriter& out, const ModelSetup& setup, const ModelState& state);
ModelState read_state(ByteReader& in, const ModelSetup& setup);

}  // namespace dda::cdem
