// bench_collapse: wall-clock cost of the explicit DDA step on Paper A's
// Sect. 6.1 collapse (dda::paper::collapse, case 1: joint friction 15 deg),
// and how that cost grows with the number of blocks. A plain program timed
// with std::chrono::steady_clock (no Google Benchmark loop): a step is long
// and changes the state, so it is timed over a run, not repeated.
//
// Default: after --warmup steps (default 600: blocks settle into contact,
// caches and the thread pool warm up) it times --steps steps (default 5000 =
// 0.5 s of simulated time) once with 1 thread and once with 2
// (Simulation::set_threads) and prints per thread count: wall time, CPU/wall
// (near 1 with 2 threads: the cores were shared), steps/s, mean broad-phase candidate
// pairs and touching pairs per step, ns per candidate and per touching pair
// (wall / steps / mean pairs: the whole step's cost shared out over its
// pairs, not the narrow phase alone), the projected wall time of the full
// 7.5 s run (75,000 steps), and whether the 1- and 2-thread final states are
// bit-identical (every vertex and velocity component compared bit for bit).
// Beside them, the host's ceiling for any 2-thread speed-up: two independent
// 1-thread runs of the scene at once (two simulations sharing nothing), their
// throughput against one run alone. On a virtual machine whose vCPUs share
// physical cores or wait for the host, that ceiling is below 2 and moves from
// minute to minute. The pair's wall time against the 2-thread run's compares
// two runs that both keep the two cores busy: 2 if splitting the step
// between two threads cost nothing (barriers, shared cache lines, uneven
// shares), whatever the host does to both cores alike. --rounds N (default 3) repeats the three runs in turn (1
// thread, 2 threads, the independent pair), and the table gives the median
// round's, so that a minute of a busy host does not decide the verdict; and
// the speed-up over the ceiling per round (their median): 1 when splitting
// the step costs nothing. A crowded host (load average above the cores)
// pulls it far below 1: a descheduled thread of the team makes its partner
// wait at each of the step's barriers, which two independent runs never do.
//
// --scaling: the same generator on bigger or smaller regions, ~10^2 .. 10^4
// blocks (--max-blocks 100000: on to 3 x 10^4 and 10^5, minutes each;
// --max-blocks 1000000: on to 3 x 10^5 and 10^6, ~1.1 kB of heap per block
// constructed and ~1.5 kB at the end of the run (the touching pairs' contact
// slots): ~1.5 GB per simulation at 10^6, two of them alive at once for the
// 1- and 2-thread runs); --min-blocks N leaves out the rows below N, --max-threads 1
// runs each row with 1 thread only (the 10^6 row in half the time). A table
// of blocks, pairs per step, wall and CPU us per step, ns per block-step and
// per candidate pair, the heap per block of the constructed simulation (of
// it the pooled block geometry, and the near pairs per block times the bytes
// each holds; a touching pair's contact slot comes on top, in the heap
// growth per touching pair and the heap per block at the run's end), the CPU time of generating the scene and of constructing the
// simulation, and the fitted exponents p of cost ~ blocks^p (least squares
// over the rows: time per step, generation, construction). --csv FILE also
// writes the table as CSV. Shapes:
//   wide   (default) the collapse's 50 m height, width grown: every block sees
//          the same depth of rock, so per-block physics stays the same and
//          the table shows the algorithm's growth;
//   column the collapse's 20:50 outline scaled in both directions: taller
//          columns put more blocks into each x-interval of the x sort-and-sweep
//          broad phase (column "x-overlap": pairs one pass visits); within the
//          warm-up gravity's compression wave reaches only the lower ~50 m, so
//          a tall column's upper blocks are still falling without contact.
//
// --skips: what a scene does not use, it does not pay for. One thread, CPU
// time per step after the warm-up, heap per block and per touching pair, for
//   the collapse as is (friction 15 deg, deformable blocks);
//   the collapse without friction (kt = 0): no friction force (Eqs. 24-26),
//          no friction energy or work banking, no friction history per
//          touching pair nor friction work per near pair;
//   the collapse with rigid blocks (Scene::strains false): no stress update,
//          no strain forces, no strain modes in the critical step;
//   Sect. 4.1's two squares with the default all-pairs test
//          (BroadPhase::kNone: one box test per step, no sort) against the
//          sweep broad phase the collapse uses (sort, skin, Verlet list).
// Each variant is its own trajectory (friction and strains change the
// motion), so the cost per touching pair is printed beside the cost per step.
//
// --window SECONDS [--no-guards]: the collapse from t = 0 for SECONDS of
// simulated time on 1 thread, nothing else (no warm-up, no timing, no
// output but one line: steps, touching pairs at the end and a fingerprint
// of the final state), for an instruction counter (lib/bench/instructions.py
// runs it under callgrind). --no-guards switches off the guards that can be
// switched off (the energy checks, the penetration and approach-energy
// measures; the step-motion bound is made infinite, but its measure comes
// with the vertex update and stays): the same trajectory (the fingerprint
// says so), and the two counts' difference is what those guards cost.
#include <algorithm>
#include <atomic>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <malloc.h>
#include <iostream>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "dda/joint_sets.hpp"
#include "dda/paper_scenes.hpp"
#include "dda/rock_scenes.hpp"
#include "dda/simulation.hpp"

