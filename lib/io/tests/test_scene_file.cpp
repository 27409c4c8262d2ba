// Scene files: every rejection class names the file, the field and the
// reason; the example scenes load and round-trip.
#include <catch2/catch.hpp>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dda/io/scene_file.hpp"
#include "dda/polygon.hpp"
#include "scene_helpers.hpp"

using namespace dda::io::test;

namespace {

// A valid two-block scene to mutate.
json base() {
  return json::parse(R"({
    "name": "base",
    "materials": [{"name": "rock", "density": 2000, "young": 1e9, "poisson": 0.25}],
    "blocks": [
      {"name": "A", "rect": [0, 0, 1, 1], "velocity": [1, 0]},
      {"name": "B", "vertices": [[2, 0], [3, 0], [3, 1], [2, 1]]}
    ],
    "contact": {"kn": 1e7, "kt": 1e7, "friction_deg": 10,
                "friction_rules": [{"groups": [0, 1], "friction_deg": 5}]},
    "gravity": [0, -9.81],
    "dt": 1e-4,
    "duration": 0.5,
    "output": {"every": 10, "snapshots": [0, 0.5], "tracked_blocks": [0]}
  })");
}

json with_vertices(std::vector<std::vector<double>> pts) {
  json j = base();
  j["blocks"][1] = {{"vertices", pts}};
  return j;
}

}  // namespace

TEST_CASE("the base scene parses with every field", "[io][scene]") {
  const SceneFile f = parse_scene(base().dump(), "scene.json");
  REQUIRE(f.scene.blocks.size() == 2);
  CHECK(f.scene.name == "base");
  CHECK(f.scene.blocks[0].vertices.size() == 4);
  CHECK(f.scene.blocks[0].vertices[2].x == 1.0);
  CHECK(f.scene.blocks[0].vertices[2].y == 1.0);
  CHECK(f.scene.blocks[0].velocity.x == 1.0);
  CHECK(f.scene.contact.kt == 1e7);
  CHECK(f.scene.contact.friction_rules.size() == 1);
  CHECK(f.scene.contact.friction_rules[0].group_b == 1);
  CHECK(f.scene.gravity.y == Approx(-9.81));
  CHECK(f.output.every == 10);
  CHECK(f.output.tracked_blocks == std::vector<int>{0});
  CHECK(f.output.snapshot_times == std::vector<double>{0.0, 0.5});
}

TEST_CASE("unknown keys are rejected at every level", "[io][scene][reject]") {
  struct Case {
    const char* pointer;  // JSON pointer of the object that gets the key
    const char* key;
    std::string field;
  };
  const std::vector<Case> cases = {
      {"", "gravty", "gravty"},
      {"/materials/0", "densty", "materials[0].densty"},
      {"/blocks/1", "colour", "blocks[1].colour"},
      {"/contact", "mu", "contact.mu"},
      {"/contact/friction_rules/0", "phi", "contact.friction_rules[0].phi"},
      {"/output", "evry", "output.evry"},
  };
  for (const Case& c : cases) {
    json j = base();
    j[json::json_pointer(c.pointer)][c.key] = 1;
    check_rejected(j, c.field, "unknown key");
  }
  json j = base();
  j["materials"][0]["densty"] = 1;
  CHECK(error_of(j).find("did you mean 'density'?") != std::string::npos);
  j = base();
  j["boundaries"] = json::array({{{"a", {0, -1}}, {"b", {1, -1}}, {"dept", 1}}});
  check_rejected(j, "boundaries[0].dept", "unknown key (did you mean 'depth'?)");
}

