// Mutation fuzzer of scene files. Seeds: the valid scenes of
// repro/scenes and the io tests' bad files. Each case applies 1-3 random
// mutations to a seed (byte edits, insertions, deletions, truncation,
// token-level edits of the JSON document: deleted keys/elements, swapped
// types, huge/tiny/odd numbers, duplicated keys/elements, deeper nesting) and
//  - reads it in-process (dda::io::parse_scene): it must return a scene or
//    throw SceneFileError, nothing else; an accepted scene must round-trip
//    through write_scene, build a Simulation (or throw SceneError) and take a
//    few steps (or throw SimulationError);
//  - for --cli-runs of the cases, runs the `dda` tool as a subprocess:
//    `dda check` must exit 0 or 2 and agree with the in-process verdict;
//    `dda run --out DIR` must exit 0, 2 or 3 (the documented codes; 1, a
//    signal or a timeout is a failure) and leave either the complete output
//    (0, 3: timeseries.csv, snapshots.csv, run.json and no .tmp file) or
//    nothing (2: not even DIR).
// A hang is a case that takes longer than --case-seconds (default 60 s;
// in-process cases take milliseconds): the fuzzer stops with the case number.
// Deterministic: case k of seed S is the same on every machine; replay one
// with --seed S --first k --cases 1 --verbose.
//
//   io_scene_fuzz [--cases N] [--seed S|random] [--cli-runs M] [--first K]
//                 [--case-seconds T] [--verbose]
#include <sys/stat.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dda/io/scene_file.hpp"
#include "dda/simulation.hpp"

namespace fs = std::filesystem;
using nlohmann::ordered_json;

namespace {

// Steps an accepted scene takes in-process (enough to run contact detection,
// the guards and the output-free step loop; short enough for 10^5 cases).
constexpr int kInProcessSteps = 5;
// Steps of a `dda run` case: the seed's duration is cut to this many steps
// before mutating, so a run takes at most seconds.
constexpr int kCliRunSteps = 200;

struct Seed {
  std::string name, text;
  bool valid_json = false;
  ordered_json doc;
};

volatile std::sig_atomic_t g_case = -1;
extern "C" void on_alarm(int) {
  char buf[128];
  const int n = std::snprintf(buf, sizeof buf, "io_scene_fuzz: FAILED: case %ld exceeded the time limit (hang)\n",
                              static_cast<long>(g_case));
  if (n > 0) (void)!write(2, buf, static_cast<std::size_t>(n));
  _exit(1);
}
extern "C" void on_crash(int sig) {
  char buf[128];
  const int n = std::snprintf(buf, sizeof buf, "io_scene_fuzz: FAILED: signal %d in case %ld\n", sig,
                              static_cast<long>(g_case));
  if (n > 0) (void)!write(2, buf, static_cast<std::size_t>(n));
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::vector<Seed> load_seeds() {
  std::vector<Seed> seeds;
  for (const char* dir : {DDA_SCENES_DIR, DDA_IO_BAD_DIR}) {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".json") files.push_back(e.path());
    std::sort(files.begin(), files.end());  // the same order everywhere
    for (const fs::path& f : files) {
      Seed s;
      s.name = f.filename().string();
      s.text = slurp(f);
      try {
        s.doc = ordered_json::parse(s.text);
        s.valid_json = true;
      } catch (const std::exception&) {
      }
      seeds.push_back(std::move(s));
    }
  }
  return seeds;
}

using Rng = std::mt19937_64;

std::size_t pick(Rng& rng, std::size_t n) { return n == 0 ? 0 : std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); }

// Numbers that break naive readers and solvers.
double odd_number(Rng& rng) {
  static const double kOdd[] = {0.0,     -0.0,   1e308,   -1e308, 1.7976931348623157e308, 5e-324, -5e-324,
                                1e-300,  1e300,  1e154,   1e-154, 9.223372036854775807e18, 4294967296.0,
                                2147483648.0, -1.0, 0.5, 1e15,  1e-15, 3.0, 16.0, 17.0, 1e6, -1e6, 1e-6};
  return kOdd[pick(rng, sizeof kOdd / sizeof kOdd[0])];
}

