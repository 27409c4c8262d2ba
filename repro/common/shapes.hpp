// Small shapes the drivers build scenes from (header only; needs dda's Vec2).
#pragma once
#include <vector>

#include "dda/vec2.hpp"

namespace repro {

// Axis-aligned rectangle, CCW from its lower left corner (x0, y0).
inline std::vector<dda::Vec2> rect(double x0, double y0, double w, double h) {
  return {{x0, y0}, {x0 + w, y0}, {x0 + w, y0 + h}, {x0, y0 + h}};
}

}  // namespace repro
