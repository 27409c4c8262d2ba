// property_fuzz: the properties of properties.cpp with many cases and a
// random seed, for `make fuzz`.
//
//   FUZZ_CASES  cases per property (default 1000000)
//   FUZZ_SEED   rapidcheck seed (default: random); printed first, so any
//               failure can be replayed with FUZZ_SEED=<seed> FUZZ_CASES=<n>
//   arguments   Catch2 test specs, default "[property]" (every property);
//               e.g. property_fuzz "[overlap]" runs one group.
// A failure prints rapidcheck's shrunk counterexample (inputs as C++
// initialisers, ready for regressions.cpp) and RC_PARAMS to reproduce it.
#define CATCH_CONFIG_CONSOLE_WIDTH 1000  // counterexamples on one line each, ready to paste
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

namespace {

std::uint64_t seed_from_env() {
  if (const char* s = std::getenv("FUZZ_SEED")) return std::strtoull(s, nullptr, 10);
  std::random_device rd;
  return (static_cast<std::uint64_t>(rd()) << 32) ^ rd();
}

long cases_from_env() {
  const char* s = std::getenv("FUZZ_CASES");
  const long n = s ? std::strtol(s, nullptr, 10) : 1000000L;
  return n > 0 ? n : 1000000L;
}

}  // namespace

int main(int argc, char** argv) {
  const long cases = cases_from_env();
  const std::uint64_t seed = seed_from_env();
  // rapidcheck reads RC_PARAMS once, on first use, i.e. after this point.
  std::string params = "max_success=" + std::to_string(cases) + " seed=" + std::to_string(seed);
  if (const char* extra = std::getenv("RC_PARAMS")) params += std::string(" ") + extra;
  setenv("RC_PARAMS", params.c_str(), 1);
  std::printf("property_fuzz: %ld cases per property, seed %llu\n  replay: FUZZ_SEED=%llu FUZZ_CASES=%ld %s\n", cases,
              static_cast<unsigned long long>(seed), static_cast<unsigned long long>(seed), cases, argv[0]);
  std::fflush(stdout);

  std::vector<char*> args(argv, argv + argc);
  char default_spec[] = "[property]";
  char durations[] = "--durations";
  char yes[] = "yes";
  if (argc == 1) args.push_back(default_spec);
  args.push_back(durations);
  args.push_back(yes);
  Catch::Session session;
  const int rc = session.applyCommandLine(static_cast<int>(args.size()), args.data());
  if (rc != 0) return rc;
  // Listing (--list-tests and the like) runs nothing: Catch2 v2 returns the
  // number of listed items from run(), which is not a failure.
  const Catch::ConfigData& cfg = session.configData();
  if (cfg.listTests || cfg.listTestNamesOnly || cfg.listTags || cfg.listReporters) return session.run() > 0 ? 0 : 1;
  const int failed = session.run();
  if (failed != 0)
    std::printf("property_fuzz: FAILED with seed %llu (replay: FUZZ_SEED=%llu FUZZ_CASES=%ld)\n",
                static_cast<unsigned long long>(seed), static_cast<unsigned long long>(seed), cases);
  return failed;
}
