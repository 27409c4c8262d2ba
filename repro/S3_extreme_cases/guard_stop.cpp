// A run that is too coarse on purpose: the two squares of Sect. 4.1 with a
// stiff contact (kn 1e10 Pa), 1 mm apart, at dt = F x the predicted
// critical step (--fraction F, default 3). Writes data/guard_stop/series.csv
// after every step. Expected: the solver's guard stops the run during the
// impact; the rows written so far are committed (all finite: the table
// refuses NaN and the guard stops before a non-finite state is reported),
// the solver's message (step, time, block, pair, what was exceeded,
// dt/dt_crit) goes to stderr and to data/guard_stop/stop.txt, and the exit
// status is 3. Without a stop (F well below 1): exit status 0.
// ctest runs it both ways (repro/S3_extreme_cases/check_guard_stop.cmake).
#include <cstdio>
#include <fstream>
#include <string>

#include "dda/simulation.hpp"
#include "repro/S3_extreme_cases/extreme_cases.hpp"
#include "repro/common/common.hpp"
#include "repro/common/driver.hpp"

int main(int argc, char** argv) {
  return repro::driver_main(
      argc, argv,
      {"guard_stop", "S3 guard stop", "A deliberately too coarse run that the solver's guard must stop (exit status 3)."},
      {{"--fraction", "F", "dt as a multiple of the predicted critical step (default 3)", false}},
      [](const repro::Driver& d) {
        const double fraction = d.number("--fraction", 3.0);
        if (!(fraction > 0.0)) {
          std::fprintf(stderr, "guard_stop: --fraction must be positive\n");
          return 2;
        }
        dda::Scene s = s3::guard_scene(fraction);
        s.blocks[0].vertices = {{-1.001, -0.5}, {-0.001, -0.5}, {-0.001, 0.5}, {-1.001, 0.5}};  // A's face at -1 mm
        dda::Simulation sim(s);
        const std::string dir = d.out + "/data/guard_stop";
        const s3::Series series =
            s3::guarded_series(sim, s.duration, dir + "/series.csv",
                               "two squares, kn 1e10 Pa, dt = " + repro::format_short(fraction) +
                                   " x predicted dt_crit = " + repro::format_short(sim.dt()) + " s");
        if (series.message.empty()) {
          std::remove((dir + "/stop.txt").c_str());
          return 0;
        }
        std::ofstream(dir + "/stop.txt") << series.message << '\n';
        std::fprintf(stderr, "guard_stop: %s\n", series.message.c_str());
        return 3;
      });
}
