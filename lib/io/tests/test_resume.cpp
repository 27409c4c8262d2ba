// Checkpoints and `dda run --resume`: a run stopped by SIGINT (or killed
// outright after a periodic checkpoint) at a random step and resumed ends
// with every output file as a run never stopped wrote it; a checkpoint that
// does not fit is refused naming the reason, and nothing is overwritten.
#include <catch2/catch.hpp>

#include <cstdint>
#include <fstream>
#include <functional>
#include <random>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_helpers.hpp"
#include "dda/io/checkpoint.hpp"

using namespace dda::io::test;
using nlohmann::json;

namespace {

// A jointed column collapsing on a floor: friction history, the sweep
// broad phase, snapshots and tracked blocks; about a second of computing.
const char* const kColumn = R"({
  "name": "column",
  "materials": [{"name": "rock", "density": 2700, "young": 2e9, "poisson": 0.3}],
  "blocks": [{"name": "thrown", "rect": [-3, 0.5, 0.5, 0.5], "velocity": [4, 0]}],
  "generated": {"name": "rock", "region": [[0, 0], [4, 0], [4, 8], [0, 8]],
                "joint_sets": [{"dip_deg": 70, "spacing": 1.0}, {"dip_deg": 30, "spacing": 1.6}],
                "min_area": 0.2},
  "boundaries": [{"a": [-5, 0], "b": [20, 0], "group": 1}],
  "contact": {"kn": 2e9, "kt": 1e9, "friction_deg": 20,
              "friction_rules": [{"groups": [0, 1], "friction_deg": 35}]},
  "gravity": [0, -9.81],
  "broad_phase": "sweep",
  "dt_fraction": 0.5,
  "duration": 0.8,
  "guards": {"energy_check_every": 25},
  "output": {"every": 7, "snapshots": [0, 0.2, 0.33, 0.5, 0.8], "tracked_blocks": ["thrown", "rock_3", "rock_10"]}
})";

// The column's scene file, one for every run here (run.json names it).
std::string column_scene() {
  static std::string path;
  if (path.empty()) {
    const std::string dir = scratch("resume_scene");
    fs::create_directories(dir);
    path = dir + "/column.json";
    std::ofstream(path) << kColumn;
  }
  return path;
}

// run.json without the fields of the wall clock and the thread count.
json run_record(const std::string& dir) {
  json j = json::parse(slurp(dir + "/run.json"));
  for (const char* key : {"wall_seconds", "steps_per_second", "threads"}) j.erase(key);
  return j;
}

// Every output of two run directories is the same, byte for byte (run.json
// up to its wall-clock fields), and neither holds a checkpoint any more.
void check_same_outputs(const std::string& a, const std::string& b) {
  auto fa = files_of(a), fb = files_of(b);
  CHECK(fa.count("checkpoint.dda") == 0);
  CHECK(fb.count("checkpoint.dda") == 0);
  CHECK(run_record(a) == run_record(b));
  fa.erase("run.json");
  fb.erase("run.json");
  REQUIRE(fa.size() == fb.size());
  for (const auto& [name, bytes] : fa) {
    INFO(name);
    REQUIRE(fb.count(name) == 1);
    CHECK(bytes.size() == fb[name].size());
    CHECK(bytes == fb[name]);
  }
}

// Every output a run can write: the long per-block table and a ParaView
// series besides the time series and the snapshots.
const std::vector<std::string> kAllOutputs = {"--block-table", "--vtk-every", "400"};

// The uninterrupted run of the column, once for every test here.
const std::string& reference_run(double* seconds = nullptr) {
  static std::string dir;
  static double wall = 0.0;
  if (dir.empty()) {
    const std::string d = scratch("resume_reference");
    const std::string scene = column_scene();
    std::vector<std::string> args = {"run", scene, "--out", d, "--quiet"};
    args.insert(args.end(), kAllOutputs.begin(), kAllOutputs.end());
    REQUIRE(run_cli(args, d + ".log") == 0);
    wall = json::parse(slurp(d + "/run.json"))["wall_seconds"].get<double>();
    dir = d;
  }
  if (seconds) *seconds = wall;
  return dir;
}

std::mt19937& rng() {
  static std::mt19937 g(std::random_device{}());
  return g;
}

