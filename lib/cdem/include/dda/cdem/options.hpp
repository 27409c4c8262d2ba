// Paper B's CDEM model: the scene (blocks, materials, gravity, dt) and the
// options of the two-scale contact (Sects. 3-5) and of the variants beyond
// the paper. Plain values; dda/cdem/model.hpp describes the method.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "dda/cdem/mesh.hpp"
#include "dda/scene.hpp"
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
  // children's. Each factor is capped at kMaxEnergyScale (model_refine.cpp);
  // what the cap leaves is still reported as deletion_loss. Not a
  // projection: the fine-scale energy becomes coarse-scale vibration.
  kEnergyMatched,
};
// How blocks touch: Paper B's two-scale contact (the default), or the
// conventional node-to-edge penalty contact that Paper B argues against, as a
// baseline on the same CST blocks (model_penalty.cpp).
enum class ContactMode : std::uint8_t { kTwoScale, kNodeToEdgePenalty };

// How Sect. 5's local subdivision is done (CdemOptions::subdivision true).
enum class SubdivisionMode : std::uint8_t {
  // Paper B Sect. 5 steps (1)-(5) (model_submodel.cpp): the coarse model
  // stays as it is (contact, clone and Eqs. 4-11 at coarse nodes, as
  // without subdivision); the colliding elements get a separate sub-model
  // of k x k sub-elements driven by the coarse nodes' velocities (Eq. 12,
  // steps dt/n), whose element forces replace the colliding elements' own
  // force on their coarse nodes (CdemOptions::submodel_transfer). The
  // default.
  kSubModel,
  // Beyond the paper, an option: the colliding elements refined in place
  // with hanging nodes, the clone formed between patch nodes
  // (model_refine.cpp, model_patches.cpp).
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

// How Sect. 5 step (5), "transfer the forces of the elements to the initial
// nodes, and the force values for the whole element may be acquired", hands
// the sub-model's element forces to the initial (coarse) nodes
// (SubdivisionMode::kSubModel only). The paper does not say which
// sub-nodes' forces are transferred, nor whether the free sub-nodes' mass
// is the coarse nodes' own; the two readings differ in momentum.
enum class SubModelTransfer : std::uint8_t {
  // Our reading, the default: the sub-elements' forces on every sub-node,
  // prescribed and free, go to the initial nodes with the sub-node's linear
  // weights in its parent element (its place when the sub-model was built),
  // and the initial nodes keep their lumped masses: the sub-model resolves
  // the colliding elements' force, the coarse nodes carry their mass. Each
  // sub-element's nodal forces sum to zero, so the returned forces do too
  // and linear momentum is conserved to round-off. While the sub-model
  // moves as the linear interpolation of its parents' corners (same
  // stress), the returned force is the parents' own element force (nested
  // constant-strain triangles); its fine-scale motion adds the correction.
  // (The mass partition instead, the free sub-nodes taking the colliding
  // elements' mass and the coarse nodes keeping the rest, conserves
  // momentum too, but leaves a coarse node whose elements all collide (the
  // touching apex, the touched node) with its corner sub-node's mass, 1/k^2
  // of its own, against the stiff sub-elements, integrated with dt (step
  // 2): on Paper B's prisms a sub-element inverts four steps after the
  // sub-model is built at the paper's dt.)
  kWholeElement,
  // The literal reading: only the forces on the prescribed sub-nodes (step
  // 3's nodes of fixed velocity) are returned, and the free sub-nodes' mass
  // is carried by the coarse nodes too. The returned forces then include
  // the free sub-nodes' inertia and do not sum to zero: momentum is lost
  // while a sub-model lives (39 % on Paper B's two prisms).
  kPrescribedNodes,
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
  // Default: the paper's sub-model (Sect. 5); kInPlace is the in-place
  // refinement beyond the paper, a named option.
  SubdivisionMode subdivision_mode = SubdivisionMode::kSubModel;
  // kSubModel: Sect. 5 step (5) read so that momentum is conserved (the
  // default) or literally (kPrescribedNodes).
  SubModelTransfer submodel_transfer = SubModelTransfer::kWholeElement;
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

}  // namespace dda::cdem
