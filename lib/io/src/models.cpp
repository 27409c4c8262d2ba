#include "dda/io/models.hpp"

namespace dda::io {

RunModel build_model(const SceneFile& file, int threads) {
  RunModel m;
  if (file.model == ContactModel::kCdem) {
    auto s = std::make_unique<cdem::ModelStepper>(cdem::Model(cdem_scene(file)));
    m.cdem = s.get();
    m.stepper = std::move(s);
  } else {
    Simulation sim(file.scene);
    sim.set_threads(threads);
    auto s = std::make_unique<SimulationStepper>(std::move(sim));
    m.penalty = s.get();
    m.stepper = std::move(s);
  }
  return m;
}

}  // namespace dda::io
