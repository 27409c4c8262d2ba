// Paper B Sect. 6, two prisms: the rows of the studies around the main run
// (the energy-matched patch deletion, the contact-point mass of Sect. 4.1,
// the mesh refinement).
#include <algorithm>
#include <cmath>

#include "repro/B_6_two_prisms/two_prisms.hpp"

namespace prisms {

using repro::format_short;

repro::Claim patch_deletion_row(const Result& matched, const Result& restricted) {
  const dda::cdem::CdemEnergyAccount& a = restricted.accounts.back();
  const dda::cdem::CdemEnergyAccount& b = matched.accounts.back();
  repro::Claim c = repro::measurement(
      "B-6",
      "(energy-matched patch deletion option, beyond the paper) energy lost at the patch deletion, beside the "
      "paper's restriction",
      "not stated (Sect. 5 deletes the patch after separation)",
      "deletion loss " + format_short(b.deletion_loss, 4) + " J/m (" +
          format_short(100.0 * b.deletion_loss / b.initial, 3) + " % of E0) against " +
          format_short(a.deletion_loss, 4) + " J/m with the paper's restriction; worst |other| / E0 " +
          format_short(worst_energy_remainder(matched.accounts), 3) + " (" +
          format_short(worst_energy_remainder(restricted.accounts), 3) + "); v_j(0.5 s) " +
          format_short(matched.vj, 6) + " m/s (" + format_short(restricted.vj, 6) + "), j's largest nodal v_x over the run " +
          format_short(matched.peak_node_vj, 4) + " m/s (" + format_short(restricted.peak_node_vj, 4) + "); strain at 0.5 s " +
          format_short(b.strain, 4) + " J/m (" + format_short(a.strain, 4) + "); max |p - p0| / p0 " +
          format_short(matched.worst_momentum, 3),
      "the restriction's energy drop handed to the coarse velocity deviations and stresses (each scaled by at most "
      "3): the fine-scale energy becomes coarse vibration, not conserved by a projection; the rest is where a "
      "factor reached its cap");
  c.key = "option-patch-deletion-energy-matched";
  c.scope = repro::Scope::kOption;
  return c;
}

repro::Claim contact_mass_row(const std::vector<MassPoint>& pts, const Result& coarse, double m_node) {
  std::string text;
  double worst = 0.0;
  for (const MassPoint& p : pts) {
    text += (text.empty() ? "" : "; ") + std::string("k ") + std::to_string(p.k) + ": masses " +
            format_short(p.mass_main) + " / " + format_short(p.mass_target) + " kg/m, loss " +
            format_short(p.loss, 6) + " J/m (Eq. 5 " + format_short(p.loss_eq5, 6) + ")";
    worst = std::max(worst, std::fabs(p.loss - p.loss_eq5) / p.loss_eq5);
  }
  repro::Claim c{"B-6", "the touch's loss follows Eq. 5 over a range of contact-point masses and falls with the mass",
                 "'the loss in mechanical energy decreases as the mass of the contact points decreases, and "
                 "∆E is zero if the mass is zero' (Sect. 4.1)",
                 text + "; coarse nodes (no subdivision): " + format_short(coarse.touch.mass_main) + " / " +
                     format_short(coarse.touch.mass_target) + " kg/m, loss " +
                     format_short(coarse.touch.energy_loss, 6) + " J/m; worst |loss - Eq. 5| / Eq. 5 " +
                     format_short(worst, 3) + "; the mass is set through the mesh (k), so 0 is a limit, not a run; "
                     "on the in-place option (the only mode that sets the contact points' mass), masses as "
                     "fractions of the in-place run's touching node (" + format_short(m_node) + " kg/m); table "
                     "contact_mass.csv",
                 "|loss - Eq. 5| <= " + format_short(kEq5Agreement) +
                     " Eq. 5 at each mass; loss strictly falls with the reduced mass",
                 touch_loss_follows_eq5(pts)};
  c.control = repro::control_test(kTestContactMass);
  c.scope = repro::Scope::kPaper;  // Sect. 4.1's statement, tested where the mass can be set
  return c;
}

std::vector<repro::Claim> mesh_rows(const std::vector<MeshPoint>& mesh) {
  std::vector<repro::Claim> claims;
  std::string vj_text, node_text, meeting;
  std::vector<double> vjs;
  for (const MeshPoint& p : mesh) {
    vj_text += (vj_text.empty() ? "" : ", ") + std::to_string(p.divisions) + ": " + format_short(p.vj, 5);
    node_text += (node_text.empty() ? "" : ", ") + std::to_string(p.divisions) + ": " + format_short(p.node_vj_fig14c, 4);
    if (fig14c_met(p.node_vj_fig14c)) meeting += (meeting.empty() ? "" : ", ") + std::to_string(p.divisions);
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
      "v_j(0.5 s) in m/s by divisions " + vj_text + "; " + order_text(observed_order(vjs)) + "; the paper's " +
          std::to_string(kPaperDivisions) + "-division mesh is " +
          format_short(100.0 * (mesh.front().vj - finest) / finest, 3) + " % off the finest" + mesh_mode,
      "a converged quantity (the block average after the collision)"));
  claims.back().scope = repro::Scope::kExtension;
  claims.push_back(fig14c_converged_row(mesh));
  claims.back().measured += mesh_mode;
  claims.back().scope = repro::Scope::kPaper;
  claims.push_back(repro::measurement(
      "B-6", "mesh refinement: j's largest nodal velocity at 0.3400 s (the quantity of Fig. 14c's 3.205 m/s)",
      "'from 0.0 to 3.205 m/s' (Fig. 14c)",
      "nodal v_x in m/s by divisions " + node_text + "; the Fig. 14c row's criterion holds for divisions " +
          (meeting.empty() ? std::string("none") : meeting) + mesh_mode,
      "a nodal value in the wave, not a converged quantity: where the Fig. 14c row passes it tells the mesh"));
  claims.back().scope = repro::Scope::kExtension;
  return claims;
}

}  // namespace prisms
