// The impact study beyond Paper B (impact_study.cpp says what it runs):
// one oblique impact of two CST-meshed 1 m squares with Paper B's two-scale
// contact per cell (angle, speed, friction, subdivision), the measured
// quantities of a cell and the per-cell criteria of the rows, here so that
// the negative controls (repro/common/controls_impact_study.cpp) apply the
// same criteria to deliberately wrong configurations.
//
// Set-up: block A (left, x in [-1 - gap, -gap]) moves with speed v at the
// impact angle theta from the contact normal (+x): v_A = v (cos theta,
// sin theta); block B (x in [0, 1]) rests; both y in [-0.5, 0.5]. The
// faces are gap = v_n * kApproachSteps * dt apart (the touch falls inside
// the third step); the run lasts kWindowWaves elastic wave times 2 L / c
// after the touch.
//
// The rigid-body impact law used for comparison (Coulomb impact, 2D, two
// equal free rigid squares striking face to face): the resultant impulse
// acts at the centre of the common face (by symmetry; with it both blocks
// gain the same spin, which keeps the faces flush, and the normal impulse
// has no moment). Per unit thickness, m = rho L^2, I = m L^2 / 6, lever
// arm r = L / 2 from each centre to the face. Effective masses at the
// contact point: normal m_n = m / 2 (no rotation couples into it),
// tangential m_t = 1 / (2 (1/m + r^2/I)) = m / 5 (the tangential impulse
// spins both blocks). Normal impulse J_n = m_n (1 + e) v_n0 with the
// measured restitution e (the law takes e as given; the study compares the
// tangential part). Tangential: stick if mu J_n >= m_t v_t0 (the friction
// impulse suffices to stop the slip at the contact point): J_t = m_t v_t0;
// else slide: J_t = mu J_n. Decoupled normal and tangential directions (the
// normal impulse at the face centre has no moment), so the slip does not
// reverse and the simple (Newton/Coulomb) law is the exact rigid one.
#pragma once
#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "dda/cdem/mesh.hpp"
#include "dda/cdem/model.hpp"
#include "dda/cdem/scenes.hpp"
#include "repro/common/common.hpp"

