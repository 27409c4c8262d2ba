// An impact study beyond Paper B, on its two-scale contact
// (Sects. 3-5: two time stages, clone node by the perfectly inelastic Eq. 4,
// Mohr-Coulomb sliding, local subdivision): two 1 m CST-meshed squares of
// Paper B's material (E 40 GPa, nu 0.25, rho 2700 kg/m3, d_tol 5e-3 m), A
// striking B at rest face to face at angle 0-85 deg from the normal, speed
// 0.1-30 m/s, friction mu = tan(phi) 0 / 0.3 / 0.6, subdivision off / on
// ('on': the in-place refinement, SubdivisionMode::kInPlace, set explicitly;
// beyond the paper), and the 'on' cells again with Paper B Sect. 5's
// sub-model as we read it (subdivision 'sub-model', kSubModel), whose rows
// (the same per-cell criteria) stand beside the others.
// impact_study.hpp has the set-up, the rigid-body impact law compared with
// and the per-cell criteria (setup.cpp, run.cpp, criteria.cpp; the rows in
// rows.cpp and submodel_rows.cpp).
//
// Expected: no pass-through, kinetic energy never above its initial value,
// the blocks separate (no cohesion or tensile strength), the touches' loss
// within Eq. 5 and the run's within Eq. 5 for the two blocks; the tangential
// impulse within Coulomb's mu J_n and on the rigid stick/slide law. Known
// beforehand: Eq. 4 takes the contact points' tangential relative velocity
// whatever phi is, so the Coulomb and rigid-law rows are expected to FAIL
// because of the paper's method.
//
// Output under <out>/data/B_9_impact_study/: cells.csv (one row per cell:
// outcome, penetration, separation, energy, loss vs Eq. 5, restitution,
// impulses and the law's prediction, the per-criterion verdicts); claims in
// <out>/claims/B_9_impact_study.csv.
#include <stdexcept>
#include <string>
#include <vector>

#include "repro/B_9_impact_study/impact_study.hpp"
#include "repro/B_9_impact_study/output.hpp"
#include "repro/common/common.hpp"
#include "repro/common/driver.hpp"

namespace {
const char* kDriver = "B_9_impact_study";


// Every cell of the three grids at `dt`, written to `path` as it runs; the
// results by grid: the paper's method, the Coulomb option, the sub-model.
struct Results {
  std::vector<impact::CellResult> paper, option, submodel;
};
Results run_cells(double dt, const std::string& path, const repro::Progress& progress) {
  // The paper's method, then the same grid with the Coulomb touch option;
  // then Paper B Sect. 5's sub-model on the subdivision-on cells.
  std::vector<impact::Cell> cells = impact::grid(false);
  for (const impact::Cell& c : impact::grid(true)) cells.push_back(c);
  for (const impact::Cell& c : impact::submodel_grid()) cells.push_back(c);

  impact::CellsCsv csv(path, dt);
  Results res;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const impact::CellResult r = impact::run_cell(cells[i], dt);
    (cells[i].submodel ? res.submodel : cells[i].coulomb ? res.option : res.paper).push_back(r);
    if (!r.ok) progress("cell " + impact::cell_name(r.cell) + " stopped: " + r.outcome);
    if ((i + 1) % 30 == 0 || i + 1 == cells.size())
      progress(std::to_string(i + 1) + " of " + std::to_string(cells.size()) + " cells");
    csv.row(r);
  }
  csv.commit();
  return res;
}
}  // namespace

int main(int argc, char** argv) {
  return repro::driver_main(
      argc, argv,
      {kDriver, "B-9 impact study",
       "Beyond Paper B: impact study of its two-scale contact (two 1 m squares, angle x speed x friction x "
       "subdivision)."},
      {{"--dt", "S", "time step, s (default 2e-5: 0.28 of the squares' critical step)", false}},
      [](const repro::Driver& d) {
        const double dt = d.number("--dt", impact::kDt);
        if (!(dt > 0.0)) throw std::invalid_argument("--dt must be > 0");
        const std::string note =
            dt == impact::kDt ? std::string() : " [NOT THE DEFAULT dt: " + repro::format_short(dt) + " s]";
        const Results res = run_cells(dt, d.out + "/data/" + kDriver + "/cells.csv", d.progress);

        std::vector<repro::Claim> claims = impact::rows(res.paper, note, res.option);
        for (const repro::Claim& c : impact::submodel_rows(res.submodel, res.paper, note)) claims.push_back(c);
        for (const repro::Claim& c : impact::cost_rows(res.paper, res.option, res.submodel, dt, note))
          claims.push_back(c);
        repro::default_scope(claims, repro::Scope::kExtension);  // beyond the paper; the option rows say so themselves
        repro::write_claims(repro::claims_path(d.out, kDriver), claims);
        d.progress("done");
        return 0;
      });
}
