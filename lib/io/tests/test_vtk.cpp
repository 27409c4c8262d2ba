// ParaView output and the long per-block table: the model-neutral writer
// (shape checks, NaN refused, atomic series), the Paper A adapter against
// the simulation it draws, the Paper B adapter on the two-prisms scene
// (elements with their nodes, clone nodes and penalty springs as contact
// points), the scene keys and `dda run`'s use of them. VTK's own reader
// reads the files back in vtk_readback.py (ctest io_vtk_readback).
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dda/cdem/scenes.hpp"
#include "dda/io/block_table.hpp"
#include "dda/io/csv.hpp"
#include "dda/io/run.hpp"
#include "dda/io/scene_file.hpp"
#include "dda/io/vtk_cdem.hpp"
#include "dda/io/vtk_dda.hpp"
#include "dda/io/vtk_series.hpp"
#include "dda/paper_scenes.hpp"

namespace fs = std::filesystem;
using nlohmann::json;
using namespace dda::io;

namespace {

std::string fresh_dir(const std::string& name) {
  const fs::path p = fs::path(DDA_IO_TEST_TMP) / "vtk" / name;
  fs::remove_all(p);
  return p.string();
}

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// A triangle and a square sharing an edge, with one cell array.
VtkMesh two_cells() {
  VtkMesh m;
  m.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 0.5}};
  const int square[] = {0, 1, 2, 3}, tri[] = {1, 4, 2};
  m.add_cell(square, 4);
  m.add_cell(tri, 3);
  VtkArray a;
  a.name = "block";
  a.integer = true;
  a.values = {0, 1};
  m.cell_data.push_back(a);
  VtkArray v;
  v.name = "velocity";
  v.components = 3;
  v.values = {0.5, 0, 0, -1.25, 2, 0};
  m.cell_data.push_back(v);
  return m;
}

// The vector of a 3-component array's tuple i.
dda::Vec2 tuple2(const VtkArray& a, std::size_t i) { return {a.values[3 * i], a.values[3 * i + 1]}; }

json small_scene() {
  return json::parse(R"({
    "materials": [{"density": 2000, "young": 1e9, "poisson": 0.25}],
    "blocks": [{"name": "A", "rect": [0, 0, 1, 1], "velocity": [1, 0]},
               {"name": "B", "rect": [1.05, 0, 1, 1]}],
    "contact": {"kn": 1e8},
    "dt": 1e-4, "duration": 0.1,
    "output": {"every": 100, "snapshots": [0, 0.06, 0.1]}
  })");
}

}  // namespace

