// dda: run, resume or check a scene file of either contact model (schema:
// lib/io/SCHEMA.md).
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "dda/cdem/model.hpp"
#include "dda/io/checkpoint.hpp"
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
    "  dda run SCENE.json --out DIR [--threads N] [--checkpoint-every T]\n"
    "          [--checkpoint-wall S] [--vtk] [--vtk-every N] [--block-table]\n"
    "          [--quiet] [--max-steps N]\n"
    "      Simulate the scene to its duration with the contact model it selects\n"
    "      (\"model\": \"penalty\", Paper A, the default; or \"cdem\", Paper B) and\n"
    "      write DIR/timeseries.csv, DIR/snapshots.csv and DIR/run.json (each via\n"
    "      a .tmp file renamed into place when the run ends). Progress goes to\n"
    "      stderr about once a second for runs longer than a second (--quiet: none).\n"
    "      A run of more than max_steps steps (duration / dt; the scene's\n"
    "      \"max_steps\", default 10000000) is refused; --max-steps N allows N.\n"
    "      --threads N           threads of the penalty solver (default: the scene's\n"
    "                            \"threads\", else 1); the results are the same bits\n"
    "                            for any N; run.json records N. The cdem model\n"
    "                            steps on one thread.\n"
    "      --checkpoint-every T  write DIR/checkpoint.dda every T s of simulated time\n"
    "      --checkpoint-wall S   ... and/or every S s of wall-clock time (both\n"
    "                            override the scene's \"checkpoint\"; either model)\n"
    "      --vtk                 also a ParaView series: DIR/vtk/blocks.pvd (penalty\n"
    "                            model: blocks as polygons with velocity, spin,\n"
    "                            stress, ...) or DIR/vtk/elements.pvd (cdem model:\n"
    "                            elements with their nodes), and DIR/vtk/contacts.pvd\n"
    "                            (contacts as points: forces, penetration); one .vtu\n"
    "                            file per frame, a frame at each snapshot time (the\n"
    "                            scene's \"output.vtk\": true)\n"
    "      --vtk-every N         a frame every N steps instead (implies --vtk;\n"
    "                            \"output.vtk_every\")\n"
    "      --block-table         also DIR/blocks.csv, one row per block (time, step,\n"
    "                            block, x, y, vx, vy, rot, spin, stress) at each\n"
    "                            time-series row (\"output.block_table\": true;\n"
    "                            penalty model). The output flags add to the\n"
    "                            scene's output section, --vtk-every overrides its\n"
    "                            vtk_every.\n"
    "      On SIGINT or SIGTERM the run finishes its current step, writes a\n"
    "      checkpoint and the output so far, and exits 130.\n"
    "  dda run --resume DIR [SCENE.json] [--threads N] [--checkpoint-every T]\n"
    "          [--checkpoint-wall S] [--quiet] [--max-steps N]\n"
    "      Continue the run whose checkpoint DIR holds, to the end: the outputs\n"
    "      are byte for byte those of a run never stopped (run.json's wall-clock\n"
    "      fields aside). SCENE.json: the scene file, if it moved (default: the\n"
    "      path the checkpoint recorded); it must be the same text. A checkpoint\n"
    "      of another scene or format version, a truncated or corrupted one, or\n"
    "      outputs changed since it was written are refused, nothing written.\n"
    "      The run keeps the outputs it started with (no --vtk, --vtk-every,\n"
    "      --block-table here).\n"
    "  dda check SCENE.json [SCENE.json ...] [--max-steps N]\n"
    "      Validate scene files only (as dda run would); one line per file.\n"
    "  dda --help\n"
    "  dda --version\n"
    "      The version and the git commit the program was built from.\n"
    "\n"
    "Exit codes:\n"
    "  0    success\n"
    "  2    bad input: command line, scene file or checkpoint (nothing is written)\n"
    "  3    the simulation failed (dda::SimulationError or a non-finite value);\n"
    "       the output up to the failure is written, run.json says why\n"
    "  4    the output could not be written\n"
    "  130  interrupted (SIGINT/SIGTERM): the output so far (with the ParaView\n"
    "       frames taken and their .pvd) and a checkpoint are written, run.json\n"
    "       says \"interrupted\"\n"
    "\n"
    "Scene file schema and output columns: lib/io/SCHEMA.md\n";

