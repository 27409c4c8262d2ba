// bench_pair_instructions: a fixed amount of pair work for an instruction
// counter, where the machine has no hardware counters (perf stat -e
// instructions is "not supported" on this virtual machine) or its time is
// shared with other jobs. The same random pairs as bench_pair_cost (same
// generator, seeds and tolerance per polygon), `passes` passes over them;
// no timing. Count with callgrind and difference two pass counts, so that
// the set-up cancels:
//   valgrind --tool=callgrind --callgrind-out-file=/dev/null
//       build/bin/bench_pair_instructions N MODE PASSES
//   instructions per pair = (I(PASSES = 3) - I(PASSES = 1)) / (2 * 1024)
// MODE 0: overlap + IP + normal force, moment and loading point (what
// BM_DdaNormalContact times); 1: overlap + IP alone (BM_DdaOverlapIp);
// 2: Box2D's b2CollidePolygons on the same pairs (BM_Box2dOverlapping).
// Prints a checksum of the results: the same bits give the same line.
// Linked with Google Benchmark only for pair_bench.hpp's helpers.
#include <box2d/b2_collision.h>
#include <box2d/b2_polygon_shape.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "dda/contact.hpp"
#include "dda/overlap.hpp"
#include "dda/potential.hpp"
#include "pair_sides.hpp"

using bench::Pair;

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s N MODE PASSES  (N vertices, MODE 0 contact / 1 overlap + IP / 2 Box2D)\n", argv[0]);
    return 2;
  }
  const int n = std::atoi(argv[1]), mode = std::atoi(argv[2]), passes = std::atoi(argv[3]);
  if (n < 3 || n > b2_maxPolygonVertices || mode < 0 || mode > 2 || passes < 0) return 2;
  // bench_pair_cost's overlapping pairs for this n.
  std::vector<Pair> v;
  bench::fill_pairs(n, true, v);
  dda::Polygon ip;
  std::array<dda::IpEdge, dda::kMaxVertices> source{};
  const b2Transform identity(b2Vec2(0.0f, 0.0f), b2Rot(0.0f));
  b2Manifold m;
  double sum = 0.0;
  for (int r = 0; r < passes; ++r)
    for (const auto& p : v) {
      if (mode == 2) {
        b2CollidePolygons(&m, &p.a.b2, identity, &p.b.b2, identity);
        sum += m.pointCount;
        continue;
      }
      const double tol = p.tol();
      const dda::OverlapState s =
          dda::overlap_and_intersection(p.a.poly, p.b.poly, tol, ip, source.data(), nullptr, dda::OverlapFacts{p.a.sharp, p.a.lines.pair.data(), p.b.lines.pair.data()});
      if (mode == 0 && s == dda::OverlapState::kOverlapping) {
        const dda::NormalForce nf = dda::normal_contact_force(p.a.side, p.b.side, ip, dda::Integration::kPaperBisector,
                                                              tol, source.data(), dda::LoadingPoint::kWithinIp);
        sum += nf.force.x + nf.point.y + nf.moment;
      } else {
        sum += ip.count;
      }
    }
  std::printf("%.17g\n", sum);
  return 0;
}
