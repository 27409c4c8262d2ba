// Hostile scene files: bytes after the document, duplicate names,
// size limits checked while reading, the step-count limit, coordinates whose
// area overflows, and line:column in messages. Each case failed before the
// reader checked it (accepted, misreported, or took unbounded time/memory).
#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include <nlohmann/json.hpp>

#include "dda/io/run.hpp"
#include "dda/io/scene_file.hpp"
#include "scene_helpers.hpp"

using dda::io::ReadOptions;
using namespace dda::io::test;

namespace {

json base() {
  return json::parse(R"({
    "materials": [{"name": "rock", "density": 2000, "young": 1e9, "poisson": 0.25}],
    "blocks": [
      {"name": "A", "rect": [0, 0, 1, 1]},
      {"name": "B", "vertices": [[2, 0], [3, 0], [3, 1], [2, 1]]}
    ],
    "contact": {"kn": 1e7},
    "dt": 1e-4,
    "duration": 0.5
  })");
}

struct Where {
  long line = -1, column = -1;  // -1: no position in the message
  std::string rest;             // after "<file>[:l:c]: "
};
Where where(const std::string& m) {
  static const std::regex re("^scene\\.json(?::([0-9]+):([0-9]+))?: (.*)$");
  std::smatch s;
  Where w;
  if (!std::regex_match(m, s, re)) return w;
  if (s[1].matched) w.line = std::stol(s[1]), w.column = std::stol(s[2]);
  w.rest = s[3];
  return w;
}

}  // namespace

TEST_CASE("bytes after the JSON document are refused, a NUL included", "[io][scene][hostile]") {
  const std::string text = base().dump();
  REQUIRE(error_of(text).empty());
  const std::string with_nul = text + std::string("\0", 1);
  std::string m = error_of(with_nul);
  INFO(m);
  CHECK(m.find("NUL byte") != std::string::npos);
  CHECK(where(m).line == 1);
  CHECK(where(m).column == static_cast<long>(text.size()) + 1);
  CHECK(error_of(text + std::string("\0{\"x\": 1}", 9)).find("NUL byte") != std::string::npos);
  CHECK_FALSE(error_of(text + " x").empty());
  CHECK_FALSE(error_of(text + "{}").empty());
  CHECK(error_of(text + " \n\t").empty());  // whitespace is allowed
}

TEST_CASE("duplicate names are refused in every named list", "[io][scene][hostile]") {
  json j = base();
  j["blocks"][1]["name"] = "A";
  check_rejected(error_of(j), "blocks[1].name", "duplicate block name \"A\"");
  j = base();
  j["materials"].push_back({{"name", "rock"}, {"density", 1}, {"young", 1}, {"poisson", 0}});
  check_rejected(error_of(j), "materials[1].name", "duplicate material name \"rock\"");
  // A generated block's name ("<name>_<k>") against a listed block's.
  j = base();
  j["blocks"][1]["name"] = "g_0";
  j["generated"] = {{"name", "g"}, {"region", {{10, 0}, {11, 0}, {11, 1}, {10, 1}}}, {"joint_sets", json::array()}};
  check_rejected(error_of(j), "generated.name", "duplicate block name \"g_0\"");
  // Two generated regions of one name.
  j = base();
  j["generated"] = {{{"name", "g"}, {"region", {{10, 0}, {11, 0}, {11, 1}, {10, 1}}}, {"joint_sets", json::array()}},
                    {{"name", "g"}, {"region", {{20, 0}, {21, 0}, {21, 1}, {20, 1}}}, {"joint_sets", json::array()}}};
  check_rejected(error_of(j), "generated[1].name", "duplicate block name \"g_0\"");
  // Unnamed blocks and materials may repeat.
  j = base();
  j["blocks"][0].erase("name");
  j["blocks"][1].erase("name");
  j["materials"].push_back({{"density", 1}, {"young", 1}, {"poisson", 0}});
  j["materials"].push_back({{"density", 1}, {"young", 1}, {"poisson", 0}});
  CHECK(error_of(j).empty());
}

TEST_CASE("nesting depth is limited while reading", "[io][scene][hostile][limits]") {
  // 100,000 nested arrays (200 KB): refused at the 17th '[', not built.
  const std::size_t n = 100000;
  const std::string text = "{\"blocks\": " + std::string(n, '[') + std::string(n, ']') + "}";
  const std::string m = error_of(text);
  INFO(m);
  CHECK(m.find("nested deeper than 16") != std::string::npos);
  const Where w = where(m);
  CHECK(w.line == 1);
  // '[' number k is at column 11 + k and depth k + 1 (the top-level object is depth 1).
  CHECK(w.column == 11 + static_cast<long>(dda::io::kMaxNestingDepth));
  // The schema's own depth (5) is far inside the limit.
  CHECK(error_of(base()).empty());
}