volatile std::sig_atomic_t g_interrupt = 0;
extern "C" void on_signal(int) { g_interrupt = 1; }

int usage_error(const std::string& message) {
  std::cerr << "dda: " << message << "\n\n" << kUsage;
  return kBadInput;
}

// "--name VALUE" or "--name=VALUE" at args[i]: sets value and returns the
// number of arguments used (0: not this option); a missing value is "".
std::size_t option_value(const std::vector<std::string>& args, std::size_t i, const std::string& name,
                         std::string& value) {
  const std::string& a = args[i];
  if (a == name) {
    value = i + 1 < args.size() ? args[i + 1] : std::string();
    return i + 1 < args.size() ? 2 : 1;
  }
  if (a.rfind(name + "=", 0) == 0) {
    value = a.substr(name.size() + 1);
    return 1;
  }
  return 0;
}

// A positive integer, or 0.
long long positive_integer(const std::string& text) {
  try {
    std::size_t end = 0;
    const long long v = std::stoll(text, &end);
    return end == text.size() && v > 0 ? v : 0;
  } catch (const std::exception&) {
    return 0;
  }
}

// A positive finite number, or 0 (NaN, infinity, 0, negative, not a number).
double positive_number(const std::string& text) {
  try {
    std::size_t end = 0;
    const double v = std::stod(text, &end);
    return end == text.size() && std::isfinite(v) && v > 0.0 ? v : 0.0;
  } catch (const std::exception&) {
    return 0.0;
  }
}

// "--max-steps N" at args[i] into read.max_steps; 0 used: not this option,
// -1: a bad value (message in `error`).
std::size_t max_steps_option(const std::vector<std::string>& args, std::size_t i, dda::io::ReadOptions& read,
                             std::string& error) {
  std::string v;
  const std::size_t used = option_value(args, i, "--max-steps", v);
  if (used == 0) return 0;
  read.max_steps = positive_integer(v);
  if (read.max_steps <= 0) error = "--max-steps needs a positive integer, got '" + v + "'";
  return used;
}