// `dda run` of the column into `dir` with every output and `extra` flags.
std::vector<std::string> column_args(const std::string& dir, const std::string& scene,
                                     const std::vector<std::string>& extra) {
  std::vector<std::string> args = {"run", scene, "--out", dir, "--quiet"};
  args.insert(args.end(), kAllOutputs.begin(), kAllOutputs.end());
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

// A random moment between fractions lo and hi of the reference run's wall time, s.
double random_moment(double lo, double hi) {
  double wall = 0.0;
  reference_run(&wall);
  return std::uniform_real_distribution<double>(lo, hi)(rng()) * wall;
}

// Starts the column in `dir` (extra: more flags) and stops it with `signal`
// at a random moment of its run; retries earlier if it ended first. The
// exit code of the stopped run.
int stopped_run(const std::string& dir, const std::string& scene, int signal, std::vector<std::string> extra = {}) {
  double delay = random_moment(0.15, 0.85);
  const std::vector<std::string> args = column_args(dir, scene, extra);
  for (int attempt = 0; attempt < 6; ++attempt, delay *= 0.5) {
    fs::remove_all(dir);
    const int rc = run_cli_signalled(args, dir + ".log", delay, signal);
    if (rc != 0) return rc;  // stopped before its end
  }
  FAIL("the run always ended before the signal");
  return 0;
}

std::int64_t json_steps(const std::string& dir) { return json::parse(slurp(dir + "/run.json"))["steps"].get<std::int64_t>(); }

// A run stopped in `dir` said where it stopped and how to go on, and its
// run.json says "interrupted" before the end of the uninterrupted run in
// `ref`: the step it stopped at.
std::int64_t check_interrupted(const std::string& dir, const std::string& ref) {
  const std::string msg = slurp(dir + ".log");
  INFO(msg);
  CHECK(msg.find("dda: interrupted at step ") != std::string::npos);
  CHECK(msg.find("continue with: dda run --resume " + dir) != std::string::npos);
  const json stopped = json::parse(slurp(dir + "/run.json"));
  CHECK(stopped["status"] == "interrupted");
  const std::int64_t at = stopped["steps"].get<std::int64_t>();
  CHECK(at < json_steps(ref));
  return at;
}

}  // namespace

TEST_CASE("a run interrupted by SIGINT at a random step and resumed ends byte-identical", "[io][resume]") {
  const std::string& ref = reference_run();
  const std::string dir = scratch("resume_sigint");
  const std::string scene = column_scene();
  REQUIRE(stopped_run(dir, scene, SIGINT) == 130);
  // Where it stopped, what it wrote, how to go on.
  CHECK(check_interrupted(dir, ref) > 0);
  CHECK(fs::exists(dir + "/checkpoint.dda"));
  CHECK(fs::exists(dir + "/timeseries.csv"));  // the output so far
  CHECK(fs::exists(dir + "/blocks.csv"));
  CHECK(fs::exists(dir + "/vtk/blocks.pvd"));
  CHECK_FALSE(fs::exists(dir + "/timeseries.csv.tmp"));
  // Resumed on two threads (the same bits on any count).
  REQUIRE(run_cli({"run", "--resume", dir, "--quiet", "--threads", "2"}, dir + "_resume.log") == 0);
  check_same_outputs(ref, dir);
  CHECK(json::parse(slurp(dir + "/run.json"))["threads"] == 2);
}

TEST_CASE("a run killed outright after a periodic checkpoint resumes from it, byte-identical", "[io][resume]") {
  const std::string& ref = reference_run();
  const std::string scene = column_scene();
  // Checkpoints on the simulated clock, or on the wall clock.
  for (const std::vector<std::string>& every :
       {std::vector<std::string>{"--checkpoint-every", "0.05"}, std::vector<std::string>{"--checkpoint-wall", "0.1"}}) {
    const std::string dir = scratch("resume_sigkill_" + every[0].substr(2));
    INFO(every[0]);
    // SIGKILL: no handler, nothing flushed or committed; the .tmp outputs
    // and the last periodic checkpoint are what is left. Sent at a random
    // moment after the first checkpoint appeared (on a loaded machine a
    // moment drawn from the whole run can come before it); earlier if the
    // run ended first.
    double delay = random_moment(0.0, 0.5);
    const std::vector<std::string> args = column_args(dir, scene, every);
    int rc = 0;
    for (int attempt = 0; attempt < 6 && rc != 128 + SIGKILL; ++attempt, delay *= 0.5) {
      fs::remove_all(dir);
      rc = signalled_when(args, dir + ".log", dir + "/checkpoint.dda", SIGKILL, delay);
    }
    REQUIRE(rc == 128 + SIGKILL);
    REQUIRE(fs::exists(dir + "/checkpoint.dda"));
    CHECK_FALSE(fs::exists(dir + "/run.json"));
    CHECK(fs::exists(dir + "/timeseries.csv.tmp"));
    // Interrupted once more on the way, then to the end. A slow start (an
    // instrumented build on a busy machine) can take the signal before the
    // handler is installed: ended by SIGTERM itself, a kill like the first.
    const std::string log = dir + "_resume.log";
    const int again = run_cli_signalled({"run", "--resume", dir, "--quiet"}, log, 0.3, SIGTERM);
    CHECK((again == 130 || again == 0 || again == 128 + SIGTERM));
    if (again != 0) REQUIRE(run_cli({"run", "--resume", dir, "--quiet"}, log) == 0);
    check_same_outputs(ref, dir);
  }
}

