// Scene files, writing: a SceneFile as the JSON text the reader takes back
// (every key written out, numbers in shortest round-trip form).
#include <nlohmann/json.hpp>

#include "dda/io/csv.hpp"
#include "dda/io/scene_file.hpp"
#include "scene_names.hpp"

namespace dda::io {

namespace {

using ojson = nlohmann::ordered_json;

ojson vec2_json(Vec2 v) { return ojson::array({v.x, v.y}); }

const char* name_of(SmallEdgeRays m) {
  switch (m) {
    case SmallEdgeRays::kVirtualAndVertex: return "virtual_and_vertex";
    case SmallEdgeRays::kVirtualReplacesVertex: return "virtual_replaces_vertex";
  }
  return "virtual_and_vertex";
}

const char* name_of(FrictionUpdate u) {
  switch (u) {
    case FrictionUpdate::kPaper: return "paper";
    case FrictionUpdate::kReturnMapping: return "return_mapping";
  }
  return "paper";
}

const char* name_of(HRule h) {
  switch (h) {
    case HRule::kMinMaxEdge: return "min_max_edge";
    case HRule::kMeanEdge: return "mean_edge";
    case HRule::kGiven: return "given";
    case HRule::kInscribedRadius: return "inscribed_radius";
  }
  return "min_max_edge";
}

}  // namespace

namespace {

ojson cdem_json(const CdemSettings& c) {
  using detail::name_in;
  const cdem::CdemOptions& o = c.options;
  const bool two_scale = o.contact == cdem::ContactMode::kTwoScale;
  ojson j = ojson::object();
  j["contact"] = name_in(detail::kCdemContact, o.contact);
  // Only the keys the reader takes in this configuration (it refuses the others).
  if (!two_scale) j["penalty_kn"] = o.penalty_kn;
  j["tolerance"] = o.tolerance;
  if (two_scale) {
    j["touch_impact"] = name_in(detail::kTouchImpact, o.touch_impact);
    j["strength"] = {{"tensile", o.strength.tensile},
                     {"cohesion", o.strength.cohesion},
                     {"friction_deg", o.strength.friction_deg}};
    j["subdivision"] = o.subdivision;
    if (o.subdivision) {
      j["subdivision_mode"] = name_in(detail::kSubdivisionMode, o.subdivision_mode);
      j["min_subdivision"] = o.min_subdivision;
      j["max_subdivision"] = o.max_subdivision;
      j["substep_safety"] = o.substep_safety;
      if (o.subdivision_mode == cdem::SubdivisionMode::kInPlace) {
        j["patch_deletion"] = name_in(detail::kPatchDeletion, o.patch_deletion);
        j["contact_point_mass"] = o.contact_point_mass;
      }
    }
  }
  j["mass_damping"] = o.mass_damping;
  j["check_stability"] = o.check_stability;
  j["divisions"] = c.divisions;
  return j;
}

}  // namespace

std::string write_scene(const SceneFile& file) {
  const Scene& s = file.scene;
  const bool penalty = file.model == ContactModel::kPenalty;
  ojson root = ojson::object();
  if (!s.name.empty()) root["name"] = s.name;
  if (!penalty) root["model"] = model_name(file.model);
  ojson mats = ojson::array();
  for (const Material& m : s.materials)
    mats.push_back({{"density", m.density}, {"young", m.young}, {"poisson", m.poisson}});
  root["materials"] = mats;
  ojson blocks = ojson::array();
  for (std::size_t i = 0; i < s.blocks.size(); ++i) {
    const BlockSpec& b = s.blocks[i];
    ojson jb = ojson::object();
    if (!b.name.empty()) jb["name"] = b.name;
    ojson verts = ojson::array();
    for (const Vec2& p : b.vertices) verts.push_back(vec2_json(p));
    jb["vertices"] = verts;
    jb["velocity"] = vec2_json(b.velocity);
    if (penalty) jb["spin"] = b.spin;
    jb["fixed"] = b.fixed;
    jb["material"] = b.material;
    if (penalty) jb["group"] = b.group;
    const CdemMesh mesh = i < file.cdem.meshes.size() ? file.cdem.meshes[i] : CdemMesh{};
    if (!penalty && mesh.cells_x > 0) jb["mesh"] = {{"cells", {mesh.cells_x, mesh.cells_y}}};
    else if (!penalty && mesh.divisions > 0) jb["mesh"] = {{"divisions", mesh.divisions}};
    blocks.push_back(jb);
  }
  root["blocks"] = blocks;
  if (penalty) {
    ojson bounds = ojson::array();
    for (const BoundarySegment& g : s.boundaries)
      bounds.push_back({{"a", vec2_json(g.a)}, {"b", vec2_json(g.b)}, {"depth", g.depth}, {"group", g.group}});
    root["boundaries"] = bounds;
    const ContactParams& c = s.contact;
    ojson contact = {{"kn", c.kn},
                    {"kt", c.kt},
                    {"friction_deg", c.friction_deg},
                    {"h_rule", name_of(c.h_rule)},
                    {"integration", c.integration == Integration::kExactEnvelope ? "exact_envelope" : "paper_bisector"},
                    {"small_edge_fraction", c.small_edge_fraction},
                    {"small_edge_rays", name_of(c.small_edge_rays)},
                    {"friction_update", name_of(c.friction_update)}};
    ojson rules = ojson::array();
    for (const FrictionRule& fr : c.friction_rules)
      rules.push_back({{"groups", {fr.group_a, fr.group_b}}, {"friction_deg", fr.friction_deg}});
    contact["friction_rules"] = rules;
    if (c.h_rule == HRule::kGiven) contact["h"] = c.h;
    root["contact"] = contact;
  } else {
    root["cdem"] = cdem_json(file.cdem);
  }
  root["gravity"] = vec2_json(s.gravity);
  if (penalty) {
    root["strains"] = s.strains;
    root["broad_phase"] = s.broad_phase == BroadPhase::kSweep ? "sweep" : "none";
    root["initial_overlap"] = s.initial_overlap;
  }
  // With dt_fraction > 0 the reader refuses a "dt" (it would be ignored).
  if (penalty && s.dt_fraction > 0.0) {
    root["dt_fraction"] = s.dt_fraction;
  } else {
    root["dt"] = s.dt;
    if (penalty) root["dt_fraction"] = s.dt_fraction;
  }
  root["duration"] = s.duration;
  if (file.max_steps != kDefaultMaxSteps) root["max_steps"] = file.max_steps;
  if (penalty) {
    root["guards"] = {{"max_step_motion", s.guards.max_step_motion},
                      {"max_balance_error", s.guards.max_balance_error},
                      {"max_energy_growth", s.guards.max_energy_growth},
                      {"energy_check_every", s.guards.energy_check_every},
                      {"max_penetration", s.guards.max_penetration},
                      {"max_approach_energy", s.guards.max_approach_energy}};
    root["rotation_update"] = s.rotation_update == RotationUpdate::kExact ? "exact" : "paper_linear";
    root["damping"] = {{"mass", s.damping.mass},
                       {"stiffness", s.damping.stiffness},
                       {"settle_time", s.damping.settle_time},
                       {"settle_sticking", s.damping.settle_sticking},
                       {"settle_slip_time", s.damping.settle_slip_time}};
    if (file.threads > 0) root["threads"] = file.threads;
  }
  if (file.checkpoint.every > 0.0 || file.checkpoint.every_wall > 0.0) {
    ojson c = ojson::object();
    if (file.checkpoint.every > 0.0) c["every"] = file.checkpoint.every;
    if (file.checkpoint.every_wall > 0.0) c["every_wall"] = file.checkpoint.every_wall;
    root["checkpoint"] = c;
  }
  root["output"] = {{"every", file.output.every},
                    {"snapshots", file.output.snapshot_times},
                    {"tracked_blocks", file.output.tracked_blocks},
                    {"vtk", file.output.vtk}};
  if (penalty) root["output"]["block_table"] = file.output.block_table;
  if (file.output.vtk_every > 0) root["output"]["vtk_every"] = file.output.vtk_every;
  return root.dump(2) + "\n";
}

void save_scene_file(const std::string& path, const SceneFile& file) { write_file_atomic(path, write_scene(file)); }

}  // namespace dda::io
