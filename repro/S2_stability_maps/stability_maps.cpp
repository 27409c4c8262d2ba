// Stability maps and a check of the critical time step.
//
// 1. dt_crit check. The solver's critical_time_step() (current contacts)
//    and predicted_critical_step() (a priori) are compared with an
//    independent value: 2 / omega_max of the linearised system (stiffness by
//    central differences of the library's contact force, DDA mass matrices;
//    repro/S_common), and with the empirical limit found by bisection on dt
//    for a block resting at its static penetration, nudged by 1e-9 m/s and
//    1e-9 rad/s so that every mode is excited (unstable: the
//    mechanical energy grows 10-fold over 20000 steps, a resting contact
//    opens, or a guard stops the run). Expected: empirical = linearised;
//    the solver's values at or below it (a bound). The "old" column is a simpler per-block estimate
//    (kn L 2 / H_i on k/m + k r^2/I, max with the strain modes).
// 2. Stability maps: kn 1e6 .. 1e12 Pa (half decades) x dt 1e-6 .. 1e-2 s
//    (quarter decades), Table 4/5 material (rho 2000, E 1 GPa, nu 0.25),
//    deformable blocks, frictionless. Shortened runs, the collision window
//    only: (a) Sect. 4.1's two squares, A at 1 m/s, starting 1 mm apart;
//    (b) Sect. 5.1's bouncing block, case 1 (B 0.1 m high), A starting 1 mm
//    above B at the 3.13 m/s it reaches after its 0.5 m fall, gravity on,
//    with the unified H and with the inscribed-radius H. Run length: 2 ms +
//    4 contact half-periods pi/omega (omega from the flat contact on the
//    relative mass), at most 0.4 s (written per run). Each run is
//    classified (s2::map_run, maps.hpp): blow-up (the state diverges: a
//    non-finite state, an area collapse, or the step-motion guard after the
//    energy grew; a stop by the energy-budget guard alone is an accuracy
//    stop, so the cell is rerun with that guard off and classified by that
//    run), flip-through (the penetration guard, the step-motion guard before
//    the energy grew, or the centroids ending in the wrong order), energy
//    growth > 1 % of the impact energy at the end, else stable. Expected:
//    stable below min(contact limit ~ kn^-1/2, strain limit 7e-4 s); the
//    solver's prediction at or below the empirical boundary; above it,
//    short contacts (a few steps) can end in growth without blowing up.
//
// Output: data/stability_maps/dt_crit_check.csv, map_<name>.csv,
// boundary_<name>.csv; claims/S2_stability_maps.csv.
#include <string>
#include <vector>

#include "repro/S2_stability_maps/maps.hpp"
#include "repro/S2_stability_maps/resting.hpp"
#include "repro/S2_stability_maps/studies.hpp"
#include "repro/S_common/stability.hpp"
#include "repro/common/common.hpp"
#include "repro/common/driver.hpp"

