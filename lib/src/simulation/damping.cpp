// Eq. 5c damping, C = a M + b K (Paper A Sect. 2.2; Scene::damping), in the
// kicks of velocity Verlet, and the settle-then-load start. Not the paper's
// method: its Eq. 6 leaves C d' out; off unless a scene asks for it.
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "simulation/friction.hpp"  // friction_tan
#include "simulation/internal.hpp"

namespace dda {

void Engine::damped_kick_block(int i, const Vec6& force) {
  // Eq. 4 with Eq. 5c's C = a M + b K, M d'' = F - a M d' - b K d', in the
  // second half kick of velocity Verlet (Eq. 7):
  // - b K d': K is the block's elastic stiffness (Eq. 5b) and its contact
  //   springs, the elastic part of F: F^{n+1} - F^n = -K (d^{n+1} - d^n) =
  //   -h K d'^{n+1/2} for a linear K (gravity, the only other force, is
  //   constant and cancels), so b K d'^{n+1/2} = -b (F^{n+1} - F^n) / h,
  //   without assembling K: the force of the step's own drift velocity. It
  //   enters a^{n+1} and so both half kicks around t^{n+1} (a lag of half a
  //   step). A sliding contact's friction force changes with its normal
  //   force, and b damps that change too.
  // - a M d': semi-implicit, at v^{n+1}: v^{n+1} = (v^{n+1/2} + h/2 M^-1 F)
  //   / (1 + a h/2), and a^{n+1} = M^-1 F - a v^{n+1} for the next first
  //   half kick, so a full step multiplies v by (1 - a h/2) / (1 + a h/2):
  //   second order, and stable for any a >= 0.
  // The work of the damping force over the step's drift Delta d^n, by the
  // trapezoid of its values at t^n and t^{n+1} (as the friction work), goes
  // to the energy budget's dissipated term (energy.cpp).
  Vec6 f = force;
  Vec6 damp = Vec6::Zero();
  if (damp_b_ > 0.0) {
    damp = (damp_b_ / dt_) * (force - force_prev_[i]);
    f += damp;
    force_prev_[i] = force;
  }
  const Vec6 af = force_acceleration(i, f);
  vel_[i] = (vel_[i] + 0.5 * dt_ * af) / (1.0 + 0.5 * damp_a_ * dt_);
  acc_[i] = af - damp_a_ * vel_[i];
  if (damp_a_ > 0.0) damp -= damp_a_ * (mass_matrix(moments_[i], density_[i]) * vel_[i]);
  damping_work_[i] += 0.5 * (damp_force_[i] + damp).dot(step_disp_[i]);
  damp_force_[i] = damp;
}

void Engine::start_damping(bool on) {
  // a^n of the current forces (summed again from the pairs' loads: the
  // same bits as the last kick's), with or without the damping, v^n kept
  // (the b term has no step behind it: it starts at zero; a fixed block's
  // force is zero).
  damped_ = on && scene_.damping.on();
  damp_a_ = damped_ ? scene_.damping.mass : 0.0;
  damp_b_ = damped_ ? scene_.damping.stiffness : 0.0;
  if (damp_b_ > 0.0) force_prev_.assign(static_cast<std::size_t>(block_count()), Vec6::Zero());
  damping_work_.resize(static_cast<std::size_t>(block_count()), 0.0);
  damp_force_.assign(static_cast<std::size_t>(block_count()), Vec6::Zero());
  for (int i = 0; i < block_count(); ++i) {
    if (fixed_[i]) continue;
    const Vec6 force = gather_contact_forces(i);
    if (damp_b_ > 0.0) force_prev_[i] = force;
    acc_[i] = force_acceleration(i, force) - damp_a_ * vel_[i];
    if (damped_) damp_force_[i] = -damp_a_ * (mass_matrix(moments_[i], density_[i]) * vel_[i]);
  }
}

void Engine::settle() {
  // The constructor's start with damping. Without a settle time: damped
  // from t = 0. With one (dynamic relaxation): from rest, damped, for that
  // long; then undamped from the settled configuration at rest (what
  // velocity the settling left is dropped), with the blocks' initial
  // velocities, the clock (time, steps, displacements) started at zero.
  // The stresses and the contacts' friction springs keep what the
  // settling loaded into them.
  const double settle = scene_.damping.settle_time;
  std::vector<Vec6> v0;
  if (settle > 0.0) {
    v0 = vel_;
    for (Vec6& v : vel_) v.setZero();
  }
  start_damping(true);
  start_energy_guard();  // damping only removes energy: the guard stays valid
  if (!(settle > 0.0)) return;
  std::vector<double> friction_tan;
  // A touching pair keeps its blocks' tan phi from its first contact
  // (PairHistory::friction_tan): each change of the table is given to them.
  const auto retake_friction_tans = [&] {
    for (std::size_t k = 0; k < near_pairs_.size(); ++k)
      if (near_pairs_[k].slot >= 0)
        contact_slots_[static_cast<std::size_t>(near_pairs_[k].slot)].history.friction_tan =
            Engine::friction_tan(near_pairs_[k].i, near_pairs_[k].j);
  };
  if (scene_.damping.settle_sticking) {
    // No friction limit while settling (an infinite tan phi: a contact's
    // normal force is never zero, so the limit is +inf, never NaN).
    friction_tan = friction_tan_table_;
    std::fill(friction_tan_table_.begin(), friction_tan_table_.end(), std::numeric_limits<double>::infinity());
    retake_friction_tans();
  }
  // With settle_sticking, the last settle_slip_time of the settle runs
  // with the friction limits again (still damped).
  const double sticking_until = scene_.damping.settle_sticking ? settle - scene_.damping.settle_slip_time : settle;
  try {
    advance_to(sticking_until);
    if (scene_.damping.settle_sticking) {
      friction_tan_table_ = friction_tan;
      retake_friction_tans();
    }
    advance_to(settle);
  } catch (const SimulationError& e) {
    SimulationError settling(std::string("while settling (damping.settle_time = ") + std::to_string(settle) +
                                 " s, before t = 0): " + e.what(),
                             e.reason);
    // Where it stopped, on the settle's own clock (before t = 0).
    settling.step = e.step, settling.time = e.time, settling.block = e.block;
    settling.pair_a = e.pair_a, settling.pair_b = e.pair_b;
    throw settling;
  }
  start_damping(false);
  for (std::size_t i = 0; i < vel_.size(); ++i) vel_[i] = v0[i];
  for (Vec6& d : disp_) d.setZero();
  steps_ = 0;
  time_ = 0.0;
  start_energy_guard();
}

void Engine::check_stiffness_damping() const {
  // Explicit steps with stiffness-proportional damping are stable for
  // h <= (2 / omega) (sqrt(1 + zeta^2) - zeta), zeta = b omega / 2: b
  // lowers the critical step. Checked at the predicted omega_max =
  // 2 / predicted_critical_step.
  const double b = scene_.damping.stiffness;
  if (!(b > 0.0) || !(dt_crit_prior_ < DBL_MAX)) return;
  const double zeta = b / dt_crit_prior_;
  const double limit = dt_crit_prior_ * (std::sqrt(1.0 + zeta * zeta) - zeta);
  if (dt_ <= limit) return;
  std::ostringstream s;
  s << "damping.stiffness: b = " << b << " s lowers the predicted critical step from " << dt_crit_prior_ << " s to "
    << limit << " s, below dt = " << dt_ << " s; use a smaller b or dt";
  throw SceneError(s.str());
}

}  // namespace dda
