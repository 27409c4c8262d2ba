// The CDEM model's step (Paper B), one file per step of the method; the
// model's state in parts is dda/cdem/model_state.hpp, the phases are free
// functions over those parts (model_ops.hpp):
//   Sect. 2   mesh and set-up ............................ model_mesh.cpp
//   Sect. 2   element forces, Eqs. 1-3 ................... model_elements.cpp
//   Sect. 3   touch detection, time of impact, two stages  model_touch.cpp
//   Sect. 4.1 clone nodes, inelastic impact, Eqs. 4-5 .... model_clone.cpp
//   Sect. 4.2 interaction force and separation, Eqs. 6-11  model_separation.cpp
//   Sect. 5   sub-model of the colliding elements, Eq. 12  model_submodel.cpp
//             (the paper's steps 1-5; SubdivisionMode::kSubModel)
//   Sect. 5   in-place refinement ........................ model_refine.cpp
//             and its patch steps ........................ model_patches.cpp
//             (beyond the paper; SubdivisionMode::kInPlace)
//   energy, momentum and other read-out ................. model_energy.cpp
//   baseline: node-to-edge penalty contact (not Paper B)  model_penalty.cpp
#include "dda/cdem/model.hpp"

#include <sstream>

#include "model_ops.hpp"

namespace dda::cdem {

Model::Model(const CdemScene& scene) {
  setup_.scene = scene;
  setup_.opt = scene.options;
  build_model(setup_, state_);
}

// One coarse step t0 -> t1 = t0 + dt, explicit central differences in
// kick-drift-kick form (Eq. 1), as a table of the method's steps.
void Model::step() {
  const ModelSetup& su = setup_;
  ModelState& st = state_;
  if (su.opt.contact == ContactMode::kNodeToEdgePenalty) return penalty_step(su, st);  // baseline, model_penalty.cpp
  const double t0 = st.time, t1 = t0 + su.dt;
  st.step_t0 = t0;
  st.step_touch_count.clear();
  // Sect. 2, Eq. 1: first half-kick of the coarse nodes.
  kick_coarse_first_half(st.nodes, st.mesh, su.dt);
  // Sects. 2-3: touches on the collision path of the step, with their time
  // of impact t0 + dt1.
  const std::vector<Touch> touches = coarse_touches(su, st, t0);
  if (!su.opt.subdivision || submodel_mode(su.opt)) {
    // Sects. 3-4.1: free motion over dt1, the clone node and its inelastic
    // impact (Eqs. 4-5), motion as a clone over dt2.
    two_stage_step(su, st, touches, t0);
    // Sect. 5 (kSubModel): the sub-models of the colliding elements
    // integrated over the step with dt/n, driven by the coarse nodes'
    // motion (steps 2-4, Eq. 12); this step's touches get theirs (step 1).
    if (submodel_mode(su.opt)) advance_submodels(su, st, t0, t1);
  } else {
    // Sect. 5 (kInPlace): the contact zone refined at each touch and
    // integrated with steps dt/n (Eq. 12), touches inside found at the patch
    // scale.
    patch_loop(su, st, t0, t1, touches);
    sync_positions(st.nodes, st.mesh, t1, st.step_t0);
  }
  st.time = t1;
  // Sect. 2, Eqs. 2-3: element forces at t1 (step 5: a sub-model's parents
  // by their sub-model); Sect. 4.2: clone forces (Eq. 11) and separation
  // (Eqs. 6-10); the second half-kick.
  forces_and_second_half_kick(su, st);
  // Sect. 5: sub-models (kSubModel) or patches (kInPlace) whose clone
  // nodes all separated are deleted.
  if (submodel_mode(su.opt)) {
    if (delete_separated_submodels(su, st)) refresh_forces_after_patch_change(su, st, t1);
  } else if (su.opt.subdivision && dissolve_free_patches(su, st)) {
    refresh_forces_after_patch_change(su, st, t1);
  }
  ++st.steps;
  check_state(st);
}

void Model::advance_to(double t) {
  while (state_.time < t - 0.5 * setup_.dt) step();
}

void check_state(const ModelState& st) {
  const NodeState& nd = st.nodes;
  for (std::size_t i = 0; i < nd.x.size(); ++i) {
    if (nd.kind[i] == NodeKind::kDead) continue;
    if (!is_finite(nd.x[i]) || !is_finite(nd.v[i])) {
      std::ostringstream s;
      s << "cdem: non-finite state at node " << i << " of block " << nd.block[i] << ", t = " << st.time << " s (step "
        << st.steps << ")";
      throw SimulationError(s.str(), StopReason::kNonFinite);
    }
  }
}

}  // namespace dda::cdem
