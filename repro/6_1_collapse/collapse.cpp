// Paper A, Sect. 6.1 "Frictional collapse of a rock mass system" (Figs. 19-20).
//
// GEOMETRY RECONSTRUCTED: Fig. 19 (the model) is lost. The paper gives a
// 20 m x 50 m region cut by two persistent joint sets, dip 80 and 40 deg,
// spacing 1.5 and 2.5 m, and the block-to-boundary friction (35 deg); not
// the boundary. Ours (dda::paper::collapse): a 20 m wide, 50 m tall column
// standing on a long fixed floor against a fixed wall on its left, free on
// its right; both joint sets dip toward the free side (+x), so the 40 deg
// set daylights on the free face and is steeper than both joint friction
// angles. Slivers below 0.5 m^2 are dropped (reported), which keeps dt at
// ~0.55 of the a-priori critical step (Simulation::predicted_critical_step).
// rho 2700, E 2 GPa, nu 0.3, kn 2 GPa, kt 1e9 N/m, dt 1e-4 s, 7.5 s;
// joint friction 15 deg (case 1) and 30 deg (case 2), 35 deg to the boundary.
//
// Expected (paper, Fig. 20 at 2.5, 5.0 and 7.5 s): "A faster collapsing
// process and a larger runout mass were observed with lower friction angle."
// Measured per case: the front (largest x of any block vertex, and of any
// block centroid), the mass-weighted mean centroid drop, the largest centroid
// travel and the runout mass (share of the rock mass whose centroid has
// left the column's footprint x <= 20 m), every 0.05 s.
//
// Round-off sensitivity: the run is chaotic (blocks collide and part many
// times), so any change at round-off level, such as numbering the same
// blocks in another order (other summation orders in the per-block force
// sums), moves the front by metres. Each case is therefore rerun with its
// blocks numbered by centroid x and by centroid y; the claim row checks
// that the case ordering holds in all three numberings, and reports the
// spread.
//
// Options: --out DIR, --duration S (default: the scene's 7.5 s; shorter for
// quick checks), --threads N (contact loop, default 1; results do not
// depend on it), --case 1|2 (default both), --exact-rotation 1 (the blocks'
// rigid part turned exactly, dda::RotationUpdate::kExact, not the paper's
// linearised Eq. 1; the claims say so).
//
// Output under data/collapse/: summary.csv (one row per case), boundaries.csv,
// case<k>/series.csv (the measures vs time), case<k>/frames.csv (block
// polygons every 0.1 s) and case<k>/blocks.csv (centroid, velocity,
// displacement, rotation per block at the same times), vtk/case<k>_t<T>.vtk
// (legacy VTK polydata at 0, 2.5, 5.0, 7.5 s), renumbered.csv (the
// renumbered reruns' end state); claims/6_1_collapse.csv.
//
// The runs, measures and criteria are in collapse.hpp (library
// collapse_cases), shared with the rows' negative controls
// (controls.cpp beside it).
#include "repro/6_1_collapse/collapse.hpp"

#include <algorithm>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

#include "repro/common/common.hpp"
#include "repro/common/integrator_options.hpp"

using namespace collapse61;
using repro::format_short;

// The driver: its name in errors, its progress lines' prefix and its usage line.
const repro::DriverInfo kInfo = {
    "collapse", "6.1 collapse",
    "Paper A Sect. 6.1 (Figs. 19-20, geometry reconstructed): frictional collapse of a jointed rock mass, cases 1 "
    "and 2."};

// Its options besides --out.
const std::initializer_list<repro::OptionHelp> kOptions = {
    {"--duration", "S", "simulated seconds per case (default 7.5: the paper's)", false},
    repro::kThreadsOption,
    {"--case", "N", "1 or 2: that case only, without the renumbered reruns (default 0: both)", true},
    repro::kExactRotationOption};

