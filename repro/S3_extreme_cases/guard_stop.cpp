// A run that is too coarse on purpose: the two squares of Sect. 4.1 with a
// stiff contact (kn 1e10 Pa), 1 mm apart, at dt = F x the predicted
// critical step (--fraction F, default 3). Writes data/guard_stop/series.csv
// after every step. Expected: the solver's guard stops the run during the
// impact; the rows written so far are committed (all finite: CsvWriter
// refuses NaN and the guard stops before a non-finite state is reported),
// the solver's message (step, time, block, pair, what was exceeded,
// dt/dt_crit) goes to stderr and to data/guard_stop/stop.txt, and the exit
// status is 3. Without a stop (F well below 1): exit status 0.
// ctest runs it both ways (repro/S3_extreme_cases/check_guard_stop.cmake).
#include <cstdio>
#include <fstream>
#include <string>

#include "dda/paper_scenes.hpp"
#include "dda/simulation.hpp"
#include "repro/common/common.hpp"
#include "repro/common/options.hpp"

int main(int argc, char** argv) {
  repro::check_command_line(argc, argv, "A deliberately too coarse run that the solver's guard must stop (exit status 3).",
                            {{"--fraction", "F", "dt as a multiple of the predicted critical step (default 3)", false}});
  const std::string out = repro::out_dir(argc, argv);
  const double fraction = repro::option_number(argc, argv, "--fraction", 3.0);
  if (!(fraction > 0.0)) {
    std::fprintf(stderr, "guard_stop: --fraction must be positive\n");
    return 2;
  }
  dda::Scene s = dda::paper::two_squares();
  s.blocks[0].vertices = {{-1.001, -0.5}, {-0.001, -0.5}, {-0.001, 0.5}, {-1.001, 0.5}};
  s.contact.kn = 1e10;
  s.dt_fraction = fraction;
  s.duration = 0.2;
  s.guards.energy_check_every = 1;  // check every step: the stop comes during the impact
  dda::Simulation sim(s);
  const std::string dir = out + "/data/guard_stop";
  repro::CsvWriter series(dir + "/series.csv", {"time", "x_A", "x_B", "vx_A", "vx_B", "total_energy"},
                          {"two squares, kn 1e10 Pa, dt = " + repro::format_short(fraction) +
                           " x predicted dt_crit = " + repro::format_short(sim.dt()) + " s"});
  try {
    while (sim.time() < s.duration) {
      sim.step();
      series.row({sim.time(), sim.centroid(0).x, sim.centroid(1).x, sim.velocity(0)[0], sim.velocity(1)[0],
                  sim.energy().total()});
    }
  } catch (const dda::SimulationError& e) {
    series.commit();
    std::ofstream(dir + "/stop.txt") << e.what() << '\n';
    std::fprintf(stderr, "guard_stop: %s\n", e.what());
    return 3;
  }
  series.commit();
  std::remove((dir + "/stop.txt").c_str());
  return 0;
}
