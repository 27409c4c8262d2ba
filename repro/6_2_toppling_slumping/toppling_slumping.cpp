// Paper A, Sect. 6.2 "Rock toppling and rock slumping" (Figs. 21-22).
//
// GEOMETRY RECONSTRUCTED: Fig. 21 (the model) is lost. The paper: valley
// slopes cut by one joint set (dip 75 deg, spacing 3 m) on a sliding base
// inclined at 30 deg; base friction 32 deg (each slope alone would stand as
// one block), joint friction 22 deg. Ours (dda::paper::toppling_slumping):
// a valley with a flat floor |x| < 8 m and two fixed sliding bases dipping
// 30 deg toward the axis, each carrying a 24 m high rock wedge with a
// horizontal top. One joint set of fixed orientation (dip 75 deg toward +x)
// cuts both wedges, so on the LEFT slope the joints dip toward the valley
// (slabs leaning back into the hill) and on the RIGHT slope they dip into
// the hill (columns leaning 15 deg out over the valley).
// rho 2700, E 2 GPa, nu 0.3, kn 0.5 GPa, kt 1e8 N/m, dt 1e-4 s, 3.5 s.
//
// Expected (paper, Fig. 22 at 3.5 s): "The left part will fail in slumping
// pattern, while the right part will fail with toppling pattern."
// Measured per side, mass-weighted over its blocks: the rotation toward the
// valley ("outward": clockwise on the left, counter-clockwise on the right),
// the slip of each block's base (the midpoint of the edge that lay on the
// sliding base at t = 0) along the base, down-dip, and the centroid
// displacement along the base. A block topples when it rotates outward about
// its toe: rotation, not base slip, carries its top; it slumps when it
// slides down the base with small rotation (see the claims for the numbers).
//
// Options: --out DIR, --duration S (default: the scene's 3.5 s), --threads N
// (default 1), --return-mapping 1 (all runs with the elastic-plastic
// friction update dda::FrictionUpdate::kReturnMapping instead of the
// paper's Eq. 26; the claims say so), --exact-rotation 1 (all runs with
// dda::RotationUpdate::kExact instead of the linearised Eq. 1; likewise).
//
// Controls (claims only): the same model with the joints locked (friction
// 80 deg), and each slope as ONE block -- the paper's premise that each
// slope alone is stable on its base. Beside the paper-method FAILs, the
// same runs with the options beyond the paper (rows "6.2 (option)"): the
// friction start-up (settled with sticking contacts, Scene::damping) for the
// premise, and the start-up with the return mapping for the mechanism.
// Expected: both pass.
//
// Output under data/toppling_slumping/: series.csv (per-side measures every
// 0.01 s), frames.csv (polygons every 0.05 s), blocks.csv (per-block state at
// the same times), sides.csv (block, side, length along the joints),
// boundaries.csv, summary.csv (model and controls), vtk/t<T>.vtk;
// claims/6_2_toppling_slumping.csv.
#include "repro/6_2_toppling_slumping/toppling_slumping.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

#include "dda/rock_scenes.hpp"
#include "dda/simulation.hpp"
#include "repro/6_2_toppling_slumping/rows.hpp"
#include "repro/common/common.hpp"
#include "repro/common/integrator_options.hpp"
#include "repro/common/rock_run.hpp"
#include "repro/common/vtk_output.hpp"

// The driver: its name in errors, its progress lines' prefix and its usage line.
const repro::DriverInfo kInfo = {
    "toppling_slumping", "6.2 toppling/slumping",
    "Paper A Sect. 6.2 (Figs. 21-22, geometry reconstructed): toppling and slumping of a jointed valley slope."};

// Its options besides --out.
const std::initializer_list<repro::OptionHelp> kOptions = {
    {"--duration", "S", "simulated seconds (default 3.5: the paper's)", false},
    repro::kThreadsOption,
    {"--return-mapping", "0|1", "1: return-mapping friction update instead of the paper's (default 0)", true},
    repro::kExactRotationOption};

