#include "repro/common/driver.hpp"

#include <cstdio>
#include <exception>

#include "repro/common/options.hpp"

namespace repro {

double Driver::number(const std::string& name, double fallback) const {
  return option_number(argc, argv, name, fallback);
}

int Driver::whole(const std::string& name, int fallback) const { return option_int(argc, argv, name, fallback); }

int driver_main(int argc, char** argv, const DriverInfo& info, std::initializer_list<OptionHelp> options,
                const std::function<int(const Driver&)>& body) {
  check_command_line(argc, argv, info.summary, options);
  try {
    const Driver driver{argc, argv, out_dir(argc, argv), Progress(info.progress)};
    return body(driver);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: error: %s\n", info.program.c_str(), e.what());
    return 1;
  }
}

}  // namespace repro
