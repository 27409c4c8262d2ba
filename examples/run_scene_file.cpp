// A JSON scene file run through the library: read and validated by dda_io
// (schema: lib/io/SCHEMA.md), stepped by dda::Simulation, read back through
// its accessors. Usage: run_scene_file SCENE.json
//
// Prints the energy budget ten times over the run and each block's centroid
// at the end. Expects the budget to close: |balance error| below 1 % of the
// largest mechanical energy seen (the solver's own guard stops a run at
// 10 %). Exit status 0 ok, 1 budget off, 2 bad scene file, 3 run stopped.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>

#include "dda/io/scene_file.hpp"
#include "dda/simulation.hpp"

int main(int argc, char** argv) {
  if (argc != 2) return std::fprintf(stderr, "usage: run_scene_file SCENE.json\n"), 2;
  dda::io::SceneFile file;
  try {
    file = dda::io::load_scene_file(argv[1]);
  } catch (const dda::io::SceneFileError& e) {  // "<file>:<line>:<col>: <field>: <reason>"
    return std::fprintf(stderr, "%s\n", e.what()), 2;
  }
  try {
    dda::Simulation sim(file.scene);
    std::printf("%s: %d blocks, dt %g s, %g s\n%10s %14s %14s %14s\n", file.scene.name.c_str(), sim.block_count(),
                sim.dt(), file.scene.duration, "t (s)", "total (J)", "dissipated", "balance err");
    double largest = 0.0, worst = 0.0;
    for (int k = 1; k <= 10; ++k) {
      sim.advance_to(file.scene.duration * k / 10);
      const dda::Energy e = sim.energy();
      largest = std::max(largest, std::abs(e.kinetic) + std::abs(e.strain) + std::abs(e.contact));
      worst = std::max(worst, std::abs(e.balance_error()));
      std::printf("%10.4f %14.6g %14.6g %14.3g\n", sim.time(), e.total(), e.dissipated, e.balance_error());
    }
    for (int i = 0; i < sim.scene_block_count(); ++i)
      std::printf("block %d %-10s centroid (%.4f, %.4f) m\n", i, file.scene.blocks[i].name.c_str(),
                  sim.centroid(i).x, sim.centroid(i).y);
    return worst <= 0.01 * largest ? 0 : 1;
  } catch (const dda::SimulationError& e) {
    return std::fprintf(stderr, "%s: run stopped: %s\n", argv[1], e.what()), 3;
  } catch (const dda::SceneError& e) {
    return std::fprintf(stderr, "%s: %s\n", argv[1], e.what()), 2;
  }
}