namespace {
using namespace topple;
constexpr double kSeriesEvery = 0.01;  // s
constexpr double kFrameEvery = 0.05;   // s

// A frame time in a file name or caption, 0.1 s resolution.
std::string time_tag(double t) { return repro::format_fixed(t, 1); }

// One row of series.csv: both sides' measures, the energies and the step's
// margin at one moment.
struct SeriesRow {
  double time;
  SideState left, right;
  double kinetic, total, dt_ratio;
};
std::vector<repro::Column<SeriesRow>> series_columns() {
  std::vector<repro::Column<SeriesRow>> columns = {{"time", [](const SeriesRow& r) { return r.time; }}};
  const std::vector<repro::Column<SideState>> side = {repro::field("outward_rotation", &SideState::outward_rotation),
                                                      repro::field("abs_rotation", &SideState::abs_rotation),
                                                      repro::field("base_slip", &SideState::base_slip),
                                                      repro::field("centroid_downdip", &SideState::centroid_downdip),
                                                      repro::field("rotation_travel", &SideState::rotation_travel),
                                                      repro::field("toppled_share", &SideState::toppled_share)};
  for (SideState SeriesRow::*which : {&SeriesRow::left, &SeriesRow::right})
    for (const repro::Column<SideState>& c : side)
      columns.push_back({(which == &SeriesRow::left ? "left_" : "right_") + c.name,
                         [which, cell = c.cell](const SeriesRow& r) { return cell(r.*which); }});
  columns.push_back({"E_kinetic", [](const SeriesRow& r) { return r.kinetic; }});
  columns.push_back({"E_total", [](const SeriesRow& r) { return r.total; }});
  columns.push_back({"dt_over_dt_crit", [](const SeriesRow& r) { return r.dt_ratio; }});
  return columns;
}

// The model's run to `duration`: series.csv, frames.csv, blocks.csv, vtk/
// under `dir`; what it measured.
ModelRun run_model(const repro::Driver& d, const dda::paper::TopplingSlumping& ts, double duration, int threads,
                   const std::string& dir, const std::string& note) {
  ModelRun m;
  m.ts = &ts;
  m.duration = duration;
  m.exact_rotation = ts.scene.rotation_update == dda::RotationUpdate::kExact;
  dda::Simulation sim(ts.scene);
  sim.set_threads(threads);
  m.blocks = sim.scene_block_count();
  m.dt_ratio0 = sim.dt() / sim.predicted_critical_step();
  m.h = sim.potential_length(0);
  m.dt = sim.dt();
  d.progress(std::to_string(m.blocks) + " blocks (" + std::to_string(ts.dropped) + " slivers dropped, " +
             format_short(ts.dropped_area, 3) + " m^2), H = " + format_short(m.h, 4) +
             " m, dt/dt_crit = " + format_short(m.dt_ratio0, 3) + " at start");
  const Tracker tracker(sim, ts, ts.side);
  tracker.write_sides(dir + "/sides.csv", note);
  repro::TableWriter<SeriesRow> series(
      dir + "/series.csv", series_columns(),
      {note, "rotations in rad (outward: toward the valley), displacements in m, energy in J/m",
       // the mode of the run, for the figure's legend
       std::string("start: the paper's (from rest, undamped); friction update: ") +
           (ts.scene.contact.friction_update == dda::FrictionUpdate::kPaper ? "the paper's Eq. 26"
                                                                            : "return mapping (not the paper's)") +
           (m.exact_rotation ? "; rotation update: exact (not the paper's)" : "")});
  repro::FrameFiles frames(dir, note);
  const auto steps = static_cast<long long>(std::llround(duration / sim.dt()));
  bool have_half = false;  // m.left_half, m.right_half: at half the duration
  repro::RunOutputs outputs;
  outputs.sample = [&] {
    m.left = tracker.measure(0);
    m.right = tracker.measure(1);
    if (!have_half && sim.step_count() >= steps / 2) {
      m.left_half = m.left;
      m.right_half = m.right;
      have_half = true;
    }
    m.health.sample(sim);
    const dda::Energy e = sim.energy();
    series.row({sim.time(), m.left, m.right, e.kinetic, e.total(), sim.dt() / sim.critical_time_step()});
  };
  outputs.frame = [&] { frames.write(sim); };
  outputs.snapshot = [&] {
    repro::write_vtk_polydata(dir + "/vtk/t" + time_tag(sim.time()) + ".vtk", sim,
                              "Paper A 6.2 toppling and slumping t = " + time_tag(sim.time()) + " s", true);
  };
  outputs.report = [&](long long, double) {
    return "t = " + format_short(sim.time(), 3) + " of " + format_short(duration, 3) + " s, right outward rotation " +
           format_short(m.right.outward_rotation * 180.0 / kPi, 3) + " deg, left base slip " +
           format_short(m.left.base_slip, 3) + " m";
  };
  outputs.series_every = static_cast<long long>(std::llround(kSeriesEvery / sim.dt()));
  outputs.frame_every = static_cast<long long>(std::llround(kFrameEvery / sim.dt()));
  outputs.snapshot_every = static_cast<long long>(std::llround(1.0 / sim.dt()));
  outputs.sample();
  outputs.frame();
  outputs.snapshot();
  const repro::Progress clock("");
  repro::run_with_outputs(sim, steps, outputs, d.progress, clock);
  m.wall = clock.elapsed_seconds();
  m.steps = sim.step_count();
  m.time = sim.time();
  m.sps = static_cast<double>(m.steps) / m.wall;
  series.commit();
  frames.commit();
  d.progress("done: " + std::to_string(m.steps) + " steps in " + format_short(m.wall, 4) + " s (" +
             format_short(m.sps, 4) + " steps/s)");
  return m;
}

// summary.csv: the model (run 0) and the two controls.
void write_summary(const std::string& path, const std::string& note, const ModelRun& m, const Controls& controls) {
  struct Run {
    int run, blocks, dropped;
    double dropped_area, h, dt_ratio0, ratio_max;
    long long steps;
    double wall;
    SideState left, right;
  };
  const dda::paper::TopplingSlumping& ts = *m.ts;
  std::vector<Run> runs = {{0, m.blocks, ts.dropped, ts.dropped_area, m.h, m.dt_ratio0, m.health.ratio_max, m.steps,
                            m.wall, m.left, m.right}};
  int k = 1;
  for (const Control* c : {&controls.locked, &controls.whole}) {
    runs.push_back({k, k == 1 ? m.blocks : 2, 0, 0.0, 0.0, 0.0, 0.0, c->steps, c->wall, c->left, c->right});
    ++k;
  }
  const double duration = m.duration, dt = m.dt;
  repro::write_table<Run>(path,
                          {{"run", [](const Run& r) { return r.run; }},
                           {"blocks", [](const Run& r) { return r.blocks; }},
                           {"dropped", [](const Run& r) { return r.dropped; }},
                           {"dropped_area", [](const Run& r) { return r.dropped_area; }},
                           {"H", [](const Run& r) { return r.h; }},
                           {"dt", [dt](const Run&) { return dt; }},
                           {"dt_over_dt_crit_start", [](const Run& r) { return r.dt_ratio0; }},
                           {"dt_over_dt_crit_max", [](const Run& r) { return r.ratio_max; }},
                           {"duration", [duration](const Run&) { return duration; }},
                           {"steps", [](const Run& r) { return static_cast<double>(r.steps); }},
                           {"wall_s", [](const Run& r) { return r.wall; }},
                           {"steps_per_s", [](const Run& r) { return static_cast<double>(r.steps) / r.wall; }},
                           {"left_outward_rotation", [](const Run& r) { return r.left.outward_rotation; }},
                           {"left_base_slip", [](const Run& r) { return r.left.base_slip; }},
                           {"right_outward_rotation", [](const Run& r) { return r.right.outward_rotation; }},
                           {"right_base_slip", [](const Run& r) { return r.right.base_slip; }}},
                          runs, {note, "run 0: the model; 1: joints locked (80 deg); 2: each slope one block"});
}

// The run: what main's driver_main calls once the command line is checked.
int reproduce(const repro::Driver& d) {
  const dda::paper::TopplingSlumping full = dda::paper::toppling_slumping();
  const double duration = d.number("--duration", full.scene.duration);
  const int threads = d.whole("--threads", 1);
  if (!(duration > 0.0)) throw std::invalid_argument("--duration must be positive");
  const bool return_mapping = d.whole("--return-mapping", 0) != 0;
  dda::paper::TopplingSlumping ts = dda::paper::toppling_slumping(full.min_area, duration);
  if (return_mapping) ts.scene.contact.friction_update = dda::FrictionUpdate::kReturnMapping;
  ts.scene.rotation_update = repro::rotation_option(d.argc, d.argv);
  const std::string dir = d.out + "/data/toppling_slumping";
  const std::string note = "Paper A Sect. 6.2, geometry reconstructed (Fig. 21 lost)";

  ModelRun m = run_model(d, ts, duration, threads, dir, note);
  m.full_duration = full.scene.duration;
  m.return_mapping = return_mapping;
  const Controls controls = run_controls(ts, threads, return_mapping);
  repro::write_boundaries(dir + "/boundaries.csv", ts.scene.boundaries);
  write_summary(dir + "/summary.csv", note, m, controls);
  repro::write_claims(repro::claims_path(d.out, "6_2_toppling_slumping"), rows(m, controls));
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return repro::driver_main(argc, argv, kInfo, kOptions, reproduce); }
