// Two 1 m squares collide head on (Paper A Sect. 4.1): A moves at 1 m/s
// toward B at rest; they exchange their velocities and keep the momentum.
// Prints both x-velocities at t = 1 s; exits 1 if they are not exchanged
// within 1 % of A's initial speed.
#include <cmath>
#include <cstdio>

#include "dda/simulation.hpp"

int main() {
  dda::Scene scene;                  // one material: 2000 kg/m^3, E = 1 GPa, nu = 0.25
  scene.contact.kn = 1e7;            // normal penalty, Pa
  scene.dt = 1e-4;                   // s
  scene.duration = 1.0;              // s
  dda::BlockSpec a, b;
  a.vertices = {{-1.5, -0.5}, {-0.5, -0.5}, {-0.5, 0.5}, {-1.5, 0.5}};  // m, counter-clockwise
  a.velocity = {1.0, 0.0};                                             // m/s
  b.vertices = {{0.0, -0.5}, {1.0, -0.5}, {1.0, 0.5}, {0.0, 0.5}};
  scene.blocks = {a, b};

  dda::Simulation sim(scene);        // throws dda::SceneError naming the bad field
  sim.advance_to(scene.duration);    // throws dda::SimulationError if a guard stops the run

  const double va = sim.velocity(0)[0], vb = sim.velocity(1)[0];
  std::printf("t = %.2f s, %lld steps: A %.4f m/s, B %.4f m/s, momentum %.4f kg m/s\n", sim.time(),
              static_cast<long long>(sim.step_count()), va, vb, sim.momentum().x);
  return std::abs(va) < 0.01 && std::abs(vb - 1.0) < 0.01 ? 0 : 1;
}