TEST_CASE("wrong JSON types are rejected", "[io][scene][reject]") {
  json j = base();
  j["contact"]["kn"] = "1e7";
  check_rejected(j, "contact.kn", "expected a number, got string \"1e7\"");
  j = base();
  j["blocks"][0]["fixed"] = 1;
  check_rejected(j, "blocks[0].fixed", "expected true or false");
  j = base();
  j["blocks"] = json::object();
  check_rejected(j, "blocks", "expected an array");
  j = base();
  j["blocks"][1]["vertices"][1] = {3.0};
  check_rejected(j, "blocks[1].vertices[1]", "expected [x, y]");
  j = base();
  j["blocks"][1]["vertices"][1][0] = "nan";
  check_rejected(j, "blocks[1].vertices[1][0]", "expected a number, got string");
  j = base();
  j["blocks"][0]["group"] = 1.5;
  check_rejected(j, "blocks[0].group", "expected an integer");
  j = base();
  j["contact"]["h_rule"] = "largest";
  check_rejected(j, "contact.h_rule", "unknown value \"largest\"");
  j = base();
  j["broad_phase"] = "grid";
  check_rejected(j, "broad_phase", "expected one of \"none\", \"sweep\"");
  j = base();
  j["output"]["tracked_blocks"] = {true};
  check_rejected(j, "output.tracked_blocks[0]", "expected a block index or name");
  CHECK(error_of("[1, 2]").find("scene.json: the top level must be a JSON object") == 0);
}

TEST_CASE("missing required keys are rejected", "[io][scene][reject]") {
  json j = base();
  j["materials"][0].erase("density");
  check_rejected(j, "materials[0].density", "missing required key");
  j = base();
  j.erase("dt");
  check_rejected(j, "dt", "missing required key");
  j = base();
  j["contact"].erase("kn");
  check_rejected(j, "contact.kn", "missing required key");
  j = base();
  j["blocks"][1].erase("vertices");
  check_rejected(j, "blocks[1].vertices", "missing required key (or give 'rect')");
  j = base();
  j["contact"]["friction_rules"][0].erase("groups");
  check_rejected(j, "contact.friction_rules[0].groups", "missing required key");
}

TEST_CASE("JSON syntax errors give file:line:column", "[io][scene][reject]") {
  const std::string text = "{\n  \"dt\": 1e-4,\n  \"blocks\": [1, 2,]\n}\n";
  const std::string m = error_of(text);
  INFO(m);
  CHECK(m.rfind("scene.json:3:19: ", 0) == 0);
  CHECK(m.find("JSON syntax error") != std::string::npos);
  CHECK(m.find("near blocks[2]") != std::string::npos);
  CHECK(error_of("").rfind("scene.json:1:1: JSON syntax error", 0) == 0);
  CHECK(error_of("{\"dt\": 1e-4} x").rfind("scene.json:1:", 0) == 0);
  // Unterminated input: the position is one past the end.
  CHECK(error_of("{\n\"dt\": [1,").rfind("scene.json:2:", 0) == 0);
}

TEST_CASE("duplicate keys are rejected", "[io][scene][reject]") {
  std::string text = base().dump(2);
  text.replace(text.find("\"density\""), 0, "\"density\": 1000,\n");
  check_rejected(error_of(text), "materials[0].density", "duplicate key");
}

TEST_CASE("each polygon fault of the kernel's validator is reported", "[io][scene][reject]") {
  using dda::describe;
  using dda::PolygonFault;
  check_rejected(with_vertices({{2, 0}, {3, 0}}), "blocks[1].vertices", describe(PolygonFault::kTooFewVertices));
  check_rejected(with_vertices({{2, 0}, {3, 0}, {3, 0}, {3, 1}}), "blocks[1].vertices[2]",
                 describe(PolygonFault::kDuplicateVertex));
  check_rejected(with_vertices({{2, 0}, {2.5, 0}, {3, 0}, {3, 1}}), "blocks[1].vertices[1]",
                 describe(PolygonFault::kCollinear));
  check_rejected(with_vertices({{2, 0}, {2, 1}, {3, 1}, {3, 0}}), "blocks[1].vertices[0]",
                 describe(PolygonFault::kClockwise));
  check_rejected(with_vertices({{2, 0}, {4, 0}, {3, 0.5}, {4, 1}, {2, 1}}), "blocks[1].vertices[2]",
                 describe(PolygonFault::kNonConvex));
  std::vector<std::vector<double>> many;
  for (int k = 0; k < dda::kMaxBlockVertices + 1; ++k) {
    const double a = 2.0 * 3.14159265358979 * k / (dda::kMaxBlockVertices + 1);
    many.push_back({2.5 + 0.5 * std::cos(a), 0.5 + 0.5 * std::sin(a)});
  }
  check_rejected(with_vertices(many), "blocks[1].vertices", describe(PolygonFault::kTooManyVertices));
  // Non-finite: JSON has no NaN or infinity, and nlohmann refuses a number
  // that overflows a double (1e400) while parsing; the field is still named.
  // (A string such as "nan" is a type error, tested above.)
  std::string text = with_vertices({{2, 0}, {3, 0}, {3, 1}, {2, 1}}).dump();
  const std::string needle = "[[2.0,0.0],[3.0,0.0],[3.0,1.0]";
  REQUIRE(text.find(needle) != std::string::npos);
  text.replace(text.find(needle), needle.size(), "[[2.0,0.0],[3.0,0.0],[1e400,1.0]");
  check_rejected(error_of(text), "blocks[1].vertices[2][0]", "number overflow");
}

