// Optional numeric command-line options of the drivers ("--name V" or
// "--name=V"), next to repro::out_dir. Header only; found by
// repro::option_text and read by repro::parse_number, as check_command_line
// reads and checks them.
#pragma once
#include <stdexcept>
#include <string>

#include "repro/common/cli.hpp"

namespace repro {

namespace detail {

// The value of option `name` (a whole number if `whole`), or `fallback` if
// absent. Throws std::invalid_argument naming the option and the reason.
inline double option_value(int argc, char** argv, const std::string& name, double fallback, bool whole) {
  std::string v;
  if (!option_text(argc, argv, name, v)) return fallback;
  double x = 0.0;
  const std::string why = parse_number(v, whole, x);
  if (!why.empty()) throw std::invalid_argument(name + " " + why);
  return x;
}

}  // namespace detail

// The value of option `name` (e.g. "--duration"), or `fallback` if absent.
// Throws std::invalid_argument if the value is missing or not a finite number.
inline double option_number(int argc, char** argv, const std::string& name, double fallback) {
  return detail::option_value(argc, argv, name, fallback, false);
}

// Like option_number, for a whole number.
inline int option_int(int argc, char** argv, const std::string& name, int fallback) {
  return static_cast<int>(detail::option_value(argc, argv, name, static_cast<double>(fallback), true));
}

}  // namespace repro
