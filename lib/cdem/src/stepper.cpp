#include "dda/cdem/stepper.hpp"

namespace dda::cdem {

Energy ModelStepper::energy() const {
  const CdemEnergyAccount a = model_.energy_account();
  const CdemEnergy e = model_.energy();
  Energy out;
  out.kinetic = e.kinetic;
  out.gravity = e.gravity;
  out.strain = e.strain;
  out.contact = e.contact;
  out.dissipated = a.touch_loss + a.refine_loss + a.deletion_loss;
  out.initial = a.initial;
  return out;
}

std::size_t ModelStepper::contact_count() const {
  return model_.scene().options.contact == ContactMode::kNodeToEdgePenalty ? model_.penalty_contacts().size()
                                                                            : model_.clones().size();
}

BlockMotion ModelStepper::block_motion(int block) const {
  BlockMotion m;
  m.position = model_.block_mean_position(block);
  m.velocity = model_.block_velocity(block);
  return m;
}

}  // namespace dda::cdem
