// Paper A, Sect. 4.1 "Collision of two identical polygons" (Figs. 7-8).
//
// Two 1 m squares on one line: A at 1 m/s along x toward B at rest
// (rho 2000, E 1 GPa, nu 0.25, kn 10 MPa, dt 1e-4 s, 1.0 s; gap 0.5 m, our
// choice since Fig. 7 is lost). Expected (paper): "the two blocks exchange
// their kinetic energy during the collision process and the results satisfy
// the conservation of momentum": after the impact v_A ~ 0, v_B ~ 1 m/s.
//
// Output: data/two_squares/velocity.csv (Fig. 8), claims/4_1_two_squares.csv.
#include <vector>

#include "dda/paper_scenes.hpp"
#include "repro/4_1_two_squares/two_squares.hpp"
#include "repro/common/common.hpp"

// The driver: its name in errors, its progress lines' prefix and its usage line.
const repro::DriverInfo kInfo = {"two_squares", "4.1 two squares",
                                 "Paper A Sect. 4.1 (Figs. 7-8): collision of two identical squares."};

namespace {

// The run: what main's driver_main calls once the command line is checked.
int reproduce(const repro::Driver& d) {
  const dda::Scene scene = dda::paper::two_squares();
  repro::TableWriter<two_squares::Sample> velocity(d.out + "/data/two_squares/velocity.csv",
                                                   two_squares::velocity_columns());
  const two_squares::Result r = two_squares::run(scene, &velocity);
  velocity.commit();
  d.progress("done: v_A = " + repro::format_short(r.va) + ", v_B = " + repro::format_short(r.vb));
  repro::write_claims(repro::claims_path(d.out, "4_1_two_squares"), two_squares::claims(r));
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return repro::driver_main(argc, argv, kInfo, {}, reproduce); }
