// The scenes of Paper A Sects. 4-5 as Scene values, shared by the repro
// drivers, the tests and the benchmarks. Parameters from SPEC.md section 7.
// Where the paper's figure is lost, the geometry is a reconstruction from
// the prose; each function says so.
#pragma once
#include <vector>

#include "dda/scene.hpp"

namespace dda::paper {

// Sect. 4.1: two 1 m squares on one line, A (block 0) at 1 m/s toward B
// (block 1) at rest, 0.5 m apart. rho 2000, E 1 GPa, nu 0.25, kn 10 MPa,
// dt 1e-4, 1.0 s, no gravity, no friction. The gap is not given in the
// paper (Fig. 7 lost): 0.5 m is our choice.
Scene two_squares();

// Sect. 4.2 (geometry RECONSTRUCTED, Fig. 9 lost): a pyramid of three 1 m
// squares (two side by side on a fixed base, one on top, centred on x = 0)
// hit from above by a symmetric pentagon moving down the symmetry axis at
// 2 m/s; gravity 9.81. rho 2000, E 0.1 GPa, nu 0.25, kn 10 MPa, dt 1e-3,
// 1.0 s. mirror[i] is the index of block i's mirror image about x = 0.
struct SymmetricStack {
  Scene scene;
  std::vector<int> mirror;
};
SymmetricStack symmetric_stack();

// Sect. 4.3 (geometry RECONSTRUCTED, Fig. 11 lost): a 1 m square block B
// (block 1) at rest on a fixed 12 m x 1 m slab A (block 0) inclined at
// theta = 30 deg, with friction angle phi. rho 2000, E 1 GPa, nu 0.25,
// kn 10 MPa, kt 1e7 N/m, dt 1e-5, gravity 9.81.
struct Incline {
  Scene scene;
  double theta_rad = 0.0;
  Vec2 downhill{};  // unit vector along the incline, pointing down
};
// start_sunk: B starts at its static penetration (see the source).
// h_given > 0: use that H instead of the paper's min-max edge rule (6.5 m
// here, set by the long slab), for the sensitivity rows of the report.
Incline incline(double phi_deg, double theta_deg = 30.0, double duration = 1.0, bool start_sunk = true,
                double h_given = 0.0);

// Analytic sliding distance of Eq. 30: l = g (sin t - cos t tan phi) t^2 / 2.
double incline_distance(double g, double theta_rad, double phi_rad, double t);

}  // namespace dda::paper