namespace {

constexpr double kJointFrictionDeg = 15.0;      // Sect. 6.1 case 1 (SPEC.md section 7)
constexpr int kDefaultSteps = 5000;             // 0.5 s at dt = 1e-4 s: a stable mean, short enough for `make bench`
constexpr int kDefaultWarmup = 600;             // 0.06 s: gravity's compression wave has crossed the 50 m
                                                // column and the touching-pair count has levelled off
constexpr std::int64_t kFullRunSteps = 75000;   // 7.5 s at dt = 1e-4 s: the paper's full collapse run
constexpr int kSampleEvery = 50;               // steps per advance() call between pair-count samples
constexpr int kThreadCounts[] = {1, 2};         // the machine's cores; results must not depend on them
constexpr int kDefaultRounds = 3;               // the median of 3 is robust to one disturbed round

// Scaling runs.
constexpr int kTargetBlocks[] = {100,   300,   1000,   3000,  10000,
                                  30000, 100000, 300000, 1000000};  // ~10^2 .. 10^6, half-decade steps
constexpr int kDefaultMaxBlocks = 10000;  // the rows above it (minutes to an hour each) run with a larger --max-blocks
constexpr double kBlockStepBudget = 2e6;  // blocks x steps timed per scene: ~seconds at ~us per block-step
constexpr int kMinScalingSteps = 200;     // enough steps for a mean even on the biggest scene
constexpr int kMaxScalingSteps = 1000;    // small scenes: cap so the table stays quick
constexpr double kRunoutLength = 180.0;   // m: the collapse's floor reaches 180 m beyond its 20 m column

constexpr double kMaxWindow = 7.5;  // s: the paper's whole collapse run

using Clock = std::chrono::steady_clock;

enum class Shape { kWide, kColumn };

struct Options {
  int steps = kDefaultSteps;
  int warmup = kDefaultWarmup;
  int rounds = kDefaultRounds;
  bool scaling = false;
  bool skips = false;
  Shape shape = Shape::kWide;
  int max_blocks = kDefaultMaxBlocks;
  int min_blocks = 0;
  int max_threads = 2;  // --max-threads 1: the scaling rows with 1 thread only (the biggest rows in half the time)
  std::string csv;
  double window = 0.0;  // s of simulated time (--window); 0: not this mode
  bool no_guards = false;
};

[[noreturn]] void usage(const char* argv0) {
  std::cerr << "usage: " << argv0
            << " [--steps N] [--warmup N] [--rounds N] [--scaling [--shape wide|column] [--min-blocks N] [--max-blocks N] [--max-threads 1|2] [--csv FILE]] [--skips]\n"
            << "       [--window SECONDS [--no-guards]]\n"
            << "  --steps: timed steps of the collapse (the scaling runs take " << kBlockStepBudget
            << " / blocks steps, " << kMinScalingSteps << " to " << kMaxScalingSteps << ")\n";
  std::exit(2);
}

// A count given on the command line: a whole number in [0, kMaxCount].
int count_arg(const char* text, const char* argv0) {
  constexpr long kMaxCount = 100000000;  // 10^8 steps is days of wall time: anything above is a typo
  char* end = nullptr;
  const long v = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || v < 0 || v > kMaxCount) usage(argv0);
  return static_cast<int>(v);
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if (a == "--steps" && has_value) o.steps = count_arg(argv[++i], argv[0]);
    else if (a == "--warmup" && has_value) o.warmup = count_arg(argv[++i], argv[0]);
    else if (a == "--rounds" && has_value) o.rounds = count_arg(argv[++i], argv[0]);
    else if (a == "--max-blocks" && has_value) o.max_blocks = count_arg(argv[++i], argv[0]);
    else if (a == "--min-blocks" && has_value) o.min_blocks = count_arg(argv[++i], argv[0]);
    else if (a == "--max-threads" && has_value) o.max_threads = count_arg(argv[++i], argv[0]);
    else if (a == "--csv" && has_value) o.csv = argv[++i];
    else if (a == "--scaling") o.scaling = true;
    else if (a == "--skips") o.skips = true;
    else if (a == "--no-guards") o.no_guards = true;
    else if (a == "--window" && has_value) {
      char* end = nullptr;
      o.window = std::strtod(argv[++i], &end);
      if (end == argv[i] || *end != '\0' || !(o.window > 0.0) || o.window > kMaxWindow) usage(argv[0]);
    }
    else if (a == "--shape" && has_value) {
      const std::string s = argv[++i];
      if (s == "wide") o.shape = Shape::kWide;
      else if (s == "column") o.shape = Shape::kColumn;
      else usage(argv[0]);
    } else usage(argv[0]);
  }
  if (o.steps < 1 || o.rounds < 1 || o.max_threads < 1) usage(argv[0]);
  return o;
}

// ---------------------------------------------------------------------------
// Timing one run.
// ---------------------------------------------------------------------------

struct RunStats {
  int threads = 1;
  int blocks = 0;  // scene blocks (boundary polygons not counted)
  std::int64_t steps = 0;
  double wall_s = 0.0;
  double cpu_s = 0.0;  // process CPU time over the timed steps, all threads
  double candidates_per_step = 0.0;
  double touching_per_step = 0.0;
  std::vector<dda::Simulation::PhaseTimes> phases;  // per thread, over the timed steps

