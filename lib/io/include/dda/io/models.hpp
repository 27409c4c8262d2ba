// The model a scene file selects, built behind the stepping interface of
// both contact models (dda::Stepper): Paper A's penalty contact
// (dda::Simulation) or Paper B's two-scale contact (dda::cdem::Model).
#pragma once
#include <memory>

#include "dda/cdem/stepper.hpp"
#include "dda/io/scene_file.hpp"
#include "dda/stepper.hpp"

namespace dda::io {

struct RunModel {
  std::unique_ptr<Stepper> stepper;
  SimulationStepper* penalty = nullptr;  // the same object, when the model is "penalty"
  cdem::ModelStepper* cdem = nullptr;    // the same object, when the model is "cdem"
};

// Builds the file's model; `threads` (>= 1) for the penalty model's solver
// (the CDEM model steps on one thread). Throws dda::SceneError.
RunModel build_model(const SceneFile& file, int threads = 1);

}  // namespace dda::io