TEST_CASE("array lengths are limited while reading", "[io][scene][hostile][limits]") {
  // A polygon of 10^6 vertices is refused at vertex 256, before the rest is read.
  std::string verts = "[";
  for (int i = 0; i < 1000000; ++i) verts += (i ? ",[0,0]" : "[0,0]");
  verts += "]";
  std::string text = base().dump();
  const std::string old = "[[2,0],[3,0],[3,1],[2,1]]";
  REQUIRE(text.find(old) != std::string::npos);
  text.replace(text.find(old), old.size(), verts);
  std::string m = error_of(text);
  INFO(m);
  check_rejected(m, "blocks[1].vertices", "more than 256 elements");
  CHECK(where(m).column < static_cast<long>(text.find(verts) + 6 * 300));  // stopped near vertex 256
  // Blocks: at most kMaxBlocks.
  json j = base();
  json blocks = json::array();
  for (std::size_t i = 0; i <= dda::io::kMaxBlocks; ++i) blocks.push_back(json::object());
  j["blocks"] = blocks;
  check_rejected(error_of(j), "blocks", "more than 100000 elements");
  // Any other array: kMaxArrayLength.
  j = base();
  j["output"] = {{"snapshots", std::vector<double>(dda::io::kMaxArrayLength + 1, 0.0)}};
  check_rejected(error_of(j), "output.snapshots", "more than 100000 elements");
  // A joint spacing that would cut a region into billions of blocks.
  j = base();
  j["generated"] = {{"region", {{10, 0}, {20, 0}, {20, 10}, {10, 10}}},
                    {"joint_sets", {{{"dip_deg", 30}, {"spacing", 1e-9}}}}};
  check_rejected(error_of(j), "generated.joint_sets[0].spacing", "more than 100000 (the reader's limit on blocks)");
  // An origin so far away that the generator's line counter k + 1 == k
  // (before: an endless loop; found by io_scene_fuzz, seed 777 case 154).
  j = base();
  j["generated"] = {{"region", {{10, 0}, {20, 0}, {20, 10}, {10, 10}}},
                    {"joint_sets", {{{"dip_deg", 75}, {"spacing", 3}, {"origin", {9.223372036854776e18, 0}}}}}};
  check_rejected(error_of(j), "generated.joint_sets[0].origin", "too far from the region");
}

TEST_CASE("file size is limited before reading", "[io][scene][hostile][limits]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(DDA_IO_TEST_TMP) / "hostile";
  fs::create_directories(dir);
  const std::string big = (dir / "big.json").string();
  {
    std::ofstream out(big, std::ios::binary);
    const std::string line(1023, ' ');
    for (std::size_t i = 0; i <= dda::io::kMaxSceneFileBytes / 1024; ++i) out << line << '\n';
  }
  const std::string m = load_error_of(big);
  INFO(m);
  CHECK(m.rfind(big + ": more than 16777216 bytes", 0) == 0);
  fs::remove(big);
  // A device without a size: at most the limit is read.
  CHECK(load_error_of("/dev/zero").find("more than 16777216 bytes") != std::string::npos);
}

TEST_CASE("a run of too many steps is refused unless allowed", "[io][scene][hostile][steps]") {
  json j = base();
  j["duration"] = 1e11;  // 10^15 steps of 1e-4 s
  std::string m = error_of(j);
  check_rejected(m, "duration", "is 1e+15 steps, more than max_steps = 10000000");
  CHECK(m.find("set \"max_steps\" in the scene file or give dda run --max-steps N") != std::string::npos);
  // The file's max_steps, or the reader option, allow it.
  j["max_steps"] = 1e15;
  CHECK(error_of(j).empty());
  j.erase("max_steps");
  ReadOptions opt;
  opt.max_steps = 1000000000000000;
  CHECK(error_of(j, opt).empty());
  opt.max_steps = 10;  // the option overrides the file (both ways)
  j["duration"] = 0.5;
  j["max_steps"] = 1e6;
  check_rejected(error_of(j, opt), "duration", "more than max_steps = 10");
  j["max_steps"] = 0;
  check_rejected(error_of(j), "max_steps", "must be >= 1");
  j["max_steps"] = 2.5;
  check_rejected(error_of(j), "max_steps", "expected an integer");
  // Exactly the limit is allowed: 5000 steps.
  j["max_steps"] = 5000;
  CHECK(error_of(j).empty());
  j["max_steps"] = 4999;
  CHECK_FALSE(error_of(j).empty());
  // max_steps round-trips when not the default.
  const SceneFile f = parse_scene(base().dump(), "scene.json");
  CHECK(f.max_steps == dda::io::kDefaultMaxSteps);
  CHECK(json::parse(dda::io::write_scene(f)).count("max_steps") == 0);
  j = base();
  j["max_steps"] = 123456789;
  const SceneFile g = parse_scene(j.dump(), "scene.json");
  CHECK(parse_scene(dda::io::write_scene(g), "x").max_steps == 123456789);
}