  double us_per_step() const { return 1e6 * wall_s / static_cast<double>(steps); }
  // CPU time per step (all threads): the work, robust to other work sharing
  // the cores (which stretches the wall time, not the CPU time).
  double cpu_us_per_step() const { return 1e6 * cpu_s / static_cast<double>(steps); }
  double ns_per_block_step() const { return 1e3 * us_per_step() / blocks; }
  double ns_per_candidate() const { return 1e3 * us_per_step() / candidates_per_step; }
  double ns_per_touching() const { return 1e3 * us_per_step() / touching_per_step; }
  // ~threads when every thread ran all the time; near 1 with 2 threads means
  // the cores were busy with something else (the timing is then not clean).
  double cpu_per_wall() const { return cpu_s / wall_s; }
};

// Advances `steps` steps as Simulation::advance calls of kSampleEvery steps
// (one thread team each, as the drivers run), summing the pair counts read
// between them (per step) into candidates and touching.
void sampled_advance(dda::Simulation& sim, int steps, double& candidates, double& touching) {
  for (int k = 0; k < steps; k += kSampleEvery) {
    const int n = std::min(kSampleEvery, steps - k);
    sim.advance(n);
    candidates += n * static_cast<double>(sim.candidate_count());
    touching += n * static_cast<double>(sim.contact_count());
  }
}

// Warms up, then times `steps` steps.
RunStats timed_run(dda::Simulation& sim, int threads, int warmup, int steps) {
  sim.set_threads(threads);
  sim.advance(warmup);
  sim.reset_phase_times();
  double candidates = 0.0, touching = 0.0;
  const std::clock_t cpu_start = std::clock();
  const Clock::time_point start = Clock::now();
  sampled_advance(sim, steps, candidates, touching);
  const Clock::time_point stop = Clock::now();
  const std::clock_t cpu_stop = std::clock();
  RunStats r;
  r.threads = threads;
  r.blocks = sim.scene_block_count();
  r.steps = steps;
  r.wall_s = std::chrono::duration<double>(stop - start).count();
  r.cpu_s = static_cast<double>(cpu_stop - cpu_start) / CLOCKS_PER_SEC;
  r.candidates_per_step = candidates / steps;
  r.touching_per_step = touching / steps;
  r.phases = sim.phase_times();
  return r;
}

// Two independent 1-thread runs of the scene at once, each on its own
// std::thread with its own Simulation: nothing shared, no barrier. Both warm
// up, wait for each other, then run the same timed steps as timed_run; the
// result is the wall time from the first start to the last stop. Two runs'
// work in that time against one run's in timed_run's is what this host gives
// two cores at best (host_ceiling).
double independent_pair_wall(const dda::Scene& scene, int warmup, int steps) {
  dda::Simulation sims[2] = {dda::Simulation(scene), dda::Simulation(scene)};
  std::atomic<int> ready{0};
  Clock::time_point start[2], stop[2];
  auto run = [&](int k) {
    dda::Simulation& sim = sims[k];
    sim.set_threads(1);
    sim.advance(warmup);
    ready.fetch_add(1);
    while (ready.load() < 2) {
    }
    double candidates = 0.0, touching = 0.0;
    start[k] = Clock::now();
    sampled_advance(sim, steps, candidates, touching);
    stop[k] = Clock::now();
  };
  std::thread other(run, 1);
  run(0);
  other.join();
  return std::chrono::duration<double>(std::max(stop[0], stop[1]) - std::min(start[0], start[1])).count();
}

bool same_bits(const double* a, const double* b, std::size_t n) { return std::memcmp(a, b, n * sizeof(double)) == 0; }

// Every vertex and velocity component of every polygon, bit for bit.
bool identical_state(const dda::Simulation& a, const dda::Simulation& b) {
  if (a.block_count() != b.block_count() || a.step_count() != b.step_count()) return false;
  for (int i = 0; i < a.block_count(); ++i) {
    const dda::Polygon& p = a.polygon(i);
    const dda::Polygon& q = b.polygon(i);
    if (p.count != q.count) return false;
    for (int k = 0; k < p.count; ++k) {
      const double pv[2] = {p.vertex(k).x, p.vertex(k).y}, qv[2] = {q.vertex(k).x, q.vertex(k).y};
      if (!same_bits(pv, qv, 2)) return false;
    }
    if (!same_bits(a.velocity(i).data(), b.velocity(i).data(), 6)) return false;
  }
  return true;
}

// Pairs whose x-intervals overlap in the final state: the work of one pass
// of an x sort-and-sweep on the blocks' boxes (its y test then rejects most).
std::int64_t x_overlap_pairs(const dda::Simulation& sim) {
  std::vector<std::pair<double, double>> x;  // (lo, hi)
  for (int i = 0; i < sim.block_count(); ++i) {
    const dda::Aabb b = dda::bounds(sim.polygon(i));
    x.emplace_back(b.lo.x, b.hi.x);
  }
  std::sort(x.begin(), x.end());
  std::int64_t pairs = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const auto end = std::upper_bound(x.begin() + static_cast<std::ptrdiff_t>(i) + 1, x.end(),
                                      std::make_pair(x[i].second, DBL_MAX));
    pairs += end - (x.begin() + static_cast<std::ptrdiff_t>(i) + 1);
  }
  return pairs;
}

// One run per thread count on the same scene; `same` says whether all final
// states equal the first one bit for bit.
// Heap bytes in use (glibc's mallinfo2): what the process has allocated and
// not freed, independent of pages the allocator keeps for reuse; the chunks
// glibc maps on their own (hblkhd: allocations above its mmap threshold, the
// big per-block arrays of a large scene) count too.
double heap_bytes() {
  const struct mallinfo2 m = mallinfo2();
  return static_cast<double>(m.uordblks + m.hblkhd);
}

