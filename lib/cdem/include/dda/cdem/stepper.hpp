// Paper B's model behind the stepping interface of both contact models
// (dda::Stepper, lib/include/dda/stepper.hpp).
#pragma once
#include <utility>

#include "dda/cdem/model.hpp"
#include "dda/stepper.hpp"

namespace dda::cdem {

// Owns the model. The energy budget in the terms of dda::Energy: kinetic,
// gravity, strain and contact (the node-to-edge baseline's springs) as the
// model's energy(); no friction springs; dissipated = what the energy
// account books as lost (the touches' measured loss, Eq. 4-5, and the
// refinement and deletion losses of Sect. 5), so that balance_error() is
// minus the account's `other` (time integration, sliding friction, mass
// damping, the clones' drift).
class ModelStepper final : public OwningStepper<Model> {
 public:
  using OwningStepper::OwningStepper;

  Model& model() { return model_; }
  const Model& model() const { return model_; }

  Energy energy() const override;
  std::size_t contact_count() const override;
  int block_count() const override { return model_.block_count(); }
  BlockMotion block_motion(int block) const override;
  bool has_rotation() const override { return false; }
  int outline_count() const override { return model_.block_count(); }
  std::vector<Vec2> outline(int i) const override { return model_.block_outline(i); }
};

}  // namespace dda::cdem
