// The CDEM model's step (Paper B), one file per step of the method:
//   Sect. 2   mesh and set-up ............................ model_mesh.cpp
//   Sect. 2   element forces, Eqs. 1-3 ................... model_elements.cpp
//   Sect. 3   touch detection, time of impact ............ model_touch.cpp
//   Sect. 4.1 clone nodes, inelastic impact, Eqs. 4-5 .... model_clone.cpp
//   Sect. 4.2 interaction force and separation, Eqs. 6-11  model_separation.cpp
//   Sect. 5   sub-model of the colliding elements, Eq. 12  model_submodel.cpp
//             (the paper's steps 1-5; SubdivisionMode::kSubModel)
//   Sect. 5   in-place refinement, patch steps ........... model_subdivision.cpp
//             (beyond the paper; SubdivisionMode::kInPlace)
//   energy, momentum and other read-out ................. model_energy.cpp
//   baseline: node-to-edge penalty contact (not Paper B)  model_penalty.cpp
#include "dda/cdem/model.hpp"

#include <algorithm>
#include <sstream>

namespace dda::cdem {

// Without subdivision, Sect. 3 as written: the touching nodes move dt1 with
// their free velocity, take the inelastic impact, and move dt2 as a clone;
// every other node moves the full dt.
void Model::literal_two_stage(const std::vector<Touch>& touches, double t0) {
  std::vector<double> tau(x_.size(), 0.0);
  std::vector<char> changed(x_.size(), 0);
  for (const Touch& T : touches) {
    if (touch_blocked(T.node)) continue;
    std::vector<int> set{T.node, T.ea, T.eb};
    for (std::size_t head = 0; head < set.size(); ++head)
      for (const Clone& c : clones_) {
        std::vector<int> cn{c.main};
        for (int a : c.t)
          if (a >= 0) cn.push_back(a);
        if (std::find(cn.begin(), cn.end(), set[head]) == cn.end()) continue;
        for (int a : cn)
          if (std::find(set.begin(), set.end(), a) == set.end()) set.push_back(a);
      }
    bool stale = false;
    for (int a : set) stale = stale || changed[a];
    if (stale) continue;  // found again next step from the updated motion
    for (int a : set)
      if (kind_[a] == NodeKind::kCoarse && !blocks_[node_block_[a]].fixed) {
        x_[a] += ((T.s - tau[a]) * dt_) * v_[a];
        tau[a] = T.s;
      }
    if (process_touch(T, false, t0 + T.s * dt_, t0, t0 + dt_))
      for (int a : set) changed[a] = 1;
  }
  for (int n : coarse_dofs_) x_[n] += ((1.0 - tau[n]) * dt_) * v_[n];
}

// One coarse step t0 -> t1 = t0 + dt, explicit central differences in
// kick-drift-kick form (Eq. 1), as a table of the method's steps.
void Model::step() {
  if (opt_.contact == ContactMode::kNodeToEdgePenalty) return penalty_step();  // baseline, model_penalty.cpp
  const double t0 = time_, t1 = t0 + dt_;
  step_t0_ = t0;
  step_touch_count_.clear();
  // Sect. 2, Eq. 1: first half-kick of the coarse nodes.
  kick_coarse_first_half();
  // Sects. 2-3: touches on the collision path of the step, with their time
  // of impact t0 + dt1.
  const std::vector<Touch> touches = coarse_touches(t0);
  if (!opt_.subdivision || submodel_mode()) {
    // Sects. 3-4.1: free motion over dt1, the clone node and its inelastic
    // impact (Eqs. 4-5), motion as a clone over dt2.
    literal_two_stage(touches, t0);
    // Sect. 5 as written (kSubModel): the sub-models of the colliding
    // elements integrated over the step with dt/n, driven by the coarse
    // nodes' motion (steps 2-4, Eq. 12); this step's touches get theirs
    // (step 1).
    if (submodel_mode()) advance_submodels(t0, t1);
  } else {
    // Sect. 5: the contact zone refined at each touch and integrated with
    // steps dt/n (Eq. 12), touches inside found at the patch scale.
    patch_loop(t0, t1, touches);
    sync_positions(t1);
  }
  time_ = t1;
  // Sect. 2, Eqs. 2-3: element forces at t1; Sect. 4.2: clone forces
  // (Eq. 11) and separation (Eqs. 6-10); the second half-kick.
  forces_and_second_half_kick();
  // Sect. 5: sub-models (kSubModel) or patches (kInPlace) whose clone
  // nodes all separated are deleted.
  if (submodel_mode()) {
    if (delete_separated_submodels()) refresh_forces_after_patch_change(t1);
  } else if (opt_.subdivision && dissolve_free_patches()) {
    refresh_forces_after_patch_change(t1);
  }
  ++steps_;
  check_state();
}

void Model::advance_to(double t) {
  while (time_ < t - 0.5 * dt_) step();
}

void Model::check_state() const {
  for (std::size_t i = 0; i < x_.size(); ++i) {
    if (kind_[i] == NodeKind::kDead) continue;
    if (!is_finite(x_[i]) || !is_finite(v_[i])) {
      std::ostringstream s;
      s << "cdem: non-finite state at node " << i << " of block " << node_block_[i] << ", t = " << time_ << " s (step "
        << steps_ << ")";
      throw SimulationError(s.str(), StopReason::kNonFinite);
    }
  }
}

}  // namespace dda::cdem