TEST_CASE("a checkpoint that does not fit is refused with the reason, nothing overwritten", "[io][resume]") {
  const std::string base = scratch("resume_refused");
  const std::string scene = column_scene();
  REQUIRE(stopped_run(base, scene, SIGINT) == 130);
  REQUIRE(fs::exists(base + "/checkpoint.dda"));
  const std::string ckpt = slurp(base + "/checkpoint.dda");

  // Each case: a copy of the stopped run, spoiled one way; resuming it exits
  // 2 naming the reason and leaves every file as it was.
  auto refused = [&](const std::string& name, const std::function<void(const std::string&)>& spoil,
                     const std::string& reason, std::vector<std::string> extra = {}) {
    const std::string dir = scratch("resume_refused_" + name);
    fs::copy(base, dir, fs::copy_options::recursive);
    spoil(dir);
    const auto before = files_of(dir);
    std::vector<std::string> args = {"run", "--resume", dir, "--quiet"};
    args.insert(args.end(), extra.begin(), extra.end());
    CHECK(run_cli(args, dir + ".log") == 2);
    const std::string msg = slurp(dir + ".log");
    INFO(name << ": " << msg);
    CHECK(msg.find(reason) != std::string::npos);
    CHECK(files_of(dir) == before);
  };
  auto write = [](const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; };

  refused("truncated", [&](const std::string& d) { write(d + "/checkpoint.dda", ckpt.substr(0, ckpt.size() / 2)); },
          "truncated");
  refused("corrupted", [&](const std::string& d) {
    std::string c = ckpt;
    c[c.size() / 2] = static_cast<char>(c[c.size() / 2] ^ 0x10);
    write(d + "/checkpoint.dda", c);
  }, "corrupted: the checksum does not match");
  refused("version", [&](const std::string& d) {
    std::string c = ckpt;
    c[8] = 7;  // the format version's low byte
    write(d + "/checkpoint.dda", c);
  }, "checkpoint format version 7; this dda reads version 1");
  refused("not_a_checkpoint", [&](const std::string& d) { write(d + "/checkpoint.dda", "{\"a\": 1}\n"); },
          "not a dda checkpoint");
  // Another scene: the same scene file edited since (one block moved).
  const std::string other_scene = base + "_other.json";
  {
    std::string text = kColumn;
    text.replace(text.find("[-3, 0.5, 0.5, 0.5]"), 19, "[-3, 0.6, 0.5, 0.5]");
    std::ofstream(other_scene) << text;
  }
  refused("another_scene", [](const std::string&) {}, "written for another scene", {other_scene});
  // An output changed since the checkpoint.
  refused("changed_output", [&](const std::string& d) {
    std::string ts = slurp(d + "/timeseries.csv");
    ts[ts.size() / 2] = ts[ts.size() / 2] == '1' ? '2' : '1';
    write(d + "/timeseries.csv", ts);
  }, "timeseries.csv: does not hold the");
  refused("removed_output", [](const std::string& d) { fs::remove(d + "/snapshots.csv"); },
          "snapshots.csv: does not hold the");
}

TEST_CASE("--resume: a directory that does not exist or holds no checkpoint", "[io][resume]") {
  const std::string dir = scratch("resume_missing");
  CHECK(run_cli({"run", "--resume", dir + "/nowhere"}, dir + ".log") == 2);
  CHECK(slurp(dir + ".log").find("nowhere: no such directory") != std::string::npos);
  fs::create_directories(dir);
  CHECK(run_cli({"run", "--resume", dir}, dir + ".log") == 2);
  CHECK(slurp(dir + ".log").find("holds no checkpoint (checkpoint.dda)") != std::string::npos);
  CHECK(fs::is_empty(dir));
}

// --- Paper B's model (the cdem two-prisms scene) ---------------------------

namespace {

// Paper B's two prisms (repro/scenes/two_prisms.json): the touch at 1/3 s,
// the clone and its sub-model live until about 0.3405 s; every output,
// with its ParaView series.
std::string prisms_scene() { return std::string(DDA_SCENES_DIR) + "/two_prisms.json"; }

// The uninterrupted run of the prisms, once for every test here.
const std::string& prisms_reference(double* seconds = nullptr) {
  static std::string dir;
  static double wall = 0.0;
  if (dir.empty()) {
    const std::string d = scratch("resume_prisms_reference");
    REQUIRE(run_cli({"run", prisms_scene(), "--out", d, "--quiet", "--vtk"}, d + ".log") == 0);
    wall = json::parse(slurp(d + "/run.json"))["wall_seconds"].get<double>();
    dir = d;
  }
  if (seconds) *seconds = wall;
  return dir;
}

}  // namespace