struct ThreadRuns {
  std::vector<RunStats> runs;
  bool same = true;
  std::int64_t x_pairs = 0;
  // Memory of the first (1-thread) simulation: heap bytes per scene block
  // when constructed (polygons, the 6-DOF state, mass matrices, bisectors,
  // broad-phase boxes), and the heap growth over the warm-up and the timed
  // steps per touching pair at the end (the contacts' state and buffers),
  // and the heap per scene block at the end of the run (both together).
  double bytes_per_block = 0.0, growth_per_touching = 0.0, end_bytes_per_block = 0.0;
  // Of it, the block geometry: the pooled vertices and normals and their
  // offsets per block (Simulation::geometry_bytes_per_block).
  std::size_t geometry_per_block = 0;
  // Of the rest, the broad phase's near pairs at construction: how many per
  // block and the solver state each holds (Simulation::bytes_per_near_pair).
  double near_pairs_per_block = 0.0;
  std::size_t bytes_per_near_pair = 0;
  // CPU time of the first simulation's constructor (blocks, H, broad
  // phase, forces at t = 0; serial), s.
  double construct_s = 0.0;
};

ThreadRuns run_thread_counts(const dda::Scene& scene, int warmup, int steps, int max_threads = 2) {
  ThreadRuns out;
  std::unique_ptr<dda::Simulation> first;
  for (int threads : kThreadCounts) {
    if (threads > max_threads) break;
    const double before = heap_bytes();
    const std::clock_t t0 = std::clock();
    auto sim = std::make_unique<dda::Simulation>(scene);
    const double construct_s = static_cast<double>(std::clock() - t0) / CLOCKS_PER_SEC;
    const double built = heap_bytes();
    const std::size_t near_pairs = sim->near_pair_count();
    out.runs.push_back(timed_run(*sim, threads, warmup, steps));
    if (!first) {
      out.bytes_per_block = (built - before) / sim->scene_block_count();
      out.geometry_per_block = sim->geometry_bytes_per_block();
      out.near_pairs_per_block = static_cast<double>(near_pairs) / sim->scene_block_count();
      out.bytes_per_near_pair = sim->bytes_per_near_pair();
      out.construct_s = construct_s;
      const double touching = static_cast<double>(sim->contact_count());
      const double end = heap_bytes();
      out.growth_per_touching = touching > 0.0 ? (end - built) / touching : 0.0;
      out.end_bytes_per_block = (end - before) / sim->scene_block_count();
      out.x_pairs = x_overlap_pairs(*sim);
      first = std::move(sim);
    } else {
      out.same = out.same && identical_state(*first, *sim);
    }
  }
  return out;
}

// The 1-minute load average (Linux), to judge whether other work shared the cores.
std::string load_note(const char* when = "before the runs") {
  std::ifstream f("/proc/loadavg");
  double load = 0.0;
  if (!(f >> load)) return "load average unknown";
  char buf[64];
  std::snprintf(buf, sizeof buf, "load average %.2f %s", load, when);
  return buf;
}

// The mean round trip of a cache line between two threads (ns), as the
// two cores the OS gives them see it: one thread stores a number, the other
// answers with the next, kPingPongRounds times. A team's barriers and
// every polygon or load that one core writes and the other reads pay this
// latency, so the 2-thread speed-up follows it (on a virtual machine it can
// change from one minute to the next with the host's placement of the vCPUs).
constexpr int kPingPongRounds = 20000;  // ~10 ms at ~0.5 us per round trip

double core_round_trip_ns() {
  alignas(64) std::atomic<int> ball{0};
  std::thread partner([&ball] {
    for (int r = 0; r < kPingPongRounds; ++r) {
      while (ball.load(std::memory_order_acquire) != 2 * r + 1) {
      }
      ball.store(2 * r + 2, std::memory_order_release);
    }
  });
  const Clock::time_point t0 = Clock::now();
  for (int r = 0; r < kPingPongRounds; ++r) {
    ball.store(2 * r + 1, std::memory_order_release);
    while (ball.load(std::memory_order_acquire) != 2 * r + 2) {
    }
  }
  const double s = std::chrono::duration<double>(Clock::now() - t0).count();
  partner.join();
  return s / kPingPongRounds * 1e9;
}

const char* openmp_note() {
#if defined(_OPENMP)
  return "OpenMP build";
#else
  return "NO OpenMP: the 2-thread runs are single-threaded";
#endif
}

// ---------------------------------------------------------------------------
// The shortened collapse.
// ---------------------------------------------------------------------------

// The index of the median of v (the lower middle for an even count).
std::size_t median_index(const std::vector<double>& v) {
  std::vector<std::size_t> order(v.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&v](std::size_t x, std::size_t y) { return v[x] < v[y]; });
  return order[(order.size() - 1) / 2];
}

std::string round_list(const std::vector<double>& v) {
  std::string s;
  char buf[32];
  for (double x : v) {
    std::snprintf(buf, sizeof buf, "%s%.2f", s.empty() ? "" : " ", x);
    s += buf;
  }
  return s;
}

