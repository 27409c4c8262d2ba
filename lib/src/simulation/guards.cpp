// The guards: a run that leaves the method's domain stops with a
// SimulationError naming the step, time, block, pair, the value, the bound
// and dt/dt_crit. Per block (flagged in the kick loop): a non-finite state,
// a collapsed area, a vertex moving too far in one step (guard_fault,
// integration.cpp: inline in the kick loop); per pair (flagged
// in the pair loop): the penetration guard (penetration_guard.cpp); every
// energy_check_every steps: the total energy's growth and the energy budget.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <exception>
#include <sstream>

#include "simulation/internal.hpp"

namespace dda {

using detail::thread_index;

namespace {

// The end of every stop message: dt against the critical step now (the
// current contacts) and as predicted at the start.
std::string dt_ratio_text(double dt, double now, double predicted) {
  std::ostringstream s;
  s << "dt/dt_crit = ";
  if (std::isfinite(now) && now < DBL_MAX) s << dt / now << " now, ";
  else s << "undefined now (state not finite), ";
  s << dt / predicted << " predicted at start";
  return s.str();
}

}  // namespace

bool Engine::guards_stop(std::int64_t done, bool energy_due, std::exception_ptr& error) {
  // The per-block flags were set before the kick loop's barrier: every
  // thread takes the same branch. One thread reports the first failure
  // (check_state) into `error`; true (for every thread) when it did.
  bool failed = false;
  for (const ThreadFlags& f : flags_) failed = failed || f.guard_failed || f.pair_failed;
  if (!(failed || energy_due)) return false;
  if (thread_index() == 0) {
    steps_ = done;
    time_ = static_cast<double>(steps_) * dt_;
    try {
      count_candidates();
      check_state(energy_due);  // stops at the failed block; the energy check when due
    } catch (...) {
      error = std::current_exception();
    }
  }
  team_barrier(Simulation::kPhaseGuards);  // every thread sees `error` before reading it
  return static_cast<bool>(error);
}

[[noreturn]] void Engine::stop(int block, StopReason why, const std::string& what) const {
  std::ostringstream s;
  s << "step " << steps_ << " (t = " << time_ << " s): block " << block;
  // The pair through which the block takes its largest contact force.
  double fmax = 0.0;
  int other = -1;
  each_contact([&](std::size_t k, const ContactSlot& c) {
    const int cp = near_pairs_[k].i, tp = near_pairs_[k].j;
    if ((cp == block || tp == block) && length(c.result.normal_force) > fmax) {
      fmax = length(c.result.normal_force);
      other = cp == block ? tp : cp;
    }
  });
  if (other >= 0) s << ", pair (" << std::min(block, other) << ", " << std::max(block, other) << ")";
  s << ": " << what << "; " << dt_ratio_text(dt_, critical_time_step(), dt_crit_prior_);
  SimulationError e(s.str(), why);
  e.step = steps_;
  e.time = time_;
  e.block = block;
  if (other >= 0) e.pair_a = std::min(block, other), e.pair_b = std::max(block, other);
  throw e;
}

[[noreturn]] void Engine::stop_pair(int a, int b, StopReason why, const std::string& what) const {
  std::ostringstream s;
  s << "step " << steps_ << " (t = " << time_ << " s): pair (" << a << ", " << b << ") = " << block_label(a)
    << " and " << block_label(b) << ": " << what << "; " << dt_ratio_text(dt_, critical_time_step(), dt_crit_prior_);
  SimulationError e(s.str(), why);
  e.step = steps_;
  e.time = time_;
  e.pair_a = std::min(a, b), e.pair_b = std::max(a, b);
  throw e;
}

std::string Engine::block_label(int i) const {
  // "block 3 'name'" (the scene's name, if any) or "boundaries[k]".
  std::ostringstream s;
  if (i >= scene_blocks_) {
    s << "boundaries[" << i - scene_blocks_ << "]";
  } else {
    s << "block " << i;
    if (!block_names_.empty() && !block_names_[static_cast<std::size_t>(i)].empty())
      s << " '" << block_names_[static_cast<std::size_t>(i)] << "'";
  }
  return s.str();
}

void Engine::check_state(bool energy_due) {
  // The first block that fails a per-block guard, with the reason.
  for (int i = 0; i < block_count(); ++i) {
    if (fixed_[i]) continue;
    const GuardFault fault = guard_fault(i);
    if (fault == GuardFault::kNone) continue;
    std::ostringstream s;  // built only for the message
    StopReason why = StopReason::kOther;
    switch (fault) {
      case GuardFault::kNone: continue;
      case GuardFault::kNonFinite: stop(i, StopReason::kNonFinite, "non-finite velocity or position");
      case GuardFault::kAreaCollapsed:
        why = StopReason::kAreaCollapsed;
        s << "area collapsed to " << moments_[i].area << " m^2";
        break;
      case GuardFault::kStepMotion:
        why = StopReason::kStepMotion;
        // Largest vertex motion of this step, |T(p) dd| at the vertices
        // (squared, recorded by move_blocks as it moved them).
        s << "a vertex moved " << std::sqrt(step_motion2_[i]) << " m in one step, more than "
          << scene_.guards.max_step_motion << " of the smallest inscribed radius within reach (" << reach_radius(i)
          << " m)";
        break;
    }
    stop(i, why, s.str());
  }
  check_pairs();  // penetration_guard.cpp: the first pair that fails the penetration guard
  if (energy_due) {
    // energy() with this step's stored contact energies, in pair order.
    Energy e = block_energy();
    each_contact([&](std::size_t, const ContactSlot& c) { e.contact += c.result.energy; });
    energy_scale_ = std::max(energy_scale_, e.kinetic + e.strain + e.contact);
    const double scale = std::max(energy_scale_, DBL_MIN);
    // The block reported: the one with the largest translational kinetic energy.
    auto fastest = [this] {
      int worst = 0;
      double kmax = -1.0;
      for (int i = 0; i < block_count(); ++i) {
        if (fixed_[i]) continue;
        const double k = vel_[i].head<2>().squaredNorm() * mass_[i];
        if (k > kmax) {
          kmax = k;
          worst = i;
        }
      }
      return worst;
    };
    const double growth = (e.total() - energy0_) / scale;
    if (growth > scene_.guards.max_energy_growth) {
      std::ostringstream s;
      s << "total energy grew by " << growth << " of the largest mechanical energy (" << energy_scale_
        << " J), more than " << scene_.guards.max_energy_growth;
      stop(fastest(), StopReason::kEnergyGrowth, s.str());
    }
    // The energy budget (energy.cpp): what the state holds plus what
    // friction and damping dissipated must stay the initial energy.
    const double max_error = scene_.guards.max_balance_error;
    if (max_error > 0.0) {
      add_budget_terms(e);
      e.initial = energy0_;
      const double error = e.balance_error() / scale;
      if (std::fabs(error) > max_error) {
        std::ostringstream s;
        s << "energy budget off by " << error << " of the largest mechanical energy (" << energy_scale_
          << " J): kinetic + gravity + strain + contact + friction springs " << e.total() << " + dissipated "
          << e.dissipated << " against " << e.initial << " at t = 0, more than guards.max_balance_error = "
          << max_error << "; reduce dt (the integration error falls with it) or raise the bound (0 switches it off)";
        stop(fastest(), StopReason::kEnergyBudget, s.str());
      }
    }
  }
}

}  // namespace dda
