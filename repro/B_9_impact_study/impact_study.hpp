// The impact study beyond Paper B (impact_study.cpp says what it runs):
// one oblique impact of two CST-meshed 1 m squares with Paper B's two-scale
// contact per cell (angle, speed, friction, subdivision), the measured
// quantities of a cell and the per-cell criteria of the rows, here so that
// the negative controls (controls.cpp beside this file) apply the
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

dda::Material paper_b_material();

// Mass per unit thickness and the rigid law's effective masses.
double block_mass();
double normal_mass();
double tangential_mass();

// Wave time 2 L / c of Paper B's material.
double wave_time();

std::vector<Vec2> square(double x0, double y0);

Vec2 impact_velocity(const Cell& c);

double gap_of(const Cell& c, double dt);

dda::cdem::CdemScene scene_of(const Cell& c, double dt = kDt);

// The initial boundary nodes of each block of `s` as model node ids, CCW
// (the model numbers each block's mesh nodes in mesh order, block by block).
std::vector<std::vector<int>> boundary_loops(const dda::cdem::CdemScene& s);

// Depth of p inside the closed polygon `poly` (crossing number): its distance
// to the polygon's boundary if inside, else 0.
double depth_in(Vec2 p, const std::vector<Vec2>& poly);

// Deepest node of any block inside another block's boundary-node outline.
double max_node_depth(const dda::cdem::Model& m, const std::vector<std::vector<int>>& loops);

// Spin of block b, rad/s: sum m (r x v) / sum m |r|^2 about its mean position.
double block_spin(const dda::cdem::Model& m, int b);

// The rigid law's J_t for a normal impulse jn and initial slip v_t0 (> 0).
double rigid_law_jt(double mu, double jn, double v_t0, bool* sticks = nullptr);

// Fills the results after the run from the model's state (shared by the
// finished and the stopped run: a stopped run reports what it reached).
void finish(CellResult& r, const dda::cdem::Model& m);

// One cell: the impact, checked every step. Never throws for a contact the
// solver cannot resolve: the cell's outcome carries the message.
CellResult run_cell(const Cell& c, double dt = kDt, const dda::cdem::CdemScene* scene_override = nullptr);

// ---- per-cell criteria (a stopped run fails every one) ----------------------------
// The run finished (the solver stops at a node deeper than d_tol), no node
// ended a step deeper than d_tol inside the other block's outline, and the
// centres stayed more than L / 2 apart in x.
bool no_pass_through(const CellResult& r);
bool energy_never_grows(const CellResult& r);
// Kinetic-energy series (J/m, KE0 first) never above its first value.
bool series_never_grows(const std::vector<double>& ke);
bool separates(const CellResult& r);
// The touches' measured loss within Eq. 5 of the clone groups they project
// (TouchRecord::energy_loss_eq5_group): a touch whose clone shares nodes
// with clones already formed projects them together (momentum conserved,
// every tie's relative velocity zero: Eq. 4 for the group), so its bound is
// the group's Eq. 5, 1/2 r^T (C M^-1 C^T)^+ r from the group's masses and
// velocities; for a lone clone it is the pair's Eq. 5. (A single pair's
// Eq. 5 does not bound a group's loss: the other ties' relative velocities
// are taken too.)
bool touch_loss_within_eq5(const CellResult& r);
// The run's whole loss within Eq. 5 for the two blocks (no loss beyond the
// kinetic energy of the relative motion).
bool total_loss_within_block_eq5(const CellResult& r);
bool obeys_coulomb(const CellResult& r);
bool matches_rigid_law(const CellResult& r);

// ---- the study's grid and rows ------------------------------------------------------
// Default grid: 210 cells (each well under a second: the
// whole grid is the default, no coarser one needed).
inline const std::vector<double> kAngles = {0.0, 15.0, 30.0, 45.0, 60.0, 75.0, 85.0};  // deg from the normal
inline const std::vector<double> kSpeeds = {0.1, 1.0, 5.0, 15.0, 30.0};                // m/s
inline const std::vector<double> kFrictions = {0.0, 0.3, 0.6};                         // mu = tan(phi)

std::vector<Cell> grid(bool coulomb = false);

// The grid's subdivision-on cells again with Sect. 5's sub-model
// (SubdivisionMode::kSubModel): the third subdivision value.
std::vector<Cell> submodel_grid();

std::string subdivision_name(const Cell& c);

std::string cell_name(const Cell& c);

// The negative controls in controls.cpp beside this file: their
// exact test-case names.
inline const char* const kTestPassThrough =
    "B-9 no pass-through: FAIL for a node 2 d_tol deep, crossed centres and a run started overlapping";
inline const char* const kTestEnergy = "B-9 kinetic energy: FAIL for a growing series and for dt above the critical step";
inline const char* const kTestSeparation = "B-9 separation: FAIL with clones of a large tensile strength and cohesion";
inline const char* const kTestTouchLoss = "B-9 touch loss: FAIL for a record whose loss exceeds Eq. 5";
inline const char* const kTestTotalLoss = "B-9 total loss: FAIL with strong mass damping";
inline const char* const kTestCoulomb = "B-9 Coulomb: FAIL for J_t above mu J_n";
inline const char* const kTestRigidLaw = "B-9 rigid law: FAIL for J_t off the stick/slide prediction";
// The sub-model cells' rows (controls.cpp beside this file).
inline const char* const kTestSubPassThrough =
    "B-9 sub-model no pass-through: FAIL for a sub-model run started 2 d_tol deep";
inline const char* const kTestSubEnergy = "B-9 sub-model kinetic energy: FAIL for dt above the critical step";
inline const char* const kTestSubSeparation =
    "B-9 sub-model separation: FAIL with clones of a large tensile strength and cohesion";
inline const char* const kTestSubTouchLoss = "B-9 sub-model touch loss: FAIL for a record whose loss exceeds Eq. 5";
inline const char* const kTestSubTotalLoss = "B-9 sub-model total loss: FAIL with strong mass damping";

// `cells`: the paper's method (every row); `option_cells`: the same grid with
// TouchImpact::kCoulomb, shown beside the Coulomb and rigid-law rows (none:
// no option rows).
std::vector<repro::Claim> rows(const std::vector<CellResult>& cells, const std::string& note = {},
                               const std::vector<CellResult>& option_cells = {});

// The rows of the sub-model cells (Paper B Sect. 5's sub-model, the grid's
// subdivision-on cells with SubdivisionMode::kSubModel), with the same
// per-cell criteria as the paper's rows above; the grid's 'on' cells (the
// in-place refinement, kInPlace, beyond the paper) are quoted beside.
std::vector<repro::Claim> submodel_rows(const std::vector<CellResult>& sub, const std::vector<CellResult>& cells,
                                        const std::string& note = {});

// The cost rows: the wall time of the paper's and the option's cells, and of
// the sub-model cells against the same cells with the in-place refinement.
std::vector<repro::Claim> cost_rows(const std::vector<CellResult>& results,
                                    const std::vector<CellResult>& option_results,
                                    const std::vector<CellResult>& submodel_results, double dt, const std::string& note);

}  // namespace impact