// Where the table's runs spent their wall time (Simulation::phase_times):
// per phase of the step and thread, ms working and waiting at the phase's
// closing barrier; and for the 2-thread run, its threads' work summed
// against the 1-thread run's (above 1: splitting the phase made its work
// itself slower: lines shared between the cores, a slower core, the host).
void print_phases(const std::vector<RunStats>& runs) {
  const char* names[dda::Simulation::kPhaseCount] = {"move blocks", "broad rebuild", "pair loop", "gather + kick",
                                                      "guards, energy"};
  std::printf("   where the time went, ms (work / wait at the phase's barrier):\n");
  std::printf("   %-16s", "phase");
  for (const RunStats& r : runs)
    for (std::size_t t = 0; t < r.phases.size(); ++t) std::printf("  %d thr, thread %zu", r.threads, t);
  std::printf("  work 2 thr / 1 thr\n");
  for (int p = 0; p < dda::Simulation::kPhaseCount; ++p) {
    std::printf("   %-16s", names[p]);
    double sum[2] = {0.0, 0.0};
    for (std::size_t k = 0; k < runs.size(); ++k)
      for (const dda::Simulation::PhaseTimes& pt : runs[k].phases) {
        std::printf("  %7.1f / %6.1f", 1e3 * pt.work[p], 1e3 * pt.wait[p]);
        if (k < 2) sum[k] += pt.work[p];
      }
    std::printf("  %18.2f\n", sum[0] > 0.0 ? sum[1] / sum[0] : 0.0);
  }
}

int run_collapse(const Options& o) {
  const dda::paper::Collapse c = dda::paper::collapse(kJointFrictionDeg);
  const dda::Scene& s = c.scene;
  std::printf("== Sect. 6.1 collapse, case 1 (joint friction %.0f deg): %zu blocks (%d slivers dropped), dt = %g s\n",
              kJointFrictionDeg, s.blocks.size(), c.dropped, s.dt);
  std::printf("   warm-up %d steps, then %d timed steps (%.3g s simulated), %d round(s); %s, %u hardware threads, %s\n",
              o.warmup, o.steps, o.steps * s.dt, o.rounds, openmp_note(), std::thread::hardware_concurrency(),
              load_note().c_str());
  const double trip_before = core_round_trip_ns();
  // Each round: 1 thread, 2 threads, the independent pair, one after the
  // other, so that the three see the same minute of the host.
  std::vector<ThreadRuns> rounds;
  std::vector<double> speedup, ceiling, busy, of_ceiling;
  bool same = true;
  for (int r = 0; r < o.rounds; ++r) {
    rounds.push_back(run_thread_counts(s, o.warmup, o.steps));
    const ThreadRuns& t = rounds.back();
    same = same && t.same;
    const double pair = independent_pair_wall(s, o.warmup, o.steps);
    speedup.push_back(t.runs[0].wall_s / t.runs[1].wall_s);
    ceiling.push_back(2.0 * t.runs[0].wall_s / pair);
    busy.push_back(pair / t.runs[1].wall_s);
    of_ceiling.push_back(speedup.back() / ceiling.back());
  }
  const double trip_after = core_round_trip_ns();
  const std::size_t m = median_index(speedup);
  std::printf("%8s %9s %9s %9s %11s %11s %9s %9s %12s\n", "threads", "wall s", "cpu/wall", "steps/s", "cand/step",
              "touch/step", "ns/cand", "ns/touch", "75k steps s");
  for (const RunStats& r : rounds[m].runs)
    std::printf("%8d %9.3f %9.2f %9.1f %11.1f %11.1f %9.1f %9.1f %12.1f\n", r.threads, r.wall_s, r.cpu_per_wall(),
                static_cast<double>(r.steps) / r.wall_s, r.candidates_per_step, r.touching_per_step,
                r.ns_per_candidate(), r.ns_per_touching(),
                r.wall_s / static_cast<double>(r.steps) * static_cast<double>(kFullRunSteps));
  std::printf("   speed-up 2 vs 1 thread: %.2fx (the table's round, the median; rounds: %s); final states\n"
              "   1 vs 2 threads bit-identical: %s\n",
              speedup[m], round_list(speedup).c_str(), same ? "yes" : "NO");
  std::printf("   host ceiling: two independent 1-thread runs at once give %.2fx the throughput of one alone\n"
              "   (median; rounds: %s): the bound of a 2-thread speed-up in the same minutes (one round's\n"
              "   speed-up may pass its ceiling when the host's speed changed between the round's runs)\n",
              ceiling[median_index(ceiling)], round_list(ceiling).c_str());
  std::printf("   2 threads against 1 with both cores busy: the independent pair's wall / the 2-thread run's\n"
              "   = %.2fx (median; rounds: %s; 2x if the pair loop, the barriers and the shared lines cost nothing)\n",
              busy[median_index(busy)], round_list(busy).c_str());
  std::printf("   speed-up / ceiling: %.2f (median; rounds: %s; 1 when splitting the step costs nothing; on a\n"
              "   crowded host, a descheduled thread of the team makes its partner wait at the step's barriers,\n"
              "   which the independent runs never do: see the waits below and the %s)\n",
              of_ceiling[median_index(of_ceiling)], round_list(of_ceiling).c_str(), load_note("after them").c_str());
  print_phases(rounds[m].runs);
  std::printf("   core-to-core round trip of a cache line: %.0f ns before, %.0f ns after the runs (the 2-thread\n"
              "   speed-up falls as it grows: barriers and the polygons and loads shared by the two cores pay it)\n",
              trip_before, trip_after);
  std::printf("   75k steps s: projected wall time of the full 7.5 s run (75,000 steps) at this run's mean cost per step\n");
  std::printf("   ns/cand, ns/touch: wall / steps / mean pairs (the whole step shared out over its pairs)\n");
  return same ? 0 : 1;
}

