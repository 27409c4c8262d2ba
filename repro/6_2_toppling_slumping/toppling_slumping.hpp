// Paper A Sect. 6.2 (toppling_slumping.cpp says what it reproduces): the
// per-side measures, the control runs and the criteria of the claim rows,
// here so that the negative controls (controls.cpp beside this file) apply
// the same criteria to deliberately wrong configurations.
#pragma once
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "dda/rock_scenes.hpp"
#include "dda/simulation.hpp"
#include "repro/common/common.hpp"

namespace topple {
using repro::format_short;
inline constexpr double kPi = 3.14159265358979323846;
// A block's edge lies on the sliding base if both its ends are this close to
// the base line (m): settling (the start-up option) presses the blocks in by
// millimetres; the joint spacing is 3 m.
inline constexpr double kBaseEdgeTolerance = 0.05;

// Per-side measures, mass-weighted means over the side's blocks.
struct SideState {
  double outward_rotation = 0.0;  // rad, > 0 toward the valley
  double abs_rotation = 0.0;      // rad
  double base_slip = 0.0;         // m, base-edge midpoint along the base, down-dip
  double centroid_downdip = 0.0;  // m, centroid along the base, down-dip
  double rotation_travel = 0.0;   // m, |rotation| x block length: the top's travel due to rotation
  double toppled_share = 0.0;     // share of the side's mass rotated outward by > 10 deg
};

// Per-side measures of a running simulation of a TopplingSlumping scene (or
// a variant of it with other blocks on the same bases).
class Tracker {
 public:
  Tracker(const dda::Simulation& sim, const dda::paper::TopplingSlumping& ts, const std::vector<int>& side)
      : sim_(sim), ts_(ts), side_(side) {
    const int n = sim.scene_block_count();
    const double dip = ts.joints.dip_deg * kPi / 180.0;
    const dda::Vec2 joint_dir{std::cos(dip), -std::sin(dip)};
    blocks_.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
      Block& b = blocks_[static_cast<std::size_t>(i)];
      const int s = side[static_cast<std::size_t>(i)];
      b.which = s < 0 ? 0 : 1;
      const dda::Vec2 toe{s < 0 ? -ts.valley_half_width : ts.valley_half_width, 0.0};
      b.down = s < 0 ? ts.left_downdip : ts.right_downdip;
      const dda::Polygon& p = sim.polygon(i);
      double lo = 1e300, hi = -1e300, nearest = kBaseEdgeTolerance;
      for (int v = 0; v < p.count; ++v) {
        const double d = dot(p.vertex(v) - toe, joint_dir);
        lo = std::min(lo, d);
        hi = std::max(hi, d);
        // The edge on the sliding base: the one nearest its line, both ends
        // within kBaseEdgeTolerance (exactly on it unless the scene settled).
        const int w = (v + 1) % p.count;
        const double off = std::max(std::fabs(cross(b.down, p.vertex(v) - toe)),
                                    std::fabs(cross(b.down, p.vertex(w) - toe)));
        if (off < nearest) {
          nearest = off;
          b.base_a = v;
          b.base_b = w;
        }
      }
      if (b.base_b < 0) throw std::runtime_error("block " + std::to_string(i) + " has no edge on the sliding base");
      b.length = hi - lo;
      b.mass = sim.mass(i);
      side_mass_[b.which] += b.mass;
      b.c0 = sim.centroid(i);
      b.mid0 = 0.5 * (p.vertex(b.base_a) + p.vertex(b.base_b));
    }
  }

  SideState measure(int which) const {  // which: 0 left, 1 right
    SideState s;
    for (std::size_t u = 0; u < blocks_.size(); ++u) {
      const Block& b = blocks_[u];
      if (b.which != which) continue;
      const int i = static_cast<int>(u);
      const double rot = sim_.displacement(i)[2];
      const double outward = which == 0 ? -rot : rot;
      const dda::Polygon& p = sim_.polygon(i);
      const dda::Vec2 mid = 0.5 * (p.vertex(b.base_a) + p.vertex(b.base_b));
      const double w = b.mass / side_mass_[which];
      s.outward_rotation += w * outward;
      s.abs_rotation += w * std::fabs(rot);
      s.base_slip += w * dot(mid - b.mid0, b.down);
      s.centroid_downdip += w * dot(sim_.centroid(i) - b.c0, b.down);
      s.rotation_travel += w * std::fabs(rot) * b.length;
      if (outward > 10.0 * kPi / 180.0) s.toppled_share += w;
    }
    return s;
  }

  void write_sides(const std::string& path, const std::string& note) const {
    std::vector<std::size_t> blocks(blocks_.size());
    for (std::size_t u = 0; u < blocks.size(); ++u) blocks[u] = u;
    const auto b = [this](std::size_t u) -> const Block& { return blocks_[u]; };
    repro::write_table<std::size_t>(path,
                                    {{"block", [](std::size_t u) { return u; }},
                                     {"side", [b](std::size_t u) { return b(u).which == 0 ? -1 : 1; }},
                                     {"mass", [b](std::size_t u) { return b(u).mass; }},
                                     {"length", [b](std::size_t u) { return b(u).length; }},
                                     {"base_vertex_a", [b](std::size_t u) { return b(u).base_a; }},
                                     {"base_vertex_b", [b](std::size_t u) { return b(u).base_b; }}},
                                    blocks, {note, "side -1: left slope, +1: right slope"});
  }

 private:
  struct Block {
    int which = 0, base_a = -1, base_b = -1;
    double mass = 0.0, length = 0.0;
    dda::Vec2 down{}, c0{}, mid0{};
  };
  const dda::Simulation& sim_;
  const dda::paper::TopplingSlumping& ts_;
  std::vector<int> side_;
  std::vector<Block> blocks_;
  double side_mass_[2] = {0.0, 0.0};
};