namespace impact {

using dda::Vec2;

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kSide = 1.0;  // m, side L of both squares (the test_oblique set-up)
inline constexpr int kDivisions = 2;  // mesh divisions per square: 16 CST elements, face midpoints are nodes
// Time step, s: 0.28 of the 2-division squares' critical step with Paper
// B's material (7.1e-5 s, Model::critical_dt), ~25 steps in the contact
// (2 L / c = 0.52 ms) and v dt = 6e-4 m < d_tol at 30 m/s.
inline constexpr double kDt = 2e-5;
inline constexpr double kApproachSteps = 2.5;  // gap = v_n kApproachSteps dt: the touch falls inside step 3
inline constexpr double kWindowWaves = 8.0;    // run length after the touch, in wave times 2 L / c (~0.52 ms)

// ---- per-cell criteria tolerances -------------------------------------------------
// Kinetic energy growth, relative to KE0: the central-difference integrator
// conserves energy in free motion and the Eq. 4/10 projections only remove
// kinetic energy, so a growth beyond round-off of sums of ~1e3 terms is a
// fault (the slack of lib/cdem/tests/test_oblique.cpp).
inline constexpr double kEnergySlack = 1e-9;
// Coulomb: |J_t| <= mu J_n + kCoulombSlack J_n: 1 % of J_n, the shear force
// at a sliding clone is the limit of the force of the step before (one step
// of ~25 in the contact, explicit lag).
inline constexpr double kCoulombSlack = 0.01;
// Stick/slide law: |J_t / J_n - predicted| <= kLawTolerance (5 % of the
// normal impulse; the blocks are deformable, the law is rigid).
inline constexpr double kLawTolerance = 0.05;

struct Cell {
  double angle_deg = 0.0;  // impact angle from the contact normal, deg
  double speed = 1.0;      // m/s
  double mu = 0.0;         // friction coefficient tan(phi)
  bool subdivision = true;
  // CdemOptions::touch_impact = TouchImpact::kCoulomb (beyond the paper: the
  // touch's tangential impulse capped at mu times its normal impulse)
  bool coulomb = false;
  // With subdivision: Paper B Sect. 5's sub-model
  // (SubdivisionMode::kSubModel); false: the in-place refinement (kInPlace,
  // beyond the paper), set explicitly so that the study's 'on' cells do not
  // follow the library's default.
  bool submodel = false;
};

struct CellResult {
  Cell cell;
  bool ok = false;      // the run finished (no ContactError / SimulationError)
  std::string outcome;  // "ok" or the solver's stop message
  double wall = 0.0;    // s
  double gap = 0.0, t_end = 0.0;
  double tol = 0.0;             // m: the run's contact tolerance d_tol
  int touches = 0, separations = 0, slips = 0;
  double max_depth = 0.0;       // m: deepest node of one block inside the other's boundary-node outline, over the run
  double min_centre_dx = 0.0;   // m: B's mean x minus A's, smallest over the run
  bool pass_through = false;    // the run stopped, max_depth > d_tol or the centres closer than L / 2
  bool separated = false;       // no clone at the end and the normal gap opening
  double t_sep = -1.0;          // s: time the last clone was removed (-1: never)
  double ke0 = 0.0;             // J/m
  double ke_growth = 0.0;       // max over the steps of KE / KE0 - 1
  double total_growth = 0.0;    // max over the steps of (KE + strain) / KE0 - 1
  double touch_loss = 0.0, touch_loss_eq5 = 0.0;  // J/m: measured sum over touches, and Eq. 5 with the clone masses
  double touch_loss_eq5_group = 0.0;  // J/m: sum of the touches' group Eq. 5 (TouchRecord::energy_loss_eq5_group)
  double total_loss = 0.0;      // J/m: KE0 - (KE + strain) at the end
  double block_eq5 = 0.0;       // J/m: Eq. 5 for the two blocks, 0.5 (m/2) |v|^2 (all relative motion lost)
  double e = 0.0;               // normal restitution of the block-average velocities
  double jn = 0.0, jt = 0.0;    // N s/m: impulse on B (B's momentum at the end)
  double omega_a = 0.0, omega_b = 0.0;  // rad/s: block spins at the end
  double slip0 = 0.0, slip_end = 0.0;   // m/s: tangential relative velocity at the face centre before / after
  double jt_law = 0.0;          // N s/m: the rigid law's J_t with the measured J_n
  bool law_sticks = false;      // the rigid law's regime
};

inline dda::Material paper_b_material() { return dda::cdem::two_prisms_scene().materials.front(); }

// Mass per unit thickness and the rigid law's effective masses.
inline double block_mass() { return paper_b_material().density * kSide * kSide; }
inline double normal_mass() { return 0.5 * block_mass(); }
inline double tangential_mass() {
  const double m = block_mass(), inertia = m * kSide * kSide / 6.0, r = 0.5 * kSide;
  return 1.0 / (2.0 * (1.0 / m + r * r / inertia));
}

// Wave time 2 L / c of Paper B's material.
inline double wave_time() {
  const dda::Material mat = paper_b_material();
  return 2.0 * kSide / std::sqrt(mat.young / mat.density);
}

inline std::vector<Vec2> square(double x0, double y0) {
  return {{x0, y0}, {x0 + kSide, y0}, {x0 + kSide, y0 + kSide}, {x0, y0 + kSide}};
}

inline Vec2 impact_velocity(const Cell& c) {
  const double a = c.angle_deg * kPi / 180.0;
  return {c.speed * std::cos(a), c.speed * std::sin(a)};
}

inline double gap_of(const Cell& c, double dt) { return impact_velocity(c).x * kApproachSteps * dt; }

inline dda::cdem::CdemScene scene_of(const Cell& c, double dt = kDt) {
  dda::cdem::CdemScene s;
  s.name = "B-9 impact study";
  s.materials = {paper_b_material()};
  s.dt = dt;
  dda::cdem::CdemBlock a, b;
  a.outline = square(-kSide - gap_of(c, dt), -0.5 * kSide);
  a.divisions = kDivisions;
  a.velocity = impact_velocity(c);
  a.name = "A";
  b.outline = square(0.0, -0.5 * kSide);
  b.divisions = kDivisions;
  b.name = "B";
  s.blocks = {a, b};
  s.options.subdivision = c.subdivision;  // tolerance: Paper B's 5e-3 m (the default)
  s.options.subdivision_mode =
      c.submodel ? dda::cdem::SubdivisionMode::kSubModel : dda::cdem::SubdivisionMode::kInPlace;
  s.options.strength.friction_deg = std::atan(c.mu) * 180.0 / kPi;
  if (c.coulomb) s.options.touch_impact = dda::cdem::TouchImpact::kCoulomb;
  return s;
}

// The initial boundary nodes of each block of `s` as model node ids, CCW
// (the model numbers each block's mesh nodes in mesh order, block by block).
inline std::vector<std::vector<int>> boundary_loops(const dda::cdem::CdemScene& s) {
  std::vector<std::vector<int>> loops;
  int base = 0;
  for (const dda::cdem::CdemBlock& b : s.blocks) {
    const dda::cdem::TriMesh mesh = dda::cdem::mesh_convex_polygon(b.outline, b.divisions);
    std::vector<std::pair<double, int>> on;
    const std::size_t n = b.outline.size();
    for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
      for (std::size_t k = 0; k < n; ++k) {
        const Vec2 p = b.outline[k], q = b.outline[(k + 1) % n], d = q - p;
        const double len = dda::length(d), t = dda::dot(mesh.nodes[i] - p, d) / (len * len);
        if (std::fabs(dda::cross(d, mesh.nodes[i] - p)) / len < 1e-12 && t >= 0.0 && t < 1.0) {
          on.push_back({static_cast<double>(k) + t, base + static_cast<int>(i)});
          break;
        }
      }
    std::sort(on.begin(), on.end());
    std::vector<int> loop;
    for (const auto& e : on) loop.push_back(e.second);
    loops.push_back(loop);
    base += static_cast<int>(mesh.nodes.size());
  }
  return loops;
}

// Depth of p inside the closed polygon `poly` (crossing number): its distance
// to the polygon's boundary if inside, else 0.
inline double depth_in(Vec2 p, const std::vector<Vec2>& poly) {
  bool inside = false;
  double d = 1e300;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vec2 a = poly[j], b = poly[i];
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) inside = !inside;
    const Vec2 ab = b - a;
    const double t = std::clamp(dda::dot(p - a, ab) / dda::length_squared(ab), 0.0, 1.0);
    d = std::min(d, dda::length(p - (a + t * ab)));
  }
  return inside ? d : 0.0;
}

// Deepest node of any block inside another block's boundary-node outline.
inline double max_node_depth(const dda::cdem::Model& m, const std::vector<std::vector<int>>& loops) {
  std::vector<std::vector<Vec2>> polys;
  for (const auto& loop : loops) {
    std::vector<Vec2> p;
    for (int i : loop) p.push_back(m.node_position(i));
    polys.push_back(p);
  }
  double worst = 0.0;
  for (int i = 0; i < m.node_count(); ++i) {
    if (m.node_kind(i) == dda::cdem::NodeKind::kDead) continue;
    for (int b = 0; b < static_cast<int>(polys.size()); ++b)
      if (b != m.node_block(i)) worst = std::max(worst, depth_in(m.node_position(i), polys[b]));
  }
  return worst;
}