TEST_CASE("non-positive density, E, kn, dt are rejected", "[io][scene][reject]") {
  for (double bad : {0.0, -1.0}) {
    json j = base();
    j["materials"][0]["density"] = bad;
    check_rejected(j, "materials[0].density", "must be positive");
    j = base();
    j["materials"][0]["young"] = bad;
    check_rejected(j, "materials[0].young", "must be positive");
    j = base();
    j["contact"]["kn"] = bad;
    check_rejected(j, "contact.kn", "must be positive");
    j = base();
    j["dt"] = bad;
    check_rejected(j, "dt", "must be a positive");
  }
}

TEST_CASE("Poisson ratio outside (-1, 0.5) is rejected", "[io][scene][reject]") {
  for (double bad : {0.5, 0.7, -1.0, -2.0}) {
    json j = base();
    j["materials"][0]["poisson"] = bad;
    check_rejected(j, "materials[0].poisson", "must lie in (-1, 0.5)");
  }
  json j = base();
  j["materials"][0]["poisson"] = 0.49;
  CHECK(error_of(j).empty());
}

TEST_CASE("friction angle outside [0, 90) is rejected", "[io][scene][reject]") {
  for (double bad : {90.0, 120.0, -1.0}) {
    json j = base();
    j["contact"]["friction_deg"] = bad;
    check_rejected(j, "contact.friction_deg", "friction angle must lie in [0, 90)");
    j = base();
    j["contact"]["friction_rules"][0]["friction_deg"] = bad;
    check_rejected(j, "contact.friction_rules[0].friction_deg", "friction angle must lie in [0, 90)");
  }
  // A friction angle without kt would be silently ignored.
  json j = base();
  j["contact"].erase("kt");
  check_rejected(j, "contact.friction_deg", "has no effect with contact.kt = 0");
}

TEST_CASE("blocks overlapping at t = 0 are rejected", "[io][scene][reject]") {
  json j = base();
  j["blocks"][1] = {{"rect", {0.5, 0.5, 1, 1}}};
  check_rejected(j, "blocks[0]", "overlaps blocks[1] at t = 0");
  // Touching is allowed.
  j["blocks"][1] = {{"rect", {1, 0, 1, 1}}};
  CHECK(error_of(j).empty());
  // A preloaded contact: allowed up to initial_overlap (the overlap's thickness).
  j["blocks"][1] = {{"rect", {0, 0.99, 1, 1}}};
  check_rejected(j, "blocks[0]", "overlaps blocks[1] at t = 0");
  j["initial_overlap"] = 0.02;
  CHECK(error_of(j).empty());
  j["initial_overlap"] = 0.005;
  check_rejected(j, "blocks[0]", "more than initial_overlap");
  j["initial_overlap"] = -1;
  check_rejected(j, "initial_overlap", "must be finite and >= 0");
}

