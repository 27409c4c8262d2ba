// The thread team of run_steps: its barrier and its shares of the blocks
// and of the near pairs, balanced by each core's measured speed. Only the
// time depends on the shares, never the results.
#include <algorithm>
#include <cmath>

#include "simulation/internal.hpp"
#include "team_barrier.hpp"

namespace dda {

using detail::thread_index;
using detail::team_size;
using detail::kPrefetchBlocks;
using detail::PhaseClock;

void Engine::start_team() {
  // The shares (the last call's while they fit the team and the lists,
  // else even ones), the barrier's reset and the phase times' slots, seen
  // by every thread after the single's implicit barrier; then each thread's
  // first phase begins.
  DDA_OMP(omp single)
  {
    const std::size_t slots = static_cast<std::size_t>(team_size()) + 1;
    const bool shares_fit = pair_split_.size() == slots && block_split_.size() == slots &&
                            pair_split_.back() == static_cast<long>(near_pairs_.size()) &&
                            block_split_.back() == block_count();
    if (!shares_fit) split_evenly(team_size());
    barrier_->reset(team_size());
    if (phase_times_.size() != static_cast<std::size_t>(team_size()))
      phase_times_.assign(static_cast<std::size_t>(team_size()), PhaseTimes{});
  }
  flags_[static_cast<std::size_t>(thread_index())].phase_start = PhaseClock::now();
}

void Engine::team_barrier(PhaseIndex phase) {
  // Every thread of a team waits here for the others (a no-op alone). In
  // run_steps, the thread's time since its phase began counts as work in
  // `phase`, the wait as waiting, and its next phase begins.
  if (!barrier_) return;  // compute_forces: serial, untimed
  const std::size_t t = static_cast<std::size_t>(thread_index());
  PhaseTimes& times = phase_times_[t];
  ThreadFlags& mine = flags_[t];
  const PhaseClock::time_point arrived = PhaseClock::now();
  times.work[phase] += std::chrono::duration<double>(arrived - mine.phase_start).count();
  if (team_size() > 1) barrier_->wait();
  mine.phase_start = team_size() > 1 ? PhaseClock::now() : arrived;
  times.wait[phase] += std::chrono::duration<double>(mine.phase_start - arrived).count();
}

Engine::BlockShare Engine::block_share() const {
  // This thread's contiguous share of the blocks (all of them outside a
  // team); which thread moves or kicks a block changes only the time.
  const int team = team_size(), t = thread_index();
  BlockShare s;
  if (team < 2) {
    s.end = block_count();
    return s;
  }
  s.team = true;
  s.begin = block_split_[static_cast<std::size_t>(t)];
  s.end = block_split_[static_cast<std::size_t>(t) + 1];
  s.prefetch_end = s.end - kPrefetchBlocks;
  return s;
}

void Engine::split_evenly(int team) {
  // Equal numbers of pairs and of blocks per thread (a start, before any
  // work or core speed is known).
  const long n = static_cast<long>(near_pairs_.size());
  pair_split_.resize(static_cast<std::size_t>(team) + 1);
  for (int t = 0; t <= team; ++t) pair_split_[static_cast<std::size_t>(t)] = n * t / team;
  block_split_.resize(static_cast<std::size_t>(team) + 1);
  for (int t = 0; t <= team; ++t) block_split_[static_cast<std::size_t>(t)] = block_count() * t / team;
  split_scratch_.resize(pair_split_.size());
  work_scratch_.resize(pair_split_.size());
}

void Engine::balance_block_split() {
  // Shares of the blocks in proportion to each core's measured speed
  // (blocks per second in the per-block phases), so that the phases end
  // together. Kept as they are until every core has a measurement.
  const int team = static_cast<int>(block_split_.size()) - 1;
  double speed_sum = 0.0;
  for (int t = 0; t < team; ++t) {
    const double c = flags_[static_cast<std::size_t>(t)].seconds_per_block;
    if (!(c > 0.0)) return;
    speed_sum += 1.0 / c;
  }
  double before = 0.0;
  for (int t = 1; t < team; ++t) {
    before += 1.0 / flags_[static_cast<std::size_t>(t) - 1].seconds_per_block;
    const int b = static_cast<int>(std::llround(block_count() * before / speed_sum));
    block_split_[static_cast<std::size_t>(t)] = std::clamp(b, block_split_[static_cast<std::size_t>(t) - 1], block_count());
  }
}

void Engine::balance_pair_split() {
  // The cost of each share in the last pair loop (its estimated work at
  // its core's measured speed, pair_work), taken as spread evenly over the
  // share's pairs; the new boundaries cut that cost into equal parts (by
  // linear interpolation inside the shares). Pairs change slowly from step
  // to step, so this follows the pile as it moves. Results do not depend
  // on the split: only the time.
  const int team = static_cast<int>(pair_split_.size()) - 1;
  if (team < 2) return;
  std::vector<double>& cum = work_scratch_;
  cum[0] = 0.0;
  for (int t = 0; t < team; ++t)
    cum[static_cast<std::size_t>(t) + 1] = cum[static_cast<std::size_t>(t)] + flags_[static_cast<std::size_t>(t)].pair_work;
  const double total = cum[static_cast<std::size_t>(team)];
  if (!(total > 0.0)) return;
  std::vector<long>& old = split_scratch_;
  old = pair_split_;
  int u = 0;
  for (int t = 1; t < team; ++t) {
    const double target = total * t / team;
    while (u < team - 1 && cum[static_cast<std::size_t>(u) + 1] <= target) ++u;
    const double w = cum[static_cast<std::size_t>(u) + 1] - cum[static_cast<std::size_t>(u)];
    const double frac = w > 0.0 ? (target - cum[static_cast<std::size_t>(u)]) / w : 0.0;
    const long lo = old[static_cast<std::size_t>(u)], hi = old[static_cast<std::size_t>(u) + 1];
    const long b = lo + static_cast<long>(std::llround(frac * static_cast<double>(hi - lo)));
    pair_split_[static_cast<std::size_t>(t)] = std::max(b, pair_split_[static_cast<std::size_t>(t) - 1]);
  }
}

}  // namespace dda
