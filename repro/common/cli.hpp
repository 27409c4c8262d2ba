// Command line and progress output shared by the drivers.
#pragma once
#include <chrono>
#include <string>

namespace repro {

// The output root: "--out DIR" or "--out=DIR"; default "out". Throws
// std::invalid_argument if --out has no value. Other arguments are ignored.
std::string out_dir(int argc, char** argv);

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
