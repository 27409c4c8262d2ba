// Google Benchmark of the narrow phase of Paper A Sect. 3.1: overlap
// examination with the entrance block (dda::overlap_state) followed by the
// intersection polygon (dda::intersection_polygon), per polygon pair.
//
// Pairs of random convex n-gons (n = 4, 6, 8) in overlapping positions are
// built once, outside the timed loop; each iteration handles one pair,
// cycling through kPairs of them, so "Time" is the cost per pair and the
// sec_per_pair counter reports the same thing explicitly (printed as e.g. "650ns").
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "dda/overlap.hpp"
#include "dda/polygon.hpp"
#include "pair_bench.hpp"

namespace {

constexpr std::size_t kPairs = 1024;  // power of two: index with a mask
using bench::kPi;

struct Pair {
  dda::Polygon a, b;
};

// kPairs overlapping pairs of n-gons, deterministic for a given n.
const std::vector<Pair>& pairs(int n) {
  static std::vector<Pair> cache[17];
  std::vector<Pair>& v = cache[n];
  if (!v.empty()) return v;
  std::mt19937_64 rng(0x5eed0000u + static_cast<unsigned>(n));
  std::uniform_real_distribution<double> u(0.0, 1.0);
  while (v.size() < kPairs) {
    const dda::Polygon a = bench::random_convex(n, rng);
    const double ang = 2 * kPi * u(rng), dist = 1.2 * u(rng);
    const dda::Polygon b = dda::translated(bench::random_convex(n, rng), {dist * std::cos(ang), dist * std::sin(ang)});
    if (dda::overlap_state(a, b) == dda::OverlapState::kOverlapping &&
        !dda::intersection_polygon(a, b).empty())
      v.push_back({a, b});
  }
  return v;
}

// Overlap test, then the intersection polygon when the pair overlaps.
void BM_OverlapAndIntersection(benchmark::State& state) {
  bench::each_pair(state, pairs(static_cast<int>(state.range(0))), [](const Pair& p) {
    if (dda::overlap_state(p.a, p.b) == dda::OverlapState::kOverlapping) {
      dda::Polygon ip = dda::intersection_polygon(p.a, p.b);
      benchmark::DoNotOptimize(ip);
    }
  });
}

// The two parts alone, to see where the time goes.
void BM_OverlapOnly(benchmark::State& state) {
  bench::each_pair(state, pairs(static_cast<int>(state.range(0))), [](const Pair& p) {
    dda::OverlapState s = dda::overlap_state(p.a, p.b);
    benchmark::DoNotOptimize(s);
  });
}

void BM_IntersectionOnly(benchmark::State& state) {
  bench::each_pair(state, pairs(static_cast<int>(state.range(0))), [](const Pair& p) {
    dda::Polygon ip = dda::intersection_polygon(p.a, p.b);
    benchmark::DoNotOptimize(ip);
  });
}

BENCHMARK(BM_OverlapAndIntersection)->Arg(4)->Arg(6)->Arg(8);
BENCHMARK(BM_OverlapOnly)->Arg(4)->Arg(6)->Arg(8);
BENCHMARK(BM_IntersectionOnly)->Arg(4)->Arg(6)->Arg(8);

}  // namespace

BENCHMARK_MAIN();
