// Negative controls of the Sect. 5.2 small-angle rows: point symmetry,
// contact and energy, each judged by the driver's own rows on a scene
// changed so that the property fails.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "dda/paper_scenes.hpp"
#include "repro/5_2_small_angles/small_angles.hpp"
#include "repro/common/claims.hpp"
#include "repro/common/controls.hpp"

using controls::row;

namespace {
// The 5.2 rows for a modified scene (the run stands in for the apex-to-apex variant too).
std::vector<repro::Claim> small_angle_rows(const dda::paper::SmallAngleTriangles& st) {
  const small_angles::Result r = small_angles::run(st, nullptr, nullptr);
  return small_angles::claims(r, r, "");
}
std::string control(const char* name) { return std::string("repro_controls: ") + name; }
}  // namespace

TEST_CASE("5.2 point symmetry: FAIL when one triangle is 1 % faster", "[controls][5.2]") {
  dda::paper::SmallAngleTriangles st = dda::paper::small_angle_triangles(5.0);
  st.scene.blocks[0].velocity = st.scene.blocks[0].velocity * 1.01;  // no longer point images in velocity
  const repro::Claim c = row(small_angle_rows(st), "symmetry");
  CHECK_FALSE(c.pass);
  CHECK(c.control == control(small_angles::kControlFaster));
}

TEST_CASE("5.2 contact: FAIL when the triangles move apart", "[controls][5.2]") {
  dda::paper::SmallAngleTriangles st = dda::paper::small_angle_triangles(5.0);
  for (dda::BlockSpec& b : st.scene.blocks) b.velocity = -1.0 * b.velocity;  // no collision at all
  const repro::Claim c = row(small_angle_rows(st), "separate");
  CHECK_FALSE(c.pass);
  CHECK(c.control == control(small_angles::kControlApart));
}

TEST_CASE("5.2 energy: FAIL with mass damping", "[controls][5.2]") {
  dda::paper::SmallAngleTriangles st = dda::paper::small_angle_triangles(5.0);
  st.scene.damping.mass = 1.0;  // 1/s: about a fifth of the energy lost over the 0.2 s run
  const auto rows = small_angle_rows(st);
  for (const char* key : {"energy", "apex-to-apex"}) {
    CHECK_FALSE(row(rows, key).pass);
    CHECK(row(rows, key).control == control(small_angles::kControlDamped));
  }
}
