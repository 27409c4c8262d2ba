// A fast block shot through a thin plate: its nodes cross the whole plate
// within one step, so no step end finds them inside it. Both contact modes
// must stop such a run with a ContactError naming the node and the blocks
// (the path of the node over the step went deeper than the mode's limit),
// never end normally with the blocks passed through each other.
//
// Negative control: the library without the check along the path
// (check_no_passage in model_touch.cpp, called from find_touches and
// penalty_step) runs the fast shot to its end in all four modes, the shot
// 1.94 m below the plate at its launch speed of 800 m/s (printed by the
// INFO of the first test case, whose CHECK(stopped) then fails). The slow
// shot onto the same plate is a legitimate contact and runs through in both
// versions.
#include <catch2/catch.hpp>
#include <cmath>

#include "dda/cdem/model.hpp"

using dda::Vec2;
using namespace dda::cdem;

namespace {

// The plate: 2 m x `thick` m, top at y = 0, its underside at y = -thick,
// free. The projectile: a 0.1 m square `gap` m above it, moving -y at
// `speed`. Soft material (E 1 MPa, rho 1000) so that a coarse dt is stable.
CdemScene plate_shot(double speed, double dt, const CdemOptions& opt, double thick = 0.05, double gap = 0.01) {
  CdemScene s;
  s.materials = {dda::Material{1000.0, 1e6, 0.25}};
  CdemBlock plate;
  plate.outline = {{-1.0, -thick}, {1.0, -thick}, {1.0, 0.0}, {-1.0, 0.0}};
  plate.divisions = 2;
  plate.name = "plate";
  CdemBlock shot;
  shot.outline = {{-0.05, gap}, {0.05, gap}, {0.05, gap + 0.1}, {-0.05, gap + 0.1}};
  shot.divisions = 2;
  shot.velocity = {0.0, -speed};
  shot.name = "shot";
  s.blocks = {plate, shot};
  s.dt = dt;
  s.duration = 10.0 * dt;
  s.options = opt;
  return s;
}

CdemOptions penalty_mode() {
  CdemOptions o;
  o.contact = ContactMode::kNodeToEdgePenalty;
  o.subdivision = false;
  return o;
}

CdemOptions two_scale(bool subdivision, SubdivisionMode mode = SubdivisionMode::kSubModel) {
  CdemOptions o;
  o.subdivision = subdivision;
  o.subdivision_mode = mode;
  return o;
}

}  // namespace

TEST_CASE("tunnel: a shot crossing a thin plate within one step stops the run", "[tunnel]") {
  constexpr double kDt = 2.5e-4;  // s, below the meshes' critical step (checked by the Model)
  // 0.2 m per step: from 0.01 m above the plate's top to 0.14 m below its
  // underside in the first step; the plate is 0.05 m thick.
  constexpr double kFast = 0.2 / kDt;
  struct Mode {
    const char* name;
    CdemOptions opt;
  };
  const Mode modes[] = {{"two-scale, no subdivision", two_scale(false)},
                        {"two-scale, sub-model", two_scale(true)},
                        {"two-scale, in-place", two_scale(true, SubdivisionMode::kInPlace)},
                        {"node-to-edge penalty", penalty_mode()}};
  for (const Mode& md : modes) {
    SECTION(md.name) {
      Model m(plate_shot(kFast, kDt, md.opt));
      // the limit of the mode is below the plate's half thickness, so the
      // node's path through the plate exceeds it
      bool stopped = false;
      try {
        m.advance_to(m.scene().duration);
      } catch (const ContactError& e) {
        stopped = true;
        INFO(e.what());
        // a node of the shot through the plate, or of the plate through
        // the shot (their relative paths cross either way)
        CHECK(m.node_block(e.node) == e.block);
        CHECK(e.block + e.other_block == 1);
        CHECK(e.block != e.other_block);
        CHECK(e.step == 1);
        CHECK(e.depth > 0.02);  // the plate's half thickness, less the interpolation of a deformed path
        CHECK(std::string(e.what()).find("smaller dt") != std::string::npos);
      }
      INFO("shot at t = " << m.time() << ": mean y " << m.block_mean_position(1).y << ", v "
                          << m.block_velocity(1).y);
      CHECK(stopped);
    }
  }
}

TEST_CASE("tunnel: a slower shot onto the same plate is a legitimate contact", "[tunnel]") {
  // 1 m/s, 2.5e-4 m per step: every mode sees the contact at a step end
  // and the shot does not pass the plate (the penalty with kn = E, stable
  // at this dt).
  constexpr double kDt = 2.5e-4;
  CdemOptions stiff = penalty_mode();
  stiff.penalty_kn = 1e6;
  const CdemOptions opts[] = {two_scale(false), two_scale(true), two_scale(true, SubdivisionMode::kInPlace), stiff};
  for (const CdemOptions& o : opts) {
    CdemScene s = plate_shot(1.0, kDt, o);
    s.duration = 0.05;
    Model m(s);
    REQUIRE_NOTHROW(m.advance_to(s.duration));
    CHECK(m.block_mean_position(1).y > 0.0);  // still above the plate's top
    CHECK(m.block_velocity(1).y > -1.0);
  }
}