// A random value of a random type.
ordered_json random_value(Rng& rng) {
  switch (pick(rng, 9)) {
    case 0: return nullptr;
    case 1: return pick(rng, 2) == 1;
    case 2: return odd_number(rng);
    case 3: return static_cast<std::int64_t>(pick(rng, 40)) - 5;
    case 4: return std::string(pick(rng, 3) ? "x" : "");
    case 5: return ordered_json::array();
    case 6: return ordered_json::object();
    case 7: return ordered_json::array({odd_number(rng), odd_number(rng)});
    default: return "rock";
  }
}

// Every node of the document (pre-order), as pointers.
void collect(ordered_json& j, std::vector<ordered_json*>& out) {
  out.push_back(&j);
  if (j.is_object() || j.is_array())
    for (auto& c : j) collect(c, out);
}

// One token-level edit of the document.
void mutate_doc(ordered_json& doc, Rng& rng) {
  std::vector<ordered_json*> nodes;
  collect(doc, nodes);
  ordered_json& n = *nodes[pick(rng, nodes.size())];
  switch (pick(rng, 8)) {
    case 0:  // delete a member or element
      if (n.is_object() && !n.empty()) {
        auto it = n.begin();
        std::advance(it, static_cast<std::ptrdiff_t>(pick(rng, n.size())));
        n.erase(it.key());
      } else if (n.is_array() && !n.empty()) {
        n.erase(n.begin() + static_cast<std::ptrdiff_t>(pick(rng, n.size())));
      }
      break;
    case 1:  // type swap: replace by a value of another type
      n = random_value(rng);
      break;
    case 2:  // a number becomes huge, tiny or odd
      if (n.is_number()) n = odd_number(rng);
      else if (n.is_array() && !n.empty()) n[pick(rng, n.size())] = odd_number(rng);
      break;
    case 3:  // duplicate an element (names, blocks, vertices)
      if (n.is_array() && !n.empty()) n.push_back(n[pick(rng, n.size())]);
      break;
    case 4:  // wrap in an array (deeper nesting)
      n = ordered_json::array({n});
      break;
    case 5:  // a number scaled (dt, duration, coordinates)
      if (n.is_number()) n = n.get<double>() * std::pow(10.0, static_cast<double>(pick(rng, 31)) - 15.0);
      break;
    case 6:  // an added key, sometimes a known one in the wrong place
      if (n.is_object()) {
        static const char* kKeys[] = {"name", "dt", "duration", "max_steps", "vertices", "rect", "material",
                                      "guards", "dt_fraction", "fixed", "velocity", "generated", "x"};
        n[kKeys[pick(rng, sizeof kKeys / sizeof kKeys[0])]] = random_value(rng);
      }
      break;
    default:  // a string changed (names, enum values)
      if (n.is_string()) n = pick(rng, 2) ? std::string("A") : n.get<std::string>() + "_";
      break;
  }
}

// One byte-level edit of the text.
void mutate_text(std::string& t, Rng& rng) {
  static const char kBytes[] = "{}[],:\"0123456789-+.eE \n\\tnul\0\x7f\xff";
  auto byte = [&] {
    return pick(rng, 4) == 0 ? static_cast<char>(pick(rng, 256)) : kBytes[pick(rng, sizeof kBytes - 1)];
  };
  const std::size_t at = pick(rng, t.size() + 1);
  switch (pick(rng, 7)) {
    case 0:
      if (at < t.size()) t[at] = byte();
      break;
    case 1: t.insert(at, 1, byte()); break;
    case 2: t.erase(at, pick(rng, 16) + 1); break;
    case 3: t.resize(at); break;  // truncated
    case 4: t += pick(rng, 2) ? std::string("\0", 1) : std::string(" {}"); break;  // trailing bytes
    case 5: {                                                                     // a slice duplicated
      const std::size_t len = std::min(pick(rng, 40) + 1, t.size() - std::min(at, t.size()));
      t.insert(at, t.substr(std::min(at, t.size()), len));
      break;
    }
    default: {  // a key duplicated in text ("x": 1, "x": 1)
      const std::size_t q = t.find("\": ", at);
      const std::size_t s = q == std::string::npos ? q : t.rfind('"', q - 1);
      const std::size_t e = q == std::string::npos ? q : t.find_first_of(",}", q);
      if (s != std::string::npos && e != std::string::npos) t.insert(e, ", " + t.substr(s, e - s));
    }
  }
}