TEST_CASE("other semantic errors name their field", "[io][scene][reject]") {
  json j = base();
  j["blocks"][0]["material"] = "granite";
  check_rejected(j, "blocks[0].material", "no material named \"granite\"");
  j = base();
  j["blocks"][0]["material"] = 3;
  check_rejected(j, "blocks[0].material", "no such material");
  j = base();
  j["blocks"][0]["rect"] = {0, 0, 0, 1};
  check_rejected(j, "blocks[0].rect", "width and height must be positive");
  j = base();
  j["blocks"][0]["vertices"] = {{0, 0}, {1, 0}, {1, 1}};
  check_rejected(j, "blocks[0]", "either 'vertices' or 'rect', not both");
  j = base();
  j["blocks"][0]["about"] = {0, 0};
  check_rejected(j, "blocks[0].about", "only used with 'rotate_deg'");
  j = base();
  j["blocks"][0]["fixed"] = true;
  check_rejected(j, "blocks[0].velocity", "a fixed block never moves");
  j = base();
  j["contact"]["h"] = 0.5;
  check_rejected(j, "contact.h", "only used with \"h_rule\": \"given\"");
  j = base();
  j["contact"]["h_rule"] = "given";
  check_rejected(j, "contact.h", "must be positive when H is given");
  j = base();
  j["output"]["every"] = 0;
  check_rejected(j, "output.every", "must be >= 1");
  j = base();
  j["output"]["snapshots"] = {0.1, 0.7};
  check_rejected(j, "output.snapshots[1]", "must lie in [0, duration]");
  j = base();
  j["output"]["tracked_blocks"] = {"C"};
  check_rejected(j, "output.tracked_blocks[0]", "no block named \"C\"");
  j = base();
  j["output"]["tracked_blocks"] = {2};
  check_rejected(j, "output.tracked_blocks[0]", "no block 2");
  j = base();
  j["boundaries"] = json::array({{{"a", {0, -1}}, {"b", {0, -1}}}});
  check_rejected(j, "boundaries[0]", "distinct");
  j = base();
  j["duration"] = -1;
  check_rejected(j, "duration", "must be finite and >= 0");
}

TEST_CASE("rect and rotate_deg generate CCW vertices", "[io][scene]") {
  json j = base();
  j["blocks"][1] = {{"rect", {2, 0, 2, 1}}, {"rotate_deg", 90}};  // about the centre (3, 0.5)
  const SceneFile f = parse_scene(j.dump(), "scene.json");
  const auto& v = f.scene.blocks[1].vertices;
  REQUIRE(v.size() == 4);
  CHECK(v[0].x == Approx(3.5));
  CHECK(v[0].y == Approx(-0.5));
  CHECK(v[2].x == Approx(2.5));
  CHECK(v[2].y == Approx(1.5));
  j["blocks"][1]["about"] = {2, 0};
  const SceneFile g = parse_scene(j.dump(), "scene.json");
  CHECK(g.scene.blocks[1].vertices[1].x == Approx(2.0));
  CHECK(g.scene.blocks[1].vertices[1].y == Approx(2.0));
}

TEST_CASE("defaults: no output section, tracked blocks by name, material by name", "[io][scene]") {
  json j = base();
  j.erase("output");
  j["blocks"][1]["material"] = "rock";
  SceneFile f = parse_scene(j.dump(), "scene.json");
  CHECK(f.output.every == 100);
  CHECK(f.output.tracked_blocks.empty());
  CHECK(f.output.snapshot_times == std::vector<double>{0.0, 0.5});
  CHECK(f.scene.blocks[1].material == 0);
  CHECK(f.scene.strains);
  CHECK(f.scene.broad_phase == dda::BroadPhase::kNone);
  j["output"] = {{"tracked_blocks", {"B", "A"}}, {"snapshots", {0.5, 0.1}}};
  f = parse_scene(j.dump(), "scene.json");
  CHECK(f.output.tracked_blocks == std::vector<int>{1, 0});
  CHECK(f.output.snapshot_times == std::vector<double>{0.1, 0.5});
}

TEST_CASE("bad scene files on disk name the file", "[io][scene][reject]") {
  struct Case {
    const char* file;
    const char* field;  // after "<path>: " (or a "line:col" prefix for syntax)
    const char* reason;
  };
  const std::vector<Case> cases = {
      {"unknown_key.json", "materials[0].densty", "unknown key"},
      {"wrong_type.json", "contact.kn", "expected a number"},
      {"missing_key.json", "dt", "missing required key"},
      {"clockwise.json", "blocks[1].vertices[0]", "clockwise vertex order"},
      {"overlap.json", "blocks[0]", "overlaps blocks[1] at t = 0"},
      {"overflow.json", "blocks[0].vertices[2][0]", "number overflow"},
      {"zero_kn.json", "contact.kn", "must be positive"},
  };
  for (const Case& c : cases) {
    const std::string path = std::string(DDA_IO_BAD_DIR) + "/" + c.file;
    check_rejected(load_error_of(path), c.field, c.reason, path);
  }
  const std::string path = std::string(DDA_IO_BAD_DIR) + "/syntax_error.json";
  const std::string m = load_error_of(path);
  INFO(m);
  CHECK(m.rfind(path + ":3:37: ", 0) == 0);
  CHECK(m.find("JSON syntax error") != std::string::npos);

  try {
    dda::io::load_scene_file("/nonexistent/scene.json");
    FAIL("accepted a missing file");
  } catch (const SceneFileError& e) {
    CHECK(std::string(e.what()).rfind("/nonexistent/scene.json: cannot open", 0) == 0);
  }
}

