// Scene files, Paper B's model: the "cdem" section (the two-scale contact's
// options, the conventional node-to-edge penalty baseline, the meshes) and
// the CDEM scene built from a file. Options that do nothing in the chosen
// configuration are refused, as the penalty model's are (scene_read.cpp).
#include "scene_cdem.hpp"

#include <cmath>

#include "dda/cdem/mesh.hpp"
#include "scene_names.hpp"

namespace dda::io {

const char* model_name(ContactModel m) { return m == ContactModel::kCdem ? "cdem" : "penalty"; }

namespace detail {

ContactModel read_model(const Reader& r, const json* v) {
  if (!v) return ContactModel::kPenalty;
  return r.choice<ContactModel>(*v, "model", {{"penalty", ContactModel::kPenalty}, {"cdem", ContactModel::kCdem}});
}

namespace {

// A key of the "cdem" section that does nothing in this configuration.
void refuse_if(const Reader& r, const json& v, const char* key, bool refuse, const std::string& why) {
  if (refuse && Reader::find(v, key)) r.fail(join_path("cdem", key), why);
}

}  // namespace

CdemSettings read_cdem(const Reader& r, const json* v) {
  CdemSettings s;
  if (!v) return s;
  const std::string path = "cdem";
  r.object(*v, path,
           {"contact", "penalty_kn", "touch_impact", "tolerance", "strength", "subdivision", "subdivision_mode",
            "min_subdivision", "max_subdivision", "substep_safety", "patch_deletion", "contact_point_mass",
            "mass_damping", "check_stability", "divisions"});
  cdem::CdemOptions& o = s.options;
  auto number = [&](const char* key, double& x) {
    if (const json* j = Reader::find(*v, key)) x = r.number(*j, join_path(path, key));
  };
  auto integer = [&](const char* key, int& x) {
    if (const json* j = Reader::find(*v, key)) x = r.integer(*j, join_path(path, key));
  };
  if (const json* x = Reader::find(*v, "contact")) o.contact = r.choice(*x, join_path(path, "contact"), kCdemContact);
  const bool two_scale = o.contact == cdem::ContactMode::kTwoScale;
  // The node-to-edge penalty baseline has no touches, clones or subdivision.
  if (!two_scale) {
    o.subdivision = false;
    const std::string why = "applies to the two-scale contact only (\"contact\": \"node_to_edge_penalty\" has no "
                            "touches, clone nodes or local subdivision)";
    for (const char* key : {"touch_impact", "strength", "subdivision", "subdivision_mode", "min_subdivision",
                            "max_subdivision", "substep_safety", "patch_deletion", "contact_point_mass"})
      refuse_if(r, *v, key, true, why);
  }
  refuse_if(r, *v, "penalty_kn", two_scale,
            "applies to \"contact\": \"node_to_edge_penalty\" only (the two-scale contact has no penalty spring)");
  number("penalty_kn", o.penalty_kn);
  if (const json* x = Reader::find(*v, "touch_impact"))
    o.touch_impact = r.choice(*x, join_path(path, "touch_impact"), kTouchImpact);
  number("tolerance", o.tolerance);
  if (const json* x = Reader::find(*v, "strength")) {
    const std::string sp = join_path(path, "strength");
    r.object(*x, sp, {"tensile", "cohesion", "friction_deg"});
    for (const auto& [key, field] : {std::pair<const char*, double*>{"tensile", &o.strength.tensile},
                                     {"cohesion", &o.strength.cohesion},
                                     {"friction_deg", &o.strength.friction_deg}})
      if (const json* y = Reader::find(*x, key)) *field = r.number(*y, join_path(sp, key));
  }
  if (const json* x = Reader::find(*v, "subdivision")) o.subdivision = r.boolean(*x, join_path(path, "subdivision"));
  const std::string off = "has no effect with \"subdivision\": false";
  for (const char* key :
       {"subdivision_mode", "min_subdivision", "max_subdivision", "substep_safety", "patch_deletion", "contact_point_mass"})
    refuse_if(r, *v, key, two_scale && !o.subdivision, off);
  if (const json* x = Reader::find(*v, "subdivision_mode"))
    o.subdivision_mode = r.choice(*x, join_path(path, "subdivision_mode"), kSubdivisionMode);
  const bool submodel = o.subdivision_mode == cdem::SubdivisionMode::kSubModel;
  const std::string in_place = "applies to \"subdivision_mode\": \"in_place\" only (the sub-model of Sect. 5 keeps "
                               "the coarse elements and their contact masses)";
  refuse_if(r, *v, "patch_deletion", o.subdivision && submodel, in_place);
  refuse_if(r, *v, "contact_point_mass", o.subdivision && submodel, in_place);
  integer("min_subdivision", o.min_subdivision);
  integer("max_subdivision", o.max_subdivision);
  number("substep_safety", o.substep_safety);
  if (const json* x = Reader::find(*v, "patch_deletion"))
    o.patch_deletion = r.choice(*x, join_path(path, "patch_deletion"), kPatchDeletion);
  number("contact_point_mass", o.contact_point_mass);
  number("mass_damping", o.mass_damping);
  if (const json* x = Reader::find(*v, "check_stability"))
    o.check_stability = r.boolean(*x, join_path(path, "check_stability"));
  integer("divisions", s.divisions);
  if (s.divisions < 1 || s.divisions > 64) r.fail(join_path(path, "divisions"), "must lie in [1, 64]");
  return s;
}

CdemMesh read_block_mesh(const Reader& r, const json& v, const std::string& path, const BlockSpec& block) {
  r.object(v, path, {"divisions", "cells"});
  CdemMesh m;
  const json* div = Reader::find(v, "divisions");
  const json* cells = Reader::find(v, "cells");
  if (div && cells) r.fail(path, "give either 'divisions' or 'cells', not both");
  if (!div && !cells) r.fail(path, "give 'divisions' (a fan mesh of the polygon) or 'cells' (a rectangle's grid)");
  if (div) {
    m.divisions = r.integer(*div, join_path(path, "divisions"));
    if (m.divisions < 1 || m.divisions > 64) r.fail(join_path(path, "divisions"), "must lie in [1, 64]");
    return m;
  }
  const std::string cp = join_path(path, "cells");
  if (!cells->is_array() || cells->size() != 2)
    r.fail(cp, "expected [nx, ny] (cells along x and y), got " + describe_value(*cells));
  m.cells_x = r.integer((*cells)[0], index_path(cp, 0));
  m.cells_y = r.integer((*cells)[1], index_path(cp, 1));
  if (m.cells_x < 1 || m.cells_y < 1 || m.cells_x > 1000 || m.cells_y > 1000)
    r.fail(cp, "cells must lie in [1, 1000] along each axis");
  // mesh_rectangle's corners, counter-clockwise from the lower left, must be
  // the block's vertices (as "rect" gives them).
  const std::vector<Vec2>& p = block.vertices;
  const bool rectangle = p.size() == 4 && p[0].y == p[1].y && p[1].x == p[2].x && p[2].y == p[3].y &&
                         p[3].x == p[0].x && p[1].x > p[0].x && p[3].y > p[0].y;
  if (!rectangle)
    r.fail(cp, "needs an axis-aligned rectangle listed counter-clockwise from its lower-left corner (give the block "
               "as \"rect\" without \"rotate_deg\")");
  return m;
}

}  // namespace detail

cdem::CdemScene cdem_scene(const SceneFile& file) {
  const Scene& s = file.scene;
  cdem::CdemScene c;
  c.name = s.name;
  c.materials = s.materials;
  c.gravity = s.gravity;
  c.dt = s.dt;
  c.duration = s.duration;
  c.options = file.cdem.options;
  for (std::size_t i = 0; i < s.blocks.size(); ++i) {
    const BlockSpec& b = s.blocks[i];
    const CdemMesh mesh = i < file.cdem.meshes.size() ? file.cdem.meshes[i] : CdemMesh{};
    cdem::CdemBlock cb;
    cb.outline = b.vertices;
    cb.divisions = mesh.divisions > 0 ? mesh.divisions : file.cdem.divisions;
    if (mesh.cells_x > 0)
      cb.mesh = cdem::mesh_rectangle(b.vertices[0], b.vertices[1].x - b.vertices[0].x, b.vertices[3].y - b.vertices[0].y,
                                     mesh.cells_x, mesh.cells_y);
    cb.velocity = b.velocity;
    cb.fixed = b.fixed;
    cb.material = b.material;
    cb.name = b.name;
    c.blocks.push_back(std::move(cb));
  }
  return c;
}

namespace detail {

void check_cdem(const Reader& r, const SceneFile& file) {
  try {
    const cdem::Model model(cdem_scene(file));
  } catch (const SceneError& e) {
    // The model names its fields as CdemScene has them: "options.x" is the
    // file's "cdem.x", a block's "outline" its "vertices", "divisions" and
    // "mesh" its "mesh".
    std::string m = e.what();
    if (m.rfind("options.", 0) == 0) m = "cdem." + m.substr(8);
    for (const auto& [from, to] : {std::pair<const char*, const char*>{".outline", ".vertices"},
                                   {".divisions:", ".mesh.divisions:"},
                                   {".mesh.nodes", ".mesh"},
                                   {".mesh.triangles", ".mesh"}}) {
      const std::size_t at = m.find(from);
      if (at != std::string::npos && at < m.find(": ")) m.replace(at, std::string(from).size(), to);
    }
    const std::size_t colon = m.find(": ");
    const std::string field = colon == std::string::npos ? "" : m.substr(0, colon);
    throw SceneFileError(r.where(field) + ": " + m);
  }
}

}  // namespace detail

}  // namespace dda::io