struct Verdict {
  bool accepted = false;
  bool runnable = false;  // accepted, a Simulation built, within the step limit
  std::string message;
};

// The in-process checks; a failure throws std::logic_error.
Verdict read_in_process(const std::string& text) {
  Verdict v;
  dda::io::SceneFile f;
  try {
    f = dda::io::parse_scene(text, "fuzz.json");
  } catch (const dda::io::SceneFileError& e) {
    v.message = e.what();
    if (v.message.rfind("fuzz.json", 0) != 0) throw std::logic_error("message does not start with the file: " + v.message);
    return v;
  }
  v.accepted = true;
  // Round trip: what the writer writes, the reader reads back to the same text.
  const std::string w = dda::io::write_scene(f);
  dda::io::SceneFile g;
  try {
    g = dda::io::parse_scene(w, "rewritten.json");
  } catch (const dda::io::SceneFileError& e) {
    throw std::logic_error(std::string("write_scene output refused: ") + e.what());
  }
  if (dda::io::write_scene(g) != w) throw std::logic_error("write_scene is not a fixed point");
  try {
    dda::Simulation sim(f.scene);
    dda::io::check_step_count(f, sim.dt(), "fuzz.json");
    v.runnable = true;
    for (int i = 0; i < kInProcessSteps && sim.time() + 0.5 * sim.dt() < f.scene.duration; ++i) sim.step();
  } catch (const dda::SceneError&) {
  } catch (const dda::SimulationError&) {
    v.runnable = true;
  } catch (const dda::io::SceneFileError&) {
  }
  return v;
}

int run_status(const std::string& cmd) {
  const int st = std::system(cmd.c_str());
  if (st == -1 || !WIFEXITED(st)) return -1;
  return WEXITSTATUS(st);
}

// `dda check` and `dda run` on the case; "" or what went wrong.
std::string run_cli(const std::string& text, const Verdict& v, const fs::path& dir, int case_seconds) {
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path scene = dir / "case.json", out = dir / "out", log = dir / "log.txt";
  std::ofstream(scene, std::ios::binary) << text;
  const std::string dda = std::string("timeout -s KILL ") + std::to_string(case_seconds) + " \"" + DDA_CLI_PATH + "\" ";
  const std::string redirect = " >\"" + log.string() + "\" 2>&1";
  const int check = run_status(dda + "check \"" + scene.string() + "\"" + redirect);
  if (check != 0 && check != 2) return "dda check exit " + std::to_string(check) + ": " + slurp(log);
  if ((check == 0) != v.runnable)
    return "dda check exit " + std::to_string(check) + " but in-process runnable = " + std::to_string(v.runnable) +
           ": " + slurp(log);
  const int run = run_status(dda + "run \"" + scene.string() + "\" --quiet --out \"" + out.string() + "\"" + redirect);
  const std::string what = "dda run exit " + std::to_string(run) + ": " + slurp(log);
  if (run == 2) {
    if (v.runnable) return what + " (the scene is runnable in-process)";
    return fs::exists(out) ? what + " (wrote " + out.string() + ")" : "";
  }
  if (run != 0 && run != 3) return what;
  if (run != (v.runnable ? run : -2)) return what + " (dda check said " + std::to_string(check) + ")";
  for (const char* f : {"timeseries.csv", "snapshots.csv", "run.json"})
    if (!fs::exists(out / f)) return what + " (no " + f + ")";
  for (const auto& e : fs::directory_iterator(out))
    if (e.path().extension() == ".tmp") return what + " (left " + e.path().string() + ")";
  const std::string status = slurp(out / "run.json");
  if ((run == 0) != (status.find("\"status\": \"completed\"") != std::string::npos)) return what + " run.json: " + status;
  return "";
}

}  // namespace

