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
// The bisectors of each polygon (Sect. 3.2.3) and its geometric tolerance
// are built once, outside the timed loop, as the simulation builds them once
// per block and step (update_block_geometry: sides_[i].tol, the bisector
// store) and takes the pair's tolerance as the larger of the two
// (pair_forces); Box2D's shapes likewise carry their normals.
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
#include "pair_bench.hpp"

namespace {

constexpr std::size_t kPairs = 1024;  // power of two: index with a mask
using bench::kPi;
constexpr double kKn = 1e9;                // Pa: a rock joint's penalty (Sect. 6)
constexpr double kH = 1.0;                 // m: H of Eq. 12 for blocks of this size
constexpr double kSmallEdgeFraction = 0.05;  // of H: the library's default (ContactParams)

b2PolygonShape to_box2d(const dda::Polygon& p) {
  std::array<b2Vec2, b2_maxPolygonVertices> v{};
  for (int k = 0; k < p.count; ++k)
    v[static_cast<std::size_t>(k)] = b2Vec2(static_cast<float>(p.v[k].x), static_cast<float>(p.v[k].y));
  b2PolygonShape s;
  s.Set(v.data(), p.count);
  return s;
}

// One polygon with what both libraries precompute per body and step.
struct Side {
  dda::Polygon poly;
  std::vector<dda::Bisector> bisectors;
  dda::PotentialSide side;
  double tol = 0.0;  // geometric_tolerance(poly), m
  b2PolygonShape b2;
};

Side make_side(const dda::Polygon& p) {
  Side s;
  s.poly = p;
  s.bisectors.resize(2 * dda::kMaxVertices);
  const double small = kSmallEdgeFraction * kH;
  const int nb = dda::bisectors(p, small, dda::SmallEdgeRays::kVirtualAndVertex, s.bisectors.data());
  s.side.kn_over_h = kKn / kH;
  s.side.small_edge = small;
  s.side.bisector_count = nb;
  s.tol = dda::geometric_tolerance(p);
  s.b2 = to_box2d(p);
  return s;
}

struct Pair {
  Side a, b;
  // pair_tolerance(a, b), as the simulation's pair loop takes it from the
  // blocks' stored tolerances.
  double tol() const { return std::max(a.tol, b.tol); }
};

bool boxes_overlap(const dda::Polygon& a, const dda::Polygon& b) {
  const dda::Aabb x = dda::bounds(a), y = dda::bounds(b);
  return x.lo.x <= y.hi.x && y.lo.x <= x.hi.x && x.lo.y <= y.hi.y && y.lo.y <= x.hi.y;
}

// kPairs pairs of n-gons, overlapping or separated with overlapping boxes;
// deterministic for a given (n, kind). The PotentialSide pointers are set
// after the vector stops growing.
std::vector<Pair>& pairs(int n, bool overlapping) {
  static std::map<std::pair<int, bool>, std::vector<Pair>> cache;
  std::vector<Pair>& v = cache[{n, overlapping}];
  if (!v.empty()) return v;
  std::mt19937_64 rng(0x5eed0000u + static_cast<unsigned>(n) + (overlapping ? 0u : 100u));
  std::uniform_real_distribution<double> u(0.0, 1.0);
  while (v.size() < kPairs) {
    const dda::Polygon a = bench::random_convex(n, rng);
    const double ang = 2 * kPi * u(rng), dist = (overlapping ? 1.2 : 2.0) * u(rng);
    const dda::Polygon b = dda::translated(bench::random_convex(n, rng), {dist * std::cos(ang), dist * std::sin(ang)});
    const dda::OverlapState s = dda::overlap_state(a, b);
    const bool keep = overlapping ? s == dda::OverlapState::kOverlapping
                                  : s == dda::OverlapState::kSeparate && boxes_overlap(a, b);
    if (keep) v.push_back({make_side(a), make_side(b)});
  }
  for (Pair& p : v) {
    for (Side* s : {&p.a, &p.b}) {
      s->side.poly = &s->poly;
      s->side.bisectors = s->bisectors.data();
    }
  }
  return v;
}

// Ours, overlapping pairs: Sect. 3.1 overlap + IP, Sect. 3.2 normal force,
// moment and loading point, as Simulation::pair_force calls them.
void BM_DdaNormalContact(benchmark::State& state) {
  const std::vector<Pair>& v = pairs(static_cast<int>(state.range(0)), true);
  std::size_t i = 0;
  dda::Polygon ip;
  std::array<dda::IpEdge, dda::kMaxVertices> source{};
  for (auto _ : state) {
    const Pair& p = v[i++ & (kPairs - 1)];
    const double tol = p.tol();
    if (dda::overlap_and_intersection(p.a.poly, p.b.poly, tol, ip, source.data()) == dda::OverlapState::kOverlapping) {
      const dda::NormalForce nf = dda::normal_contact_force(p.a.side, p.b.side, ip, dda::Integration::kPaperBisector,
                                                            tol, source.data(), dda::LoadingPoint::kWithinIp);
      benchmark::DoNotOptimize(nf);
    }
  }
  bench::report_per_pair(state);
}

// Ours, overlapping pairs, geometry only: Sect. 3.1 overlap + IP.
void BM_DdaOverlapIp(benchmark::State& state) {
  const std::vector<Pair>& v = pairs(static_cast<int>(state.range(0)), true);
  std::size_t i = 0;
  dda::Polygon ip;
  std::array<dda::IpEdge, dda::kMaxVertices> source{};
  for (auto _ : state) {
    const Pair& p = v[i++ & (kPairs - 1)];
    const double tol = p.tol();
    const dda::OverlapState s = dda::overlap_and_intersection(p.a.poly, p.b.poly, tol, ip, source.data());
    benchmark::DoNotOptimize(s);
    benchmark::DoNotOptimize(ip);
  }
  bench::report_per_pair(state);
}

// Ours, separated candidates: the overlap test alone.
void BM_DdaSeparated(benchmark::State& state) {
  const std::vector<Pair>& v = pairs(static_cast<int>(state.range(0)), false);
  std::size_t i = 0;
  for (auto _ : state) {
    const Pair& p = v[i++ & (kPairs - 1)];
    dda::OverlapState s = dda::overlap_state(p.a.poly, p.b.poly);
    benchmark::DoNotOptimize(s);
  }
  bench::report_per_pair(state);
}

// Box2D's manifold on the same pairs (identity transforms).
void box2d_manifold(benchmark::State& state, bool overlapping) {
  const std::vector<Pair>& v = pairs(static_cast<int>(state.range(0)), overlapping);
  const b2Transform identity(b2Vec2(0.0f, 0.0f), b2Rot(0.0f));
  std::size_t i = 0;
  b2Manifold m;
  for (auto _ : state) {
    const Pair& p = v[i++ & (kPairs - 1)];
    b2CollidePolygons(&m, &p.a.b2, identity, &p.b.b2, identity);
    benchmark::DoNotOptimize(m);
  }
  bench::report_per_pair(state);
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