namespace {

using Claims = std::vector<repro::Claim>;

// The generator's row and each case's stability and energy row.
void run_rows(const std::vector<CaseResult>& runs, double full, const std::string& run_note, Claims& claims) {
  const CaseResult& a = runs.front();
  repro::add_claim(
      claims,
      {"6.1",
       "joint-set generator: the 20 m x 50 m column cut by dips 80/40 deg, spacings 1.5/2.5 m, slivers < 0.5 m^2 "
       "dropped, runs below the stability limit",
       "Fig. 19 (lost): two persistent joint sets cut the region into a block system",
       std::to_string(a.blocks) + " blocks, " + std::to_string(a.dropped) + " slivers dropped (" +
           format_short(a.dropped_area, 3) + " m^2 = " + format_short(100.0 * a.dropped_area / a.region_area, 3) +
           " % of the region); H = " + format_short(a.h, 4) + " m; dt/dt_crit = " + format_short(a.dt_ratio0, 3) +
           " predicted at start, at most " + format_short(a.dt_ratio_max, 3) + " (case " + std::to_string(a.index) +
           ") from the live contacts during the run",
       "dt/dt_crit < 0.6 at start (against the predicted critical step, an a-priori bound) and < 1 throughout (live "
       "contacts); dropped area < 1 % of the region",
       generator_ok(a)},
      control(kControlGenerator), repro::Scope::kSuite);  // the suite's generator and time step
  for (const CaseResult& r : runs) {
    const EnergyBudget e = energy_budget(r);
    repro::add_claim(
        claims,
        {"6.1",
         "case " + std::to_string(r.index) + " (joint friction " + format_short(r.friction, 3) +
             " deg) runs to the end without a stability guard tripping; energy only dissipates" + run_note,
         "explicit DDA, dt 1e-4 s, " + format_short(full, 3) + " s",
         format_short(r.duration, 3) + " s in " + std::to_string(r.steps) + " steps, " + format_short(r.wall, 4) +
             " s wall (" + format_short(static_cast<double>(r.steps) / r.wall, 4) +
             " steps/s); potential energy released " + format_short(e.released, 4) +
             " J/m, total energy at end - start = " + format_short(e.change, 4) + " J/m, largest rise above start " +
             format_short(e.rise, 3) + " J/m" + (r.stopped.empty() ? "" : "; STOPPED by a guard: " + r.stopped),
         "largest rise < 1 % of the released potential energy (Verlet conserves energy to O(dt^2); friction removes "
         "it)",
         e.pass},
        control(kControlStable), repro::Scope::kSuite);  // the suite's guards
  }
}

// "a vs b" to `digits` significant digits: case 1's value beside case 2's.
std::string vs(double a, double b, int digits) { return format_short(a, digits) + " vs " + format_short(b, digits); }

// The paper's statement at two of Fig. 20's snapshots: faster collapse and
// further runout with the lower friction.
void paper_rows(const CaseResult& c1, const CaseResult& c2, double duration, const std::string& run_note,
                Claims& claims) {
  // The paper's statement both rows test, at two of Fig. 20's snapshots.
  const std::string kLowerFrictionQuote =
      "'A faster collapsing process and a larger runout mass were observed with lower friction angle' "
      "(Sect. 6.1, Fig. 20 ";
  // Faster collapse: the mean centroid drop and the front at the first
  // snapshot time (2.5 s), and the whole front history.
  const Sample& p1 = c1.at(faster_time(duration));
  const Sample& p2 = c2.at(faster_time(duration));
  const FrontLead lead = front_lead(c1, c2);
  std::string fronts;
  for (double t : kPaperTimes) {
    if (t > duration + 1e-9) continue;
    fronts += (fronts.empty() ? "" : "; ") + std::string("t = ") + time_tag(t) +
              " s: " + vs(c1.at(t).front_x, c2.at(t).front_x, 4) + " m";
  }
  repro::add_claim(
      claims,
      {"6.1", "lower joint friction collapses faster (case 1: 15 deg vs case 2: 30 deg)" + run_note,
       kLowerFrictionQuote + "a/b at 2.5 s)",
       "at t = " + time_tag(p1.t) + " s mean centroid drop " + vs(p1.mean_drop, p2.mean_drop, 3) + " m, front " +
           vs(p1.front_x, p2.front_x, 4) + " m; case 1's front ahead or level in " + std::to_string(lead.ahead) +
           " of " + std::to_string(lead.compared) + " samples after 0.5 s (" + fronts + ")",
       "case 1's mean drop > 1.1 x case 2's and its front > case 2's + 2.5 m at 2.5 s", collapses_faster(p1, p2)},
      control(kControlFaster), repro::Scope::kPaper);
  const Sample& e1 = c1.at(duration);
  const Sample& e2 = c2.at(duration);
  repro::add_claim(claims,
                   {"6.1", "lower joint friction runs out further and with a larger runout mass" + run_note,
                    kLowerFrictionQuote + "e/f at 7.5 s)",
                    "at t = " + time_tag(e1.t) + " s: front (farthest vertex) " + vs(e1.front_x, e2.front_x, 4) +
                        " m, farthest centroid " + vs(e1.front_cx, e2.front_cx, 4) + " m, largest centroid travel " +
                        vs(e1.max_travel, e2.max_travel, 4) + " m, runout mass (centroid beyond x = 20 m) " +
                        format_short(100.0 * e1.runout_mass, 3) + " % vs " + format_short(100.0 * e2.runout_mass, 3) +
                        " %, mean drop " + vs(e1.mean_drop, e2.mean_drop, 3) + " m",
                    "case 1's front > case 2's + 2.5 m (one joint spacing) and its runout mass > case 2's",
                    runs_out_further(e1, e2)},
                   control(kControlRunout), repro::Scope::kPaper);
}

// Round-off sensitivity: the runout ordering in every numbering.
void renumbered_row(const Ends& ends, const std::string& run_note, Claims& claims) {
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  std::string fronts[2];
  for (const auto& end : ends)
    for (int c = 0; c < 2; ++c) {
      lo[c] = std::min(lo[c], end[c].front_x);
      hi[c] = std::max(hi[c], end[c].front_x);
      fronts[c] += (fronts[c].empty() ? "" : ", ") + format_short(end[c].front_x, 4) + " m (" +
                   format_short(100.0 * end[c].runout_mass, 3) + " %)";
    }
  repro::add_claim(
      claims,
      {"6.1",
       "the runout ordering survives round-off-level changes: each case rerun with its blocks numbered by "
       "centroid x and by centroid y (same blocks; other summation orders)" +
           run_note,
       "(not discussed in the paper: a chaotic granular run, one realisation per case)",
       "front at the end (runout mass) for " + std::string(kNumberings[0]) + " / " + kNumberings[1] + " / " +
           kNumberings[2] + " numbering: case 1 " + fronts[0] + "; case 2 " + fronts[1] + "; spread of the front " +
           format_short(hi[0] - lo[0], 3) + " m (case 1), " + format_short(hi[1] - lo[1], 3) + " m (case 2)",
       "in every numbering case 1's front > case 2's + 2.5 m and its runout mass > case 2's", ordering_survives(ends)},
      control(kControlRenumbered), repro::Scope::kExtension);
}

// The run: what main's driver_main calls once the command line is checked.
int reproduce(const repro::Driver& d) {
  const double full = dda::paper::collapse(kFrictions[0]).scene.duration;
  const double duration = d.number("--duration", full);
  const int threads = d.whole("--threads", 1);
  const int only = d.whole("--case", 0);
  const dda::RotationUpdate rotation = repro::rotation_option(d.argc, d.argv);
  if (!(duration > 0.0)) throw std::invalid_argument("--duration must be positive");
  if (only < 0 || only > 2) throw std::invalid_argument("--case must be 1 or 2");
  const std::string dir = d.out + "/data/collapse";

  std::vector<CaseResult> runs;
  for (int k = 1; k <= 2; ++k)
    if (only == 0 || only == k) runs.push_back(run_case(k, scene(kFrictions[k - 1], duration, rotation), threads, dir));
  write_summary(dir, runs);
  write_boundaries(dir);

  // Round-off sensitivity: both cases again with the blocks renumbered.
  const bool renumber = runs.size() == 2;
  Ends ends;
  if (renumber) {
    for (int c = 0; c < 2; ++c) ends[0][c] = runs[static_cast<std::size_t>(c)].series.back();
    for (int axis = 0; axis < 2; ++axis)
      for (int c = 0; c < 2; ++c)
        ends[axis + 1][c] = rerun_renumbered(c + 1, scene(kFrictions[c], duration, rotation), threads, axis);
    write_renumbered(dir, ends);
  }

  const bool short_run = duration < full - 1e-9;
  const std::string run_note = (short_run ? " [SHORT RUN: --duration " + format_short(duration, 3) + " s]" : "") +
                               (rotation == dda::RotationUpdate::kExact ? repro::kExactRotationNote : "");
  Claims claims;
  run_rows(runs, full, run_note, claims);
  if (runs.size() == 2) paper_rows(runs[0], runs[1], duration, run_note, claims);
  if (renumber) renumbered_row(ends, run_note, claims);
  repro::write_claims(repro::claims_path(d.out, "6_1_collapse"), claims);
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return repro::driver_main(argc, argv, kInfo, kOptions, reproduce); }