int main(int argc, char** argv) {
  long cases = 2000, cli_runs = 20, first = 0;
  int case_seconds = 60;
  std::uint64_t seed = 20261125;
  bool verbose = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::cerr << "io_scene_fuzz: " << a << " needs a value\n";
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--cases") cases = std::stol(next());
    else if (a == "--cli-runs") cli_runs = std::stol(next());
    else if (a == "--first") first = std::stol(next());
    else if (a == "--case-seconds") case_seconds = std::stoi(next());
    else if (a == "--verbose") verbose = true;
    else if (a == "--seed") {
      const std::string s = next();
      seed = s == "random" ? std::random_device{}() * 0x100000001ull + std::random_device{}() : std::stoull(s);
    } else {
      std::cerr << "io_scene_fuzz: unknown argument " << a << "\n";
      return 2;
    }
  }
  std::signal(SIGALRM, on_alarm);
  for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL}) std::signal(sig, on_crash);
  const std::vector<Seed> seeds = load_seeds();
  const fs::path tmp = fs::path(DDA_IO_TEST_TMP) / ("fuzz_" + std::to_string(getpid()));
  const long cli_every = cli_runs > 0 ? std::max(1L, cases / cli_runs) : 0;
  std::printf("io_scene_fuzz: %ld cases from %zu seeds, seed %llu, %ld dda runs, hang limit %d s per case\n"
              "  replay a case K: io_scene_fuzz --seed %llu --first K --cases 1 --verbose\n",
              cases, seeds.size(), static_cast<unsigned long long>(seed), cli_runs, case_seconds,
              static_cast<unsigned long long>(seed));
  std::fflush(stdout);
  long accepted = 0, runnable = 0, cli_done = 0, failures = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (long k = first; k < first + cases; ++k) {
    g_case = static_cast<std::sig_atomic_t>(k);
    Rng rng(seed ^ (0x9E3779B97F4A7C15ull * static_cast<std::uint64_t>(k + 1)));
    const Seed& s = seeds[pick(rng, seeds.size())];
    const bool cli = cli_every > 0 && (k - first) % cli_every == 0 && cli_done < cli_runs;
    std::string text = s.text;
    const int edits = 1 + static_cast<int>(pick(rng, 3));
    if (s.valid_json && pick(rng, 3) != 0) {
      ordered_json doc = s.doc;
      // A run case: at most kCliRunSteps steps of the seed's dt.
      if (cli && doc.is_object() && doc.contains("dt") && doc["dt"].is_number() && doc.contains("duration") &&
          doc["duration"].is_number())
        doc["duration"] = std::min(doc["duration"].get<double>(), kCliRunSteps * doc["dt"].get<double>());
      for (int e = 0; e < edits; ++e) mutate_doc(doc, rng);
      text = doc.dump(pick(rng, 2) ? 2 : -1);
      if (pick(rng, 4) == 0) mutate_text(text, rng);
    } else {
      for (int e = 0; e < edits; ++e) mutate_text(text, rng);
    }
    if (verbose) {
      std::printf("case %ld (seed file %s):\n%s\n", k, s.name.c_str(), text.c_str());
      std::fflush(stdout);
    }
    alarm(static_cast<unsigned>(case_seconds));
    std::string failure;
    Verdict v;
    try {
      v = read_in_process(text);
    } catch (const std::exception& e) {
      failure = std::string("in-process: ") + e.what();
    }
    if (failure.empty() && cli) {
      alarm(static_cast<unsigned>(3 * case_seconds));  // check + run, each under `timeout`
      failure = run_cli(text, v, tmp, case_seconds);
      ++cli_done;
    }
    alarm(0);
    accepted += v.accepted;
    runnable += v.runnable;
    if (verbose) std::printf("case %ld: %s\n", k, v.accepted ? "accepted" : v.message.c_str());
    if (!failure.empty()) {
      ++failures;
      std::printf("io_scene_fuzz: FAILED case %ld (seed file %s): %s\n--- case text ---\n%s\n---\n", k, s.name.c_str(),
                  failure.c_str(), text.c_str());
      if (failures >= 5) break;
    }
  }
  fs::remove_all(tmp);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("io_scene_fuzz: %ld cases (%ld accepted, %ld runnable), %ld dda check+run subprocess cases, %.1f s: %s\n",
              cases, accepted, runnable, cli_done, secs, failures ? "FAILED" : "0 failures");
  return failures ? 1 : 0;
}
