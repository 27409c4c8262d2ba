// Two elastic bars head on: the claim rows against 1D wave theory (each
// CDEM model on its finest mesh, Paper A at its dt and kn ratio, energy) and
// the measurements (observed order, dt refinement, work-precision, A's kn).
#include <algorithm>
#include <cmath>

#include "repro/B_8_bar_waves/bar_waves.hpp"

namespace bars {

std::string pct(double x) { return format_short(100.0 * x, 3) + " %"; }

std::vector<repro::Claim> rows(const std::vector<Run>& runs, const Setup& s, const std::string& run_note) {
  const double E = s.material.young;
  auto series = [&](const std::string& model, const std::string& ser) {
    std::vector<Run> v;
    for (const Run& r : runs)
      if (r.model == model && r.series == ser) v.push_back(r);
    return v;
  };
  const std::vector<Run> b0 = series("B0", "mesh"), b = series("B", "mesh");
  const Run& bf = b.back();
  const std::vector<Run> a_dt = series("A", "dt"), a_kn = series("A", "kn");
  const Run& a0 = a_dt.front();  // Paper A's dt and kn ratio
  const std::string theory = "1D bars (plane stress, nu = 0): T = 2L/c = " + format_short(s.contact_time(), 4) +
                             " s, stress rho c v/2 = " + format_short(s.contact_stress(), 4) +
                             " Pa, velocities exchanged (0, " + format_short(s.speed) + " m/s)";
  auto mesh_text = [&](const std::vector<Run>& v, double Run::*f) {
    std::string t;
    for (const Run& r : v)
      t += (t.empty() ? "" : ", ") + std::to_string(r.ny) + ": " + (r.ok() ? pct(r.*f) : std::string("stopped"));
    return "by ny " + t;
  };
  auto finest_text = [&](const Run& r) {
    return "finest mesh ny " + std::to_string(r.ny) + " (h " + format_short(r.h * 1e3, 3) + " mm, dt " +
           format_short(r.dt, 3) + " s)" + (r.ok() ? "" : " STOPPED: " + r.stopped);
  };
  // Used only if a B row fails: what the runs measured, not a diagnosis.
  // (Cutting the patch steps at each touch and an uncapped sliding friction
  // once made the subdivided contact chatter and gain energy, up to 2.39 E0
  // at ny 8 with the finest run stopped; model.hpp states the fixes.)
  double b_growth = 0.0;
  for (const Run& r : b) b_growth = std::max(b_growth, r.energy_growth);
  const std::string b_cause =
      "implementation: with subdivision the finest run " + (bf.ok() ? std::string("completed") : "stopped") +
      " with " + std::to_string(bf.touches) + " touches on ny " + std::to_string(bf.ny) +
      " (B0: " + std::to_string(b0.back().touches) + "), largest (E - E0) / E0 " + format_short(b_growth, 3) +
      "; the patch coupling (velocity boundary condition, hanging nodes, the approximations of Eq. 12 in the "
      "model) is ours: Paper B gives no algorithm";
  std::vector<repro::Claim> claims;
  struct Quantity {
    const char* key;
    const char* what;
    double Run::*err;
    bool (*ok)(const Run&, const Setup&);
    double tol;
    const char* why;  // the reason for the bound
    const char* control;
  };
  const Quantity quantities[] = {
      {"duration", "contact duration (first touch to the last clone separation) matches 2L/c", &Run::duration_err,
       duration_ok, kDurationTol, "between B0's errors at ny 16 and at ny 8 (listed by ny): it tells the finest mesh from the coarser", kTestDuration},
      {"stress", "mean contact stress (impulse / (duration W)) matches rho c v / 2", &Run::stress_err, stress_ok,
       kStressTol, "between B0's errors at ny 16 and at ny 8 (listed by ny): it tells the finest mesh from the coarser", kTestStress},
      {"plateau", "contact stress over the middle half of the pulse matches rho c v / 2", &Run::plateau_err,
       plateau_ok, kPlateauTol, "B0's plateau is within 0.6 % on every mesh: 2 % leaves room for the step-wise force",
       kTestPlateau},
      {"exchange", "the bars exchange their velocities (block averages after separation)", &Run::exchange_err,
       exchange_ok, kExchangeTol, "about 2.5 x B0's error at ny 16, about its error at ny 4", kTestExchange},
  };
  for (const Quantity& q : quantities) {
    for (const auto* pr : {&b0, &b}) {
      const std::vector<Run>& v = *pr;
      const Run& f = v.back();
      const std::string model = f.model;
      repro::Claim c{"B-8",
                     model + ": " + q.what + " on the finest mesh" + run_note,
                     theory,
                     "relative error " + mesh_text(v, q.err) + "; " + finest_text(f),
                     "|error| < " + pct(q.tol) + " on the finest mesh (" + q.why + ")",
                     q.ok(f, s)};
      c.key = model + "-" + q.key;
      c.control = repro::control_test(q.control);
      if (model == "B") repro::explain_fail(c, repro::Root::kUnexplained, b_cause);
      if (model == "B0") repro::explain_fail(c, repro::Root::kMeshDispersion,
                                             "the CST mesh's dispersion (error ~ h^(2/3)); a finer mesh passes");
      claims.push_back(c);
    }
    // Paper A at its dt and kn ratio. Its block has 6 DOF (one
    // constant-strain mode) and carries no wave: the penalty spring kn sets
    // the contact time and force (the kn series row), not the bar's
    // impedance rho c, so the wave's duration, stress and plateau cannot be
    // met by construction: measurements. The exchange of velocities is a
    // check (momentum and energy give it to any elastic contact).
    const bool wave = std::string(q.key) != "exchange";
    const std::string a_what = std::string("A (Paper A's 6-DOF blocks, penalty kn = E/100): ") + q.what + run_note;
    const std::string a_measured = "relative error " + pct(a0.*q.err) + " at dt " + format_short(a0.dt) + " s (duration " +
                                   format_short(a0.duration, 4) + " s, mean stress " + format_short(a0.mean_stress, 4) +
                                   " Pa, plateau " + format_short(a0.plateau_stress, 4) + " Pa, v " +
                                   format_short(a0.v0, 3) + " / " + format_short(a0.v1, 4) + " m/s)";
    repro::Claim c = wave ? repro::measurement("B-8", a_what, theory, a_measured,
                                               "no verdict: a 6-DOF block carries no wave, its contact follows kn "
                                               "(the kn series row)")
                          : repro::Claim{"B-8", a_what, theory, a_measured,
                                         "|error| < " + pct(q.tol) + " (the CDEM rows' criterion)", q.ok(a0, s)};
    c.key = std::string("A-") + q.key;
    if (!wave) c.control = repro::control_test(q.control);
    repro::explain_fail(c, repro::Root::kUnexplained,
                        "an elastic contact of two equal free blocks exchanges their velocities (momentum and "
                        "energy); not explained");
    claims.push_back(c);
  }
  // Energy never grows.
  for (const std::string model : {"B0", "B"}) {
    std::vector<Run> v = series(model, "mesh");
    const std::vector<Run> d = series(model, "dt");
    v.insert(v.end(), d.begin(), d.end());
    double worst = 0.0, lost_finest = 0.0;
    for (const Run& r : v) worst = std::max(worst, r.energy_growth);
    for (const Run& r : series(model, "mesh"))
      if (r.ok()) lost_finest = r.energy_end;
    repro::Claim c{"B-8", model + ": the energy never grows above its initial value" + run_note,
                   "elastic impact: energy kept; the clone's projection (Eq. 5) only removes it",
                   "largest (E - E0) / E0 over every step of the " + std::to_string(v.size()) +
                       " mesh and dt runs: " + format_short(worst, 3) + "; E_end / E0 - 1 of the finest completed mesh: " +
                       pct(lost_finest),
                   "(E - E0) / E0 < " + format_short(kEnergyGrowthTol) + " at every step of every run",
                   energy_never_grows(v)};
    c.key = model + "-energy";
    c.control = repro::control_test(kTestEnergy);
    if (model == "B") repro::explain_fail(c, repro::Root::kUnexplained, b_cause);
    claims.push_back(c);
  }
  // Measurements: observed order, dt refinement, work-precision, A's kn.
  {
    std::vector<Run> fine;  // the three finest completed B0 meshes
    for (const Run& r : b0)
      if (r.ok()) fine.push_back(r);
    if (fine.size() > 3) fine.erase(fine.begin(), fine.end() - 3);
    std::string ny_list;
    for (const Run& r : fine) ny_list += (ny_list.empty() ? "" : ", ") + std::to_string(r.ny);
    claims.push_back(repro::measurement(
        "B-8", "B0: observed order of convergence with the mesh (dt with h)" + run_note,
        "a dispersive second-order mesh: front width ~ (h^2 L)^(1/3), so errors ~ h^(2/3) asymptotically",
        "least-squares slope of log|error| on log h over ny " + ny_list + ": duration " +
            format_short(observed_order(fine, &Run::duration_err), 3) + ", mean stress " +
            format_short(observed_order(fine, &Run::stress_err), 3) + ", exchange " +
            format_short(observed_order(fine, &Run::exchange_err), 3),
        "the observed order (the plateau is within 1 % on every mesh, no order); the contact end is resolved to "
        "a step, which makes the duration's order noisy"));
    claims.back().key = "B0-order";
  }
  {
    std::string t;
    for (std::size_t i = 0; i < b.size() && i < b0.size(); ++i)
      t += (t.empty() ? "" : "; ") + std::string("ny ") + std::to_string(b[i].ny) + ": " +
           (b[i].ok() && b0[i].ok() ? "duration " + pct(b[i].duration_err) + " / " + pct(b0[i].duration_err) +
                                          ", mean stress " + pct(b[i].stress_err) + " / " + pct(b0[i].stress_err) +
                                          ", run " + format_short(b[i].wall, 2) + " / " + format_short(b0[i].wall, 2) +
                                          " s"
                                    : std::string("B ") + (b[i].ok() ? "ok" : "stopped") + ", B0 " +
                                          (b0[i].ok() ? "ok" : "stopped"));
    claims.push_back(repro::measurement(
        "B-8", "B against B0 on the same mesh: what the subdivision buys" + run_note,
        "Paper B Sect. 5: subdivision resolves the wave at the contact",
        "errors B / B0 by mesh: " + t, "no verdict: compares the two CDEM contacts mesh by mesh"));
    claims.back().key = "B-vs-B0";
  }
  {
    std::string t;
    for (const std::string model : {"B0", "B"}) {
      std::vector<Run> v;
      for (const Run& r : runs)
        if (r.model == model && r.ny == kDtSweepNy) v.push_back(r);
      t += (t.empty() ? "" : "; ") + model + " ny " + std::to_string(kDtSweepNy) + ":";
      for (const Run& r : v)
        t += std::string(&r == &v.front() ? "" : ";") + " dt " + format_short(r.dt, 3) + " s: " +
             (r.ok() ? "T " + pct(r.duration_err) + ", stress " + pct(r.stress_err) + ", exchange " +
                           pct(r.exchange_err) + ", " + format_short(r.wall, 2) + " s run"
                     : "stopped");
    }
    claims.push_back(repro::measurement(
        "B-8", "dt refinement on one mesh (c dt / h = 0.3, 0.15, 0.075)" + run_note, "1D theory", t,
        "the error is the mesh's (dispersion), not the time step's: a smaller dt costs more and does not converge to "
        "the theory"));
    claims.back().key = "dt-refinement";
  }
  {
    auto wp = [&](const std::vector<Run>& v) {
      std::string t;
      for (const Run& r : v)
        if (r.ok())
          t += (t.empty() ? "" : ", ") + format_short(r.wall, 2) + " s: " + pct(std::fabs(r.stress_err));
      return t;
    };
    claims.push_back(repro::measurement(
        "B-8", "error against run time (work-precision, figure B_bar_waves)" + run_note,
        "work-precision over mesh and dt refinement",
        "|mean stress error| by run time: B0 mesh series " + wp(b0) + "; B mesh series " + wp(b) +
            "; A dt series (kn = E/100) " + wp(a_dt) + ". A does not converge to the theory at any cost",
        "no verdict: the figure shows error against run time for every run"));
    claims.back().key = "work-precision";
  }
  {
    std::string t;
    for (const Run& r : a_kn)
      t += (t.empty() ? "" : "; ") + std::string("kn ") + format_short(r.kn / E, 2) + " E: " +
           (r.ok() ? "T " + format_short(r.duration * 1e3, 3) + " ms (" + pct(r.duration_err) + "), stress " +
                         pct(r.stress_err) + ", plateau " + pct(r.plateau_err) + ", exchange " + pct(r.exchange_err) +
                         ", E_end/E0 - 1 " + format_short(r.energy_end, 2)
                   : "stopped: " + r.stopped);
    claims.push_back(repro::measurement(
        "B-8", "A: the contact against its penalty kn (dt " + format_short(kDdaDt[3]) + " s)" + run_note,
        "1D theory has no contact parameter",
        t, "A's duration and stress follow kn; a kn that matches 2L/c does not give the rectangular pulse or the "
           "exchange (the block has no wave)"));
    claims.back().key = "A-kn";
  }
  return claims;
}

}  // namespace bars
