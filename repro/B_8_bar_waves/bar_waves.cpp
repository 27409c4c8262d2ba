// Waves against theory (beyond both papers; Paper B
// Sect. 5's local subdivision exists to resolve the elastic waves of an
// impact): two equal elastic bars head on, against 1D bar theory.
//
// Scene: two bars L = 1 m long, W = 0.2 m wide (L / W = 5), 10 mm apart;
// the striker at v = 1 m/s along +x onto the target at rest. Material: Paper
// A Sect. 4.1's rho = 2000 kg/m3, E = 1 GPa, with nu = 0.
// What the CST elements model: PLANE STRESS (dda::elastic_matrix, used by
// lib/cdem/src/model_mesh.cpp: D = E / (1 - nu^2) [1 nu 0; nu 1 0; 0 0
// (1 - nu) / 2]); the 1D bar speed of a thin plane-stress bar is
// c = sqrt(E / rho). With nu = 0 (the Material allows it) a uniaxial stress
// state is exact in the continuum, so 1D theory holds without lateral
// (Poisson) dispersion, and plane stress and plane strain agree.
// 1D theory (equal bars, one at v onto one at rest): contact from gap / v
// for 2 L / c = 2.83 ms (c = 707 m/s), a rectangular contact-stress pulse of
// rho c v / 2 = 0.707 MPa, and then the bars exchange their velocities
// (striker 0, target v), energy kept.
//
// Models:
//   B  : CDEM (Paper B), clone node + local subdivision (the in-place
//        refinement, SubdivisionMode::kInPlace, set explicitly: a study,
//        not a paper figure, so its outputs do not follow the default);
//   B0 : CDEM, clone node without subdivision;
//   A  : Paper A's 6-DOF DDA blocks with the penalty contact (kn = E / 100,
//        Paper A Sect. 4.1's ratio; also a kn sweep).
// Each bar in B / B0 is a structured mesh of ny x 5 ny square cells (two CST
// elements each, dda::cdem::mesh_rectangle), ny = 1 ... 16, dt = 0.3 h / c
// (mesh series), and on ny = 4 dt halved twice (dt series). A: dt from 1e-4
// s halved three times at kn = E / 100 (dt series), and kn = E / 100 ... 10 E
// at dt = 1.25e-5 s (kn series).
// Per run: contact duration (first touch to the last clone separation; A:
// first to last step with an overlap), mean contact stress (impulse on the
// target / (duration W)), the plateau (mean contact stress over the middle
// half of 2 L / c), the block-average velocities after separation, energy
// (end and largest growth), wall time.
// Expected: the CST mesh is dispersive, so B / B0 converge to the theory
// slowly (asymptotically as h^(2/3): the front's width grows as
// (h^2 L)^(1/3)); the plateau is right on every mesh. A's blocks have one strain mode and no wave: its contact
// lasts as long as kn makes it (17 ms at E / 100), its stress is kn's, not
// rho c v / 2, but it exchanges the velocities as rigid blocks do.
//
// Output under <out>/data/B_8_bar_waves/: runs.csv (one row per run, with
// the wall time; a stopped run has its error and no values), traces.csv
// (contact stress against time after the touch for one run of each model);
// claims in <out>/claims/B_8_bar_waves.csv.
#include <stdexcept>
#include <string>
#include <vector>

#include "repro/B_8_bar_waves/bar_waves.hpp"
#include "repro/B_8_bar_waves/output.hpp"
#include "repro/common/common.hpp"
#include "repro/common/driver.hpp"

namespace {
const char* kDriver = "B_8_bar_waves";

// One run's progress line.
std::string summary(const bars::Run& r) {
  using bars::pct;
  using repro::format_short;
  return r.model + " " + r.series + " ny " + std::to_string(r.ny) + " dt " + format_short(r.dt) + " kn " +
         format_short(r.kn) + ": " + format_short(r.wall, 3) + " s, " +
         (r.ok() ? "T " + pct(r.duration_err) + ", stress " + pct(r.stress_err) + ", plateau " + pct(r.plateau_err) +
                       ", exchange " + pct(r.exchange_err) + ", dE " + format_short(r.energy_end, 3) + ", growth " +
                       format_short(r.energy_growth, 3)
                 : "STOPPED: " + r.stopped);
}
}  // namespace

int main(int argc, char** argv) {
  return repro::driver_main(
      argc, argv,
      {kDriver, "B-8 bar waves",
       "Beyond both papers: two elastic bars head on against 1D wave theory (CDEM B, B0; Paper A's DDA)."},
      {{"--max-ny", "N", "finest CDEM mesh: elements across the width (default 16; powers of 2 from 1)", true}},
      [](const repro::Driver& d) {
        using namespace bars;
        const int max_ny = d.whole("--max-ny", 16);
        if (max_ny < 1) throw std::invalid_argument("--max-ny must be >= 1");
        const std::string run_note = max_ny == 16 ? "" : " [NOT THE DEFAULT: --max-ny " + std::to_string(max_ny) + "]";
        const Setup s;

        // The runs: B and B0 on the mesh series and the dt series, A on its dt and kn series.
        const Study study = run_study(s, max_ny, [&d](const Run& r) { d.progress(summary(r)); });
        write_runs(d.out + "/data/" + kDriver + "/", s, study);

        std::vector<repro::Claim> claims = rows(study.runs, s, run_note);
        repro::default_scope(claims, repro::Scope::kExtension);  // beyond both papers: 1D wave theory, every row
        repro::write_claims(repro::claims_path(d.out, kDriver), claims);
        d.progress("done");
        return 0;
      });
}
