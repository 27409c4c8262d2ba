// Run output: atomic CSV files, the time-series columns, runs that complete,
// fail or are interrupted.
#include <catch2/catch.hpp>

#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "dda/io/csv.hpp"
#include "dda/io/run.hpp"
#include "dda/io/scene_file.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// A fresh, empty directory for one test.
std::string fresh_dir(const std::string& name) {
  const fs::path p = fs::path(DDA_IO_TEST_TMP) / name;
  fs::remove_all(p);
  return p.string();
}

std::vector<std::vector<std::string>> read_csv(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::vector<std::string>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::stringstream s(line);
    std::string f;
    while (std::getline(s, f, ',')) fields.push_back(f);
    rows.push_back(fields);
  }
  return rows;
}

int column(const std::vector<std::string>& header, const std::string& name) {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return static_cast<int>(i);
  FAIL("no column " << name);
  return -1;
}

bool no_tmp_files(const std::string& dir) {
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".tmp") return false;
  return true;
}

// Two unit squares, A at speed v toward B, `gap` apart.
dda::io::SceneFile squares(double v, double gap, double kn, double dt, double duration, int every) {
  json j = {{"materials", {{{"density", 2000}, {"young", 1e9}, {"poisson", 0.25}}}},
            {"blocks", {{{"name", "A"}, {"rect", {0, 0, 1, 1}}, {"velocity", {v, 0}}},
                        {{"name", "B"}, {"rect", {1 + gap, 0, 1, 1}}}}},
            {"contact", {{"kn", kn}}},
            {"dt", dt},
            {"duration", duration},
            {"output", {{"every", every}}}};
  return dda::io::parse_scene(j.dump(), "squares.json");
}

// The record `dir`/run.json of a run.
json run_record(const std::string& dir) {
  std::ifstream in(dir + "/run.json");
  return json::parse(in);
}

// `f` run into `dir` with its interrupt flag already set before the first
// step, and what every such run leaves: a checkpoint, no temporary file,
// run.json's status, the time series' row at t = 0. The result and run.json.
std::pair<dda::io::RunResult, json> interrupted_run(const dda::io::SceneFile& f, const std::string& dir) {
  volatile std::sig_atomic_t flag = 1;
  dda::io::RunOptions opt;
  opt.out_dir = dir;
  opt.interrupt = &flag;
  const dda::io::RunResult r = dda::io::run_scene(f, opt);
  CHECK(r.status == dda::io::RunStatus::kInterrupted);
  CHECK(r.checkpoint_path == dir + "/checkpoint.dda");
  REQUIRE(fs::exists(dir + "/checkpoint.dda"));
  CHECK(no_tmp_files(dir));
  const json run = run_record(dir);
  CHECK(run["status"] == "interrupted");
  CHECK(read_csv(dir + "/timeseries.csv").size() == 2);
  return {r, run};
}

}  // namespace

TEST_CASE("CsvFile appears only on commit and refuses NaN rows", "[io][csv]") {
  const std::string dir = fresh_dir("csv");
  fs::create_directories(dir);
  const std::string path = dir + "/a.csv";
  {
    dda::io::CsvFile f(path, {"t", "n"});
    f.row({0.1, 3});
    CHECK(fs::exists(path + ".tmp"));
    CHECK_FALSE(fs::exists(path));
    CHECK_THROWS_AS(f.row({std::nan(""), 4}), dda::io::NonFiniteValue);
    CHECK_THROWS_AS(f.row({HUGE_VAL, 4}), dda::io::NonFiniteValue);
    f.row({1e-300, -7});
    f.commit();
  }
  CHECK(fs::exists(path));
  CHECK_FALSE(fs::exists(path + ".tmp"));
  const auto rows = read_csv(path);
  REQUIRE(rows.size() == 3);
  CHECK(rows[0] == std::vector<std::string>{"t", "n"});
  CHECK(rows[1] == std::vector<std::string>{"0.1", "3"});
  CHECK(rows[2] == std::vector<std::string>{"1e-300", "-7"});
  {
    dda::io::CsvFile g(dir + "/b.csv", {"t"});
    g.row({1.0});
  }  // no commit: nothing left behind
  CHECK_FALSE(fs::exists(dir + "/b.csv"));
  CHECK_FALSE(fs::exists(dir + "/b.csv.tmp"));
  CHECK_THROWS_AS(dda::io::CsvFile("/nonexistent/dir/c.csv", {"t"}), dda::io::OutputError);
}

