#include "dda/io/vtk_dda.hpp"

#include <cmath>

namespace dda::io {

namespace {

VtkArray array(const char* name, int components, bool integer, std::size_t tuples,
               std::vector<std::string> component_names = {}) {
  VtkArray a;
  a.name = name;
  a.components = components;
  a.integer = integer;
  a.values.reserve(tuples * static_cast<std::size_t>(components));
  a.component_names = std::move(component_names);
  return a;
}

void push3(VtkArray& a, double x, double y, double z = 0.0) { a.values.insert(a.values.end(), {x, y, z}); }

}  // namespace

VtkMesh block_mesh(const Simulation& sim, bool with_boundaries) {
  const int n = with_boundaries ? sim.block_count() : sim.scene_block_count();
  const std::size_t cells = static_cast<std::size_t>(n);
  VtkMesh m;
  VtkArray block = array("block", 1, true, cells), fixed = array("fixed", 1, true, cells),
           speed = array("speed", 1, false, cells), rotation = array("rotation", 1, false, cells),
           velocity = array("velocity", 3, false, cells), displacement = array("displacement", 3, false, cells),
           boundary = array("boundary", 1, true, cells), spin = array("spin", 1, false, cells),
           centroid = array("centroid", 3, false, cells),
           stress = array("stress", 3, false, cells, {"sxx", "syy", "sxy"});
  int corners[kMaxVertices];
  for (int i = 0; i < n; ++i) {
    const PolygonView p = sim.polygon_view(i);
    for (int k = 0; k < p.count; ++k) {
      corners[k] = static_cast<int>(m.points.size());
      m.points.push_back(p.vertex(k));
    }
    m.add_cell(corners, p.count);
    const Vec6& v = sim.velocity(i);
    const Vec6& d = sim.displacement(i);
    const Vec3& s = sim.stress(i);
    const Vec2 c = sim.centroid(i);
    block.values.push_back(i);
    fixed.values.push_back(sim.fixed(i) ? 1 : 0);
    speed.values.push_back(std::hypot(v[0], v[1]));
    rotation.values.push_back(d[2]);
    push3(velocity, v[0], v[1]);
    push3(displacement, d[0], d[1]);
    boundary.values.push_back(i >= sim.scene_block_count() ? 1 : 0);
    spin.values.push_back(v[2]);
    push3(centroid, c.x, c.y);
    push3(stress, s[0], s[1], s[2]);
  }
  m.cell_data = {std::move(block),    std::move(fixed),    std::move(speed),    std::move(rotation),
                 std::move(velocity), std::move(displacement), std::move(boundary), std::move(spin),
                 std::move(centroid), std::move(stress)};
  return m;
}

VtkMesh contact_mesh(const Simulation& sim) {
  const std::vector<ContactInfo>& cs = sim.contacts();
  const std::size_t n = cs.size();
  VtkMesh m;
  VtkArray block = array("block", 1, true, n), target = array("target", 1, true, n),
           normal = array("normal_force", 3, false, n), shear = array("shear_force", 3, false, n),
           penetration = array("penetration", 1, false, n), area = array("overlap_area", 1, false, n),
           length = array("contact_length", 1, false, n), couple = array("couple", 1, false, n),
           sliding = array("sliding", 1, true, n);
  for (const ContactInfo& c : cs) {
    m.add_vertex(c.point);
    block.values.push_back(c.cp);
    target.values.push_back(c.tp);
    push3(normal, c.normal_force.x, c.normal_force.y);
    push3(shear, c.tangential_force.x, c.tangential_force.y);
    penetration.values.push_back(c.ip_length > 0.0 ? c.ip_area / c.ip_length : 0.0);
    area.values.push_back(c.ip_area);
    length.values.push_back(c.ip_length);
    couple.values.push_back(c.couple);
    sliding.values.push_back(c.sliding ? 1 : 0);
  }
  m.point_data = {std::move(block),       std::move(target), std::move(normal), std::move(shear),
                  std::move(penetration), std::move(area),   std::move(length), std::move(couple),
                  std::move(sliding)};
  return m;
}

}  // namespace dda::io
