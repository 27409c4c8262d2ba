// Paper B Sect. 2, Eqs. 1-3: element forces of the constant-strain triangles
// (incremental stress, rotated), their assembly on the nodes, and the
// kinematics of the explicit step (positions at a time inside the step,
// half-kicks of the patch nodes).
#include "dda/cdem/model.hpp"

#include <cmath>
#include <sstream>

#include "geometry.hpp"

namespace dda::cdem {

using namespace detail;

void Model::sync_positions(double t) {
  const double tau = t - step_t0_;
  for (int n : coarse_dofs_) x_[n] = xs_[n] + tau * v_[n];
  for (int h : hanging_) {
    x_[h] = lerp(x_[hang_a_[h]], x_[hang_b_[h]], hang_w_[h]);
    v_[h] = lerp(v_[hang_a_[h]], v_[hang_b_[h]], hang_w_[h]);
  }
}

void Model::add_node_force(int n, Vec2 f, bool patch_eval) {
  if (kind_[n] == NodeKind::kHanging) {
    add_node_force(hang_a_[n], (1.0 - hang_w_[n]) * f, patch_eval);
    add_node_force(hang_b_[n], hang_w_[n] * f, patch_eval);
    return;
  }
  if (patch_eval && kind_[n] == NodeKind::kCoarse)
    iface_[n] += f;
  else
    f_[n] += f;
}

// Incremental CST force (Paper B Eqs. 2-3): strain increment from the
// displacement since the last evaluation with B of the mid configuration,
// stress rotated by the element's incremental rotation and incremented with
// D d_eps; nodal forces -A B^T sigma with B of the current configuration.
void Model::element_force(Elem& e, bool patch_eval) {
  const std::array<Vec2, 3> x{x_[e.n[0]], x_[e.n[1]], x_[e.n[2]]};
  std::array<Vec2, 3> f;
  if (cst_incremental_force(x, e.last, e.stress, d_[blocks_[e.block].material], f) != 0) {
    std::ostringstream s;
    s << "cdem: element of block " << e.block << " inverted at t = " << time_ << " s (step " << steps_ << ")";
    throw SimulationError(s.str(), StopReason::kAreaCollapsed);
  }
  for (int i = 0; i < 3; ++i) add_node_force(e.n[i], f[i], patch_eval);
}

void Model::compute_coarse_forces() {
  const Vec2 g = scene_.gravity;
  for (int n : coarse_dofs_) f_[n] = m_[n] * g - opt_.mass_damping * m_[n] * v_[n];
  for (int e : coarse_eval_) {
    if (blocks_[elem(e).block].fixed) continue;
    if (in_submodel(e)) continue;  // Sect. 5 step 5: its sub-model's force instead
    element_force(elem(e), false);
  }
  add_submodel_forces();
  solve_clones(false, time_);
  if (opt_.contact == ContactMode::kNodeToEdgePenalty) add_penalty_forces();
}

void Model::compute_patch_forces(double t) {
  const Vec2 g = scene_.gravity;
  for (int n : fine_dofs_) f_[n] = m_[n] * g - opt_.mass_damping * m_[n] * v_[n];
  for (int n : coarse_dofs_) iface_[n] = Vec2{};
  for (int e : patch_eval_)
    if (!blocks_[elem(e).block].fixed) element_force(elem(e), true);
  solve_clones(true, t);
}

void Model::kick_patch(double h) {
  for (int n : fine_dofs_) v_[n] += (h * inv_m_[n]) * f_[n];
  for (int n : coarse_dofs_) iimp_[n] += h * iface_[n];
}

// Coarse nodes next to a patch (corners of coarse elements evaluated at the
// patch steps) get those elements' force in their half-kicks like any other
// force (f_ = coarse-step forces + iface_ at t0 and t1), and at t1 the
// difference between the impulse the patch steps integrated for them (iimp_)
// and what the two half-kicks gave (dt/2 at t0 and t1): so the impulses of
// every element on all its corners match (momentum exact) while the kicks
// stay centred (a return of the averaged impulse alone lags by dt/2 and
// pumps energy in at a rate ~ (omega dt)^2).
void Model::kick_coarse_first_half() {
  for (int n : coarse_dofs_) {
    iface0_[n] = iface_[n];
    v_[n] += (0.5 * dt_ * inv_m_[n]) * f_[n];
  }
  for (int n : coarse_dofs_) xs_[n] = x_[n];
}

void Model::forces_and_second_half_kick() {
  if (patch_eval_.empty())
    for (int n : coarse_dofs_) iface_[n] = Vec2{};
  compute_coarse_forces();
  for (int n : coarse_dofs_) {
    v_[n] += inv_m_[n] * ((0.5 * dt_) * f_[n] + iimp_[n] - (0.5 * dt_) * iface0_[n]);
    iimp_[n] = Vec2{};
    iface0_[n] = Vec2{};
    f_[n] += iface_[n];
  }
}

// After the mesh changed at the step end: forces of the new mesh at t.
void Model::refresh_forces_after_patch_change(double t) {
  for (int n : coarse_dofs_) iface_[n] = Vec2{};
  if (!patch_eval_.empty()) compute_patch_forces(t);
  compute_coarse_forces();
  for (int n : coarse_dofs_) f_[n] += iface_[n];
}

}  // namespace dda::cdem
