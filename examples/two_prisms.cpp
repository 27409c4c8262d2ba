// Paper B Sect. 6 with the two-scale contact (dda::cdem): prism i (4 CST
// elements, 3 m/s) strikes prism j at rest, 1 m ahead (geometry
// RECONSTRUCTED: the paper's figure with the dimensions is lost). No contact
// spring: the step is split at the touch, the two points become one clone
// node, the colliding elements are subdivided. Prints the first touch and
// both blocks' velocities at the end; exits 1 unless the touch comes at
// gap / speed = 1/3 s (within one step) and j ends moving away from i.
#include <cmath>
#include <cstdio>

#include "dda/cdem/model.hpp"
#include "dda/cdem/scenes.hpp"

int main() {
  const dda::cdem::CdemScene scene = dda::cdem::two_prisms();  // dt 5e-4 s, 0.5 s
  dda::cdem::Model model(scene);
  model.advance_to(scene.duration);  // throws dda::SimulationError if a check stops the run

  if (model.touches().empty()) return std::printf("no touch\n"), 1;
  const dda::cdem::TouchRecord& touch = model.touches().front();
  const dda::Vec2 vi = model.block_velocity(0), vj = model.block_velocity(1);
  std::printf("first touch at t = %.5f s (step %.4f-%.4f s); %zu touches, %zu separations\n", touch.time,
              touch.step_start, touch.step_end, model.touches().size(), model.separations().size());
  std::printf("t = %.3f s: block i vx %.4f m/s, block j vx %.4f m/s\n", model.time(), vi.x, vj.x);
  const bool touch_ok = std::abs(touch.time - 1.0 / 3.0) <= scene.dt;
  return touch_ok && vj.x > vi.x ? 0 : 1;
}
