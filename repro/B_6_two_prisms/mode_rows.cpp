// Paper B Sect. 6, two prisms: Sect. 5's sub-model (our reading) against the
// in-place refinement, rows beyond the paper's own statements.
#include "repro/B_6_two_prisms/two_prisms.hpp"

namespace prisms {

std::vector<repro::Claim> mode_rows(const ModeRun& sub, const ModeRun& inplace, const Result& coarse) {
  using repro::format_short;
  std::vector<repro::Claim> claims;
  const Result& a = sub.r;
  const Result& b = inplace.r;
  claims.push_back({"B-6",
                    "Sect. 5's sub-model (our reading): the touch is at the two-stage touch time, as with the "
                    "in-place refinement",
                    "0.3333 s (1 m at 3.0 m/s); Sect. 5's sub-model leaves the coarse contact as it is",
                    "sub-model t = " + format_short(a.touch.time, 12) + " s, in-place t = " +
                        format_short(b.touch.time, 12) + " s, without subdivision " + format_short(coarse.touch.time, 12) +
                        " s",
                    "|t - 1/3| < 1e-12 s in both modes", touch_time_exact(a.touch) && touch_time_exact(b.touch)});
  claims.back().control = repro::control_test(kTestSubTouch);
  claims.back().key = "submodel-touch";
  claims.push_back({"B-6",
                    "Sect. 5's sub-model (our reading): the energy never grows above its initial value",
                    "'A little energy loss occurs'",
                    "max (kinetic + strain) / E0 over the rows: sub-model " + format_short(max_energy_ratio(a.accounts), 10) +
                        " (the in-place refinement beside, beyond the paper: " +
                        format_short(max_energy_ratio(b.accounts), 10) + ", its patch steps' transient)",
                    "<= 1 + 1e-9 with the sub-model (Eq. 4 and the deletion remove energy; central differences below "
                    "the critical step add none)",
                    energy_never_grows(a.accounts)});
  claims.back().control = repro::control_test(kTestSubEnergy);
  claims.back().key = "submodel-energy-never-grows";
  repro::explain_fail(claims.back(), repro::Root::kSubModelReading,
                      "the sub-model as we read Sect. 5 steps (1)-(5) adds energy: max (kinetic + strain) / E0 " +
                          format_short(max_energy_ratio(a.accounts), 10) + ", max |p - p0| / p0 " +
                          format_short(a.worst_momentum, 3));
  claims.push_back({"B-6", "Sect. 5's sub-model (our reading): momentum is conserved through the collision",
                    "'momentum conservation applied'",
                    "max |p - p0| / p0: sub-model " + format_short(a.worst_momentum, 3) + " (k " + std::to_string(sub.k) +
                        ", n " + std::to_string(sub.n) + "), in-place " + format_short(b.worst_momentum, 3) +
                        ", without subdivision " + format_short(coarse.worst_momentum, 3),
                    "< 1e-12 (round-off) with the sub-model", momentum_conserved(a)});
  claims.back().control = repro::control_test(kTestSubMomentum);
  claims.back().key = "submodel-momentum";
  repro::explain_fail(claims.back(), repro::Root::kSubModelReading,
                      "Sect. 5 step 5: the sub-model's forces returned to the coarse nodes do not sum to zero while "
                      "it lives: max |p - p0| / p0 " + format_short(a.worst_momentum, 3) + " (k " +
                          std::to_string(sub.k) + ", n " + std::to_string(sub.n) +
                          "); the literal reading (the forces on the prescribed sub-nodes only) returns the free "
                          "sub-nodes' inertia, the default returns the element forces on every sub-node");
  auto worst_other = [](const Result& r) { return worst_energy_remainder(r.accounts); };
  claims.push_back(repro::measurement(
      "B-6", "Sect. 5's sub-model (our reading) against the in-place refinement: block j's velocities and the "
      "separation",
      "Fig. 14c: j 'from 0.0 to 3.205 m/s' (0.3400 s); Fig. 15a: separated at 0.3405 s; Fig. 16: j ends with about "
      "i's initial 3.0 m/s",
      "j's block-average v_x at 0.5 s: sub-model " + format_short(a.vj, 5) + ", in-place " + format_short(b.vj, 5) +
          ", without subdivision " + format_short(coarse.vj, 5) + " m/s; j's largest nodal v_x at 0.3400 s: " +
          format_short(a.peak_node_vj_at_fig14c, 4) + ", " + format_short(b.peak_node_vj_at_fig14c, 4) + ", " +
          format_short(coarse.peak_node_vj_at_fig14c, 4) + " m/s; separation at " + format_short(a.t_sep, 6) + ", " +
          format_short(b.t_sep, 6) + ", " + format_short(coarse.t_sep, 6) + " s; i at 0.5 s " + format_short(a.vi, 4) +
          ", " + format_short(b.vi, 4) + ", " + format_short(coarse.vi, 4) + " m/s",
      "the sub-model and the option beyond the paper on the same rebuilt prisms (" + std::string(kRebuilt) + ")"));
  claims.back().key = "submodel-vs-inplace-velocities";
  claims.push_back(repro::measurement(
      "B-6", "Sect. 5's sub-model (our reading) against the in-place refinement: energy account, momentum and cost",
      "not stated",
      "worst |other| / E0 over the rows: sub-model " + format_short(worst_other(a), 3) + ", in-place " +
          format_short(worst_other(b), 3) + ", without subdivision " + format_short(worst_other(coarse), 3) +
          "; at 0.5 s E / E0 " + format_short((a.e_end.total()) / a.e0, 4) + ", " + format_short(b.e_end.total() / b.e0, 4) +
          ", " + format_short(coarse.e_end.total() / coarse.e0, 4) + "; sub-model deletion loss " +
          format_short(a.accounts.back().deletion_loss, 4) + " J/m and fine-scale kinetic energy dropped " +
          format_short(sub.kinetic_dropped, 4) + " J/m (E0 " + format_short(a.e0, 7) + " J/m); max |p - p0| / p0 " +
          format_short(a.worst_momentum, 3) + ", " + format_short(b.worst_momentum, 3) + "; cost: sub-model " +
          std::to_string(sub.submodels) + " sub-model(s), k " + std::to_string(sub.k) + ", n " + std::to_string(sub.n) +
          ", " + std::to_string(sub.substeps) + " substeps, wall " + format_short(sub.wall, 3) + " s, CPU " +
          format_short(sub.cpu, 3) + " s; in-place k " + std::to_string(inplace.k) + ", n " + std::to_string(inplace.n) +
          ", " + std::to_string(inplace.substeps) + " patch steps, wall " + format_short(inplace.wall, 3) + " s, CPU " +
          format_short(inplace.cpu, 3) + " s",
      "other: the account's remainder (the free sub-nodes' fine-scale kinetic energy, outside the coarse balance, "
      "enters it); cost on this machine"));
  claims.back().key = "submodel-vs-inplace-energy";
  for (repro::Claim& c : claims) c.scope = repro::Scope::kExtension;
  return claims;
}
}  // namespace prisms
