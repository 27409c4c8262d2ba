// Paper B's two-scale contact model on node-based deformable blocks: a
// compact CDEM-style body model beside the 6-DOF DDA block (dda::Simulation).
//
// Bodies (Paper B Sect. 2): each block is a mesh of constant-strain
// triangles with lumped nodal masses, integrated by explicit central
// differences (Eq. 1, M u'' + C u' = F + P, C = alpha M) in kick-drift-kick
// form; element forces come from the strain matrix B of the current
// configuration, incrementally (Eqs. 2-3): d_eps = B d_u, d_sigma = D d_eps,
// sigma += d_sigma (rotated with the element's incremental rotation),
// F = -A B^T sigma.
//
// Contact, without any penalty spring:
//  * detection (Sect. 2, 2D): boundary nodes of one block against boundary
//    edges of another; a pair is a candidate when the node ends the step
//    closer to the edge than the contact tolerance d_tol;
//  * two time stages (Sect. 3): the touch time on the collision path (the
//    relative node-edge motion over the step, solved exactly) splits the step
//    into dt1 (free motion) and dt2 (contact);
//  * clone node (Sect. 4): the touching node and the touched point become one
//    node (summed mass and force; for a point inside an edge the edge's
//    nodes share it with their linear weights), its velocity set by
//    perfectly inelastic momentum conservation (Eq. 4, energy loss Eq. 5);
//    the interaction force (Eq. 11) is checked against the tensile limit
//    (Eq. 6) and the Mohr-Coulomb shear limit (Eqs. 7-10) for separation;
//  * local subdivision (Sect. 5), two modes (CdemOptions::subdivision_mode):
//    - kSubModel (the default), Sect. 5 as written (steps 1-5, Eq. 12; model_submodel.cpp):
//      the coarse model stays as it is (contact, clone and Eqs. 4-11 at
//      coarse nodes with coarse masses, exactly as without subdivision). At
//      a touch the colliding elements (within c dt2 of the contact point,
//      c = sqrt(E/rho), and at least those holding the touching node and
//      the touched point) get a separate sub-model, each split k x k (k =
//      ceil(h_e / (c dt2)), clamped; one k per sub-model), built at the end
//      of the touch's step. Its sub-nodes at the coarse nodes and on edges
//      shared with elements outside it follow the coarse nodes' motion over
//      each step (velocity boundary conditions, step 3); the others
//      (inside, on edges between colliding elements, on the free boundary)
//      are free. It is integrated with n = ceil(dt / (substep_safety x the
//      sub-elements' element-bound critical step)) substeps per coarse step
//      (step 4); the sub-elements' force on its prescribed nodes at the step
//      end is returned to the coarse nodes with linear weights and replaces
//      the colliding elements' own force (step 5). Deleted when no clone
//      ties its parents' corners (the contact points separated): the
//      parents take the area-averaged stress. Interpretations: the shared
//      edges are prescribed too (conforming with the coarse neighbours);
//      the force at the step end, not the substep average (centred for the
//      coarse kick-drift-kick). Measured, not assumed: the free sub-nodes
//      carry mass the coarse nodes also carry, and the returned forces
//      include their inertia, so the coarse momentum and energy are not
//      conserved while a sub-model lives (a property of the procedure as
//      written; the energy account's `other` shows it).
//    - kInPlace (an option beyond the paper; the default before the flip to
//      the paper's sub-model): at a touch, the elements within c dt2 of
//      the contact point are refined k x k in place
//      (k = ceil(h_e / (c dt2)), clamped), mass and momentum moved exactly;
//      the patch (its elements and the coarse elements touching its nodes)
//      is integrated with steps dt/n, the coarse nodes around it moving
//      with their coarse-step velocity (the velocity boundary condition of
//      Eq. 12); the patch forces on those coarse nodes are returned to them
//      (centred kicks plus an O(dt^3) correction at the step end, so that
//      momentum stays exact). Edges between refined and unrefined elements
//      carry hanging nodes tied linearly to the edge. The clone is formed
//      between patch nodes, so its masses (Eq. 5 loss) are the small patch
//      masses. The patch is deleted (restricted back to the coarse
//      elements, momentum exact, stress area-averaged) when its clone nodes
//      separated. This differs from Sect. 5 as written: the coarse elements
//      are replaced while the patch lives and its state must be restricted
//      back when it is deleted (the deletion loss of the energy account).
//
// Approximations relative to Paper B (which gives no algorithm tables):
// the tie is node-to-node or node-to-edge-point (the point shares its mass
// and force with the edge's nodes by their linear weights); a clone whose
// shear reaches the limit slides (Eq. 10: normal velocity tied, shear force
// the one the tie demands to stop the slip within the step, reduced to the
// limit with its sign, so friction never reverses a slip; the tied point
// following the node along the target's face) instead of being removed as Sect. 4.2's last sentence
// says: removed, the pressed node touches again at once, and each re-touch's
// inelastic impact takes the tangential velocity (a frictionless face stuck
// or, with the re-touch delayed, was passed through); a released node may
// touch again from the next patch step (coarse level: later in the same
// step); every boundary node is checked at each interval's start against
// the other blocks at any depth; touches inside a patch step split that
// step's drift for all patch nodes (all drift to the touch time, the touch is
// processed, the drift goes on), while the kicks stay on the uniform grid
// t0 + j dt/n (cutting the kick-drift-kick step itself at each touch makes
// the steps irregular, and leapfrog with irregular steps pumps energy into
// the patch's top modes); the coarse step is split for the touching nodes
// only, as in Sect. 3; one k per run.
//
// The library does no I/O. Errors: dda::SceneError for a bad scene (also
// when dt exceeds the mesh's critical step), dda::SimulationError for a run
// that goes wrong (inverted element, non-finite state), and its subclass
// ContactError for a contact that cannot be resolved (a node deeper than
// d_tol inside another block, a touch that does not let the step advance).
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "dda/block.hpp"
#include "dda/cdem/mesh.hpp"
#include "dda/scene.hpp"
#include "dda/simulation.hpp"
#include "dda/vec2.hpp"

