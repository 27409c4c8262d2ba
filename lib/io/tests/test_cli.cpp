// The `dda` executable: exit codes and what it writes (runs the built binary).
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "scene_helpers.hpp"

namespace fs = std::filesystem;
using dda::io::test::write_scene;

namespace {

// Runs `dda <args>` with output to `log`; returns the exit code.
int run_cli(const std::string& args, const std::string& log) {
  const std::string cmd = std::string("\"") + DDA_CLI_PATH + "\" " + args + " >\"" + log + "\" 2>&1";
  const int status = std::system(cmd.c_str());
  REQUIRE(status != -1);
  REQUIRE(WIFEXITED(status));
  return WEXITSTATUS(status);
}

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string tmp(const std::string& name) {
  const fs::path p = fs::path(DDA_IO_TEST_TMP) / "cli" / name;
  fs::remove_all(p);
  fs::create_directories(p.parent_path());
  return p.string();
}

}  // namespace

TEST_CASE("dda run on a bad file exits 2 and writes nothing", "[io][cli]") {
  for (const char* bad : {"clockwise.json", "syntax_error.json", "unknown_key.json", "overflow.json"}) {
    const std::string out = tmp(std::string("bad_") + bad);
    const std::string log = out + ".log";
    const std::string file = std::string(DDA_IO_BAD_DIR) + "/" + bad;
    CHECK(run_cli("run \"" + file + "\" --out \"" + out + "\"", log) == 2);
    CHECK_FALSE(fs::exists(out));  // not even the directory
    const std::string msg = slurp(log);
    INFO(msg);
    CHECK(msg.find(file) == 0);  // the message starts with the file name
  }
}

TEST_CASE("dda check: 0 on a good file, 2 on a bad one", "[io][cli]") {
  const std::string log = tmp("check") + ".log";
  CHECK(run_cli(std::string("check \"") + DDA_SCENES_DIR + "/two_squares.json\"", log) == 0);
  CHECK(slurp(log).find(": ok: 2 blocks") != std::string::npos);
  CHECK(run_cli(std::string("check \"") + DDA_IO_BAD_DIR + "/missing_key.json\"", log) == 2);
  CHECK(slurp(log).find("missing_key.json: dt: missing required key") != std::string::npos);
}

TEST_CASE("dda usage errors exit 2, --help exits 0", "[io][cli]") {
  const std::string log = tmp("usage") + ".log";
  CHECK(run_cli("--help", log) == 0);
  CHECK(slurp(log).find("dda run SCENE.json --out DIR") != std::string::npos);
  CHECK(run_cli("", log) == 2);
  CHECK(run_cli("frobnicate", log) == 2);
  CHECK(run_cli(std::string("run \"") + DDA_SCENES_DIR + "/two_squares.json\"", log) == 2);  // no --out
  CHECK(run_cli("run --out /tmp/x", log) == 2);
}

TEST_CASE("dda run writes the outputs and exits 0", "[io][cli]") {
  const std::string dir = tmp("run");
  const std::string scene = write_scene(dir, R"({
    "materials": [{"density": 2000, "young": 1e9, "poisson": 0.25}],
    "blocks": [{"rect": [0, 0, 1, 1], "velocity": [1, 0]}, {"rect": [1.01, 0, 1, 1]}],
    "contact": {"kn": 1e7}, "dt": 1e-4, "duration": 0.05
  })");
  const std::string out = dir + "/out";
  CHECK(run_cli("run \"" + scene + "\" --out \"" + out + "\" --quiet", dir + "/log") == 0);
  CHECK(fs::exists(out + "/timeseries.csv"));
  CHECK(fs::exists(out + "/snapshots.csv"));
  CHECK(fs::exists(out + "/run.json"));
  CHECK_FALSE(fs::exists(out + "/timeseries.csv.tmp"));
}

TEST_CASE("dda run exits 3 on a SimulationError and keeps the valid rows", "[io][cli]") {
  const std::string dir = tmp("blowup");
  const std::string scene = write_scene(dir, R"({
    "materials": [{"density": 2000, "young": 1e9, "poisson": 0.25}],
    "blocks": [{"rect": [0, 0, 1, 1], "velocity": [50, 0]}, {"rect": [1.05, 0, 1, 1]}],
    "contact": {"kn": 1e12}, "dt": 1e-3, "duration": 1.0, "output": {"every": 1}
  })");
  const std::string out = dir + "/out";
  CHECK(run_cli("run \"" + scene + "\" --out \"" + out + "\"", dir + "/log") == 3);
  const std::string msg = slurp(dir + "/log");
  INFO(msg);
  CHECK(msg.find("simulation failed") != std::string::npos);
  CHECK(fs::exists(out + "/timeseries.csv"));
  CHECK(slurp(out + "/run.json").find("\"simulation_error\"") != std::string::npos);
}

TEST_CASE("dda check with dt_fraction reports the step it gives", "[io][cli]") {
  const std::string dir = tmp("check_dt_fraction");
  const std::string scene = write_scene(dir, R"({
    "materials": [{"density": 2000, "young": 1e9, "poisson": 0.25}],
    "blocks": [{"rect": [0, 0, 1, 1], "velocity": [1, 0]}, {"rect": [1.01, 0, 1, 1]}],
    "contact": {"kn": 1e7, "small_edge_rays": "virtual_replaces_vertex"},
    "dt_fraction": 0.5, "duration": 0.05,
    "guards": {"max_step_motion": 0.2, "max_energy_growth": 1.0, "energy_check_every": 10}
  })");
  const std::string log = dir + ".log";
  CHECK(run_cli("check \"" + scene + "\"", log) == 0);
  const std::string msg = slurp(log);
  INFO(msg);
  CHECK(msg.find(": ok: 2 blocks") != std::string::npos);
  CHECK(msg.find("(dt_fraction 0.5 of the predicted critical step ") != std::string::npos);
  // An unknown key inside "guards": exit 2, the field named.
  std::ofstream(scene) << R"({
    "materials": [{"density": 2000, "young": 1e9, "poisson": 0.25}],
    "blocks": [{"rect": [0, 0, 1, 1]}],
    "contact": {"kn": 1e7}, "dt": 1e-4, "duration": 0.05,
    "guards": {"max_energy": 1.0}
  })";
  CHECK(run_cli("check \"" + scene + "\"", log) == 2);
  const std::string m = slurp(log);
  CHECK(m.find(scene + ":") == 0);
  CHECK(m.find(": guards.max_energy: unknown key") != std::string::npos);
}
