// The impact study: one cell run to the end of its window, measured.
#include <chrono>

#include "repro/B_9_impact_study/impact_study.hpp"

namespace impact {

void finish(CellResult& r, const dda::cdem::Model& m) {
  const dda::cdem::CdemEnergyAccount acc = m.energy_account();
  r.touches = static_cast<int>(m.touches().size());
  r.separations = static_cast<int>(m.separations().size());
  r.slips = static_cast<int>(m.slips().size());
  r.touch_loss = acc.touch_loss;
  r.touch_loss_eq5 = acc.touch_loss_eq5;
  r.touch_loss_eq5_group = acc.touch_loss_eq5_group;
  r.total_loss = r.ke0 - (acc.kinetic + acc.strain);
  const Vec2 v0 = impact_velocity(r.cell);
  r.block_eq5 = 0.5 * normal_mass() * dda::length_squared(v0);
  const Vec2 va = m.block_velocity(0), vb = m.block_velocity(1);
  r.e = v0.x > 0.0 ? -(va.x - vb.x) / v0.x : 0.0;
  r.jn = m.block_momentum(1).x;
  r.jt = m.block_momentum(1).y;
  r.omega_a = block_spin(m, 0);
  r.omega_b = block_spin(m, 1);
  r.slip0 = v0.y;
  r.slip_end = (va.y - vb.y) + 0.5 * kSide * (r.omega_a + r.omega_b);
  r.jt_law = rigid_law_jt(r.cell.mu, r.jn, r.slip0, &r.law_sticks);
  r.separated = r.ok && m.clones().empty() && vb.x - va.x > 0.0 && r.touches > 0;
}
CellResult run_cell(const Cell& c, double dt, const dda::cdem::CdemScene* scene_override) {
  const auto start = std::chrono::steady_clock::now();
  CellResult r;
  r.cell = c;
  const dda::cdem::CdemScene s = scene_override ? *scene_override : scene_of(c, dt);
  r.tol = s.options.tolerance;
  r.gap = gap_of(c, dt);
  const double vn = impact_velocity(c).x;
  r.t_end = r.gap / vn + kWindowWaves * wave_time();
  const auto loops = boundary_loops(s);
  dda::cdem::Model m(s);
  r.ke0 = m.energy().kinetic;
  r.min_centre_dx = m.block_mean_position(1).x - m.block_mean_position(0).x;
  bool in_contact = false;
  try {
    while (m.time() < r.t_end - 0.5 * m.dt()) {
      m.step();
      const dda::cdem::CdemEnergy e = m.energy();
      r.ke_growth = std::max(r.ke_growth, e.kinetic / r.ke0 - 1.0);
      r.total_growth = std::max(r.total_growth, (e.kinetic + e.strain) / r.ke0 - 1.0);
      r.max_depth = std::max(r.max_depth, max_node_depth(m, loops));
      r.min_centre_dx = std::min(r.min_centre_dx, m.block_mean_position(1).x - m.block_mean_position(0).x);
      const bool now = !m.clones().empty();
      if (in_contact && !now) r.t_sep = m.time();
      in_contact = now;
    }
    r.ok = true;
    r.outcome = "ok";
  } catch (const dda::SimulationError& err) {  // ContactError included
    r.ok = false;
    r.outcome = err.what();
  }
  finish(r, m);
  r.pass_through = !r.ok || r.max_depth > r.tol || r.min_centre_dx < 0.5 * kSide;
  r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}
}  // namespace impact