TEST_CASE("time-series columns", "[io][run]") {
  const std::vector<std::string> h = dda::io::timeseries_header({0, 2});
  const std::vector<std::string> expected = {
      "time",     "step",      "b0_x",     "b0_y",     "b0_vx",     "b0_vy",     "b0_rot",   "b0_spin",
      "b2_x",     "b2_y",      "b2_vx",    "b2_vy",    "b2_rot",    "b2_spin",   "E_kinetic", "E_gravity",
      "E_strain", "E_contact", "E_friction_spring", "E_total", "E_dissipated", "E_balance_error", "px",
      "py",       "contacts"};
  CHECK(h == expected);
}

TEST_CASE("a completed run writes the time series, the snapshots and run.json", "[io][run]") {
  const std::string dir = fresh_dir("complete");
  const dda::io::SceneFile f = squares(1.0, 0.01, 1e7, 1e-4, 0.1, 7);  // 1000 steps; contact from 0.01 s
  dda::io::RunOptions opt;
  opt.out_dir = dir;
  opt.scene_label = "squares.json";
  const dda::io::RunResult r = dda::io::run_scene(f, opt);
  CHECK(r.status == dda::io::RunStatus::kCompleted);
  CHECK(r.steps == 1000);
  CHECK(r.time == Approx(0.1));
  CHECK(no_tmp_files(dir));

  const auto ts = read_csv(dir + "/timeseries.csv");
  REQUIRE(ts.size() == 1 + 1 + 1000 / 7 + 1);  // header, t = 0, every 7 steps, the last step
  CHECK(ts[0] == dda::io::timeseries_header({0, 1}));
  CHECK(std::stod(ts[1][0]) == 0.0);
  CHECK(std::stod(ts.back()[0]) == Approx(0.1));
  CHECK(ts.back()[1] == "1000");
  const int px = column(ts[0], "px"), etot = column(ts[0], "E_total"), n = column(ts[0], "contacts");
  const int balance = column(ts[0], "E_balance_error"), lost = column(ts[0], "E_dissipated");
  int touching_rows = 0;
  for (std::size_t i = 1; i < ts.size(); ++i) {
    touching_rows += ts[i][static_cast<std::size_t>(n)] == "1";
    CHECK(std::stod(ts[i][static_cast<std::size_t>(px)]) == Approx(2000.0).epsilon(1e-9));
    CHECK(std::stod(ts[i][static_cast<std::size_t>(etot)]) == Approx(1000.0).epsilon(2e-2));
    // Frictionless and undamped: nothing dissipated; the budget closes to
    // the explicit scheme's O(dt^2) error (well below 1 % of the 1 kJ).
    CHECK(std::stod(ts[i][static_cast<std::size_t>(lost)]) == 0.0);
    CHECK(std::fabs(std::stod(ts[i][static_cast<std::size_t>(balance)])) < 10.0);
  }
  CHECK(touching_rows > 0);

  const auto snap = read_csv(dir + "/snapshots.csv");
  CHECK(snap[0] == std::vector<std::string>{"time", "step", "block", "vertex", "x", "y"});
  REQUIRE(snap.size() == 1 + 2 * 2 * 4);  // default snapshots: t = 0 and the end; 2 blocks of 4 vertices
  CHECK(snap[1] == std::vector<std::string>{"0", "0", "0", "0", "0", "0"});
  CHECK(std::stod(snap.back()[0]) == Approx(0.1));

  const json run = run_record(dir);
  CHECK(run["status"] == "completed");
  CHECK(run["steps"] == 1000);
  CHECK(run["blocks"][1]["name"] == "B");
  CHECK(run["blocks"][0]["mass"].get<double>() == Approx(2000.0));
}

TEST_CASE("Paper A 4.1 example: the two squares exchange velocities", "[io][run][examples]") {
  const std::string dir = fresh_dir("two_squares");
  const dda::io::SceneFile f = dda::io::load_scene_file(std::string(DDA_SCENES_DIR) + "/two_squares.json");
  dda::io::RunOptions opt;
  opt.out_dir = dir;
  const dda::io::RunResult r = dda::io::run_scene(f, opt);
  REQUIRE(r.status == dda::io::RunStatus::kCompleted);
  const auto ts = read_csv(dir + "/timeseries.csv");
  const auto& last = ts.back();
  CHECK(std::stod(last[static_cast<std::size_t>(column(ts[0], "time"))]) == Approx(1.0));
  CHECK(std::fabs(std::stod(last[static_cast<std::size_t>(column(ts[0], "b0_vx"))])) < 0.02);
  CHECK(std::stod(last[static_cast<std::size_t>(column(ts[0], "b1_vx"))]) == Approx(1.0).epsilon(0.02));
  CHECK(std::stod(last[static_cast<std::size_t>(column(ts[0], "px"))]) == Approx(2000.0).epsilon(1e-9));
}