TEST_CASE("the example scenes load and round-trip", "[io][scene][examples]") {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(DDA_SCENES_DIR))
    if (e.path().extension() == ".json") files.push_back(e.path().string());
  REQUIRE(files.size() >= 2);
  for (const std::string& path : files) {
    INFO(path);
    SceneFile f;
    REQUIRE_NOTHROW(f = dda::io::load_scene_file(path));
    const std::string text = dda::io::write_scene(f);
    const SceneFile g = parse_scene(text, path + " (rewritten)");
    CHECK(dda::io::write_scene(g) == text);
    REQUIRE(g.scene.blocks.size() == f.scene.blocks.size());
    for (std::size_t i = 0; i < f.scene.blocks.size(); ++i) {
      REQUIRE(g.scene.blocks[i].vertices.size() == f.scene.blocks[i].vertices.size());
      for (std::size_t k = 0; k < f.scene.blocks[i].vertices.size(); ++k)
        CHECK(g.scene.blocks[i].vertices[k] == f.scene.blocks[i].vertices[k]);  // bit-exact
      CHECK(g.scene.blocks[i].name == f.scene.blocks[i].name);
    }
    CHECK(g.scene.dt == f.scene.dt);
    CHECK(g.scene.contact.kn == f.scene.contact.kn);
    CHECK(g.output.snapshot_times == f.output.snapshot_times);
    CHECK(g.output.tracked_blocks == f.output.tracked_blocks);
  }
  const SceneFile two = dda::io::load_scene_file(std::string(DDA_SCENES_DIR) + "/two_squares.json");
  CHECK(two.scene.materials[0].density == 2000.0);
  CHECK(two.scene.materials[0].young == 1e9);
  CHECK(two.scene.contact.kn == 1e7);
  CHECK(two.scene.dt == 1e-4);
  CHECK(two.scene.duration == 1.0);
  CHECK(two.scene.blocks[0].velocity.x == 1.0);
  CHECK(two.scene.gravity == dda::Vec2{});
}

TEST_CASE("the complete example of SCHEMA.md parses", "[io][scene][examples]") {
  std::ifstream in(DDA_IO_SCHEMA);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string doc = ss.str();
  const std::size_t section = doc.find("## Complete example");
  REQUIRE(section != std::string::npos);
  const std::size_t begin = doc.find("```json\n", section);
  REQUIRE(begin != std::string::npos);
  const std::size_t end = doc.find("\n```", begin + 8);
  REQUIRE(end != std::string::npos);
  SceneFile f;
  REQUIRE_NOTHROW(f = parse_scene(doc.substr(begin + 8, end - begin - 8), "SCHEMA.md"));
  CHECK(f.scene.blocks.size() == 2);
  CHECK(f.scene.boundaries.size() == 1);
  CHECK(f.output.tracked_blocks == std::vector<int>{0, 1});
}

TEST_CASE("dt_fraction, guards and contact.small_edge_rays: defaults", "[io][scene][options]") {
  const SceneFile f = parse_scene(base().dump(), "scene.json");
  const dda::Scene defaults;
  CHECK(f.scene.dt_fraction == 0.0);
  CHECK(f.scene.dt == 1e-4);
  CHECK(f.scene.guards.max_step_motion == defaults.guards.max_step_motion);
  CHECK(f.scene.guards.max_energy_growth == defaults.guards.max_energy_growth);
  CHECK(f.scene.guards.energy_check_every == defaults.guards.energy_check_every);
  CHECK(f.scene.guards.max_penetration == defaults.guards.max_penetration);
  CHECK(f.scene.guards.max_approach_energy == defaults.guards.max_approach_energy);
  CHECK(f.scene.contact.small_edge_rays == dda::SmallEdgeRays::kVirtualAndVertex);
}