// Spin of block b, rad/s: sum m (r x v) / sum m |r|^2 about its mean position.
inline double block_spin(const dda::cdem::Model& m, int b) {
  const Vec2 c = m.block_mean_position(b);
  double l = 0.0, j = 0.0;
  for (int i = 0; i < m.node_count(); ++i) {
    if (m.node_block(i) != b || m.node_kind(i) == dda::cdem::NodeKind::kDead) continue;
    const Vec2 r = m.node_position(i) - c;
    l += m.node_mass(i) * dda::cross(r, m.node_velocity(i));
    j += m.node_mass(i) * dda::length_squared(r);
  }
  return j > 0.0 ? l / j : 0.0;
}

// The rigid law's J_t for a normal impulse jn and initial slip v_t0 (> 0).
inline double rigid_law_jt(double mu, double jn, double v_t0, bool* sticks = nullptr) {
  const double stick = tangential_mass() * v_t0;
  if (sticks) *sticks = mu * jn >= stick;
  return std::min(stick, mu * jn);
}

// Fills the results after the run from the model's state (shared by the
// finished and the stopped run: a stopped run reports what it reached).
inline void finish(CellResult& r, const dda::cdem::Model& m) {
  const dda::cdem::CdemEnergyAccount acc = m.energy_account();
  r.touches = static_cast<int>(m.touches().size());
  r.separations = static_cast<int>(m.separations().size());
  r.slips = static_cast<int>(m.slips().size());
  r.touch_loss = acc.touch_loss;
  r.touch_loss_eq5 = acc.touch_loss_eq5;
  r.touch_loss_eq5_group = acc.touch_loss_eq5_group;
  r.total_loss = r.ke0 - (acc.kinetic + acc.strain);
  const Vec2 v0 = impact_velocity(r.cell);
  r.block_eq5 = 0.5 * normal_mass() * dda::length_squared(v0);
  const Vec2 va = m.block_velocity(0), vb = m.block_velocity(1);
  r.e = v0.x > 0.0 ? -(va.x - vb.x) / v0.x : 0.0;
  r.jn = m.block_momentum(1).x;
  r.jt = m.block_momentum(1).y;
  r.omega_a = block_spin(m, 0);
  r.omega_b = block_spin(m, 1);
  r.slip0 = v0.y;
  r.slip_end = (va.y - vb.y) + 0.5 * kSide * (r.omega_a + r.omega_b);
  r.jt_law = rigid_law_jt(r.cell.mu, r.jn, r.slip0, &r.law_sticks);
  r.separated = r.ok && m.clones().empty() && vb.x - va.x > 0.0 && r.touches > 0;
}