TEST_CASE("a run stopped by SimulationError keeps the valid rows", "[io][run]") {
  // A fast impact on a stiff penalty with a coarse step: the blocks blow up.
  const std::string dir = fresh_dir("blowup");
  const dda::io::SceneFile f = squares(50.0, 0.05, 1e12, 1e-3, 1.0, 1);
  dda::io::RunOptions opt;
  opt.out_dir = dir;
  const dda::io::RunResult r = dda::io::run_scene(f, opt);
  REQUIRE(r.status == dda::io::RunStatus::kSimulationError);
  CHECK_FALSE(r.message.empty());
  CHECK(r.steps < 1000);
  CHECK(no_tmp_files(dir));
  const auto ts = read_csv(dir + "/timeseries.csv");
  CHECK(ts.size() >= 2);
  CHECK(ts.size() == r.timeseries_rows + 1);
  for (const auto& row : ts)
    for (const std::string& field : row) {
      CHECK(field.find("nan") == std::string::npos);
      CHECK(field.find("inf") == std::string::npos);
    }
  const json run = run_record(dir);
  CHECK(run["status"] == "simulation_error");
  CHECK(run["message"].get<std::string>() == r.message);
}

TEST_CASE("an interrupted run writes the output so far and a checkpoint", "[io][run]") {
  const std::string dir = fresh_dir("interrupted");
  const dda::io::SceneFile f = squares(1.0, 0.01, 1e7, 1e-4, 0.1, 7);
  const auto [r, run] = interrupted_run(f, dir);
  CHECK(r.steps == 0);
  CHECK(r.timeseries_rows == 1);  // the row at t = 0
  CHECK(run["message"] == "interrupted at step 0 (t = 0 s)");
}

TEST_CASE("an interrupted cdem run writes the output so far and a checkpoint", "[io][run]") {
  const std::string dir = fresh_dir("interrupted_cdem");
  const dda::io::SceneFile f = dda::io::load_scene_file(std::string(DDA_SCENES_DIR) + "/two_prisms.json");
  const json run = interrupted_run(f, dir).second;
  CHECK(run["model"] == "cdem");
  // The checkpoint holds the cdem model's section beside the run's.
  const dda::io::Checkpoint c = dda::io::read_checkpoint(dir);
  CHECK(c.model == "cdem");
  CHECK(c.find("run") != nullptr);
  CHECK(c.find("cdem.model") != nullptr);
  CHECK(c.find("penalty.simulation") == nullptr);
}

TEST_CASE("write_file_atomic and save_scene_file", "[io][csv]") {
  const std::string dir = fresh_dir("save");
  fs::create_directories(dir);
  const dda::io::SceneFile f = squares(1.0, 0.01, 1e7, 1e-4, 0.1, 7);
  dda::io::save_scene_file(dir + "/s.json", f);
  CHECK(no_tmp_files(dir));
  const dda::io::SceneFile g = dda::io::load_scene_file(dir + "/s.json");
  CHECK(dda::io::write_scene(g) == dda::io::write_scene(f));
}

TEST_CASE("with dt_fraction, the run uses and records that fraction of the predicted critical step", "[io][run]") {
  const std::string dir = fresh_dir("dt_fraction");
  json j = {{"materials", {{{"density", 2000}, {"young", 1e9}, {"poisson", 0.25}}}},
            {"blocks", {{{"name", "A"}, {"rect", {0, 0, 1, 1}}, {"velocity", {1, 0}}},
                        {{"name", "B"}, {"rect", {1.01, 0, 1, 1}}}}},
            {"contact", {{"kn", 1e7}}},
            {"dt_fraction", 0.5},
            {"duration", 0.02},
            {"output", {{"every", 1000}}}};
  const dda::io::SceneFile f = dda::io::parse_scene(j.dump(), "fraction.json");
  const dda::Simulation sim(f.scene);
  REQUIRE(sim.predicted_critical_step() > 0.0);
  CHECK(sim.dt() == 0.5 * sim.predicted_critical_step());
  dda::io::RunOptions opt;
  opt.out_dir = dir;
  const dda::io::RunResult r = dda::io::run_scene(f, opt);
  REQUIRE(r.status == dda::io::RunStatus::kCompleted);
  const json run = run_record(dir);
  CHECK(run["dt"].get<double>() == sim.dt());
  CHECK(r.steps == static_cast<std::int64_t>(std::llround(0.02 / sim.dt())));
}
