#include "dda/robustness_scenes.hpp"

#include <algorithm>
#include <cmath>

#include "dda/overlap.hpp"
#include "dda/potential.hpp"
#include "scene_blocks.hpp"

namespace dda::paper {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kG = 9.81;  // m/s^2

// Table 5 material and normal penalty, shared by Sects. 5.1-5.3.
Scene table5_scene(const char* name, double dt, double duration) {
  Scene s;
  s.name = name;
  s.materials = {{2000.0, 1e9, 0.25}};
  s.contact.kn = 50e6;
  s.contact.kt = 0.0;  // frictionless: see the header
  s.dt = dt;
  s.duration = duration;
  return s;
}

}  // namespace

BouncingBlock bouncing_block(double b_height, HRule h_rule, double duration) {
  BouncingBlock bb;
  bb.b_height = b_height;
  Scene& s = bb.scene = table5_scene("5.1 bouncing block (reconstructed)", 1e-4, duration);
  s.gravity = {0.0, -kG};
  s.contact.h_rule = h_rule;
  const double half_w = 2.0;  // B is 4 m wide
  const double a = 1.0;       // A is a 1 m square
  s.blocks = {
      block({{-half_w, -b_height}, {half_w, -b_height}, {half_w, 0.0}, {-half_w, 0.0}}, {}, true, 0, "B"),
      block({{-0.5 * a, bb.drop}, {0.5 * a, bb.drop}, {0.5 * a, bb.drop + a}, {-0.5 * a, bb.drop + a}}, {}, false, 0,
            "A"),
  };
  return bb;
}

SmallAngleTriangles small_angle_triangles(double angle_deg, double duration, TriangleLayout layout) {
  SmallAngleTriangles st;
  st.angle_deg = angle_deg;
  st.layout = layout;
  Scene& s = st.scene = table5_scene("5.2 small-angle triangles (reconstructed)", 2e-5, duration);
  const double len = 1.0, gap = 0.01;
  const double half = 0.5 * angle_deg * kPi / 180.0;
  const double w = len * std::tan(half);  // half width of the base
  std::vector<Vec2> t0;                   // CCW, apex first
  if (layout == TriangleLayout::kLongSidesFacing) {
    // Apex at (a, -s) pointing right; its upper side y = (a - x) w / len - s
    // and block 1's lower side (the point image) are parallel, 2 s - 2 a w / len
    // apart: s sets that gap.
    const double a = 0.25, s_off = a * w / len + 0.5 * gap;
    t0 = {{a, -s_off}, {a - len, w - s_off}, {a - len, -w - s_off}};
  } else {
    t0 = {{0.0, 0.0}, {-w, -len}, {w, -len}};
    const double tilt = 0.2 * angle_deg * kPi / 180.0;
    for (Vec2& p : t0) p = rotate(p, tilt) + Vec2{0.0, -0.5 * gap};
  }
  // Point image through the centre (0, 0): a rotation by 180 deg keeps CCW.
  std::vector<Vec2> t1;
  for (const Vec2& p : t0) t1.push_back(-p);
  s.blocks = {block(t0, {0.0, 1.0}, false, 0, "lower"), block(t1, {0.0, -1.0}, false, 0, "upper")};
  st.centre = {0.0, 0.0};
  st.apex = {0, 0};
  return st;
}

