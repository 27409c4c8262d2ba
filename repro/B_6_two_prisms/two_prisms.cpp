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
#include <stdexcept>
#include <string>
#include <vector>

#include "dda/cdem/model.hpp"
#include "dda/cdem/scenes.hpp"
#include "repro/B_6_two_prisms/output.hpp"
#include "repro/B_6_two_prisms/two_prisms.hpp"
#include "repro/common/common.hpp"
#include "repro/common/driver.hpp"

namespace {
const char* kDriver = "B_6_two_prisms";
constexpr int kMeshDivisions[] = {2, 4, 8, 16, 32};  // 4 to 4096 CST elements per block; 32: ~25 s

// The prisms with options `o`, meshed with `divisions`, stepped with `dt`.
dda::cdem::CdemScene prisms_scene(int divisions, double dt, const dda::cdem::CdemOptions& o) {
  dda::cdem::CdemScene s = dda::cdem::two_prisms(divisions, o);
  s.dt = dt;
  return s;
}

// Every run of the driver with `divisions` and `dt`: the data files under
// `dir` and the claim rows.
std::vector<repro::Claim> run_all(int divisions, double dt, const std::string& dir, const repro::Progress& progress) {
  using repro::format_short;
  // Rows of a run off the paper's mesh or dt say so.
  const std::string run_note =
      divisions == prisms::kPaperDivisions && dt == prisms::kPaperDt
          ? std::string()
          : " [NOT THE PAPER'S SETTINGS: --divisions " + std::to_string(divisions) + ", --dt " + format_short(dt) + "]";

  // The main run, Sect. 5 as written (the default, SubdivisionMode::kSubModel): Figs. 13-16.
  dda::cdem::CdemOptions opt;
  opt.capture_touch_snapshots = true;
  prisms::FigureFiles figures(dir, opt);
  const prisms::Result r = prisms::simulate(prisms_scene(divisions, dt, opt), [&](const dda::cdem::Model& m) {
    if (m.step_count() == 0)
      progress("mesh: " + std::to_string(m.node_count()) + " nodes, critical step " + format_short(m.critical_dt()) +
               " s (dt " + format_short(m.dt()) + " s)");
    figures.on_step(m);
  });
  figures.commit(r);
  progress("touch " + format_short(r.touch.time, 8) + " s, separation " + format_short(r.t_sep, 6) + " s, v_i " +
           format_short(r.vi) + ", v_j " + format_short(r.vj) + " m/s");

  // The same collision with coarse clone nodes (no subdivision): the size of
  // the Eq. 5 loss with the coarse lumped masses.
  dda::cdem::CdemOptions coarse_opt;
  coarse_opt.subdivision = false;
  prisms::History hist_c(dir + "history_nosub.csv", "Paper B Sect. 6, two prisms, clone node without subdivision; ",
                         coarse_opt);
  const prisms::Result coarse =
      prisms::simulate(prisms_scene(divisions, dt, coarse_opt), [&](const dda::cdem::Model& m) { hist_c.row(m); });
  hist_c.commit();

  // Mesh refinement: the same collision on finer meshes (dt with h).
  std::vector<prisms::MeshPoint> mesh;
  for (int d : kMeshDivisions) mesh.push_back(prisms::mesh_point(d));
  prisms::write_mesh_study(dir + "mesh_study.csv", mesh);

  // The paper's rows on the main run; beside each that fails, the same claim
  // on the in-place refinement (kInPlace, an option beyond the paper).
  const prisms::ModeRun inplace = prisms::run_mode(dda::cdem::SubdivisionMode::kInPlace, divisions, dt);
  std::vector<repro::Claim> claims = prisms::flipped_rows(r, inplace.r, coarse);

  // Sect. 5 as written against the in-place refinement, and on the refinement study's meshes.
  const prisms::ModeRun sub = prisms::run_mode(dda::cdem::SubdivisionMode::kSubModel, divisions, dt);
  progress("sub-model: v_j " + format_short(sub.r.vj) + " m/s, k " + std::to_string(sub.k) + ", n " +
           std::to_string(sub.n) + "; in-place v_j " + format_short(inplace.r.vj) + " m/s");
  for (const repro::Claim& c : prisms::mode_rows(sub, inplace, coarse)) claims.push_back(c);
  std::vector<prisms::SubMeshPoint> sub_mesh;
  for (int d : kMeshDivisions) sub_mesh.push_back(prisms::submodel_mesh_point(d));
  prisms::write_submodel_mesh_study(dir + "mesh_study_submodel.csv", sub_mesh);
  claims.push_back(prisms::submodel_mesh_row(sub_mesh));

  // Beyond the paper: the patch deletion's energy handed to the coarse mesh
  // (CdemOptions::patch_deletion = kEnergyMatched, an in-place option),
  // beside the paper's restriction (the in-place run).
  dda::cdem::CdemOptions matched_opt;
  matched_opt.patch_deletion = dda::cdem::PatchDeletion::kEnergyMatched;
  matched_opt.subdivision_mode = dda::cdem::SubdivisionMode::kInPlace;
  claims.push_back(prisms::patch_deletion_row(prisms::simulate(prisms_scene(divisions, dt, matched_opt)), inplace.r));

  // Sect. 4.1: the contact points' mass sets the touch's loss
  // (CdemOptions::contact_point_mass); masses as fractions of the touching
  // node's coarse lumped mass. contact_point_mass is an in-place option
  // (refused with the sub-model): the touching node is the in-place run's.
  const double m_node = prisms::touching_node_mass(inplace.r);
  std::vector<prisms::MassPoint> pts;
  for (double f : prisms::kMassFractions)
    pts.push_back(prisms::contact_mass_point(f * m_node, prisms::kMassMaxSubdivision));
  prisms::write_contact_mass(dir + "contact_mass.csv", pts, coarse.touch.energy_loss);
  claims.push_back(prisms::contact_mass_row(pts, coarse, m_node));

  for (repro::Claim& c : claims) c.claim += run_note;
  // The mesh-refinement rows (the study's own meshes and steps).
  for (const repro::Claim& c : prisms::mesh_rows(mesh)) claims.push_back(c);
  return claims;
}

}  // namespace

int main(int argc, char** argv) {
  return repro::driver_main(
      argc, argv, {kDriver, "B-6 two prisms", "Paper B Sect. 6 (Figs. 12-16): two triangular prisms colliding."},
      {{"--divisions", "N", "mesh divisions per block edge (default 2: the paper's example here)", true},
       {"--dt", "S", "time step, s (default 5e-4: the paper's)", false}},
      [](const repro::Driver& d) {
        const int divisions = d.whole("--divisions", prisms::kPaperDivisions);
        const double dt = d.number("--dt", prisms::kPaperDt);
        if (divisions < 1 || !(dt > 0.0)) throw std::invalid_argument("--divisions must be >= 1 and --dt > 0");
        const std::vector<repro::Claim> claims = run_all(divisions, dt, d.out + "/data/" + kDriver + "/", d.progress);
        repro::write_claims(repro::claims_path(d.out, kDriver), claims);
        d.progress("done");
        return 0;
      });
}
