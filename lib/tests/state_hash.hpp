// A fingerprint of a simulation's state for bit-for-bit comparisons between
// runs (determinism, thread counts, broad phases): FNV-1a over the bytes of
// every block's vertices and velocity DOFs.
#pragma once
#include <cstdint>

#include "dda/simulation.hpp"

namespace dda::test {

inline std::uint64_t state_hash(const Simulation& sim) {
  std::uint64_t h = 1469598103934665603ull;
  auto mix = [&](const void* p, std::size_t n) {
    const unsigned char* c = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ c[i]) * 1099511628211ull;
  };
  for (int i = 0; i < sim.block_count(); ++i) {
    const Polygon& p = sim.polygon(i);
    mix(p.v.data(), sizeof(Vec2) * static_cast<std::size_t>(p.count));
    mix(sim.velocity(i).data(), sizeof(double) * 6);
  }
  return h;
}

}  // namespace dda::test
