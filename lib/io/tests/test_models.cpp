// Either contact model from a scene file: the "model" key, Paper B's
// "cdem" section and block meshes, keys refused under the model they do not
// apply to, `dda run` on Paper B's two prisms reproducing the B-6 driver's
// run bit for bit, --threads giving the same bits, and every new key and
// flag refusing bad values.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_helpers.hpp"
#include "dda/cdem/scenes.hpp"
#include "dda/io/models.hpp"
#include "dda/io/scene_file.hpp"
#include "scene_helpers.hpp"

using namespace dda::io::test;

namespace {

// Two triangles 1 m apart, the right one at rest: a valid CDEM scene.
json cdem_base() {
  return json::parse(R"({
    "model": "cdem",
    "materials": [{"density": 2700, "young": 4e10, "poisson": 0.25}],
    "blocks": [
      {"name": "i", "vertices": [[-7, -3.5], [0, 0], [-7, 3.5]], "velocity": [3, 0]},
      {"name": "j", "vertices": [[1, -3.5], [8, 0], [1, 3.5]]}
    ],
    "cdem": {"divisions": 2},
    "dt": 5e-4,
    "duration": 0.01
  })");
}

json penalty_base() {
  return json::parse(R"({
    "materials": [{"density": 2000, "young": 1e9, "poisson": 0.25}],
    "blocks": [{"rect": [0, 0, 1, 1], "velocity": [1, 0]}, {"rect": [1.5, 0, 1, 1]}],
    "contact": {"kn": 1e7},
    "dt": 1e-4,
    "duration": 0.01
  })");
}

// Numbers of a CSV file written in shortest round-trip form, by row.
std::vector<std::vector<double>> read_numbers(const std::string& path, std::vector<std::string>& header) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::stringstream h(line);
  for (std::string f; std::getline(h, f, ',');) header.push_back(f);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream s(line);
    for (std::string f; std::getline(s, f, ',');) row.push_back(std::strtod(f.c_str(), nullptr));
    rows.push_back(row);
  }
  return rows;
}

std::size_t column(const std::vector<std::string>& header, const std::string& name) {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return i;
  FAIL("no column " << name);
  return 0;
}

}  // namespace

