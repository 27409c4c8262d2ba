#include "dda/stepper.hpp"

namespace dda {

BlockMotion SimulationStepper::block_motion(int block) const {
  const Vec6& v = model_.velocity(block);
  BlockMotion m;
  m.position = model_.centroid(block);
  m.velocity = {v[0], v[1]};
  m.rotation = model_.displacement(block)[2];
  m.spin = v[2];
  return m;
}

std::vector<Vec2> SimulationStepper::outline(int i) const {
  const PolygonView p = model_.polygon_view(i);
  return std::vector<Vec2>(p.v, p.v + p.count);
}

}  // namespace dda
