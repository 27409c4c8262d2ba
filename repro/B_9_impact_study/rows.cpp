// The impact study: the rows of the paper's method over the grid (and the
// Coulomb touch option beside its Coulomb and rigid-law rows).
#include "repro/B_9_impact_study/tally.hpp"

namespace impact {

std::vector<repro::Claim> rows(const std::vector<CellResult>& cells, const std::string& note,
                               const std::vector<CellResult>& option_cells) {
  using repro::format_short;
  std::vector<repro::Claim> out;
  const std::string grid_text = std::to_string(cells.size()) + " cells (angle x speed x friction x subdivision)" + note;
  auto add = [&](const std::string& key, const std::string& claim, const std::string& paper, const Tally& t,
                 const std::string& extra, const std::string& tol, const char* test) {
    out.push_back(tally_row(key, claim, paper, count_text(t) + (extra.empty() ? "" : "; " + extra) + "; " + grid_text,
                            tol, t, test));
  };
  const auto stop_cause = [&](repro::Claim& c) {
    repro::explain_fail(c, repro::Root::kUnexplained,
                        "in the failing cells the contact with friction creates energy (the touches' measured loss "
                        "far above the run's loss: the energy account's remainder is a gain), and some runs grow until "
                        "an element inverts or a node ends deeper than d_tol and the solver stops; the cells affected "
                        "change erratically with dt. Paper B's method cannot add energy (Eq. 4 removes it, central "
                        "differences below the critical step conserve it): the fault is in our clone/sliding "
                        "implementation");
  };

  add("no-pass-through", "no pass-through in any cell of the impact study", "not in the paper: no pass-through in any cell",
      tally(cells, no_pass_through,
            [](const CellResult& r) {
              return stopped_or(r, "depth " + format_short(r.max_depth, 3) + " m, centres " +
                                       format_short(r.min_centre_dx, 4) + " m apart");
            }),
      "deepest node over the finished cells " +
          stats(cells, [](const CellResult& r) { return r.max_depth; }, [](const CellResult&) { return true; }) +
          " m",
      "per cell: the run finishes (a node deeper than d_tol stops it), no node ends a step deeper than d_tol = 5e-3 m "
      "inside the other block's boundary-node outline, centres > L/2 apart",
      kTestPassThrough);
  stop_cause(out.back());

  add("kinetic-energy", "kinetic energy never grows in any cell", "not in the paper: kinetic energy never grows",
      tally(cells, energy_never_grows,
            [](const CellResult& r) { return "max KE/KE0 - 1 = " + format_short(r.ke_growth, 3) + (r.ok ? "" : ", stopped"); }),
      "max KE/KE0 - 1 over the finished cells " +
          stats(cells, [](const CellResult& r) { return r.ke_growth; }, [](const CellResult&) { return true; }) +
          "; of KE + strain " +
          stats(cells, [](const CellResult& r) { return r.total_growth; }, [](const CellResult&) { return true; }),
      "per cell: the run finishes and KE(t) <= KE0 (1 + 1e-9) at every step (central differences conserve energy in "
      "free motion, the clone projections only remove it: round-off slack)",
      kTestEnergy);
  stop_cause(out.back());

  add("separation", "the blocks separate in every cell (no cohesion or tensile strength holds them)",
      "not in the paper: the blocks separate (when friction allows)",
      tally(cells, separates,
            [](const CellResult& r) { return stopped_or(r, r.separated ? "separated" : "still tied or closing"); }),
      "last clone released at " +
          stats(cells, [](const CellResult& r) { return r.t_sep * 1e3; }, [](const CellResult& r) { return r.t_sep >= 0.0; }) +
          " ms",
      "per cell: at the end (8 wave times 2L/c after the touch) no clone is left and B moves away from A in x "
      "(friction without cohesion never holds: Eq. 6 with sigma_t = 0)",
      kTestSeparation);
  stop_cause(out.back());

  add("touch-loss-eq5", "the touches' measured loss stays within Eq. 5 of the clones they project",
      "Paper B Eq. 5: the loss of a clone's perfectly inelastic impact, 1/2 m_m m_t / (m_m + m_t) |v_m - v_t|^2; for "
      "a group of clones sharing nodes (projected together) the group's Eq. 5, 1/2 r^T (C M^-1 C^T)^+ r",
      tally(cells, touch_loss_within_eq5,
            [](const CellResult& r) {
              return stopped_or(r, "measured/group Eq. 5 - 1 = " +
                                       format_short(r.touch_loss / r.touch_loss_eq5_group - 1.0, 3));
            }),
      "measured / group Eq. 5 over the finished cells " +
          stats(cells,
                [](const CellResult& r) {
                  return r.touch_loss_eq5_group > 0 ? r.touch_loss / r.touch_loss_eq5_group : 1.0;
                },
                [](const CellResult&) { return true; }) +
          "; measured / the new pairs' own Eq. 5 (not a bound for a group) " +
          stats(cells, [](const CellResult& r) { return r.touch_loss_eq5 > 0 ? r.touch_loss / r.touch_loss_eq5 : 1.0; },
                [](const CellResult&) { return true; }),
      "per cell: 0 <= sum of the touches' measured kinetic-energy drops <= sum of their group Eq. 5 values (+1e-9 "
      "KE0). The group projection is Eq. 4 for several ties (momentum conserved, every tie inelastic), so its Eq. 5 "
      "is the group's; a single pair's Eq. 5 leaves out the other ties' relative velocities the group takes",
      kTestTouchLoss);
  repro::explain_fail(out.back(), repro::Root::kUnexplained,
                      "a touch's measured drop exceeds the Eq. 5 of the clone group it projects: the group "
                      "projection (Gauss-Seidel) did not reach the group's perfectly inelastic "
                      "state, or energy entered in it");

  add("total-loss-eq5", "the run's energy loss stays within Eq. 5 for the two blocks",
      "Eq. 5 applied to the blocks: a perfectly inelastic block impact loses 1/2 (m/2) |v|^2, the most any impact can",
      tally(cells, total_loss_within_block_eq5,
            [](const CellResult& r) {
              return stopped_or(r, "loss / block Eq. 5 = " + format_short(r.total_loss / r.block_eq5, 4));
            }),
      "loss / block Eq. 5 over the finished cells " +
          stats(cells, [](const CellResult& r) { return r.total_loss / r.block_eq5; }, [](const CellResult&) { return true; }),
      "per cell: 0 <= KE0 - (KE + strain)_end <= 1/2 (m/2) |v0|^2 (1 + 1e-9)", kTestTotalLoss);
  stop_cause(out.back());

  add("coulomb", "the tangential impulse obeys Coulomb's limit in every cell",
      "not in the paper: the rigid-body Coulomb impact law, |J_t| <= mu J_n",
      tally(cells, obeys_coulomb,
            [](const CellResult& r) { return stopped_or(r, "J_t/J_n = " + format_short(r.jt / r.jn, 3)); }, 6),
      "J_t/J_n - mu over the finished cells " +
          stats(cells, [](const CellResult& r) { return r.jt / r.jn - r.cell.mu; }, [](const CellResult&) { return true; }) +
          "; at mu = 0, |J_t|/J_n " +
          stats(cells, [](const CellResult& r) { return std::fabs(r.jt / r.jn); }, [](const CellResult& r) { return r.cell.mu == 0.0 && r.cell.angle_deg > 0.0; }),
      "per cell: |J_t| <= (mu + 0.01) J_n (J from B's momentum at the end; 1 % for the explicit lag of the sliding "
      "clone's shear force)",
      kTestCoulomb);
  repro::explain_fail(out.back(), repro::Root::kCloneImpact,
                      "Paper B Sect. 4.1 forms each clone by a perfectly inelastic impact of the two contact points "
                      "(Eq. 4, 'no slipping occurs' in the touch step): it takes the points' whole relative "
                      "velocity, tangential included, whatever phi is; only afterwards does the Mohr-Coulomb limit "
                      "(Eqs. 7-10) cap the clone's shear force. The formation impulses are not limited by mu J_n "
                      "(at mu = 0 J_t is not 0). A stopped run fails this row too (see the pass-through row)");
  const std::string option_grid = std::to_string(option_cells.size()) +
                                  " cells (the same grid with the Coulomb touch option)" + note;
  auto add_option = [&](const std::string& key, const std::string& claim, const std::string& paper, const Tally& t,
                        const std::string& extra, const std::string& tol, const char* test) {
    out.push_back(tally_row(key, claim, paper, count_text(t) + (extra.empty() ? "" : "; " + extra) + "; " + option_grid,
                            tol, t, test));
    out.back().scope = repro::Scope::kOption;
  };
  if (!option_cells.empty()) {
    add_option("coulomb-option",
               "(Coulomb touch option, beyond the paper) the tangential impulse obeys Coulomb's limit in every cell",
               "not in the paper: the rigid-body Coulomb impact law, |J_t| <= mu J_n; the option caps each touch's "
               "tangential impulse at mu times its normal impulse",
               tally(option_cells, obeys_coulomb,
                     [](const CellResult& r) { return stopped_or(r, "J_t/J_n = " + format_short(r.jt / r.jn, 3)); }, 6),
               "J_t/J_n - mu over the finished cells " +
                   stats(option_cells, [](const CellResult& r) { return r.jt / r.jn - r.cell.mu; },
                         [](const CellResult&) { return true; }) +
                   "; at mu = 0, |J_t|/J_n " +
                   stats(option_cells, [](const CellResult& r) { return std::fabs(r.jt / r.jn); },
                         [](const CellResult& r) { return r.cell.mu == 0.0 && r.cell.angle_deg > 0.0; }) +
                   "; the option's cells also: no pass-through " +
                   std::to_string(tally(option_cells, no_pass_through, [](const CellResult&) { return ""; }).pass) +
                   ", KE never grows " +
                   std::to_string(tally(option_cells, energy_never_grows, [](const CellResult&) { return ""; }).pass) +
                   ", separate " +
                   std::to_string(tally(option_cells, separates, [](const CellResult&) { return ""; }).pass) +
                   ", touch loss within group Eq. 5 " +
                   std::to_string(tally(option_cells, touch_loss_within_eq5, [](const CellResult&) { return ""; }).pass) +
                   " of " + std::to_string(option_cells.size()),
               "per cell: |J_t| <= (mu + 0.01) J_n, as the paper's row", kTestCoulomb);
    repro::explain_fail(out.back(), repro::Root::kCornerNormal,
                        "with the Coulomb touch each touch's impulse obeys mu J_n along the clone's normal, but the "
                        "squares' corners are level (A's lower right corner meets B's lower left one): a corner "
                        "arriving within d_tol of the other block's corner is tied to the perpendicular face, whose "
                        "normal is tangential to the impact face, so its normal impulses are J_t for the blocks "
                        "(measured in (85 deg, 1 m/s, mu 0, sub off): A's corner node touches B's bottom face again "
                        "every two steps, J_n 7-63 N s/m each along y, J_t/J_n 4.24). The contact normal at a "
                        "corner-to-corner touch is our node-to-edge choice, not fixed by the option");
  }

  add("rigid-law", "the tangential impulse matches the rigid-body stick/slide law in every cell",
      "not in the paper: the rigid-body Coulomb impact law, stick if mu J_n >= m_t v_t0 (J_t = m_t v_t0, m_t = m/5 with the "
      "spin), else slide (J_t = mu J_n)",
      tally(cells, matches_rigid_law,
            [](const CellResult& r) {
              return stopped_or(r, "J_t/J_n = " + format_short(r.jt / r.jn, 3) + " vs law " +
                                       format_short(r.jt_law / r.jn, 3) + (r.law_sticks ? " (stick)" : " (slide)"));
            }, 6),
      "(J_t - J_t,law)/J_n over the finished cells " +
          stats(cells, [](const CellResult& r) { return (r.jt - r.jt_law) / r.jn; }, [](const CellResult&) { return true; }),
      "per cell: |J_t - J_t,law| <= 0.05 J_n with the measured J_n and restitution", kTestRigidLaw);
  repro::explain_fail(out.back(), repro::Root::kCloneImpact,
                      "the clone formation of Eq. 4 takes the tangential relative velocity of every touching node "
                      "pair (see the Coulomb row), so the tangential impulse follows the number and masses of the "
                      "touches, not mu: above the law's value in sliding cells (mu = 0 included) and off it in "
                      "sticking ones (the deformable blocks' spin differs from the rigid face-centre impulse too)");
  if (!option_cells.empty()) {
    add_option("rigid-law-option",
               "(Coulomb touch option, beyond the paper) the tangential impulse matches the rigid-body stick/slide "
               "law in every cell",
               "not in the paper: the rigid-body Coulomb impact law, as the row of the paper's method",
               tally(option_cells, matches_rigid_law,
                     [](const CellResult& r) {
                       return stopped_or(r, "J_t/J_n = " + format_short(r.jt / r.jn, 3) + " vs law " +
                                                format_short(r.jt_law / r.jn, 3) +
                                                (r.law_sticks ? " (stick)" : " (slide)"));
                     }, 6),
               "(J_t - J_t,law)/J_n over the finished cells " +
                   stats(option_cells, [](const CellResult& r) { return (r.jt - r.jt_law) / r.jn; },
                         [](const CellResult&) { return true; }),
               "per cell: |J_t - J_t,law| <= 0.05 J_n with the measured J_n and restitution", kTestRigidLaw);
    repro::explain_fail(out.back(), repro::Root::kCornerNormal,
                        "the cells failing the option's Coulomb row (corner-to-corner touches on the perpendicular "
                        "face, see there) fail this row too; the others are deformable CST meshes touching node by "
                        "node, whose stick regime's J_t differs from the rigid law's m_t v_t0 (m_t = m/5 with the "
                        "rigid spin) by more than 5 % of J_n");
  }

  const auto sub_on = [](const CellResult& r) { return r.cell.subdivision; };
  const auto sub_off = [](const CellResult& r) { return !r.cell.subdivision; };
  const auto e_of = [](const CellResult& r) { return r.e; };
  out.push_back(repro::measurement(
      "B-9", "normal restitution of the block-average velocities over the impact study",
      "Paper B: the clone impact is perfectly inelastic at the contact points; the blocks rebound by their elastic "
      "waves (no restitution parameter)",
      "e = -(v_n after)/(v_n before): subdivision off " + stats(cells, e_of, sub_off) + "; on " +
          stats(cells, e_of, sub_on) + "; head-on cells, off " +
          stats(cells, e_of, [](const CellResult& r) { return !r.cell.subdivision && r.cell.angle_deg == 0.0; }) +
          ", on " + stats(cells, e_of, [](const CellResult& r) { return r.cell.subdivision && r.cell.angle_deg == 0.0; }) +
          "; " + grid_text,
      "the model's restitution: set by the clone masses (subdivision makes them small) and the mesh, not an input"));
  out.back().key = "restitution";
  const auto loss_ratio = [](const CellResult& r) { return r.total_loss / r.block_eq5; };
  const auto touch_share = [](const CellResult& r) { return r.total_loss > 0 ? r.touch_loss / r.total_loss : 0.0; };
  out.push_back(repro::measurement(
      "B-9", "energy loss against Eq. 5 for the two blocks over the impact study",
      "Eq. 5: the loss falls with the contact-point mass (subdivision)",
      "loss / block Eq. 5: subdivision off " + stats(cells, loss_ratio, sub_off) + "; on " +
          stats(cells, loss_ratio, sub_on) + "; the touches' share of the loss: off " + stats(cells, touch_share, sub_off) +
          ", on " + stats(cells, touch_share, sub_on) + "; " + grid_text,
      "where the energy goes (the rest: patch remaps, friction work at sliding clones, integration)"));
  out.back().key = "loss-ratio";
  return out;
}
}  // namespace impact
