// Paper B, Sect. 6 "Verification examples" (Figs. 12-16): two triangular
// prisms, block i at 3.0 m/s toward block j at rest, 1 m apart in x;
// E = 40 GPa, nu = 0.25, rho = 2700 kg/m3, dt = 5e-4 s, contact tolerance
// 5e-3 m; the two-scale contact model (two time stages, clone node, local
// subdivision), no contact spring.
//
// RECONSTRUCTED geometry (Fig. 12 lost, no dimensions in the text): two
// identical isosceles triangles 7 m long with a 7 m vertical base, apex A of
// i at (0, 0) pointing +x, base of j at x = 1 m, each meshed into 4 CST
// elements (c dt = 1.9 m < element size, critical step 7.4e-4 s). The size
// was chosen so that the clone node separates at about the time of Fig. 15a
// (0.3405 s); see dda/cdem/scenes.hpp.
//
// Expected (paper): vertex A touches j's edge at 0.3333 s, "in the step from
// 0.3335 to 0.3340 s" (as printed); block j accelerates "from 0.0 to 3.205
// m/s" (Fig. 14c), the clone node separates (Fig. 15a, 0.3405 s), j ends
// with about i's initial speed (Fig. 16), momentum conserved, "a little
// energy loss".
//
// Output under <out>/data/B_6_two_prisms/: history.csv (Fig. 16; also the
// run without subdivision, history_nosub.csv), snapshots.csv and clones.csv
// (Figs. 13-15), events.csv (touches and separations); claims in
// <out>/claims/B_6_two_prisms.csv.
#include <cmath>
#include <string>
#include <vector>

#include "dda/cdem/model.hpp"
#include "dda/cdem/scenes.hpp"
#include "repro/common/common.hpp"

namespace {

using dda::cdem::Model;
using repro::format_short;

const char* kDriver = "B_6_two_prisms";
const char* kRebuilt = "prisms rebuilt (Fig. 12 lost): 7 m x 7 m isosceles triangles, 4 CST elements each";

struct Run {
  double p0 = 0.0, e0 = 0.0, worst_momentum = 0.0;
  double peak_node_vj = 0.0, peak_node_vj_time = 0.0, peak_mean_vj = 0.0;
  double peak_node_vj_at_fig14c = 0.0;
  int max_substeps = 1;
};

std::vector<std::string> history_header() {
  return {"time",        "ux_i",         "ux_j",    "vx_i",           "vx_j",
          "vx_max_j",    "momentum_x",   "kinetic", "strain",         "total_energy",
          "impact_loss", "remap_change", "clones",  "patch_elements", "patch_substeps"};
}

void history_row(repro::CsvWriter& csv, const Model& m) {
  const dda::cdem::CdemEnergy e = m.energy();
  csv.row({m.time(), m.block_displacement(0).x, m.block_displacement(1).x, m.block_velocity(0).x, m.block_velocity(1).x,
           m.block_max_velocity_x(1), m.momentum().x, e.kinetic, e.strain, e.total(), m.impact_energy_loss(),
           m.remap_energy_change(), static_cast<double>(m.clones().size()),
           static_cast<double>(m.active_elements(true)), static_cast<double>(m.patch_substeps())});
}

void write_snapshot(repro::CsvWriter& tris, repro::CsvWriter& clones, int id, const std::string& label,
                    const dda::cdem::Snapshot& s) {
  for (const auto& t : s.tris)
    tris.row(std::vector<std::string>{std::to_string(id), repro::format_full(s.time), label, std::to_string(t.block),
                                      t.fine ? "1" : "0", repro::format_full(t.x[0].x), repro::format_full(t.x[0].y),
                                      repro::format_full(t.x[1].x), repro::format_full(t.x[1].y),
                                      repro::format_full(t.x[2].x), repro::format_full(t.x[2].y),
                                      repro::format_full(t.velocity.x), repro::format_full(t.velocity.y)});
  for (const dda::Vec2& p : s.clone_points)
    clones.row(std::vector<std::string>{std::to_string(id), repro::format_full(s.time), label, repro::format_full(p.x),
                                        repro::format_full(p.y)});
}

}  // namespace

