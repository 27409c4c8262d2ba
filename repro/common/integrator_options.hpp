// Command-line options that choose an integrator option of the solver,
// shared by the drivers that offer them (next to repro/common/options.hpp,
// which stays free of the solver: this header needs dda/scene.hpp).
#pragma once
#include "dda/scene.hpp"
#include "repro/common/options.hpp"

namespace repro {

// --exact-rotation 0|1, shared by the drivers that offer it: 1 turns the
// blocks' rigid part exactly (dda::RotationUpdate::kExact, not the paper's
// linearised Eq. 1); the driver's claims must say so (kExactRotationNote).
inline constexpr OptionHelp kExactRotationOption{
    "--exact-rotation", "0|1", "1: exact rotation of the blocks' rigid part instead of the paper's linearised Eq. 1 (default 0)",
    true};
inline constexpr const char* kExactRotationNote = " [EXACT ROTATION: rotation update not the paper's Eq. 1]";
// --threads N, shared by the drivers that offer it: OpenMP threads of the
// solver (Simulation::set_threads); the results do not depend on the count.
inline constexpr OptionHelp kThreadsOption{"--threads", "N",
                                           "OpenMP threads (default 1; results are bit-identical for any count)", true};
inline dda::RotationUpdate rotation_option(int argc, char** argv) {
  return option_int(argc, argv, kExactRotationOption.name, 0) != 0 ? dda::RotationUpdate::kExact
                                                                    : dda::RotationUpdate::kPaperLinear;
}

}  // namespace repro
