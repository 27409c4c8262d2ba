// The CDEM model's phases as free functions over the parts of its state
// (dda/cdem/model_state.hpp), grouped by the file that defines them. Each
// takes the parts it reads and writes; the ones that drive a whole phase
// (a touch, a refinement, a sub-model's step) take the set-up and the
// state. Internal: not installed.
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

#include "dda/cdem/model_state.hpp"

namespace dda::cdem {

// A detected touch, not yet processed (one interval: a coarse or patch step).
struct Touch {
  double s = 0.0;  // fraction of the interval
  int node = -1, ea = -1, eb = -1;
  double xi = 0.0;
};

inline std::uint64_t edge_key(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b)), hi = static_cast<std::uint64_t>(std::max(a, b));
  return (lo << 32) | hi;
}
inline bool in_clone(const NodeState& nd, int node) { return nd.clone_count[node] > 0; }
// Sect. 5 by the sub-model (kSubModel) in this run.
inline bool submodel_mode(const CdemOptions& opt) {
  return opt.subdivision && opt.subdivision_mode == SubdivisionMode::kSubModel && opt.contact == ContactMode::kTwoScale;
}
// Coarse element e is a parent of a live sub-model: its force, strain
// energy and drawing come from the sub-model (step 5).
inline bool in_submodel(const SubModels& subs, int e) {
  return !subs.elem_owner.empty() && subs.elem_owner[static_cast<std::size_t>(e)] >= 0;
}

// model.cpp
void check_state(const ModelState& st);

// model_mesh.cpp: set-up and the mesh's derived lists
void build_model(ModelSetup& su, ModelState& st);
double element_omega_max(const Element& e, const std::vector<Vec2>& x, const Mat3& d);
void compute_critical_steps(ModelSetup& su, const ModelState& st);
void classify(const MeshState& mesh, NodeState& nd);
void rebuild_lists(MeshState& mesh, const NodeState& nd, const std::vector<BlockState>& blocks);
void rebuild_boundary(MeshState& mesh, std::size_t node_count, std::size_t block_count);
std::vector<double> lumped_masses(const MeshState& mesh, const NodeState& nd);

// model_elements.cpp: forces and kicks
void sync_positions(NodeState& nd, const MeshState& mesh, double t, double step_t0);
void add_node_force(NodeState& nd, int n, Vec2 f, bool patch_eval);
void element_force(Element& e, NodeState& nd, const Mat3& d, bool patch_eval, double time, std::int64_t steps);
void compute_coarse_forces(const ModelSetup& su, ModelState& st);
void compute_patch_forces(const ModelSetup& su, ModelState& st, double t);
void kick_patch(NodeState& nd, const MeshState& mesh, double h);
void kick_coarse_first_half(NodeState& nd, const MeshState& mesh, double dt);
void forces_and_second_half_kick(const ModelSetup& su, ModelState& st);
void refresh_forces_after_patch_change(const ModelSetup& su, ModelState& st, double t);

// model_touch.cpp: detection, time of impact, the two stages
std::vector<Touch> find_touches(const ModelSetup& su, const ModelState& st, bool coarse_level, double t_start,
                                double t_p0, double t_p1, const std::vector<Vec2>& p0, const std::vector<Vec2>& p1);
std::vector<Touch> coarse_touches(const ModelSetup& su, const ModelState& st, double t0);
double depth_inside(const MeshState& mesh, int block, Vec2 p, const std::vector<Vec2>& pos);
void check_not_inside(const ModelSetup& su, const ModelState& st, int node, int other, const std::vector<Vec2>& pos,
                      double t);
// ContactError if the node, moving p0 -> p1 over [t0, t1] with the other
// nodes, entered block `other` and left it again within the interval after
// reaching deeper than `limit` (m; limit_name names it in the message).
void check_no_passage(const ModelState& st, int node, int other, const std::vector<Vec2>& p0,
                      const std::vector<Vec2>& p1, double t0, double t1, double limit, const char* limit_name);