TEST_CASE("the model key selects the contact model; the cdem section its options", "[io][models]") {
  const dda::io::SceneFile p = parse_scene(penalty_base().dump(), "p.json");
  CHECK(p.model == dda::io::ContactModel::kPenalty);
  json j = cdem_base();
  j["cdem"] = {{"contact", "two_scale"},
               {"touch_impact", "coulomb"},
               {"tolerance", 4e-3},
               {"strength", {{"tensile", 1e5}, {"cohesion", 2e5}, {"friction_deg", 25}}},
               {"subdivision_mode", "in_place"},
               {"min_subdivision", 3},
               {"max_subdivision", 5},
               {"substep_safety", 0.8},
               {"patch_deletion", "energy_matched"},
               {"mass_damping", 0.5},
               {"divisions", 2}};
  j["blocks"][1]["mesh"] = {{"divisions", 4}};
  j["dt"] = 2e-4;  // the finer mesh's critical step is shorter
  const dda::io::SceneFile f = parse_scene(j.dump(), "c.json");
  CHECK(f.model == dda::io::ContactModel::kCdem);
  const dda::cdem::CdemOptions& o = f.cdem.options;
  CHECK(o.touch_impact == dda::cdem::TouchImpact::kCoulomb);
  CHECK(o.tolerance == 4e-3);
  CHECK(o.strength.tensile == 1e5);
  CHECK(o.strength.cohesion == 2e5);
  CHECK(o.strength.friction_deg == 25.0);
  CHECK(o.subdivision_mode == dda::cdem::SubdivisionMode::kInPlace);
  CHECK(o.min_subdivision == 3);
  CHECK(o.max_subdivision == 5);
  CHECK(o.substep_safety == 0.8);
  CHECK(o.patch_deletion == dda::cdem::PatchDeletion::kEnergyMatched);
  CHECK(o.mass_damping == 0.5);
  const dda::cdem::CdemScene c = dda::io::cdem_scene(f);
  REQUIRE(c.blocks.size() == 2);
  CHECK(c.blocks[0].divisions == 2);
  CHECK(c.blocks[1].divisions == 4);
  // The writer's text reads back to the same scene.
  const dda::io::SceneFile g = parse_scene(dda::io::write_scene(f), "rewritten.json");
  CHECK(dda::io::write_scene(g) == dda::io::write_scene(f));
  CHECK(g.cdem.options.patch_deletion == dda::cdem::PatchDeletion::kEnergyMatched);
  // The node-to-edge penalty baseline and a rectangle's grid mesh.
  json b = cdem_base();
  b["blocks"] = json::parse(R"([{"name": "bar", "rect": [0, 0, 4, 1], "velocity": [1, 0], "mesh": {"cells": [8, 2]}},
                                {"name": "wall", "rect": [4.5, -1, 1, 3], "fixed": true}])");
  b["cdem"] = {{"contact", "node_to_edge_penalty"}, {"penalty_kn", 1e8}};
  b["dt"] = 1e-5;
  const dda::io::SceneFile pen = parse_scene(b.dump(), "bar.json");
  CHECK(pen.cdem.options.contact == dda::cdem::ContactMode::kNodeToEdgePenalty);
  CHECK_FALSE(pen.cdem.options.subdivision);
  const dda::cdem::Model bar(dda::io::cdem_scene(pen));
  CHECK(bar.active_elements(false) == 8 * 2 * 2 + 4);  // the grid's 32 triangles and the wall's fan of 4
}

TEST_CASE("keys of the other model and bad cdem values are refused, naming the field", "[io][models]") {
  auto expect = [](const json& j, const std::string& text) {
    const std::string m = error_of(j);
    INFO(m);
    CHECK(m.find(text) != std::string::npos);
  };
  // Each case: the base scene, the values set (by JSON pointer), the message.
  struct Case {
    json (*base)();
    std::vector<std::pair<const char*, json>> set;
    const char* message;
  };
  const std::vector<Case> cases = {
      {penalty_base, {{"/model", "cdm"}}, "model: unknown value \"cdm\"; expected one of \"penalty\", \"cdem\""},
      {penalty_base,
       {{"/cdem", json{{"divisions", 2}}}},
       "cdem: applies to the cdem model only; this scene's \"model\" is \"penalty\""},
      {penalty_base, {{"/blocks/0/mesh", json{{"divisions", 2}}}}, "blocks[0].mesh: applies to the cdem model only"},
      {cdem_base, {{"/blocks/0/spin", 1.0}}, "blocks[0].spin: applies to the penalty model only"},
      {cdem_base, {{"/cdem/contact", "two-scale"}}, "cdem.contact: unknown value \"two-scale\""},
      {cdem_base, {{"/cdem/penalty_kn", 1e8}}, "cdem.penalty_kn: applies to \"contact\": \"node_to_edge_penalty\" only"},
      {cdem_base,
       {{"/cdem/contact", "node_to_edge_penalty"}, {"/cdem/strength", json{{"tensile", 1.0}}}},
       "cdem.strength: applies to the two-scale contact only"},
      {cdem_base,
       {{"/cdem/subdivision", false}, {"/cdem/max_subdivision", 4}},
       "cdem.max_subdivision: has no effect with \"subdivision\": false"},
      {cdem_base,
       {{"/cdem/patch_deletion", "energy_matched"}},
       "cdem.patch_deletion: applies to \"subdivision_mode\": \"in_place\" only"},
      {cdem_base, {{"/cdem/tolerance", 0}}, "cdem.tolerance: must be positive"},
      {cdem_base, {{"/cdem/divisions", 0}}, "cdem.divisions: must lie in [1, 64]"},
      {cdem_base, {{"/blocks/0/mesh", json{{"cells", {2, 2}}}}}, "blocks[0].mesh.cells: needs an axis-aligned rectangle"},
      {cdem_base, {{"/dt", 5e-3}}, "dt: time step 0.005 s exceeds the critical step"},  // above the mesh's critical step
  };
  for (const Case& k : cases) {
    json j = k.base();
    for (const auto& [at, value] : k.set) j[json::json_pointer(at)] = value;
    expect(j, k.message);
  }
  for (const char* key : {"contact", "boundaries", "strains", "guards", "damping", "dt_fraction", "threads",
                          "broad_phase", "initial_overlap", "rotation_update"}) {
    json c = cdem_base();
    c[key] = penalty_base().value(key, json(1));
    if (std::string(key) == "boundaries") c[key] = json::array();
    expect(c, std::string(key) + ": applies to the penalty model only");
  }
  // The message has the position of the field in the file.
  json c = cdem_base();
  c["cdem"]["tolerance"] = -1;
  const std::string m = error_of(c);
  CHECK(m.rfind("scene.json:", 0) == 0);
  CHECK(m.find(":cdem.tolerance") == std::string::npos);  // "file:line:col: cdem.tolerance: ..."
  CHECK(m.find(": cdem.tolerance: ") != std::string::npos);
}

