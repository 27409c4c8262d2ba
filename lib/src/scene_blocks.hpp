// A block of the built-in scenes (paper_scenes.cpp, robustness_scenes.cpp)
// in one call. Internal: not installed.
#pragma once
#include <utility>
#include <vector>

#include "dda/scene.hpp"

namespace dda::paper {

// Vertices counter-clockwise, initial centroid velocity (m/s), whether the
// block is fixed, its friction group and its name.
inline BlockSpec block(std::vector<Vec2> v, Vec2 vel = {}, bool fixed = false, int group = 0, const char* name = "") {
  BlockSpec b;
  b.vertices = std::move(v);
  b.velocity = vel;
  b.fixed = fixed;
  b.group = group;
  b.name = name;
  return b;
}

}  // namespace dda::paper
