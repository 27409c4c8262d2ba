// Paper A Sect. 6.2 (toppling_slumping.cpp says what it reproduces): the
// control runs beside the model and the table of claim rows.
#pragma once
#include <vector>

#include "dda/rock_scenes.hpp"
#include "repro/6_2_toppling_slumping/toppling_slumping.hpp"
#include "repro/common/claims.hpp"

namespace topple {

// The runs beside the model (no output but the claims): joints locked (80
// deg instead of 22); each slope as ONE block (the paper's premise); the
// friction start-up option (Scene::damping) on one block per slope, and with
// the return mapping on the model and the locked model; and, unless the
// model itself ran with it, the return mapping on the model and on one block
// per slope (the ratchet diagnosis).
struct Controls {
  Control locked, whole, whole_su, su, locked_su, rm, whole_rm;
};
Controls run_controls(const dda::paper::TopplingSlumping& ts, int threads, bool return_mapping);

// What the model's run measured.
struct ModelRun {
  const dda::paper::TopplingSlumping* ts = nullptr;
  int blocks = 0;
  double duration = 0.0, full_duration = 0.0, dt_ratio0 = 0.0, wall = 0.0, sps = 0.0, time = 0.0;
  double h = 0.0, dt = 0.0;  // H of Eq. 12 and the time step, m and s
  long long steps = 0;
  Health health;
  SideState left, right, left_half, right_half;  // at the end and at half the duration
  bool return_mapping = false, exact_rotation = false;
};

// The claim rows of the model and its controls.
std::vector<repro::Claim> rows(const ModelRun& m, const Controls& c);

}  // namespace topple
