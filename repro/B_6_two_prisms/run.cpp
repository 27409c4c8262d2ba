// Paper B Sect. 6, two prisms: the runs (one model run watched step by step,
// the mode runs, the mesh-refinement and contact-point mass points).
#include "repro/B_6_two_prisms/two_prisms.hpp"

namespace prisms {

Result simulate(const dda::cdem::CdemScene& scene,
                const std::function<void(const dda::cdem::Model&)>& on_step) {
  dda::cdem::Model m(scene);
  Result r;
  r.dt = m.dt();
  r.p0 = m.momentum().x;
  r.e0 = m.energy().total();
  r.accounts.push_back(m.energy_account());
  if (on_step) on_step(m);
  while (m.time() < scene.duration - 0.5 * m.dt()) {
    m.step();
    r.worst_momentum = std::max(r.worst_momentum, std::fabs(m.momentum().x - r.p0) / std::fabs(r.p0));
    if (m.block_max_velocity_x(1) > r.peak_node_vj) {
      r.peak_node_vj = m.block_max_velocity_x(1);
      r.peak_node_vj_time = m.time();
    }
    r.peak_mean_vj = std::max(r.peak_mean_vj, m.block_velocity(1).x);
    r.max_substeps = std::max(r.max_substeps, m.patch_substeps());
    for (const auto& sm : m.submodels()) r.max_substeps = std::max(r.max_substeps, sm.substeps);  // kSubModel
    if (std::fabs(m.time() - kFig14cTime) < 0.5 * m.dt()) r.peak_node_vj_at_fig14c = m.block_max_velocity_x(1);
    r.accounts.push_back(m.energy_account());
    if (on_step) on_step(m);
  }
  if (m.touches().empty()) throw std::runtime_error("B-6: no touch happened");
  r.touch = m.touches().front();
  for (const auto& s : m.separations())
    if (s.time > r.touch.time) {
      r.t_sep = s.time;
      r.sep_kind = s.criterion == dda::cdem::SeparationCriterion::kTension ? "tension (Eq. 6)" : "shear (Eqs. 7-10)";
    }
  r.vi = m.block_velocity(0).x;
  r.vj = m.block_velocity(1).x;
  r.momentum_end = m.momentum().x;
  r.e_end = m.energy();
  r.impact = m.impact_energy_loss();
  r.remap = m.remap_energy_change();
  return r;
}
MassPoint contact_mass_point(double target, int max_subdivision) {
  dda::cdem::CdemOptions o;
  o.contact_point_mass = target;
  o.subdivision_mode = dda::cdem::SubdivisionMode::kInPlace;  // contact_point_mass is an in-place option
  o.max_subdivision = max_subdivision;
  const Result r = simulate(dda::cdem::two_prisms(kPaperDivisionsForMass, o));
  return {target, r.touch.subdivision, r.touch.mass_main, r.touch.mass_target, r.touch.energy_loss,
          r.touch.energy_loss_eq5};
}
double touching_node_mass(const Result& r) {
  return dda::cdem::Model(dda::cdem::two_prisms(kPaperDivisionsForMass)).node_mass(r.touch.main_node);
}
MeshPoint mesh_point(int divisions) {
  dda::cdem::CdemOptions o;
  o.subdivision_mode = dda::cdem::SubdivisionMode::kInPlace;
  dda::cdem::CdemScene s = dda::cdem::two_prisms(divisions, o);
  s.dt = kPaperDt * kPaperDivisions / divisions;
  const Result r = simulate(s);
  return {divisions, s.dt, r.vj, r.peak_node_vj_at_fig14c, r.t_sep};
}
ModeRun run_mode(dda::cdem::SubdivisionMode mode, int divisions, double dt) {
  dda::cdem::CdemOptions o;
  o.subdivision_mode = mode;
  dda::cdem::CdemScene s = dda::cdem::two_prisms(divisions, o);
  s.dt = dt;
  ModeRun run;
  const auto wall0 = std::chrono::steady_clock::now();
  const std::clock_t cpu0 = std::clock();
  run.r = simulate(s, [&](const dda::cdem::Model& m) {
    if (m.submodels().empty()) {
      run.substeps = m.patch_substeps_taken();
      run.k = m.subdivision_level();
      run.n = std::max(run.n, m.patch_substeps());
      return;
    }
    run.submodels = static_cast<int>(m.submodels().size());
    run.k = m.submodels().front().k;
    run.n = m.submodels().front().substeps;
    run.substeps = 0;
    run.kinetic_dropped = 0.0;
    for (const auto& sm : m.submodels()) {
      run.substeps += sm.substeps_taken;
      run.kinetic_dropped += sm.kinetic_dropped;
    }
    run.submodel_deleted = m.submodels().front().deleted;
  });
  run.cpu = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
  run.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return run;
}
SubMeshPoint submodel_mesh_point(int divisions) {
  dda::cdem::CdemOptions o;
  o.subdivision_mode = dda::cdem::SubdivisionMode::kSubModel;
  dda::cdem::CdemScene s = dda::cdem::two_prisms(divisions, o);
  s.dt = kPaperDt * kPaperDivisions / divisions;
  SubMeshPoint p;
  p.divisions = divisions;
  p.dt = s.dt;
  try {
    const Result r = simulate(s);
    p.vj = r.vj;
    p.node_vj_fig14c = r.peak_node_vj_at_fig14c;
    p.t_sep = r.t_sep;
    p.momentum = r.worst_momentum;
  } catch (const dda::SimulationError& e) {
    p.stopped = e.what();
  }
  return p;
}
}  // namespace prisms
