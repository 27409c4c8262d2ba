// Google Benchmark: the cost of one polygon pair in the narrow phase, this
// library against Box2D's b2CollidePolygons (Box2D 2.4, Debian's
// libbox2d-dev: a benchmark-only peer, never linked by the library), on the
// same random convex n-gons (n = 4, 6, 8; Box2D's limit is 8), in the same
// run. Two kinds of pair:
//   overlapping  the pair overlaps: ours is the whole normal contact of
//                Paper A Sect. 3 -- overlap test with the entrance block and
//                intersection polygon (overlap_and_intersection), then the
//                potential normal force of Eqs. 11-18, its moment and the
//                loading point of Eq. 20 (normal_contact_force, as the
//                simulation calls it); Box2D's is its contact manifold
//                (b2CollidePolygons: SAT, reference face, clipping);
//   separated    bounding boxes overlap, the polygons do not (a broad-phase
//                candidate that is no contact): ours is the overlap test
//                (overlap_state), Box2D's again b2CollidePolygons.
// The overlapping pairs are also timed with our overlap test and
// intersection polygon alone (the part that does what Box2D's manifold
// does: find the contact region), so that the report can split our cost
// into geometry and the potential's integration (Eqs. 11-18), which has no
// counterpart in Box2D: for each of the IP's (up to 2n) edges, the other
// polygon's n edge lines and n bisector crossings, O(n^2) per pair against
// the manifold's O(n).
// Friction (Eqs. 24-26) is not included: it needs the pair's history, which
// lives in the simulation; bench_collapse times it in the full step.
// The pairs and what each polygon precomputes (bisectors, tolerance,
// Box2D's shape) are built outside the timed loop: pair_sides.hpp.
//
// After the runs it prints, per n, both costs per pair and their ratio.
#include <benchmark/benchmark.h>

#include <box2d/b2_collision.h>
#include <box2d/b2_polygon_shape.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "dda/contact.hpp"
#include "dda/overlap.hpp"
#include "dda/polygon.hpp"
#include "dda/potential.hpp"
#include "pair_sides.hpp"

namespace {

using bench::Pair;

// bench::fill_pairs's pairs for (n, kind), built once per run.
std::vector<Pair>& pairs(int n, bool overlapping) {
  static std::map<std::pair<int, bool>, std::vector<Pair>> cache;
  std::vector<Pair>& v = cache[{n, overlapping}];
  if (v.empty()) bench::fill_pairs(n, overlapping, v);
  return v;
}

// Ours, overlapping pairs: Sect. 3.1 overlap + IP, Sect. 3.2 normal force,
// moment and loading point, as Simulation::pair_force calls them.
void BM_DdaNormalContact(benchmark::State& state) {
  dda::Polygon ip;
  std::array<dda::IpEdge, dda::kMaxVertices> source{};
  bench::each_pair(state, pairs(static_cast<int>(state.range(0)), true), [&](const Pair& p) {
    const double tol = p.tol();
    if (dda::overlap_and_intersection(p.a.poly, p.b.poly, tol, ip, source.data(), nullptr, dda::OverlapFacts{p.a.sharp, p.a.lines.pair.data(), p.b.lines.pair.data()}) ==
        dda::OverlapState::kOverlapping) {
      const dda::NormalForce nf = dda::normal_contact_force(p.a.side, p.b.side, ip, dda::Integration::kPaperBisector,
                                                            tol, source.data(), dda::LoadingPoint::kWithinIp);
      benchmark::DoNotOptimize(nf);
    }
  });
}

// Ours, overlapping pairs, geometry only: Sect. 3.1 overlap + IP.
void BM_DdaOverlapIp(benchmark::State& state) {
  dda::Polygon ip;
  std::array<dda::IpEdge, dda::kMaxVertices> source{};
  bench::each_pair(state, pairs(static_cast<int>(state.range(0)), true), [&](const Pair& p) {
    const dda::OverlapState s =
        dda::overlap_and_intersection(p.a.poly, p.b.poly, p.tol(), ip, source.data(), nullptr, dda::OverlapFacts{p.a.sharp, p.a.lines.pair.data(), p.b.lines.pair.data()});
    benchmark::DoNotOptimize(s);
    benchmark::DoNotOptimize(ip);
  });
}

// Ours, separated candidates: the overlap test alone.
void BM_DdaSeparated(benchmark::State& state) {
  bench::each_pair(state, pairs(static_cast<int>(state.range(0)), false), [](const Pair& p) {
    dda::OverlapState s = dda::overlap_state(p.a.poly, p.b.poly);
    benchmark::DoNotOptimize(s);
  });
}

// Box2D's manifold on the same pairs (identity transforms).
void box2d_manifold(benchmark::State& state, bool overlapping) {
  const b2Transform identity(b2Vec2(0.0f, 0.0f), b2Rot(0.0f));
  b2Manifold m;
  bench::each_pair(state, pairs(static_cast<int>(state.range(0)), overlapping), [&](const Pair& p) {
    b2CollidePolygons(&m, &p.a.b2, identity, &p.b.b2, identity);
    benchmark::DoNotOptimize(m);
  });
}
void BM_Box2dOverlapping(benchmark::State& state) { box2d_manifold(state, true); }
void BM_Box2dSeparated(benchmark::State& state) { box2d_manifold(state, false); }

BENCHMARK(BM_DdaNormalContact)->Arg(4)->Arg(6)->Arg(8);
BENCHMARK(BM_DdaOverlapIp)->Arg(4)->Arg(6)->Arg(8);
BENCHMARK(BM_Box2dOverlapping)->Arg(4)->Arg(6)->Arg(8);
BENCHMARK(BM_DdaSeparated)->Arg(4)->Arg(6)->Arg(8);
BENCHMARK(BM_Box2dSeparated)->Arg(4)->Arg(6)->Arg(8);

// The console output, plus each run's time per pair kept for the ratios.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  std::map<std::string, double> ns;
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& r : runs)
      if (r.run_type == Run::RT_Iteration && r.iterations > 0) ns[r.benchmark_name()] = r.GetAdjustedCPUTime();
    ConsoleReporter::ReportRuns(runs);
  }
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  std::printf("\npair cost against Box2D 2.4 b2CollidePolygons (same pairs, same run; CPU ns per pair, robust to a shared machine):\n");
  for (const char* n : {"4", "6", "8"}) {
    auto show = [&](const char* what, const std::string& ours, const std::string& theirs) {
      const auto a = reporter.ns.find(ours + "/" + n), b = reporter.ns.find(theirs + "/" + n);
      if (a == reporter.ns.end() || b == reporter.ns.end()) return;
      std::printf("  n = %s, %-12s DDA %7.1f ns, Box2D %7.1f ns, ratio %.2f\n", n, what, a->second, b->second,
                  a->second / b->second);
    };
    show("overlapping:", "BM_DdaNormalContact", "BM_Box2dOverlapping");
    show("  of it IP:", "BM_DdaOverlapIp", "BM_Box2dOverlapping");
    show("separated:", "BM_DdaSeparated", "BM_Box2dSeparated");
  }
  std::printf("  overlapping: overlap + IP + potential normal force, moment and loading point (friction excluded);\n"
              "  of it IP: overlap + intersection polygon alone (what Box2D's manifold does); the rest of the\n"
              "  overlapping cost is the potential's integration over the IP's edges, O(n^2) per pair\n");
  benchmark::Shutdown();
  return 0;
}