TEST_CASE("vtu text: cells, types, arrays and the time", "[io][vtk]") {
  const std::string s = vtu_text(two_cells(), 0.25, "test");
  CHECK(s.find("<Piece NumberOfPoints=\"5\" NumberOfCells=\"2\">") != std::string::npos);
  CHECK(s.find("Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">\n0.25\n") != std::string::npos);
  // offsets 4, 7; types polygon (7) and triangle (5)
  CHECK(s.find("Name=\"offsets\" format=\"ascii\">\n4\n7\n") != std::string::npos);
  CHECK(s.find("Name=\"types\" format=\"ascii\">\n7\n5\n") != std::string::npos);
  CHECK(s.find("Name=\"connectivity\" format=\"ascii\">\n0 1 2 3\n1 4 2\n") != std::string::npos);
  CHECK(s.find("<DataArray type=\"Int64\" Name=\"block\" NumberOfComponents=\"1\" format=\"ascii\">\n0\n1\n") !=
        std::string::npos);
  CHECK(s.find("Name=\"velocity\" NumberOfComponents=\"3\" format=\"ascii\">\n0.5 0 0\n-1.25 2 0\n") !=
        std::string::npos);
}

TEST_CASE("the writer refuses a bad mesh and names a NaN", "[io][vtk]") {
  VtkMesh m = two_cells();
  m.cell_data[1].values[4] = std::nan("");
  try {
    (void)vtu_text(m, 0.0, "frame.vtu");
    FAIL("a NaN was written");
  } catch (const NonFiniteValue& e) {
    const std::string what = e.what();
    INFO(what);
    CHECK(what.find("frame.vtu") == 0);
    CHECK(what.find("'velocity'") != std::string::npos);
    CHECK(what.find("tuple 1") != std::string::npos);
  }
  m = two_cells();
  m.points[4].x = INFINITY;
  CHECK_THROWS_AS(vtu_text(m, 0.0, "x"), NonFiniteValue);
  CHECK_THROWS_AS(vtu_text(two_cells(), NAN, "x"), NonFiniteValue);
  m = two_cells();
  m.connectivity[5] = 9;  // no point 9
  CHECK_THROWS_AS(check_mesh(m, "x"), std::invalid_argument);
  m = two_cells();
  m.cell_data[0].values.push_back(2);  // three values for two cells
  CHECK_THROWS_AS(check_mesh(m, "x"), std::invalid_argument);
  m = two_cells();
  m.cell_data[0].values[1] = 1.5;  // an integer array
  CHECK_THROWS_AS(check_mesh(m, "x"), std::invalid_argument);
  m = two_cells();
  m.cell_data[1].component_names = {"vx", "vy"};  // three components
  CHECK_THROWS_AS(check_mesh(m, "x"), std::invalid_argument);
}

TEST_CASE("legacy VTK text", "[io][vtk]") {
  const std::string s = legacy_vtk_text(two_cells(), "title\nwith a break", "x");
  CHECK(s ==
        "# vtk DataFile Version 3.0\ntitle with a break\nASCII\nDATASET POLYDATA\nPOINTS 5 double\n"
        "0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0.5 0\nPOLYGONS 2 9\n4 0 1 2 3\n3 1 4 2\nCELL_DATA 2\n"
        "SCALARS block int 1\nLOOKUP_TABLE default\n0\n1\nVECTORS velocity double\n0.5 0 0\n-1.25 2 0\n");
}

TEST_CASE("a series writes each frame whole and the collection at the end", "[io][vtk]") {
  const std::string dir = fresh_dir("series") + "/vtk";
  VtkSeries s(dir, "blocks");
  s.add(0.0, two_cells());
  s.add(0.125, two_cells());
  VtkMesh bad = two_cells();
  bad.cell_data[0].name = "block";
  bad.cell_data[1].values[0] = NAN;
  CHECK_THROWS_AS(s.add(0.25, bad), NonFiniteValue);
  CHECK(s.frames() == 2);
  CHECK_FALSE(fs::exists(dir + "/blocks_000002.vtu"));
  CHECK_FALSE(fs::exists(dir + "/blocks_000002.vtu.tmp"));
  CHECK_FALSE(fs::exists(s.collection_path()));
  s.write_collection();
  const std::string pvd = slurp(s.collection_path());
  CHECK(pvd.find("<DataSet timestep=\"0\" group=\"\" part=\"0\" file=\"blocks_000000.vtu\"/>") != std::string::npos);
  CHECK(pvd.find("<DataSet timestep=\"0.125\" group=\"\" part=\"0\" file=\"blocks_000001.vtu\"/>") !=
        std::string::npos);
  CHECK(count_of(pvd, "<DataSet ") == 2);
  CHECK(slurp(dir + "/blocks_000001.vtu") == vtu_text(two_cells(), 0.125, ""));
  for (const auto& e : fs::directory_iterator(dir)) CHECK(e.path().extension() != ".tmp");
}

TEST_CASE("Paper A adapter: one polygon per block, one point per contact", "[io][vtk]") {
  dda::Scene scene = dda::paper::two_squares();
  scene.boundaries.push_back({{-3, -0.6}, {3, -0.6}, 1.0, 0});  // a floor below the squares, not touching
  dda::Simulation sim(scene);
  while (sim.contacts().empty() && sim.time() < scene.duration) sim.step();
  REQUIRE_FALSE(sim.contacts().empty());
  const VtkMesh m = block_mesh(sim);
  REQUIRE(m.cell_count() == static_cast<std::size_t>(sim.block_count()));
  const VtkArray& velocity = *m.cell_array("velocity");
  const VtkArray& stress = *m.cell_array("stress");
  const VtkArray& boundary = *m.cell_array("boundary");
  for (int i = 0; i < sim.block_count(); ++i) {
    const dda::Polygon p = sim.polygon(i);
    const int o = m.offsets[static_cast<std::size_t>(i)];
    REQUIRE(m.offsets[static_cast<std::size_t>(i) + 1] - o == p.count);
    for (int k = 0; k < p.count; ++k) {
      const dda::Vec2 x = m.points[static_cast<std::size_t>(m.connectivity[static_cast<std::size_t>(o + k)])];
      CHECK(x.x == p.vertex(k).x);
      CHECK(x.y == p.vertex(k).y);
    }
    const auto u = static_cast<std::size_t>(i);
    CHECK(tuple2(velocity, u).x == sim.velocity(i)[0]);
    CHECK(tuple2(velocity, u).y == sim.velocity(i)[1]);
    CHECK(m.cell_array("spin")->values[u] == sim.velocity(i)[2]);
    CHECK(stress.values[3 * u + 2] == sim.stress(i)[2]);
    CHECK(boundary.values[u] == (i >= sim.scene_block_count() ? 1 : 0));
  }
  CHECK(block_mesh(sim, false).cell_count() == static_cast<std::size_t>(sim.scene_block_count()));

  const VtkMesh c = contact_mesh(sim);
  const std::vector<dda::ContactInfo> contacts = sim.contacts();
  REQUIRE(c.point_count() == contacts.size());
  CHECK(c.cell_count() == c.point_count());
  for (std::size_t k = 0; k < c.point_count(); ++k) {
    const dda::ContactInfo& ci = contacts[k];
    CHECK(c.points[k].x == ci.point.x);
    CHECK(tuple2(*c.point_array("normal_force"), k).x == ci.normal_force.x);
    CHECK(c.point_array("block")->values[k] == ci.cp);
    CHECK(c.point_array("target")->values[k] == ci.tp);
    CHECK(c.point_array("penetration")->values[k] == Approx(ci.ip_area / ci.ip_length));
    CHECK(c.point_array("penetration")->values[k] > 0.0);
  }
}

TEST_CASE("Paper B adapter: elements with their nodes, clone nodes as contact points", "[io][vtk][cdem]") {
  dda::cdem::Model model(dda::cdem::two_prisms());  // Sect. 6, the sub-model subdivision (the default)
  // The apex touches the base at about 1/3 s; step until a clone lives
  // with its sub-model.
  while ((model.clones().empty() || model.live_submodels() == 0) && model.time() < 0.5) model.step();
  REQUIRE_FALSE(model.clones().empty());
  REQUIRE(model.live_submodels() > 0);

  const dda::cdem::Snapshot snap = model.snapshot();
  const VtkMesh m = element_mesh(model);
  REQUIRE(m.cell_count() == snap.tris.size());
  const VtkArray& node = *m.point_array("node");
  const VtkArray& kind = *m.point_array("kind");
  std::set<int> nodes_seen;
  int sub_nodes = 0;
  for (std::size_t p = 0; p < m.point_count(); ++p) {
    const int id = static_cast<int>(node.values[p]);
    if (id >= 0) {
      CHECK(nodes_seen.insert(id).second);  // each model node once
      CHECK(m.points[p].x == model.node_position(id).x);
      CHECK(m.points[p].y == model.node_position(id).y);
      CHECK(tuple2(*m.point_array("velocity"), p).x == model.node_velocity(id).x);
      CHECK(m.point_array("block")->values[p] == model.node_block(id));
      CHECK(kind.values[p] != 3);
    } else {
      CHECK(kind.values[p] == 3);
      ++sub_nodes;
    }
  }
  CHECK(sub_nodes > 0);  // the live sub-model's nodes
  int fine = 0;
  for (std::size_t c = 0; c < m.cell_count(); ++c) {
    const dda::cdem::Snapshot::Tri& t = snap.tris[c];
    REQUIRE(m.offsets[c + 1] - m.offsets[c] == 3);
    for (std::size_t k = 0; k < 3; ++k) {
      const dda::Vec2 x = m.points[static_cast<std::size_t>(m.connectivity[m.offsets[c] + k])];
      CHECK(x.x == t.x[k].x);
      CHECK(x.y == t.x[k].y);
    }
    CHECK(m.cell_array("block")->values[c] == t.block);
    CHECK(m.cell_array("stress")->values[3 * c] == t.stress[0]);
    fine += t.fine ? 1 : 0;
  }
  CHECK(fine > 0);
  // The mesh is connected through shared nodes: fewer points than corners.
  CHECK(m.point_count() < 3 * m.cell_count());

  const std::vector<dda::cdem::CloneView> clones = model.clones();
  const VtkMesh c = contact_mesh(model);
  REQUIRE(c.point_count() == clones.size());
  for (std::size_t k = 0; k < clones.size(); ++k) {
    CHECK(c.points[k].x == clones[k].point.x);
    CHECK(c.point_array("node")->values[k] == clones[k].main_node);
    CHECK(c.point_array("block")->values[k] == 0);  // the apex of block i touches block j
    CHECK(c.point_array("target")->values[k] == 1);
    const dda::Vec2 f = tuple2(*c.point_array("force"), k), fn = tuple2(*c.point_array("normal_force"), k),
                    ft = tuple2(*c.point_array("shear_force"), k);
    CHECK(f.x == clones[k].force.x);
    CHECK(fn.x + ft.x == Approx(f.x).margin(1e-9 * std::hypot(f.x, f.y)));
    CHECK(fn.y + ft.y == Approx(f.y).margin(1e-9 * std::hypot(f.x, f.y)));
    CHECK(std::fabs(dda::cross(fn, clones[k].normal)) <= 1e-9 * std::hypot(fn.x, fn.y));  // along the normal
    CHECK(std::fabs(dda::dot(ft, clones[k].normal)) <= 1e-9 * std::hypot(f.x, f.y) + 1e-300);
    // The clone ties the node to the touched point: they drift apart by much
    // less than the contact tolerance.
    CHECK(std::fabs(c.point_array("penetration")->values[k]) < model.scene().options.tolerance);
  }
  check_mesh(m, "elements");
  check_mesh(c, "clones");

  // After the separation (about 0.34 s) no clone is left.
  model.advance_to(0.45);
  CHECK(model.clones().empty());
  CHECK(contact_mesh(model).point_count() == 0);
  CHECK(element_mesh(model).cell_count() == model.snapshot().tris.size());
}

TEST_CASE("Paper B adapter: the penalty baseline's springs as contact points", "[io][vtk][cdem]") {
  dda::cdem::CdemOptions opt;
  opt.contact = dda::cdem::ContactMode::kNodeToEdgePenalty;
  opt.subdivision = false;
  dda::cdem::Model model(dda::cdem::two_prisms(2, opt));
  while (model.penalty_contacts().empty() && model.time() < 0.5) model.step();
  REQUIRE_FALSE(model.penalty_contacts().empty());
  const VtkMesh c = contact_mesh(model);
  REQUIRE(c.point_count() == model.penalty_contacts().size());
  for (std::size_t k = 0; k < c.point_count(); ++k) {
    const dda::cdem::Model::PenaltyContact& p = model.penalty_contacts()[k];
    CHECK(c.points[k].x == model.node_position(p.node).x);
    CHECK(c.point_array("penetration")->values[k] == p.depth);
    CHECK(tuple2(*c.point_array("normal_force"), k).y == Approx(model.penalty_kn() * p.depth * p.normal.y));
    CHECK(tuple2(*c.point_array("shear_force"), k).x == Approx(0.0).margin(1e-9 * model.penalty_kn() * p.depth));
  }
  // Without subdivision every point is a model node.
  const VtkMesh m = element_mesh(model);
  for (double id : m.point_array("node")->values) CHECK(id >= 0);
}

TEST_CASE("output keys: vtk, vtk_every, block_table", "[io][vtk][scene]") {
  json j = small_scene();
  SceneFile f = parse_scene(j.dump(), "scene.json");
  CHECK_FALSE(f.output.vtk);
  CHECK(f.output.vtk_every == 0);
  CHECK_FALSE(f.output.block_table);
  j["output"]["vtk"] = true;
  j["output"]["vtk_every"] = 50;
  j["output"]["block_table"] = true;
  f = parse_scene(j.dump(), "scene.json");
  CHECK(f.output.vtk);
  CHECK(f.output.vtk_every == 50);
  CHECK(f.output.block_table);
  const SceneFile g = parse_scene(write_scene(f), "rewritten.json");  // round trip
  CHECK(g.output.vtk);
  CHECK(g.output.vtk_every == 50);
  CHECK(g.output.block_table);

  auto error_of = [](const json& scene) -> std::string {
    try {
      (void)parse_scene(scene.dump(2), "scene.json");
    } catch (const SceneFileError& e) {
      return e.what();
    }
    return "";
  };
  struct Bad {
    const char* key;
    json value;
    bool with_vtk;
    const char* message;  // after "scene.json:<line>:<col>: "
  };
  const std::vector<Bad> bad = {
      {"vtk", "yes", false, "output.vtk: expected true or false, got string \"yes\""},
      {"block_table", 1, false, "output.block_table: expected true or false, got number 1"},
      {"vtk_every", 0, true, "output.vtk_every: must be >= 1 (steps between ParaView frames)"},
      {"vtk_every", 2.5, true, "output.vtk_every: expected an integer, got number 2.5"},
      {"vtk_every", 10, false, "output.vtk_every: needs \"vtk\": true (it would be ignored)"},
      {"vtk_evry", 10, true, "output.vtk_evry: unknown key (did you mean 'vtk_every'?)"},
  };
  for (const Bad& b : bad) {
    json k = small_scene();
    if (b.with_vtk) k["output"]["vtk"] = true;
    k["output"][b.key] = b.value;
    const std::string e = error_of(k);
    INFO(e);
    CHECK(e.rfind("scene.json:", 0) == 0);
    CHECK(e.find(std::string(": ") + b.message) != std::string::npos);
  }
}

TEST_CASE("dda run: the block table and the ParaView series agree with the time series", "[io][vtk][run]") {
  json j = small_scene();
  j["output"]["every"] = 20;
  j["output"]["block_table"] = true;
  j["output"]["vtk"] = true;
  const SceneFile f = parse_scene(j.dump(), "small.json");
  RunOptions opt;
  opt.out_dir = fresh_dir("run");
  const RunResult r = run_scene(f, opt);
  REQUIRE(r.status == RunStatus::kCompleted);
  CHECK(r.block_table_rows == 2 * r.timeseries_rows);
  CHECK(r.vtk_frames == 3);  // the snapshot times 0, 0.06, 0.1
  const json run = json::parse(slurp(opt.out_dir + "/run.json"));
  CHECK(run["block_table_rows"] == r.block_table_rows);
  CHECK(run["vtk_frames"] == 3);
  for (const char* file : {"blocks.pvd", "contacts.pvd", "blocks_000002.vtu", "contacts_000002.vtu"})
    CHECK(fs::exists(opt.out_dir + "/vtk/" + file));
  CHECK_FALSE(fs::exists(opt.out_dir + "/vtk/blocks_000003.vtu"));
  // blocks.csv holds the time series' numbers, row for row.
  std::ifstream ts(opt.out_dir + "/timeseries.csv"), bt(opt.out_dir + "/blocks.csv");
  std::string ts_line, bt_line;
  std::getline(ts, ts_line);
  std::getline(bt, bt_line);
  CHECK(bt_line == "time,step,block,x,y,vx,vy,rot,spin,sxx,syy,sxy");
  std::size_t rows = 0;
  while (std::getline(ts, ts_line)) {
    std::vector<std::string> t;
    std::stringstream s(ts_line);
    for (std::string x; std::getline(s, x, ',');) t.push_back(x);
    for (int b = 0; b < 2; ++b) {
      REQUIRE(std::getline(bt, bt_line));
      std::vector<std::string> r2;
      std::stringstream s2(bt_line);
      for (std::string x; std::getline(s2, x, ',');) r2.push_back(x);
      REQUIRE(r2.size() == 12);
      CHECK(r2[0] == t[0]);  // time
      CHECK(r2[1] == t[1]);  // step
      CHECK(r2[2] == std::to_string(b));
      for (int c = 0; c < 6; ++c) CHECK(r2[3 + static_cast<std::size_t>(c)] == t[2 + 6 * b + c]);
    }
    ++rows;
  }
  CHECK(rows == r.timeseries_rows);
  CHECK_FALSE(std::getline(bt, bt_line));

  // vtk_every: frames at 0, 300, 600, 900 and the last step, 1000.
  json k = small_scene();
  k["output"]["vtk"] = true;
  k["output"]["vtk_every"] = 300;
  opt.out_dir = fresh_dir("run_every");
  CHECK(run_scene(parse_scene(k.dump(), "small.json"), opt).vtk_frames == 5);
  CHECK(count_of(slurp(opt.out_dir + "/vtk/blocks.pvd"), "<DataSet ") == 5);
  CHECK_FALSE(fs::exists(opt.out_dir + "/blocks.csv"));
}

TEST_CASE("dda run --vtk, --vtk-every, --block-table; bad values exit 2", "[io][vtk][cli]") {
  const std::string dir = fresh_dir("cli");
  fs::create_directories(dir);
  const std::string scene = dir + "/small.json", log = dir + "/log.txt";
  {
    std::ofstream f(scene);
    f << small_scene().dump(2);
  }
  auto run = [&](const std::string& args) {
    const std::string cmd = std::string("\"") + DDA_CLI_PATH + "\" " + args + " >\"" + log + "\" 2>&1";
    const int status = std::system(cmd.c_str());
    REQUIRE(WIFEXITED(status));
    return WEXITSTATUS(status);
  };
  for (const char* bad : {"--vtk-every 0", "--vtk-every -3", "--vtk-every x", "--vtk-every=2.5", "--vtk-every",
                          "--vtk-every 99999999999"}) {
    INFO(bad);
    CHECK(run("run \"" + scene + "\" --out \"" + dir + "/bad\" " + bad) == 2);
    CHECK(slurp(log).find("run: --vtk-every needs a positive integer") == 5);  // after "dda: "
    CHECK_FALSE(fs::exists(dir + "/bad"));
  }
  CHECK(run("run \"" + scene + "\" --out \"" + dir + "/out\" --vtk --block-table") == 0);
  const std::string said = slurp(log);
  INFO(said);
  CHECK(said.find("/out/blocks.csv (") != std::string::npos);
  CHECK(said.find("/out/vtk/blocks.pvd and contacts.pvd (3 frames each)") != std::string::npos);
  CHECK(fs::exists(dir + "/out/blocks.csv"));
  CHECK(count_of(slurp(dir + "/out/vtk/contacts.pvd"), "<DataSet ") == 3);
  CHECK(run("run \"" + scene + "\" --out \"" + dir + "/every\" --vtk-every=250 --quiet") == 0);
  CHECK(count_of(slurp(dir + "/every/vtk/blocks.pvd"), "<DataSet ") == 5);  // steps 0, 250, 500, 750, 1000
  CHECK_FALSE(fs::exists(dir + "/every/blocks.csv"));
  CHECK(run("--help") == 0);
  const std::string help = slurp(log);
  for (const char* flag : {"--vtk", "--vtk-every N", "--block-table", "output.vtk_every", "output.block_table"})
    CHECK(help.find(flag) != std::string::npos);
}

TEST_CASE("an interrupted run keeps its ParaView frames and commits the CSV files so far", "[io][vtk][run]") {
  json j = small_scene();
  j["output"]["vtk"] = true;
  j["output"]["block_table"] = true;
  RunOptions opt;
  opt.out_dir = fresh_dir("interrupted");
  volatile std::sig_atomic_t flag = 1;  // set before the first step
  opt.interrupt = &flag;
  const RunResult r = run_scene(parse_scene(j.dump(), "small.json"), opt);
  CHECK(r.status == RunStatus::kInterrupted);
  CHECK(r.vtk_frames == 1);  // the snapshot at t = 0, taken before the first step
  CHECK(count_of(slurp(opt.out_dir + "/vtk/blocks.pvd"), "<DataSet ") == 1);
  CHECK(fs::exists(opt.out_dir + "/vtk/contacts_000000.vtu"));
  // The rows of t = 0, the checkpoint to resume from, run.json saying so.
  for (const char* file : {"timeseries.csv", "snapshots.csv", "blocks.csv", "run.json", "checkpoint.dda"})
    CHECK(fs::exists(opt.out_dir + "/" + file));
  CHECK(json::parse(slurp(opt.out_dir + "/run.json"))["status"] == "interrupted");
  for (const auto& e : fs::recursive_directory_iterator(opt.out_dir)) CHECK(e.path().extension() != ".tmp");
}
