// Paper A against Paper B on the same collisions: the rows of A, B and B0 on
// one scene (touch, momentum, energy and its account, velocities, cost,
// contact duration) and the row of A's kn dependence.
#include <algorithm>
#include <cmath>
#include <limits>

#include "repro/B_7_contact_comparison/contact_comparison.hpp"

namespace compare {
namespace {

double best_of(const std::vector<Result>& v, double Result::*f) {
  double w = std::numeric_limits<double>::infinity();
  for (const Result& r : v) w = std::min(w, std::fabs(r.*f));
  return w;
}

}  // namespace

std::vector<Result> pick(const std::vector<Result>& results, const std::string& scene, const std::string& model) {
  std::vector<Result> v;
  for (const Result& r : results)
    if (r.scene == scene && r.model == model) v.push_back(r);
  return v;
}

std::vector<repro::Claim> scene_rows(const SceneDef& def, const std::vector<Result>& results,
                                     const std::map<std::string, History>& histories) {
  std::vector<repro::Claim> claims;
  const auto a = pick(results, def.name, "A"), b = pick(results, def.name, "B"), b0 = pick(results, def.name, "B0");
  const Result &a0 = a.front(), &bb = b.front(), &bc = b0.front();
  const std::string sec = "B-7 " + def.name;
  // Touch time. B: solved on the collision path (round-off). A: the first
  // step end with an overlap, so late by up to one step.
  const double b_touch = std::max(worst_of(b, &Result::touch_err), worst_of(b0, &Result::touch_err));
  claims.push_back({sec, "touch time: B (two-stage split) is exact, A (penalty) is late by up to one step",
                    "reference gap / speed = " + format_short(def.t_touch_exact, 8) + " s",
                    "B, B0: max |error| " + format_short(b_touch, 3) + " s over the dt sweep; A: " +
                        format_short(a0.touch_err, 3) + " s at dt " + format_short(a0.dt) + " ... " +
                        format_short(a.back().touch_err, 3) + " s at dt " + format_short(a.back().dt) + ". B BETTER",
                    "B < 1e-12 s; A <= dt", touch_ok(a, b, b0)});
  claims.back().control = kControlTouch;
  claims.push_back({sec, "momentum: both models conserve it through the impact", "conservation law",
                    "max |p - p0| / p0: A " + format_short(worst_of(a, &Result::mom_err), 3) + ", B " +
                        format_short(worst_of(b, &Result::mom_err), 3) + ", B0 " +
                        format_short(worst_of(b0, &Result::mom_err), 3) + ". TIE",
                    "< 1e-12 for all", momentum_ok(a, b, b0)});
  claims.back().control = kControlMomentum;
  claims.push_back(
      {sec, "energy: A's elastic penalty keeps it, B loses some (clone impact, patch remaps)",
       "an elastic collision keeps the energy",
       "E_end / E0 - 1 at the base dt: A " + format_short(a0.energy_err_end, 3) + " (max during contact " +
           format_short(a0.energy_err_max, 3) + "), B " + format_short(bb.energy_err_end, 3) + ", B0 " +
           format_short(bc.energy_err_end, 3) + "; smallest |error| over the sweep: A " +
           format_short(best_of(a, &Result::energy_err_end), 3) + ", B " +
           format_short(best_of(b, &Result::energy_err_end), 3) + ". A BETTER",
       "|A| < 1e-3 and |A| < |B|", energy_ok(a0, bb)});
  claims.back().control = repro::control_test(kTestEnergy);
  {
    const History& hb = histories.at(def.name + "/B");
    const History& hb0 = histories.at(def.name + "/B0");
    const dda::cdem::CdemEnergyAccount& e = hb.accounts.back();
    const dda::cdem::CdemEnergyAccount& e0 = hb0.accounts.back();
    auto pct = [&](double v, double e_init) { return format_short(100.0 * v / e_init, 3) + " %"; };
    claims.push_back(repro::measurement(
        sec, "where B's energy goes: the energy account per row (energy_history.csv)",
        "Paper B: Eq. 5 loss at the touch; Sect. 5 patches",
        "at the base dt, end of run, in % of E0: B touch " + pct(e.touch_loss, e.initial) + " (Eq. 5 " +
            pct(e.touch_loss_eq5, e.initial) + "), refine " + pct(e.refine_loss, e.initial) + ", deletion " +
            pct(e.deletion_loss, e.initial) + ", other " + pct(e.other, e.initial) + ", worst |other| / E0 " +
            format_short(worst_energy_remainder(hb.accounts), 3) + "; B0 touch " +
            pct(e0.touch_loss, e0.initial) + ", other " + pct(e0.other, e0.initial) + ", worst |other| / E0 " +
            format_short(worst_energy_remainder(hb0.accounts), 3),
        "the losses are measured by the model (touch: the projection's kinetic-energy drop; refine, deletion: the "
        "total-energy drop of the mesh change); 'other' is the integration's remainder"));
  }
  claims.push_back({sec,
                    "post-impact velocities: A exchanges them like rigid blocks, B leaves some energy in vibration",
                    "equal rigid blocks exchange velocities (v_i -> 0, v_j -> " + format_short(def.v0) + " m/s)",
                    "at the base dt: A v_i " + format_short(a0.v_i, 4) + ", v_j " + format_short(a0.v_j, 6) +
                        "; B v_i " + format_short(bb.v_i, 4) + ", v_j " + format_short(bb.v_j, 6) + "; B0 v_i " +
                        format_short(bc.v_i, 4) + ", v_j " + format_short(bc.v_j, 6) +
                        " m/s. A CLOSER to the rigid exchange; B's shortfall is "
                        "the energy kept in vibration and lost in the clone (a deformable-body effect, not an error "
                        "of the rigid reference alone)",
                    "|v_j - v0| / v0: A < 1e-3, B < 10 %", exchange_ok(a0, bb)});
  claims.back().control = kControlExchange;
  // dt convergence at equal work: which is better for the same run time. A
  // measurement: its former criterion (the smallest dt costs more wall time
  // than the base dt) holds by construction (8 to 16 times the steps) and
  // says nothing about the error; the figure shows the trade-off.
  claims.push_back(repro::measurement(
      sec, "error against run time over the dt sweep (figure B_comparison)", "work-precision",
      "run time at the base dt: A " + format_short(a0.wall, 3) + " s, B " + format_short(bb.wall, 3) + " s, B0 " +
          format_short(bc.wall, 3) + " s; at the smallest dt: A " + format_short(a.back().wall, 3) + " s, B " +
          format_short(b.back().wall, 3) + " s. v_j change from the base to the smallest dt: A " +
          format_short(a0.vj_err_self, 3) + ", B " + format_short(bb.vj_err_self, 3) +
          " (of v0). A is cheaper per run (6 DOF per "
          "block) and converges in v_j; B's touch time is exact at every cost",
      "no verdict: a smaller dt costs more by construction (more steps); the figure shows error against run "
      "time"));
  if (def.name == "squares") {
    const double t_ref = squares_wave_time();
    const double da = a0.contact_end - a0.contact_start, db = bb.contact_end - bb.contact_start;
    claims.push_back({sec, "contact duration: B's follows the elastic wave, A's follows kn",
                      "two elastic bars of length L: 2 L / c = " + format_short(t_ref, 4) + " s",
                      "A " + format_short(da, 4) + " s (kn = 10 MPa), B " + format_short(db, 4) + " s, B0 " +
                          format_short(bc.contact_end - bc.contact_start, 4) + " s. B BETTER",
                      "|B - 2L/c| < 25 %; A farther from 2L/c than B", squares_duration_ok(a0, bb, t_ref)});
    claims.back().control = repro::control_test(kTestSquaresDuration);
  } else {
    claims.push_back({sec, "contact duration on the prisms", "Paper B Figs. 14-15: about 7 ms (0.3333 to 0.3405 s)",
                      "A " + format_short(a0.contact_end - a0.contact_start, 4) + " s (kn = 0.4 GPa), B " +
                          format_short(bb.contact_end - bb.contact_start, 4) + " s, B0 " +
                          format_short(bc.contact_end - bc.contact_start, 4) + " s. The penalty contact lasts " +
                          format_short((a0.contact_end - a0.contact_start) / (bb.contact_end - bb.contact_start), 3) +
                          " times longer than the wave-governed one",
                      "B within 2 ms of 7.2 ms; A > 3 x B",
                      prisms_duration_ok(a0, bb)});
    claims.back().control = repro::control_test(kTestPrismsDuration);
    // The rebuilt prisms' size was chosen so that the clone separates at
    // about the paper's 0.3405 s: B's duration is fitted, not reproduced.
    claims.back().fitted = true;
  }
  return claims;
}

repro::Claim kn_row(const SceneDef& def, const std::vector<KnRun>& runs, const Result& b) {
  std::string text;
  for (const KnRun& k : runs) {
    const Result& r = k.result;
    text += (text.empty() ? "" : "; ") + std::string("kn ") + format_short(0.4e9 * k.factor, 2) + " Pa: contact " +
            format_short(r.contact_end - r.contact_start, 3) + " s, v_j " + format_short(r.v_j, 5) + " m/s";
  }
  repro::Claim c{"B-7 prisms", "A's collision depends on its penalty kn, B's has no contact parameter",
                    "Paper B Sect. 1: spring stiffness 'difficult to identify'",
                    "A at dt 5e-4 s: " + text + "; B: contact " + format_short(b.contact_end - b.contact_start, 3) +
                        " s with no spring. B BETTER (no parameter); A's outcome (exchange) is robust to kn, its "
                        "duration is not",
                    "A's duration falls with kn (x1 > x10 > x100) and every run exchanges v within 1 %",
                    kn_dependence_ok(runs, def.v0)};
  c.control = repro::control_test(kTestKn);
  return c;
}

}  // namespace compare