// ---------------------------------------------------------------------------
// Scaling with block count.
// ---------------------------------------------------------------------------

// The collapse scene with its column replaced by a width x height region
// cut by the same joint sets, on the same kind of floor and wall.
dda::Scene scaled_scene(const dda::paper::Collapse& base, double width, double height, int& dropped) {
  const std::vector<dda::Vec2> region = {{0.0, 0.0}, {width, 0.0}, {width, height}, {0.0, height}};
  const dda::GeneratedBlocks g = dda::generate_blocks(region, base.joint_sets, base.min_area);
  dropped = g.dropped;
  dda::Scene s = base.scene;  // materials, contact, gravity, broad phase, dt
  s.name = "scaled 6.1 collapse, " + std::to_string(width) + " m x " + std::to_string(height) + " m";
  s.blocks.clear();
  for (const dda::Polygon& p : g.blocks) {
    dda::BlockSpec b;
    b.vertices.assign(p.v.begin(), p.v.begin() + p.count);
    b.group = dda::paper::kRockGroup;
    s.blocks.push_back(std::move(b));
  }
  // Wall (solid for x < 0) and floor (solid for y < 0), as collapse() builds them.
  const double depth = base.scene.boundaries.front().depth;
  const double wall_height_factor = 1.2;  // the collapse's wall rises 20% above its column
  dda::BoundarySegment wall, floor;
  wall.a = {0.0, wall_height_factor * height};
  wall.b = {0.0, 0.0};
  floor.a = {-depth, 0.0};
  floor.b = {width + kRunoutLength, 0.0};
  wall.depth = floor.depth = depth;
  wall.group = floor.group = dda::paper::kBoundaryGroup;
  s.boundaries = {wall, floor};
  return s;
}

// Region size for about `target` blocks: the block density is the collapse's.
std::pair<double, double> region_for(const dda::paper::Collapse& base, Shape shape, double target) {
  const double ratio = target / static_cast<double>(base.scene.blocks.size());
  if (shape == Shape::kWide) return {base.width * ratio, base.height};
  const double scale = std::sqrt(ratio);
  return {base.width * scale, base.height * scale};
}

struct ScalingRow {
  int target = 0;
  double width = 0.0, height = 0.0;
  int warmup = 0;
  double generate_s = 0.0;  // CPU time of cutting the region into blocks (generate_blocks) and building the scene, s
  ThreadRuns t;
};

ScalingRow scaling_row(const dda::paper::Collapse& base, Shape shape, int target, int warmup, int max_threads) {
  ScalingRow row;
  row.target = target;
  // One correction of the size for the actual count (edge pieces, slivers).
  auto [w, h] = region_for(base, shape, target);
  int dropped = 0;
  const std::size_t first = scaled_scene(base, w, h, dropped).blocks.size();
  const double fix = target / static_cast<double>(first);
  if (shape == Shape::kWide) w *= fix;
  else {
    w *= std::sqrt(fix);
    h *= std::sqrt(fix);
  }
  row.width = w;
  row.height = h;
  const std::clock_t t0 = std::clock();
  const dda::Scene s = scaled_scene(base, w, h, dropped);
  row.generate_s = static_cast<double>(std::clock() - t0) / CLOCKS_PER_SEC;
  const int n = static_cast<int>(s.blocks.size());
  const int steps = std::clamp(static_cast<int>(kBlockStepBudget / n), kMinScalingSteps, kMaxScalingSteps);
  row.warmup = warmup;
  row.t = run_thread_counts(s, warmup, steps, max_threads);
  return row;
}

// Least-squares slope of log(cost) against log(blocks) over the rows;
// cost(row) is the cost of one row (time per step, setup time).
template <class Cost>
double growth_exponent(const std::vector<ScalingRow>& rows, Cost cost) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(rows.size());
  for (const ScalingRow& r : rows) {
    const double x = std::log(r.t.runs[0].blocks), y = std::log(cost(r));
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

void write_csv(const std::string& path, const std::vector<ScalingRow>& rows, Shape shape) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp);
    if (!f) throw std::runtime_error("cannot write " + tmp);
    f << "shape,blocks,width_m,height_m,threads,warmup_steps,steps,wall_s,candidates_per_step,touching_per_step,"
         "x_overlap_pairs,cpu_per_wall,us_per_step,cpu_us_per_step,ns_per_block_step,ns_per_candidate,ns_per_touching,identical_1_2,"
         "bytes_per_block,growth_bytes_per_touching,near_pairs_per_block,bytes_per_near_pair,generate_s,construct_s,"
         "end_bytes_per_block\n";
    f.precision(9);
    for (const ScalingRow& r : rows)
      for (const RunStats& s : r.t.runs)
        f << (shape == Shape::kWide ? "wide" : "column") << ',' << s.blocks << ',' << r.width << ',' << r.height
          << ',' << s.threads << ',' << r.warmup << ',' << s.steps << ',' << s.wall_s << ',' << s.candidates_per_step << ','
          << s.touching_per_step << ',' << r.t.x_pairs << ',' << s.cpu_per_wall() << ',' << s.us_per_step() << ',' << s.cpu_us_per_step() << ',' << s.ns_per_block_step()
          << ',' << s.ns_per_candidate() << ',' << s.ns_per_touching() << ',' << (r.t.runs.size() < 2 ? "" : r.t.same ? "1" : "0") << ','
          << r.t.bytes_per_block << ',' << r.t.growth_per_touching << ',' << r.t.near_pairs_per_block << ','
          << r.t.bytes_per_near_pair << ',' << r.generate_s << ',' << r.t.construct_s << ',' << r.t.end_bytes_per_block
          << '\n';
    if (!f) throw std::runtime_error("error writing " + tmp);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) throw std::runtime_error("cannot rename " + tmp + " to " + path);
}

