// Paper A, Sect. 4.1 "Collision of two identical polygons" (Figs. 7-8).
//
// Two 1 m squares on one line: A at 1 m/s along x toward B at rest
// (rho 2000, E 1 GPa, nu 0.25, kn 10 MPa, dt 1e-4 s, 1.0 s; gap 0.5 m, our
// choice since Fig. 7 is lost). Expected (paper): "the two blocks exchange
// their kinetic energy during the collision process and the results satisfy
// the conservation of momentum": after the impact v_A ~ 0, v_B ~ 1 m/s.
//
// Output: data/two_squares/velocity.csv (Fig. 8), claims/4_1_two_squares.csv.
#include <cmath>
#include <vector>

#include "dda/paper_scenes.hpp"
#include "dda/simulation.hpp"
#include "repro/common/common.hpp"

int main(int argc, char** argv) {
  repro::check_command_line(argc, argv, "Paper A Sect. 4.1 (Figs. 7-8): collision of two identical squares.");
  const std::string out = repro::out_dir(argc, argv);
  const repro::Progress progress("4.1 two squares");
  const dda::Scene scene = dda::paper::two_squares();
  dda::Simulation sim(scene);

  repro::CsvWriter csv(out + "/data/two_squares/velocity.csv",
                       {"time", "vx_A", "vx_B", "momentum_x", "kinetic", "strain", "contact", "total_energy"});
  const double p0 = sim.momentum().x;
  const double e0 = sim.energy().total();
  double worst_momentum = 0.0, worst_energy = 0.0, t_first = -1.0, t_last = -1.0;
  auto record = [&] {
    const dda::Energy e = sim.energy();
    csv.row({sim.time(), sim.velocity(0)[0], sim.velocity(1)[0], sim.momentum().x, e.kinetic, e.strain, e.contact,
             e.total()});
    worst_energy = std::max(worst_energy, std::fabs(e.total() - e0) / e0);
  };
  record();
  while (sim.time() < scene.duration) {
    sim.step();
    worst_momentum = std::max(worst_momentum, std::fabs(sim.momentum().x - p0) / std::fabs(p0));
    if (!sim.contacts().empty()) {
      if (t_first < 0.0) t_first = sim.time();
      t_last = sim.time();
    }
    if (sim.step_count() % 10 == 0) record();
  }
  csv.commit();
  const double va = sim.velocity(0)[0], vb = sim.velocity(1)[0];
  progress("done: v_A = " + repro::format_short(va) + ", v_B = " + repro::format_short(vb));

  using repro::format_short;
  // Tolerances: velocity exchange within 1 % of the impact speed (the blocks
  // keep a small strain vibration after the impact); momentum to round-off
  // (forces are applied equal and opposite at one point); energy within 1 %
  // (velocity Verlet is symplectic: no drift, O(h^2) oscillation).
  std::vector<repro::Claim> claims = {
      {"4.1", "block A stops after the impact", "Fig. 8: v_A -> 0", "v_A(1 s) = " + format_short(va) + " m/s",
       "|v_A| < 0.01 m/s", std::fabs(va) < 0.01},
      {"4.1", "block B leaves with A's speed", "Fig. 8: v_B -> 1 m/s", "v_B(1 s) = " + format_short(vb) + " m/s",
       "|v_B - 1| < 0.01 m/s", std::fabs(vb - 1.0) < 0.01},
      {"4.1", "momentum is conserved", "'the results satisfy the conservation of momentum'",
       "max |p - p0| / p0 = " + format_short(worst_momentum, 3), "< 1e-9", worst_momentum < 1e-9},
      {"4.1", "energy is conserved through the collision (no damping)", "kinetic energy exchanged",
       "max |E - E0| / E0 = " + format_short(worst_energy, 3) + "; contact from t = " + format_short(t_first) +
           " to " + format_short(t_last) + " s",
       "< 1e-2", worst_energy < 1e-2},
  };
  repro::write_claims(repro::claims_path(out, "4_1_two_squares"), claims);
  return 0;
}