TEST_CASE("threads and checkpoint keys: values and refusals", "[io][models]") {
  json j = penalty_base();
  j["threads"] = 2;
  j["checkpoint"] = {{"every", 0.005}, {"every_wall", 60}};
  const dda::io::SceneFile f = parse_scene(j.dump(), "t.json");
  CHECK(f.threads == 2);
  CHECK(f.checkpoint.every == 0.005);
  CHECK(f.checkpoint.every_wall == 60.0);
  CHECK(dda::io::write_scene(parse_scene(dda::io::write_scene(f), "w.json")) == dda::io::write_scene(f));
  // Checkpoints hold either model's state: the key is the cdem model's too.
  json c = cdem_base();
  c["checkpoint"] = {{"every", 0.25}};
  const dda::io::SceneFile fc = parse_scene(c.dump(), "c.json");
  CHECK(fc.checkpoint.every == 0.25);
  CHECK(parse_scene(dda::io::write_scene(fc), "w.json").checkpoint.every == 0.25);
  auto expect = [](const json& s, const std::string& text) {
    const std::string m = error_of(s);
    INFO(m);
    CHECK(m.find(text) != std::string::npos);
  };
  j = penalty_base();
  j["threads"] = 0;
  expect(j, "threads: must lie in [1, 1024]");
  j["threads"] = 1.5;
  expect(j, "threads: expected an integer");
  j = penalty_base();
  j["checkpoint"] = {{"every", 0}};
  expect(j, "checkpoint.every: must be > 0");
  j["checkpoint"] = {{"every_wall", -1}};
  expect(j, "checkpoint.every_wall: must be > 0");
  j["checkpoint"] = json::object();
  expect(j, "checkpoint: give \"every\"");
  j["checkpoint"] = {{"evry", 1}};
  expect(j, "checkpoint.evry: unknown key (did you mean 'every'?)");
  // JSON has no NaN: the text "NaN" is a syntax error, a string a type error.
  j["checkpoint"] = {{"every", "nan"}};
  expect(j, "checkpoint.every: expected a number, got string");
}

