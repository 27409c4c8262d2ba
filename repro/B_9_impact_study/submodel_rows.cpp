// The impact study: the rows of the sub-model cells (Paper B Sect. 5's
// sub-model, our reading), with the in-place refinement beside.
#include "repro/B_9_impact_study/tally.hpp"

namespace impact {

std::vector<repro::Claim> submodel_rows(const std::vector<CellResult>& sub, const std::vector<CellResult>& cells,
                                        const std::string& note) {
  using repro::format_short;
  std::vector<repro::Claim> out;
  std::vector<CellResult> inplace;
  for (const CellResult& r : cells)
    if (r.cell.subdivision && !r.cell.submodel) inplace.push_back(r);
  const std::string grid_text = std::to_string(sub.size()) +
                                " cells (the grid's subdivision-on cells with Sect. 5's sub-model)" + note;
  auto add = [&](const std::string& key, const std::string& claim, const std::string& paper, const Tally& t,
                 const Tally& beside, const std::string& extra, const std::string& tol, const char* test) {
    out.push_back(tally_row(key, claim, paper,
                            count_text(t) + (extra.empty() ? "" : "; " + extra) +
                                "; in-place refinement (beyond the paper) " + std::to_string(beside.pass) + " of " +
                                std::to_string(beside.total) + "; " + grid_text,
                            tol, t, test));
  };
  const auto none = [](const CellResult&) { return std::string(); };
  const auto all = [](const CellResult&) { return true; };
  add("submodel-no-pass-through", "(Sect. 5's sub-model, our reading) no pass-through in any cell of the impact study",
      "not in the paper: no pass-through in any cell",
      tally(sub, no_pass_through,
            [](const CellResult& r) {
              return stopped_or(r, "depth " + format_short(r.max_depth, 3) + " m, centres " +
                                       format_short(r.min_centre_dx, 4) + " m apart");
            }),
      tally(inplace, no_pass_through, none),
      "deepest node " + stats(sub, [](const CellResult& r) { return r.max_depth; }, all) + " m",
      "per cell, as the paper's row: the run finishes, no node deeper than d_tol, centres > L/2 apart",
      kTestSubPassThrough);
  add("submodel-kinetic-energy", "(Sect. 5's sub-model, our reading) kinetic energy never grows in any cell",
      "not in the paper: kinetic energy never grows",
      tally(sub, energy_never_grows,
            [](const CellResult& r) { return "max KE/KE0 - 1 = " + format_short(r.ke_growth, 3) + (r.ok ? "" : ", stopped"); }),
      tally(inplace, energy_never_grows, none),
      "max KE/KE0 - 1 " + stats(sub, [](const CellResult& r) { return r.ke_growth; }, all) + "; of KE + strain " +
          stats(sub, [](const CellResult& r) { return r.total_growth; }, all),
      "per cell, as the paper's row: KE(t) <= KE0 (1 + 1e-9) at every step", kTestSubEnergy);
  add("submodel-separation", "(Sect. 5's sub-model, our reading) the blocks separate in every cell",
      "not in the paper: the blocks separate (when friction allows)",
      tally(sub, separates,
            [](const CellResult& r) { return stopped_or(r, r.separated ? "separated" : "still tied or closing"); }),
      tally(inplace, separates, none),
      "last clone released at " +
          stats(sub, [](const CellResult& r) { return r.t_sep * 1e3; }, [](const CellResult& r) { return r.t_sep >= 0.0; }) +
          " ms",
      "per cell, as the paper's row: no clone left at the end and B moving away from A in x", kTestSubSeparation);
  {
    // Attached on FAIL only, with the run's numbers: the same cells with the
    // in-place refinement (beside) and without subdivision.
    const Tally beside = tally(inplace, separates, none);
    repro::explain_fail(out.back(), repro::Root::kSubModelReading,
                        "the sub-model of Sect. 5 as we read its steps (1)-(5) changes the blocks' relative motion "
                        "while it lives; the contact re-touches and a clone formed late is still tied at the end of "
                        "the window; the same grid separates in " + std::to_string(beside.pass) + " of " +
                        std::to_string(beside.total) + " cells with the in-place refinement");
  }
  add("submodel-touch-loss-eq5", "(Sect. 5's sub-model, our reading) the touches' measured loss stays within Eq. 5",
      "Paper B Eq. 5 (the clones are between coarse nodes: Eq. 5 with the coarse masses)",
      tally(sub, touch_loss_within_eq5,
            [](const CellResult& r) {
              return stopped_or(r, "measured/group Eq. 5 - 1 = " +
                                       format_short(r.touch_loss / r.touch_loss_eq5_group - 1.0, 3));
            }),
      tally(inplace, touch_loss_within_eq5, none), "",
      "per cell, as the paper's row: 0 <= measured <= group Eq. 5 (+1e-9 KE0)", kTestSubTouchLoss);
  add("submodel-total-loss-eq5",
      "(Sect. 5's sub-model, our reading) the run's energy loss stays within Eq. 5 for the two blocks",
      "Eq. 5 applied to the blocks: a perfectly inelastic block impact loses 1/2 (m/2) |v|^2, the most any impact can",
      tally(sub, total_loss_within_block_eq5,
            [](const CellResult& r) {
              return stopped_or(r, "loss / block Eq. 5 = " + format_short(r.total_loss / r.block_eq5, 4));
            }),
      tally(inplace, total_loss_within_block_eq5, none),
      "loss / block Eq. 5 " + stats(sub, [](const CellResult& r) { return r.total_loss / r.block_eq5; }, all),
      "per cell, as the paper's row: 0 <= KE0 - (KE + strain)_end <= 1/2 (m/2) |v0|^2 (1 + 1e-9)", kTestSubTotalLoss);
  out.push_back(repro::measurement(
      "B-9", "(Sect. 5's sub-model, our reading) restitution and energy loss against the in-place refinement",
      "Paper B: the clone impact is perfectly inelastic at the contact points",
      "e: sub-model " + stats(sub, [](const CellResult& r) { return r.e; }, all) + ", in-place " +
          stats(inplace, [](const CellResult& r) { return r.e; }, all) + "; loss / block Eq. 5: sub-model " +
          stats(sub, [](const CellResult& r) { return r.total_loss / r.block_eq5; }, all) + ", in-place " +
          stats(inplace, [](const CellResult& r) { return r.total_loss / r.block_eq5; }, all) + "; " + grid_text,
      "the sub-model's clones are between coarse nodes (coarse masses in Eq. 5), the in-place patch's between "
      "patch nodes"));
  out.back().key = "submodel-restitution-loss";
  return out;
}
}  // namespace impact
