// Scene files with "generated" regions (a region cut by joint sets, Paper A
// Sect. 6): parsing, block order and attributes, every rejection names its
// field, and the Sect. 6 example scenes equal the C++ scene builders.
#include <catch2/catch.hpp>


#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dda/io/scene_file.hpp"
#include "dda/rock_scenes.hpp"
#include "scene_helpers.hpp"

using namespace dda::io::test;

namespace {

// One listed block left of a 4 m x 2 m region cut by vertical joints 1 m
// apart (4 blocks) and a 45 deg set 1 m apart.
json base() {
  return json::parse(R"({
    "materials": [{"name": "soft", "density": 1000, "young": 1e8, "poisson": 0.2},
                  {"name": "rock", "density": 2700, "young": 2e9, "poisson": 0.3}],
    "blocks": [{"name": "lone", "rect": [-2, 0, 1, 1]}],
    "generated": {
      "name": "g",
      "region": [[0, 0], [4, 0], [4, 2], [0, 2]],
      "joint_sets": [{"dip_deg": 90, "spacing": 1, "origin": [0, 0]}],
      "material": "rock",
      "group": 2
    },
    "contact": {"kn": 1e7},
    "dt": 1e-4,
    "duration": 0.1
  })");
}

void check_same_scene(const dda::Scene& a, const dda::Scene& b) {
  REQUIRE(a.blocks.size() == b.blocks.size());
  for (std::size_t i = 0; i < a.blocks.size(); ++i) {
    INFO("block " << i);
    REQUIRE(a.blocks[i].vertices.size() == b.blocks[i].vertices.size());
    for (std::size_t k = 0; k < a.blocks[i].vertices.size(); ++k)
      CHECK(a.blocks[i].vertices[k] == b.blocks[i].vertices[k]);  // bit-exact
    CHECK(a.blocks[i].group == b.blocks[i].group);
    CHECK(a.blocks[i].material == b.blocks[i].material);
    CHECK(a.blocks[i].fixed == b.blocks[i].fixed);
  }
  REQUIRE(a.boundaries.size() == b.boundaries.size());
  for (std::size_t i = 0; i < a.boundaries.size(); ++i) {
    INFO("boundary " << i);
    CHECK(a.boundaries[i].a == b.boundaries[i].a);
    CHECK(a.boundaries[i].b == b.boundaries[i].b);
    CHECK(a.boundaries[i].depth == b.boundaries[i].depth);
    CHECK(a.boundaries[i].group == b.boundaries[i].group);
  }
  REQUIRE(a.materials.size() == b.materials.size());
  CHECK(a.materials[0].density == b.materials[0].density);
  CHECK(a.materials[0].young == b.materials[0].young);
  CHECK(a.materials[0].poisson == b.materials[0].poisson);
  CHECK(a.contact.kn == b.contact.kn);
  CHECK(a.contact.kt == b.contact.kt);
  CHECK(a.contact.friction_deg == b.contact.friction_deg);
  REQUIRE(a.contact.friction_rules.size() == b.contact.friction_rules.size());
  for (std::size_t i = 0; i < a.contact.friction_rules.size(); ++i) {
    CHECK(a.contact.friction_rules[i].group_a == b.contact.friction_rules[i].group_a);
    CHECK(a.contact.friction_rules[i].group_b == b.contact.friction_rules[i].group_b);
    CHECK(a.contact.friction_rules[i].friction_deg == b.contact.friction_rules[i].friction_deg);
  }
  CHECK(a.contact.h_rule == b.contact.h_rule);
  CHECK(a.gravity == b.gravity);
  CHECK(a.broad_phase == b.broad_phase);
  CHECK(a.dt == b.dt);
  CHECK(a.duration == b.duration);
}

}  // namespace

TEST_CASE("a generated region becomes blocks after the listed ones", "[io][scene][generated]") {
  const SceneFile f = parse_scene(base().dump(), "scene.json");
  REQUIRE(f.scene.blocks.size() == 5);
  CHECK(f.scene.blocks[0].name == "lone");
  CHECK(f.scene.blocks[0].group == 0);
  REQUIRE(f.generated.size() == 1);
  CHECK(f.generated[0].first_block == 1);
  CHECK(f.generated[0].count == 4);
  CHECK(f.generated[0].dropped == 0);
  double area = 0.0;
  for (int i = 1; i < 5; ++i) {
    const dda::BlockSpec& b = f.scene.blocks[static_cast<std::size_t>(i)];
    CHECK(b.name == "g_" + std::to_string(i - 1));
    CHECK(b.material == 1);  // "rock"
    CHECK(b.group == 2);
    CHECK_FALSE(b.fixed);
    const dda::Polygon p = dda::make_polygon(b.vertices.data(), static_cast<int>(b.vertices.size()));
    area += dda::area(p);
  }
  CHECK(area == Approx(8.0).epsilon(1e-12));
  // Names work in tracked_blocks.
  json j = base();
  j["output"] = {{"tracked_blocks", {"g_3", "lone"}}};
  CHECK(parse_scene(j.dump(), "scene.json").output.tracked_blocks == std::vector<int>{4, 0});
}