namespace dda::cdem {

// Strength of a clone node (per unit thickness the contact 'area' A_c is
// the clone's tributary boundary length, m).
struct CloneStrength {
  double tensile = 0.0;        // sigma_t of Eq. 6, Pa: 0 separates at any tension
  double cohesion = 0.0;       // c of Eq. 7, Pa
  double friction_deg = 30.0;  // phi of Eq. 7, degrees
};

// When a patch whose clone nodes all separated is deleted (restricted back
// to its coarse elements, Sect. 5). The restriction keeps mass and momentum
// exactly but not the fine-scale kinetic and strain energy the coarse
// elements cannot represent: that energy is lost (deletion_loss of the
// energy account). No projection onto the coarse mesh can keep it; the
// option beyond the paper hands it to the coarse mesh's own vibration.
// (Waiting until the fine-scale energy has left the patch does not work
// here: on the prisms a trial restriction still lost more than 1e-3 of the
// kinetic + strain energy 0.2 s after the separation, and a patch kept that
// long loses 2 % of E0 at its interface with the coarse steps.)
enum class PatchDeletion : std::uint8_t {
  // Paper B Sect. 5: in the step the patch's clone nodes separated;
  // momentum-conserving restriction, stress area-averaged.
  kAtSeparation,
  // Beyond the paper, at the same time: the same restriction, then the
  // energy it dropped is handed to the coarse mesh in the form it can hold:
  // the restricted velocities' deviation from their mass-weighted mean is
  // scaled so that the kinetic energy is kept (linear momentum unchanged;
  // angular momentum not exactly), and each
  // parent's area-averaged stress is scaled so that its strain energy is its
  // children's. Each factor is capped at kMaxEnergyScale (model_subdivision
  // .cpp); what the cap leaves is still reported as deletion_loss. Not a
  // projection: the fine-scale energy becomes coarse-scale vibration.
  kEnergyMatched,
};
// How blocks touch: Paper B's two-scale contact (the default), or the
// conventional node-to-edge penalty contact that Paper B argues against, as a
// baseline on the same CST blocks (model_penalty.cpp).
enum class ContactMode : std::uint8_t { kTwoScale, kNodeToEdgePenalty };

// How Sect. 5's local subdivision is done (CdemOptions::subdivision true).
enum class SubdivisionMode : std::uint8_t {
  // Paper B Sect. 5 steps (1)-(5) as written (model_submodel.cpp): the
  // coarse model stays as it is (contact, clone and Eqs. 4-11 at coarse
  // nodes, as without subdivision); the colliding elements get a separate
  // sub-model of k x k sub-elements driven by the coarse nodes' velocities
  // (Eq. 12, steps dt/n), whose element forces replace the colliding
  // elements' own force on their coarse nodes. The default.
  kSubModel,
  // Beyond the paper, an option: the colliding elements refined in place
  // with hanging nodes, the clone formed between patch nodes
  // (model_subdivision.cpp).
  kInPlace,
};

// The impact that forms a clone at a touch (Sect. 4.1).
enum class TouchImpact : std::uint8_t {
  // Paper B Eq. 4: perfectly inelastic, the contact points take one velocity
  // ('no slipping occurs' in the touch step), tangential part included,
  // whatever phi is: the formation impulse is not limited by Coulomb.
  kPerfectlyInelastic,
  // Beyond the paper: a Coulomb impact. The normal relative velocity is tied
  // as in Eq. 4; the tangential impulse is the one that stops the slip,
  // capped at tan(phi) times the clone's normal impulse (cohesion, a force,
  // gives no impulse). Capped, the clone starts sliding (Eq. 10); else it
  // sticks as in Eq. 4. Momentum conserved; the loss never exceeds Eq. 4's.
  kCoulomb,
};

struct CdemOptions {
  ContactMode contact = ContactMode::kTwoScale;
  TouchImpact touch_impact = TouchImpact::kPerfectlyInelastic;  // Sect. 4.1 as published
  // kNodeToEdgePenalty only: the normal spring between a boundary node and
  // the boundary edge it penetrates, Pa (N/m of force per unit thickness per
  // m of penetration); 0: E / 100 of the stiffer of the two blocks' materials
  // (Paper A Sect. 4.1's ratio kn / E, the kn Paper A's scenes use in B-7).
  // Frictionless, undamped; needs subdivision = false.
  double penalty_kn = 0.0;
  double tolerance = 5e-3;  // contact tolerance d_tol, m (Paper B Sect. 6)
  CloneStrength strength;
  bool subdivision = true;  // Sect. 5 local subdivision; off: clones of coarse nodes
  // Default: the paper's sub-model (Sect. 5 as written); kInPlace is the
  // in-place refinement beyond the paper, a named option.
  SubdivisionMode subdivision_mode = SubdivisionMode::kSubModel;
  // Refinement k x k of an element in the contact zone: k = ceil(h_e / (c dt2))
  // (h_e = sqrt(2 A_e), the element's length scale), clamped to this range.
  // One k per run, fixed by the first touch, so that refined neighbours share
  // their edge nodes.
  int min_subdivision = 2;
  int max_subdivision = 6;
  double substep_safety = 0.9;           // patch step dt/n <= safety * element-bound critical step
  double mass_damping = 0.0;             // alpha of C = alpha M, 1/s
  bool check_stability = true;           // SceneError if dt exceeds the coarse mesh's critical step
  bool capture_touch_snapshots = false;  // store a Snapshot in every TouchRecord
  PatchDeletion patch_deletion = PatchDeletion::kAtSeparation;  // Sect. 5 as published
  // Contact-point mass (Paper B Sect. 4.1: Eq. 5's loss falls with the mass
  // of the contact points, zero mass being an elastic touch; 'we can achieve
  // collisions with different energy losses by adjusting the mass of the
  // contact points'), kg/m. 0: off, k from c dt2 as in Sect. 5. > 0 (with
  // subdivision): the subdivision k is chosen at the first touch as the
  // smallest k >= min_subdivision that brings the touching node's lumped mass
  // M down to M / k^2 <= contact_point_mass (the lumped masses of the other
  // nodes follow from the refined mesh); SceneError if that needs k >
  // max_subdivision. The mass is set through the mesh, so it cannot reach 0.
  double contact_point_mass = 0.0;
};

struct CdemBlock {
  std::vector<Vec2> outline;  // convex, counter-clockwise
  int divisions = 1;          // mesh_convex_polygon divisions
  // Optional own mesh (e.g. mesh_rectangle): used instead of
  // mesh_convex_polygon(outline, divisions) when it has triangles. Its first
  // outline.size() nodes must be the outline's vertices, in order; its
  // triangles CCW and conforming.
  TriMesh mesh;
  Vec2 velocity{};            // initial velocity of every node, m/s
  bool fixed = false;         // nodes never move (infinite mass)
  int material = 0;           // index into CdemScene::materials
  std::string name;
};

struct CdemScene {
  std::string name;
  std::vector<Material> materials{Material{}};
  std::vector<CdemBlock> blocks;
  Vec2 gravity{};
  double dt = 1e-4;
  double duration = 1.0;
  CdemOptions options;
};

// A DDA scene's blocks, materials, gravity, dt and duration as a CDEM scene
// (each block meshed with `divisions`); the penalty parameters are dropped.
CdemScene from_dda_scene(const dda::Scene& scene, int divisions, const CdemOptions& options = {});

enum class NodeKind : std::uint8_t {
  kCoarse,   // corner of unrefined elements only: integrated with dt
  kFine,     // corner of a patch element: integrated with dt/n
  kHanging,  // on an edge between a refined and an unrefined element: follows the edge linearly
  kDead,     // removed with its patch
};

// kTension: Eq. 6, the clone is removed. kShear: Eqs. 7-9, the shear limit
// is reached and the clone starts sliding (Eq. 10; listed in slips(), not a
// separation). kSlidOff: a sliding clone's node left the target's boundary
// (past a corner) or reached an edge integrated on the other level; the
// clone is removed and the node is free to touch again.
enum class SeparationCriterion : std::uint8_t { kTension, kShear, kSlidOff };

// A run stopped because a contact cannot be resolved: a node found inside
// another block deeper than the contact tolerance (its time of impact lies
// in an earlier step), or a touch that does not let the step advance.
struct ContactError : SimulationError {
  ContactError(const std::string& what, int node_, int block_, int other_block_, std::int64_t step_, double time_,
               double depth_, StopReason why = StopReason::kPenetration)
      : SimulationError(what, why),
        node(node_),
        block(block_),
        other_block(other_block_),
        step(step_),
        time(time_),
        depth(depth_) {}
  int node, block, other_block;
  std::int64_t step;
  double time, depth;  // s; m behind the other block's boundary
};

struct Snapshot {
  struct Tri {
    std::array<Vec2, 3> x;
    Vec2 velocity;  // mean of the corner velocities
    int block = 0;
    bool fine = false;
    std::array<int, 3> node{-1, -1, -1};  // the corners' node ids (-1: a sub-model's sub-node)
    std::array<Vec2, 3> v{};              // the corners' velocities
    Vec3 stress = Vec3::Zero();           // the element's (sxx, syy, sxy), Pa
  };
  double time = 0.0;
  std::vector<Tri> tris;
  std::vector<Vec2> clone_points;
};

// One touch: a node reaching an edge within a step (Sects. 3-4).
struct TouchRecord {
  double time = 0.0;  // touch time t0 + dt1
  double step_start = 0.0, step_end = 0.0;
  double dt1 = 0.0, dt2 = 0.0;  // free-motion and contact parts of the step
  bool fine = false;            // found inside a refined patch (patch step)
  int main_node = -1, main_block = -1, target_block = -1;
  bool node_to_node = false;                  // the touched point is a node of the target
  Vec2 point{};                               // contact point
  double mass_main = 0.0, mass_target = 0.0;  // target: effective mass at the point
  Vec2 v_main{}, v_target{}, v_clone{};       // before the impact / clone after (Eq. 4)
  double energy_loss_eq5 = 0.0;               // Eq. 5 with these masses, J/m
  // Eq. 5 for the clone group projected at this touch (the new clone and the
  // clones sharing nodes with it, model_clone.cpp): the loss of the group's
  // perfectly inelastic projection from the group's masses and velocities,
  // 1/2 r^T (C M^-1 C^T)^+ r (r = C v the ties' relative velocities), J/m;
  // energy_loss_eq5 for a lone clone. Eq. 5 is its one-pair case.
  double energy_loss_eq5_group = 0.0;
  double energy_loss = 0.0;                   // measured kinetic-energy drop of the projection, J/m
  double impulse_normal = 0.0, impulse_tangential = 0.0;  // the new clone's impulse on the main node, N s/m
  bool coulomb_capped = false;                // TouchImpact::kCoulomb: |J_t| = tan(phi) J_n, the clone slides
  int subdivision = 0;                        // k used (0: none)
  double radius = 0.0;                        // refinement radius c dt2, m
  int refined_elements = 0;                   // coarse elements refined at this touch
  std::vector<Snapshot> snapshot;             // 0 or 1 entries (CdemOptions::capture_touch_snapshots)
};

struct SeparationRecord {
  double time = 0.0;
  int main_node = -1, main_block = -1, target_block = -1;
  SeparationCriterion criterion = SeparationCriterion::kTension;
  double normal_force = 0.0;  // N/m, > 0 compression
  double shear_force = 0.0;   // N/m
  double limit = 0.0;         // sigma_t A_c (tension) or F_n tan(phi) + c A_c (shear)
  double contact_area = 0.0;  // A_c, m (per unit thickness)
  bool fine = false;
};

struct CloneView {
  int main_node = -1;
  std::array<int, 2> target{-1, -1};
  std::array<double, 2> weight{0.0, 0.0};
  Vec2 point{};
  Vec2 force{};  // interaction force on the main node, N/m (Eq. 11)
  Vec2 normal{};  // unit normal from the target into the main node's block
  bool fine = false;
};

// One sub-model of SubdivisionMode::kSubModel (Sect. 5), from the touch
// that made it to its deletion.
struct SubModelRecord {
  double created = 0.0;   // s, end of the touch's step (its state is built at t1)
  double deleted = -1.0;  // s, end of the step its parents' clones all separated; -1 while it lives
  int main_node = -1, main_block = -1, target_block = -1;  // the touch
  int elements = 0;         // colliding (parent) coarse elements
  int k = 0;                // each parent split k x k
  int sub_nodes = 0, free_nodes = 0;
  int substeps = 0;         // n: dt / n <= substep_safety * sub_critical_dt
  double sub_critical_dt = 0.0;  // min over sub-elements of 2 / omega_max(e), s
  std::int64_t substeps_taken = 0;
  double radius = 0.0;      // c dt2 of the touch, m
  // At deletion, J/m: the kinetic energy of its free sub-nodes relative to
  // the coarse velocity field interpolated at them (the fine-scale part,
  // dropped: the coarse nodes carry that mass too and keep their own
  // velocities), and
  // the strain-energy change of setting each parent's stress to its
  // sub-elements' area average (in deletion_loss of the energy account).
  double kinetic_dropped = 0.0, strain_change = 0.0;
};

struct CdemEnergy {
  double kinetic = 0.0;
  double strain = 0.0;
  double gravity = 0.0;
  double contact = 0.0;  // penalty springs (ContactMode::kNodeToEdgePenalty), 0 otherwise
  double total() const { return kinetic + strain + gravity + contact; }
};

// Where the energy of a run went, J per unit thickness, at the model's
// current time (one time-series row):
//   initial = kinetic + strain + gravity + touch_loss + refine_loss
//             + deletion_loss + other.
// touch_loss is measured (the kinetic-energy drop of each touch's Eq. 4
// projection; touch_loss_eq5 is Eq. 5 with the clone's masses, for
// comparison; touch_loss_eq5_group Eq. 5 of the projected clone group, its
// bound); refine_loss and deletion_loss are the total-energy drops of
// refining elements and of deleting patches (Sect. 5); other is what is left:
// time integration, work of friction at sliding clones, mass damping, and
// the clone constraint's drift.
struct CdemEnergyAccount {
  double time = 0.0;
  double initial = 0.0;
  double kinetic = 0.0, strain = 0.0, gravity = 0.0;
  double touch_loss = 0.0, touch_loss_eq5 = 0.0;
  double touch_loss_eq5_group = 0.0;  // sum of TouchRecord::energy_loss_eq5_group
  double refine_loss = 0.0, deletion_loss = 0.0;
  double other = 0.0;
  // SubdivisionMode::kSubModel: the kinetic energy of the live sub-models'
  // free sub-nodes relative to the coarse velocity field interpolated at
  // them, J/m. NOT in the balance above (their mass is also carried by the
  // coarse nodes); strain counts the sub-elements instead of their parents.
  double submodel_kinetic = 0.0;
};

class Model {
 public:
  explicit Model(const CdemScene& scene);

