// Scene files, writing: a SceneFile as the JSON text the reader takes back
// (every key written out, numbers in shortest round-trip form).
#include <nlohmann/json.hpp>

#include "dda/io/csv.hpp"
#include "dda/io/scene_file.hpp"

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

std::string write_scene(const SceneFile& file) {
  const Scene& s = file.scene;
  ojson root = ojson::object();
  if (!s.name.empty()) root["name"] = s.name;
  ojson mats = ojson::array();
  for (const Material& m : s.materials)
    mats.push_back({{"density", m.density}, {"young", m.young}, {"poisson", m.poisson}});
  root["materials"] = mats;
  ojson blocks = ojson::array();
  for (const BlockSpec& b : s.blocks) {
    ojson jb = ojson::object();
    if (!b.name.empty()) jb["name"] = b.name;
    ojson verts = ojson::array();
    for (const Vec2& p : b.vertices) verts.push_back(vec2_json(p));
    jb["vertices"] = verts;
    jb["velocity"] = vec2_json(b.velocity);
    jb["spin"] = b.spin;
    jb["fixed"] = b.fixed;
    jb["material"] = b.material;
    jb["group"] = b.group;
    blocks.push_back(jb);
  }
  root["blocks"] = blocks;
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
  root["gravity"] = vec2_json(s.gravity);
  root["strains"] = s.strains;
  root["broad_phase"] = s.broad_phase == BroadPhase::kSweep ? "sweep" : "none";
  root["initial_overlap"] = s.initial_overlap;
  // With dt_fraction > 0 the reader refuses a "dt" (it would be ignored).
  if (s.dt_fraction > 0.0) {
    root["dt_fraction"] = s.dt_fraction;
  } else {
    root["dt"] = s.dt;
    root["dt_fraction"] = s.dt_fraction;
  }
  root["duration"] = s.duration;
  if (file.max_steps != kDefaultMaxSteps) root["max_steps"] = file.max_steps;
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
  root["output"] = {{"every", file.output.every},
                    {"snapshots", file.output.snapshot_times},
                    {"tracked_blocks", file.output.tracked_blocks}};
  return root.dump(2) + "\n";
}

void save_scene_file(const std::string& path, const SceneFile& file) { write_file_atomic(path, write_scene(file)); }

}  // namespace dda::io
