// S1 work precision: the paper's scenes with a reference, one Case per
// option (what each measures: work_precision.cpp's header comment); our
// own scenes are in cases_ours.cpp, the parts of both in case_kit.hpp.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "dda/paper_scenes.hpp"
#include "dda/robustness_scenes.hpp"
#include "dda/simulation.hpp"
#include "repro/S1_work_precision/case_kit.hpp"
#include "repro/S1_work_precision/work_precision.hpp"

namespace s1 {
namespace {
using dda::Vec2;
using kit::Conservation;
using kit::make_case;
using kit::option_name;
using repro::format_short;

const dda::HRule kUnified = dda::HRule::kMinMaxEdge, kInscribed = dda::HRule::kInscribedRadius;
const dda::Integration kPaperRule = dda::Integration::kPaperBisector, kExactRule = dda::Integration::kExactEnvelope;

std::vector<Case> two_squares_cases() {
  std::vector<Case> out;
  struct Opt {
    dda::HRule h;
    dda::Integration rule;
    bool strains;
  };
  for (const Opt& o : {Opt{kUnified, kPaperRule, true}, Opt{kUnified, kExactRule, true},
                       Opt{kInscribed, kPaperRule, true}, Opt{kInscribed, kExactRule, true},
                       Opt{kUnified, kPaperRule, false}}) {
    Case c = make_case("4.1 two squares", option_name(o.rule, o.h, true) + (o.strains ? "" : ", rigid (strains off)"),
                       dda::paper::two_squares(), -4, 3, 0.008);  // 6.25e-6 .. 8e-4 s
    c.sc.contact.integration = o.rule;
    c.sc.contact.h_rule = o.h;
    c.sc.strains = o.strains;
    c.measures = {{"momentum", "exact conservation", 1e-12},
                  {"energy out of contact", "exact conservation", 1e-12},
                  {"energy in contact", "exact conservation", 1e-12},
                  {"exchanged velocity", "rigid elastic exchange v_A = 0, v_B = 1 m/s", 1e-12}};
    c.observer = [] {
      return kit::conservation_observer([](const Conservation& cons, const dda::Simulation& sim) {
        const double v0 = 1.0;
        const double exch = (std::fabs(sim.velocity(0)[0]) + std::fabs(sim.velocity(1)[0] - v0)) / v0;
        return std::vector<double>{cons.momentum_error(), cons.energy_error(), cons.energy_error_contact(), exch};
      });
    };
    kit::whole_run_trajectory(c);
    out.push_back(c);
  }
  return out;
}

std::vector<Case> incline_cases() {
  std::vector<Case> out;
  struct Opt {
    double phi;
    dda::Integration rule;
    bool start_up = false;  // the friction start-up option (settled with sticking contacts; not the paper's)
  };
  for (const Opt& o : {Opt{0.0, kPaperRule}, Opt{10.0, kPaperRule}, Opt{20.0, kPaperRule}, Opt{20.0, kExactRule},
                       Opt{20.0, kPaperRule, true}}) {
    const dda::paper::Incline in = dda::paper::incline(o.phi);
    Case c = make_case("4.3 incline",
                       "phi = " + format_short(o.phi) + " deg, " + option_name(o.rule, kUnified, false) +
                           (o.start_up ? ", friction start-up (not the paper's)" : ""),
                       in.scene, -1, 7, 0.01024);  // 5e-6 .. 1.28e-3 s; samples every 8 steps of the largest dt
    c.sc.contact.integration = o.rule;
    if (o.start_up) {  // as in the 4.3 driver: a = 80 1/s for 0.5 s with sticking contacts
      c.sc.damping.mass = 80.0;
      c.sc.damping.settle_time = 0.5;
      c.sc.damping.settle_sticking = true;
    }
    c.sc.duration = 1.024;  // a whole number of samples
    c.measures = {{"Eq. 30", "Eq. 30 at t = 1.024 s", 1e-12},
                  {"energy balance", "kinetic + gravity + strain + contact + friction springs + dissipated = initial",
                   1e-13}};
    const double phi = o.phi * kit::kPi / 180.0;
    c.observer = [in, phi] {
      auto c0 = std::make_shared<Vec2>();
      auto budget = std::make_shared<Budget>();
      Observer ob;
      ob.begin = [c0, budget](const dda::Simulation& sim) {
        *c0 = sim.centroid(1);
        budget->step(sim);
      };
      ob.step = [budget](const dda::Simulation& sim) { budget->step(sim); };
      ob.end = [c0, budget, in, phi](const dda::Simulation& sim) {
        const double l = dot(sim.centroid(1) - *c0, in.downhill);
        const double la = dda::paper::incline_distance(kit::kG, in.theta_rad, phi, sim.time());
        return std::vector<double>{std::fabs(l - la) / la, budget->error()};
      };
      return ob;
    };
    kit::whole_run_trajectory(c);
    out.push_back(c);
  }
  return out;
}

std::vector<Case> triangles_cases() {
  std::vector<Case> out;
  for (dda::HRule h : {kUnified, kInscribed})
    for (dda::Integration rule : {kPaperRule, kExactRule}) {
      const dda::paper::SmallAngleTriangles st = dda::paper::small_angle_triangles();
      Case c = make_case("5.2 small-angle triangles", option_name(rule, h, true), st.scene, -5, 2,
                         0.0016);  // 6.25e-7 .. 8e-5 s
      c.sc.contact.integration = rule;
      c.sc.contact.h_rule = h;
      c.sc.duration = 0.2;
      const Vec2 centre = st.centre;
      c.measures = {{"point symmetry (m)", "exact: block 1 = 2 c - block 0", 1e-12},
                    {"energy out of contact", "exact conservation", 1e-12},
                    {"energy in contact", "exact conservation", 1e-12}};
      c.observer = [centre] {
        auto sym = std::make_shared<double>(0.0);
        Observer o = kit::conservation_observer([sym](const Conservation& cons, const dda::Simulation&) {
          return std::vector<double>{*sym, cons.energy_error(), cons.energy_error_contact()};
        });
        o.step = [conserve = o.step, sym, centre](const dda::Simulation& sim) {
          conserve(sim);
          *sym = std::max(*sym, dda::paper::point_symmetry_error(sim.polygon(0), sim.polygon(1), centre));
        };
        return o;
      };
      out.push_back(c);
    }
  return out;
}

std::vector<Case> bouncing_cases() {
  std::vector<Case> out;
  for (dda::HRule h : {kUnified, kInscribed}) {
    Case c = make_case("5.1 bouncing block", "case 1, " + option_name(kPaperRule, h, true),
                       dda::paper::bouncing_block(0.1, h, 1.536).scene, -4, 3, 0.0064);  // 6.25e-6 .. 8e-4 s
    c.measures = {{"energy out of contact", "exact conservation", 1e-12}};
    c.observer = kit::energy_observer;
    // First impact: A falls 0.5 m (t = 0.319 s) and rebounds within ~0.1 s.
    c.trajectory_windows = {0.4992, c.sc.duration};
    c.trajectory_names = {"trajectory, first impact (t <= 0.5 s)", "trajectory, all impacts (1.5 s)"};
    out.push_back(c);
  }
  return out;
}

std::vector<Case> small_edge_cases() {
  std::vector<Case> out;
  struct Opt {
    dda::Integration rule;
    dda::RotationUpdate update;
  };
  for (const Opt& opt : {Opt{kPaperRule, dda::RotationUpdate::kPaperLinear},
                         Opt{kExactRule, dda::RotationUpdate::kPaperLinear},
                         Opt{kPaperRule, dda::RotationUpdate::kExact}}) {
    Case c = make_case("5.3 small edge",
                       "case b, " + option_name(opt.rule, kUnified, false) +
                           (opt.update == dda::RotationUpdate::kExact ? ", exact rotation (not the paper's)" : ""),
                       dda::paper::small_edge_impact(dda::paper::SmallEdgeCase::kOnNeighbourEdge).scene, -5, 2,
                       0.0016);  // 3.125e-6 .. 4e-4 s
    c.sc.contact.integration = opt.rule;
    c.sc.rotation_update = opt.update;
    c.sc.duration = 0.2048;
    c.measures = {{"energy out of contact", "exact conservation", 1e-12}};
    c.observer = kit::energy_observer;
    kit::whole_run_trajectory(c);
    out.push_back(c);
  }
  return out;
}

}  // namespace

std::vector<Case> all_cases() {
  std::vector<Case> cases;
  for (std::vector<Case> (*make)() : {two_squares_cases, incline_cases, resting_cases, triangles_cases,
                                       bouncing_cases, small_edge_cases, free_rotation_cases, damping_cases}) {
    const std::vector<Case> v = make();
    cases.insert(cases.end(), v.begin(), v.end());
  }
  return cases;
}

}  // namespace s1
