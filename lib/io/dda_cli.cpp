// dda: run or check a scene file (schema: lib/io/SCHEMA.md).
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "dda/io/csv.hpp"
#include "dda/io/run.hpp"
#include "dda/io/scene_file.hpp"
#include "dda/simulation.hpp"

namespace {

constexpr int kOk = 0;
constexpr int kBadInput = 2;
constexpr int kSimulationFailed = 3;
constexpr int kOutputFailed = 4;
constexpr int kInterrupted = 130;

const char* const kUsage =
    "Usage:\n"
    "  dda run SCENE.json --out DIR [--quiet] [--max-steps N] [--vtk]\n"
    "          [--vtk-every N] [--block-table]\n"
    "      Simulate the scene to its duration and write DIR/timeseries.csv,\n"
    "      DIR/snapshots.csv and DIR/run.json (each via a .tmp file renamed\n"
    "      into place when complete). Progress goes to stderr about once a\n"
    "      second for runs longer than a second (--quiet: none).\n"
    "      A run of more than max_steps steps (duration / dt; the scene's\n"
    "      \"max_steps\", default 10000000) is refused; --max-steps N allows N.\n"
    "      --vtk: also a ParaView series, DIR/vtk/blocks.pvd (blocks as\n"
    "      polygons: velocity, spin, stress, ...) and DIR/vtk/contacts.pvd\n"
    "      (contacts as points: forces, penetration), one .vtu file per frame,\n"
    "      a frame at each snapshot time (the scene's \"output.vtk\": true).\n"
    "      --vtk-every N: a frame every N steps instead (implies --vtk;\n"
    "      \"output.vtk_every\"). --block-table: also DIR/blocks.csv, one row\n"
    "      per block (time, step, block, x, y, vx, vy, rot, spin, stress) at\n"
    "      each time-series row (\"output.block_table\": true). The flags add\n"
    "      to the scene's output section and override its vtk_every.\n"
    "  dda check SCENE.json [SCENE.json ...] [--max-steps N]\n"
    "      Validate scene files only (as dda run would); one line per file.\n"
    "  dda --help\n"
    "\n"
    "Exit codes:\n"
    "  0    success\n"
    "  2    bad input: command line or scene file (nothing is written)\n"
    "  3    the simulation failed (dda::SimulationError or a non-finite value);\n"
    "       the output up to the failure is written, run.json says why\n"
    "  4    the output could not be written\n"
    "  130  interrupted (SIGINT/SIGTERM); no CSV file or run.json is written\n"
    "       (ParaView frames already taken stay, with their .pvd)\n"
    "\n"
    "Scene file schema and output columns: lib/io/SCHEMA.md\n";

volatile std::sig_atomic_t g_interrupt = 0;
extern "C" void on_signal(int) { g_interrupt = 1; }

int usage_error(const std::string& message) {
  std::cerr << "dda: " << message << "\n\n" << kUsage;
  return kBadInput;
}

// "<name> N" / "<name>=N" at args[i]: N > 0, or 0 on a bad value.
// Returns the number of arguments used (0: not this option).
std::size_t positive_option(const std::vector<std::string>& args, std::size_t i, const std::string& name,
                            std::int64_t& n) {
  const std::string& a = args[i];
  std::string value;
  std::size_t used = 0;
  if (a == name) {
    if (i + 1 >= args.size()) return n = 0, 1;
    value = args[i + 1], used = 2;
  } else if (a.rfind(name + "=", 0) == 0) {
    value = a.substr(name.size() + 1), used = 1;
  } else {
    return 0;
  }
  try {
    std::size_t end = 0;
    const long long v = std::stoll(value, &end);
    n = end == value.size() && v > 0 ? v : 0;
  } catch (const std::exception&) {
    n = 0;
  }
  return used;
}

std::size_t max_steps_option(const std::vector<std::string>& args, std::size_t i, std::int64_t& n) {
  return positive_option(args, i, "--max-steps", n);
}

int cmd_check(const std::vector<std::string>& args) {
  std::vector<std::string> files;
  dda::io::ReadOptions read;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (const std::size_t used = max_steps_option(args, i, read.max_steps)) {
      if (read.max_steps <= 0) return usage_error("check: --max-steps needs a positive integer");
      i += used - 1;
    } else if (args[i].rfind("--", 0) == 0) {
      return usage_error("check: unknown option " + args[i]);
    } else {
      files.push_back(args[i]);
    }
  }
  if (files.empty()) return usage_error("check: no scene file given");
  int rc = kOk;
  for (const std::string& path : files) {
    try {
      const dda::io::SceneFile f = dda::io::load_scene_file(path, read);
      // With dt_fraction > 0 the step is only known once the simulation is
      // built (a fraction of its predicted critical step).
      double dt = f.scene.dt, dt_crit = 0.0;
      if (f.scene.dt_fraction > 0.0) {
        try {
          const dda::Simulation sim(f.scene);
          dt = sim.dt();
          dt_crit = sim.predicted_critical_step();
          dda::io::check_step_count(f, dt, path);
        } catch (const dda::io::SceneFileError& e) {
          std::cerr << e.what() << "\n";
          rc = kBadInput;
          continue;
        } catch (const std::exception& e) {
          std::cerr << path << ": " << e.what() << "\n";
          rc = kBadInput;
          continue;
        }
      }
      const double steps = std::round(f.scene.duration / dt);
      std::cout << path << ": ok: " << f.scene.blocks.size() << " blocks, " << f.scene.boundaries.size()
                << " boundary segments, " << steps << " steps of " << dt << " s";
      if (f.scene.dt_fraction > 0.0)
        std::cout << " (dt_fraction " << f.scene.dt_fraction << " of the predicted critical step " << dt_crit
                  << " s)";
      for (std::size_t g = 0; g < f.generated.size(); ++g)
        std::cout << (g == 0 ? " (" : "; ") << f.generated[g].count << " blocks generated from region " << g << ", "
                  << f.generated[g].dropped << " slivers dropped (" << f.generated[g].dropped_area << " m^2)"
                  << (g + 1 == f.generated.size() ? ")" : "");
      std::cout << "\n";
    } catch (const dda::io::SceneFileError& e) {
      std::cerr << e.what() << "\n";
      rc = kBadInput;
    }
  }
  return rc;
}

