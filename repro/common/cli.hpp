// Command line and progress output shared by the drivers.
#pragma once
#include <chrono>
#include <initializer_list>
#include <string>

namespace repro {

// The value text of option `name` ("--name V" or "--name=V"; the last one
// given wins): true with it in `value` ("" when V is missing), false if the
// option is absent. Arguments are read as check_command_line reads them: an
// option's separate value is never taken for an option itself, nor an
// argument starting with "--" for a value.
bool option_text(int argc, char** argv, const std::string& name, std::string& value);

// The output root: "--out DIR" or "--out=DIR"; default "out". Throws
// std::invalid_argument if --out has no value. Other arguments are ignored.
std::string out_dir(int argc, char** argv);

// text as a finite number (a whole one of at most 1e9 in magnitude if
// `whole`): "" with the value in x, or why not ("needs a value",
// "not a finite number: '2s'", "not a whole number: '1.5'").
std::string parse_number(const std::string& text, bool whole, double& x);

// One numeric option a driver accepts besides --out: "--name V" or
// "--name=V". whole: V must be a whole number.
struct OptionHelp {
  const char* name;   // "--duration"
  const char* value;  // placeholder in the usage line: "S"
  const char* help;   // one line: "simulated seconds per case (default 7.5)"
  bool whole = false;
};

// What is wrong with the command line, or "" if nothing: every argument
// must be --out with a directory, one of `options` with a finite number
// (whole where asked), or --help / -h. Names the argument and the reason.
std::string command_line_error(int argc, char** argv, std::initializer_list<OptionHelp> options);

// The usage text: "usage: <program> [--out DIR] [--name V]...", the
// summary, and one line per option.
std::string usage_text(const std::string& program, const std::string& summary,
                       std::initializer_list<OptionHelp> options);

// Run first in each driver's main, before anything is computed or written.
// --help / -h: prints the usage to stdout and exits 0. A bad command line
// (unknown option, stray argument, missing or non-numeric value): prints
// "<program>: <error>" and the usage to stderr and exits 2. Afterwards
// out_dir, option_number and option_int cannot throw.
void check_command_line(int argc, char** argv, const std::string& summary,
                        std::initializer_list<OptionHelp> options = {});

// Progress lines on stderr, "[name +12.3s] message", so stdout stays clean.
class Progress {
 public:
  explicit Progress(std::string name);
  void operator()(const std::string& message) const;
  double elapsed_seconds() const;

 private:
  std::string name_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace repro
