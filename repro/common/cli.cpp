#include "repro/common/cli.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <utility>
#include <vector>

namespace repro {

namespace {

// One argument of a driver's command line: --help / -h, a word that is no
// option, or an option with its value ("--name V" or "--name=V"; V empty
// when missing: "--name" last, or followed by another "--" argument; "-3"
// is a value). The one reading of argv behind option_text,
// out_dir and check_command_line.
struct Arg {
  enum class Kind { kHelp, kStray, kOption } kind = Kind::kOption;
  std::string text;   // the argument as given
  std::string name;   // kOption: "--name"
  std::string value;  // kOption: V
};

std::vector<Arg> read_args(int argc, char** argv) {
  std::vector<Arg> args;
  for (int i = 1; i < argc; ++i) {
    Arg a;
    a.text = argv[i];
    const std::size_t eq = a.text.find('=');
    if (a.text == "--help" || a.text == "-h") {
      a.kind = Arg::Kind::kHelp;
    } else if (a.text.rfind('-', 0) != 0) {
      a.kind = Arg::Kind::kStray;
    } else if (a.text.rfind("--", 0) == 0 && eq != std::string::npos) {
      a.name = a.text.substr(0, eq);
      a.value = a.text.substr(eq + 1);
    } else {
      a.name = a.text;
      if (i + 1 < argc && std::string(argv[i + 1]).rfind("--", 0) != 0) a.value = argv[++i];
    }
    args.push_back(std::move(a));
  }
  return args;
}

}  // namespace

bool option_text(int argc, char** argv, const std::string& name, std::string& value) {
  bool found = false;
  for (const Arg& a : read_args(argc, argv))
    if (a.kind == Arg::Kind::kOption && a.name == name) {
      value = a.value;
      found = true;
    }
  return found;
}

std::string out_dir(int argc, char** argv) {
  std::string out = "out";
  if (option_text(argc, argv, "--out", out) && out.empty()) throw std::invalid_argument("--out needs a directory");
  return out;
}

std::string parse_number(const std::string& text, bool whole, double& x) {
  if (text.empty()) return "needs a value";
  char* end = nullptr;
  x = std::strtod(text.c_str(), &end);
  if (*end != '\0' || !std::isfinite(x)) return "not a finite number: '" + text + "'";
  if (whole && (x != std::floor(x) || std::fabs(x) > 1e9)) return "not a whole number: '" + text + "'";
  return "";
}

namespace {

// command_line_error, also saying whether --help / -h was given (as an
// argument, not as an option's value) before the first error.
std::string walk(int argc, char** argv, std::initializer_list<OptionHelp> options, bool& help) {
  help = false;
  std::string valid = "--out";
  for (const OptionHelp& o : options) valid += std::string(", ") + o.name;
  const std::string takes = " (this driver takes " + valid + ", --help)";
  for (const Arg& a : read_args(argc, argv)) {
    if (a.kind == Arg::Kind::kHelp) {
      help = true;
      continue;
    }
    if (a.kind == Arg::Kind::kStray) return "unexpected argument '" + a.text + "'" + takes;
    if (a.name == "--out") {
      if (a.value.empty()) return "--out needs a directory";
      continue;
    }
    const OptionHelp* known = nullptr;
    for (const OptionHelp& o : options)
      if (a.name == o.name) known = &o;
    if (!known) return "unknown option '" + a.name + "'" + takes;
    double x = 0.0;
    const std::string why = parse_number(a.value, known->whole, x);
    if (!why.empty()) return a.name + " " + why;
  }
  return "";
}

}  // namespace

std::string command_line_error(int argc, char** argv, std::initializer_list<OptionHelp> options) {
  bool help = false;
  return walk(argc, argv, options, help);
}

std::string usage_text(const std::string& program, const std::string& summary,
                       std::initializer_list<OptionHelp> options) {
  std::string u = "usage: " + program + " [--out DIR]";
  for (const OptionHelp& o : options) u += std::string(" [") + o.name + " " + o.value + "]";
  u += "\n" + summary + "\n";
  std::size_t width = 9;  // "--out DIR"
  for (const OptionHelp& o : options) width = std::max(width, std::strlen(o.name) + 1 + std::strlen(o.value));
  auto line = [&](const std::string& option, const std::string& help) {
    u += "  " + option + std::string(width + 2 - option.size(), ' ') + help + "\n";
  };
  line("--out DIR", "output root: data/ and figures/ go below it (default out)");
  for (const OptionHelp& o : options) line(std::string(o.name) + " " + o.value, o.help);
  return u;
}

void check_command_line(int argc, char** argv, const std::string& summary, std::initializer_list<OptionHelp> options) {
  std::string program = argc > 0 ? argv[0] : "driver";
  const std::size_t slash = program.find_last_of('/');
  if (slash != std::string::npos) program = program.substr(slash + 1);
  bool help = false;
  const std::string error = walk(argc, argv, options, help);
  if (help) {
    std::fputs(usage_text(program, summary, options).c_str(), stdout);
    std::exit(0);
  }
  if (!error.empty()) {
    std::fprintf(stderr, "%s: %s\n%s", program.c_str(), error.c_str(), usage_text(program, summary, options).c_str());
    std::exit(2);
  }
}

Progress::Progress(std::string name) : name_(std::move(name)), start_(std::chrono::steady_clock::now()) {}

double Progress::elapsed_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::operator()(const std::string& message) const {
  std::fprintf(stderr, "[%s +%.2fs] %s\n", name_.c_str(), elapsed_seconds(), message.c_str());
  std::fflush(stderr);
}

}  // namespace repro