  void step();
  void advance_to(double t);  // steps until time() >= t - dt/2

  double time() const { return time_; }
  double dt() const { return dt_; }
  std::int64_t step_count() const { return steps_; }
  const CdemScene& scene() const { return scene_; }

  // Critical step of the coarse mesh: 2 / omega_max of M^-1 K (power
  // iteration), and the element bound min_e 2 / omega_max(e) (Irons).
  double critical_dt() const { return critical_dt_; }
  double element_critical_dt() const { return element_critical_dt_; }
  // kNodeToEdgePenalty: 2 / sqrt(omega_max^2 + 6 kn max(1/m) of the boundary
  // nodes), the mesh's critical step with up to three penalty springs per
  // node (model_penalty.cpp); critical_dt() otherwise.
  double contact_critical_dt() const { return contact_critical_dt_; }
  // kNodeToEdgePenalty: the springs of the last force evaluation.
  struct PenaltyContact {
    int node = -1, a = -1, b = -1;  // node behind the edge a -> b of another block
    double xi = 0.0, depth = 0.0;   // foot on the edge (0 at a), penetration, m
    Vec2 normal{};                  // the edge's outward unit normal
  };
  const std::vector<PenaltyContact>& penalty_contacts() const { return penalty_contacts_; }
  double penalty_kn() const { return penalty_kn_; }  // Pa, resolved (0 in the two-scale mode)

