// Negative controls of the Sect. 4.3 incline rows: Eq. 30 with and without
// friction, creep after the stop and rest on the 30 deg slope, each judged
// by the driver's own criterion on a run with the friction changed so that
// the claim fails.
#include <catch2/catch.hpp>

#include <string>

#include "dda/paper_scenes.hpp"
#include "repro/4_3_incline/incline.hpp"
#include "repro/common/claims.hpp"

TEST_CASE("4.3 Eq. 30 with friction: FAIL with friction off", "[controls][4.3]") {
  for (double phi : {10.0, 20.0}) {
    dda::paper::Incline in = dda::paper::incline(phi);
    in.scene.contact.kt = 0.0;  // friction off: B slides as on a frictionless plane
    const repro::Claim c = incline::eq30_row(phi, incline::run(in, nullptr, phi, dda::FrictionUpdate::kPaper));
    CHECK_FALSE(c.pass);
    CHECK(c.control == incline::kControlEq30Friction);
  }
  // The other configurations whose rows name this control, each judged
  // against Eq. 30 at phi = 20 deg without friction: H = 1 m, B starting
  // just touching, and the start-up option (which needs kt > 0 to settle:
  // there the friction angle is 0 instead).
  const auto paper = dda::FrictionUpdate::kPaper;
  dda::paper::Incline h1 = dda::paper::incline(20.0, 30.0, 1.0, true, 1.0);
  h1.scene.contact.kt = 0.0;
  CHECK_FALSE(incline::eq30_met(incline::run(h1, nullptr, 20.0, paper)));
  dda::paper::Incline touching = dda::paper::incline(20.0, 30.0, 1.0, false);
  touching.scene.contact.kt = 0.0;
  CHECK_FALSE(incline::eq30_met(incline::run(touching, nullptr, 20.0, paper)));
  CHECK_FALSE(incline::eq30_met(incline::run(incline::with_start_up(dda::paper::incline(0.0)), nullptr, 20.0, paper)));
  CHECK_FALSE(incline::eq30_met(
      incline::run(incline::with_start_up(dda::paper::incline(0.0, 30.0, 1.0, true, 1.0)), nullptr, 20.0, paper)));
}

TEST_CASE("4.3 Eq. 30 without friction: FAIL with friction on", "[controls][4.3]") {
  // The phi = 0 row judged on a run with the 10 deg friction of the next case.
  const repro::Claim c =
      incline::eq30_row(0.0, incline::run(dda::paper::incline(10.0), nullptr, 0.0, dda::FrictionUpdate::kPaper));
  CHECK_FALSE(c.pass);
  CHECK(c.control == repro::control_test(incline::kControlEq30Frictionless));
  // The phi = 0 start-up option's row, on the option's run with 10 deg friction.
  CHECK_FALSE(incline::eq30_met(incline::run(incline::with_start_up(dda::paper::incline(10.0)), nullptr, 0.0,
                                             dda::FrictionUpdate::kPaper)));
}

TEST_CASE("4.3 creep: FAIL on a slope steeper than the friction angle", "[controls][4.3]") {
  // With a friction angle of 15 deg on the 20 deg slope B never stops: it
  // accelerates downhill at g (sin 20 - cos 20 tan 15) = 0.88 m/s^2, so the
  // "creep" after the would-be stop is a slide, with either update.
  for (dda::FrictionUpdate u : {dda::FrictionUpdate::kPaper, dda::FrictionUpdate::kReturnMapping}) {
    const incline::Creep c = incline::creep(u, 15.0);
    INFO("rate " << c.rate << " m/s");
    CHECK_FALSE(incline::creep_stopped(c));
  }
  CHECK(incline::creep_stopped(incline::creep(dda::FrictionUpdate::kReturnMapping)));
}

TEST_CASE("4.3 rest: FAIL with friction off", "[controls][4.3]") {
  dda::paper::Incline in = dda::paper::incline(incline::kRestPhi);
  in.scene.contact.kt = 0.0;  // friction off: the block slides down the 30 deg slope
  const repro::Claim c =
      incline::rest_row(incline::run(in, nullptr, incline::kRestPhi, dda::FrictionUpdate::kPaper));
  CHECK_FALSE(c.pass);
  CHECK(c.control == std::string("repro_controls: ") + incline::kControlRest);
  // The start-up option's row (settling needs kt > 0: friction angle 0 instead).
  const repro::Claim s = incline::rest_row(incline::run(incline::with_start_up(dda::paper::incline(0.0)), nullptr,
                                                        incline::kRestPhi, dda::FrictionUpdate::kPaper));
  CHECK_FALSE(s.pass);
}