TEST_CASE("with dt_fraction the step limit uses the simulation's dt", "[io][scene][hostile][steps]") {
  json j = base();
  j.erase("dt");
  j["dt_fraction"] = 0.5;
  j["duration"] = 1e11;
  const SceneFile f = parse_scene(j.dump(), "scene.json");  // dt unknown here
  dda::io::RunOptions opt;
  opt.out_dir = std::string(DDA_IO_TEST_TMP) + "/hostile/never";
  opt.scene_label = "scene.json";
  std::filesystem::remove_all(opt.out_dir);
  std::string m;
  try {
    dda::io::run_scene(f, opt);
  } catch (const SceneFileError& e) {
    m = e.what();
  }
  INFO(m);
  CHECK(m.find("scene.json: duration: ") == 0);
  CHECK(m.find("more than max_steps") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(opt.out_dir));  // nothing written
}

TEST_CASE("coordinates whose area overflows say so", "[io][scene][hostile]") {
  json j = base();
  j["blocks"][1]["vertices"] = {{0, 10}, {1e308, 10}, {1e308, 1e308}, {0, 1e308}};
  std::string m = error_of(j);
  check_rejected(m, "blocks[1].vertices", "overflows a double");
  CHECK(m.find("duplicate vertex") == std::string::npos);
  j = base();
  j["blocks"][0]["rect"] = {1e308, 0, 1e308, 1};  // x0 + w is infinite
  check_rejected(error_of(j), "blocks[0].rect", "vertex 1: coordinate overflows");
  j = base();
  j["blocks"][0]["rect"] = {-1e200, -1e200, 1e200, 1e200};
  check_rejected(error_of(j), "blocks[0].rect", "squared length overflows");
  j = base();  // edges of 1e154 m are finite when squared, the area (~1e308 * 4) is not
  j["blocks"][0]["rect"] = {-1e154, -1e154, 1.3e154, 1.3e154};
  check_rejected(error_of(j), "blocks[0].rect", "area overflows");
  j = base();
  j["boundaries"] = {{{"a", {-1e200, 0}}, {"b", {1e200, 0}}}};
  check_rejected(error_of(j), "boundaries[0]", "squared length overflows");
  j = base();
  j["generated"] = {{"region", {{10, 0}, {1e300, 0}, {1e300, 1e300}, {10, 1e300}}}, {"joint_sets", json::array()}};
  check_rejected(error_of(j), "generated.region", "overflows a double");
}

TEST_CASE("messages give line and column of the field", "[io][scene][hostile]") {
  const std::string text =
      "{\n"
      "  \"materials\": [{\"density\": 2000, \"young\": 1e9, \"poisson\": 0.25}],\n"
      "  \"blocks\": [{\"rect\": [0, 0, 1, 1]}],\n"
      "  \"contact\": {\"kn\": -1},\n"
      "  \"dt\": 1e-4, \"duration\": 1\n"
      "}\n";
  std::string m = error_of(text);
  INFO(m);
  CHECK(m.rfind("scene.json:4:", 0) == 0);
  check_rejected(m, "contact.kn", "must be positive");
  // A kernel message about a vertex points at the vertex.
  json j = base();
  j["blocks"][1]["vertices"] = {{2, 0}, {2, 1}, {3, 1}, {3, 0}};  // clockwise
  const std::string t2 = j.dump(1);
  m = error_of(t2);
  INFO(m);
  CHECK(where(m).line > 1);
  // A missing key has no position: just the file.
  j = base();
  j.erase("dt");
  m = error_of(j);
  CHECK(m.rfind("scene.json: dt: missing required key", 0) == 0);
}

TEST_CASE("guards.max_balance_error is read, checked and written", "[io][scene][options]") {
  json j = base();
  j["guards"] = {{"max_balance_error", 0.02}};
  const SceneFile f = parse_scene(j.dump(), "scene.json");
  CHECK(f.scene.guards.max_balance_error == 0.02);
  CHECK(parse_scene(dda::io::write_scene(f), "x").scene.guards.max_balance_error == 0.02);
  CHECK(parse_scene(base().dump(), "x").scene.guards.max_balance_error == dda::StabilityGuards{}.max_balance_error);
  j["guards"]["max_balance_error"] = -1;
  check_rejected(error_of(j), "guards.max_balance_error", "must be >= 0");
}

TEST_CASE("friction group numbers are bounded (the friction table is groups^2)", "[io][scene][hostile]") {
  // Before: a group of 1e6 made the simulation fill a table of (1e6)^2 (int
  // overflow) doubles; a negative boundary group indexed it out of bounds.
  json j = base();
  j["blocks"][0]["group"] = 1000000;
  check_rejected(error_of(j), "blocks[0].group", "must lie in [0, 1024)");
  j = base();
  j["boundaries"] = {{{"a", {-5, -1}}, {"b", {5, -1}}, {"group", -1}}};
  check_rejected(error_of(j), "boundaries[0].group", "must lie in [0, 1024)");
  j = base();
  j["contact"]["kt"] = 1e7;
  j["contact"]["friction_rules"] = {{{"groups", {0, 5000}}, {"friction_deg", 10}}};
  check_rejected(error_of(j), "contact.friction_rules[0]", "groups must lie in [0, 1024)");
  j = base();
  j["blocks"][0]["group"] = 1023;
  CHECK(error_of(j).empty());
}