TEST_CASE("dda run on Paper B's two prisms reproduces the B-6 driver's run bit for bit", "[io][models][cdem]") {
  // The driver's run (repro/B_6_two_prisms): dda::cdem::two_prisms with 2
  // divisions and the default options (Sect. 5 as written), touch
  // snapshots captured, dt 5e-4 s, stepped while time < duration - dt/2.
  dda::cdem::CdemOptions opt;
  opt.capture_touch_snapshots = true;
  dda::cdem::CdemScene scene = dda::cdem::two_prisms(2, opt);
  scene.dt = 5e-4;
  dda::cdem::Model driver(scene);

  const std::string dir = scratch("two_prisms");
  const std::string file = std::string(DDA_SCENES_DIR) + "/two_prisms.json";
  REQUIRE(run_cli({"check", file}, dir + "_check.log") == 0);
  INFO(slurp(dir + "_check.log"));
  CHECK(slurp(dir + "_check.log").find("model cdem (8 elements") != std::string::npos);
  REQUIRE(run_cli({"run", file, "--out", dir, "--quiet", "--vtk"}, dir + ".log") == 0);
  std::vector<std::string> h;
  const std::vector<std::vector<double>> rows = read_numbers(dir + "/timeseries.csv", h);
  const std::size_t c_step = column(h, "step"), c_time = column(h, "time");
  REQUIRE(rows.size() > 900);
  std::size_t compared = 0;
  for (const std::vector<double>& row : rows) {
    while (driver.step_count() < static_cast<std::int64_t>(row[c_step])) driver.step();
    REQUIRE(driver.step_count() == static_cast<std::int64_t>(row[c_step]));
    CHECK(row[c_time] == driver.time());
    for (int b = 0; b < 2; ++b) {
      const std::string p = "b" + std::to_string(b) + "_";
      CHECK(row[column(h, p + "x")] == driver.block_mean_position(b).x);
      CHECK(row[column(h, p + "y")] == driver.block_mean_position(b).y);
      CHECK(row[column(h, p + "vx")] == driver.block_velocity(b).x);
      CHECK(row[column(h, p + "vy")] == driver.block_velocity(b).y);
    }
    const dda::cdem::CdemEnergy e = driver.energy();
    const dda::cdem::CdemEnergyAccount a = driver.energy_account();
    CHECK(row[column(h, "E_kinetic")] == e.kinetic);
    CHECK(row[column(h, "E_strain")] == e.strain);
    CHECK(row[column(h, "E_dissipated")] == a.touch_loss + a.refine_loss + a.deletion_loss);
    CHECK(row[column(h, "px")] == driver.momentum().x);
    CHECK(row[column(h, "contacts")] == static_cast<double>(driver.clones().size()));
    ++compared;
  }
  // The driver's loop ends where dda run's does.
  while (driver.time() < scene.duration - 0.5 * driver.dt()) driver.step();
  CHECK(static_cast<std::int64_t>(rows.back()[c_step]) == driver.step_count());
  CHECK(compared == rows.size());
  // Its collision happened: a touch, a clone that separated, j moving off.
  CHECK(driver.touches().size() >= 1);
  CHECK(driver.separations().size() >= 1);
  CHECK(driver.block_velocity(1).x > 1.0);
  // The snapshots: the outline vertices at the end, exactly.
  std::vector<std::string> sh;
  const std::vector<std::vector<double>> snaps = read_numbers(dir + "/snapshots.csv", sh);
  std::size_t at_end = 0;
  for (const std::vector<double>& s : snaps) {
    if (static_cast<std::int64_t>(s[1]) != driver.step_count()) continue;
    const std::vector<dda::Vec2> o = driver.block_outline(static_cast<int>(s[2]));
    const dda::Vec2 v = o[static_cast<std::size_t>(s[3])];
    CHECK(s[4] == v.x);
    CHECK(s[5] == v.y);
    ++at_end;
  }
  CHECK(at_end == 6);  // two triangles
  const json run = json::parse(slurp(dir + "/run.json"));
  CHECK(run["model"] == "cdem");
  // The ParaView series of the cdem model: its elements and clone nodes, a frame per snapshot.
  CHECK(run["vtk_frames"] == 7);
  CHECK(fs::exists(dir + "/vtk/elements.pvd"));
  CHECK(fs::exists(dir + "/vtk/elements_000006.vtu"));
  CHECK(fs::exists(dir + "/vtk/contacts.pvd"));
  CHECK(run["status"] == "completed");
}

