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

std::string time_tag(double t) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f", t);
  return b;
}

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
                          {note, "rotations in rad (outward: toward the valley), displacements in m, energy in J/m"});
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
  // Steps between outputs run as one Simulation::advance (one thread team).
  auto next_output = [&](long long s) {
    return std::min({steps, (s / series_every + 1) * series_every, (s / frame_every + 1) * frame_every,
                     (s / vtk_every + 1) * vtk_every});
  };
  for (long long s = 0; s < steps;) {
    const long long to = next_output(s);
    sim.advance(to - s);
    s = to;
    if (s % series_every == 0 || s == steps) sample();
    if (s % frame_every == 0 || s == steps) frame();
    if (s % vtk_every == 0 || s == steps) vtk();
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

  // Controls (no output but the claims): the joints locked (friction 80 deg
  // instead of 22), and each slope as ONE block (the wedge outline itself),
  // the paper's premise "both the left slope and right slope will keep
  // stable as one unique block".
  dda::Scene locked = ts.scene;
  locked.contact.friction_deg = 80.0;
  const Control c_locked = run_control(ts, locked, ts.side, threads, "joints locked (80 deg)");
  const dda::Scene whole = one_block_per_slope(ts);
  const Control c_whole = run_control(ts, whole, {-1, +1}, threads, "each slope one block");
  // Diagnosis controls: the model and the single blocks again with the
  // elastic-plastic friction update (not the paper's rule), to measure how
  // much of the slip after the start-up transient is the re-stick ratchet
  // of Eq. 26 (dda::FrictionUpdate).
  // The friction start-up option beside the paper's start (not the paper's
  // method; Scene::damping settle_sticking): the same runs started from a
  // settled state whose stick springs already carry the static shear.
  // The slumping mechanism with the return mapping as well (the start-up
  // option alone leaves Eq. 26's re-stick ratchet, diagnosis row below).
  const Control c_whole_su = run_control(ts, start_up(whole), {-1, +1}, threads, "each slope one block, start-up option");
  dda::Scene model_su = start_up(ts.scene), locked_su = start_up(locked);
  model_su.contact.friction_update = locked_su.contact.friction_update = dda::FrictionUpdate::kReturnMapping;
  const Control c_su = run_control(ts, model_su, ts.side, threads, "start-up option and return mapping");
  const Control c_locked_su = run_control(ts, locked_su, ts.side, threads, "joints locked, start-up option and return mapping");
  Control c_rm, c_whole_rm;
  if (!return_mapping) {
    dda::Scene rm = ts.scene, whole_rm = whole;
    rm.contact.friction_update = whole_rm.contact.friction_update = dda::FrictionUpdate::kReturnMapping;
    c_rm = run_control(ts, rm, ts.side, threads, "return mapping");
    c_whole_rm = run_control(ts, whole_rm, {-1, +1}, threads, "each slope one block, return mapping");
  }

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
    for (const Control* c : {&c_locked, &c_whole}) {
      sum.row({static_cast<double>(k), k == 1 ? static_cast<double>(n) : 2.0, 0.0, 0.0, 0.0, sim.dt(), 0.0, 0.0,
               duration, static_cast<double>(c->steps), c->wall, static_cast<double>(c->steps) / c->wall,
               c->left.outward_rotation, c->left.base_slip, c->right.outward_rotation, c->right.base_slip});
      ++k;
    }
    sum.commit();
  }

  // ---- claims ------------------------------------------------------------
  const bool short_run = duration < full.scene.duration - 1e-9;
  const std::string run_note =
      (short_run ? " [SHORT RUN: --duration " + format_short(duration, 3) + " s]" : "") +
      (return_mapping ? " [RETURN MAPPING: friction update not the paper's Eq. 26]" : "") +
      (exact_rotation ? repro::kExactRotationNote : "");
  auto describe = [&](const SideState& s) {
    return "outward rotation " + format_short(s.outward_rotation * kDeg, 3) + " deg (|rotation| " +
           format_short(s.abs_rotation * kDeg, 3) + " deg, top travel from rotation " +
           format_short(s.rotation_travel, 3) + " m), base slip down-dip " + format_short(s.base_slip, 3) +
           " m, centroid down-dip " + format_short(s.centroid_downdip, 3) + " m, mass rotated outward > 10 deg " +
           format_short(100.0 * s.toppled_share, 3) + " %";
  };
  std::vector<repro::Claim> claims;
  claims.push_back({"6.2",
                    "the reconstructed valley model runs to the end below the stability limit, energy only dissipates" +
                        run_note,
                    "explicit DDA, dt 1e-4 s, 3.5 s",
                    std::to_string(n) + " blocks (" + std::to_string(ts.dropped) + " slivers < " +
                        format_short(ts.min_area, 3) + " m^2 dropped, " + format_short(ts.dropped_area, 3) +
                        " m^2); dt/dt_crit " + format_short(dt_ratio0, 3) + " at start, at most " +
                        format_short(health.ratio_max, 3) + " during the run; largest rise of the total energy above its start " +
                        format_short(health.rise, 3) + " J/m (start " + format_short(health.e0, 4) + " J/m); " +
                        std::to_string(sim.step_count()) + " steps in " + format_short(wall, 4) + " s (" +
                        format_short(sps, 4) + " steps/s)",
                    "dt/dt_crit < 1 throughout; energy rise < 1e-3 of |E(0)|", runs_stably(health)});
  claims.back().control = repro::control_test(kControlHealth);
  // Toppling (right): the blocks rotate toward the valley about their toes:
  // a mean outward rotation beyond 10 deg (far more than the fraction of a
  // degree a settling block takes), at least half the side's mass rotated
  // outward > 10 deg, rotation moving the tops more than twice as far as the
  // bases slip, and -- the joints' role -- at least twice the rotation of
  // the locked-joint control.
  claims.push_back({"6.2", "the right slope (joints dipping into the slope) topples, through slip on the 22 deg joints" + run_note,
                    "Fig. 22 (3.5 s): \"the right part will fail with toppling pattern\"",
                    "right slope at t = " + format_short(sim.time(), 3) + " s: " + describe(right) +
                        "; with the joints locked (80 deg): outward rotation " +
                        format_short(c_locked.right.outward_rotation * kDeg, 3) + " deg",
                    "mean outward rotation > 10 deg, > 50 % of the mass rotated outward > 10 deg, top travel from "
                    "rotation > 2 x |base slip|, and outward rotation > 2 x the locked-joint control's",
                    topples(right, c_locked.right)});
  claims.back().control = kControlMechanism;
  // Slumping (left), kinematics: the mass moves down the base -- the bases
  // slip more than 0.5 m (beyond elastic/penalty settling, millimetres) --
  // with small rotations (mean |rotation| < 10 deg and less than half the
  // right slope's).
  claims.push_back({"6.2", "the left slope (joints dipping toward the valley) slumps: slides down its base with small rotations" + run_note,
                    "Fig. 22 (3.5 s): \"the left part will fail in slumping pattern\"",
                    "left slope at t = " + format_short(sim.time(), 3) + " s: " + describe(left),
                    "base slip down-dip > 0.5 m; mean |rotation| < 10 deg and < half the right slope's",
                    slumps(left, right)});
  claims.back().control = kControlMechanism;
  // Slumping (left), mechanism: the paper attributes the failure to the
  // 22 deg joints; then locking the joints must stop most of it (slip with
  // free joints > 2 x slip with locked joints).
  // Measured: with the paper's friction update the left slabs creep down the
  // base at a steady rate with free or locked joints alike (mean centroid
  // down-dip, free / locked: 0.42 / 0.49 m at 3.5 s, 0.80 / 0.98 m at 7 s):
  // the re-stick ratchet of the premise row below, not joint slip. With
  // --return-mapping 1 they move 0.14 / 0.12 m in the first second (the
  // start-up transient of the premise row) and then stay at rest (0.155 /
  // 0.131 m at 7 s): this reconstruction has no joint-driven slumping.
  claims.push_back({"6.2", "the left slope's slumping comes from slip on the 22 deg joints (locking them stops it)" + run_note,
                    "\"influenced by the joint set with a friction angle of 22 deg, the stable condition ... will be broken\"",
                    "left base slip at t = " + format_short(sim.time(), 3) + " s: " + format_short(left.base_slip, 3) +
                        " m with the joints at 22 deg, " + format_short(c_locked.left.base_slip, 3) +
                        " m with the joints locked at 80 deg (outward rotation " +
                        format_short(c_locked.left.outward_rotation * kDeg, 3) + " deg); one block per slope: " +
                        format_short(c_whole.left.base_slip, 3) + " m (next row)",
                    "base slip with free joints > 2 x with locked joints",
                    joints_carry_slip(left, c_locked.left)});
  claims.back().control = kControlMechanism;
  repro::explain_fail(claims.back(), repro::Cause::kPaperMethod,
                      "the left slope slides on its base as much with locked joints: the slip is the start-up "
                      "transient of suddenly applied gravity on the undamped stick spring and the re-stick ratchet "
                      "of Eq. 26 (diagnosis row), not joint slip; the geometry is also reconstructed (Fig. 21 lost); with "
                      "the friction start-up option and the return mapping beyond the paper (next row) the joints "
                      "carry it");
  // Beside it, the options beyond the paper: the friction start-up (springs
  // pre-loaded by settling) and the return mapping (no re-stick ratchet).
  // Measured (3.5 s): left base slip 0.051 m with free joints, 1e-6 m with
  // the joints locked; the start-up option alone leaves the ratchet (free /
  // locked 0.38 / 0.50 m).
  claims.push_back({"6.2 (option)",
                    "the left slope's slumping comes from slip on the 22 deg joints (locking them stops it), with the "
                    "friction start-up option and the return mapping (not the paper's start and update)" + run_note,
                    "\"influenced by the joint set with a friction angle of 22 deg, the stable condition ... will be broken\"",
                    "left base slip at t = " + format_short(duration, 3) + " s: " + format_short(c_su.left.base_slip, 3) +
                        " m with the joints at 22 deg (mean |rotation| " +
                        format_short(c_su.left.abs_rotation * kDeg, 3) + " deg), " +
                        format_short(c_locked_su.left.base_slip, 3) + " m with the joints locked at 80 deg; right "
                        "outward rotation " + format_short(c_su.right.outward_rotation * kDeg, 3) + " deg",
                    "base slip with free joints > 2 x with locked joints, and > 0.01 m (beyond settling)",
                    joints_carry_slip(c_su.left, c_locked_su.left, 0.01)});
  claims.back().control = kControlMechanism;
  repro::explain_fail(claims.back(), repro::Cause::kImplementation,
                      "with the springs pre-loaded and no ratchet only the joints should let the left slope move; "
                      "not explained, needs an issue note");
  // The premise: one block per slope on the 30 deg base with 32 deg friction
  // is stable (tan 32 > tan 30). Stable: < 0.05 m of slip in 3.5 s (a block
  // that starts sliding at the 8 % friction margin's deficit would move
  // metres; elastic and penalty settling is millimetres).
  // Measured causes of the slip (each wedge alone on its base, 3.5 s): (1)
  // the undamped stick phase under suddenly applied gravity reaches the
  // limit with the wedge moving at ~0.5 m/s (kt = 1e8 N/m on ~1e6 kg/m:
  // omega ~ 10 rad/s), and the 8 % friction margin stops it only after
  // g sin^2(theta) m / (2 kt (cos(theta) tan(phi) - sin(theta))) ~ 0.3 m;
  // (2) with the paper's rule each re-stick restarts the spring from zero
  // shear (dda::FrictionUpdate::kPaper) and the wedge ratchets on: left
  // 0.99 m at 3.5 s, 1.23 m at 10 s, where the return mapping stops it; (3)
  // the blocks start just touching, so fn swings between ~0 and 2 W cos
  // (undamped normal mode) and with it the limit. With the wedge started at
  // its static penetration and the return mapping: 0.29-0.37 m, then at
  // rest; that remainder scales as 1/kt.
  claims.push_back({"6.2", "premise: each slope as ONE block stays on its 30 deg base (friction 32 deg)" + run_note,
                    "\"both the left slope and right slope will keep stable as one unique block\"",
                    "one block per slope, same parameters, " + format_short(duration, 3) + " s: left slid " +
                        format_short(c_whole.left.base_slip, 3) + " m (rotation " +
                        format_short(c_whole.left.outward_rotation * kDeg, 3) + " deg), right slid " +
                        format_short(c_whole.right.base_slip, 3) + " m (rotation " +
                        format_short(c_whole.right.outward_rotation * kDeg, 3) + " deg)",
                    "|slip| < 0.05 m on both sides",
                    stays(c_whole)});
  claims.back().control = kControlMechanism;
  repro::explain_fail(claims.back(), repro::Cause::kPaperMethod,
                      "suddenly applied gravity on the undamped stick spring (kt = 1e8 N/m) reaches the friction "
                      "limit moving, and the 8 % margin stops the wedge only after ~0.3 m (analytic, see the source); "
                      "then each re-stick of Eq. 26 restarts the spring from zero shear and the wedge ratchets on; "
                      "the return mapping (an option beyond the paper) stops the ratchet (diagnosis row); the friction "
                      "start-up option beyond the paper (next row) passes");
  // Beside it, the friction start-up option alone (the paper's Eq. 26
  // update): the wedges start from the settled state, springs loaded.
  claims.push_back({"6.2 (option)",
                    "premise: each slope as ONE block stays on its 30 deg base (friction 32 deg), with the friction "
                    "start-up option (settled with sticking contacts, not the paper's start)" + run_note,
                    "\"both the left slope and right slope will keep stable as one unique block\"",
                    "one block per slope, settled, then " + format_short(duration, 3) + " s: left slid " +
                        format_short(c_whole_su.left.base_slip, 3) + " m, right slid " +
                        format_short(c_whole_su.right.base_slip, 3) + " m",
                    "|slip| < 0.05 m on both sides",
                    stays(c_whole_su)});
  claims.back().control = kControlMechanism;
  repro::explain_fail(claims.back(), repro::Cause::kImplementation,
                      "the start-up option should remove the sudden loading; not explained, needs an issue note");
  // Diagnosis of the two rows above (not a paper claim): if the slip that
  // goes on after the start-up transient is the ratchet of Eq. 26's
  // re-stick (spring restarted from zero shear), the elastic-plastic update
  // must all but stop it. Second-half slip = slip(t) - slip(t / 2).
  if (!return_mapping) {
    auto late = [](const SideState& end, const SideState& half) { return end.base_slip - half.base_slip; };
    const double model_paper = late(left, left_half), model_rm = late(c_rm.left, c_rm.left_half);
    const double one_paper = late(c_whole.left, c_whole.left_half), one_rm = late(c_whole_rm.left, c_whole_rm.left_half);
    const double one_paper_r = late(c_whole.right, c_whole.right_half),
                 one_rm_r = late(c_whole_rm.right, c_whole_rm.right_half);
    const std::string half = format_short(0.5 * duration, 3), end = format_short(duration, 3);
    claims.push_back(
        {"6.2", "diagnosis (not a paper claim): the left slope's slip in the second half of the run (its "
                "'slumping' above) is the re-stick ratchet of Eq. 26 (a sliding pair restarts its stick spring "
                "from zero shear), not a failure mechanism" + run_note,
         "Sect. 3.2.5-3.2.6: d = Delta d after a sliding step; the paper reports no creep",
         "left base slip between t = " + half + " and " + end + " s, paper rule / elastic-plastic update "
         "(dda::FrictionUpdate::kReturnMapping): model " + format_short(model_paper, 3) + " / " +
             format_short(model_rm, 3) + " m; one block per slope, left " + format_short(one_paper, 3) + " / " +
             format_short(one_rm, 3) + " m, right " + format_short(one_paper_r, 3) + " / " +
             format_short(one_rm_r, 3) + " m; total slip with the elastic-plastic update: model left " +
             format_short(c_rm.left.base_slip, 3) + " m, one block left / right " +
             format_short(c_whole_rm.left.base_slip, 3) + " / " + format_short(c_whole_rm.right.base_slip, 3) +
             " m (the start-up transient: suddenly applied gravity on the undamped stick spring, and the "
             "undamped normal vibration of blocks that start just touching, which makes the friction limit swing)",
         "model left: late slip with the elastic-plastic update < 0.25 x with the paper rule",
         ratchet_explains(model_rm, model_paper)});
    claims.back().control = repro::control_test(kControlRatchet);
  }
  repro::write_claims(repro::claims_path(out, "6_2_toppling_slumping"), claims);
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "toppling_slumping: %s\n", e.what());
  return 1;
}