  int block_count() const { return static_cast<int>(blocks_.size()); }
  double block_mass(int b) const;
  Vec2 block_momentum(int b) const;
  Vec2 block_velocity(int b) const;          // momentum / mass
  Vec2 block_mean_position(int b) const;     // mass-weighted mean node position
  Vec2 block_displacement(int b) const;      // mean position minus its initial value
  double block_max_velocity_x(int b) const;  // largest nodal x-velocity
  double block_min_velocity_x(int b) const;
  std::vector<Vec2> block_outline(int b) const;  // current positions of the outline vertices

  Vec2 momentum() const;
  CdemEnergy energy() const;
  double impact_energy_loss() const { return impact_loss_; }    // sum over touches, measured
  double remap_energy_change() const { return remap_change_; }  // refine + delete patches
  CdemEnergyAccount energy_account() const;

  const std::vector<TouchRecord>& touches() const { return touches_; }
  const std::vector<SeparationRecord>& separations() const { return separations_; }
  const std::vector<SeparationRecord>& slips() const { return slips_; }  // clones that started sliding
  std::vector<CloneView> clones() const;
  int subdivision_level() const { return k_; }
  int patch_substeps() const { return substeps_; }
  int active_elements(bool fine) const;
  std::int64_t patch_substeps_taken() const { return substeps_taken_; }
  // SubdivisionMode::kSubModel: every sub-model made so far, and how many live.
  const std::vector<SubModelRecord>& submodels() const { return submodel_records_; }
  int live_submodels() const { return static_cast<int>(subs_.size()); }

