// Negative controls of the B-7 rows, Paper A's contact (A) against Paper
// B's (B, and B0 without subdivision) on the same collisions: time of
// impact, momentum, velocity exchange, energy, contact duration and the kn
// dependence, and the node-to-edge penalty baseline P's touch, momentum and
// stability rows. Each test applies the row's own criterion to the driver's
// configuration (PASS) and to a deliberately wrong one (FAIL): a wrong
// reference, block j fixed or twice as dense, mass damping, a softer or a
// stiffer contact.
#include <catch2/catch.hpp>

#include <functional>
#include <string>
#include <vector>

#include "dda/cdem/model.hpp"
#include "dda/scene.hpp"
#include "repro/B_7_contact_comparison/contact_comparison.hpp"
#include "repro/B_7_contact_comparison/penalty_baseline.hpp"
#include "repro/common/controls.hpp"

namespace {
compare::SceneDef scene_def(const std::string& name) {
  return controls::named(compare::scene_defs(), name, "B-7 scene");
}
// The runs of A, B and B0 at the base dt.
struct Runs {
  std::vector<compare::Result> a, b, b0;
};
Runs base_runs(const compare::SceneDef& d) {
  return {compare::run_sweep(d, "A", nullptr, true), compare::run_sweep(d, "B", nullptr, true),
          compare::run_sweep(d, "B0", nullptr, true)};
}
compare::Result base_run(const compare::SceneDef& d, const std::string& model) {
  return compare::run_sweep(d, model, nullptr, true).front();
}
// d with its Paper A (DDA) scene changed by f.
compare::SceneDef with_dda(const compare::SceneDef& d, const std::function<void(dda::Scene&)>& f) {
  compare::SceneDef w = d;
  const auto make = d.dda_scene;
  w.dda_scene = [make, f] {
    dda::Scene s = make();
    f(s);
    return s;
  };
  return w;
}
// d with its Paper B (CDEM) scenes changed by f.
compare::SceneDef with_cdem(const compare::SceneDef& d, const std::function<void(dda::cdem::CdemScene&)>& f) {
  compare::SceneDef w = d;
  const auto make = d.cdem_scene;
  w.cdem_scene = [make, f](bool sub) {
    dda::cdem::CdemScene s = make(sub);
    f(s);
    return s;
  };
  return w;
}
// Every material of a CDEM scene a quarter as stiff: c = sqrt(E / rho) halved.
void quarter_stiffness(dda::cdem::CdemScene& s) {
  for (dda::Material& m : s.materials) m.young /= 4.0;
}
// Block j (index 1) fixed: a wall that takes the momentum, block i bounces back.
template <class SceneT>
void fix_j(SceneT& s) {
  s.blocks[1].fixed = true;
}
template <class SceneT>
void j_twice_as_dense(SceneT& s) {
  controls::make_j_denser(s, 2.0);
}
}  // namespace

// --- A against B on the squares, every model at the base dt --------------------------
TEST_CASE("B-7 touch: FAIL against a wrong time of impact", "[controls][B-7]") {
  compare::SceneDef d = scene_def("squares");
  const Runs ok = base_runs(d);
  CHECK(compare::touch_ok(ok.a, ok.b, ok.b0));
  d.t_touch_exact = 0.45;  // s: the reference of a 0.45 m gap; the scene's is 0.5 m
  const Runs wrong = base_runs(d);
  CHECK_FALSE(compare::touch_ok(wrong.a, wrong.b, wrong.b0));
}

TEST_CASE("B-7 momentum: FAIL with block j fixed", "[controls][B-7]") {
  const compare::SceneDef d = scene_def("squares");
  const Runs wrong = base_runs(with_cdem(with_dda(d, fix_j<dda::Scene>), fix_j<dda::cdem::CdemScene>));
  CHECK_FALSE(compare::momentum_ok(wrong.a, wrong.b, wrong.b0));
}

TEST_CASE("B-7 exchange: FAIL with block j twice as dense", "[controls][B-7]") {
  const compare::SceneDef d = scene_def("squares");
  const Runs ok = base_runs(d);
  CHECK(compare::exchange_ok(ok.a.front(), ok.b.front()));
  const Runs wrong =
      base_runs(with_cdem(with_dda(d, j_twice_as_dense<dda::Scene>), j_twice_as_dense<dda::cdem::CdemScene>));
  CHECK_FALSE(compare::exchange_ok(wrong.a.front(), wrong.b.front()));
}

// --- A against B: one run per model at the base dt ------------------------------------
TEST_CASE(compare::kTestEnergy, "[controls][B-7]") {
  for (const std::string name : {"prisms", "squares"}) {
    INFO(name);
    const compare::SceneDef d = scene_def(name);
    const compare::Result b = base_run(d, "B");
    CHECK(compare::energy_ok(base_run(d, "A"), b));
    // Mass damping 1/s in A's blocks: A loses 78 % (prisms) / 86 % (squares)
    // of E0, far more than B's 1.1 % / 1.6 %.
    const compare::SceneDef damped = with_dda(d, [](dda::Scene& s) { s.damping.mass = 1.0; });
    CHECK_FALSE(compare::energy_ok(base_run(damped, "A"), b));
  }
}