bool locate_edge(const MeshState& mesh, const std::vector<Vec2>& x, int block, Vec2 p, int& a, int& b, double& xi);
void two_stage_step(const ModelSetup& su, ModelState& st, const std::vector<Touch>& touches, double t0);

// model_clone.cpp: clone nodes, Eqs. 4-5
bool touch_blocked(const std::vector<Clone>& clones, int node);
std::vector<int> tied_partners(const std::vector<Clone>& clones, int node);
std::vector<int> clone_component(const std::vector<Clone>& clones, int ci);
double group_eq5(const std::vector<Clone>& clones, const NodeState& nd, const MeshState& mesh,
                 const std::vector<int>& comp);
double project_component(std::vector<Clone>& clones, NodeState& nd, const MeshState& mesh, const CdemOptions& opt,
                         int ci, TouchRecord* rec);
bool process_touch(const ModelSetup& su, ModelState& st, const Touch& touch, bool fine_level, double t, double t0,
                   double t1);
Vec2 vertex_normal(const MeshState& mesh, const std::vector<Vec2>& x, int node);
Vec2 clone_normal(const Clone& c, const MeshState& mesh, const std::vector<Vec2>& x);
double tributary_length(const MeshState& mesh, const std::vector<Vec2>& x, int node);

// model_separation.cpp: Eq. 11 and the separation criteria, Eqs. 6-10
bool follow_sliding_target(Clone& c, NodeState& nd, const MeshState& mesh, const std::vector<BlockState>& blocks);
void release_clone(NodeState& nd, const Clone& c, double t);
void solve_clones(const ModelSetup& su, ModelState& st, bool fine, double t);

// model_submodel.cpp: Sect. 5 by a separate sub-model
void request_submodel(SubModels& subs, int touch_index, int main_node, Vec2 point, int ea, int eb, double dt2);
void create_submodel(const ModelSetup& su, ModelState& st, const SubModelRequest& req, int touch_index, double t);
void advance_submodels(const ModelSetup& su, ModelState& st, double t0, double t1);
void submodel_forces(SubModel& s, const ModelSetup& su, const ModelState& st, double t);
void add_submodel_forces(const SubModels& subs, NodeState& nd);
bool delete_separated_submodels(const ModelSetup& su, ModelState& st);
double submodel_strain(const ModelSetup& su, const ModelState& st);
double submodel_kinetic(const SubModel& s, const MeshState& mesh, const NodeState& nd);
double submodel_kinetic(const ModelState& st);

// model_refine.cpp, model_patches.cpp: Sect. 5 by the in-place refinement
void update_substeps(const ModelSetup& su, ModelState& st);
void finish_mesh_change(const ModelSetup& su, ModelState& st);
void refine(const ModelSetup& su, ModelState& st, const std::vector<int>& elems);
void unrefine(const ModelSetup& su, ModelState& st, const std::vector<int>& parents);
void refine_contact_zone(const ModelSetup& su, ModelState& st, int main_node, Vec2 point, int& ea, int& eb, double& xi,
                         TouchRecord& rec);
bool dissolve_free_patches(const ModelSetup& su, ModelState& st);
void patch_loop(const ModelSetup& su, ModelState& st, double t0, double t1, std::vector<Touch> touches);

// model_penalty.cpp: the node-to-edge penalty baseline
void setup_penalty(ModelSetup& su, const ModelState& st);
void penalty_step(const ModelSetup& su, ModelState& st);
void add_penalty_forces(const ModelSetup& su, ModelState& st);
double penalty_energy(const ModelSetup& su, const std::vector<PenaltyContact>& contacts);

// model_energy.cpp: read-out used inside the step
double kinetic_energy(const NodeState& nd);
CdemEnergy energy_of(const ModelSetup& su, const ModelState& st);
Vec2 block_mean_position(const ModelState& st, int b);
Snapshot snapshot_of(const ModelState& st);

}  // namespace dda::cdem