int cmd_check(const std::vector<std::string>& args) {
  std::vector<std::string> files;
  dda::io::ReadOptions read;
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string error;
    if (const std::size_t used = max_steps_option(args, i, read, error)) {
      if (!error.empty()) return usage_error("check: " + error);
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
      std::cout << path << ": ok: " << f.scene.blocks.size() << " blocks, ";
      if (f.model == dda::io::ContactModel::kCdem) {
        const dda::cdem::Model model(dda::io::cdem_scene(f));
        std::cout << "model cdem (" << model.active_elements(false) << " elements, " << model.node_count()
                  << " nodes; critical step " << model.critical_dt() << " s), ";
      } else {
        std::cout << f.scene.boundaries.size() << " boundary segments, ";
      }
      std::cout << steps << " steps of " << dt << " s";
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

// What `dda run` was asked on its command line.
struct RunArgs {
  std::string scene_path, out_dir, resume_dir;
  bool quiet = false;
  dda::io::ReadOptions read;
  int threads = 0;
  dda::io::CheckpointSpec checkpoint;
  bool vtk = false, block_table = false;
  int vtk_every = 0;
};

// Parses the arguments of `dda run`; "" or the usage error's message.
std::string parse_run_args(const std::vector<std::string>& args, RunArgs& a) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    std::string v, error;
    std::size_t used = 0;
    if ((used = max_steps_option(args, i, a.read, error))) {
      if (!error.empty()) return error;
    } else if ((used = option_value(args, i, "--out", v))) {
      if (v.empty()) return "--out needs a directory";
      a.out_dir = v;
    } else if ((used = option_value(args, i, "--resume", v))) {
      if (v.empty()) return "--resume needs the directory of the run to continue";
      a.resume_dir = v;
    } else if ((used = option_value(args, i, "--threads", v))) {
      const long long n = positive_integer(v);
      if (n <= 0 || n > dda::io::kMaxThreads)
        return "--threads needs an integer in [1, " + std::to_string(dda::io::kMaxThreads) + "], got '" + v + "'";
      a.threads = static_cast<int>(n);
    } else if ((used = option_value(args, i, "--checkpoint-every", v))) {
      a.checkpoint.every = positive_number(v);
      if (!(a.checkpoint.every > 0.0))
        return "--checkpoint-every needs a positive number of seconds of simulated time, got '" + v + "'";
    } else if ((used = option_value(args, i, "--checkpoint-wall", v))) {
      a.checkpoint.every_wall = positive_number(v);
      if (!(a.checkpoint.every_wall > 0.0))
        return "--checkpoint-wall needs a positive number of seconds of wall-clock time, got '" + v + "'";
    } else if ((used = option_value(args, i, "--vtk-every", v))) {
      const long long n = positive_integer(v);
      if (n <= 0 || n > std::numeric_limits<int>::max())
        return "--vtk-every needs a positive integer (steps between ParaView frames), got '" + v + "'";
      a.vtk_every = static_cast<int>(n);
    } else if (arg == "--vtk") {
      used = 1;
      a.vtk = true;
    } else if (arg == "--block-table") {
      used = 1;
      a.block_table = true;
    } else if (arg == "--quiet" || arg == "-q") {
      used = 1;
      a.quiet = true;
    } else if (arg.rfind("-", 0) == 0 && arg != "-") {
      return "unknown option " + arg;
    } else if (a.scene_path.empty()) {
      used = 1;
      a.scene_path = arg;
    } else {
      return "more than one scene file given";
    }
    i += used - 1;
  }
  if (!a.resume_dir.empty()) {
    if (!a.out_dir.empty() && a.out_dir != a.resume_dir)
      return "--resume DIR continues the run in DIR: give no other --out";
    if (a.vtk || a.vtk_every > 0 || a.block_table)
      return "--resume: the run keeps the outputs it started with (no --vtk, --vtk-every or --block-table)";
    a.out_dir = a.resume_dir;
    return "";
  }
  if (a.scene_path.empty()) return "no scene file given";
  if (a.out_dir.empty()) return "--out DIR is required";
  return "";
}

