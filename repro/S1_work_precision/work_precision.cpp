// Work-precision: error against run time for every scene with a reference.
//
// For each scene below, dt is swept over more than two decades in factors
// of 2 (dt = paper dt * 2^k, so every run reaches the same sample times
// exactly), one curve per option: the paper's bisector segmentation vs the
// exact envelope integration, and the unified (min-max edge) vs the
// inscribed-radius H where the scene has different block sizes. The error
// is measured in one monitored run; the run time is the median of 3 to 9
// more runs with no monitoring (std::chrono::steady_clock, construction
// included; the CPU time is written too: on a loaded machine the wall time
// includes waiting for a core). References:
//   4.1 two squares (1 s): momentum (exact conservation), energy (exact
//       conservation), exchanged velocity (rigid elastic exchange: v_A = 0,
//       v_B = 1 m/s), trajectory against a converged run at dt_min / 16;
//   4.3 incline (1 s), phi = 0, 10, 20 deg: Eq. 30 at t = 1 s, and the
//       trajectory against a run at dt_min / 16;
//   resting block (our scene): a rigid 1 m square released at contact on a
//       fixed 4 m x 1 m block (Table 5: kn 50 MPa; no damping, so it
//       oscillates about its static penetration instead of settling).
//       Derivation (flat contact of length L; the IP is an L x delta strip):
//       B's potential is kn d/H_B with d the depth, A's is kn d/H_A except
//       in A's two corner triangles (area delta^2/2 each) where the side
//       edges are nearer, so the upward force is
//         f(delta) = kn [L delta (1/H_A + 1/H_B) - delta^2 / H_A]
//       (unified H: 2 kn L delta / H - kn delta^2 / H). Static penetration
//       f = W = rho g A_A; released from delta = 0 at rest, energy gives
//       the deepest point: kn [L (1/H_A + 1/H_B) delta / 2 - delta^2 /
//       (3 H_A)] = W. Measured: deepest penetration vs that, the static
//       check (start at delta_s: the block must stay put), trajectory;
//   5.2 small-angle triangles (0.2 s): point symmetry (exact by symmetry),
//       energy (exact conservation, frictionless);
//   5.1 bouncing block, case 1 (B 0.1 m high), 1.5 s: trajectory of A
//       against a run at dt_min / 16, over the first impact only and over
//       all impacts (no analytic answer);
//   5.3 vertex on the edge next to the 0.01 m edge (0.2 s): trajectory and
//       energy (the scene where the two integrations differ);
//   free rotation (ours): a rigid square spinning at 2 rad/s, no contact:
//       area and vertex positions against the exact rotation;
//   beside the paper's rule, Scene::rotation_update = kExact (not the
//       paper's) on the free rotation and on 5.3; and the energy budget
//       (Energy::balance_error, friction springs and dissipated work
//       included) on the 4.3 incline with and without friction.
// Expected: velocity Verlet is exact in free flight (constant force), so
// every error comes from the contacts; where the contact force is smooth
// along the path (continuous in the penetration) the error is O(dt^2).
// Momentum is conserved to round-off (equal and opposite forces) and
// point symmetry to round-off; friction stick/slip switching is not smooth;
// a spinning block converges at first order only (DDA's linearised
// rotation); with deformable blocks the energy during contact is off by a
// dt-independent amount (one-point loading of the strains, Eqs. 22-23).
// dt/dt_crit: the solver's predicted_critical_step() at the start and the
// largest dt/critical_time_step() over the run.
//
// Output: data/work_precision/runs.csv (one row per scene, option, measure
// and dt), data/work_precision/orders.csv (observed order, error and run
// time at the paper's dt), claims/S1_work_precision.csv.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "repro/S1_work_precision/work_precision.hpp"
#include "repro/common/common.hpp"
#include "repro/common/driver.hpp"

int main(int argc, char** argv) {
  return repro::driver_main(
      argc, argv,
      {"work_precision", "S1 work precision", "Work-precision: error against run time for every scene with a reference."},
      {{"--timing-repeats", "N", "timed runs per dt at most (default 9: 3 to 9 by run length; the errors and "
                                 "verdicts do not depend on it)", true},
       {"--jobs", "N", "cases run at once, one thread each (default 1; more makes the timings share cores)", true}},
      [](const repro::Driver& d) {
        const std::vector<s1::Case> cases = s1::all_cases();
        s1::SweepOptions options;
        options.max_repeats = d.whole("--timing-repeats", options.max_repeats);
        options.jobs = d.whole("--jobs", options.jobs);
        if (options.max_repeats < 1 || options.jobs < 1) {
          std::fprintf(stderr, "work_precision: --timing-repeats and --jobs need a whole number of at least 1\n");
          return 2;
        }
        s1::References references;
        const std::vector<s1::CurveSummary> curves =
            s1::sweep(cases, d.out + "/data/work_precision", references, d.progress, options);
        std::vector<repro::Claim> claims = s1::claim_rows(curves, references);
        repro::default_scope(claims, repro::Scope::kSuite);  // integrator orders and work-precision: the suite's own
        repro::write_claims(repro::claims_path(d.out, "S1_work_precision"), claims);
        d.progress("done");
        return 0;
      });
}
