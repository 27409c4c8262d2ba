// Optional numeric command-line options of the drivers ("--name V" or
// "--name=V"), next to repro::out_dir. Header only.
#pragma once
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

namespace repro {

// The value of option `name` (e.g. "--duration"), or `fallback` if absent.
// Throws std::invalid_argument if the value is missing or not a finite number.
inline double option_number(int argc, char** argv, const std::string& name, double fallback) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    std::string v;
    if (a == name) {
      if (i + 1 >= argc) throw std::invalid_argument(name + " needs a value");
      v = argv[i + 1];
    } else if (a.rfind(name + "=", 0) == 0) {
      v = a.substr(name.size() + 1);
    } else {
      continue;
    }
    char* end = nullptr;
    const double x = std::strtod(v.c_str(), &end);
    if (v.empty() || *end != '\0' || !std::isfinite(x)) throw std::invalid_argument(name + ": not a number: '" + v + "'");
    return x;
  }
  return fallback;
}

// Like option_number, for a whole number.
inline int option_int(int argc, char** argv, const std::string& name, int fallback) {
  const double x = option_number(argc, argv, name, static_cast<double>(fallback));
  if (x != std::floor(x) || std::fabs(x) > 1e9) throw std::invalid_argument(name + ": not a whole number");
  return static_cast<int>(x);
}

}  // namespace repro
