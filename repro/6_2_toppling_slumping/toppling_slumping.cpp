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
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "dda/rock_scenes.hpp"
#include "dda/simulation.hpp"
#include "repro/6_2_toppling_slumping/rows.hpp"
#include "repro/6_2_toppling_slumping/toppling_slumping.hpp"
#include "repro/common/common.hpp"
#include "repro/common/integrator_options.hpp"
#include "repro/common/options.hpp"
#include "repro/common/sim_output.hpp"
#include "repro/common/vtk_output.hpp"

namespace {
using namespace topple;
constexpr double kSeriesEvery = 0.01;  // s
constexpr double kFrameEvery = 0.05;   // s

// A frame time in a file name or caption, 0.1 s resolution.
std::string time_tag(double t) { return repro::format_fixed(t, 1); }

}  // namespace

int main(int argc, char** argv) try {
  repro::check_command_line(argc, argv, "Paper A Sect. 6.2 (Figs. 21-22, geometry reconstructed): toppling and slumping of a jointed valley slope.",
                            {{"--duration", "S", "simulated seconds (default 3.5: the paper's)", false},
                             {"--threads", "N", "OpenMP threads (default 1; results are bit-identical for any count)", true},
                             {"--return-mapping", "0|1", "1: return-mapping friction update instead of the paper's (default 0)", true},
                             repro::kExactRotationOption});
  const std::string out = repro::out_dir(argc, argv);
  const dda::paper::TopplingSlumping full = dda::paper::toppling_slumping();
  const double duration = repro::option_number(argc, argv, "--duration", full.scene.duration);
  const int threads = repro::option_int(argc, argv, "--threads", 1);
  if (!(duration > 0.0)) throw std::invalid_argument("--duration must be positive");
  const bool return_mapping = repro::option_int(argc, argv, "--return-mapping", 0) != 0;
  dda::paper::TopplingSlumping ts = dda::paper::toppling_slumping(full.min_area, duration);
  if (return_mapping) ts.scene.contact.friction_update = dda::FrictionUpdate::kReturnMapping;
  ts.scene.rotation_update = repro::rotation_option(argc, argv);
  const bool exact_rotation = ts.scene.rotation_update == dda::RotationUpdate::kExact;
  const repro::Progress progress("6.2 toppling/slumping");
  dda::Simulation sim(ts.scene);
  sim.set_threads(threads);
  const int n = sim.scene_block_count();
  const double dt_ratio0 = sim.dt() / sim.predicted_critical_step();
  progress(std::to_string(n) + " blocks (" + std::to_string(ts.dropped) + " slivers dropped, " +
           format_short(ts.dropped_area, 3) + " m^2), H = " + format_short(sim.potential_length(0), 4) +
           " m, dt/dt_crit = " + format_short(dt_ratio0, 3) + " at start");
  const std::string dir = out + "/data/toppling_slumping";
  const std::string note = "Paper A Sect. 6.2, geometry reconstructed (Fig. 21 lost)";
  const Tracker tracker(sim, ts, ts.side);
  tracker.write_sides(dir + "/sides.csv", note);

  repro::CsvWriter series(dir + "/series.csv",
                          {"time", "left_outward_rotation", "left_abs_rotation", "left_base_slip",
                           "left_centroid_downdip", "left_rotation_travel", "left_toppled_share",
                           "right_outward_rotation", "right_abs_rotation", "right_base_slip", "right_centroid_downdip",
                           "right_rotation_travel", "right_toppled_share", "E_kinetic", "E_total", "dt_over_dt_crit"},
                          {note, "rotations in rad (outward: toward the valley), displacements in m, energy in J/m",
                           // the mode of the run, for the figure's legend
                           std::string("start: the paper's (from rest, undamped); friction update: ") +
                               (ts.scene.contact.friction_update == dda::FrictionUpdate::kPaper
                                    ? "the paper's Eq. 26"
                                    : "return mapping (not the paper's)") +
                               (exact_rotation ? "; rotation update: exact (not the paper's)" : "")});
  repro::CsvWriter frames(dir + "/frames.csv", repro::snapshot_header(), {note});
  repro::CsvWriter states(dir + "/blocks.csv",
                          {"time", "block", "cx", "cy", "vx", "vy", "speed", "dx", "dy", "rotation"}, {note});
  Health health;
  SideState left, right, left_half, right_half;  // now, and at half the duration
  const auto half_step = static_cast<long long>(std::llround(duration / sim.dt())) / 2;
  bool have_half = false;
  auto sample = [&] {
    left = tracker.measure(0);
    right = tracker.measure(1);
    if (!have_half && sim.step_count() >= half_step) {
      left_half = left;
      right_half = right;
      have_half = true;
    }
    health.sample(sim);
    const dda::Energy e = sim.energy();
    const double ratio = sim.dt() / sim.critical_time_step();
    series.row({sim.time(), left.outward_rotation, left.abs_rotation, left.base_slip, left.centroid_downdip,
                left.rotation_travel, left.toppled_share, right.outward_rotation, right.abs_rotation, right.base_slip,
                right.centroid_downdip, right.rotation_travel, right.toppled_share, e.kinetic, e.total(), ratio});
  };
  auto frame = [&] {
    repro::write_snapshot(frames, sim);
    for (int i = 0; i < n; ++i) {
      const dda::Vec6& v = sim.velocity(i);
      const dda::Vec6& d = sim.displacement(i);
      states.row({sim.time(), static_cast<double>(i), sim.centroid(i).x, sim.centroid(i).y, v[0], v[1],
                  std::hypot(v[0], v[1]), d[0], d[1], d[2]});
    }
  };
  auto vtk = [&] {
    repro::write_vtk_polydata(dir + "/vtk/t" + time_tag(sim.time()) + ".vtk", sim,
                              "Paper A 6.2 toppling and slumping t = " + time_tag(sim.time()) + " s", true);
  };

  const auto steps = static_cast<long long>(std::llround(duration / sim.dt()));
  const auto series_every = static_cast<long long>(std::llround(kSeriesEvery / sim.dt()));
  const auto frame_every = static_cast<long long>(std::llround(kFrameEvery / sim.dt()));
  const auto vtk_every = static_cast<long long>(std::llround(1.0 / sim.dt()));
  sample();
  frame();
  vtk();
  const repro::Progress clock("");
  double last_report = 0.0;
  const repro::OutputSchedule outputs(steps, {series_every, frame_every, vtk_every});
  for (long long s = 0; s < steps;) {
    const long long to = outputs.next(s);
    sim.advance(to - s);
    s = to;
    if (outputs.at(s, series_every)) sample();
    if (outputs.at(s, frame_every)) frame();
    if (outputs.at(s, vtk_every)) vtk();
    if (s % series_every == 0 && clock.elapsed_seconds() - last_report > 5.0) {
      last_report = clock.elapsed_seconds();
      progress("t = " + format_short(sim.time(), 3) + " of " + format_short(duration, 3) + " s, right outward rotation " +
               format_short(right.outward_rotation * 180.0 / kPi, 3) + " deg, left base slip " +
               format_short(left.base_slip, 3) + " m");
    }
  }
  const double wall = clock.elapsed_seconds();
  const double sps = static_cast<double>(sim.step_count()) / wall;
  series.commit();
  frames.commit();
  states.commit();
  progress("done: " + std::to_string(sim.step_count()) + " steps in " + format_short(wall, 4) + " s (" +
           format_short(sps, 4) + " steps/s)");

  const Controls controls = run_controls(ts, threads, return_mapping);

  {
    repro::CsvWriter b(dir + "/boundaries.csv", {"ax", "ay", "bx", "by", "depth"},
                       {"boundary segments, solid on the right of a -> b"});
    for (const dda::BoundarySegment& g : ts.scene.boundaries) b.row({g.a.x, g.a.y, g.b.x, g.b.y, g.depth});
    b.commit();
  }
  {
    repro::CsvWriter sum(dir + "/summary.csv",
                         {"run", "blocks", "dropped", "dropped_area", "H", "dt", "dt_over_dt_crit_start",
                          "dt_over_dt_crit_max", "duration", "steps", "wall_s", "steps_per_s", "left_outward_rotation",
                          "left_base_slip", "right_outward_rotation", "right_base_slip"},
                         {note, "run 0: the model; 1: joints locked (80 deg); 2: each slope one block"});
    sum.row({0.0, static_cast<double>(n), static_cast<double>(ts.dropped), ts.dropped_area, sim.potential_length(0),
             sim.dt(), dt_ratio0, health.ratio_max, duration, static_cast<double>(sim.step_count()), wall, sps,
             left.outward_rotation, left.base_slip, right.outward_rotation, right.base_slip});
    int k = 1;
    for (const Control* c : {&controls.locked, &controls.whole}) {
      sum.row({static_cast<double>(k), k == 1 ? static_cast<double>(n) : 2.0, 0.0, 0.0, 0.0, sim.dt(), 0.0, 0.0,
               duration, static_cast<double>(c->steps), c->wall, static_cast<double>(c->steps) / c->wall,
               c->left.outward_rotation, c->left.base_slip, c->right.outward_rotation, c->right.base_slip});
      ++k;
    }
    sum.commit();
  }

  ModelRun m;
  m.ts = &ts;
  m.blocks = n;
  m.duration = duration;
  m.full_duration = full.scene.duration;
  m.dt_ratio0 = dt_ratio0;
  m.wall = wall;
  m.sps = sps;
  m.time = sim.time();
  m.steps = sim.step_count();
  m.health = health;
  m.left = left;
  m.right = right;
  m.left_half = left_half;
  m.right_half = right_half;
  m.return_mapping = return_mapping;
  m.exact_rotation = exact_rotation;
  const std::vector<repro::Claim> claims = rows(m, controls);
  repro::write_claims(repro::claims_path(out, "6_2_toppling_slumping"), claims);
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "toppling_slumping: %s\n", e.what());
  return 1;
}
