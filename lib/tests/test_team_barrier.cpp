#include <catch2/catch.hpp>

#include <atomic>
#include <thread>
#include <vector>

#include "team_barrier.hpp"

// The team barrier's contract: after wait() every thread sees what every
// other thread wrote before its wait(). Each round every thread publishes
// the round number in its slot, waits, reads all slots, and waits again
// before the next write. More threads than cores (4 on the 2-vCPU runner)
// checks that waiting threads yield their core.
TEST_CASE("team barrier: every thread sees the others' writes of the round", "[simulation]") {
  for (const int team : {2, 4}) {
    const int rounds = team == 2 ? 20000 : 2000;
    dda::detail::TeamBarrier barrier;
    barrier.reset(team);
    std::vector<int> slot(static_cast<std::size_t>(team) * 16, -1);  // one cache line apart
    std::atomic<long> stale{0};
    auto run = [&](int t) {
      long bad = 0;
      for (int r = 0; r < rounds; ++r) {
        slot[static_cast<std::size_t>(t) * 16] = r;
        barrier.wait();
        for (int u = 0; u < team; ++u) bad += slot[static_cast<std::size_t>(u) * 16] != r;
        barrier.wait();
      }
      stale += bad;
    };
    std::vector<std::thread> threads;
    for (int t = 1; t < team; ++t) threads.emplace_back(run, t);
    run(0);
    for (std::thread& th : threads) th.join();
    INFO("team " << team);
    CHECK(stale.load() == 0);
  }
}
