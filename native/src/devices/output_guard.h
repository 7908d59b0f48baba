// SPDX-License-Identifier: MIT
// The last step before a glove: what the world asks for, cut to what this glove may
// render and how fast its output may rise. A glove that keeps pushing hurts a hand, so
// every output is scaled down to the glove's limits (never turned), rises no faster
// than its rate limit, and drops to zero at once when told to.
#pragma once

#include <glm/gtc/quaternion.hpp>

#include "devices/device_types.h"
#include "forces/device_outputs.h"

namespace frusta {

struct OutputRates {
  double max_force_rate = 500.0;   // newtons per second a resistance or tip force may rise
  double max_torque_rate = 25.0;   // newton-metres per second a joint torque may rise
};

class OutputGuard {
 public:
  OutputGuard(const DeviceCapabilities& capabilities, const OutputRates& rates)
      : capabilities_(capabilities), rates_(rates) {}

  void set_capabilities(const DeviceCapabilities& capabilities) { capabilities_ = capabilities; }

  // The command for this tick from the world's outputs (world frame) and the haptic
  // palm's rotation (fingertip forces go out in the palm's frame); dt is the time since
  // the previous command, seconds. Outputs the glove lacks stay zero.
  const DeviceCommand& shape(const DeviceOutputs& outputs, const glm::dquat& palm_rotation,
                             double dt);
  // Everything to zero now; the next shape() rises from zero.
  const DeviceCommand& zero();
  const DeviceCommand& last() const { return command_; }

 private:
  DeviceCapabilities capabilities_;
  OutputRates rates_;
  DeviceCommand command_;
};

}  // namespace frusta