int run_scaling(const Options& o) {
  const dda::paper::Collapse base = dda::paper::collapse(kJointFrictionDeg);
  std::printf("== scaling with block count: %s regions cut by the collapse's joint sets (dip 80/40 deg, spacing "
              "1.5/2.5 m), floor and wall; %s\n",
              o.shape == Shape::kWide ? "50 m high, widening" : "20:50 columns, scaled", openmp_note());
  std::printf("   warm-up %d steps, then %g / blocks steps (%d to %d); %s\n", o.warmup, kBlockStepBudget,
              kMinScalingSteps, kMaxScalingSteps, load_note().c_str());
  std::printf("   sizeof(dda::Polygon) = %zu bytes (capacity %d vertices and normals; scratch and intersection "
              "polygons), sizeof(dda::PolygonView) = %zu bytes (a pooled block's view)\n",
              sizeof(dda::Polygon), dda::kMaxVertices, sizeof(dda::PolygonView));
  std::printf("%7s %11s %3s %5s %8s %10s %10s %10s %10s %10s %11s %8s %8s %5s %8s %9s %6s %7s %8s %10s %7s %7s\n", "blocks",
              "region m", "thr", "steps", "cpu/wall", "cand/step", "touch/step", "x-overlap", "us/step", "cpu us",
              "ns/blk-step", "ns/cand", "ns/touch", "same", "kB/block", "geo B/blk", "np/blk", "B/np", "B/touch",
              "end kB/blk", "gen s", "build s");
  std::vector<ScalingRow> rows;
  for (int target : kTargetBlocks) {
    if (target > o.max_blocks || target < o.min_blocks) continue;
    rows.push_back(scaling_row(base, o.shape, target, o.warmup, o.max_threads));
    const ScalingRow& r = rows.back();
    for (const RunStats& s : r.t.runs)
      std::printf("%7d %5.0fx%-5.0f %3d %5lld %8.2f %10.1f %10.1f %10lld %10.1f %10.1f %11.1f %8.1f %8.1f %5s %8.2f %9zu %6.2f %7zu %8.0f %10.2f %7.2f %7.2f\n",
                  s.blocks, r.width, r.height, s.threads, static_cast<long long>(s.steps), s.cpu_per_wall(),
                  s.candidates_per_step, s.touching_per_step, static_cast<long long>(r.t.x_pairs), s.us_per_step(),
                  s.cpu_us_per_step(), s.ns_per_block_step(), s.ns_per_candidate(), s.ns_per_touching(),
                  r.t.runs.size() < 2 ? "-" : r.t.same ? "yes" : "NO", r.t.bytes_per_block / 1e3, r.t.geometry_per_block,
                  r.t.near_pairs_per_block, r.t.bytes_per_near_pair,
                  r.t.growth_per_touching, r.t.end_bytes_per_block / 1e3, r.generate_s, r.t.construct_s);
    std::fflush(stdout);
  }
  bool all_same = true;
  for (const ScalingRow& r : rows) all_same = all_same && r.t.same;
  if (rows.size() >= 2) {
    for (std::size_t k = 0; k < rows.front().t.runs.size(); ++k)
      std::printf("   %d thread(s): wall us/step ~ blocks^%.2f, CPU us/step ~ blocks^%.2f (least squares over the rows;"
                  " the CPU fit is the one to trust when cpu/wall < threads: the cores were shared)\n",
                  kThreadCounts[k], growth_exponent(rows, [k](const ScalingRow& r) { return r.t.runs[k].us_per_step(); }),
                  growth_exponent(rows, [k](const ScalingRow& r) { return r.t.runs[k].cpu_us_per_step(); }));
    std::printf("   setup: generating the scene ~ blocks^%.2f, constructing the simulation ~ blocks^%.2f (CPU time)\n",
                growth_exponent(rows, [](const ScalingRow& r) { return r.generate_s; }),
                growth_exponent(rows, [](const ScalingRow& r) { return r.t.construct_s; }));
  }
  std::printf("   x-overlap: pairs whose x-intervals overlap at the end (one x sort-and-sweep pass visits them);"
              " same: 1- and 2-thread final states bit-identical;\n   kB/block: heap per block of the constructed "
              "simulation; geo B/blk: of it, the pooled block geometry (vertices, normals, offsets);\n   np/blk, B/np: "
              "of it, the near pairs per block at construction and the solver state of each;\n   B/touch: heap "
              "growth over the run per touching pair at its end (mallinfo2); end kB/blk: heap per block at the\n   "
              "end of the run (kB/block + touching pairs x B/touch); gen s, build s: CPU time of\n   "
              "generating the scene and of constructing the first simulation\n");
  if (!o.csv.empty()) {
    write_csv(o.csv, rows, o.shape);
    std::printf("   wrote %s\n", o.csv.c_str());
  }
  return all_same ? 0 : 1;
}

// ---------------------------------------------------------------------------
// What a scene skips.
// ---------------------------------------------------------------------------

struct SkipRow {
  const char* name;
  dda::Scene scene;
  bool whole_run;  // time the scene's whole duration from t = 0 (the squares touch at 0.5 s)
};

