// S1 work precision: the claim rows, each criterion a function of
// work_precision.hpp so that the negative controls apply the same one.
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "repro/S1_work_precision/work_precision.hpp"

namespace s1 {

bool order_met(const repro::stab::Order& order, double expected, double tol) {
  return order.valid() && std::fabs(order.p - expected) <= tol;
}
bool roundoff_met(double max_error, double level) { return max_error < level; }
bool plateau_met(const repro::stab::Order& order) { return order.note == "plateau"; }

double resting_deviation(dda::HRule h, double sunk) {
  const Resting r = resting_block(h, sunk);
  dda::Simulation sim(r.sc);
  double dev = 0.0;
  while (sim.time() < r.sc.duration - 0.5 * sim.dt()) {
    sim.step();
    dev = std::max(dev, std::fabs(penetration(sim) - sunk));
  }
  return dev;
}

std::vector<repro::Claim> claim_rows(const std::vector<CurveSummary>& curves, const References& references) {
  using repro::format_short;
  // ---- claims ----------------------------------------------------------------
  std::vector<repro::Claim> claims;
  auto find = [&](const std::string& scene, const std::string& option_part, const std::string& measure) {
    for (const CurveSummary& cs : curves)
      if (cs.scene == scene && cs.option.find(option_part) != std::string::npos && cs.measure == measure) return cs;
    throw std::runtime_error("no curve " + scene + " / " + option_part + " / " + measure);
  };
  auto at_paper = [](const CurveSummary& cs) {
    return "error " + format_short(cs.error_at_paper, 3) + " at the paper's dt (dt/dt_crit " +
           format_short(cs.ratio_at_paper, 3) + ", " + format_short(cs.wall_at_paper * 1e3, 3) + " ms)";
  };
  auto order_text = [](const CurveSummary& cs) {
    return cs.order.valid() ? "order " + format_short(cs.order.p, 3) + " (fit over dt " + format_short(cs.order.dt_lo, 3) +
                                  ".." + format_short(cs.order.dt_hi, 3) + " s)"
                            : "no order: " + cs.order.note;
  };
  auto order_claim = [&](const std::string& section, const CurveSummary& cs, double expected, double tol,
                         const std::string& why) {
    claims.push_back({section, cs.scene + ", " + cs.option + ": " + cs.measure + " converges at order " +
                                   format_short(expected) + " (" + why + ")",
                      "velocity Verlet: second order for smooth forces", order_text(cs) + "; " + at_paper(cs),
                      "|order - " + format_short(expected) + "| <= " + format_short(tol),
                      order_met(cs.order, expected, tol)});
    // The controls cover the expected orders the rows use (1 and 2, tol 0.3).
    if (tol <= 0.3 && (expected == 2.0 || expected == 1.0))
      claims.back().control = expected == 2.0 ? kControlOrder2 : kControlOrder1;
  };
  auto roundoff_claim = [&](const std::string& section, const CurveSummary& cs, double level, const std::string& what) {
    claims.push_back({section, cs.scene + ", " + cs.option + ": " + what + " at round-off for every stable dt",
                      "exact in the method",
                      "largest error over the sweep " + format_short(cs.max_error, 3) + "; " + at_paper(cs),
                      "below " + format_short(level) + " at every dt that ran", roundoff_met(cs.max_error, level)});
    if (level <= 1e-10) claims.back().control = kControlRoundoff;  // the control's level
  };
  auto plateau_claim = [&](const std::string& section, const CurveSummary& cs, const std::string& what,
                           const std::string& why) {
    claims.push_back({section, cs.scene + ", " + cs.option + ": " + what + " is a model error that dt does not reduce",
                      why, order_text(cs) + "; " + at_paper(cs), "fitted errors within a factor 1.5 (plateau)",
                      plateau_met(cs.order)});
    claims.back().control = kControlPlateau;
  };
  const std::string pu = "paper segmentation, H unified";
  roundoff_claim("S1 / 4.1", find("4.1 two squares", pu, "momentum"), 1e-12, "momentum");
  order_claim("S1 / 4.1", find("4.1 two squares", pu, "energy out of contact"), 2.0, 0.3,
              "energy after the impact");
  plateau_claim("S1 / 4.1", find("4.1 two squares", pu, "energy in contact"), "the energy error during contact",
                "deformable blocks: the contact force loads the strains through one point (Eqs. 22-23)");
  order_claim("S1 / 4.1", find("4.1 two squares", "rigid", "energy in contact"), 2.0, 0.3,
              "rigid blocks: the force is the gradient of the contact energy");
  plateau_claim("S1 / 4.1", find("4.1 two squares", pu, "exchanged velocity"), "the gap to a full exchange",
                "deformable blocks keep an elastic vibration after the impact");
  {
    // The final velocities depend on where the separation falls inside a
    // step: the local order scatters, so the slope is fitted over every dt.
    const CurveSummary cs = find("4.1 two squares", "rigid", "exchanged velocity");
    claims.push_back({"S1 / 4.1", cs.scene + ", " + cs.option +
                                      ": exchanged velocity converges at order 2 over the sweep (rigid blocks "
                                      "exchange velocities exactly in the limit)",
                      "Fig. 8: velocities exchanged",
                      "order over every stable dt " + format_short(cs.order_all.p, 3) + "; over the 4 smallest " +
                          order_text(cs) + "; " + at_paper(cs),
                      "|order over every stable dt - 2| <= 0.3", order_met(cs.order_all, 2.0, 0.3)});
    claims.back().control = kControlOrder2;
  }
  order_claim("S1 / 4.1", find("4.1 two squares", pu, "trajectory (m)"), 2.0, 0.3,
              "one impact, force continuous in the penetration");
  order_claim("S1 / 4.1", find("4.1 two squares", "paper segmentation, H inscribed radius", "trajectory (m)"), 2.0,
              0.3, "inscribed-radius H: twice as stiff");
  roundoff_claim("S1 / 4.3", find("4.3 incline", "phi = 0 deg", "Eq. 30"), 1e-12,
                 "frictionless sliding distance against Eq. 30");
  using Why = std::pair<const char*, const char*>;  // an option or measure, and why its order is expected
  for (const Why& w : {Why{"phi = 0 deg", "persistent frictionless contact"},
                       Why{"phi = 10 deg", "persistent contact with friction, sliding throughout"}})
    order_claim("S1 / 4.3", find("4.3 incline", w.first, "trajectory (m)"), 2.0, 0.3, w.second);
  {
    const CurveSummary cs = find("4.3 incline", "phi = 20 deg, paper", "trajectory (m)");
    claims.push_back({"S1 / 4.3", cs.scene + ", " + cs.option + ": trajectory error (stick/slip switching)",
                      "not discussed in the paper", order_text(cs) + "; " + at_paper(cs),
                      "information: switching between stick and slip is not smooth", false, repro::Kind::kMeasurement});
    const CurveSummary e = find("4.3 incline", "phi = 20 deg, paper", "Eq. 30");
    claims.push_back({"S1 / 4.3", "phi = 20 deg: error against Eq. 30 is the model's (penalty stick phase), not dt's",
                      "Fig. 12: good agreement",
                      at_paper(e) + "; trajectory error at the paper's dt " + format_short(cs.error_at_paper, 3) + " m",
                      "Eq. 30 error > 100 x the dt error (relative to the 0.9 m distance)",
                      model_error_dominates(e.error_at_paper, cs.error_at_paper)});
    claims.back().control = repro::control_test(kControlModelError);
  }
  // The energy budget with friction: the sliding
  // work is dissipated, the springs hold the rest.
  for (const char* phi : {"phi = 0 deg", "phi = 10 deg", "phi = 20 deg, paper"}) {
    const CurveSummary cs = find("4.3 incline", phi, "energy balance");
    claims.push_back({"S1 / 4.3", cs.scene + ", " + cs.option +
                                      ": the energy budget closes (kinetic + gravity + strain + contact + friction "
                                      "springs + dissipated sliding work = initial) at every stable dt",
                      "Sect. 2.3 energy; friction work (Eqs. 24-26) dissipated",
                      "largest error over the sweep " + format_short(cs.max_error, 3) + "; " + order_text(cs) + "; " +
                          at_paper(cs),
                      "below 1e-3 of the energy turned over at every dt that ran",
                      budget_closes(cs.max_error) && cs.error_at_paper >= 0.0});
    claims.back().control = repro::control_test(kControlBudget);
  }
  {
    // The friction start-up option (not the paper's) against Eq. 30 over dt.
    const CurveSummary cs = find("4.3 incline", "friction start-up", "Eq. 30");
    claims.push_back({"S1 / 4.3", cs.scene + ", " + cs.option + ": within 1 % of Eq. 30 at every stable dt",
                      "Fig. 12: 'good agreements' (Eq. 30)",
                      "largest error over the sweep " + format_short(cs.max_error, 3) + "; " + order_text(cs) + "; " +
                          at_paper(cs),
                      "below 1 % at every dt that ran", within_eq30(cs.max_error) && cs.error_at_paper >= 0.0});
    claims.back().control = repro::control_test(kControlEq30);
  }
  for (const char* h : {"H unified", "H inscribed radius"})
    order_claim("S1 / resting", find("resting block", std::string("paper segmentation, ") + h, "deepest penetration"),
                2.0, 0.3, "rigid block released at contact, analytic turning point");
  // Static check: A placed at the derived static penetration must stay there.
  for (dda::HRule h : {dda::HRule::kMinMaxEdge, dda::HRule::kInscribedRadius}) {
    const double ds = resting_block(h, 0.0).static_pen();
    const double dev = resting_deviation(h, ds);
    const std::string hn = h == dda::HRule::kMinMaxEdge ? "unified H = 2.5 m" : "inscribed-radius H = 0.5 m";
    claims.push_back({"S1 / resting",
                      "static penetration of a flat contact, " + hn +
                          ": delta_s = L - sqrt(L^2 - W H / kn) (unified), in general the root of kn [L delta "
                          "(1/H_A + 1/H_B) - delta^2 / H_A] = W; A placed there stays",
                      "derived here (f = 2 kn delta L / H - kn delta^2 / H)",
                      "delta_s = " + format_short(ds, 6) + " m; max |delta - delta_s| over 0.5 s = " +
                          format_short(dev, 3) + " m (" + format_short(dev / ds, 3) + " of delta_s)",
                      "< 1e-6 of delta_s", stays_at(dev, ds)});
    claims.back().control = repro::control_test(kControlStatic);
  }
  {
    const CurveSummary sym = find("5.2 small-angle triangles", pu, "point symmetry (m)");
    roundoff_claim("S1 / 5.2", sym, 1e-12, "point symmetry");
    const CurveSummary ec = find("5.2 small-angle triangles", pu, "energy in contact");
    claims.push_back({"S1 / 5.2", ec.scene + ", " + ec.option + ": energy error in contact",
                      "not discussed in the paper", order_text(ec) + "; " + at_paper(ec),
                      "information (deformable blocks: one-point loading of the strains)", false, repro::Kind::kMeasurement});
  }
  for (const char* h : {"H unified", "H inscribed radius"}) {
    order_claim("S1 / 5.1", find("5.1 bouncing block", h, "trajectory, first impact (t <= 0.5 s) (m)"), 2.0, 0.3,
                "first impact");
    const CurveSummary all = find("5.1 bouncing block", h, "trajectory, all impacts (1.5 s) (m)");
    claims.push_back({"S1 / 5.1", all.scene + ", " + all.option + ": trajectory over all impacts",
                      "no analytic answer (converged run)", order_text(all) + "; " + at_paper(all),
                      "information: repeated impacts", false, repro::Kind::kMeasurement});
  }
  for (const char* o : {"paper segmentation", "exact integration"})
    order_claim("S1 / 5.3", find("5.3 small edge", o, "trajectory (m)"), 1.0, 0.3,
                "the off-centre impact sets the block spinning: linearised rotation, see 'free rotation'");
  // Beside the paper's rule, the option that fixes it (Scene::rotation_update).
  roundoff_claim("S1 / rotation", find("free rotation", "exact rotation", "area"), 1e-12,
                 "area of a spinning block with the exact rotation update");
  roundoff_claim("S1 / rotation", find("free rotation", "exact rotation", "vertex position (m)"), 1e-10,
                 "vertex positions of a spinning block with the exact rotation update");
  order_claim("S1 / 5.3", find("5.3 small edge", "exact rotation", "trajectory (m)"), 2.0, 0.3,
              "the exact rotation update (not the paper's) restores second order on the spinning block");
  for (const Why& w : {Why{"area", "DDA's linearised vertex update T(p) dd grows a spinning block"},
                       Why{"vertex position (m)", "the growth moves the vertices off the exact rotation"}})
    order_claim("S1 / rotation", find("free rotation", "rigid", w.first), 1.0, 0.3, w.second);
  // Eq. 5c damping (an option beyond the paper), its orders measured.
  for (const char* m : {"vertex position (m)", "kinetic energy", "energy budget"})
    order_claim("S1 / damping", find("damped flight", "a = 2", m), 2.0, 0.3,
                "semi-implicit mass-damping kick, v multiplied by (1 - a h/2) / (1 + a h/2) per step");
  order_claim("S1 / damping", find("4.1 two squares", "stiffness damping", "trajectory (m)"), 2.0, 0.3,
              "b K d' from the step's drift velocity enters both half kicks around t^{n+1}: centred");
  {
    const CurveSummary& cs = find("4.1 two squares", "stiffness damping", "energy budget");
    claims.push_back({"S1 / damping", cs.scene + ", " + cs.option + ": energy budget with the damping work",
                      "not in the paper (Eq. 5c is not used in its examples)", order_text(cs) + "; " + at_paper(cs),
                      "information: deformable blocks in contact leave a model error dt does not reduce (see "
                      "'energy in contact')", false, repro::Kind::kMeasurement});
  }
  // Paper segmentation against exact integration, both converged: the
  // difference is the model's (the segmentation misses kinks of the
  // potential), to compare with the dt error at the paper's dt.
  for (const auto& [key, samples] : references) {
    const std::size_t at = key.find("paper segmentation");
    if (at == std::string::npos) continue;
    const std::string other = key.substr(0, at) + "exact integration" + key.substr(at + 18);
    for (const auto& [key2, samples2] : references) {
      if (key2 != other || samples2.size() != samples.size()) continue;
      double d = 0.0;
      for (std::size_t k = 0; k < samples.size(); ++k)
        d = std::max(d, repro::stab::max_abs_difference(samples[k], samples2[k]));
      const std::string scene = key.substr(0, key.find(" | ")), option = key.substr(key.find(" | ") + 3);
      double dt_error = -1.0;
      for (const CurveSummary& cs : curves)
        if (cs.scene == scene && cs.option == option && cs.measure.rfind("trajectory", 0) == 0)
          dt_error = std::max(dt_error, cs.error_at_paper);
      claims.push_back({"S1 / integration", scene + ", " + option + " vs exact integration: converged trajectories",
                        "Sect. 3.2.3 segmentation (exact only where the bisector crossings are all the kinks of the potential)",
                        "max vertex distance between the two converged runs " + format_short(d, 3) +
                            " m; dt error of the paper segmentation at the paper's dt " +
                            format_short(dt_error, 3) + " m",
                        "information: a model difference, not a dt error", false, repro::Kind::kMeasurement});
    }
  }
  return claims;
}

}  // namespace s1
