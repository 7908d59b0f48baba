// SPDX-License-Identifier: MIT
#include "devices/glove_calibration.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/validate.h"

namespace frusta {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180.0;

}  // namespace

GloveCalibration default_glove_calibration() {
  GloveCalibration c;
  for (int32_t f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    const bool thumb = f == FRUSTA_FINGER_THUMB;
    const std::array<double, kFlexionJoints> fist =
        thumb ? std::array<double, kFlexionJoints>{45 * kDegree, 40 * kDegree, 60 * kDegree}
              : std::array<double, kFlexionJoints>{80 * kDegree, 90 * kDegree, 70 * kDegree};
    for (int32_t j = 0; j < kFlexionJoints; ++j) {
      c.curl_open[f][j] = 0.0;
      c.curl_closed[f][j] = c.analog_max;
      c.flexion_open[f][j] = 0.0;
      c.flexion_closed[f][j] = fist[j];
    }
    c.splay_center[f] = 2048.0;
    c.splay_span[f] = 2047.0;
    c.abduction_range[f] = 15 * kDegree;
  }
  return c;
}

frusta_result check_glove_calibration(const GloveCalibration& c) {
  const auto bad = [](const char* field, int32_t f, double value) {
    return fail(std::isfinite(value) ? FRUSTA_ERROR_OUT_OF_RANGE : FRUSTA_ERROR_NOT_FINITE,
                "calibration.%s[%d] is %g", field, f, value);
  };
  if (!(c.analog_max >= 1.0 && c.analog_max <= 1e9))
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "calibration.analog_max is %g, not in [1, 1e9]",
                c.analog_max);
  if (!(c.brake_full_scale > 0.0 && c.brake_full_scale <= 1e6))
    return fail(FRUSTA_ERROR_OUT_OF_RANGE,
                "calibration.brake_full_scale is %g newtons, not in (0, 1e6]", c.brake_full_scale);
  if (!(c.brake_units >= 1.0 && c.brake_units <= 65535.0))
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "calibration.brake_units is %g, not in [1, 65535]",
                c.brake_units);
  for (int32_t f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    for (int32_t j = 0; j < kFlexionJoints; ++j) {
      const int32_t i = f * kFlexionJoints + j;
      const double open = c.curl_open[f][j], closed = c.curl_closed[f][j];
      if (!(open >= 0.0 && open <= c.analog_max)) return bad("curl_open (flattened)", i, open);
      if (!(closed >= 0.0 && closed <= c.analog_max))
        return bad("curl_closed (flattened)", i, closed);
      if (std::fabs(closed - open) < 1.0)
        return fail(FRUSTA_ERROR_OUT_OF_RANGE,
                    "calibration.curl_open and curl_closed [finger %d][joint %d] are both %g: "
                    "calibrate with the hand open, then in a fist",
                    f, j, open);
      if (!(std::fabs(c.flexion_open[f][j]) <= kPi)) return bad("flexion_open (flattened)", i, c.flexion_open[f][j]);
      if (!(std::fabs(c.flexion_closed[f][j]) <= kPi))
        return bad("flexion_closed (flattened)", i, c.flexion_closed[f][j]);
    }
    if (!(c.splay_center[f] >= 0.0 && c.splay_center[f] <= c.analog_max))
      return bad("splay_center", f, c.splay_center[f]);
    if (!(c.splay_span[f] >= 1.0 && c.splay_span[f] <= c.analog_max))
      return bad("splay_span", f, c.splay_span[f]);
    if (!(c.abduction_range[f] >= 0.0 && c.abduction_range[f] <= kPi / 2))
      return bad("abduction_range", f, c.abduction_range[f]);
  }
  return FRUSTA_OK;
}

void raw_to_joint_angles(const GloveCalibration& c, const RawGloveReading& raw,
                         const std::array<double, FRUSTA_HAND_JOINT_COUNT>& previous,
                         std::array<double, FRUSTA_HAND_JOINT_COUNT>* angles) {
  *angles = previous;
  for (int32_t f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    double* finger = angles->data() + f * FRUSTA_JOINTS_PER_FINGER;
    if (raw.has_splay[f]) {
      const double s = std::clamp((raw.splay[f] - c.splay_center[f]) / c.splay_span[f], -1.0, 1.0);
      finger[0] = s * c.abduction_range[f];
    }
    if (!raw.has_curl[f]) continue;
    for (int32_t j = 0; j < kFlexionJoints; ++j) {
      const double t = std::clamp(
          (raw.curl[f][j] - c.curl_open[f][j]) / (c.curl_closed[f][j] - c.curl_open[f][j]), 0.0, 1.0);
      finger[1 + j] = c.flexion_open[f][j] + t * (c.flexion_closed[f][j] - c.flexion_open[f][j]);
    }
  }
}

int32_t resistance_to_brake_units(const GloveCalibration& c, double newtons) {
  if (!(newtons > 0.0)) return 0;  // NaN too: a brake released is the safe side
  const double units = std::min(newtons / c.brake_full_scale, 1.0) * c.brake_units;
  return static_cast<int32_t>(std::lround(units));
}

}  // namespace frusta