TEST_CASE("dt_fraction, guards and contact.small_edge_rays are read", "[io][scene][options]") {
  json j = base();
  j.erase("dt");
  j["dt_fraction"] = 0.5;
  SceneFile f = parse_scene(j.dump(), "scene.json");
  CHECK(f.scene.dt_fraction == 0.5);
  // dt_fraction = 0 (off) with a dt is the default spelled out.
  j = base();
  j["dt_fraction"] = 0;
  f = parse_scene(j.dump(), "scene.json");
  CHECK(f.scene.dt_fraction == 0.0);
  CHECK(f.scene.dt == 1e-4);

  j = base();
  j["guards"] = {{"max_step_motion", 0.1}};
  f = parse_scene(j.dump(), "scene.json");
  CHECK(f.scene.guards.max_step_motion == 0.1);
  CHECK(f.scene.guards.max_energy_growth == dda::StabilityGuards{}.max_energy_growth);
  CHECK(f.scene.guards.energy_check_every == dda::StabilityGuards{}.energy_check_every);
  j["guards"] = {{"max_energy_growth", 2.5}};
  f = parse_scene(j.dump(), "scene.json");
  CHECK(f.scene.guards.max_energy_growth == 2.5);
  CHECK(f.scene.guards.max_step_motion == dda::StabilityGuards{}.max_step_motion);
  j["guards"] = {{"energy_check_every", 7}};
  f = parse_scene(j.dump(), "scene.json");
  CHECK(f.scene.guards.energy_check_every == 7);
  j["guards"] = {{"energy_check_every", 0}};  // 0 switches the energy check off
  CHECK(parse_scene(j.dump(), "scene.json").scene.guards.energy_check_every == 0);
  j["guards"] = {{"energy_check_every", 3.0}};  // integral doubles are integers
  CHECK(parse_scene(j.dump(), "scene.json").scene.guards.energy_check_every == 3);
  j["guards"] = {{"max_penetration", 0}, {"max_approach_energy", 2.0}};  // 0 switches the depth check off
  f = parse_scene(j.dump(), "scene.json");
  CHECK(f.scene.guards.max_penetration == 0.0);
  CHECK(f.scene.guards.max_approach_energy == 2.0);
  j["guards"] = json::object();
  CHECK(parse_scene(j.dump(), "scene.json").scene.guards.max_step_motion == dda::StabilityGuards{}.max_step_motion);

  j = base();
  j["contact"]["small_edge_rays"] = "virtual_replaces_vertex";
  CHECK(parse_scene(j.dump(), "scene.json").scene.contact.small_edge_rays ==
        dda::SmallEdgeRays::kVirtualReplacesVertex);
  j["contact"]["small_edge_rays"] = "virtual_and_vertex";
  CHECK(parse_scene(j.dump(), "scene.json").scene.contact.small_edge_rays == dda::SmallEdgeRays::kVirtualAndVertex);
}

