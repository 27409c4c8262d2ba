// Scene-file keys of the integrator options: "rotation_update" and
// "damping" (Eq. 5c, settle-then-load).
#include <catch2/catch.hpp>

#include <string>

#include <nlohmann/json.hpp>

#include "dda/io/scene_file.hpp"
#include "scene_helpers.hpp"

using namespace dda::io::test;

namespace {

json scene() {
  return json::parse(R"({
    "materials": [{"density": 2000, "young": 1e9, "poisson": 0.25}],
    "blocks": [{"rect": [0, 0, 1, 1], "spin": 1}],
    "contact": {"kn": 1e7, "kt": 1e7, "friction_deg": 20},
    "dt": 1e-4,
    "duration": 0.1
  })");
}

}  // namespace

TEST_CASE("rotation_update and damping: defaults, values, round trip", "[io][scene][options]") {
  json j = scene();
  dda::Scene s = parse_scene(j.dump(), "scene.json").scene;
  CHECK(s.rotation_update == dda::RotationUpdate::kPaperLinear);
  CHECK_FALSE(s.damping.on());
  CHECK(s.damping.settle_time == 0.0);
  j["rotation_update"] = "exact";
  j["damping"] = {{"mass", 2.0}, {"stiffness", 1e-4}, {"settle_time", 0.5}, {"settle_sticking", true}, {"settle_slip_time", 0.2}};
  const dda::io::SceneFile f = parse_scene(j.dump(), "scene.json");
  CHECK(f.scene.rotation_update == dda::RotationUpdate::kExact);
  CHECK(f.scene.damping.mass == 2.0);
  CHECK(f.scene.damping.stiffness == 1e-4);
  CHECK(f.scene.damping.settle_time == 0.5);
  CHECK(f.scene.damping.settle_sticking);
  CHECK(f.scene.damping.settle_slip_time == 0.2);
  const std::string text = dda::io::write_scene(f);
  const dda::Scene g = parse_scene(text, "scene.json (rewritten)").scene;
  CHECK(g.rotation_update == dda::RotationUpdate::kExact);
  CHECK(g.damping.mass == 2.0);
  CHECK(g.damping.stiffness == 1e-4);
  CHECK(g.damping.settle_time == 0.5);
  CHECK(g.damping.settle_sticking);
  CHECK(g.damping.settle_slip_time == 0.2);
}

TEST_CASE("invalid rotation_update and damping name their field", "[io][scene][options][reject]") {
  json j = scene();
  j["rotation_update"] = "linear";
  CHECK(error_of(j).find("rotation_update: unknown value \"linear\"") != std::string::npos);
  j = scene();
  j["damping"] = {{"mass", -1.0}};
  CHECK(error_of(j).find("damping.mass: must be finite and >= 0") != std::string::npos);
  j = scene();
  j["damping"] = {{"settle_time", 1.0}};
  CHECK(error_of(j).find("damping.settle_time: settling needs damping") != std::string::npos);
  j = scene();
  j["damping"] = {{"mass", 1.0}, {"settle_sticking", true}};
  CHECK(error_of(j).find("damping.settle_sticking: needs damping.settle_time > 0") != std::string::npos);
  j = scene();
  j["damping"] = {{"mass", 1.0}, {"settle_time", 0.5}, {"settle_sticking", true}, {"settle_slip_time", 0.5}};
  CHECK(error_of(j).find("damping.settle_slip_time: needs damping.settle_sticking and a value below") !=
        std::string::npos);
  j = scene();
  j["damping"] = {{"alpha", 1.0}};
  CHECK(error_of(j).find("damping.alpha: unknown key") != std::string::npos);
  CHECK(error_of(scene()).empty());
}
