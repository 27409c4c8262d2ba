// Simulation's public calls, each forwarded once to its engine (the state
// and the step's phases, internal.hpp): a step's work runs in the engine's
// members, so a call here costs one indirection per advance, not per block.
#include "simulation/internal.hpp"

namespace dda {

Simulation::Simulation(const Scene& scene) : engine_(std::make_unique<Engine>(scene)) {}
Simulation::Simulation(Simulation&&) noexcept = default;
Simulation& Simulation::operator=(Simulation&&) noexcept = default;
Simulation::~Simulation() = default;

void Simulation::step() { engine_->run_steps(1); }
void Simulation::advance(std::int64_t count) { engine_->run_steps(count); }
void Simulation::advance_to(double t) { engine_->advance_to(t); }

double Simulation::time() const { return engine_->time_; }
std::int64_t Simulation::step_count() const { return engine_->steps_; }
double Simulation::dt() const { return engine_->dt_; }
void Simulation::set_threads(int n) { engine_->threads_ = n < 1 ? 1 : n; }
int Simulation::threads() const { return engine_->threads_; }
const Scene& Simulation::scene() const { return engine_->scene_; }

int Simulation::block_count() const { return engine_->block_count(); }
int Simulation::scene_block_count() const { return engine_->scene_blocks_; }
PolygonView Simulation::polygon_view(int i) const { return engine_->polygon_view(i); }
std::size_t Simulation::geometry_bytes_per_block() const { return engine_->geometry_bytes_per_block(); }
Vec2 Simulation::centroid(int i) const { return engine_->moments_[i].centroid; }
double Simulation::area(int i) const { return engine_->moments_[i].area; }
double Simulation::mass(int i) const { return engine_->mass_[i]; }
bool Simulation::fixed(int i) const { return engine_->fixed_[i]; }
int Simulation::material(int i) const { return i < engine_->scene_blocks_ ? engine_->elastic_index_[i] : -1; }
const Vec6& Simulation::velocity(int i) const { return engine_->vel_[i]; }
const Vec6& Simulation::displacement(int i) const { return engine_->disp_[i]; }
const Vec3& Simulation::stress(int i) const { return engine_->stress_[i]; }
double Simulation::potential_length(int i) const { return engine_->h_[i]; }

double Simulation::critical_time_step() const { return engine_->critical_time_step(); }
double Simulation::predicted_critical_step() const { return engine_->dt_crit_prior_; }
double Simulation::strain_critical_step(int i) const {
  const double w2 = engine_->block_strain_omega2(i);
  return w2 > 0.0 ? 2.0 / std::sqrt(w2) : DBL_MAX;
}

Vec2 Simulation::momentum() const { return engine_->momentum(); }
Energy Simulation::energy() const { return engine_->energy(); }
std::vector<ContactInfo> Simulation::contacts() const { return engine_->contacts(); }
std::size_t Simulation::contact_count() const { return engine_->contact_count(); }
std::size_t Simulation::candidate_count() const { return engine_->candidate_count_; }
std::size_t Simulation::bytes_per_near_pair() const { return engine_->bytes_per_near_pair(); }
std::size_t Simulation::near_pair_count() const { return engine_->near_pairs_.size(); }
std::int64_t Simulation::broad_phase_rebuilds() const { return engine_->broad_phase_rebuilds_; }
const std::vector<Simulation::PhaseTimes>& Simulation::phase_times() const { return engine_->phase_times_; }
void Simulation::reset_phase_times() { engine_->phase_times_.clear(); }

void Simulation::save_state(ByteWriter& out) const { engine_->save_state(out); }
void Simulation::restore_state(ByteReader& in) { engine_->restore_state(in); }

}  // namespace dda