TEST_CASE("invalid dt_fraction, guards and contact.small_edge_rays name their field", "[io][scene][options][reject]") {
  // dt_fraction
  for (double bad : {-0.5, -1e-300}) {
    json j = base();
    j["dt_fraction"] = bad;
    check_rejected(j, "dt_fraction", "must be >= 0");
    j.erase("dt");  // the range is checked before dt is looked for
    check_rejected(j, "dt_fraction", "must be >= 0");
  }
  json j = base();
  j["dt_fraction"] = "0.5";
  check_rejected(j, "dt_fraction", "expected a number, got string \"0.5\"");
  j = base();
  j["dt_fraction"] = 0.5;  // dt would be silently replaced
  check_rejected(j, "dt", "has no effect with dt_fraction > 0");
  j = base();
  j.erase("dt");
  j["dt_fraction"] = 0;  // off: dt is needed
  check_rejected(j, "dt", "missing required key");
  j = base();
  j["dt_fracton"] = 0.5;
  check_rejected(j, "dt_fracton", "unknown key (did you mean 'dt_fraction'?)");

  // guards
  j = base();
  j["guards"] = 0.25;
  check_rejected(j, "guards", "expected an object, got number");
  j = base();
  j["guards"] = {{"max_step_motin", 0.1}};
  check_rejected(j, "guards.max_step_motin", "unknown key (did you mean 'max_step_motion'?)");
  j = base();
  j["guards"] = {{"max_step", 0.1}};
  check_rejected(j, "guards.max_step",
                 "unknown key; allowed here: max_step_motion max_balance_error max_energy_growth energy_check_every");
  j = base();
  j["guards"] = {{"energy_check_every", 10}, {"flip_through", true}};
  check_rejected(j, "guards.flip_through", "unknown key");
  j = base();
  j["gaurds"] = json::object();
  check_rejected(j, "gaurds", "unknown key (did you mean 'guards'?)");
  for (double bad : {0.0, -1.0}) {
    j = base();
    j["guards"] = {{"max_step_motion", bad}};
    check_rejected(j, "guards.max_step_motion", "must be positive");
    j = base();
    j["guards"] = {{"max_energy_growth", bad}};
    check_rejected(j, "guards.max_energy_growth", "must be positive");
  }
  j = base();
  j["guards"] = {{"max_step_motion", "0.25"}};
  check_rejected(j, "guards.max_step_motion", "expected a number, got string");
  j = base();
  j["guards"] = {{"energy_check_every", -1}};
  check_rejected(j, "guards.energy_check_every", "must be >= 0");
  j = base();
  j["guards"] = {{"energy_check_every", 1.5}};
  check_rejected(j, "guards.energy_check_every", "expected an integer, got number 1.5");
  j = base();
  j["guards"] = {{"energy_check_every", 1e12}};
  check_rejected(j, "guards.energy_check_every", "expected an integer");
  j = base();
  j["guards"] = {{"energy_check_every", 10000000000LL}};
  check_rejected(j, "guards.energy_check_every", "integer out of range");

  // contact.small_edge_rays
  j = base();
  j["contact"]["small_edge_rays"] = "replace";
  check_rejected(j, "contact.small_edge_rays",
                 "unknown value \"replace\"; expected one of \"virtual_and_vertex\", \"virtual_replaces_vertex\"");
  j = base();
  j["contact"]["small_edge_rays"] = "kVirtualReplacesVertex";  // the C++ spelling is not the file's
  check_rejected(j, "contact.small_edge_rays", "unknown value");
  j = base();
  j["contact"]["small_edge_rays"] = 1;
  check_rejected(j, "contact.small_edge_rays", "expected a string, got number 1");
  j = base();
  j["contact"]["small_edge_ray"] = "virtual_and_vertex";
  check_rejected(j, "contact.small_edge_ray", "unknown key (did you mean 'small_edge_rays'?)");
}

TEST_CASE("dt_fraction, guards and contact.small_edge_rays round-trip", "[io][scene][options]") {
  auto round_trip = [](const json& j) {
    const SceneFile f = parse_scene(j.dump(), "scene.json");
    const std::string text = dda::io::write_scene(f);
    const SceneFile g = parse_scene(text, "scene.json (rewritten)");
    CHECK(dda::io::write_scene(g) == text);
    CHECK(g.scene.dt == f.scene.dt);
    CHECK(g.scene.dt_fraction == f.scene.dt_fraction);
    CHECK(g.scene.guards.max_step_motion == f.scene.guards.max_step_motion);
    CHECK(g.scene.guards.max_energy_growth == f.scene.guards.max_energy_growth);
    CHECK(g.scene.guards.energy_check_every == f.scene.guards.energy_check_every);
    CHECK(g.scene.guards.max_penetration == f.scene.guards.max_penetration);
    CHECK(g.scene.guards.max_approach_energy == f.scene.guards.max_approach_energy);
    CHECK(g.scene.contact.small_edge_rays == f.scene.contact.small_edge_rays);
    return std::make_pair(f, json::parse(text));
  };
  // Non-default values of every new key.
  json j = base();
  j.erase("dt");
  j["dt_fraction"] = 0.3;
  j["guards"] = {{"max_step_motion", 0.125}, {"max_energy_growth", 3.0}, {"energy_check_every", 0}};
  j["contact"]["small_edge_rays"] = "virtual_replaces_vertex";
  auto [f, written] = round_trip(j);
  CHECK(f.scene.dt_fraction == 0.3);
  CHECK(f.scene.guards.max_step_motion == 0.125);
  CHECK(f.scene.guards.max_energy_growth == 3.0);
  CHECK(f.scene.guards.energy_check_every == 0);
  CHECK(f.scene.contact.small_edge_rays == dda::SmallEdgeRays::kVirtualReplacesVertex);
  CHECK(written["dt_fraction"] == 0.3);
  CHECK_FALSE(written.contains("dt"));  // the reader would refuse it next to dt_fraction > 0
  CHECK(written["guards"]["energy_check_every"] == 0);
  CHECK(written["contact"]["small_edge_rays"] == "virtual_replaces_vertex");

  // Defaults: written out explicitly, dt kept.
  auto [d, dw] = round_trip(base());
  CHECK(dw["dt"] == 1e-4);
  CHECK(dw["dt_fraction"] == 0);
  CHECK(dw["guards"] == json({{"max_step_motion", d.scene.guards.max_step_motion},
                              {"max_balance_error", d.scene.guards.max_balance_error},
                              {"max_energy_growth", d.scene.guards.max_energy_growth},
                              {"energy_check_every", d.scene.guards.energy_check_every},
                              {"max_penetration", d.scene.guards.max_penetration},
                              {"max_approach_energy", d.scene.guards.max_approach_energy}}));
  CHECK(dw["contact"]["small_edge_rays"] == "virtual_and_vertex");
}

