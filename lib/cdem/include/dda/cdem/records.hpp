// What a CDEM model run reports: node classes, the touches, separations
// and sub-models it made, snapshots for drawing, energies, and the error of
// a contact that cannot be resolved. Plain values.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "dda/block.hpp"
#include "dda/simulation.hpp"
#include "dda/vec2.hpp"

namespace dda::cdem {

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

// A node-to-edge penalty spring of ContactMode::kNodeToEdgePenalty at the
// last force evaluation.
struct PenaltyContact {
  int node = -1, a = -1, b = -1;  // node behind the edge a -> b of another block
  double xi = 0.0, depth = 0.0;   // foot on the edge (0 at a), penetration, m
  Vec2 normal{};                  // the edge's outward unit normal
};

}  // namespace dda::cdem
