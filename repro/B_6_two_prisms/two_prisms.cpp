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
// Output under <out>/data/B_6_two_prisms/: history.csv (Fig. 16, with the
// energy account's columns per row; also the run without subdivision,
// history_nosub.csv), snapshots.csv and clones.csv
// (Figs. 13-15), events.csv (touches and separations), mesh_study.csv (the
// same collision on meshes of 2 to 32 divisions, dt scaled with h: j's
// block-average velocity converges, the nodal peak of Fig. 14c does not),
// contact_mass.csv (Sect. 4.1: the touch's loss against Eq. 5 over a range
// of contact-point masses); claims in <out>/claims/B_6_two_prisms.csv.
// Beyond the paper, as rows beside its method: the energy account per row,
// the patch deletion with CdemOptions::patch_deletion = kEnergyMatched.
// The main run (history.csv, snapshots.csv, clones.csv, events.csv: Figs.
// 13-16) is Sect. 5 as written (SubdivisionMode::kSubModel, the separate
// sub-model of the colliding elements, the library default); beside each of
// its rows that fails, the same claim on the in-place refinement (kInPlace,
// an option beyond the paper). Sect. 5 as written against the in-place
// refinement: touch time, energy,
// momentum, j's velocities and cost, in rows of their own; the sub-model on
// the refinement study's meshes in mesh_study_submodel.csv.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "dda/cdem/model.hpp"
#include "dda/cdem/scenes.hpp"
#include "repro/B_6_two_prisms/two_prisms.hpp"
#include "repro/common/common.hpp"
#include "repro/common/options.hpp"

