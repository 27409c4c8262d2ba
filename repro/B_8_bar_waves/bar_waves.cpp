// Waves against theory (beyond both papers; Paper B
// Sect. 5's local subdivision exists to resolve the elastic waves of an
// impact): two equal elastic bars head on, against 1D bar theory.
//
// Scene: two bars L = 1 m long, W = 0.2 m wide (L / W = 5), 10 mm apart;
// the striker at v = 1 m/s along +x onto the target at rest. Material: Paper
// A Sect. 4.1's rho = 2000 kg/m3, E = 1 GPa, with nu = 0.
// What the CST elements model: PLANE STRESS (dda::elastic_matrix, used by
// lib/cdem/src/model_mesh.cpp: D = E / (1 - nu^2) [1 nu 0; nu 1 0; 0 0
// (1 - nu) / 2]); the 1D bar speed of a thin plane-stress bar is
// c = sqrt(E / rho). With nu = 0 (the Material allows it) a uniaxial stress
// state is exact in the continuum, so 1D theory holds without lateral
// (Poisson) dispersion, and plane stress and plane strain agree.
// 1D theory (equal bars, one at v onto one at rest): contact from gap / v
// for 2 L / c = 2.83 ms (c = 707 m/s), a rectangular contact-stress pulse of
// rho c v / 2 = 0.707 MPa, and then the bars exchange their velocities
// (striker 0, target v), energy kept.
//
// Models:
//   B  : CDEM (Paper B), clone node + local subdivision (the in-place
//        refinement, SubdivisionMode::kInPlace, set explicitly: a study,
//        not a paper figure, so its outputs do not follow the default);
//   B0 : CDEM, clone node without subdivision;
//   A  : Paper A's 6-DOF DDA blocks with the penalty contact (kn = E / 100,
//        Paper A Sect. 4.1's ratio; also a kn sweep).
// Each bar in B / B0 is a structured mesh of ny x 5 ny square cells (two CST
// elements each, dda::cdem::mesh_rectangle), ny = 1 ... 16, dt = 0.3 h / c
// (mesh series), and on ny = 4 dt halved twice (dt series). A: dt from 1e-4
// s halved three times at kn = E / 100 (dt series), and kn = E / 100 ... 10 E
// at dt = 1.25e-5 s (kn series).
// Per run: contact duration (first touch to the last clone separation; A:
// first to last step with an overlap), mean contact stress (impulse on the
// target / (duration W)), the plateau (mean contact stress over the middle
// half of 2 L / c), the block-average velocities after separation, energy
// (end and largest growth), wall time.
// Expected: the CST mesh is dispersive, so B / B0 converge to the theory
// slowly (asymptotically as h^(2/3): the front's width grows as
// (h^2 L)^(1/3)); the plateau is right on every mesh. A's blocks have one strain mode and no wave: its contact
// lasts as long as kn makes it (17 ms at E / 100), its stress is kn's, not
// rho c v / 2, but it exchanges the velocities as rigid blocks do.
//
// Output under <out>/data/B_8_bar_waves/: runs.csv (one row per run, with
// the wall time; a stopped run has its error and no values), traces.csv
// (contact stress against time after the touch for one run of each model);
// claims in <out>/claims/B_8_bar_waves.csv.
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "repro/B_8_bar_waves/bar_waves.hpp"
#include "repro/common/common.hpp"
#include "repro/common/options.hpp"