TEST_CASE("dda run --threads N: the same files for any N, recorded in run.json", "[io][models]") {
  const std::string dir = scratch("threads");
  const std::string scene = write_scene(dir, R"({
    "materials": [{"density": 2700, "young": 2e9, "poisson": 0.3}],
    "blocks": [],
    "generated": {"region": [[0, 0], [3, 0], [3, 5], [0, 5]],
                  "joint_sets": [{"dip_deg": 65, "spacing": 0.9}, {"dip_deg": 25, "spacing": 1.3}], "min_area": 0.1},
    "boundaries": [{"a": [-5, 0], "b": [10, 0]}],
    "contact": {"kn": 2e9, "kt": 1e9, "friction_deg": 25},
    "gravity": [0, -9.81], "broad_phase": "sweep", "dt_fraction": 0.5, "duration": 0.1,
    "threads": 3,
    "output": {"every": 5, "snapshots": [0, 0.05, 0.1]}
  })", "pile.json");
  REQUIRE(run_cli({"run", scene, "--out", dir + "/one", "--quiet", "--threads", "1"}, dir + "/one.log") == 0);
  REQUIRE(run_cli({"run", scene, "--out", dir + "/two", "--quiet", "--threads", "2"}, dir + "/two.log") == 0);
  REQUIRE(run_cli({"run", scene, "--out", dir + "/file", "--quiet"}, dir + "/file.log") == 0);  // the scene's 3
  for (const char* name : {"timeseries.csv", "snapshots.csv"}) {
    INFO(name);
    const std::string one = slurp(dir + "/one/" + name);
    CHECK(one.size() > 1000);
    CHECK(one == slurp(dir + "/two/" + name));
    CHECK(one == slurp(dir + "/file/" + name));
  }
  CHECK(json::parse(slurp(dir + "/one/run.json"))["threads"] == 1);
  CHECK(json::parse(slurp(dir + "/two/run.json"))["threads"] == 2);
  CHECK(json::parse(slurp(dir + "/file/run.json"))["threads"] == 3);
}

TEST_CASE("bad values of the new flags exit 2 naming the flag, nothing written", "[io][models][cli]") {
  const std::string dir = scratch("bad_flags");
  const std::string squares = std::string(DDA_SCENES_DIR) + "/two_squares.json";
  const std::string prisms = std::string(DDA_SCENES_DIR) + "/two_prisms.json";
  auto refused = [&](const std::vector<std::string>& args, const std::string& text) {
    CHECK(run_cli(args, dir + ".log") == 2);
    const std::string m = slurp(dir + ".log");
    INFO(m);
    CHECK(m.find(text) != std::string::npos);
    CHECK_FALSE(fs::exists(dir));
  };
  refused({"run", squares, "--out", dir, "--threads", "0"}, "--threads needs an integer in [1, 1024], got '0'");
  refused({"run", squares, "--out", dir, "--threads", "two"}, "--threads needs an integer");
  refused({"run", squares, "--out", dir, "--threads"}, "--threads needs an integer");
  refused({"run", squares, "--out", dir, "--checkpoint-every", "0"},
          "--checkpoint-every needs a positive number of seconds of simulated time, got '0'");
  refused({"run", squares, "--out", dir, "--checkpoint-every", "nan"}, "--checkpoint-every needs a positive number");
  refused({"run", squares, "--out", dir, "--checkpoint-every=-1"}, "--checkpoint-every needs a positive number");
  refused({"run", squares, "--out", dir, "--checkpoint-wall", "inf"}, "--checkpoint-wall needs a positive number");
  refused({"run", prisms, "--out", dir, "--threads", "2"}, "--threads: the cdem model");
  refused({"run", squares, "--resume", dir + "_a", "--out", dir}, "--resume DIR continues the run in DIR");
}