int cmd_run(const std::vector<std::string>& args) {
  std::string scene_path, out_dir;
  bool quiet = false, vtk = false, block_table = false;
  std::int64_t vtk_every = 0;
  dda::io::ReadOptions read;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (const std::size_t used = max_steps_option(args, i, read.max_steps)) {
      if (read.max_steps <= 0) return usage_error("run: --max-steps needs a positive integer");
      i += used - 1;
    } else if (const std::size_t used_vtk = positive_option(args, i, "--vtk-every", vtk_every)) {
      if (vtk_every <= 0 || vtk_every > std::numeric_limits<int>::max())
        return usage_error("run: --vtk-every needs a positive integer (steps between ParaView frames)");
      i += used_vtk - 1;
    } else if (a == "--vtk") {
      vtk = true;
    } else if (a == "--block-table") {
      block_table = true;
    } else if (a == "--out") {
      if (i + 1 >= args.size()) return usage_error("run: --out needs a directory");
      out_dir = args[++i];
    } else if (a.rfind("--out=", 0) == 0) {
      out_dir = a.substr(6);
    } else if (a == "--quiet" || a == "-q") {
      quiet = true;
    } else if (a.rfind("-", 0) == 0 && a != "-") {
      return usage_error("run: unknown option " + a);
    } else if (scene_path.empty()) {
      scene_path = a;
    } else {
      return usage_error("run: more than one scene file given");
    }
  }
  if (scene_path.empty()) return usage_error("run: no scene file given");
  if (out_dir.empty()) return usage_error("run: --out DIR is required");

  dda::io::SceneFile file;
  try {
    file = dda::io::load_scene_file(scene_path, read);
  } catch (const dda::io::SceneFileError& e) {
    std::cerr << e.what() << "\n";
    return kBadInput;
  }
  file.output.vtk = file.output.vtk || vtk || vtk_every > 0;
  if (vtk_every > 0) file.output.vtk_every = static_cast<int>(vtk_every);
  file.output.block_table = file.output.block_table || block_table;

  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  dda::io::RunOptions opt;
  opt.out_dir = out_dir;
  opt.scene_label = scene_path;
  opt.progress = quiet ? nullptr : &std::cerr;
  opt.interrupt = &g_interrupt;
  try {
    const dda::io::RunResult r = dda::io::run_scene(file, opt);
    switch (r.status) {
      case dda::io::RunStatus::kCompleted:
        if (!quiet) {
          std::cerr << "dda: done: " << r.steps << " steps to t = " << r.time << " s in " << r.wall_seconds
                    << " s; wrote " << out_dir << "/timeseries.csv (" << r.timeseries_rows << " rows), " << out_dir
                    << "/snapshots.csv (" << r.snapshot_rows << " rows), ";
          if (file.output.block_table) std::cerr << out_dir << "/blocks.csv (" << r.block_table_rows << " rows), ";
          if (file.output.vtk)
            std::cerr << out_dir << "/vtk/blocks.pvd and contacts.pvd (" << r.vtk_frames << " frames each), ";
          std::cerr << out_dir << "/run.json\n";
        }
        return kOk;
      case dda::io::RunStatus::kSimulationError:
        std::cerr << scene_path << ": simulation failed: " << r.message << "\n"
                  << "dda: wrote the output up to t = " << r.last_row_time << " s to " << out_dir << " (" << r.timeseries_rows
                  << " time-series rows)\n";
        return kSimulationFailed;
      case dda::io::RunStatus::kInterrupted:
        std::cerr << "dda: interrupted at t = " << r.time << " s; no CSV file or run.json written";
        if (file.output.vtk) std::cerr << " (" << r.vtk_frames << " ParaView frames in " << out_dir << "/vtk)";
        std::cerr << "\n";
        return kInterrupted;
    }
  } catch (const dda::io::OutputError& e) {
    std::cerr << "dda: output error: " << e.what() << "\n";
    return kOutputFailed;
  } catch (const dda::io::SceneFileError& e) {  // the step limit with the simulation's dt
    std::cerr << e.what() << "\n";
    return kBadInput;
  } catch (const dda::SceneError& e) {  // not expected after load_scene_file
    std::cerr << scene_path << ": " << e.what() << "\n";
    return kBadInput;
  }
  return kOk;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) return usage_error("no command given");
  const std::string& cmd = args[0];
  bool help = false;
  for (const std::string& a : args) help = help || a == "--help" || a == "-h";
  if (help || cmd == "help") {
    std::cout << kUsage;
    return kOk;
  }
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  try {
    if (cmd == "run") return cmd_run(rest);
    if (cmd == "check") return cmd_check(rest);
  } catch (const std::exception& e) {
    std::cerr << "dda: internal error: " << e.what() << "\n";
    return 1;
  }
  return usage_error("unknown command '" + cmd + "'");
}
