// S1 work precision: the parts of the cases (case_kit.hpp).
#include "repro/S1_work_precision/case_kit.hpp"

#include <algorithm>
#include <memory>

namespace s1::kit {

std::vector<double> pow2_dts(double paper_dt, int k_lo, int k_hi) {
  std::vector<double> d;
  for (int k = k_lo; k <= k_hi; ++k) d.push_back(std::ldexp(paper_dt, k));
  return d;
}

std::string option_name(dda::Integration rule, dda::HRule h, bool show_h) {
  std::string s = rule == dda::Integration::kPaperBisector ? "paper segmentation" : "exact integration";
  if (show_h) s += h == dda::HRule::kInscribedRadius ? ", H inscribed radius" : ", H unified";
  return s;
}

Case make_case(const std::string& scene, const std::string& option, const dda::Scene& sc, int k_lo, int k_hi,
               double sample_every) {
  Case c;
  c.scene = scene;
  c.option = option;
  c.sc = sc;
  c.paper_dt = sc.dt;
  c.dts = pow2_dts(c.paper_dt, k_lo, k_hi);
  c.sample_every = sample_every;
  return c;
}

void whole_run_trajectory(Case& c) {
  c.trajectory_windows = {c.sc.duration};
  c.trajectory_names = {"trajectory"};
}

void Conservation::begin(const dda::Simulation& sim) {
  const dda::Energy e = sim.energy();
  e0 = e.total();
  e_mech = e.kinetic + e.strain + e.contact;
  p0 = sim.momentum();
}

void Conservation::step(const dda::Simulation& sim) {
  const dda::Energy e = sim.energy();
  e_mech = std::max(e_mech, e.kinetic + e.strain + e.contact);
  double& d = sim.contact_count() == 0 ? de : de_contact;
  d = std::max(d, std::fabs(e.total() - e0));
  dp = std::max(dp, dda::length(sim.momentum() - p0));
}

Observer conservation_observer(ConservationEnd end) {
  auto cons = std::make_shared<Conservation>();
  Observer o;
  o.begin = [cons](const dda::Simulation& sim) { cons->begin(sim); };
  o.step = [cons](const dda::Simulation& sim) { cons->step(sim); };
  o.end = [cons, end](const dda::Simulation& sim) { return end(*cons, sim); };
  return o;
}

Observer energy_observer() {
  return conservation_observer(
      [](const Conservation& cons, const dda::Simulation&) { return std::vector<double>{cons.energy_error()}; });
}

Observer budget_observer() {
  auto budget = std::make_shared<Budget>();
  Observer o;
  o.step = [budget](const dda::Simulation& sim) { budget->step(sim); };
  o.end = [budget](const dda::Simulation&) { return std::vector<double>{budget->error()}; };
  return o;
}

dda::Scene spinning_square(const std::string& name, dda::RotationUpdate update, dda::Vec2 velocity, double spin) {
  dda::Scene s;
  s.name = name;
  s.materials = {{2000.0, 1e9, 0.25}};
  s.strains = false;
  s.rotation_update = update;
  s.dt = 1e-4;
  s.duration = 1.024;
  dda::BlockSpec b;
  b.vertices = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
  b.velocity = velocity;
  b.spin = spin;
  s.blocks = {b};
  return s;
}

double vertex_error(const dda::Simulation& sim, const dda::BlockSpec& spec, dda::Vec2 shift, double angle) {
  double e = 0.0;
  for (int k = 0; k < sim.polygon(0).count; ++k)
    e = std::max(e, dda::length(sim.polygon(0).vertex(k) - (shift + dda::rotate(spec.vertices[k], angle))));
  return e;
}

}  // namespace s1::kit