namespace {

using dda::cdem::Model;
using prisms::kRebuilt;
using repro::format_short;

const char* kDriver = "B_6_two_prisms";
constexpr int kMeshDivisions[] = {2, 4, 8, 16, 32};  // 4 to 4096 CST elements per block; 32: ~25 s

std::vector<std::string> history_header() {
  return {"time",        "ux_i",         "ux_j",    "vx_i",           "vx_j",
          "vx_max_j",    "momentum_x",   "kinetic", "strain",         "total_energy",
          "impact_loss", "remap_change", "clones",  "patch_elements", "patch_substeps",
          // the energy account (Model::energy_account), J/m
          "energy_initial", "gravity", "touch_loss", "touch_loss_eq5", "refine_loss", "deletion_loss", "energy_other"};
}

// The subdivision mode a run used, in words, for the data files' comment
// line "subdivision mode: ..." (the figures label the curves with it).
std::string subdivision_mode_text(const dda::cdem::CdemOptions& o) {
  if (!o.subdivision) return "none (clone node of the coarse nodes)";
  switch (o.subdivision_mode) {
    case dda::cdem::SubdivisionMode::kSubModel:
      return o.submodel_transfer == dda::cdem::SubModelTransfer::kWholeElement
                 ? "sub-model of the colliding elements (Paper B Sect. 5; step 5 returns every sub-node's force)"
                 : "sub-model of the colliding elements (Paper B Sect. 5; step 5 read literally)";
    case dda::cdem::SubdivisionMode::kInPlace:
      return "in-place refinement (beyond the paper)";
  }
  return "unnamed mode";
}

void history_row(repro::CsvWriter& csv, const Model& m) {
  const dda::cdem::CdemEnergy e = m.energy();
  const dda::cdem::CdemEnergyAccount a = m.energy_account();
  csv.row({m.time(), m.block_displacement(0).x, m.block_displacement(1).x, m.block_velocity(0).x, m.block_velocity(1).x,
           m.block_max_velocity_x(1), m.momentum().x, e.kinetic, e.strain, e.total(), m.impact_energy_loss(),
           m.remap_energy_change(), static_cast<double>(m.clones().size()),
           static_cast<double>(m.active_elements(true)), static_cast<double>(m.patch_substeps()), a.initial,
           a.gravity, a.touch_loss, a.touch_loss_eq5, a.refine_loss, a.deletion_loss, a.other});
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

int main(int argc, char** argv) try {
  repro::check_command_line(argc, argv, "Paper B Sect. 6 (Figs. 12-16): two triangular prisms colliding.",
                            {{"--divisions", "N", "mesh divisions per block edge (default 2: the paper's example here)", true},
                             {"--dt", "S", "time step, s (default 5e-4: the paper's)", false}});
  const int divisions = repro::option_int(argc, argv, "--divisions", prisms::kPaperDivisions);
  const double dt = repro::option_number(argc, argv, "--dt", prisms::kPaperDt);
  if (divisions < 1 || !(dt > 0.0)) throw std::invalid_argument("--divisions must be >= 1 and --dt > 0");
  // Rows of a run off the paper's mesh or dt say so.
  const std::string run_note =
      divisions == prisms::kPaperDivisions && dt == prisms::kPaperDt
          ? std::string()
          : " [NOT THE PAPER'S SETTINGS: --divisions " + std::to_string(divisions) + ", --dt " + format_short(dt) + "]";
  const std::string out = repro::out_dir(argc, argv);
  const repro::Progress progress("B-6 two prisms");
  const std::string dir = out + "/data/" + kDriver + "/";

  dda::cdem::CdemOptions opt;  // the default: Sect. 5 as written (SubdivisionMode::kSubModel)
  opt.capture_touch_snapshots = true;
  dda::cdem::CdemScene scene = dda::cdem::two_prisms(divisions, opt);
  scene.dt = dt;

  repro::CsvWriter hist(dir + "history.csv", history_header(),
                        {std::string("Paper B Sect. 6, two prisms, clone node + subdivision; ") + kRebuilt,
                         "subdivision mode: " + subdivision_mode_text(opt)});
  repro::CsvWriter tris(dir + "snapshots.csv",
                        {"snapshot", "time", "label", "block", "fine", "x0", "y0", "x1", "y1", "x2", "y2", "vx", "vy"},
                        {kRebuilt, "subdivision mode: " + subdivision_mode_text(opt)});
  repro::CsvWriter clones(dir + "clones.csv", {"snapshot", "time", "label", "x", "y"});

  // Snapshot times: Fig. 13 (start, touch), Fig. 14 a-c, Fig. 15 a-b; and
  // the last step before the first separation ("last step with the clone").
  struct Shot {
    double time;
    std::string label;
  };
  const std::vector<Shot> shots = {{0.0, "Fig. 13: t = 0"},        {0.3335, "Fig. 14a: 0.3335 s"},
                                   {0.3340, "Fig. 14b: 0.3340 s"}, {0.3400, "Fig. 14c: 0.3400 s"},
                                   {0.3405, "Fig. 15a: 0.3405 s"}, {0.4960, "Fig. 15b: 0.4960 s"}};
  std::size_t next_shot = 0;
  int shot_id = 0;
  dda::cdem::Snapshot previous;
  bool before_separation = true;
  std::vector<dda::cdem::TouchRecord> touches;
  std::vector<dda::cdem::SeparationRecord> separations;
  const prisms::Result r = prisms::simulate(scene, [&](const Model& m) {
    if (m.step_count() == 0)
      progress("mesh: " + std::to_string(m.node_count()) + " nodes, critical step " + format_short(m.critical_dt()) +
               " s (dt " + format_short(m.dt()) + " s)");
    if (before_separation && !m.separations().empty()) {
      before_separation = false;
      write_snapshot(tris, clones, shot_id++, "last step with the clone: " + format_short(previous.time, 5) + " s",
                     previous);
    }
    if (before_separation) previous = m.snapshot();
    history_row(hist, m);
    while (next_shot < shots.size() && std::fabs(m.time() - shots[next_shot].time) < 0.5 * m.dt())
      write_snapshot(tris, clones, shot_id++, shots[next_shot++].label, m.snapshot());
    if (m.touches().size() != touches.size()) touches = m.touches();
    if (m.separations().size() != separations.size()) separations = m.separations();
  });
  write_snapshot(tris, clones, shot_id++, "Fig. 13: touch " + format_short(r.touch.time, 6) + " s",
                 r.touch.snapshot.at(0));

  repro::CsvWriter events(dir + "events.csv", {"kind", "time", "detail_a", "detail_b", "detail_c", "detail_d"});
  for (const auto& t : touches)
    events.row(std::vector<std::string>{"touch", repro::format_full(t.time), "dt1=" + format_short(t.dt1, 6),
                                        "dt2=" + format_short(t.dt2, 6), "k=" + std::to_string(t.subdivision),
                                        "loss=" + format_short(t.energy_loss, 6)});
  for (const auto& s : separations)
    events.row(std::vector<std::string>{"separation", repro::format_full(s.time),
                                        s.criterion == dda::cdem::SeparationCriterion::kTension ? "tension" : "shear",
                                        "Fn=" + format_short(s.normal_force, 6), "Fs=" + format_short(s.shear_force, 6),
                                        "limit=" + format_short(s.limit, 6)});
  hist.commit();
  tris.commit();
  clones.commit();
  events.commit();
  progress("touch " + format_short(r.touch.time, 8) + " s, separation " + format_short(r.t_sep, 6) + " s, v_i " +
           format_short(r.vi) + ", v_j " + format_short(r.vj) + " m/s");

  // The same collision with coarse clone nodes (no subdivision): the size of
  // the Eq. 5 loss with the coarse lumped masses.
  dda::cdem::CdemOptions coarse_opt;
  coarse_opt.subdivision = false;
  repro::CsvWriter hist_c(dir + "history_nosub.csv", history_header(),
                          {std::string("Paper B Sect. 6, two prisms, clone node without subdivision; ") + kRebuilt,
                           "subdivision mode: " + subdivision_mode_text(coarse_opt)});
  dda::cdem::CdemScene coarse_scene = dda::cdem::two_prisms(divisions, coarse_opt);
  coarse_scene.dt = dt;
  const prisms::Result coarse = prisms::simulate(coarse_scene, [&](const Model& m) { history_row(hist_c, m); });
  hist_c.commit();

  // Mesh refinement: the same collision on finer meshes (dt with h).
  std::vector<prisms::MeshPoint> mesh;
  repro::CsvWriter mesh_csv(dir + "mesh_study.csv", {"divisions", "dt", "vj_block_average", "vj_node_at_0.34", "t_sep"},
                            {std::string("Paper B Sect. 6, two prisms on finer meshes, dt scaled with the element "
                                         "size (c dt / h fixed); ") + kRebuilt});
  for (int d : kMeshDivisions) {
    mesh.push_back(prisms::mesh_point(d));
    const prisms::MeshPoint& p = mesh.back();
    mesh_csv.row({static_cast<double>(d), p.dt, p.vj, p.node_vj_fig14c, p.t_sep});
  }
  mesh_csv.commit();
  // Sect. 5 as written (SubdivisionMode::kSubModel, the main run r) beside
  // the in-place refinement (kInPlace, an option beyond the paper): the same
  // prisms in both modes; the in-place rows beside the sub-model's failing ones.
  const prisms::ModeRun inplace = prisms::run_mode(dda::cdem::SubdivisionMode::kInPlace, divisions, dt);
  std::vector<repro::Claim> claims = prisms::flipped_rows(r, inplace.r, coarse);
  {
    const prisms::ModeRun sub = prisms::run_mode(dda::cdem::SubdivisionMode::kSubModel, divisions, dt);
    progress("sub-model: v_j " + format_short(sub.r.vj) + " m/s, k " + std::to_string(sub.k) + ", n " +
             std::to_string(sub.n) + "; in-place v_j " + format_short(inplace.r.vj) + " m/s");
    for (const repro::Claim& c : prisms::mode_rows(sub, inplace, coarse)) claims.push_back(c);
    std::vector<prisms::SubMeshPoint> sub_mesh;
    repro::CsvWriter sub_csv(dir + "mesh_study_submodel.csv",
                             {"divisions", "dt", "vj_block_average", "vj_node_at_0.34", "t_sep", "momentum_drift",
                              "stopped"},
                             {std::string("Paper B Sect. 5 as written (sub-model) on the refinement study's meshes, dt "
                                          "scaled with the element size; ") + kRebuilt});
    for (int d : kMeshDivisions) {
      sub_mesh.push_back(prisms::submodel_mesh_point(d));
      const prisms::SubMeshPoint& p = sub_mesh.back();
      const bool ok = p.stopped.empty();  // a stopped run's fields are no data
      auto num = [&](double x) { return ok ? repro::format_full(x) : std::string(); };
      sub_csv.row(std::vector<std::string>{std::to_string(d), repro::format_full(p.dt), num(p.vj), num(p.node_vj_fig14c),
                                           num(p.t_sep), num(p.momentum), ok ? "" : "stopped"});
    }
    sub_csv.commit();
    claims.push_back(prisms::submodel_mesh_row(sub_mesh));
  }
  // Beyond the paper: the patch deletion's energy handed
  // to the coarse mesh (CdemOptions::patch_deletion = kEnergyMatched),
  // beside the paper's restriction above.
  {
    dda::cdem::CdemOptions matched_opt;
    matched_opt.patch_deletion = dda::cdem::PatchDeletion::kEnergyMatched;
    matched_opt.subdivision_mode = dda::cdem::SubdivisionMode::kInPlace;  // patch_deletion is an in-place option
    dda::cdem::CdemScene matched_scene = dda::cdem::two_prisms(divisions, matched_opt);
    matched_scene.dt = dt;
    const prisms::Result matched = prisms::simulate(matched_scene);
    const prisms::Result& restricted = inplace.r;  // the in-place refinement with the paper's restriction
    const dda::cdem::CdemEnergyAccount& a = restricted.accounts.back();
    const dda::cdem::CdemEnergyAccount& b = matched.accounts.back();
    claims.push_back(repro::measurement(
        "B-6",
        "(energy-matched patch deletion option, beyond the paper) energy lost at the patch deletion, beside the "
        "paper's restriction",
        "not stated (Sect. 5 deletes the patch after separation)",
        "deletion loss " + format_short(b.deletion_loss, 4) + " J/m (" +
            format_short(100.0 * b.deletion_loss / b.initial, 3) + " % of E0) against " +
            format_short(a.deletion_loss, 4) + " J/m with the paper's restriction; worst |other| / E0 " +
            format_short(prisms::worst_energy_remainder(matched.accounts), 3) + " (" +
            format_short(prisms::worst_energy_remainder(restricted.accounts), 3) + "); v_j(0.5 s) " +
            format_short(matched.vj, 6) + " m/s (" + format_short(restricted.vj, 6) + "), j's largest nodal v_x over the run " +
            format_short(matched.peak_node_vj, 4) + " m/s (" + format_short(restricted.peak_node_vj, 4) + "); strain at 0.5 s " +
            format_short(b.strain, 4) + " J/m (" + format_short(a.strain, 4) + "); max |p - p0| / p0 " +
            format_short(matched.worst_momentum, 3),
        "the restriction's energy drop handed to the coarse velocity deviations and stresses (each scaled by at most "
        "3): the fine-scale energy becomes coarse vibration, not conserved by a projection; the rest is where a "
        "factor reached its cap"));
    claims.back().key = "option-patch-deletion-energy-matched";
    claims.back().scope = repro::Scope::kOption;
  }
  // Sect. 4.1: the contact points' mass sets the touch's loss
  // (CdemOptions::contact_point_mass); masses as fractions of the touching
  // node's coarse lumped mass. contact_point_mass is an in-place option
  // (refused with the sub-model): the touching node is the in-place run's.
  {
    const double m_node = prisms::touching_node_mass(inplace.r);
    std::vector<prisms::MassPoint> pts;
    repro::CsvWriter mass_csv(dir + "contact_mass.csv",
                              {"contact_point_mass", "k", "mass_main", "mass_target", "loss", "loss_eq5",
                               "loss_over_coarse"},
                              {"Paper B Sect. 4.1: one touch of the prisms with the contact points' mass set through "
                               "the subdivision k (CdemOptions::contact_point_mass); masses kg/m, losses J/m; "
                               "loss_over_coarse: against the touch of coarse nodes (no subdivision); " +
                               std::string(kRebuilt)});
    for (double f : prisms::kMassFractions) {
      pts.push_back(prisms::contact_mass_point(f * m_node, prisms::kMassMaxSubdivision));
      const prisms::MassPoint& p = pts.back();
      mass_csv.row({p.target, static_cast<double>(p.k), p.mass_main, p.mass_target, p.loss, p.loss_eq5,
                    p.loss / coarse.touch.energy_loss});
    }
    mass_csv.commit();
    std::string text;
    double worst = 0.0;
    for (const prisms::MassPoint& p : pts) {
      text += (text.empty() ? "" : "; ") + std::string("k ") + std::to_string(p.k) + ": masses " +
              format_short(p.mass_main) + " / " + format_short(p.mass_target) + " kg/m, loss " +
              format_short(p.loss, 6) + " J/m (Eq. 5 " + format_short(p.loss_eq5, 6) + ")";
      worst = std::max(worst, std::fabs(p.loss - p.loss_eq5) / p.loss_eq5);
    }
    claims.push_back({"B-6", "the touch's loss follows Eq. 5 over a range of contact-point masses and falls with the mass",
                      "'the loss in mechanical energy decreases as the mass of the contact points decreases, and "
                      "∆E is zero if the mass is zero' (Sect. 4.1)",
                      text + "; coarse nodes (no subdivision): " + format_short(coarse.touch.mass_main) + " / " +
                          format_short(coarse.touch.mass_target) + " kg/m, loss " +
                          format_short(coarse.touch.energy_loss, 6) + " J/m; worst |loss - Eq. 5| / Eq. 5 " +
                          format_short(worst, 3) + "; the mass is set through the mesh (k), so 0 is a limit, not a run; "
                          "on the in-place option (the only mode that sets the contact points' mass), masses as "
                          "fractions of the in-place run's touching node (" + format_short(m_node) + " kg/m); table "
                          "contact_mass.csv",
                      "|loss - Eq. 5| <= " + format_short(prisms::kEq5Agreement) +
                          " Eq. 5 at each mass; loss strictly falls with the reduced mass",
                      prisms::touch_loss_follows_eq5(pts)});
    claims.back().control = repro::control_test(prisms::kTestContactMass);
    claims.back().scope = repro::Scope::kPaper;  // Sect. 4.1's statement, tested where the mass can be set
  }
  for (repro::Claim& c : claims) c.claim += run_note;
  std::string vj_text, node_text, meeting;
  std::vector<double> vjs;
  for (const prisms::MeshPoint& p : mesh) {
    vj_text += (vj_text.empty() ? "" : ", ") + std::to_string(p.divisions) + ": " + format_short(p.vj, 5);
    node_text += (node_text.empty() ? "" : ", ") + std::to_string(p.divisions) + ": " + format_short(p.node_vj_fig14c, 4);
    if (prisms::fig14c_met(p.node_vj_fig14c)) meeting += (meeting.empty() ? "" : ", ") + std::to_string(p.divisions);
    vjs.push_back(p.vj);
  }
  const double finest = mesh.back().vj;
  const std::string mesh_mode =
      "; the refinement study of the in-place option (table mesh_study.csv); the sub-model has its own study "
      "(mesh_study_submodel.csv and its mesh-refinement row)";
  auto order_text = [](double p) {
    return p > 0.0 ? "observed order over the three finest " + format_short(p, 3)
                   : std::string("no observed order: the last differences do not shrink (the separation step moves "
                                 "with the mesh)");
  };
  claims.push_back(repro::measurement(
      "B-6", "mesh refinement: j's block-average velocity after separation (divisions per block edge, dt with h)",
      "\"the velocity of block j after collision is approximately equal to the initial velocity of block i\"",
      "v_j(0.5 s) in m/s by divisions " + vj_text + "; " + order_text(prisms::observed_order(vjs)) + "; the paper's " + std::to_string(prisms::kPaperDivisions) +
          "-division mesh is " + format_short(100.0 * (mesh.front().vj - finest) / finest, 3) + " % off the finest" + mesh_mode,
      "a converged quantity (the block average after the collision)"));
  claims.back().scope = repro::Scope::kExtension;
  claims.push_back(prisms::fig14c_converged_row(mesh));
  claims.back().measured += mesh_mode;
  claims.back().scope = repro::Scope::kPaper;
  claims.push_back(repro::measurement(
      "B-6", "mesh refinement: j's largest nodal velocity at 0.3400 s (the quantity of Fig. 14c's 3.205 m/s)",
      "'from 0.0 to 3.205 m/s' (Fig. 14c)",
      "nodal v_x in m/s by divisions " + node_text + "; the Fig. 14c row's criterion holds for divisions " +
          (meeting.empty() ? std::string("none") : meeting) + mesh_mode,
      "a nodal value in the wave, not a converged quantity: where the Fig. 14c row passes it tells the mesh"));
  claims.back().scope = repro::Scope::kExtension;
  repro::write_claims(repro::claims_path(out, kDriver), claims);
  progress("done");
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "B_6_two_prisms: error: %s\n", e.what());
  return 1;
}