  int node_count() const { return static_cast<int>(x_.size()); }
  Vec2 node_position(int i) const { return x_[i]; }
  Vec2 node_velocity(int i) const { return v_[i]; }
  double node_mass(int i) const { return m_[i]; }
  NodeKind node_kind(int i) const { return kind_[i]; }
  int node_block(int i) const { return node_block_[i]; }

  Snapshot snapshot() const;

 private:
  struct Elem {
    std::array<int, 3> n{};
    int block = 0;
    int level = 0;     // 0 coarse, 1 patch
    int parent = -1;   // for patch elements
    int lattice = -1;  // for refined coarse elements: index into lattices_
    bool active = true;
    Vec3 stress = Vec3::Zero();
    std::array<Vec2, 3> last{};  // node positions at the last force evaluation
    double mass = 0.0;
  };
  struct Lattice {
    int elem = -1, k = 0;
    std::vector<int> nodes;     // lattice_index -> node
    std::vector<int> children;  // element ids
  };
  struct EdgeInfo {
    int lo = -1, hi = -1;  // coarse node ids, lo < hi
    std::array<int, 2> elems{-1, -1};
    std::vector<int> nodes;  // k - 1 nodes from lo to hi while refined on a side
  };
  struct BEdge {  // a boundary edge, CCW (outward normal perp_right(b - a))
    int a = -1, b = -1, block = 0;
    bool fine = false;  // a sub-edge of a refined element
  };
  struct Clone {
    int main = -1;
    std::array<int, 2> t{-1, -1};
    std::array<double, 2> w{0.0, 0.0};
    int ea = -1, eb = -1;  // the touched edge (for the normal)
    double area = 0.0;     // A_c
    bool fine = false;
    // Sliding (Eq. 10): the shear limit was reached; from then on only the
    // normal velocity is tied, the shear force is the one the tie demands
    // (stopping the slip) capped at the limit with its sign, and the tied
    // point follows the node along the target's boundary.
    bool sliding = false;
    Vec2 lambda{};
  };
  // SubdivisionMode::kSubModel (model_submodel.cpp).
  struct SubElem {
    std::array<int, 3> n{};  // sub-node ids
    int parent = -1;         // coarse element
    Vec3 stress = Vec3::Zero();
    std::array<Vec2, 3> last{};
    double mass = 0.0;
  };
  struct SubModel {
    int record = -1;  // index into submodel_records_
    int k = 0, substeps = 1;
    std::vector<int> parents;
    std::vector<Vec2> x, v, f;        // sub-node state; f: force of the last evaluation
    std::vector<double> m, inv_m;     // lumped masses (inv_m 0 for prescribed nodes)
    std::vector<int> block;           // sub-node's block
    // prescribed sub-nodes follow (1 - w) X_a + w X_b of coarse nodes a, b
    std::vector<std::array<int, 2>> drive;
    std::vector<double> drive_w;
    std::vector<char> prescribed;
    // where each sub-node sits in a parent: x = X0 + a (X1 - X0) + b (X2 - X0)
    std::vector<int> home;
    std::vector<std::array<double, 2>> home_ab;
    std::vector<SubElem> elems;
    std::vector<int> coarse;          // the coarse nodes that drive it
    std::vector<Vec2> coarse_x0;      // their positions at the last sync
    std::vector<Vec2> coarse_force;   // step 5: force returned to them, N/m
    std::vector<Vec2> bc;             // scratch: element forces on the prescribed sub-nodes, N/m
  };
  struct SubRequest {
    int main_node = -1, ea = -1, eb = -1;
    Vec2 point{};
    double dt2 = 0.0;
  };
  struct Touch {     // a detected touch, not yet processed
    double s = 0.0;  // fraction of the interval
    int node = -1, ea = -1, eb = -1;
    double xi = 0.0;
  };
  struct Block {
    std::vector<int> nodes;    // every node ever made for the block
    std::vector<int> outline;  // coarse outline vertex nodes, CCW
    int material = 0;
    bool fixed = false;
    Vec2 initial_mean{};
  };