// One cell: the impact, checked every step. Never throws for a contact the
// solver cannot resolve: the cell's outcome carries the message.
inline CellResult run_cell(const Cell& c, double dt = kDt, const dda::cdem::CdemScene* scene_override = nullptr) {
  const auto start = std::chrono::steady_clock::now();
  CellResult r;
  r.cell = c;
  const dda::cdem::CdemScene s = scene_override ? *scene_override : scene_of(c, dt);
  r.tol = s.options.tolerance;
  r.gap = gap_of(c, dt);
  const double vn = impact_velocity(c).x;
  r.t_end = r.gap / vn + kWindowWaves * wave_time();
  const auto loops = boundary_loops(s);
  dda::cdem::Model m(s);
  r.ke0 = m.energy().kinetic;
  r.min_centre_dx = m.block_mean_position(1).x - m.block_mean_position(0).x;
  bool in_contact = false;
  try {
    while (m.time() < r.t_end - 0.5 * m.dt()) {
      m.step();
      const dda::cdem::CdemEnergy e = m.energy();
      r.ke_growth = std::max(r.ke_growth, e.kinetic / r.ke0 - 1.0);
      r.total_growth = std::max(r.total_growth, (e.kinetic + e.strain) / r.ke0 - 1.0);
      r.max_depth = std::max(r.max_depth, max_node_depth(m, loops));
      r.min_centre_dx = std::min(r.min_centre_dx, m.block_mean_position(1).x - m.block_mean_position(0).x);
      const bool now = !m.clones().empty();
      if (in_contact && !now) r.t_sep = m.time();
      in_contact = now;
    }
    r.ok = true;
    r.outcome = "ok";
  } catch (const dda::SimulationError& err) {  // ContactError included
    r.ok = false;
    r.outcome = err.what();
  }
  finish(r, m);
  r.pass_through = !r.ok || r.max_depth > r.tol || r.min_centre_dx < 0.5 * kSide;
  r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

// ---- per-cell criteria (a stopped run fails every one) ----------------------------
// The run finished (the solver stops at a node deeper than d_tol), no node
// ended a step deeper than d_tol inside the other block's outline, and the
// centres stayed more than L / 2 apart in x.
inline bool no_pass_through(const CellResult& r) {
  return r.ok && r.max_depth <= r.tol && r.min_centre_dx >= 0.5 * kSide;
}
inline bool energy_never_grows(const CellResult& r) { return r.ok && r.ke_growth <= kEnergySlack; }
// Kinetic-energy series (J/m, KE0 first) never above its first value.
inline bool series_never_grows(const std::vector<double>& ke) {
  for (double k : ke)
    if (k > ke.front() * (1.0 + kEnergySlack)) return false;
  return true;
}
inline bool separates(const CellResult& r) { return r.ok && r.separated; }
// The touches' measured loss within Eq. 5 of the clone groups they project
// (TouchRecord::energy_loss_eq5_group): a touch whose clone shares nodes
// with clones already formed projects them together (momentum conserved,
// every tie's relative velocity zero: Eq. 4 for the group), so its bound is
// the group's Eq. 5, 1/2 r^T (C M^-1 C^T)^+ r from the group's masses and
// velocities; for a lone clone it is the pair's Eq. 5. (A single pair's
// Eq. 5 does not bound a group's loss: the other ties' relative velocities
// are taken too.)
inline bool touch_loss_within_eq5(const CellResult& r) {
  return r.ok && r.touch_loss >= -kEnergySlack * r.ke0 &&
         r.touch_loss <= r.touch_loss_eq5_group + kEnergySlack * r.ke0;
}
// The run's whole loss within Eq. 5 for the two blocks (no loss beyond the
// kinetic energy of the relative motion).
inline bool total_loss_within_block_eq5(const CellResult& r) {
  return r.ok && r.total_loss >= -kEnergySlack * r.ke0 && r.total_loss <= r.block_eq5 * (1.0 + kEnergySlack);
}
inline bool obeys_coulomb(const CellResult& r) {
  return r.ok && r.jn > 0.0 && std::fabs(r.jt) <= (r.cell.mu + kCoulombSlack) * r.jn;
}
inline bool matches_rigid_law(const CellResult& r) {
  return r.ok && r.jn > 0.0 && std::fabs(r.jt - r.jt_law) <= kLawTolerance * r.jn;
}

// ---- the study's grid and rows ------------------------------------------------------
// Default grid: 210 cells (each well under a second: the
// whole grid is the default, no coarser one needed).
inline const std::vector<double> kAngles = {0.0, 15.0, 30.0, 45.0, 60.0, 75.0, 85.0};  // deg from the normal
inline const std::vector<double> kSpeeds = {0.1, 1.0, 5.0, 15.0, 30.0};                // m/s
inline const std::vector<double> kFrictions = {0.0, 0.3, 0.6};                         // mu = tan(phi)

inline std::vector<Cell> grid(bool coulomb = false) {
  std::vector<Cell> cells;
  for (bool sub : {false, true})
    for (double mu : kFrictions)
      for (double v : kSpeeds)
        for (double a : kAngles) cells.push_back({a, v, mu, sub, coulomb});
  return cells;
}

// The grid's subdivision-on cells again with Sect. 5's sub-model
// (SubdivisionMode::kSubModel): the third subdivision value.
inline std::vector<Cell> submodel_grid() {
  std::vector<Cell> cells;
  for (double mu : kFrictions)
    for (double v : kSpeeds)
      for (double a : kAngles) cells.push_back({a, v, mu, true, false, true});
  return cells;
}

inline std::string subdivision_name(const Cell& c) {
  return !c.subdivision ? "off" : c.submodel ? "sub-model" : "on";
}

inline std::string cell_name(const Cell& c) {
  return "(" + repro::format_short(c.angle_deg) + " deg, " + repro::format_short(c.speed) + " m/s, mu " +
         repro::format_short(c.mu) + ", sub " + subdivision_name(c) + (c.coulomb ? ", Coulomb touch" : "") + ")";
}

// The negative controls in repro/common/controls_impact_study.cpp: their
// exact test-case names.
inline const char* const kTestPassThrough =
    "B-9 no pass-through: FAIL for a node 2 d_tol deep, crossed centres and a run started overlapping";
inline const char* const kTestEnergy = "B-9 kinetic energy: FAIL for a growing series and for dt above the critical step";
inline const char* const kTestSeparation = "B-9 separation: FAIL with clones of a large tensile strength and cohesion";
inline const char* const kTestTouchLoss = "B-9 touch loss: FAIL for a record whose loss exceeds Eq. 5";
inline const char* const kTestTotalLoss = "B-9 total loss: FAIL with strong mass damping";
inline const char* const kTestCoulomb = "B-9 Coulomb: FAIL for J_t above mu J_n";
inline const char* const kTestRigidLaw = "B-9 rigid law: FAIL for J_t off the stick/slide prediction";
// The sub-model cells' rows (repro/common/controls_submodel.cpp).
inline const char* const kTestSubPassThrough =
    "B-9 sub-model no pass-through: FAIL for a sub-model run started 2 d_tol deep";
inline const char* const kTestSubEnergy = "B-9 sub-model kinetic energy: FAIL for dt above the critical step";
inline const char* const kTestSubSeparation =
    "B-9 sub-model separation: FAIL with clones of a large tensile strength and cohesion";
inline const char* const kTestSubTouchLoss = "B-9 sub-model touch loss: FAIL for a record whose loss exceeds Eq. 5";
inline const char* const kTestSubTotalLoss = "B-9 sub-model total loss: FAIL with strong mass damping";

// Cells failing `ok`, as "n of N" and a list (the first `shown`, with a
// detail per cell).
struct Tally {
  int pass = 0, total = 0;
  std::string failing;
};
template <class Pred, class Detail>
Tally tally(const std::vector<CellResult>& cells, Pred ok, Detail detail, int shown = 8) {
  Tally t;
  int listed = 0;
  for (const CellResult& r : cells) {
    ++t.total;
    if (ok(r)) {
      ++t.pass;
      continue;
    }
    if (listed < shown) t.failing += (listed ? "; " : "") + cell_name(r.cell) + " " + detail(r);
    ++listed;
  }
  if (listed > shown) t.failing += "; and " + std::to_string(listed - shown) + " more";
  return t;
}
inline std::string count_text(const Tally& t) {
  return std::to_string(t.pass) + " of " + std::to_string(t.total) + " cells" +
         (t.failing.empty() ? std::string() : "; failing: " + t.failing);
}
inline std::string stopped_or(const CellResult& r, const std::string& text) {
  return r.ok ? text : "stopped: " + r.outcome.substr(0, 90);
}

// Minimum, median and maximum of f over the cells that finished and pass `keep`.
template <class F, class Keep>
std::string stats(const std::vector<CellResult>& cells, F f, Keep keep) {
  std::vector<double> v;
  for (const CellResult& r : cells)
    if (r.ok && keep(r)) v.push_back(f(r));
  if (v.empty()) return "no cell";
  std::sort(v.begin(), v.end());
  return "min " + repro::format_short(v.front(), 3) + ", median " + repro::format_short(v[v.size() / 2], 3) +
         ", max " + repro::format_short(v.back(), 3) + " (" + std::to_string(v.size()) + " cells)";
}

// `cells`: the paper's method (every row); `option_cells`: the same grid with
// TouchImpact::kCoulomb, shown beside the Coulomb and rigid-law rows (none:
// no option rows).
inline std::vector<repro::Claim> rows(const std::vector<CellResult>& cells, const std::string& note = {},
                                      const std::vector<CellResult>& option_cells = {}) {
  using repro::format_short;
  std::vector<repro::Claim> out;
  const std::string grid_text = std::to_string(cells.size()) + " cells (angle x speed x friction x subdivision)" + note;
  auto add = [&](const std::string& key, const std::string& claim, const std::string& paper, const Tally& t,
                 const std::string& extra, const std::string& tol, const char* test) {
    out.push_back({"B-9", claim, paper, count_text(t) + (extra.empty() ? "" : "; " + extra) + "; " + grid_text, tol,
                   t.pass == t.total && t.total > 0});
    out.back().key = key;
    out.back().control = repro::control_test(test);
  };
  const auto stop_cause = [&](repro::Claim& c) {
    repro::explain_fail(c, repro::Root::kUnexplained,
                        "in the failing cells the contact with friction creates energy (the touches' measured loss "
                        "far above the run's loss: the energy account's remainder is a gain), and some runs grow until "
                        "an element inverts or a node ends deeper than d_tol and the solver stops; the cells affected "
                        "change erratically with dt. Paper B's method cannot add energy (Eq. 4 removes it, central "
                        "differences below the critical step conserve it): the fault is in our clone/sliding "
                        "implementation");
  };

  add("no-pass-through", "no pass-through in any cell of the impact study", "not in the paper: no pass-through in any cell",
      tally(cells, no_pass_through,
            [](const CellResult& r) {
              return stopped_or(r, "depth " + format_short(r.max_depth, 3) + " m, centres " +
                                       format_short(r.min_centre_dx, 4) + " m apart");
            }),
      "deepest node over the finished cells " +
          stats(cells, [](const CellResult& r) { return r.max_depth; }, [](const CellResult&) { return true; }) +
          " m",
      "per cell: the run finishes (a node deeper than d_tol stops it), no node ends a step deeper than d_tol = 5e-3 m "
      "inside the other block's boundary-node outline, centres > L/2 apart",
      kTestPassThrough);
  stop_cause(out.back());

  add("kinetic-energy", "kinetic energy never grows in any cell", "not in the paper: kinetic energy never grows",
      tally(cells, energy_never_grows,
            [](const CellResult& r) { return "max KE/KE0 - 1 = " + format_short(r.ke_growth, 3) + (r.ok ? "" : ", stopped"); }),
      "max KE/KE0 - 1 over the finished cells " +
          stats(cells, [](const CellResult& r) { return r.ke_growth; }, [](const CellResult&) { return true; }) +
          "; of KE + strain " +
          stats(cells, [](const CellResult& r) { return r.total_growth; }, [](const CellResult&) { return true; }),
      "per cell: the run finishes and KE(t) <= KE0 (1 + 1e-9) at every step (central differences conserve energy in "
      "free motion, the clone projections only remove it: round-off slack)",
      kTestEnergy);
  stop_cause(out.back());

  add("separation", "the blocks separate in every cell (no cohesion or tensile strength holds them)",
      "not in the paper: the blocks separate (when friction allows)",
      tally(cells, separates,
            [](const CellResult& r) { return stopped_or(r, r.separated ? "separated" : "still tied or closing"); }),
      "last clone released at " +
          stats(cells, [](const CellResult& r) { return r.t_sep * 1e3; }, [](const CellResult& r) { return r.t_sep >= 0.0; }) +
          " ms",
      "per cell: at the end (8 wave times 2L/c after the touch) no clone is left and B moves away from A in x "
      "(friction without cohesion never holds: Eq. 6 with sigma_t = 0)",
      kTestSeparation);
  stop_cause(out.back());

  add("touch-loss-eq5", "the touches' measured loss stays within Eq. 5 of the clones they project",
      "Paper B Eq. 5: the loss of a clone's perfectly inelastic impact, 1/2 m_m m_t / (m_m + m_t) |v_m - v_t|^2; for "
      "a group of clones sharing nodes (projected together) the group's Eq. 5, 1/2 r^T (C M^-1 C^T)^+ r",
      tally(cells, touch_loss_within_eq5,
            [](const CellResult& r) {
              return stopped_or(r, "measured/group Eq. 5 - 1 = " +
                                       format_short(r.touch_loss / r.touch_loss_eq5_group - 1.0, 3));
            }),
      "measured / group Eq. 5 over the finished cells " +
          stats(cells,
                [](const CellResult& r) {
                  return r.touch_loss_eq5_group > 0 ? r.touch_loss / r.touch_loss_eq5_group : 1.0;
                },
                [](const CellResult&) { return true; }) +
          "; measured / the new pairs' own Eq. 5 (not a bound for a group) " +
          stats(cells, [](const CellResult& r) { return r.touch_loss_eq5 > 0 ? r.touch_loss / r.touch_loss_eq5 : 1.0; },
                [](const CellResult&) { return true; }),
      "per cell: 0 <= sum of the touches' measured kinetic-energy drops <= sum of their group Eq. 5 values (+1e-9 "
      "KE0). The group projection is Eq. 4 for several ties (momentum conserved, every tie inelastic), so its Eq. 5 "
      "is the group's; a single pair's Eq. 5 leaves out the other ties' relative velocities the group takes",
      kTestTouchLoss);
  repro::explain_fail(out.back(), repro::Root::kUnexplained,
                      "a touch's measured drop exceeds the Eq. 5 of the clone group it projects: the group "
                      "projection (Gauss-Seidel) did not reach the group's perfectly inelastic "
                      "state, or energy entered in it");

  add("total-loss-eq5", "the run's energy loss stays within Eq. 5 for the two blocks",
      "Eq. 5 applied to the blocks: a perfectly inelastic block impact loses 1/2 (m/2) |v|^2, the most any impact can",
      tally(cells, total_loss_within_block_eq5,
            [](const CellResult& r) {
              return stopped_or(r, "loss / block Eq. 5 = " + format_short(r.total_loss / r.block_eq5, 4));
            }),
      "loss / block Eq. 5 over the finished cells " +
          stats(cells, [](const CellResult& r) { return r.total_loss / r.block_eq5; }, [](const CellResult&) { return true; }),
      "per cell: 0 <= KE0 - (KE + strain)_end <= 1/2 (m/2) |v0|^2 (1 + 1e-9)", kTestTotalLoss);
  stop_cause(out.back());

  add("coulomb", "the tangential impulse obeys Coulomb's limit in every cell",
      "not in the paper: the rigid-body Coulomb impact law, |J_t| <= mu J_n",
      tally(cells, obeys_coulomb,
            [](const CellResult& r) { return stopped_or(r, "J_t/J_n = " + format_short(r.jt / r.jn, 3)); }, 6),
      "J_t/J_n - mu over the finished cells " +
          stats(cells, [](const CellResult& r) { return r.jt / r.jn - r.cell.mu; }, [](const CellResult&) { return true; }) +
          "; at mu = 0, |J_t|/J_n " +
          stats(cells, [](const CellResult& r) { return std::fabs(r.jt / r.jn); }, [](const CellResult& r) { return r.cell.mu == 0.0 && r.cell.angle_deg > 0.0; }),
      "per cell: |J_t| <= (mu + 0.01) J_n (J from B's momentum at the end; 1 % for the explicit lag of the sliding "
      "clone's shear force)",
      kTestCoulomb);
  repro::explain_fail(out.back(), repro::Root::kCloneImpact,
                      "Paper B Sect. 4.1 forms each clone by a perfectly inelastic impact of the two contact points "
                      "(Eq. 4, 'no slipping occurs' in the touch step): it takes the points' whole relative "
                      "velocity, tangential included, whatever phi is; only afterwards does the Mohr-Coulomb limit "
                      "(Eqs. 7-10) cap the clone's shear force. The formation impulses are not limited by mu J_n "
                      "(at mu = 0 J_t is not 0). A stopped run fails this row too (see the pass-through row)");
  const std::string option_grid = std::to_string(option_cells.size()) +
                                  " cells (the same grid with the Coulomb touch option)" + note;
  auto add_option = [&](const std::string& key, const std::string& claim, const std::string& paper, const Tally& t,
                        const std::string& extra, const std::string& tol, const char* test) {
    out.push_back({"B-9", claim, paper, count_text(t) + (extra.empty() ? "" : "; " + extra) + "; " + option_grid, tol,
                   t.pass == t.total && t.total > 0});
    out.back().key = key;
    out.back().control = repro::control_test(test);
    out.back().scope = repro::Scope::kOption;
  };
  if (!option_cells.empty()) {
    add_option("coulomb-option",
               "(Coulomb touch option, beyond the paper) the tangential impulse obeys Coulomb's limit in every cell",
               "not in the paper: the rigid-body Coulomb impact law, |J_t| <= mu J_n; the option caps each touch's "
               "tangential impulse at mu times its normal impulse",
               tally(option_cells, obeys_coulomb,
                     [](const CellResult& r) { return stopped_or(r, "J_t/J_n = " + format_short(r.jt / r.jn, 3)); }, 6),
               "J_t/J_n - mu over the finished cells " +
                   stats(option_cells, [](const CellResult& r) { return r.jt / r.jn - r.cell.mu; },
                         [](const CellResult&) { return true; }) +
                   "; at mu = 0, |J_t|/J_n " +
                   stats(option_cells, [](const CellResult& r) { return std::fabs(r.jt / r.jn); },
                         [](const CellResult& r) { return r.cell.mu == 0.0 && r.cell.angle_deg > 0.0; }) +
                   "; the option's cells also: no pass-through " +
                   std::to_string(tally(option_cells, no_pass_through, [](const CellResult&) { return ""; }).pass) +
                   ", KE never grows " +
                   std::to_string(tally(option_cells, energy_never_grows, [](const CellResult&) { return ""; }).pass) +
                   ", separate " +
                   std::to_string(tally(option_cells, separates, [](const CellResult&) { return ""; }).pass) +
                   ", touch loss within group Eq. 5 " +
                   std::to_string(tally(option_cells, touch_loss_within_eq5, [](const CellResult&) { return ""; }).pass) +
                   " of " + std::to_string(option_cells.size()),
               "per cell: |J_t| <= (mu + 0.01) J_n, as the paper's row", kTestCoulomb);
    repro::explain_fail(out.back(), repro::Root::kCornerNormal,
                        "with the Coulomb touch each touch's impulse obeys mu J_n along the clone's normal, but the "
                        "squares' corners are level (A's lower right corner meets B's lower left one): a corner "
                        "arriving within d_tol of the other block's corner is tied to the perpendicular face, whose "
                        "normal is tangential to the impact face, so its normal impulses are J_t for the blocks "
                        "(measured in (85 deg, 1 m/s, mu 0, sub off): A's corner node touches B's bottom face again "
                        "every two steps, J_n 7-63 N s/m each along y, J_t/J_n 4.24). The contact normal at a "
                        "corner-to-corner touch is our node-to-edge choice, not fixed by the option");
  }

  add("rigid-law", "the tangential impulse matches the rigid-body stick/slide law in every cell",
      "not in the paper: the rigid-body Coulomb impact law, stick if mu J_n >= m_t v_t0 (J_t = m_t v_t0, m_t = m/5 with the "
      "spin), else slide (J_t = mu J_n)",
      tally(cells, matches_rigid_law,
            [](const CellResult& r) {
              return stopped_or(r, "J_t/J_n = " + format_short(r.jt / r.jn, 3) + " vs law " +
                                       format_short(r.jt_law / r.jn, 3) + (r.law_sticks ? " (stick)" : " (slide)"));
            }, 6),
      "(J_t - J_t,law)/J_n over the finished cells " +
          stats(cells, [](const CellResult& r) { return (r.jt - r.jt_law) / r.jn; }, [](const CellResult&) { return true; }),
      "per cell: |J_t - J_t,law| <= 0.05 J_n with the measured J_n and restitution", kTestRigidLaw);
  repro::explain_fail(out.back(), repro::Root::kCloneImpact,
                      "the clone formation of Eq. 4 takes the tangential relative velocity of every touching node "
                      "pair (see the Coulomb row), so the tangential impulse follows the number and masses of the "
                      "touches, not mu: above the law's value in sliding cells (mu = 0 included) and off it in "
                      "sticking ones (the deformable blocks' spin differs from the rigid face-centre impulse too)");
  if (!option_cells.empty()) {
    add_option("rigid-law-option",
               "(Coulomb touch option, beyond the paper) the tangential impulse matches the rigid-body stick/slide "
               "law in every cell",
               "not in the paper: the rigid-body Coulomb impact law, as the row of the paper's method",
               tally(option_cells, matches_rigid_law,
                     [](const CellResult& r) {
                       return stopped_or(r, "J_t/J_n = " + format_short(r.jt / r.jn, 3) + " vs law " +
                                                format_short(r.jt_law / r.jn, 3) +
                                                (r.law_sticks ? " (stick)" : " (slide)"));
                     }, 6),
               "(J_t - J_t,law)/J_n over the finished cells " +
                   stats(option_cells, [](const CellResult& r) { return (r.jt - r.jt_law) / r.jn; },
                         [](const CellResult&) { return true; }),
               "per cell: |J_t - J_t,law| <= 0.05 J_n with the measured J_n and restitution", kTestRigidLaw);
    repro::explain_fail(out.back(), repro::Root::kCornerNormal,
                        "the cells failing the option's Coulomb row (corner-to-corner touches on the perpendicular "
                        "face, see there) fail this row too; the others are deformable CST meshes touching node by "
                        "node, whose stick regime's J_t differs from the rigid law's m_t v_t0 (m_t = m/5 with the "
                        "rigid spin) by more than 5 % of J_n");
  }

  const auto sub_on = [](const CellResult& r) { return r.cell.subdivision; };
  const auto sub_off = [](const CellResult& r) { return !r.cell.subdivision; };
  const auto e_of = [](const CellResult& r) { return r.e; };
  out.push_back(repro::measurement(
      "B-9", "normal restitution of the block-average velocities over the impact study",
      "Paper B: the clone impact is perfectly inelastic at the contact points; the blocks rebound by their elastic "
      "waves (no restitution parameter)",
      "e = -(v_n after)/(v_n before): subdivision off " + stats(cells, e_of, sub_off) + "; on " +
          stats(cells, e_of, sub_on) + "; head-on cells, off " +
          stats(cells, e_of, [](const CellResult& r) { return !r.cell.subdivision && r.cell.angle_deg == 0.0; }) +
          ", on " + stats(cells, e_of, [](const CellResult& r) { return r.cell.subdivision && r.cell.angle_deg == 0.0; }) +
          "; " + grid_text,
      "the model's restitution: set by the clone masses (subdivision makes them small) and the mesh, not an input"));
  out.back().key = "restitution";
  const auto loss_ratio = [](const CellResult& r) { return r.total_loss / r.block_eq5; };
  const auto touch_share = [](const CellResult& r) { return r.total_loss > 0 ? r.touch_loss / r.total_loss : 0.0; };
  out.push_back(repro::measurement(
      "B-9", "energy loss against Eq. 5 for the two blocks over the impact study",
      "Eq. 5: the loss falls with the contact-point mass (subdivision)",
      "loss / block Eq. 5: subdivision off " + stats(cells, loss_ratio, sub_off) + "; on " +
          stats(cells, loss_ratio, sub_on) + "; the touches' share of the loss: off " + stats(cells, touch_share, sub_off) +
          ", on " + stats(cells, touch_share, sub_on) + "; " + grid_text,
      "where the energy goes (the rest: patch remaps, friction work at sliding clones, integration)"));
  out.back().key = "loss-ratio";
  return out;
}

// The rows of the sub-model cells (Paper B Sect. 5's sub-model, the grid's
// subdivision-on cells with SubdivisionMode::kSubModel), with the same
// per-cell criteria as the paper's rows above; the grid's 'on' cells (the
// in-place refinement, kInPlace, beyond the paper) are quoted beside.
inline std::vector<repro::Claim> submodel_rows(const std::vector<CellResult>& sub, const std::vector<CellResult>& cells,
                                               const std::string& note = {}) {
  using repro::format_short;
  std::vector<repro::Claim> out;
  std::vector<CellResult> inplace;
  for (const CellResult& r : cells)
    if (r.cell.subdivision && !r.cell.submodel) inplace.push_back(r);
  const std::string grid_text = std::to_string(sub.size()) +
                                " cells (the grid's subdivision-on cells with Sect. 5's sub-model)" + note;
  auto add = [&](const std::string& key, const std::string& claim, const std::string& paper, const Tally& t,
                 const Tally& beside, const std::string& extra, const std::string& tol, const char* test) {
    out.push_back({"B-9", claim, paper,
                   count_text(t) + (extra.empty() ? "" : "; " + extra) + "; in-place refinement (beyond the paper) " +
                       std::to_string(beside.pass) + " of " + std::to_string(beside.total) + "; " + grid_text,
                   tol, t.pass == t.total && t.total > 0});
    out.back().key = key;
    out.back().control = repro::control_test(test);
  };
  const auto none = [](const CellResult&) { return std::string(); };
  const auto all = [](const CellResult&) { return true; };
  add("submodel-no-pass-through", "(Sect. 5's sub-model, our reading) no pass-through in any cell of the impact study",
      "not in the paper: no pass-through in any cell",
      tally(sub, no_pass_through,
            [](const CellResult& r) {
              return stopped_or(r, "depth " + format_short(r.max_depth, 3) + " m, centres " +
                                       format_short(r.min_centre_dx, 4) + " m apart");
            }),
      tally(inplace, no_pass_through, none),
      "deepest node " + stats(sub, [](const CellResult& r) { return r.max_depth; }, all) + " m",
      "per cell, as the paper's row: the run finishes, no node deeper than d_tol, centres > L/2 apart",
      kTestSubPassThrough);
  add("submodel-kinetic-energy", "(Sect. 5's sub-model, our reading) kinetic energy never grows in any cell",
      "not in the paper: kinetic energy never grows",
      tally(sub, energy_never_grows,
            [](const CellResult& r) { return "max KE/KE0 - 1 = " + format_short(r.ke_growth, 3) + (r.ok ? "" : ", stopped"); }),
      tally(inplace, energy_never_grows, none),
      "max KE/KE0 - 1 " + stats(sub, [](const CellResult& r) { return r.ke_growth; }, all) + "; of KE + strain " +
          stats(sub, [](const CellResult& r) { return r.total_growth; }, all),
      "per cell, as the paper's row: KE(t) <= KE0 (1 + 1e-9) at every step", kTestSubEnergy);
  add("submodel-separation", "(Sect. 5's sub-model, our reading) the blocks separate in every cell",
      "not in the paper: the blocks separate (when friction allows)",
      tally(sub, separates,
            [](const CellResult& r) { return stopped_or(r, r.separated ? "separated" : "still tied or closing"); }),
      tally(inplace, separates, none),
      "last clone released at " +
          stats(sub, [](const CellResult& r) { return r.t_sep * 1e3; }, [](const CellResult& r) { return r.t_sep >= 0.0; }) +
          " ms",
      "per cell, as the paper's row: no clone left at the end and B moving away from A in x", kTestSubSeparation);
  {
    // Attached on FAIL only, with the run's numbers: the same cells with the
    // in-place refinement (beside) and without subdivision.
    const Tally beside = tally(inplace, separates, none);
    repro::explain_fail(out.back(), repro::Root::kSubModelReading,
                        "the sub-model of Sect. 5 as we read its steps (1)-(5) changes the blocks' relative motion "
                        "while it lives; the contact re-touches and a clone formed late is still tied at the end of "
                        "the window; the same grid separates in " + std::to_string(beside.pass) + " of " +
                        std::to_string(beside.total) + " cells with the in-place refinement");
  }
  add("submodel-touch-loss-eq5", "(Sect. 5's sub-model, our reading) the touches' measured loss stays within Eq. 5",
      "Paper B Eq. 5 (the clones are between coarse nodes: Eq. 5 with the coarse masses)",
      tally(sub, touch_loss_within_eq5,
            [](const CellResult& r) {
              return stopped_or(r, "measured/group Eq. 5 - 1 = " +
                                       format_short(r.touch_loss / r.touch_loss_eq5_group - 1.0, 3));
            }),
      tally(inplace, touch_loss_within_eq5, none), "",
      "per cell, as the paper's row: 0 <= measured <= group Eq. 5 (+1e-9 KE0)", kTestSubTouchLoss);
  add("submodel-total-loss-eq5",
      "(Sect. 5's sub-model, our reading) the run's energy loss stays within Eq. 5 for the two blocks",
      "Eq. 5 applied to the blocks: a perfectly inelastic block impact loses 1/2 (m/2) |v|^2, the most any impact can",
      tally(sub, total_loss_within_block_eq5,
            [](const CellResult& r) {
              return stopped_or(r, "loss / block Eq. 5 = " + format_short(r.total_loss / r.block_eq5, 4));
            }),
      tally(inplace, total_loss_within_block_eq5, none),
      "loss / block Eq. 5 " + stats(sub, [](const CellResult& r) { return r.total_loss / r.block_eq5; }, all),
      "per cell, as the paper's row: 0 <= KE0 - (KE + strain)_end <= 1/2 (m/2) |v0|^2 (1 + 1e-9)", kTestSubTotalLoss);
  out.push_back(repro::measurement(
      "B-9", "(Sect. 5's sub-model, our reading) restitution and energy loss against the in-place refinement",
      "Paper B: the clone impact is perfectly inelastic at the contact points",
      "e: sub-model " + stats(sub, [](const CellResult& r) { return r.e; }, all) + ", in-place " +
          stats(inplace, [](const CellResult& r) { return r.e; }, all) + "; loss / block Eq. 5: sub-model " +
          stats(sub, [](const CellResult& r) { return r.total_loss / r.block_eq5; }, all) + ", in-place " +
          stats(inplace, [](const CellResult& r) { return r.total_loss / r.block_eq5; }, all) + "; " + grid_text,
      "the sub-model's clones are between coarse nodes (coarse masses in Eq. 5), the in-place patch's between "
      "patch nodes"));
  out.back().key = "submodel-restitution-loss";
  return out;
}

}  // namespace impact