int run_skips(const Options& o) {
  const dda::Scene collapse = dda::paper::collapse(kJointFrictionDeg).scene;
  dda::Scene frictionless = collapse;
  frictionless.contact.kt = 0.0;  // ContactParams::friction() is kt > 0
  dda::Scene rigid = collapse;
  rigid.strains = false;
  dda::Scene squares = dda::paper::two_squares();
  squares.broad_phase = dda::BroadPhase::kNone;
  dda::Scene squares_sweep = squares;
  squares_sweep.broad_phase = dda::BroadPhase::kSweep;
  const SkipRow rows[] = {{"collapse, friction 15 deg, deformable", collapse, false},
                          {"collapse, frictionless (kt = 0)", frictionless, false},
                          {"collapse, rigid blocks (no strains)", rigid, false},
                          {"4.1 two squares, all-pairs test", squares, true},
                          {"4.1 two squares, sweep broad phase", squares_sweep, true}};
  std::printf("== what a scene skips: 1 thread; the collapse %d warm-up + %d timed steps, the squares their whole "
              "%.1f s run; %s\n",
              o.warmup, o.steps, squares.duration, load_note().c_str());
  std::printf("%-40s %7s %10s %11s %10s %10s %9s %9s %7s\n", "scene", "blocks", "touch/step", "cpu us/step",
              "ns/touch", "kB/block", "geo B/blk", "B/touch", "B/pair");
  for (const SkipRow& r : rows) {
    const double before = heap_bytes();
    dda::Simulation sim(r.scene);
    const double built = heap_bytes();
    const int whole = static_cast<int>(std::lround(r.scene.duration / r.scene.dt));
    const RunStats st = r.whole_run ? timed_run(sim, 1, 0, whole) : timed_run(sim, 1, o.warmup, o.steps);
    const double touching = static_cast<double>(sim.contact_count());
    const double cpu_us = 1e6 * st.cpu_s / static_cast<double>(st.steps);
    // Per touching pair only where a pair touches on most steps (the squares touch for ~2 % of theirs).
    char per_touch[32] = "-", per_touch_heap[32] = "-";
    if (st.touching_per_step >= 1.0) std::snprintf(per_touch, sizeof per_touch, "%.1f", 1e3 * cpu_us / st.touching_per_step);
    if (touching > 0.0) std::snprintf(per_touch_heap, sizeof per_touch_heap, "%.0f", (heap_bytes() - built) / touching);
    std::printf("%-40s %7d %10.2f %11.2f %10s %10.2f %9zu %9s %7zu\n", r.name, st.blocks, st.touching_per_step, cpu_us,
                per_touch, (built - before) / st.blocks / 1e3, sim.geometry_bytes_per_block(), per_touch_heap,
                sim.bytes_per_near_pair());
    std::fflush(stdout);
  }
  std::printf("   cpu us/step: process CPU time per step (robust to a shared machine); ns/touch: the same per\n"
              "   touching pair; kB/block: heap of the constructed simulation per block; geo B/blk: of it, the\n"
              "   pooled block geometry (vertices, normals, offsets; a Polygon value per block was %zu B);\n"
              "   B/touch: heap growth\n"
              "   over the run per touching pair at its end; B/pair: solver state per broad-phase near pair\n"
              "   (a frictionless scene has no friction history: Simulation::bytes_per_near_pair)\n",
              sizeof(dda::Polygon));
  return 0;
}

}  // namespace

// ---------------------------------------------------------------------------
// The instruction-count window.
// ---------------------------------------------------------------------------

// FNV-1a over every block's vertices and velocity DOFs: equal for two runs
// whose states are equal bit for bit.
std::uint64_t state_fingerprint(const dda::Simulation& sim) {
  std::uint64_t h = 1469598103934665603ull;
  auto mix = [&](const void* p, std::size_t n) {
    const unsigned char* c = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ c[i]) * 1099511628211ull;
  };
  for (int i = 0; i < sim.block_count(); ++i) {
    const dda::PolygonView p = sim.polygon_view(i);
    mix(p.v, sizeof(dda::Vec2) * static_cast<std::size_t>(p.count));
    mix(sim.velocity(i).data(), sizeof(double) * 6);
  }
  return h;
}

int run_window(const Options& o) {
  dda::Scene s = dda::paper::collapse(kJointFrictionDeg).scene;
  if (o.no_guards) {
    s.guards.max_step_motion = DBL_MAX;
    s.guards.max_balance_error = 0.0;
    s.guards.max_energy_growth = DBL_MAX;  // must be positive; not checked with energy_check_every = 0
    s.guards.energy_check_every = 0;
    s.guards.max_penetration = 0.0;
    s.guards.max_approach_energy = 0.0;
  }
  dda::Simulation sim(s);
  sim.set_threads(1);
  sim.advance_to(o.window);
  std::printf("window %.3g s: %lld steps, %zu touching pairs at the end, guards %s, state fingerprint %016llx\n",
              o.window, static_cast<long long>(sim.step_count()), sim.contact_count(), o.no_guards ? "off" : "on",
              static_cast<unsigned long long>(state_fingerprint(sim)));
  return 0;
}

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  try {
    if (o.window > 0.0) return run_window(o);
    if (o.skips) return run_skips(o);
    return o.scaling ? run_scaling(o) : run_collapse(o);
  } catch (const std::exception& e) {
    std::cerr << "bench_collapse: " << e.what() << "\n";
    return 1;
  }
}