  // set-up
  void build(const CdemScene& scene);
  void compute_critical_steps();
  // topology
  std::uint64_t edge_key(int a, int b) const;
  void classify();
  void rebuild_lists();
  void rebuild_boundary();
  std::vector<double> lumped_masses() const;
  void refine(const std::vector<int>& elems);
  void unrefine(const std::vector<int>& parents);
  void update_substeps();
  void finish_mesh_change();
  double element_omega_max(const Elem& e) const;
  // kinematics and forces
  void sync_positions(double t);
  void add_node_force(int n, Vec2 f, bool patch_eval);
  void element_force(Elem& e, bool patch_eval);
  void compute_coarse_forces();
  void compute_patch_forces(double t);
  void solve_clones(bool fine, double t);
  std::vector<int> clone_component(int ci) const;
  double project_component(int ci, TouchRecord* rec = nullptr);
  double group_eq5(const std::vector<int>& comp) const;
  void kick_patch(double h);
  void kick_coarse_first_half();
  void forces_and_second_half_kick();
  void refresh_forces_after_patch_change(double t);
  bool locate_edge(int block, Vec2 p, int& a, int& b, double& xi) const;
  // contact
  std::vector<Touch> find_touches(bool coarse_level, double t_start, const std::vector<Vec2>& p0,
                                  const std::vector<Vec2>& p1) const;
  std::vector<Touch> coarse_touches(double t0) const;
  double depth_inside(int block, Vec2 p, const std::vector<Vec2>& pos) const;
  void check_not_inside(int node, int other_block, const std::vector<Vec2>& pos, double t) const;
  bool follow_sliding_target(Clone& c);
  void release_clone(const Clone& c, double t);
  bool process_touch(const Touch& touch, bool fine_level, double t, double t0, double t1);
  void refine_contact_zone(int main_node, Vec2 point, int& ea, int& eb, double& xi, TouchRecord& rec);
  bool dissolve_free_patches();
  double tributary_length(int node) const;
  Vec2 vertex_normal(int node) const;
  Vec2 clone_normal(const Clone& c) const;
  bool in_clone(int node) const;
  bool touch_blocked(int node) const;
  std::vector<int> tied_partners(int node) const;
  // Sect. 5 as written: the sub-model (model_submodel.cpp)
  bool submodel_mode() const {
    return opt_.subdivision && opt_.subdivision_mode == SubdivisionMode::kSubModel &&
           opt_.contact == ContactMode::kTwoScale;
  }
  // Coarse element e is a parent of a live sub-model: its force, strain
  // energy and drawing come from the sub-model (step 5).
  bool in_submodel(int e) const { return !elem_sub_.empty() && elem_sub_[static_cast<std::size_t>(e)] >= 0; }
  void request_submodel(int main_node, Vec2 point, int ea, int eb, const TouchRecord& rec);
  void create_submodel(const SubRequest& req, int touch_index, double t);
  void advance_submodels(double t0, double t1);
  void submodel_forces(SubModel& s, double t);
  void add_submodel_forces();
  bool delete_separated_submodels();
  double submodel_strain() const;
  double submodel_kinetic() const;
  double submodel_kinetic(const SubModel& s) const;
  // node-to-edge penalty baseline (model_penalty.cpp)
  void setup_penalty();
  void penalty_step();
  void add_penalty_forces();
  double penalty_energy() const;
  // stepping
  void literal_two_stage(const std::vector<Touch>& touches, double t0);
  void patch_loop(double t0, double t1, std::vector<Touch> coarse_touches);
  void check_state() const;
  double kinetic_energy() const;
  Elem& elem(int e) { return elems_[static_cast<std::size_t>(e)]; }
  const Elem& elem(int e) const { return elems_[static_cast<std::size_t>(e)]; }