int cmd_run(const std::vector<std::string>& args) {
  RunArgs a;
  if (const std::string error = parse_run_args(args, a); !error.empty()) return usage_error("run: " + error);

  // A resumed run: the checkpoint first (it names the scene), then the scene.
  dda::io::Checkpoint checkpoint;
  const bool resume = !a.resume_dir.empty();
  if (resume) {
    try {
      checkpoint = dda::io::read_checkpoint(a.resume_dir);
    } catch (const dda::io::CheckpointError& e) {
      std::cerr << "dda: cannot resume: " << e.what() << "\n";
      return kBadInput;
    }
    if (a.scene_path.empty()) a.scene_path = checkpoint.scene_path;
  }
  dda::io::SceneFile file;
  try {
    file = dda::io::load_scene_file(a.scene_path, a.read);
  } catch (const dda::io::SceneFileError& e) {
    std::cerr << e.what() << "\n";
    if (resume)
      std::cerr << "dda: cannot resume: the scene of the checkpoint in " << a.resume_dir
                << " (give its file: dda run SCENE.json --resume " << a.resume_dir << ")\n";
    return kBadInput;
  }
  file.output.vtk = file.output.vtk || a.vtk || a.vtk_every > 0;
  if (a.vtk_every > 0) file.output.vtk_every = a.vtk_every;
  file.output.block_table = file.output.block_table || a.block_table;
  if (file.model == dda::io::ContactModel::kCdem && a.block_table)
    return usage_error("run: --block-table: the per-block table of 6-DOF blocks is the penalty model's (" +
                       a.scene_path + " is a cdem scene)");
  if (file.model == dda::io::ContactModel::kCdem && a.threads > 1)
    return usage_error("run: --threads: the cdem model (" + a.scene_path + ") steps on one thread");

  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  dda::io::RunOptions opt;
  opt.out_dir = a.out_dir;
  opt.scene_label = a.scene_path;
  opt.progress = a.quiet ? nullptr : &std::cerr;
  opt.interrupt = &g_interrupt;
  opt.threads = a.threads;
  opt.checkpoint = a.checkpoint;
  opt.resume = resume ? &checkpoint : nullptr;
  const std::string& out_dir = a.out_dir;
  try {
    const dda::io::RunResult r = dda::io::run_scene(file, opt);
    switch (r.status) {
      case dda::io::RunStatus::kCompleted:
        if (!a.quiet) {
          std::cerr << "dda: done: " << r.steps << " steps to t = " << r.time << " s in " << r.wall_seconds
                    << " s on " << r.threads << (r.threads == 1 ? " thread" : " threads") << "; wrote " << out_dir
                    << "/timeseries.csv (" << r.timeseries_rows << " rows), " << out_dir << "/snapshots.csv ("
                    << r.snapshot_rows << " rows), ";
          // (counts, not the flags: a resumed run keeps the outputs it started with)
          if (r.block_table_rows > 0) std::cerr << out_dir << "/blocks.csv (" << r.block_table_rows << " rows), ";
          if (r.vtk_frames > 0)
            std::cerr << out_dir << "/vtk/" << (file.model == dda::io::ContactModel::kCdem ? "elements" : "blocks")
                      << ".pvd and contacts.pvd (" << r.vtk_frames << " frames each), ";
          std::cerr << out_dir << "/run.json\n";
        }
        return kOk;
      case dda::io::RunStatus::kSimulationError:
        std::cerr << a.scene_path << ": simulation failed: " << r.message << "\n"
                  << "dda: wrote the output up to t = " << r.last_row_time << " s to " << out_dir << " ("
                  << r.timeseries_rows << " time-series rows)\n";
        return kSimulationFailed;
      case dda::io::RunStatus::kInterrupted:
        std::cerr << "dda: " << r.message << "; wrote the output so far to " << out_dir;
        if (r.vtk_frames > 0) std::cerr << " (with " << r.vtk_frames << " ParaView frames in " << out_dir << "/vtk)";
        if (!r.checkpoint_path.empty())
          std::cerr << " and the checkpoint " << r.checkpoint_path << "; continue with: dda run --resume " << out_dir
                    << "\n";
        else
          std::cerr << "; no checkpoint\n";
        return kInterrupted;
    }
  } catch (const dda::io::CheckpointError& e) {
    std::cerr << "dda: cannot resume: " << e.what() << "\n";
    return kBadInput;
  } catch (const dda::io::OutputError& e) {
    std::cerr << "dda: output error: " << e.what() << "\n";
    return kOutputFailed;
  } catch (const dda::io::SceneFileError& e) {  // the step limit with the model's dt
    std::cerr << e.what() << "\n";
    return kBadInput;
  } catch (const dda::SceneError& e) {  // not expected after load_scene_file
    std::cerr << a.scene_path << ": " << e.what() << "\n";
    return kBadInput;
  }
  return kOk;
}

}  // namespace

// Written at build time by cmake/dda_version.cmake.
extern const char* const kDdaVersion;
extern const char* const kDdaCommit;

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) return usage_error("no command given");
  const std::string& cmd = args[0];
  if (cmd == "--version" || cmd == "version") {
    std::cout << "dda " << kDdaVersion << " (commit " << kDdaCommit << ")\n";
    return kOk;
  }
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
