// The explicit DDA step as a table of contents: each phase lives in its own
// file (see internal.hpp); run_steps below lists them in order.
#include <exception>

#include "simulation/internal.hpp"
#include "team_barrier.hpp"

namespace dda {

void Engine::advance_to(double t) {
  std::int64_t count = 0;
  while (static_cast<double>(steps_ + count) * dt_ + 0.5 * dt_ < t) ++count;
  run_steps(count);
}

void Engine::run_steps(std::int64_t count) {
  // Paper A Sect. 2.3: velocity Verlet (Eqs. 6-8) with the potential
  // contact forces of Sect. 3 at t^{n+1}. One parallel region serves all
  // `count` steps: every thread runs this loop and each phase shares out its
  // own loop (per block or per near pair; team.cpp). Each block's and each
  // pair's result is computed by one thread and each block sums its pair
  // forces in pair order: the same bits for any thread count. A guard's
  // SimulationError cannot leave the parallel region: it is caught where it
  // is thrown, every thread stops after that step, and it is rethrown here.
  if (count <= 0) return;
  const std::int64_t first = steps_;
  const int every = scene_.guards.energy_check_every;
  std::exception_ptr error;
  detail::TeamBarrier barrier;
  barrier_ = &barrier;
  // The flags are set afresh in every step; the measured speeds (and in
  // start_team the shares) carry over from the last call with the same
  // team: an advance of a few steps at a time starts balanced.
  if (flags_.size() != static_cast<std::size_t>(threads_)) flags_.assign(static_cast<std::size_t>(threads_), ThreadFlags{});
  for (ThreadFlags& f : flags_) f.left_skin = f.guard_failed = f.pair_failed = false;
  if (thread_contacts_.size() < static_cast<std::size_t>(threads_)) thread_contacts_.resize(static_cast<std::size_t>(threads_));
  // Alone, the loop runs outside any parallel region: an OpenMP team of one
  // still pays two futex system calls per region (its start and the single's
  // barrier), as much as a small scene's whole step when it is advanced one
  // step at a time.
  const auto team_steps = [&] {
    start_team();  // team.cpp: first shares, barrier reset
    for (std::int64_t k = 0; k < count; ++k) {
      const std::int64_t done = first + k + 1;
      const bool energy_due = every > 0 && done % every == 0;
      // integration.cpp, Eqs. 7-8: v^{n+1/2} = v^n + h/2 a^n, move by
      // h v^{n+1/2}; the moved geometry.
      move_blocks();
      // broad_phase.cpp: the near pairs, rebuilt when a block left its grown box.
      update_near_pairs();
      // contact_forces.cpp + friction.hpp: per pair, overlap and IP (Sect.
      // 3.1), normal force and pg (Eqs. 10-20), friction (Eqs. 24-26).
      pair_forces(energy_due);
      // integration.cpp, Eqs. 22-23, 28-29, 6-7: F^{n+1}, the body forces
      // (gravity, Eq. 4's K d) and the contact forces summed in pair order
      // through T(pg)^T, a^{n+1}, v^{n+1}; per-block guard flags.
      gather_and_kick();
      if (detail::thread_index() == 0) balance_pair_split();  // team.cpp: the next pair loop's shares
      // guards.cpp: a failed guard or a due energy check stops the run.
      if (guards_stop(done, energy_due, error)) break;
    }
  };
  if (threads_ > 1) {
    DDA_OMP(omp parallel num_threads(threads_))
    team_steps();
  } else {
    team_steps();
  }
  barrier_ = nullptr;
  if (error) std::rethrow_exception(error);
  steps_ = first + count;
  time_ = static_cast<double>(steps_) * dt_;
  count_candidates();
}

void Engine::compute_forces() {
  // Serial: the pairs' loads at the current state, and with their candidate
  // flags each block's reach (the constructor's a^0: kick and
  // start_damping sum the blocks' forces).
  rebuild_near_pairs();
  if (thread_contacts_.empty()) thread_contacts_.resize(1);
  pair_forces(false);
  merge_contacts();  // contact_forces.cpp: slots for the pairs in contact
  count_candidates();
}

std::vector<ContactInfo> Engine::contacts() const {
  std::vector<ContactInfo> c;
  c.reserve(contact_count());
  each_contact([&](std::size_t k, const ContactSlot&) { c.push_back(contact_info(k)); });
  return c;
}

void Engine::count_candidates() {
  // The candidate pairs of the last force evaluation, for the accessor.
  candidate_count_ = 0;
  for (const NearPair& p : near_pairs_) candidate_count_ += p.candidate ? 1 : 0;
}

}  // namespace dda
