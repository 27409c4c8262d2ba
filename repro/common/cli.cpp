#include "repro/common/cli.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace repro {

std::string out_dir(int argc, char** argv) {
  std::string out = "out";
  for (int i = 1; i < argc; ++i) {
    const char* a = argv[i];
    if (std::strcmp(a, "--out") == 0) {
      if (i + 1 >= argc || argv[i + 1][0] == '\0') throw std::invalid_argument("--out needs a directory");
      out = argv[++i];
    } else if (std::strncmp(a, "--out=", 6) == 0) {
      if (a[6] == '\0') throw std::invalid_argument("--out= needs a directory");
      out = a + 6;
    }
  }
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

bool is_help(const std::string& a) { return a == "--help" || a == "-h"; }

// command_line_error, also saying whether --help / -h was given as an
// argument (not as an option's value).
std::string walk(int argc, char** argv, std::initializer_list<OptionHelp> options, bool& help) {
  help = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (is_help(a)) {
      help = true;
      continue;
    }
    const std::size_t eq = a.find('=');
    const std::string name = a.rfind("--", 0) == 0 ? a.substr(0, eq) : a;
    const bool inline_value = a.rfind("--", 0) == 0 && eq != std::string::npos;
    const bool has_next = i + 1 < argc;
    if (name == "--out") {
      const std::string v = inline_value ? a.substr(eq + 1) : (has_next ? argv[i + 1] : "");
      if (v.empty()) return "--out needs a directory";
      if (!inline_value) ++i;
      continue;
    }
    const OptionHelp* known = nullptr;
    for (const OptionHelp& o : options)
      if (name == o.name) known = &o;
    if (!known) {
      std::string valid = "--out";
      for (const OptionHelp& o : options) valid += std::string(", ") + o.name;
      return (a.rfind("-", 0) == 0 ? "unknown option '" + name + "'" : "unexpected argument '" + a + "'") +
             " (this driver takes " + valid + ", --help)";
    }
    const std::string v = inline_value ? a.substr(eq + 1) : (has_next ? argv[i + 1] : "");
    double x = 0.0;
    const std::string why = parse_number(v, known->whole, x);
    if (!why.empty()) return name + " " + why;
    if (!inline_value) ++i;
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
