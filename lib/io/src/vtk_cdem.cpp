#include "dda/io/vtk_cdem.hpp"

#include <cstring>
#include <map>
#include <tuple>
#include <unordered_map>

namespace dda::io {

namespace {

VtkArray array(const char* name, int components, bool integer, std::vector<std::string> component_names = {}) {
  VtkArray a;
  a.name = name;
  a.components = components;
  a.integer = integer;
  a.component_names = std::move(component_names);
  return a;
}

void push3(VtkArray& a, Vec2 v) { a.values.insert(a.values.end(), {v.x, v.y, 0.0}); }

int kind_code(cdem::NodeKind k) {
  switch (k) {
    case cdem::NodeKind::kCoarse: return 0;
    case cdem::NodeKind::kFine: return 1;
    case cdem::NodeKind::kHanging: return 2;
    case cdem::NodeKind::kDead: break;
  }
  return -1;  // a dead node is no element's corner
}

constexpr int kSubNodeKind = 3;

}  // namespace

VtkMesh element_mesh(const cdem::Model& model) {
  const cdem::Snapshot snap = model.snapshot();
  VtkMesh m;
  VtkArray p_node = array("node", 1, true), p_block = array("block", 1, true), p_kind = array("kind", 1, true),
           p_velocity = array("velocity", 3, false);
  VtkArray c_block = array("block", 1, true), c_fine = array("fine", 1, true), c_velocity = array("velocity", 3, false),
           c_stress = array("stress", 3, false, {"sxx", "syy", "sxy"});
  std::unordered_map<int, int> node_point;  // model node -> point
  // Sub-model sub-nodes have no id: one point per (block, exact position).
  std::map<std::tuple<int, double, double>, int> sub_point;
  auto add_point = [&](Vec2 x, Vec2 v, int node, int block, int kind) {
    const int p = static_cast<int>(m.points.size());
    m.points.push_back(x);
    p_node.values.push_back(node);
    p_block.values.push_back(block);
    p_kind.values.push_back(kind);
    push3(p_velocity, v);
    return p;
  };
  for (const cdem::Snapshot::Tri& t : snap.tris) {
    int corners[3];
    for (int k = 0; k < 3; ++k) {
      const int node = t.node[static_cast<std::size_t>(k)];
      const Vec2 x = t.x[static_cast<std::size_t>(k)], v = t.v[static_cast<std::size_t>(k)];
      if (node >= 0) {
        const auto it = node_point.find(node);
        corners[k] = it != node_point.end()
                         ? it->second
                         : node_point[node] = add_point(model.node_position(node), model.node_velocity(node), node,
                                                        model.node_block(node), kind_code(model.node_kind(node)));
      } else {
        const auto key = std::make_tuple(t.block, x.x, x.y);
        const auto it = sub_point.find(key);
        corners[k] = it != sub_point.end() ? it->second : sub_point[key] = add_point(x, v, -1, t.block, kSubNodeKind);
      }
    }
    m.add_cell(corners, 3);
    c_block.values.push_back(t.block);
    c_fine.values.push_back(t.fine ? 1 : 0);
    push3(c_velocity, t.velocity);
    c_stress.values.insert(c_stress.values.end(), {t.stress[0], t.stress[1], t.stress[2]});
  }
  m.point_data = {std::move(p_node), std::move(p_block), std::move(p_kind), std::move(p_velocity)};
  m.cell_data = {std::move(c_block), std::move(c_fine), std::move(c_velocity), std::move(c_stress)};
  return m;
}

VtkMesh contact_mesh(const cdem::Model& model) {
  VtkMesh m;
  VtkArray node = array("node", 1, true), block = array("block", 1, true), target = array("target", 1, true),
           force = array("force", 3, false), normal_force = array("normal_force", 3, false),
           shear_force = array("shear_force", 3, false), penetration = array("penetration", 1, false),
           fine = array("fine", 1, true);
  auto add = [&](Vec2 at, int main, int target_block, Vec2 f, Vec2 n, double depth, bool is_fine) {
    m.add_vertex(at);
    node.values.push_back(main);
    block.values.push_back(model.node_block(main));
    target.values.push_back(target_block);
    const Vec2 fn = dot(f, n) * n;
    push3(force, f);
    push3(normal_force, fn);
    push3(shear_force, f - fn);
    penetration.values.push_back(depth);
    fine.values.push_back(is_fine ? 1 : 0);
  };
  for (const cdem::CloneView& c : model.clones()) {
    Vec2 tied{};
    for (int q = 0; q < 2; ++q)
      if (c.target[static_cast<std::size_t>(q)] >= 0)
        tied += c.weight[static_cast<std::size_t>(q)] * model.node_position(c.target[static_cast<std::size_t>(q)]);
    add(c.point, c.main_node, model.node_block(c.target[0]), c.force, c.normal, -dot(c.point - tied, c.normal), c.fine);
  }
  for (const cdem::Model::PenaltyContact& c : model.penalty_contacts())
    add(model.node_position(c.node), c.node, model.node_block(c.a), (model.penalty_kn() * c.depth) * c.normal, c.normal,
        c.depth, false);
  m.point_data = {std::move(node),        std::move(block),       std::move(target),
                  std::move(force),       std::move(normal_force), std::move(shear_force),
                  std::move(penetration), std::move(fine)};
  return m;
}

}  // namespace dda::io