// The friction start-up option (not the paper's start; Scene::damping):
// settled from rest for kSettleTime with mass damping (Eq. 5c) and every
// contact sticking, the last kSettleSlipTime of it with the friction angles
// again (still damped: the wedges' toe corners, which touch the valley floor
// with almost no normal force, shed the shear they took while sticking),
// then released at t = 0 with the stick springs carrying the static shear.
inline constexpr double kSettleDamping = 10.0;  // 1/s: about the wedges' 9.5 rad/s stick mode (kt 1e8 N/m, ~1e6 kg/m)
inline constexpr double kSettleTime = 2.0;      // s: 10 decay times (a / 2 = 5 1/s)
inline constexpr double kSettleSlipTime = 1.0;  // s
inline dda::Scene start_up(dda::Scene s) {
  s.damping.mass = kSettleDamping;
  s.damping.settle_time = kSettleTime;
  s.damping.settle_sticking = true;
  s.damping.settle_slip_time = kSettleSlipTime;
  return s;
}

// A control run without output: the per-side state at the end.
struct Control {
  SideState left, right;            // at the end
  SideState left_half, right_half;  // at half the duration
  double wall = 0.0;
  long long steps = 0;
};
inline Control run_control(const dda::paper::TopplingSlumping& ts, const dda::Scene& scene, const std::vector<int>& side,
                    int threads, const std::string& label) {
  const repro::Progress clock("6.2 control: " + label);
  dda::Simulation sim(scene);
  sim.set_threads(threads);
  const Tracker tr(sim, ts, side);
  const auto steps = static_cast<long long>(std::llround(scene.duration / sim.dt()));
  Control c;
  sim.advance(steps / 2);
  c.left_half = tr.measure(0);
  c.right_half = tr.measure(1);
  sim.advance(steps - steps / 2);
  c.left = tr.measure(0);
  c.right = tr.measure(1);
  c.wall = clock.elapsed_seconds();
  c.steps = sim.step_count();
  clock("done: " + std::to_string(c.steps) + " steps in " + format_short(c.wall, 3) + " s; left base slip " +
        format_short(c.left_half.base_slip, 3) + " m at half time, " + format_short(c.left.base_slip, 3) + " m at the end, right outward rotation " +
        format_short(c.right.outward_rotation * 180.0 / kPi, 3) + " deg");
  return c;
}


using dda::paper::one_block_per_slope;

// ---- criteria of the claim rows (toppling_slumping.cpp says why) -----------
inline constexpr double kDeg = 180.0 / kPi;
// Toppling (right): mean outward rotation beyond 10 deg, > 50 % of the mass
// rotated outward > 10 deg, rotation moving the tops more than twice as far
// as the bases slip, and more than twice the locked-joint control's rotation.
inline bool topples(const SideState& right, const SideState& locked_right) {
  return right.outward_rotation > 10.0 / kDeg && right.toppled_share > 0.5 &&
         right.rotation_travel > 2.0 * std::fabs(right.base_slip) &&
         right.outward_rotation > 2.0 * locked_right.outward_rotation;
}
// Slumping kinematics (left): base slip > 0.5 m with mean |rotation| < 10 deg
// and less than half the right slope's.
inline bool slumps(const SideState& left, const SideState& right) {
  return left.base_slip > 0.5 && left.abs_rotation < 10.0 / kDeg && left.abs_rotation < 0.5 * right.abs_rotation;
}
// The joints carry the slumping: base slip with free joints more than twice
// that with locked joints, and beyond settling (min_slip, m).
inline bool joints_carry_slip(const SideState& free_left, const SideState& locked_left, double min_slip = 0.0) {
  return free_left.base_slip > 2.0 * std::fabs(locked_left.base_slip) && free_left.base_slip > min_slip;
}
// Each slope as one block stays: |base slip| < 0.05 m on both sides.
inline constexpr double kStaysSlip = 0.05;  // m: elastic and penalty settling is millimetres
inline bool stays(const Control& whole) {
  return std::fabs(whole.left.base_slip) < kStaysSlip && std::fabs(whole.right.base_slip) < kStaysSlip;
}
// The model runs below the stability limit and its energy only dissipates:
// dt / the current critical step stays below 1 and the total energy never
// rises above its start by more than 1e-3 of |E(0)|. Sampled by the driver
// every 0.01 s.
struct Health {
  double e0 = 0.0, rise = 0.0, ratio_max = 0.0;
  bool started = false;
  void sample(const dda::Simulation& sim) {
    const double e = sim.energy().total();
    if (!started) e0 = e;
    started = true;
    rise = std::max(rise, e - e0);
    ratio_max = std::max(ratio_max, sim.dt() / sim.critical_time_step());
  }
};
inline bool runs_stably(const Health& h) { return h.ratio_max < 1.0 && h.rise < 1e-3 * std::fabs(h.e0); }
inline constexpr const char* kControlHealth = "6.2 stable run: FAIL at twice the critical step";
// Diagnosis row: the slip in the second half of the run with the
// elastic-plastic update is below a quarter of that with the paper's rule.
inline bool ratchet_explains(double late_return_mapping, double late_paper) {
  return std::fabs(late_return_mapping) < 0.25 * std::fabs(late_paper);
}
inline constexpr const char* kControlRatchet = "6.2 ratchet diagnosis: FAIL when both runs use the paper's update";

// The negative controls (controls.cpp) named by the rows.
inline const char* const kControlMechanism =
    "repro_controls: 6.2 toppling, slumping, premise: FAIL with locked joints, a rough base and a gentle friction";

}  // namespace topple
