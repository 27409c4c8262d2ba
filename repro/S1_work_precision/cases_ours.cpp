// S1 work precision: our scenes with an exact answer (not the paper's):
// the resting block, the free rotation and the damped runs, one Case per
// option (what each measures: work_precision.cpp's header comment).
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "dda/paper_scenes.hpp"
#include "dda/simulation.hpp"
#include "repro/S1_work_precision/case_kit.hpp"
#include "repro/S1_work_precision/work_precision.hpp"

namespace s1 {
using dda::Vec2;
using kit::make_case;

Resting resting_block(dda::HRule h, double sunk) {
  Resting r;
  dda::Scene& s = r.sc;
  s.name = "resting block (ours)";
  s.materials = {{2000.0, 1e9, 0.25}};
  s.contact.kn = 50e6;  // Table 5
  s.contact.h_rule = h;
  s.gravity = {0.0, -kit::kG};
  s.strains = false;  // rigid: the contact law alone (strains would add their own vibration)
  s.dt = 1e-4;
  s.duration = 0.512;
  dda::BlockSpec b;
  b.vertices = {{-2.0, -1.0}, {2.0, -1.0}, {2.0, 0.0}, {-2.0, 0.0}};
  b.fixed = true;
  b.name = "B";
  dda::BlockSpec a;
  a.vertices = {{-0.5, -sunk}, {0.5, -sunk}, {0.5, 1.0 - sunk}, {-0.5, 1.0 - sunk}};
  a.name = "A";
  s.blocks = {b, a};
  r.h_a = h == dda::HRule::kInscribedRadius ? 0.5 : 2.5;  // inscribed radius of A / min-max edge (4 + 1) / 2
  r.h_b = h == dda::HRule::kInscribedRadius ? 0.5 : 2.5;  // inscribed radius of B (1 m high)
  r.weight = 2000.0 * 1.0 * kit::kG;
  s.initial_overlap = sunk > 0.0 ? 2.0 * sunk : 0.0;
  return r;
}

double penetration(const dda::Simulation& sim) {
  double lo = 1e300;
  const dda::Polygon& p = sim.polygon(1);
  for (int k = 0; k < p.count; ++k) lo = std::min(lo, p.vertex(k).y);
  return -lo;  // B's top is y = 0
}

// A free block spinning at 2 rad/s, no contact, no gravity: isolates the
// kinematic update. DDA moves each vertex by T(p) dd (Eq. 8), a linearised
// rotation: each step scales the block by sqrt(1 + (w dt)^2), so over a
// fixed time the area grows by ~ w^2 dt T, first order in dt.
// Scene::rotation_update = kExact turns the rigid part exactly (not the
// paper's rule): area and vertex positions at round-off for every dt.
std::vector<Case> free_rotation_cases() {
  std::vector<Case> out;
  for (dda::RotationUpdate update : {dda::RotationUpdate::kPaperLinear, dda::RotationUpdate::kExact}) {
    Case c = make_case("free rotation",
                       update == dda::RotationUpdate::kExact
                           ? "rigid 1 m square, w = 2 rad/s, exact rotation (not the paper's)"
                           : "rigid 1 m square, w = 2 rad/s",
                       kit::spinning_square("free rotation (ours)", update, {0.0, 0.0}, 2.0), -4, 3, 0.0064);
    c.measures = {{"area", "exact: rigid motion keeps the area", 1e-12},
                  {"vertex position (m)", "exact rotation by w t about the centroid", 1e-12}};
    const dda::BlockSpec spec = c.sc.blocks[0];
    c.observer = [spec] {
      auto a0 = std::make_shared<double>(0.0);
      Observer o;
      o.begin = [a0](const dda::Simulation& sim) { *a0 = sim.area(0); };
      o.end = [a0, spec](const dda::Simulation& sim) {
        const double e = kit::vertex_error(sim, spec, {0.0, 0.0}, spec.spin * sim.time());
        return std::vector<double>{std::fabs(sim.area(0) / *a0 - 1.0), e};
      };
      return o;
    };
    out.push_back(c);
  }
  return out;
}

namespace {
// The deepest penetration over the run against the energy estimate dmax
// (relative).
Observer deepest_penetration(double dmax) {
  auto deepest = std::make_shared<double>(0.0);
  Observer o;
  o.step = [deepest](const dda::Simulation& sim) { *deepest = std::max(*deepest, penetration(sim)); };
  o.end = [deepest, dmax](const dda::Simulation&) { return std::vector<double>{std::fabs(*deepest - dmax) / dmax}; };
  return o;
}
}  // namespace

std::vector<Case> resting_cases() {
  std::vector<Case> out;
  for (dda::HRule h : {dda::HRule::kMinMaxEdge, dda::HRule::kInscribedRadius})
    for (dda::Integration rule : {dda::Integration::kPaperBisector, dda::Integration::kExactEnvelope}) {
      const Resting r = resting_block(h, 0.0);
      Case c = make_case("resting block", kit::option_name(rule, h, true), r.sc, -3, 6,
                         0.0064);  // 1.25e-5 .. 6.4e-3 s
      c.sc.contact.integration = rule;
      c.measures = {{"deepest penetration", "energy: kn [L s delta / 2 - delta^2 / (3 H_A)] = W", 1e-12}};
      const double dmax = r.max_pen();
      c.observer = [dmax] { return deepest_penetration(dmax); };
      kit::whole_run_trajectory(c);
      out.push_back(c);
    }
  return out;
}

// Eq. 5c damping (Scene::damping; not the paper's method: its Eq. 6 leaves
// C d' out), its order measured, not assumed:
// - mass damping a: a rigid 1 m square in free flight (1, 0.5) m/s, spinning
//   at 2 rad/s, a = 2 1/s, no gravity, the exact rotation update (so the
//   rotation adds no first-order error of its own). Exact: every velocity
//   decays as e^{-a t}, the centroid moves by v0 (1 - e^{-a t}) / a and the
//   block turns by w0 (1 - e^{-a t}) / a; kinetic energy E0 e^{-2 a t}.
//   Expected: second order (the semi-implicit kick, damping.cpp).
// - stiffness damping b: the 4.1 two squares (deformable, unified H) with
//   b = 1e-5 s, against a converged run; the energy budget (damping work
//   counted as dissipated) against exact closure. The b K d' term, from the
//   step's drift velocity v^{n+1/2}, enters both half kicks around t^{n+1}
//   (damping.cpp), so the damping impulse is centred: second order expected.
std::vector<Case> damping_cases() {
  std::vector<Case> out;
  {
    dda::Scene flight = kit::spinning_square("damped flight (ours)", dda::RotationUpdate::kExact, {1.0, 0.5}, 2.0);
    flight.damping.mass = 2.0;
    Case c = make_case("damped flight", "rigid 1 m square, a = 2 1/s, exact rotation", flight, -4, 3, 0.0064);
    c.measures = {{"vertex position (m)", "exact: decaying velocity and spin, x = v0 (1 - e^-at) / a", 1e-13},
                  {"kinetic energy", "exact: E0 e^-2at", 1e-13},
                  {"energy budget", "kinetic + damping work = E0", 1e-13}};
    const dda::BlockSpec spec = flight.blocks[0];
    const double a = flight.damping.mass;
    c.observer = [spec, a] {
      auto e0 = std::make_shared<double>(0.0);
      auto budget = std::make_shared<Budget>();
      Observer o;
      o.begin = [e0](const dda::Simulation& sim) { *e0 = sim.energy().kinetic; };
      o.step = [budget](const dda::Simulation& sim) { budget->step(sim); };
      o.end = [spec, a, e0, budget](const dda::Simulation& sim) {
        const double t = sim.time(), f = (1.0 - std::exp(-a * t)) / a;
        const double e = kit::vertex_error(sim, spec, f * spec.velocity, spec.spin * f);
        const double ek = *e0 * std::exp(-2.0 * a * t);
        return std::vector<double>{e, std::fabs(sim.energy().kinetic / ek - 1.0), budget->error()};
      };
      return o;
    };
    out.push_back(c);
  }
  {
    dda::Scene damped = dda::paper::two_squares();
    damped.damping.stiffness = 1e-5;
    // b lowers the critical step below 8e-4 s (damping.cpp): paper dt * 2^-4 .. 2^2.
    Case c = make_case("4.1 two squares", "paper segmentation, H unified, stiffness damping b = 1e-5 s", damped, -4, 2,
                       0.008);
    c.measures = {{"energy budget", "kinetic + strain + contact + damping work = E0", 1e-13}};
    c.observer = kit::budget_observer;
    kit::whole_run_trajectory(c);
    out.push_back(c);
  }
  return out;
}

}  // namespace s1
