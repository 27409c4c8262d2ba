// Two elastic bars head on: one run per model (the CDEM bars, Paper A's DDA
// bars) watched step by step, and the study's series of runs.
#include <chrono>
#include <cmath>

#include "repro/B_8_bar_waves/bar_waves.hpp"

namespace bars {
namespace {

// A run that reached its time limit before the bars touched (or separated):
// a SimulationError, recorded as the run's stop.
[[noreturn]] void throw_unfinished(bool not_touched, double t_limit) {
  throw dda::SimulationError(std::string("the bars did not ") + (not_touched ? "touch" : "separate") + " by t = " +
                             repro::format_short(t_limit) + " s");
}

}  // namespace

void set_errors(Run& r, const Setup& s) {
  r.duration = r.t_end - r.t_touch;
  r.duration_err = (r.duration - s.contact_time()) / s.contact_time();
  r.stress_err = (r.mean_stress - s.contact_stress()) / s.contact_stress();
  r.plateau_err = (r.plateau_stress - s.contact_stress()) / s.contact_stress();
  r.exchange_err = std::max(std::fabs(r.v0), std::fabs(r.v1 - s.speed)) / s.speed;
}
double seconds_since(std::chrono::steady_clock::time_point a) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count();
}
Run run_cdem(const Setup& s, int ny, double dt, bool subdivision, Trace* trace,
             bool check_stability) {
  Run r;
  r.model = subdivision ? "B" : "B0";
  r.ny = ny;
  r.h = s.width / ny;
  r.dt = dt > 0.0 ? dt : kCourant * r.h / s.wave_speed();
  const auto start = std::chrono::steady_clock::now();
  dda::cdem::CdemScene scene = cdem_scene(s, ny, r.dt, subdivision);
  scene.options.check_stability = check_stability;
  dda::cdem::Model m(scene);
  r.critical_dt = m.critical_dt();
  const double T = s.contact_time(), p0 = m.momentum().x, e0 = m.energy().total();
  Plateau plateau;
  const double t_limit = s.touch_time() + kCdemMaxContacts * T;
  double t_free = -1.0;  // since when no clone exists after the touch
  try {
    while (true) {
      const double t0 = m.time(), q0 = m.block_momentum(1).x;
      m.step();
      ++r.steps;
      const double t1 = m.time(), stress = (m.block_momentum(1).x - q0) / (t1 - t0) / s.width;
      r.momentum_err = std::max(r.momentum_err, std::fabs(m.momentum().x - p0) / std::fabs(p0));
      r.energy_growth = std::max(r.energy_growth, (m.energy().total() - e0) / e0);
      if (!m.touches().empty()) {
        if (r.t_touch < 0.0) r.t_touch = m.touches().front().time;
        plateau.add(t0, t1, stress, r.t_touch, T);
        if (trace && t1 <= r.t_touch + 1.6 * T) {
          trace->t.push_back(0.5 * (t0 + t1));
          trace->stress.push_back(stress);
        }
        if (m.clones().empty()) {
          if (t_free < 0.0) t_free = t1;
        } else {
          t_free = -1.0;
        }
        if (t_free >= 0.0 && t1 >= t_free + 0.5 * T) break;
      }
      if (t1 > t_limit) throw_unfinished(r.t_touch < 0.0, t_limit);
    }
  } catch (const dda::SimulationError& e) {
    r.wall = seconds_since(start);
    r.stopped = e.what();
    r.touches = static_cast<int>(m.touches().size());
    r.separations = static_cast<int>(m.separations().size());
    return r;
  }
  r.wall = seconds_since(start);
  r.t_end = m.separations().empty() ? t_free : m.separations().back().time;
  r.touches = static_cast<int>(m.touches().size());
  r.separations = static_cast<int>(m.separations().size());
  r.v0 = m.block_velocity(0).x;
  r.v1 = m.block_velocity(1).x;
  r.mean_stress = m.block_momentum(1).x / ((r.t_end - r.t_touch) * s.width);
  r.plateau_stress = plateau.mean();
  r.energy_end = (m.energy().total() - e0) / e0;
  set_errors(r, s);
  return r;
}
Run run_dda(const Setup& s, double dt, double kn, Trace* trace) {
  Run r;
  r.model = "A";
  r.dt = dt;
  r.kn = kn;
  const auto start = std::chrono::steady_clock::now();
  dda::Simulation sim(dda_scene(s, dt, kn));
  r.critical_dt = sim.critical_time_step();
  const double T = s.contact_time(), p0 = sim.momentum().x;
  const double e0 = sim.energy().total(), m1 = sim.mass(1);
  Plateau plateau;
  const double t_limit = s.touch_time() + kDdaMaxContacts * T;
  try {
    while (true) {
      const double t0 = sim.time(), q0 = m1 * sim.velocity(1)[0];
      sim.step();
      ++r.steps;
      const double t1 = sim.time(), stress = (m1 * sim.velocity(1)[0] - q0) / (t1 - t0) / s.width;
      r.momentum_err = std::max(r.momentum_err, std::fabs(sim.momentum().x - p0) / std::fabs(p0));
      const bool contact = sim.contact_count() > 0;
      if (contact) {
        // energy() integrates the contact energy: only while in contact
        r.energy_growth = std::max(r.energy_growth, (sim.energy().total() - e0) / e0);
        if (r.t_touch < 0.0) r.t_touch = t1;  // the first step end with an overlap
        r.t_end = t1;
      }
      if (r.t_touch >= 0.0) {
        plateau.add(t0, t1, stress, r.t_touch, T);
        if (trace && (contact || t1 <= r.t_end + 0.6 * T)) {
          trace->t.push_back(0.5 * (t0 + t1));
          trace->stress.push_back(stress);
        }
        if (!contact && t1 >= r.t_end + 0.5 * T) break;
      }
      if (t1 > t_limit) throw_unfinished(r.t_touch < 0.0, t_limit);
    }
  } catch (const dda::SimulationError& e) {
    r.wall = seconds_since(start);
    r.stopped = e.what();
    return r;
  }
  r.wall = seconds_since(start);
  r.v0 = sim.velocity(0)[0];
  r.v1 = sim.velocity(1)[0];
  r.mean_stress = m1 * r.v1 / ((r.t_end - r.t_touch) * s.width);
  r.plateau_stress = plateau.mean();
  const double e_end = sim.energy().total();
  r.energy_end = (e_end - e0) / e0;
  r.energy_growth = std::max(r.energy_growth, r.energy_end);
  set_errors(r, s);
  return r;
}
}  // namespace bars