  CdemScene scene_;
  CdemOptions opt_;
  double dt_ = 0.0, time_ = 0.0, step_t0_ = 0.0;
  std::int64_t steps_ = 0, substeps_taken_ = 0;
  double critical_dt_ = 0.0, element_critical_dt_ = 0.0;

  std::vector<Mat3> d_, c_;         // per material: elastic and compliance matrices
  std::vector<double> wave_speed_;  // per material sqrt(E / rho)
  std::vector<Block> blocks_;

  // nodes (structure of arrays)
  // x, v: position and velocity; xs: coarse position at the step start;
  // f: force of the last evaluation at the node's level; iface: force of
  // the patch-evaluated elements on coarse nodes (last patch evaluation);
  // iface0: its value in the first half-kick of the step; iimp: its impulse
  // integrated over the patch steps of the current step (see step()).
  std::vector<Vec2> x_, v_, xs_, f_, iface_, iface0_, iimp_, scratch_;
  std::vector<double> m_, inv_m_;
  std::vector<int> node_block_;
  std::vector<NodeKind> kind_;
  std::vector<int> hang_a_, hang_b_;
  std::vector<double> hang_w_;  // weight of hang_b_
  std::vector<int> clone_count_;
  std::vector<double> released_at_;  // time the node's last clone was removed

