#include "dda/paper_scenes.hpp"

#include <cmath>

#include "scene_blocks.hpp"

namespace dda::paper {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kG = 9.81;  // m/s^2

std::vector<Vec2> rect(double x0, double y0, double w, double h) {
  return {{x0, y0}, {x0 + w, y0}, {x0 + w, y0 + h}, {x0, y0 + h}};
}
}  // namespace

Scene two_squares() {
  Scene s;
  s.name = "4.1 two squares";
  s.materials = {{2000.0, 1e9, 0.25}};
  s.contact.kn = 10e6;
  s.dt = 1e-4;
  s.duration = 1.0;
  s.blocks = {block(rect(-1.5, -0.5, 1.0, 1.0), {1.0, 0.0}), block(rect(0.0, -0.5, 1.0, 1.0))};
  s.blocks[0].name = "A";
  s.blocks[1].name = "B";
  return s;
}

SymmetricStack symmetric_stack() {
  SymmetricStack st;
  Scene& s = st.scene;
  s.name = "4.2 symmetric stack (reconstructed)";
  s.materials = {{2000.0, 0.1e9, 0.25}};
  s.contact.kn = 10e6;
  s.gravity = {0.0, -kG};
  s.dt = 1e-3;
  s.duration = 1.0;
  s.blocks = {
      block(rect(-3.0, -1.0, 6.0, 1.0), {}, true),                        // 0 fixed base
      block(rect(-1.0, 0.0, 1.0, 1.0)),                                    // 1 bottom left
      block(rect(0.0, 0.0, 1.0, 1.0)),                                     // 2 bottom right
      block(rect(-0.5, 1.0, 1.0, 1.0)),                                    // 3 top, axis x = 0
      block({{-0.3, 2.5}, {0.3, 2.5}, {0.5, 2.9}, {0.0, 3.2}, {-0.5, 2.9}}, {0.0, -2.0}),  // 4 impactor
  };
  st.mirror = {0, 2, 1, 3, 4};
  return st;
}

Incline incline(double phi_deg, double theta_deg, double duration, bool start_sunk, double h_given) {
  Incline in;
  in.theta_rad = theta_deg * kPi / 180.0;
  const double th = in.theta_rad;
  const Vec2 along{std::cos(th), std::sin(th)};  // uphill direction of the slab surface
  in.downhill = -along;
  const Vec2 up = perp_left(along);
  Scene& s = in.scene;
  s.name = "4.3 incline (reconstructed)";
  s.materials = {{2000.0, 1e9, 0.25}};
  s.contact.kn = 10e6;
  s.contact.kt = 1e7;
  s.contact.friction_deg = phi_deg;
  s.gravity = {0.0, -kG};
  s.dt = 1e-5;
  s.duration = duration;
  // Slab: surface from the origin uphill for 12 m, 1 m thick below it.
  const double len = 12.0;
  const std::vector<Vec2> slab = {-1.0 * up, len * along - 1.0 * up, len * along, {0.0, 0.0}};
  // Block: 1 m square with its base on the surface, 8 m up the slope, sunk
  // by its static penetration so that the normal force starts at its
  // equilibrium value (Fig. 11 is lost; starting just touching drops B into
  // the slab and leaves an undamped normal oscillation between 0 and 2 W).
  // For a flat contact of length L both potentials push: f = 2 kn delta L / H,
  // so delta = W cos(theta) H / (2 kn L), with H of the min-max edge rule.
  const double side = 1.0, h_rule = h_given > 0.0 ? h_given : 0.5 * (side + len);
  if (h_given > 0.0) {
    s.contact.h_rule = HRule::kGiven;
    s.contact.h = h_given;
  }
  const double weight = s.materials[0].density * side * side * kG;
  const double delta = start_sunk ? weight * std::cos(th) * h_rule / (2.0 * s.contact.kn * side) : 0.0;
  const Vec2 o = 8.0 * along - delta * up;
  const std::vector<Vec2> blk = {o, o + along, o + along + up, o + up};
  s.blocks = {block(slab, {}, true), block(blk)};
  s.initial_overlap = 2.0 * delta;
  s.blocks[0].name = "A";
  s.blocks[1].name = "B";
  return in;
}

double incline_distance(double g, double theta_rad, double phi_rad, double t) {
  const double a = g * (std::sin(theta_rad) - std::cos(theta_rad) * std::tan(phi_rad));
  return a > 0.0 ? 0.5 * a * t * t : 0.0;
}

}  // namespace dda::paper