int main(int argc, char** argv) {
  repro::check_command_line(argc, argv, "Paper B Sect. 6 (Figs. 12-16): two triangular prisms colliding.");
  const std::string out = repro::out_dir(argc, argv);
  const repro::Progress progress("B-6 two prisms");
  const std::string dir = out + "/data/" + kDriver + "/";

  dda::cdem::CdemOptions opt;
  opt.capture_touch_snapshots = true;
  const dda::cdem::CdemScene scene = dda::cdem::two_prisms(2, opt);
  Model m(scene);
  progress("mesh: " + std::to_string(m.node_count()) + " nodes, critical step " + format_short(m.critical_dt()) +
           " s (dt " + format_short(m.dt()) + " s)");

  repro::CsvWriter hist(dir + "history.csv", history_header(),
                        {std::string("Paper B Sect. 6, two prisms, clone node + subdivision; ") + kRebuilt});
  repro::CsvWriter tris(dir + "snapshots.csv",
                        {"snapshot", "time", "label", "block", "fine", "x0", "y0", "x1", "y1", "x2", "y2", "vx", "vy"},
                        {kRebuilt});
  repro::CsvWriter clones(dir + "clones.csv", {"snapshot", "time", "label", "x", "y"});

  // Snapshot times: Fig. 13 (start, touch), Fig. 14 a-c, Fig. 15 a-b.
  struct Shot {
    double time;
    std::string label;
  };
  const std::vector<Shot> shots = {{0.0, "Fig. 13: t = 0"},        {0.3335, "Fig. 14a: 0.3335 s"},
                                   {0.3340, "Fig. 14b: 0.3340 s"}, {0.3400, "Fig. 14c: 0.3400 s"},
                                   {0.3405, "Fig. 15a: 0.3405 s"}, {0.4960, "Fig. 15b: 0.4960 s"}};
  std::size_t next_shot = 0;
  int shot_id = 0;
  Run r;
  r.p0 = m.momentum().x;
  r.e0 = m.energy().total();
  auto take_shots = [&] {
    while (next_shot < shots.size() && std::fabs(m.time() - shots[next_shot].time) < 0.5 * m.dt()) {
      write_snapshot(tris, clones, shot_id++, shots[next_shot].label, m.snapshot());
      if (std::fabs(shots[next_shot].time - 0.3400) < 1e-9) r.peak_node_vj_at_fig14c = m.block_max_velocity_x(1);
      ++next_shot;
    }
  };
  history_row(hist, m);
  take_shots();
  // The last step before the first separation is drawn too ("last step with
  // the clone"): keep the previous step's snapshot until then.
  dda::cdem::Snapshot previous = m.snapshot();
  bool before_separation = true;
  while (m.time() < scene.duration - 0.5 * m.dt()) {
    if (before_separation) previous = m.snapshot();
    m.step();
    if (before_separation && !m.separations().empty()) {
      before_separation = false;
      write_snapshot(tris, clones, shot_id++, "last step with the clone: " + format_short(previous.time, 5) + " s",
                     previous);
    }
    r.worst_momentum = std::max(r.worst_momentum, std::fabs(m.momentum().x - r.p0) / std::fabs(r.p0));
    if (m.block_max_velocity_x(1) > r.peak_node_vj) {
      r.peak_node_vj = m.block_max_velocity_x(1);
      r.peak_node_vj_time = m.time();
    }
    r.peak_mean_vj = std::max(r.peak_mean_vj, m.block_velocity(1).x);
    r.max_substeps = std::max(r.max_substeps, m.patch_substeps());
    history_row(hist, m);
    take_shots();
  }
  if (m.touches().empty()) throw std::runtime_error("B-6: no touch happened");
  const dda::cdem::TouchRecord& touch = m.touches().front();
  write_snapshot(tris, clones, shot_id++, "Fig. 13: touch " + format_short(touch.time, 6) + " s", touch.snapshot.at(0));

  repro::CsvWriter events(dir + "events.csv", {"kind", "time", "detail_a", "detail_b", "detail_c", "detail_d"});
  for (const auto& t : m.touches())
    events.row(std::vector<std::string>{"touch", repro::format_full(t.time), "dt1=" + format_short(t.dt1, 6),
                                        "dt2=" + format_short(t.dt2, 6), "k=" + std::to_string(t.subdivision),
                                        "loss=" + format_short(t.energy_loss, 6)});
  for (const auto& s : m.separations())
    events.row(std::vector<std::string>{"separation", repro::format_full(s.time),
                                        s.criterion == dda::cdem::SeparationCriterion::kTension ? "tension" : "shear",
                                        "Fn=" + format_short(s.normal_force, 6), "Fs=" + format_short(s.shear_force, 6),
                                        "limit=" + format_short(s.limit, 6)});
  hist.commit();
  tris.commit();
  clones.commit();
  events.commit();

  const dda::cdem::CdemEnergy e_end = m.energy();
  const double vi = m.block_velocity(0).x, vj = m.block_velocity(1).x;
  const double impact = m.impact_energy_loss(), remap = m.remap_energy_change();
  const double e_loss = r.e0 - e_end.total();
  const double residual = e_loss - impact + remap;
  double t_sep = -1.0;
  std::string sep_kind = "none";
  for (const auto& s : m.separations())
    if (s.time > touch.time) {
      t_sep = s.time;
      sep_kind = s.criterion == dda::cdem::SeparationCriterion::kTension ? "tension (Eq. 6)" : "shear (Eqs. 7-10)";
    }
  progress("touch " + format_short(touch.time, 8) + " s, separation " + format_short(t_sep, 6) + " s, v_i " +
           format_short(vi) + ", v_j " + format_short(vj) + " m/s");

  // The same collision with coarse clone nodes (no subdivision): the size of
  // the Eq. 5 loss with the coarse lumped masses.
  dda::cdem::CdemOptions coarse_opt;
  coarse_opt.subdivision = false;
  Model mc(dda::cdem::two_prisms(2, coarse_opt));
  repro::CsvWriter hist_c(dir + "history_nosub.csv", history_header(),
                          {std::string("Paper B Sect. 6, two prisms, clone node without subdivision; ") + kRebuilt});
  history_row(hist_c, mc);
  while (mc.time() < scene.duration - 0.5 * mc.dt()) {
    mc.step();
    history_row(hist_c, mc);
  }
  hist_c.commit();
  const dda::cdem::TouchRecord& touch_c = mc.touches().front();

  // Tolerances. Touch time: solved exactly on the straight collision path,
  // so round-off (1e-12 s). Momentum: the clone impulse and all element
  // forces are internal, remaps move momentum with the mass: round-off
  // (1e-12). Final v_j: 'approximately equal' to 3.0 m/s read as within 5 %.
  // Peak: the paper's 3.205 m/s exceeds 3.0, which no block-mean velocity
  // can (energy), so it is a nodal value of its (unknown) mesh: we ask for a
  // nodal overshoot above 3.0 m/s within 10 % of 3.205 m/s. Energy: 'a
  // little loss' read as 0 < loss < 5 % of the initial energy, and the
  // balance (impact loss of Eq. 5 + patch remaps) must close within 1 %.
  const double dt = m.dt();
  const double t_exact = 1.0 / 3.0;
  const double step_start = std::floor(t_exact / dt) * dt;
  std::vector<repro::Claim> claims;
  claims.push_back({"B-6", "vertex A of block i touches block j's edge at the two-stage touch time",
                    "0.3333 s (1 m at 3.0 m/s)",
                    "t = " + format_short(touch.time, 10) + " s (dt1 = " + format_short(touch.dt1, 6) +
                        " s free motion, dt2 = " + format_short(touch.dt2, 6) + " s contact); " + kRebuilt,
                    "|t - 1/3| < 1e-12 s", std::fabs(touch.time - t_exact) < 1e-12});
  claims.push_back({"B-6", "the touch falls in the step printed by the paper", "'in the step from 0.3335 to 0.3340 s'",
                    "touch in the step [" + format_short(touch.step_start, 5) + ", " + format_short(touch.step_end, 5) +
                        "] s; the printed step does not contain the printed touch time 0.3333 s (with t0 = 0 and dt "
                        "= 5e-4 s, 1/3 s lies in [0.3330, 0.3335]): NOT MATCHED, the paper's label looks one step off",
                    "touch step = [0.3335, 0.3340] s",
                    std::fabs(touch.step_start - 0.3335) < 1e-9 && std::fabs(touch.step_end - 0.3340) < 1e-9});
  repro::explain_fail(claims.back(), repro::Cause::kMissingData,
                      "the paper's printed step [0.3335, 0.3340] s does not contain its own printed touch time "
                      "0.3333 s; with t0 = 0 and dt = 5e-4 s, 1/3 s lies in [0.3330, 0.3335] (analytic): the label "
                      "is inconsistent with the paper's other data");
  claims.push_back(
      {"B-6", "the step containing the touch is split into dt1 + dt2 = dt", "Sect. 3 (Figs. 4-6)",
       "step [" + format_short(touch.step_start, 5) + ", " + format_short(touch.step_end, 5) +
           "] s, dt1 = " + format_short(touch.dt1, 6) + " s, dt2 = " + format_short(touch.dt2, 6) + " s",
       "dt1 = 1/3 - " + format_short(step_start, 5) + " s to 1e-12, dt1 + dt2 = dt",
       std::fabs(touch.dt1 - (t_exact - step_start)) < 1e-12 && std::fabs(touch.dt1 + touch.dt2 - dt) < 1e-15});
  const double r_expected = std::sqrt(40e9 / 2700.0) * touch.dt2;
  claims.push_back({"B-6", "the contact zone is refined within c dt2 of the contact point (Sect. 5)",
                    "radius c dt2, c = sqrt(E/rho)",
                    "radius " + format_short(touch.radius) + " m (c dt2 = " + format_short(r_expected) + " m), " +
                        std::to_string(touch.refined_elements) + " coarse elements refined " +
                        std::to_string(touch.subdivision) + " x " + std::to_string(touch.subdivision) +
                        ", patch step dt/" + std::to_string(r.max_substeps) + " while refined; clone masses " +
                        format_short(touch.mass_main) + " / " + format_short(touch.mass_target) + " kg/m",
                    "radius = c dt2 to 1e-12; >= 1 element refined",
                    std::fabs(touch.radius - r_expected) < 1e-12 * r_expected && touch.refined_elements >= 1});
  const double v14c = r.peak_node_vj_at_fig14c;
  const bool peak_ok = v14c > 3.0 && std::fabs(v14c - 3.205) <= 0.1 * 3.205;
  claims.push_back({"B-6", "block j speeds up to about 3.2 m/s during the collision",
                    "'from 0.0 to 3.205 m/s' (Fig. 14c, 0.3400 s)",
                    "largest nodal v_x of j at 0.3400 s: " + format_short(v14c) + " m/s (" +
                        format_short(100.0 * (v14c - 3.205) / 3.205, 2) + " %); over the run " +
                        format_short(r.peak_node_vj) + " m/s at " + format_short(r.peak_node_vj_time, 5) +
                        " s; the block mean peaks at " + format_short(r.peak_mean_vj) +
                        " m/s (a mean above 3.0 would break energy). Nodal peaks depend on the mesh (" + kRebuilt + ")",
                    "nodal v_x at 0.3400 s > 3.0 m/s and within 10 % of 3.205 m/s", peak_ok});
  claims.push_back({"B-6", "the clone node separates after the collision", "Fig. 15a: separated at 0.3405 s",
                    "separation at " + format_short(t_sep, 6) + " s by " + sep_kind +
                        "; the rebuilt block size was chosen to match this time, so it is not an independent check",
                    "within 2 steps of 0.3405 s", t_sep > 0.0 && std::fabs(t_sep - 0.3405) <= 2.0 * dt + 1e-12});
  claims.push_back({"B-6", "block j ends with about block i's initial speed", "Fig. 16: slope of j ~ i's initial slope",
                    "v_j(0.5 s) = " + format_short(vj) + " m/s, v_i = " + format_short(vi) + " m/s (3.0 before)",
                    "|v_j - 3.0| < 5 % of 3.0", std::fabs(vj - 3.0) < 0.05 * 3.0});
  claims.push_back({"B-6", "momentum is conserved before and after the collision", "'momentum conservation applied'",
                    "p_x before " + format_short(r.p0, 8) + " kg m/s/m, after " + format_short(m.momentum().x, 8) +
                        "; max |p - p0| / p0 = " + format_short(r.worst_momentum, 3),
                    "< 1e-12", r.worst_momentum < 1e-12});
  claims.push_back({"B-6", "a little energy is lost in the collision", "'A little energy loss occurs'",
                    "E before " + format_short(r.e0, 7) + " J/m, after " + format_short(e_end.total(), 7) +
                        " J/m (kinetic " + format_short(e_end.kinetic, 6) + ", strain " +
                        format_short(e_end.strain, 4) + "): loss " + format_short(100.0 * e_loss / r.e0, 3) +
                        " % = clone impact (Eq. 5) " + format_short(impact, 4) + " + patch remaps " +
                        format_short(-remap, 4) + " + integration " + format_short(residual, 3) + " J/m",
                    "0 < loss < 5 % of E0; |integration residual| < 1 % of E0",
                    e_loss > 0.0 && e_loss < 0.05 * r.e0 && std::fabs(residual) < 0.01 * r.e0});
  claims.push_back({"B-6",
                    "subdivision makes the clone's inelastic loss small (Eq. 5: it falls with the contact-point mass)",
                    "Sect. 4.1: 'the loss decreases as the mass of the contact points decreases'",
                    "with subdivision: clone masses " + format_short(touch.mass_main) + " + " +
                        format_short(touch.mass_target) + " kg/m, loss " + format_short(touch.energy_loss) +
                        " J/m; without (coarse nodes): " + format_short(touch_c.mass_main) + " + " +
                        format_short(touch_c.mass_target) + " kg/m, loss " + format_short(touch_c.energy_loss) +
                        " J/m; v_j(0.5 s) " + format_short(vj) + " vs " + format_short(mc.block_velocity(1).x) + " m/s",
                    "loss with subdivision < loss without", touch.energy_loss < touch_c.energy_loss});
  repro::write_claims(repro::claims_path(out, kDriver), claims);
  progress("done");
  return 0;
}