TEST_CASE("contact.friction_update: default and both values", "[io][scene][options]") {
  json j = base();
  CHECK(parse_scene(j.dump(), "scene.json").scene.contact.friction_update == dda::FrictionUpdate::kPaper);
  j["contact"]["friction_update"] = "return_mapping";
  CHECK(parse_scene(j.dump(), "scene.json").scene.contact.friction_update == dda::FrictionUpdate::kReturnMapping);
  j["contact"]["friction_update"] = "paper";
  CHECK(parse_scene(j.dump(), "scene.json").scene.contact.friction_update == dda::FrictionUpdate::kPaper);
  // Without friction the default spelled out is accepted, like "friction_deg": 0.
  j = base();
  j["contact"] = {{"kn", 1e7}, {"kt", 0}, {"friction_deg", 0}, {"friction_update", "paper"}};
  CHECK(parse_scene(j.dump(), "scene.json").scene.contact.friction_update == dda::FrictionUpdate::kPaper);
}

TEST_CASE("invalid contact.friction_update names its field", "[io][scene][options][reject]") {
  json j = base();
  j["contact"]["friction_update"] = "return-mapping";
  check_rejected(j, "contact.friction_update",
                 "unknown value \"return-mapping\"; expected one of \"paper\", \"return_mapping\"");
  j["contact"]["friction_update"] = "kReturnMapping";  // the C++ spelling is not the file's
  check_rejected(j, "contact.friction_update", "unknown value");
  j["contact"]["friction_update"] = true;
  check_rejected(j, "contact.friction_update", "expected a string");
  j = base();
  j["contact"]["friction_updates"] = "paper";
  check_rejected(j, "contact.friction_updates", "unknown key (did you mean 'friction_update'?)");
  // The rule would be silently ignored without kt.
  j = base();
  j["contact"] = {{"kn", 1e7}, {"friction_update", "return_mapping"}};
  check_rejected(j, "contact.friction_update", "has no effect with contact.kt = 0");
}

TEST_CASE("contact.friction_update round-trips", "[io][scene][options]") {
  for (const char* name : {"paper", "return_mapping"}) {
    INFO(name);
    json j = base();
    j["contact"]["friction_update"] = name;
    const SceneFile f = parse_scene(j.dump(), "scene.json");
    const std::string text = dda::io::write_scene(f);
    CHECK(json::parse(text)["contact"]["friction_update"] == name);
    const SceneFile g = parse_scene(text, "scene.json (rewritten)");
    CHECK(g.scene.contact.friction_update == f.scene.contact.friction_update);
    CHECK(dda::io::write_scene(g) == text);
  }
  // Without friction: the default is written and read back.
  json j = base();
  j["contact"] = {{"kn", 1e7}};
  const std::string text = dda::io::write_scene(parse_scene(j.dump(), "scene.json"));
  CHECK(json::parse(text)["contact"]["friction_update"] == "paper");
  CHECK(parse_scene(text, "scene.json (rewritten)").scene.contact.friction_update == dda::FrictionUpdate::kPaper);
}
