// Shared by the pair benchmarks (bench_geometry, pair_sides.hpp): random
// convex polygons, the loop over the pairs and the per-pair counter.
#pragma once
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "dda/polygon.hpp"

namespace bench {

inline constexpr double kPi = 3.14159265358979323846;

// A random convex n-gon: jittered angles on a random ellipse (any points on a
// convex curve in angular order are convex), validated by the library.
inline dda::Polygon random_convex(int n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (;;) {
    const double ax = 0.5 + 0.5 * u(rng), ay = 0.5 + 0.5 * u(rng), rot = 2 * kPi * u(rng), phase = 2 * kPi * u(rng);
    std::vector<dda::Vec2> p(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
      const double t = phase + 2 * kPi * (k + 0.7 * (u(rng) - 0.5)) / n;
      p[static_cast<std::size_t>(k)] = dda::rotate({ax * std::cos(t), ay * std::sin(t)}, rot);
    }
    if (dda::validate_polygon(p.data(), n).ok()) return dda::make_polygon(p.data(), n);
  }
}

// Items processed and seconds per pair (the console shows it with an SI
// prefix, e.g. "650ns"): one pair per iteration.
inline void report_per_pair(benchmark::State& state) {
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
  state.counters["sec_per_pair"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// `work(pair)` on `pairs` in turn, one pair per iteration (their count a
// power of two: indexed with a mask), reported per pair.
template <class Pair, class Work>
void each_pair(benchmark::State& state, const std::vector<Pair>& pairs, Work work) {
  const std::size_t mask = pairs.size() - 1;
  if (pairs.empty() || (pairs.size() & mask) != 0) {
    state.SkipWithError("the pair count is not a power of two");
    return;
  }
  std::size_t i = 0;
  for (auto _ : state) work(pairs[i++ & mask]);
  report_per_pair(state);
}

}  // namespace bench