namespace {
using namespace bars;
const char* kDriver = "B_8_bar_waves";
constexpr int kMeshNy[] = {1, 2, 4, 8, 16};  // elements across the width: h = 200 ... 12.5 mm
constexpr int kDtSweepNy = 4;                // the mesh of the dt series
constexpr double kDtSweepCourant[] = {0.15, 0.075};  // c dt / h below the mesh series' 0.3
constexpr double kDdaDt[] = {1e-4, 5e-5, 2.5e-5, 1.25e-5};  // s: Paper A Sect. 4.1's 1e-4 s, halved
constexpr double kKnFactors[] = {0.01, 0.1, 1.0, 10.0};     // kn / E; 0.01: Paper A Sect. 4.1's ratio

// A run timed again when it is too short to time once: the mean wall time
// of repeats until 0.2 s have passed (at most 20 runs).
template <class F>
Run timed(F run) {
  Run r = run();
  if (r.wall >= 0.05) return r;
  double total = r.wall;
  int n = 1;
  while (n < 20 && total < 0.2) {
    total += run().wall;
    ++n;
  }
  r.wall = total / n;
  return r;
}

std::string num(const Run& r, double v) { return r.ok() ? repro::format_full(v) : std::string(); }

std::string pct(double x) { return format_short(100.0 * x, 3) + " %"; }

}  // namespace