TEST_CASE("generated takes one object or an array; min_area drops slivers", "[io][scene][generated]") {
  json j = base();
  json second = j["generated"];
  second.erase("name");
  second["region"] = {{0, 3}, {4, 3}, {4, 5}, {0, 5}};
  second["joint_sets"] = {{{"dip_deg", 90}, {"spacing", 1}, {"origin", {0.1, 0}}}};
  second["min_area"] = 0.5;
  j["generated"] = {j["generated"], second};
  const SceneFile f = parse_scene(j.dump(), "scene.json");
  REQUIRE(f.generated.size() == 2);
  CHECK(f.generated[0].first_block == 1);
  CHECK(f.generated[1].first_block == 5);
  // Cuts at x = 0.1, 1.1, 2.1, 3.1: pieces 0.1, 1, 1, 1, 0.9 m wide; the 0.2 m^2 strip is dropped.
  CHECK(f.generated[1].count == 4);
  CHECK(f.generated[1].dropped == 1);
  CHECK(f.generated[1].dropped_area == Approx(0.2).epsilon(1e-9));
  CHECK(f.scene.blocks.size() == 9);
  CHECK(f.scene.blocks[5].name.empty());
}

TEST_CASE("bad generated sections name their field", "[io][scene][generated][reject]") {
  json j = base();
  j["generated"]["region"] = {{0, 0}, {0, 2}, {4, 2}, {4, 0}};
  check_rejected(j, "generated.region", "counter-clockwise");

  j = base();
  j["generated"]["joint_sets"][0]["spacing"] = 0;
  check_rejected(j, "generated.joint_sets[0].spacing", "must be positive");

  j = base();
  j["generated"]["joint_sets"][0]["dip_deg"] = 180;
  check_rejected(j, "generated.joint_sets[0].dip", "(0, 180)");

  j = base();
  j["generated"]["joint_sets"][0].erase("dip_deg");
  j["generated"]["joint_sets"][0]["dip_dg"] = 45;
  check_rejected(j, "generated.joint_sets[0].dip_dg", "did you mean 'dip_deg'");

  j = base();
  j["generated"].erase("region");
  check_rejected(j, "generated.region", "missing required key");

  j = base();
  j["generated"]["min_area"] = -1;
  check_rejected(j, "generated.min_area", "must be >= 0");

  j = base();
  j["generated"]["material"] = "granite";
  check_rejected(j, "generated.material", "no material named");

  j = base();
  j["generated"] = {j["generated"], 3};
  check_rejected(j, "generated[1]", "expected an object");

  j = base();
  j["generated"] = "left";
  check_rejected(j, "generated", "expected an array");

  // An overlap found by the kernel names the generated block.
  j = base();
  j["blocks"][0]["rect"] = {0.5, 0.5, 1, 1};
  const std::string m = error_of(j);
  INFO(m);
  CHECK(m.find("overlaps") != std::string::npos);
  CHECK(m.find("is block 0 of generated") != std::string::npos);
}

TEST_CASE("the Sect. 6 example scene files equal the C++ scene builders", "[io][scene][generated][examples]") {
  const SceneFile c1 = dda::io::load_scene_file(std::string(DDA_SCENES_DIR) + "/collapse_case1.json");
  const dda::paper::Collapse col = dda::paper::collapse(15.0);
  check_same_scene(c1.scene, col.scene);
  REQUIRE(c1.generated.size() == 1);
  CHECK(c1.generated[0].dropped == col.dropped);
  CHECK(c1.generated[0].dropped_area == col.dropped_area);

  const SceneFile ts = dda::io::load_scene_file(std::string(DDA_SCENES_DIR) + "/toppling_slumping.json");
  const dda::paper::TopplingSlumping tsb = dda::paper::toppling_slumping();
  check_same_scene(ts.scene, tsb.scene);
  REQUIRE(ts.generated.size() == 2);
  CHECK(ts.generated[0].dropped + ts.generated[1].dropped == tsb.dropped);
}
