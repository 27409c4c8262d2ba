#include "repro/common/cli.hpp"

#include <cstdio>
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

Progress::Progress(std::string name) : name_(std::move(name)), start_(std::chrono::steady_clock::now()) {}

double Progress::elapsed_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::operator()(const std::string& message) const {
  std::fprintf(stderr, "[%s +%.2fs] %s\n", name_.c_str(), elapsed_seconds(), message.c_str());
  std::fflush(stderr);
}

}  // namespace repro