  std::vector<Elem> elems_;
  std::vector<Lattice> lattices_;
  std::unordered_map<std::uint64_t, EdgeInfo> edges_;
  std::vector<BEdge> coarse_bedges_;  // outline edges of the coarse mesh
  std::vector<int> coarse_bedge_elem_;
  std::vector<BEdge> bedges_;
  std::vector<std::vector<int>> block_bedges_;  // indices into bedges_ per block
  std::vector<int> bnodes_;
  // active coarse / patch elements; elements evaluated at the coarse step
  // (all corners coarse) and at the patch steps (patch elements and coarse
  // elements with a patch-integrated corner)
  std::vector<int> coarse_elems_, fine_elems_, coarse_eval_, patch_eval_;
  std::vector<int> coarse_dofs_, fine_dofs_, hanging_;

  std::vector<Clone> clones_;
  std::vector<TouchRecord> touches_;
  std::vector<SeparationRecord> separations_;
  std::vector<SeparationRecord> slips_;
  std::unordered_map<int, int> step_touch_count_;  // touches per node in the current coarse step
  int k_ = 0;         // subdivision level of this run (0 until the first refinement)
  int substeps_ = 1;  // n of dt/n in patches
  double impact_loss_ = 0.0, remap_change_ = 0.0;
  double refine_loss_ = 0.0, deletion_loss_ = 0.0, touch_loss_eq5_ = 0.0, initial_energy_ = 0.0;
  double touch_loss_eq5_group_ = 0.0;
  // node-to-edge penalty baseline
  double penalty_kn_ = 0.0, contact_critical_dt_ = 0.0, penalty_max_depth_ = 0.0;
  std::vector<PenaltyContact> penalty_contacts_;
  // SubdivisionMode::kSubModel
  std::vector<SubModel> subs_;
  std::vector<SubModelRecord> submodel_records_;
  std::vector<SubRequest> sub_requests_;  // touches of the current step
  std::vector<int> touch_of_request_;     // their index into touches_
  std::vector<int> elem_sub_;             // coarse element -> index into subs_, -1
  std::int64_t sub_substeps_taken_ = 0;
};

}  // namespace dda::cdem