TEST_CASE("a cdem run interrupted by SIGINT at a random step and resumed ends byte-identical", "[io][resume][cdem]") {
  double wall = 0.0;
  const std::string& ref = prisms_reference(&wall);
  const std::string dir = scratch("resume_prisms_sigint");
  // The signal a random part of the run's wall time after its output files
  // are open (its handler is installed by then).
  std::uniform_real_distribution<double> when(0.05, 0.9);
  double delay = when(rng()) * wall;
  int rc = 0;
  for (int attempt = 0; attempt < 6 && rc == 0; ++attempt, delay *= 0.5) {
    fs::remove_all(dir);
    rc = signalled_when({"run", prisms_scene(), "--out", dir, "--quiet", "--vtk"}, dir + ".log",
                        dir + "/timeseries.csv.tmp", SIGINT, delay);
  }
  REQUIRE(rc == 130);
  const std::int64_t at = check_interrupted(dir, ref);
  CHECK(json::parse(slurp(dir + "/run.json"))["model"] == "cdem");
  REQUIRE(fs::exists(dir + "/checkpoint.dda"));
  CHECK(fs::exists(dir + "/vtk/elements.pvd"));
  REQUIRE(run_cli({"run", "--resume", dir}, dir + "_resume.log") == 0);
  INFO(slurp(dir + "_resume.log"));
  CHECK(slurp(dir + "_resume.log").find("from step " + std::to_string(at) + " ") != std::string::npos);
  check_same_outputs(ref, dir);
}

TEST_CASE("a cdem run killed after its checkpoint in the collision resumes from it, byte-identical",
          "[io][resume][cdem]") {
  // A checkpoint at 0.3345 s of simulated time (step 669): the clone tied,
  // the sub-model of the colliding elements live. SIGKILL as soon as it is
  // on the disk: nothing flushed or committed after it.
  const std::string& ref = prisms_reference();
  const std::string dir = scratch("resume_prisms_sigkill");
  int rc = 0;
  for (int attempt = 0; attempt < 8 && rc != 128 + SIGKILL; ++attempt) {
    fs::remove_all(dir);
    rc = signalled_when({"run", prisms_scene(), "--out", dir, "--quiet", "--vtk", "--checkpoint-every", "0.3345"},
                        dir + ".log", dir + "/checkpoint.dda", SIGKILL);
  }
  REQUIRE(rc == 128 + SIGKILL);
  REQUIRE(fs::exists(dir + "/checkpoint.dda"));
  CHECK_FALSE(fs::exists(dir + "/run.json"));
  const dda::io::Checkpoint c = dda::io::read_checkpoint(dir);
  CHECK(c.model == "cdem");
  REQUIRE(c.find("cdem.model") != nullptr);
  const std::string log = dir + "_resume.log";
  REQUIRE(run_cli({"run", "--resume", dir}, log) == 0);
  INFO(slurp(log));
  CHECK(slurp(log).find("from step 669 (t = 0.3345") != std::string::npos);
  check_same_outputs(ref, dir);
}

TEST_CASE("a cdem checkpoint resumed with another scene file is refused, nothing overwritten", "[io][resume][cdem]") {
  const std::string dir = scratch("resume_prisms_refused");
  // Interrupted before its first step: a checkpoint at step 0.
  int rc = 0;
  for (int attempt = 0; attempt < 4 && rc != 130; ++attempt) {
    fs::remove_all(dir);
    rc = signalled_when({"run", prisms_scene(), "--out", dir, "--quiet"}, dir + ".log", dir + "/timeseries.csv.tmp",
                        SIGTERM);
  }
  REQUIRE(rc == 130);
  REQUIRE(fs::exists(dir + "/checkpoint.dda"));
  const auto before = files_of(dir);
  // The same scene with the other subdivision mode: the text differs.
  const std::string other = dir + "_in_place.json";
  {
    std::string text = slurp(prisms_scene());
    const std::string from = "\"subdivision_mode\": \"submodel\"";
    text.replace(text.find(from), from.size(), "\"subdivision_mode\": \"in_place\"");
    std::ofstream(other) << text;
  }
  CHECK(run_cli({"run", "--resume", dir, other, "--quiet"}, dir + "_other.log") == 2);
  CHECK(slurp(dir + "_other.log").find("written for another scene") != std::string::npos);
  CHECK(files_of(dir) == before);
}
