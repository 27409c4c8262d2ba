#include "dda/cdem/mesh.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <utility>

namespace dda::cdem {

std::vector<std::array<int, 3>> lattice_triangles(int k) {
  std::vector<std::array<int, 3>> t;
  t.reserve(static_cast<std::size_t>(k * k));
  for (int j = 0; j < k; ++j)
    for (int i = 0; i + j < k; ++i) {
      t.push_back({lattice_index(i, j, k), lattice_index(i + 1, j, k), lattice_index(i, j + 1, k)});
      if (i + j + 2 <= k)
        t.push_back({lattice_index(i + 1, j, k), lattice_index(i + 1, j + 1, k), lattice_index(i, j + 1, k)});
    }
  return t;
}

TriMesh mesh_convex_polygon(const std::vector<Vec2>& outline, int divisions) {
  const int n = static_cast<int>(outline.size());
  if (n < 3) throw std::invalid_argument("mesh_convex_polygon: fewer than 3 points");
  if (divisions < 1) throw std::invalid_argument("mesh_convex_polygon: divisions must be >= 1");
  const int k = divisions;
  TriMesh mesh;
  mesh.nodes = outline;
  std::vector<std::array<int, 3>> base;
  if (n == 3) {
    base.push_back({0, 1, 2});
  } else {
    Vec2 c{};
    for (const Vec2& p : outline) c += p;  // vertex mean: inside a convex polygon
    mesh.nodes.push_back(c / static_cast<double>(n));
    for (int i = 0; i < n; ++i) base.push_back({n, i, (i + 1) % n});
  }
  // Interior nodes of each base edge, ordered from the lower to the higher id.
  std::map<std::pair<int, int>, std::vector<int>> edge_nodes;
  auto edge = [&](int a, int b) -> std::vector<int> {
    const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
    auto it = edge_nodes.find(key);
    if (it == edge_nodes.end()) {
      std::vector<int> ids;
      const Vec2 p = mesh.nodes[static_cast<std::size_t>(key.first)];
      const Vec2 q = mesh.nodes[static_cast<std::size_t>(key.second)];
      for (int t = 1; t < k; ++t) {
        ids.push_back(static_cast<int>(mesh.nodes.size()));
        mesh.nodes.push_back(lerp(p, q, static_cast<double>(t) / k));
      }
      it = edge_nodes.emplace(key, std::move(ids)).first;
    }
    std::vector<int> ids = it->second;
    if (a > b) std::reverse(ids.begin(), ids.end());
    return ids;
  };
  const auto sub = lattice_triangles(k);
  for (const auto& tri : base) {
    const Vec2 v0 = mesh.nodes[static_cast<std::size_t>(tri[0])];
    const Vec2 v1 = mesh.nodes[static_cast<std::size_t>(tri[1])];
    const Vec2 v2 = mesh.nodes[static_cast<std::size_t>(tri[2])];
    const std::vector<int> e01 = edge(tri[0], tri[1]), e12 = edge(tri[1], tri[2]), e02 = edge(tri[0], tri[2]);
    std::vector<int> lat(static_cast<std::size_t>(lattice_count(k)));
    for (int j = 0; j <= k; ++j)
      for (int i = 0; i + j <= k; ++i) {
        int id = lattice_boundary_node(i, j, k, tri, e01, e12, e02);
        if (id < 0) {
          id = static_cast<int>(mesh.nodes.size());
          mesh.nodes.push_back(v0 + (static_cast<double>(i) / k) * (v1 - v0) +
                               (static_cast<double>(j) / k) * (v2 - v0));
        }
        lat[static_cast<std::size_t>(lattice_index(i, j, k))] = id;
      }
    for (const auto& s : sub)
      mesh.triangles.push_back({lat[static_cast<std::size_t>(s[0])], lat[static_cast<std::size_t>(s[1])],
                                lat[static_cast<std::size_t>(s[2])]});
  }
  return mesh;
}

TriMesh mesh_rectangle(Vec2 lo, double lx, double ly, int nx, int ny) {
  if (nx < 1 || ny < 1) throw std::invalid_argument("mesh_rectangle: nx and ny must be >= 1");
  if (!(lx > 0.0) || !(ly > 0.0)) throw std::invalid_argument("mesh_rectangle: lx and ly must be positive");
  TriMesh mesh;
  // Grid point (i, j) -> node id: the four corners first (CCW from lo).
  std::vector<int> id(static_cast<std::size_t>((nx + 1) * (ny + 1)), -1);
  auto at = [&](int i, int j) -> int& { return id[static_cast<std::size_t>(j * (nx + 1) + i)]; };
  auto point = [&](int i, int j) {
    return Vec2{lo.x + lx * static_cast<double>(i) / nx, lo.y + ly * static_cast<double>(j) / ny};
  };
  const int corner[4][2] = {{0, 0}, {nx, 0}, {nx, ny}, {0, ny}};
  for (const auto& c : corner) {
    at(c[0], c[1]) = static_cast<int>(mesh.nodes.size());
    mesh.nodes.push_back(point(c[0], c[1]));
  }
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      if (at(i, j) < 0) {
        at(i, j) = static_cast<int>(mesh.nodes.size());
        mesh.nodes.push_back(point(i, j));
      }
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      if ((i + j) % 2 == 0) {  // diagonal a-c
        mesh.triangles.push_back({a, b, c});
        mesh.triangles.push_back({a, c, d});
      } else {  // diagonal b-d
        mesh.triangles.push_back({a, b, d});
        mesh.triangles.push_back({b, c, d});
      }
    }
  return mesh;
}

}  // namespace dda::cdem