SmallEdgeImpact small_edge_impact(SmallEdgeCase which, double small_edge, double duration) {
  SmallEdgeImpact si;
  si.small_edge = small_edge;
  Scene& s = si.scene = table5_scene(
      which == SmallEdgeCase::kOnSmallEdge ? "5.3a vertex on the small edge (reconstructed)"
                                           : "5.3b vertex on the edge next to the small edge (reconstructed)",
      1e-4, duration);
  s.gravity = {0.0, -kG};
  const double e2 = 0.5 * small_edge;
  const std::vector<Vec2> lower = {{-0.5, 0.0}, {0.5, 0.0}, {0.5, 0.7}, {e2, 1.0}, {-e2, 1.0}, {-0.5, 0.7}};
  // Surface height of the lower block at x (top of the roof).
  const double slope = 0.3 / (0.5 - e2);
  auto surface = [&](double x) { return std::fabs(x) <= e2 ? 1.0 : 1.0 - (std::fabs(x) - e2) * slope; };
  const double x_hit = which == SmallEdgeCase::kOnSmallEdge ? 0.0 : e2 + 0.02;
  si.hit_point = {x_hit, surface(x_hit)};
  si.mirror_symmetric = which == SmallEdgeCase::kOnSmallEdge;
  const double gap = 0.01, h = 0.5 / std::sqrt(2.0);  // half diagonal of the 0.5 m square
  const Vec2 p = si.hit_point + Vec2{0.0, gap};
  const std::vector<Vec2> upper = {p, p + Vec2{h, h}, p + Vec2{0.0, 2.0 * h}, p + Vec2{-h, h}};
  s.blocks = {block(lower, {}, true, 0, "lower"), block(upper, {0.0, -1.0}, false, 0, "upper")};
  si.contact_vertex = 0;
  return si;
}

double overlap_thickness(const Polygon& a, const Polygon& b) {
  const double tol = pair_tolerance(a, b);
  if (overlap_state(a, b, tol) != OverlapState::kOverlapping) return 0.0;
  const Polygon ip = intersection_polygon(a, b, tol);
  return ip.count >= 3 ? 2.0 * inscribed_circle(ip).radius : 0.0;
}

double vertex_depth(const Polygon& a, const Polygon& b) {
  double d = 0.0;
  for (int i = 0; i < a.count; ++i) d = std::max(d, exit_distance(b, a.vertex(i)));
  for (int i = 0; i < b.count; ++i) d = std::max(d, exit_distance(a, b.vertex(i)));
  return d;
}

double point_symmetry_error(const Polygon& a, const Polygon& b, Vec2 centre) {
  double e = 0.0;
  for (int k = 0; k < std::min(a.count, b.count); ++k) e = std::max(e, length(a.vertex(k) + b.vertex(k) - 2.0 * centre));
  return e;
}

double mirror_symmetry_error(const Simulation& sim, int block, double x0) {
  const Polygon& p = sim.polygon(block);
  const Vec2 c = sim.centroid(block);
  double r = 0.0;
  for (int k = 0; k < p.count; ++k) r = std::max(r, length(p.vertex(k) - c));
  return std::max(std::fabs(c.x - x0), std::fabs(sim.displacement(block)[2]) * r);
}

RunMonitor::RunMonitor(const Simulation& sim, int a, int b) : sim_(&sim), a_(a), b_(b) {
  const Energy e = sim.energy();
  e0_ = e.total();
  e_mech_ = e.kinetic + e.strain + e.contact;
}

void RunMonitor::sample() {
  const Simulation& sim = *sim_;
  const Energy e = sim.energy();
  e_mech_ = std::max(e_mech_, e.kinetic + e.strain + e.contact);
  max_dev_ = std::max(max_dev_, std::fabs(e.total() - e0_));
  max_growth_ = std::max(max_growth_, e.total() - e0_);
  stats_.energy_error = e_mech_ > 0.0 ? max_dev_ / e_mech_ : 0.0;
  stats_.energy_growth = e_mech_ > 0.0 ? max_growth_ / e_mech_ : 0.0;
  const double th = overlap_thickness(sim.polygon(a_), sim.polygon(b_));
  stats_.peak_thickness = std::max(stats_.peak_thickness, th);
  stats_.peak_vertex_depth = std::max(stats_.peak_vertex_depth, vertex_depth(sim.polygon(a_), sim.polygon(b_)));
  bool touching = false;
  for (const ContactInfo& c : sim.contacts())
    if ((c.cp == a_ && c.tp == b_) || (c.cp == b_ && c.tp == a_)) touching = true;
  if (touching) {
    if (stats_.first_contact < 0.0) stats_.first_contact = sim.time();
    stats_.last_contact = sim.time();
    ++stats_.contact_steps;
  }
  ++stats_.samples;
}

}  // namespace dda::paper
