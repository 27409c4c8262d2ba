#include "dda/rock_scenes.hpp"

#include <cmath>
#include <stdexcept>

namespace dda::paper {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kG = 9.81;  // m/s^2

double rad(double deg) { return deg * kPi / 180.0; }

// Appends the generated pieces as free rock blocks (material 0, group 0).
void add_blocks(Scene& s, const GeneratedBlocks& g) {
  for (const Polygon& p : g.blocks) {
    BlockSpec b;
    b.vertices.assign(p.v.begin(), p.v.begin() + p.count);
    b.group = kRockGroup;
    s.blocks.push_back(std::move(b));
  }
}

BoundarySegment segment(Vec2 a, Vec2 b, double depth) {
  BoundarySegment s;
  s.a = a;
  s.b = b;
  s.depth = depth;
  s.group = kBoundaryGroup;
  return s;
}

}  // namespace

Collapse collapse(double joint_friction_deg, double min_area, double duration, double floor_length) {
  Collapse c;
  Scene& s = c.scene;
  s.name = "6.1 collapse (reconstructed), joint friction " + std::to_string(joint_friction_deg) + " deg";
  s.materials = {{2700.0, 2e9, 0.3}};
  s.contact.kn = 2e9;
  s.contact.kt = 1e9;
  s.contact.friction_deg = joint_friction_deg;                    // rock-rock (joints)
  s.contact.friction_rules = {{kRockGroup, kBoundaryGroup, 35.0}};  // rock-boundary
  s.gravity = {0.0, -kG};
  s.broad_phase = BroadPhase::kSweep;
  s.dt = 1e-4;
  s.duration = duration;

  c.region = {{0.0, 0.0}, {c.width, 0.0}, {c.width, c.height}, {0.0, c.height}};
  c.joint_sets = {{80.0, 1.5, {0.0, 0.0}}, {40.0, 2.5, {0.0, 0.0}}};
  c.min_area = min_area;
  c.floor_length = floor_length;
  const GeneratedBlocks g = generate_blocks(c.region, c.joint_sets, min_area);
  c.dropped = g.dropped;
  c.dropped_area = g.dropped_area;
  add_blocks(s, g);
  // Solid on the right of a -> b: the wall is solid for x < 0, the floor for y < 0.
  const double depth = 5.0;
  s.boundaries = {segment({0.0, 1.2 * c.height}, {0.0, 0.0}, depth),
                  segment({-depth, 0.0}, {floor_length, 0.0}, depth)};
  return c;
}

TopplingSlumping toppling_slumping(double min_area, double duration, double height, double valley_half_width,
                                   double right_face_deg) {
  if (!(height > 0.0 && valley_half_width > 0.0 && right_face_deg > 30.0 && right_face_deg < 90.0))
    throw std::invalid_argument("toppling_slumping: need height > 0, valley_half_width > 0, 30 < right_face_deg < 90");
  TopplingSlumping t;
  Scene& s = t.scene;
  s.name = "6.2 toppling and slumping (reconstructed)";
  s.materials = {{2700.0, 2e9, 0.3}};
  s.contact.kn = 0.5e9;
  s.contact.kt = 1e8;
  s.contact.friction_deg = 22.0;                                   // joints
  s.contact.friction_rules = {{kRockGroup, kBoundaryGroup, 32.0}};  // sliding base
  s.gravity = {0.0, -kG};
  s.broad_phase = BroadPhase::kSweep;
  s.dt = 1e-4;
  s.duration = duration;

  const double a = valley_half_width, h = height, base = rad(t.base_dip_deg);
  t.valley_half_width = a;
  t.height = h;
  t.min_area = min_area;
  t.joints = {75.0, 3.0, {}};
  t.left_downdip = {std::cos(base), -std::sin(base)};
  t.right_downdip = {-std::cos(base), -std::sin(base)};
  const Vec2 toe_l{-a, 0.0}, toe_r{a, 0.0};
  const double back = h / std::tan(base);  // horizontal reach of the base up to the top
  // Left wedge: toe, face top (the face is the joint plane through the toe), back apex on the base.
  t.left_region = {toe_l, {-a - h / std::tan(rad(t.joints.dip_deg)), h}, {-a - back, h}};
  // Right wedge: toe, back apex on the base, face top.
  t.right_region = {toe_r, {a + back, h}, {a + h / std::tan(rad(right_face_deg)), h}};

  JointSet js = t.joints;
  js.origin = toe_l;
  const GeneratedBlocks gl = generate_blocks(t.left_region, {js}, min_area);
  js.origin = toe_r;
  const GeneratedBlocks gr = generate_blocks(t.right_region, {js}, min_area);
  t.dropped = gl.dropped + gr.dropped;
  t.dropped_area = gl.dropped_area + gr.dropped_area;
  add_blocks(s, gl);
  t.side.assign(gl.blocks.size(), -1);
  add_blocks(s, gr);
  t.side.resize(s.blocks.size(), +1);

  // Sliding bases 10 m longer than the wedges' contact, and the valley floor.
  const double depth = 10.0, len = h / std::sin(base) + 10.0;
  s.boundaries = {segment(toe_l - len * t.left_downdip, toe_l, depth), segment(toe_l, toe_r, depth),
                  segment(toe_r, toe_r - len * t.right_downdip, depth)};
  return t;
}

Scene one_block_per_slope(const TopplingSlumping& ts) {
  Scene whole = ts.scene;
  whole.blocks.clear();
  for (const auto* region : {&ts.left_region, &ts.right_region}) {
    BlockSpec b;
    b.vertices = *region;
    b.group = kRockGroup;
    whole.blocks.push_back(b);
  }
  return whole;
}

}  // namespace dda::paper