TEST_CASE(compare::kTestPrismsDuration, "[controls][B-7]") {
  const compare::SceneDef d = scene_def("prisms");
  const compare::Result a = base_run(d, "A"), b = base_run(d, "B");
  CHECK(compare::prisms_duration_ok(a, b));  // A 0.21 s, B 6.7 ms
  // B's prisms a quarter as stiff: the wave takes twice as long, the clone
  // holds 13.3 ms (the window is 7.2 +- 2 ms).
  CHECK_FALSE(compare::prisms_duration_ok(a, base_run(with_cdem(d, quarter_stiffness), "B")));
  // A's kn 10^4 times stiffer (4e12 Pa): A's contact lasts 10 ms, less
  // than 3 x B's 6.7 ms.
  const compare::SceneDef stiff = with_dda(d, [](dda::Scene& s) { s.contact.kn *= 1e4; });
  CHECK_FALSE(compare::prisms_duration_ok(base_run(stiff, "A"), b));
}

TEST_CASE(compare::kTestSquaresDuration, "[controls][B-7]") {
  const compare::SceneDef d = scene_def("squares");
  const double t_ref = compare::squares_wave_time();  // 2.83 ms
  const compare::Result a = base_run(d, "A");
  CHECK(compare::squares_duration_ok(a, base_run(d, "B"), t_ref));  // B 2.97 ms, A 22 ms
  // B's squares a quarter as stiff: B's contact lasts 5.9 ms, twice 2 L / c
  // of the paper's material.
  CHECK_FALSE(compare::squares_duration_ok(a, base_run(with_cdem(d, quarter_stiffness), "B"), t_ref));
}

TEST_CASE(compare::kTestKn, "[controls][B-7]") {
  const compare::SceneDef d = scene_def("prisms");
  const std::vector<double> factors = {1.0, 10.0, 100.0};
  CHECK(compare::kn_dependence_ok(compare::kn_sweep(d, factors), d.v0));
  // Block j twice as dense: A leaves j at 2 m / (m + M) v0 = 2 m/s at every
  // kn, not the exchanged 3 m/s.
  const compare::SceneDef dense = with_dda(d, j_twice_as_dense<dda::Scene>);
  CHECK_FALSE(compare::kn_dependence_ok(compare::kn_sweep(dense, factors), d.v0));
}

// --- The node-to-edge penalty baseline P, on the prisms (runs of milliseconds) --------
TEST_CASE(compare::kTestPenaltyTouch, "[controls][B-7][P]") {
  compare::SceneDef d = scene_def("prisms");
  CHECK(compare::penalty_touch_ok(compare::penalty_sweep(d, nullptr, true), d.t_touch_exact));
  // The reference of a 0.9 m gap (0.3 s), the scene's is 1 m: P is 33 ms
  // (67 steps) late against it.
  d.t_touch_exact = 0.9 / d.v0;
  CHECK_FALSE(compare::penalty_touch_ok(compare::penalty_sweep(d, nullptr, true), d.t_touch_exact));
  // The reference of a 1.1 m gap: P would touch before it.
  d.t_touch_exact = 1.1 / d.v0;
  CHECK_FALSE(compare::penalty_touch_ok(compare::penalty_sweep(d, nullptr, true), d.t_touch_exact));
}

TEST_CASE(compare::kTestPenaltyMomentum, "[controls][B-7][P]") {
  const compare::SceneDef d = scene_def("prisms");
  CHECK(compare::penalty_momentum_ok(compare::penalty_sweep(d, nullptr, true)));
  const compare::SceneDef fixed = with_cdem(d, fix_j<dda::cdem::CdemScene>);
  CHECK_FALSE(compare::penalty_momentum_ok(compare::penalty_sweep(fixed, nullptr, true)));
}

TEST_CASE(compare::kTestPenaltyStability, "[controls][B-7][P]") {
  const compare::SceneDef d = scene_def("prisms");
  const compare::StabilityProbe p = compare::probe_stability(d, compare::kStiffKnFactor, 0.1);
  CAPTURE(p.dt_pred, p.dt_mesh, p.dt_stable, p.dt_unstable, p.failure);
  CHECK(compare::stability_prediction_ok(p, p.dt_pred));
  // The mesh's critical step alone (7.4e-4 s) ignores the spring of kn =
  // 100 E: the prisms blow up at 6e-5 s, far below it.
  CHECK_FALSE(compare::stability_prediction_ok(p, p.dt_mesh));
}
