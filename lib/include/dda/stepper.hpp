// One stepping interface for both contact models: Paper A's potential-based
// penalty contact on 6-DOF blocks (dda::Simulation, adapted here by
// SimulationStepper) and Paper B's two-scale contact on CST-meshed blocks
// (dda::cdem::Model, adapted by dda::cdem::ModelStepper in lib/cdem). A run
// loop, a comparison of the two models or a parameter study written against
// Stepper runs either: step, time, the energy budget, momentum, what each
// block does, and the guard stop (both models throw dda::SimulationError
// whose `reason` says which guard stopped the run).
//
// The core library does not depend on lib/cdem: the CDEM adapter lives there.
#pragma once
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "dda/simulation.hpp"
#include "dda/vec2.hpp"

namespace dda {

// What a time series records of one block.
struct BlockMotion {
  Vec2 position{};        // m: the centroid (penalty model), the mass-weighted mean node position (CDEM)
  Vec2 velocity{};        // m/s: of the centroid (penalty), momentum / mass (CDEM)
  double rotation = 0.0;  // rad, accumulated since t = 0 (only where has_rotation())
  double spin = 0.0;      // rad/s (only where has_rotation())
};

class Stepper {
 public:
  virtual ~Stepper() = default;

  // One step. Throws dda::SimulationError (its `reason` the guard that
  // fired) when the run leaves the method's domain; the state is then that
  // of the failed step, for the message, not for going on.
  virtual void step() = 0;
  // `count` steps, with the same result as `count` calls of step() (a
  // model may run them faster together).
  virtual void advance(std::int64_t count) {
    for (std::int64_t k = 0; k < count; ++k) step();
  }

  virtual double time() const = 0;            // s
  virtual double dt() const = 0;              // s, the step in use
  virtual std::int64_t step_count() const = 0;
  virtual double duration() const = 0;        // s, the scene's

  // The energy budget, J/m: what the state holds (kinetic, gravity, strain,
  // contact, friction springs), what left it (dissipated) and the initial
  // total; balance_error() = total() + dissipated - initial.
  virtual Energy energy() const = 0;
  virtual Vec2 momentum() const = 0;  // kg m/s per m, of the moving blocks
  // Contacts of the last force evaluation (penalty: pairs in contact; CDEM:
  // clone nodes, or penalty springs in its node-to-edge baseline).
  virtual std::size_t contact_count() const = 0;

  // The scene's blocks (boundary polygons of the penalty model are not
  // among them: see outline_count).
  virtual int block_count() const = 0;
  virtual BlockMotion block_motion(int block) const = 0;
  // Whether BlockMotion::rotation and spin mean anything (rigid-body
  // rotation of a 6-DOF block; a CST mesh has none of its own).
  virtual bool has_rotation() const = 0;
  // Outlines for snapshots: the scene's blocks first, then (penalty model)
  // the boundary polygons; each counter-clockwise, current positions.
  virtual int outline_count() const = 0;
  virtual std::vector<Vec2> outline(int i) const = 0;
};

// An adapter that owns its model (Simulation, cdem::Model) and passes on
// what both models name alike: the step, the clock, the scene's duration,
// the momentum.
template <class Model>
class OwningStepper : public Stepper {
 public:
  explicit OwningStepper(Model model) : model_(std::move(model)) {}

  void step() override { model_.step(); }
  double time() const override { return model_.time(); }
  double dt() const override { return model_.dt(); }
  std::int64_t step_count() const override { return model_.step_count(); }
  double duration() const override { return model_.scene().duration; }
  Vec2 momentum() const override { return model_.momentum(); }

 protected:
  Model model_;
};

// Paper A's model behind the interface; owns the simulation.
class SimulationStepper final : public OwningStepper<Simulation> {
 public:
  using OwningStepper::OwningStepper;

  Simulation& simulation() { return model_; }
  const Simulation& simulation() const { return model_; }

  void advance(std::int64_t count) override { model_.advance(count); }
  Energy energy() const override { return model_.energy(); }
  std::size_t contact_count() const override { return model_.contacts().size(); }
  int block_count() const override { return model_.scene_block_count(); }
  BlockMotion block_motion(int block) const override;
  bool has_rotation() const override { return true; }
  int outline_count() const override { return model_.block_count(); }
  std::vector<Vec2> outline(int i) const override;
};

}  // namespace dda
