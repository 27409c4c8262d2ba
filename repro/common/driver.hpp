// The opening and closing every driver shares: its command line checked
// (usage on --help, exit 2 on a bad one), the output root, progress lines on
// stderr, and a failed run reported as "<program>: error: <what>" with exit
// status 1. A driver's main is then one call:
//
//   int main(int argc, char** argv) {
//     return repro::driver_main(argc, argv, {"bouncing_block", "5.1 bouncing block", "Paper A Sect. 5.1 ..."}, {},
//                               [](const repro::Driver& d) { ...; return 0; });
//   }
//
// The body reads its options through the Driver (d.number, d.whole), writes
// under d.out and reports through d.progress.
#pragma once
#include <functional>
#include <initializer_list>
#include <string>

#include "repro/common/cli.hpp"

namespace repro {

// Who the driver is: `program` prefixes its error lines, `progress` its
// progress lines, `summary` is the usage text's first line.
struct DriverInfo {
  std::string program;   // "bouncing_block"
  std::string progress;  // "5.1 bouncing block"
  std::string summary;   // "Paper A Sect. 5.1 (Figs. 13-14): ..."
};

// What a driver's body is given: its command line (already checked), the
// output root (--out, default "out") and its progress line writer.
struct Driver {
  int argc;
  char** argv;
  std::string out;
  Progress progress;

  // Option `name` ("--duration") as a number, or `fallback` if absent.
  double number(const std::string& name, double fallback) const;
  // Option `name` as a whole number, or `fallback` if absent.
  int whole(const std::string& name, int fallback) const;
};

// Checks the command line against `options` (check_command_line: exits 0 on
// --help, 2 on a bad command line), then runs `body`. An exception out of
// the body prints "<program>: error: <what>" on stderr and gives exit
// status 1; otherwise the body's return value is the exit status.
int driver_main(int argc, char** argv, const DriverInfo& info, std::initializer_list<OptionHelp> options,
                const std::function<int(const Driver&)>& body);

}  // namespace repro