namespace {
using repro::format_short;
using repro::stab::RunClass;
using namespace s2;

// The two rows of the dt_crit check.
void dt_crit_rows(const DtCritSummary& d, std::vector<repro::Claim>& claims) {
  claims.push_back({"S2 / dt_crit", "the linearised dt_crit (independent check) is the empirical stability limit "
                                    "of a resting contact",
                    "velocity Verlet: stable iff dt < 2 / omega_max",
                    "largest |empirical / linearised - 1| over " + std::to_string(d.cases) +
                        " cases (kn 1e6..1e9, rigid and deformable, unified and inscribed H, one and two free "
                        "blocks) = " + format_short(d.worst_emp, 3),
                    "< " + format_short(kEmpiricalTolerance), linearised_is_empirical(d.worst_emp)});
  claims.back().control = repro::control_test(kControlEmpirical);
  claims.push_back({"S2 / dt_crit", "the solver's critical time step never exceeds the linearised limit",
                    "a critical step must be safe",
                    "current / linearised in [" + format_short(d.best_cur, 3) + ", " + format_short(d.worst_cur, 3) +
                        "]; predicted / linearised <= " + format_short(d.worst_pred, 3) +
                        "; the per-block estimate 2 kn L_max / H reached " + format_short(d.worst_old, 3),
                    "current and predicted <= 1.0", solver_steps_are_safe(d.worst_cur, d.worst_pred)});
  claims.back().control = repro::control_test(kControlSafe);
}

// The two rows of one map; returns its class counts in words.
std::string map_rows(const MapScene& m, const MapSummary& s, std::vector<repro::Claim>& claims) {
  auto counts = [](const int* n) {
    return std::to_string(n[0]) + " stable, " + std::to_string(n[1]) + " energy growth, " + std::to_string(n[2]) +
           " flip-through, " + std::to_string(n[3]) + " blow-up";
  };
  std::string flip_note;
  for (double kn : s.flip_below) flip_note += (flip_note.empty() ? "" : ", ") + format_short(kn);
  const std::string summary = "at dt <= predicted: " + counts(s.below) + "; above: " + counts(s.above);
  const double paper_kn = m.scene.contact.kn;
  const std::string threshold =
      s.all_through_kn > 0.0
          ? "every dt <= predicted passes through at kn <= " + format_short(s.all_through_kn, 4) +
                " Pa: the paper's kn " + format_short(paper_kn, 3) + " Pa is " +
                format_short(paper_kn / s.all_through_kn, 3) + " times that"
          : "no kn of the map passes through at every dt (the paper's kn " + format_short(paper_kn, 3) + " Pa)";
  claims.push_back({"S2 / map", m.title + ": no blow-up and no pass-through at dt <= the predicted dt_crit",
                    "not in the papers: stability of stiff cases against the predicted critical step",
                    threshold + "; " + summary + "; first blow-up at " + format_short(s.min_blowup_ratio, 3) + " to " +
                        format_short(s.max_blowup_ratio, 3) +
                        " x predicted over kn; per-block estimate 2 kn L_max / H: " +
                        std::to_string(s.old_blowups_below) + " blow-ups at or below it",
                    "0 blow-ups and 0 flip-throughs at dt <= predicted", s.failures_below == 0});
  claims.back().key = "map-" + m.name + "-no-failure-below-predicted";
  claims.back().control = repro::control_test(kControlFailBelow);
  const bool blowup_below = s.below[static_cast<int>(RunClass::kBlowUp)] > 0;
  repro::explain_fail(claims.back(), blowup_below ? repro::Root::kUnexplained : repro::Root::kThinBlock,
                      blowup_below
                          ? "the solver's a-priori critical step is not a bound for this scene: a run blows up "
                            "below it; not explained"
                          : std::to_string(s.below[static_cast<int>(RunClass::kFlipThrough)]) +
                                " cells at dt <= predicted pass through: below some kn the penalty cannot stop the "
                                "block within the thin block's half thickness at any dt; " + threshold);
  claims.push_back({"S2 / map", m.title + ": energy created by under-resolved impacts below the prediction",
                    "not discussed in the paper",
                    "smallest dt / predicted of an 'energy growth > 1 %' run: " + format_short(s.growth_ratio, 3) +
                        (flip_note.empty() ? std::string("")
                                           : "; flip-through at dt <= predicted (penetration deeper than half "
                                             "the thin block, not a time-step effect) for kn = " + flip_note + " Pa"),
                    "information: an accuracy limit (few steps per contact), not a stability limit", false,
                    repro::Kind::kMeasurement});
  return summary;
}

}  // namespace

int main(int argc, char** argv) {
  return repro::driver_main(
      argc, argv, {"stability_maps", "S2 stability maps", "Stability maps and a check of the critical time step."}, {},
      [](const repro::Driver& d) {
        const std::string dir = d.out + "/data/stability_maps";
        std::vector<repro::Claim> claims;

        // 1. dt_crit check: resting contacts, linearised vs empirical vs the solver.
        dt_crit_rows(dt_crit_check(dir), claims);
        d.progress("dt_crit check done");

        // 2. Maps: the two squares, the bouncing block with each H rule.
        for (const MapScene& m : {two_squares_map(), bouncing_map(dda::HRule::kMinMaxEdge),
                                  bouncing_map(dda::HRule::kInscribedRadius)})
          d.progress(m.title + ": " + map_rows(m, map_study(m, dir), claims));
        repro::default_scope(claims, repro::Scope::kSuite);  // the suite's own stability study, every row
        repro::write_claims(repro::claims_path(d.out, "S2_stability_maps"), claims);
        d.progress("done");
        return 0;
      });
}
