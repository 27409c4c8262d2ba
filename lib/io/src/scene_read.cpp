// Scene files, reading: the sections of the schema (lib/io/SCHEMA.md) read
// from the parsed document (json_reader.hpp) into a dda::Scene and what a
// run writes, then validated (the kernel's dda::check_scene, and what only
// matters for a file: keys that would be silently ignored).
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <tuple>

#include "dda/io/csv.hpp"
#include "dda/io/scene_file.hpp"
#include "dda/joint_sets.hpp"
#include "dda/simulation.hpp"
#include "json_reader.hpp"
#include "scene_cdem.hpp"

namespace dda::io {

using detail::describe_value;
using detail::index_path;
using detail::join_path;
using detail::json;
using detail::Reader;

namespace {

constexpr double kPi = 3.14159265358979323846;

// ---------------------------------------------------------------------------
// Sections

struct Names {
  std::vector<std::string> materials;  // optional material names
};

// Finite coordinates whose products are not: |x|, |y| beyond ~1e154 make a
// polygon's area or an edge's squared length overflow a double, which the
// kernel would misreport (as a duplicate vertex, say). Refused with the
// reason. Also catches a vertex that became infinite (x0 + w, a rotation).
void check_magnitude(const Reader& r, const std::vector<Vec2>& pts, const std::string& path) {
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (!is_finite(pts[i]))
      r.fail(path, "vertex " + std::to_string(i) + ": coordinate overflows (beyond the double range)");
  double twice_area = 0.0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Vec2 p = pts[i], q = pts[(i + 1) % pts.size()];
    const Vec2 d = q - p;
    if (!std::isfinite(d.x * d.x + d.y * d.y))
      r.fail(path, "coordinates too large: an edge's squared length overflows a double (keep |x|, |y| below 1e150 m)");
    twice_area += p.x * q.y - q.x * p.y;
  }
  if (!std::isfinite(twice_area))
    r.fail(path, "coordinates too large: the polygon's area overflows a double (keep |x|, |y| below 1e150 m)");
}

std::vector<Vec2> rect_vertices(const Reader& r, const json& v, const std::string& path) {
  if (!v.is_array() || v.size() != 4)
    r.fail(path, "expected [x0, y0, width, height] (an array of 4 numbers), got " + describe_value(v));
  double a[4];
  for (std::size_t i = 0; i < 4; ++i) a[i] = r.number(v[i], index_path(path, i));
  if (!(a[2] > 0.0 && a[3] > 0.0)) r.fail(path, "width and height must be positive");
  return {{a[0], a[1]}, {a[0] + a[2], a[1]}, {a[0] + a[2], a[1] + a[3]}, {a[0], a[1] + a[3]}};
}

Material read_material(const Reader& r, const json& v, const std::string& path, std::string& name) {
  r.object(v, path, {"name", "density", "young", "poisson"});
  Material m;
  if (const json* n = Reader::find(v, "name")) name = r.string(*n, join_path(path, "name"));
  m.density = r.number(r.need(v, path, "density"), join_path(path, "density"));
  m.young = r.number(r.need(v, path, "young"), join_path(path, "young"));
  m.poisson = r.number(r.need(v, path, "poisson"), join_path(path, "poisson"));
  return m;
}

// A material given by index or by name.
int material_ref(const Reader& r, const json& x, const std::string& mp, const Names& names) {
  if (x.is_string()) {
    const std::string name = x.get<std::string>();
    const auto it = std::find(names.materials.begin(), names.materials.end(), name);
    if (it == names.materials.end()) r.fail(mp, "no material named \"" + name + "\"");
    if (std::find(it + 1, names.materials.end(), name) != names.materials.end())
      r.fail(mp, "material name \"" + name + "\" is ambiguous (several materials have it)");
    return static_cast<int>(it - names.materials.begin());
  }
  if (x.is_number()) return r.integer(x, mp);
  r.fail(mp, "expected a material index or name, got " + describe_value(x));
}

BlockSpec read_block(const Reader& r, const json& v, const std::string& path, const Names& names) {
  r.object(v, path,
           {"name", "vertices", "rect", "rotate_deg", "about", "velocity", "spin", "fixed", "material", "group", "mesh"});
  BlockSpec b;
  const json* verts = Reader::find(v, "vertices");
  const json* rect = Reader::find(v, "rect");
  if (verts && rect) r.fail(path, "give either 'vertices' or 'rect', not both");
  if (!verts && !rect) r.fail(join_path(path, "vertices"), "missing required key (or give 'rect')");
  if (verts) {
    const std::string vp = join_path(path, "vertices");
    r.array(*verts, vp, " of [x, y] points");
    for (std::size_t i = 0; i < verts->size(); ++i) b.vertices.push_back(r.vec2((*verts)[i], index_path(vp, i)));
  } else {
    b.vertices = rect_vertices(r, *rect, join_path(path, "rect"));
  }
  check_magnitude(r, b.vertices, join_path(path, verts ? "vertices" : "rect"));
  const json* rot = Reader::find(v, "rotate_deg");
  const json* about = Reader::find(v, "about");
  if (about && !rot) r.fail(join_path(path, "about"), "only used with 'rotate_deg'");
  if (rot) {
    const double deg = r.number(*rot, join_path(path, "rotate_deg"));
    Vec2 pivot{};
    if (about) {
      pivot = r.vec2(*about, join_path(path, "about"));
    } else if (!b.vertices.empty()) {
      for (const Vec2& p : b.vertices) pivot += p;
      pivot = pivot / static_cast<double>(b.vertices.size());
    }
    const double a = deg * kPi / 180.0;
    for (Vec2& p : b.vertices) p = pivot + rotate(p - pivot, a);
    check_magnitude(r, b.vertices, join_path(path, "rotate_deg"));
  }
  r.optional(v, path, "name", b.name);
  r.optional(v, path, "velocity", b.velocity);
  r.optional(v, path, "spin", b.spin);
  r.optional(v, path, "fixed", b.fixed);
  r.optional(v, path, "group", b.group);
  if (const json* x = Reader::find(v, "material")) b.material = material_ref(r, *x, join_path(path, "material"), names);
  if (b.fixed && (b.velocity != Vec2{} || b.spin != 0.0))
    r.fail(join_path(path, Reader::find(v, "velocity") ? "velocity" : "spin"),
           "a fixed block never moves: give it no velocity or spin");
  return b;
}

BoundarySegment read_boundary(const Reader& r, const json& v, const std::string& path) {
  r.object(v, path, {"a", "b", "depth", "group"});
  BoundarySegment s;
  s.a = r.vec2(r.need(v, path, "a"), join_path(path, "a"));
  s.b = r.vec2(r.need(v, path, "b"), join_path(path, "b"));
  if (!std::isfinite((s.b.x - s.a.x) * (s.b.x - s.a.x) + (s.b.y - s.a.y) * (s.b.y - s.a.y)))
    r.fail(path, "coordinates too large: the segment's squared length overflows a double (keep |x|, |y| below 1e150 m)");
  r.optional(v, path, "depth", s.depth);
  r.optional(v, path, "group", s.group);
  return s;
}

// A "generated" entry: a region cut into convex blocks by joint sets
// (dda::generate_blocks); appends the blocks to `blocks`.
GeneratedRegion read_generated(const Reader& r, const json& v, const std::string& path, const Names& names,
                               std::vector<BlockSpec>& blocks) {
  r.object(v, path, {"name", "region", "joint_sets", "min_area", "material", "group"});
  const std::string rp = join_path(path, "region");
  const json& reg = r.array(r.need(v, path, "region"), rp, " of [x, y] points");
  std::vector<Vec2> region;
  for (std::size_t i = 0; i < reg.size(); ++i) region.push_back(r.vec2(reg[i], index_path(rp, i)));
  check_magnitude(r, region, rp);
  const std::string jp = join_path(path, "joint_sets");
  const json& js = r.array(r.need(v, path, "joint_sets"), jp, " of {\"dip_deg\", \"spacing\", \"origin\"}");
  std::vector<JointSet> sets;
  for (std::size_t i = 0; i < js.size(); ++i) {
    const std::string ep = index_path(jp, i);
    r.object(js[i], ep, {"dip_deg", "spacing", "origin"});
    JointSet j;
    j.dip_deg = r.number(r.need(js[i], ep, "dip_deg"), join_path(ep, "dip_deg"));
    j.spacing = r.number(r.need(js[i], ep, "spacing"), join_path(ep, "spacing"));
    if (const json* x = Reader::find(js[i], "origin")) j.origin = r.vec2(*x, join_path(ep, "origin"));
    sets.push_back(j);
  }
  // The generator cuts the region with every line of every set: refuse a
  // spacing that would make more than kMaxBlocks pieces before it runs (a
  // tiny spacing would otherwise take forever). Parallel families of n_k
  // lines cut a convex part into at most prod (n_k + 1) pieces.
  double pieces = std::max<double>(1.0, static_cast<double>(region.size()));  // convex parts <= vertices
  for (std::size_t k = 0; k < sets.size(); ++k) {
    const JointSet& j = sets[k];
    if (!(j.spacing > 0.0) || !(j.dip_deg > 0.0 && j.dip_deg < 180.0)) continue;  // the generator says why
    const double a = j.dip_deg * kPi / 180.0;
    const Vec2 nrm{std::sin(a), std::cos(a)};
    double lo = std::numeric_limits<double>::max(), hi = -lo;
    for (const Vec2& p : region) {
      const double d = dot(nrm, p - j.origin);
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
    // The generator counts lines k = lo / spacing ... hi / spacing in a
    // double: beyond 2^52, k + 1 == k and it would never finish (fuzzer
    // finding: an origin at 9.2e18 m).
    constexpr double kMaxLineIndex = 4503599627370496.0;  // 2^52
    if (!(std::max(std::fabs(lo), std::fabs(hi)) / j.spacing < kMaxLineIndex))
      r.fail(join_path(index_path(jp, k), "origin"),
             "too far from the region for the spacing (the region lies more than 2^52 spacings from the origin)");
    const double lines = (hi - lo) / j.spacing + 1.0;
    pieces *= lines + 1.0;
    if (!(pieces <= static_cast<double>(kMaxBlocks)))
      r.fail(join_path(index_path(jp, k), "spacing"),
             "the joint sets would cut the region into up to " + format_number(pieces) + " blocks, more than " +
                 std::to_string(kMaxBlocks) + " (the reader's limit on blocks)");
  }
  double min_area = 0.0;
  if (const json* x = Reader::find(v, "min_area")) {
    min_area = r.number(*x, join_path(path, "min_area"));
    if (!(min_area >= 0.0)) r.fail(join_path(path, "min_area"), "must be >= 0 (m^2)");
  }
  BlockSpec proto;
  if (const json* x = Reader::find(v, "material")) proto.material = material_ref(r, *x, join_path(path, "material"), names);
  r.optional(v, path, "group", proto.group);
  std::string name;
  r.optional(v, path, "name", name);
  GeneratedBlocks g;
  try {
    g = generate_blocks(region, sets, min_area);
  } catch (const std::invalid_argument& e) {
    // The generator names "region..." or "joint_sets[k]..." first.
    const std::string m = e.what();
    if (m.rfind("region", 0) == 0 || m.rfind("joint_sets", 0) == 0) r.fail("", path + "." + m);
    r.fail(path, m);
  }
  GeneratedRegion out;
  out.first_block = static_cast<int>(blocks.size());
  out.count = static_cast<int>(g.blocks.size());
  out.dropped = g.dropped;
  out.dropped_area = g.dropped_area;
  for (std::size_t k = 0; k < g.blocks.size(); ++k) {
    BlockSpec b = proto;
    b.vertices.assign(g.blocks[k].v.begin(), g.blocks[k].v.begin() + g.blocks[k].count);
    if (!name.empty()) b.name = name + "_" + std::to_string(k);
    blocks.push_back(std::move(b));
  }
  return out;
}

ContactParams read_contact(const Reader& r, const json& v, const std::string& path) {
  r.object(v, path,
           {"kn", "kt", "friction_deg", "friction_rules", "h_rule", "h", "integration", "small_edge_fraction",
            "small_edge_rays", "friction_update"});
  ContactParams c;
  c.kn = r.number(r.need(v, path, "kn"), join_path(path, "kn"));
  r.optional(v, path, "kt", c.kt);
  r.optional(v, path, "friction_deg", c.friction_deg);
  if (const json* x = Reader::find(v, "friction_rules")) {
    const std::string rp = join_path(path, "friction_rules");
    r.array(*x, rp, " of {\"groups\": [a, b], \"friction_deg\": phi}");
    for (std::size_t i = 0; i < x->size(); ++i) {
      const json& e = (*x)[i];
      const std::string ep = index_path(rp, i);
      r.object(e, ep, {"groups", "friction_deg"});
      const json& g = r.need(e, ep, "groups");
      const std::string gp = join_path(ep, "groups");
      if (!g.is_array() || g.size() != 2) r.fail(gp, "expected [a, b] (two group numbers), got " + describe_value(g));
      FrictionRule rule;
      rule.group_a = r.integer(g[0], index_path(gp, 0));
      rule.group_b = r.integer(g[1], index_path(gp, 1));
      rule.friction_deg = r.number(r.need(e, ep, "friction_deg"), join_path(ep, "friction_deg"));
      c.friction_rules.push_back(rule);
    }
  }
  if (const json* x = Reader::find(v, "h_rule"))
    c.h_rule = r.choice<HRule>(*x, join_path(path, "h_rule"),
                               {{"min_max_edge", HRule::kMinMaxEdge},
                                {"mean_edge", HRule::kMeanEdge},
                                {"given", HRule::kGiven},
                                {"inscribed_radius", HRule::kInscribedRadius}});
  if (const json* x = Reader::find(v, "h")) {
    if (c.h_rule != HRule::kGiven) r.fail(join_path(path, "h"), "only used with \"h_rule\": \"given\"");
    c.h = r.number(*x, join_path(path, "h"));
  }
  if (const json* x = Reader::find(v, "integration"))
    c.integration = r.choice<Integration>(
        *x, join_path(path, "integration"),
        {{"paper_bisector", Integration::kPaperBisector}, {"exact_envelope", Integration::kExactEnvelope}});
  r.optional(v, path, "small_edge_fraction", c.small_edge_fraction);
  if (const json* x = Reader::find(v, "small_edge_rays"))
    c.small_edge_rays = r.choice<SmallEdgeRays>(*x, join_path(path, "small_edge_rays"),
                                                {{"virtual_and_vertex", SmallEdgeRays::kVirtualAndVertex},
                                                 {"virtual_replaces_vertex", SmallEdgeRays::kVirtualReplacesVertex}});
  if (const json* x = Reader::find(v, "friction_update"))
    c.friction_update = r.choice<FrictionUpdate>(
        *x, join_path(path, "friction_update"),
        {{"paper", FrictionUpdate::kPaper}, {"return_mapping", FrictionUpdate::kReturnMapping}});
  return c;
}

// The solver's stability guards; every key optional (the kernel checks the
// ranges, with the same field names: guards.max_step_motion, ...).
StabilityGuards read_guards(const Reader& r, const json& v, const std::string& path) {
  r.object(v, path,
           {"max_step_motion", "max_balance_error", "max_energy_growth", "energy_check_every", "max_penetration",
            "max_approach_energy"});
  StabilityGuards g;
  r.optional(v, path, "max_step_motion", g.max_step_motion);
  r.optional(v, path, "max_balance_error", g.max_balance_error);
  r.optional(v, path, "max_energy_growth", g.max_energy_growth);
  r.optional(v, path, "energy_check_every", g.energy_check_every);
  r.optional(v, path, "max_penetration", g.max_penetration);
  r.optional(v, path, "max_approach_energy", g.max_approach_energy);
  return g;
}

OutputSpec read_output(const Reader& r, const json* v, const Scene& scene) {
  OutputSpec out;
  const std::string path = "output";
  const std::vector<double> default_snapshots =
      scene.duration > 0.0 ? std::vector<double>{0.0, scene.duration} : std::vector<double>{0.0};
  if (!v) {
    out.snapshot_times = default_snapshots;
    return out;
  }
  r.object(*v, path, {"every", "snapshots", "tracked_blocks", "vtk", "vtk_every", "block_table"});
  if (const json* x = Reader::find(*v, "every")) {
    out.every = r.integer(*x, "output.every");
    if (out.every < 1) r.fail("output.every", "must be >= 1 (steps between time-series rows)");
  }
  if (const json* x = Reader::find(*v, "snapshots")) {
    r.array(*x, "output.snapshots", " of times");
    for (std::size_t i = 0; i < x->size(); ++i) {
      const std::string p = index_path("output.snapshots", i);
      const double t = r.number((*x)[i], p);
      if (!(t >= 0.0 && t <= scene.duration))
        r.fail(p, "snapshot time must lie in [0, duration] = [0, " + format_number(scene.duration) + "] s");
      out.snapshot_times.push_back(t);
    }
    std::sort(out.snapshot_times.begin(), out.snapshot_times.end());
  } else {
    out.snapshot_times = default_snapshots;
  }
  if (const json* x = Reader::find(*v, "tracked_blocks")) {
    r.array(*x, "output.tracked_blocks", " of block indices or names");
    const int n = static_cast<int>(scene.blocks.size());
    for (std::size_t i = 0; i < x->size(); ++i) {
      const json& e = (*x)[i];
      const std::string p = index_path("output.tracked_blocks", i);
      int id = -1;
      if (e.is_string()) {
        const std::string name = e.get<std::string>();
        for (int k = 0; k < n; ++k)
          if (scene.blocks[static_cast<std::size_t>(k)].name == name) {
            if (id >= 0) r.fail(p, "block name \"" + name + "\" is ambiguous (several blocks have it)");
            id = k;
          }
        if (id < 0) r.fail(p, "no block named \"" + name + "\"");
      } else if (e.is_number()) {
        id = r.integer(e, p);
        if (id < 0 || id >= n)
          r.fail(p, "no block " + std::to_string(id) + " (the scene has " + std::to_string(n) + " blocks)");
      } else {
        r.fail(p, "expected a block index or name, got " + describe_value(e));
      }
      if (std::find(out.tracked_blocks.begin(), out.tracked_blocks.end(), id) != out.tracked_blocks.end())
        r.fail(p, "block " + std::to_string(id) + " is listed twice");
      out.tracked_blocks.push_back(id);
    }
  }
  if (const json* x = Reader::find(*v, "vtk")) out.vtk = r.boolean(*x, "output.vtk");
  if (const json* x = Reader::find(*v, "vtk_every")) {
    out.vtk_every = r.integer(*x, "output.vtk_every");
    if (out.vtk_every < 1) r.fail("output.vtk_every", "must be >= 1 (steps between ParaView frames)");
    if (!out.vtk) r.fail("output.vtk_every", "needs \"vtk\": true (it would be ignored)");
  }
  if (const json* x = Reader::find(*v, "block_table")) out.block_table = r.boolean(*x, "output.block_table");
  return out;
}

// " (blocks[7] is block 2 of generated[0])" for a kernel message about a
// generated block, so that the file's author can find it; "" otherwise.
std::string generated_note(const std::string& message, const std::vector<GeneratedRegion>& generated,
                           const std::vector<std::string>& paths) {
  if (generated.empty()) return "";
  std::string note;
  std::size_t pos = 0;
  while ((pos = message.find("blocks[", pos)) != std::string::npos) {
    const std::size_t end = message.find(']', pos);
    if (end == std::string::npos) break;
    int id = -1;
    try {
      id = std::stoi(message.substr(pos + 7, end - pos - 7));
    } catch (const std::exception&) {
      break;
    }
    for (std::size_t g = 0; g < generated.size(); ++g) {
      const GeneratedRegion& gr = generated[g];
      if (id >= gr.first_block && id < gr.first_block + gr.count) {
        const std::string& where = paths[g];
        note += std::string(note.empty() ? " (" : "; ") + "blocks[" + std::to_string(id) + "] is block " +
                std::to_string(id - gr.first_block) + " of " + where;
      }
    }
    pos = end;
  }
  return note.empty() ? "" : note + ")";
}

// Eq. 5c damping; every key optional (the kernel checks the ranges).
Damping read_damping(const Reader& r, const json& v, const std::string& path) {
  r.object(v, path, {"mass", "stiffness", "settle_time", "settle_sticking", "settle_slip_time"});
  Damping d;
  r.optional(v, path, "mass", d.mass);
  r.optional(v, path, "stiffness", d.stiffness);
  r.optional(v, path, "settle_time", d.settle_time);
  r.optional(v, path, "settle_sticking", d.settle_sticking);
  r.optional(v, path, "settle_slip_time", d.settle_slip_time);
  return d;
}

// Names identify blocks (output.tracked_blocks) and materials: two with one
// name would make a reference ambiguous. Empty names (unnamed) may repeat.
void check_block_names(const Reader& r, const std::vector<BlockSpec>& blocks,
                       const std::vector<GeneratedRegion>& generated, const std::vector<std::string>& generated_paths) {
  // The file path of block i's name: "blocks[i].name" or "generated[g].name".
  auto name_path = [&](std::size_t i) {
    for (std::size_t g = 0; g < generated.size(); ++g)
      if (static_cast<int>(i) >= generated[g].first_block &&
          static_cast<int>(i) < generated[g].first_block + generated[g].count)
        return join_path(generated_paths[g], "name");
    return join_path(index_path("blocks", i), "name");
  };
  std::map<std::string, std::size_t> seen;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const std::string& name = blocks[i].name;
    if (name.empty()) continue;
    const auto [it, fresh] = seen.emplace(name, i);
    if (fresh) continue;
    r.fail(name_path(i), "duplicate block name \"" + name + "\" (blocks[" + std::to_string(it->second) + "] and blocks[" +
                             std::to_string(i) + "] have it; names must be unique)");
  }
}

// Keys of one model's that a scene of the other model has no use for: an
// error naming the model, so that nothing is silently ignored.
std::string only_penalty(const std::string& what) {
  return "applies to the penalty model only (" + what + "); this scene's \"model\" is \"cdem\"";
}

void check_model_keys(const Reader& r, const json& root, bool penalty) {
  if (penalty) {
    if (Reader::find(root, "cdem"))
      r.fail("cdem", "applies to the cdem model only; this scene's \"model\" is \"penalty\" (the default): set "
                     "\"model\": \"cdem\" to use Paper B's two-scale contact");
    return;
  }
  const std::pair<const char*, const char*> penalty_keys[] = {
      {"contact", "the potential-based contact; Paper B's contact settings go in \"cdem\""},
      {"boundaries", "boundary segments; give the ground as a fixed block"},
      {"strains", "the 6-DOF block's strains; CDEM blocks are meshes of constant-strain triangles"},
      {"broad_phase", "the pair search of the penalty contact"},
      {"initial_overlap", "preloaded overlaps of the penalty contact"},
      {"dt_fraction", "the penalty model's predicted critical step; give dt"},
      {"guards", "the penalty model's stability guards"},
      {"rotation_update", "the 6-DOF block's rotation"},
      {"damping", "Eq. 5c damping of Paper A; Paper B's mass damping is cdem.mass_damping"},
      {"threads", "the penalty solver's threads; the cdem model steps on one"},
  };
  for (const auto& [key, what] : penalty_keys)
    if (Reader::find(root, key)) r.fail(key, only_penalty(what));
}

void check_block_keys(const Reader& r, const json& block, const std::string& path, bool penalty) {
  if (penalty) {
    if (Reader::find(block, "mesh"))
      r.fail(join_path(path, "mesh"), "applies to the cdem model only (the element mesh of a block); this scene's "
                                      "\"model\" is \"penalty\" (the default)");
    return;
  }
  if (Reader::find(block, "spin")) r.fail(join_path(path, "spin"), only_penalty("a 6-DOF block's initial spin"));
  if (Reader::find(block, "group")) r.fail(join_path(path, "group"), only_penalty("friction groups"));
}

// When dda run writes checkpoints.
CheckpointSpec read_checkpoint_spec(const Reader& r, const json& v) {
  r.object(v, "checkpoint", {"every", "every_wall"});
  CheckpointSpec c;
  for (const auto& [key, field, unit] :
       {std::tuple<const char*, double*, const char*>{"every", &c.every, "s of simulated time"},
        {"every_wall", &c.every_wall, "s of wall-clock time"}})
    if (const json* x = Reader::find(v, key)) {
      const std::string p = join_path("checkpoint", key);
      *field = r.number(*x, p);
      if (!(*field > 0.0)) r.fail(p, std::string("must be > 0 (") + unit + " between checkpoints; leave it out for none)");
    }
  if (!(c.every > 0.0 || c.every_wall > 0.0))
    r.fail("checkpoint", "give \"every\" (s of simulated time) or \"every_wall\" (s of wall-clock time)");
  return c;
}

}  // namespace