int main(int argc, char** argv) try {
  repro::check_command_line(
      argc, argv, "Beyond both papers: two elastic bars head on against 1D wave theory (CDEM B, B0; Paper A's DDA).",
      {{"--max-ny", "N", "finest CDEM mesh: elements across the width (default 16; powers of 2 from 1)", true}});
  const int max_ny = repro::option_int(argc, argv, "--max-ny", 16);
  if (max_ny < 1) throw std::invalid_argument("--max-ny must be >= 1");
  const std::string run_note = max_ny == 16 ? "" : " [NOT THE DEFAULT: --max-ny " + std::to_string(max_ny) + "]";
  const std::string out = repro::out_dir(argc, argv);
  const repro::Progress progress("B-8 bar waves");
  const std::string dir = out + "/data/" + kDriver + "/";
  const Setup s;
  const double E = s.material.young;

  std::vector<Run> runs;
  std::map<std::string, Trace> traces;
  auto note = [&](const Run& r) {
    progress(r.model + " " + r.series + " ny " + std::to_string(r.ny) + " dt " + format_short(r.dt) + " kn " +
             format_short(r.kn) + ": " + format_short(r.wall, 3) + " s, " +
             (r.ok() ? "T " + pct(r.duration_err) + ", stress " + pct(r.stress_err) + ", plateau " +
                           pct(r.plateau_err) + ", exchange " + pct(r.exchange_err) + ", dE " +
                           format_short(r.energy_end, 3) + ", growth " + format_short(r.energy_growth, 3)
                     : "STOPPED: " + r.stopped));
  };
  // Mesh series, dt = kCourant h / c; the trace of each CDEM model on its
  // finest completed mesh (kept as the series goes).
  for (const bool sub : {false, true})
    for (int ny : kMeshNy) {
      if (ny > max_ny) continue;
      Trace tr;
      Run r = timed([&] {
        tr = Trace{};
        return run_cdem(s, ny, 0.0, sub, &tr);
      });
      r.series = "mesh";
      if (r.ok()) traces[r.model] = tr;
      runs.push_back(r);
      note(r);
    }
  // dt series on one mesh (its first point is the mesh series' run).
  for (const bool sub : {false, true})
    for (double courant : kDtSweepCourant) {
      if (kDtSweepNy > max_ny) continue;
      const double dt = courant * (s.width / kDtSweepNy) / s.wave_speed();
      Run r = timed([&] { return run_cdem(s, kDtSweepNy, dt, sub); });
      r.series = "dt";
      runs.push_back(r);
      note(r);
    }
  // Paper A: dt series at kn = E / 100, kn series at the smallest dt.
  for (double dt : kDdaDt) {
    Trace tr;
    Run r = timed([&] {
      tr = Trace{};
      return run_dda(s, dt, 0.01 * E, &tr);
    });
    r.series = "dt";
    if (dt == kDdaDt[2]) traces["A"] = tr;
    runs.push_back(r);
    note(r);
  }
  for (double f : kKnFactors) {
    Trace tr;
    Run r = timed([&] {
      tr = Trace{};
      return run_dda(s, kDdaDt[3], f * E, &tr);
    });
    r.series = "kn";
    if (f == 1.0) traces["A kn=E"] = tr;
    runs.push_back(r);
    note(r);
  }

  repro::CsvWriter csv(
      dir + "runs.csv",
      {"model", "series", "ny", "h", "dt", "kn", "wall_s", "steps", "critical_dt", "status", "t_touch", "t_end",
       "duration", "duration_err", "mean_stress", "stress_err", "plateau_stress", "plateau_err", "v0", "v1",
       "exchange_err", "energy_end", "energy_growth", "momentum_err", "touches", "separations"},
      {"two bars L " + format_short(s.length) + " m x W " + format_short(s.width) + " m, v " + format_short(s.speed) +
       " m/s onto a bar at rest; rho " + format_short(s.material.density) + ", E " + format_short(E) +
       " Pa, nu 0 (plane stress); 2L/c " + repro::format_full(s.contact_time()) + " s, rho c v/2 " +
       repro::format_full(s.contact_stress()) + " Pa. B: clone + subdivision; B0: clone, no subdivision; A: "
       "Paper A DDA penalty. errors signed, relative to 1D theory; status 'stopped: ...' has no values. "
       "wall_s: mean of repeated runs when one is shorter than 0.05 s",
       // the mode cdem_scene() sets for B (the figure labels B's curves with it)
       "subdivision mode of B: in-place refinement (beyond the paper)"});
  for (const Run& r : runs)
    csv.row(std::vector<std::string>{
        r.model, r.series, std::to_string(r.ny), repro::format_full(r.h), repro::format_full(r.dt),
        repro::format_full(r.kn), repro::format_full(r.wall), std::to_string(r.steps), repro::format_full(r.critical_dt),
        r.ok() ? "ok" : "stopped: " + r.stopped, num(r, r.t_touch), num(r, r.t_end), num(r, r.duration),
        num(r, r.duration_err), num(r, r.mean_stress), num(r, r.stress_err), num(r, r.plateau_stress),
        num(r, r.plateau_err), num(r, r.v0), num(r, r.v1), num(r, r.exchange_err), num(r, r.energy_end),
        repro::format_full(r.energy_growth), repro::format_full(r.momentum_err), std::to_string(r.touches),
        std::to_string(r.separations)});
  csv.commit();
  repro::CsvWriter tcsv(dir + "traces.csv", {"run", "time_after_touch", "stress"},
                        {"contact stress (the target's momentum change over each step / W, Pa) against the time "
                         "after the first touch; B, B0: finest completed mesh of the mesh series; A: kn = E/100 and "
                         "kn = E"});
  for (const auto& [name, tr] : traces) {
    const Run* src = nullptr;
    for (const Run& r : runs)
      if (r.ok() && (name == "A kn=E" ? (r.series == "kn" && r.kn == E)
                                       : name == "A" ? (r.model == "A" && r.series == "dt" && r.dt == kDdaDt[2])
                                                     : (r.model == name && r.series == "mesh")))
        src = &r;
    if (!src) continue;
    const std::string label = name == "A" ? "A kn=E/100 dt=" + format_short(src->dt)
                              : name == "A kn=E" ? "A kn=E dt=" + format_short(src->dt)
                                                 : name + " ny=" + std::to_string(src->ny);
    for (std::size_t k = 0; k < tr.t.size(); ++k)
      tcsv.row(std::vector<std::string>{label, repro::format_full(tr.t[k] - src->t_touch),
                                        repro::format_full(tr.stress[k])});
  }
  tcsv.commit();

  // ----- claims -------------------------------------------------------------
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
  repro::default_scope(claims, repro::Scope::kExtension);  // beyond both papers: 1D wave theory, every row
  repro::write_claims(repro::claims_path(out, kDriver), claims);
  progress("done");
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "B_8_bar_waves: error: %s\n", e.what());
  return 1;
}
