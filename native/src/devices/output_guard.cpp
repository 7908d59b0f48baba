// SPDX-License-Identifier: MIT
#include "devices/output_guard.h"

#include <algorithm>
#include <cmath>

namespace frusta {

namespace {

// `target` cut to `limit` and to `previous + rise` (a fall is never slowed: it is the
// safe direction). NaN becomes zero.
double limit_scalar(double target, double previous, double limit, double rise) {
  if (!std::isfinite(target)) return 0.0;
  const double cap = std::min(limit, std::fabs(previous) + rise);
  return std::clamp(target, -cap, cap);
}

vec3 limit_vector(const vec3& target, const vec3& previous, double limit, double rise) {
  const double length = glm::length(target);
  if (!std::isfinite(length)) return vec3(0.0);
  const double cap = std::min(limit, glm::length(previous) + rise);
  return length > cap ? target * (cap / length) : target;
}

}  // namespace

const DeviceCommand& OutputGuard::shape(const DeviceOutputs& outputs,
                                        const glm::dquat& palm_rotation, double dt) {
  const double force_rise = rates_.max_force_rate * std::max(dt, 0.0);
  const double torque_rise = rates_.max_torque_rate * std::max(dt, 0.0);
  const uint32_t renders = capabilities_.outputs;
  const glm::dquat to_palm = glm::conjugate(palm_rotation);
  for (int32_t f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    const bool present = f < capabilities_.fingers;
    command_.finger_resistance[f] =
        present && (renders & kOutputFingerResistance)
            ? std::max(0.0, limit_scalar(outputs.finger_resistance[f], command_.finger_resistance[f],
                                         capabilities_.max_finger_resistance, force_rise))
            : 0.0;
    command_.fingertip_force[f] =
        present && (renders & kOutputFingertipForce)
            ? limit_vector(to_palm * outputs.fingertip_force[f], command_.fingertip_force[f],
                           capabilities_.max_fingertip_force, force_rise)
            : vec3(0.0);
    for (int32_t j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j) {
      const int32_t i = f * FRUSTA_JOINTS_PER_FINGER + j;
      command_.joint_torque[i] =
          present && (renders & kOutputJointTorque)
              ? limit_scalar(outputs.joint_torque[i], command_.joint_torque[i],
                             capabilities_.max_joint_torque, torque_rise)
              : 0.0;
    }
  }
  return command_;
}

const DeviceCommand& OutputGuard::zero() {
  command_ = DeviceCommand{};
  return command_;
}

}  // namespace frusta