void check_step_count(const SceneFile& file, double dt, const std::string& label) {
  const Scene& s = file.scene;
  if (!(dt > 0.0) || !(s.duration > 0.0)) return;  // check_scene's business
  const double steps = s.duration / dt;
  if (steps <= static_cast<double>(file.max_steps)) return;
  throw SceneFileError(label + ": duration: " + format_number(s.duration) + " s at dt = " + format_number(dt) +
                       " s is " + format_number(std::ceil(steps)) + " steps, more than max_steps = " +
                       std::to_string(file.max_steps) +
                       " (a typo in duration or dt?); to allow a run this long, set \"max_steps\" in the scene file "
                       "or give dda run --max-steps N");
}

SceneFile parse_scene(const std::string& json_text, const std::string& file_label, const ReadOptions& options) {
  const Reader r(file_label, &json_text);
  if (json_text.size() > kMaxSceneFileBytes)
    throw SceneFileError(file_label + ": " + std::to_string(json_text.size()) + " bytes, more than " +
                         std::to_string(kMaxSceneFileBytes) + " (the reader's limit on scene files)");
  const json root = detail::parse_json(json_text, r);
  if (!root.is_object()) r.fail("", "the top level must be a JSON object, got " + describe_value(root));
  r.object(root, "",
           {"name", "description", "model", "materials", "blocks", "generated", "boundaries", "contact", "cdem",
            "gravity", "strains", "broad_phase", "initial_overlap", "dt", "dt_fraction", "duration", "max_steps",
            "guards", "rotation_update", "damping", "threads", "checkpoint", "output"});

  SceneFile f;
  f.text_hash = content_hash(json_text.data(), json_text.size());
  Scene& s = f.scene;
  f.model = detail::read_model(r, Reader::find(root, "model"));
  const bool penalty = f.model == ContactModel::kPenalty;
  check_model_keys(r, root, penalty);
  if (const json* x = Reader::find(root, "name")) s.name = r.string(*x, "name");
  if (const json* x = Reader::find(root, "description")) r.string(*x, "description");

  Names names;
  const json& mats = r.array(r.need(root, "", "materials"), "materials", " of materials");
  s.materials.clear();
  for (std::size_t i = 0; i < mats.size(); ++i) {
    names.materials.emplace_back();
    s.materials.push_back(read_material(r, mats[i], index_path("materials", i), names.materials.back()));
    const std::string& name = names.materials.back();
    for (std::size_t k = 0; !name.empty() && k < i; ++k)
      if (names.materials[k] == name)
        r.fail(join_path(index_path("materials", i), "name"),
               "duplicate material name \"" + name + "\" (also materials[" + std::to_string(k) + "].name)");
  }
  const json& blocks = r.array(r.need(root, "", "blocks"), "blocks", " of blocks");
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const std::string bp = index_path("blocks", i);
    s.blocks.push_back(read_block(r, blocks[i], bp, names));
    check_block_keys(r, blocks[i], bp, penalty);
    if (const json* m = Reader::find(blocks[i], "mesh")) {
      f.cdem.meshes.resize(s.blocks.size());
      f.cdem.meshes.back() = detail::read_block_mesh(r, *m, join_path(bp, "mesh"), s.blocks.back());
    }
  }
  std::vector<std::string> generated_paths;
  if (const json* x = Reader::find(root, "generated")) {
    // One generator object, or an array of them.
    if (x->is_object()) {
      generated_paths.push_back("generated");
    } else {
      r.array(*x, "generated", " of generated regions (or one object)");
      for (std::size_t i = 0; i < x->size(); ++i) generated_paths.push_back(index_path("generated", i));
    }
    for (std::size_t i = 0; i < generated_paths.size(); ++i) {
      const json& g = x->is_object() ? *x : (*x)[i];
      if (!penalty && g.is_object() && Reader::find(g, "group"))
        r.fail(join_path(generated_paths[i], "group"), only_penalty("friction groups"));
      f.generated.push_back(read_generated(r, g, generated_paths[i], names, s.blocks));
    }
  }
  if (s.blocks.size() > kMaxBlocks)
    r.fail(f.generated.empty() ? "blocks" : "generated",
           std::to_string(s.blocks.size()) + " blocks, more than " + std::to_string(kMaxBlocks) +
               " (the reader's limit on blocks)");
  check_block_names(r, s.blocks, f.generated, generated_paths);
  if (const json* x = Reader::find(root, "boundaries")) {
    r.array(*x, "boundaries", " of segments");
    for (std::size_t i = 0; i < x->size(); ++i)
      s.boundaries.push_back(read_boundary(r, (*x)[i], index_path("boundaries", i)));
  }
  if (penalty) s.contact = read_contact(r, r.need(root, "", "contact"), "contact");
  {
    // Blocks without a "mesh" (and generated ones) take cdem.divisions.
    CdemSettings cdem = detail::read_cdem(r, Reader::find(root, "cdem"));
    cdem.meshes = std::move(f.cdem.meshes);
    cdem.meshes.resize(s.blocks.size());
    f.cdem = std::move(cdem);
  }
  if (const json* x = Reader::find(root, "gravity")) s.gravity = r.vec2(*x, "gravity");
  if (const json* x = Reader::find(root, "strains")) s.strains = r.boolean(*x, "strains");
  if (const json* x = Reader::find(root, "broad_phase"))
    s.broad_phase = r.choice<BroadPhase>(*x, "broad_phase", {{"none", BroadPhase::kNone}, {"sweep", BroadPhase::kSweep}});
  if (const json* x = Reader::find(root, "initial_overlap")) s.initial_overlap = r.number(*x, "initial_overlap");
  // The step: "dt", or "dt_fraction" > 0 (a fraction of the predicted
  // critical step, which replaces dt when the simulation is built; a "dt"
  // next to it would be silently ignored).
  if (const json* x = Reader::find(root, "dt_fraction")) {
    s.dt_fraction = r.number(*x, "dt_fraction");
    if (!(s.dt_fraction >= 0.0))
      r.fail("dt_fraction", "must be >= 0 (0: the step is dt; > 0: this fraction of the predicted critical step)");
  }
  if (s.dt_fraction > 0.0) {
    if (Reader::find(root, "dt"))
      r.fail("dt", "has no effect with dt_fraction > 0 (the step is dt_fraction times the predicted critical step); "
                   "give one of them");
  } else {
    s.dt = r.number(r.need(root, "", "dt"), "dt");
  }
  s.duration = r.number(r.need(root, "", "duration"), "duration");
  f.max_steps = kDefaultMaxSteps;
  if (const json* x = Reader::find(root, "max_steps")) {
    f.max_steps = r.int64(*x, "max_steps");
    if (f.max_steps < 1) r.fail("max_steps", "must be >= 1 (the most steps a run may take)");
  }
  if (options.max_steps > 0) f.max_steps = options.max_steps;
  if (const json* x = Reader::find(root, "guards")) s.guards = read_guards(r, *x, "guards");
  if (const json* x = Reader::find(root, "rotation_update"))
    s.rotation_update = r.choice<RotationUpdate>(
        *x, "rotation_update", {{"paper_linear", RotationUpdate::kPaperLinear}, {"exact", RotationUpdate::kExact}});
  if (const json* x = Reader::find(root, "damping")) s.damping = read_damping(r, *x, "damping");
  if (const json* x = Reader::find(root, "threads")) {
    f.threads = r.integer(*x, "threads");
    if (f.threads < 1 || f.threads > kMaxThreads)
      r.fail("threads", "must lie in [1, " + std::to_string(kMaxThreads) + "] (the solver's threads; 1 by default)");
  }
  if (const json* x = Reader::find(root, "checkpoint")) f.checkpoint = read_checkpoint_spec(r, *x);

  // The kernel's semantic checks (polygons, ranges, overlaps at t = 0).
  try {
    check_scene(s);
  } catch (const SceneError& e) {
    // The kernel's message starts with the field ("blocks[1].vertices: ...").
    const std::string m = e.what();
    const std::size_t colon = m.find(": ");
    throw SceneFileError(r.where(colon == std::string::npos ? "" : m.substr(0, colon)) + ": " + m +
                         generated_note(m, f.generated, generated_paths));
  }
  if (s.dt_fraction == 0.0) check_step_count(f, s.dt, file_label);
  // Consistency that only matters for a file: a friction angle or update rule
  // that would be silently ignored.
  if (!s.contact.friction()) {
    if (s.contact.friction_deg > 0.0)
      r.fail("contact.friction_deg", "has no effect with contact.kt = 0 (kt > 0 switches friction on)");
    if (!s.contact.friction_rules.empty())
      r.fail("contact.friction_rules", "have no effect with contact.kt = 0 (kt > 0 switches friction on)");
    if (s.contact.friction_update != FrictionUpdate::kPaper)
      r.fail("contact.friction_update", "has no effect with contact.kt = 0 (kt > 0 switches friction on)");
  }
  f.output = read_output(r, Reader::find(root, "output"), s);
  if (!penalty && f.output.block_table)
    r.fail("output.block_table", only_penalty("the per-block table of 6-DOF blocks: rotation, spin, stress"));
  if (!penalty) detail::check_cdem(r, f);  // meshes, options, dt against the mesh's critical step
  return f;
}


SceneFile load_scene_file(const std::string& path, const ReadOptions& options) {
  return parse_scene(detail::read_text_file(path), path, options);
}

}  // namespace dda::io
