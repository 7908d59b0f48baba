// SPDX-License-Identifier: MIT
// How a glove's own units become the engine's: raw curl and splay readings (OpenGloves'
// 0..4095) to joint angles, and a finger's resistance in newtons to brake units
// (OpenGloves' 0..1000). A calibrated step per glove, not a constant in the code: the
// readings of a straight finger and a fist differ from glove to glove and drift with
// how it is worn. Calibrate by reading the raw curl with the hand open and in a fist.
#pragma once

#include <array>
#include <cstdint>

#include "core/base.h"

namespace frusta {

constexpr int32_t kFlexionJoints = FRUSTA_JOINTS_PER_FINGER - 1;  // after abduction

struct GloveCalibration {
  // raw curl of each flexion joint (thumb first) with the finger straight and in a fist;
  // a glove with one sensor per finger repeats it for the finger's three joints
  std::array<std::array<double, kFlexionJoints>, FRUSTA_FINGER_COUNT> curl_open{};
  std::array<std::array<double, kFlexionJoints>, FRUSTA_FINGER_COUNT> curl_closed{};
  // the flexion angles the two readings mean, radians
  std::array<std::array<double, kFlexionJoints>, FRUSTA_FINGER_COUNT> flexion_open{};
  std::array<std::array<double, kFlexionJoints>, FRUSTA_FINGER_COUNT> flexion_closed{};
  // raw splay of a finger held straight ahead, and the raw span to either side that
  // means abduction_range radians
  std::array<double, FRUSTA_FINGER_COUNT> splay_center{};
  std::array<double, FRUSTA_FINGER_COUNT> splay_span{};
  std::array<double, FRUSTA_FINGER_COUNT> abduction_range{};  // radians
  // the finger resistance (newtons) that sets a brake to its full brake_units
  double brake_full_scale = 10.0;
  double brake_units = 1000.0;  // OpenGloves' force-feedback range
  double analog_max = 4095.0;   // the largest raw reading the glove sends (12-bit ADC)
};

// A LucidGloves-like glove: curl 0 straight, 4095 in a fist, splay centred at 2048;
// the fist bends the finger joints 80, 90 and 70 degrees (the thumb 45, 40, 60), a
// full splay 15 degrees; a full brake holds 10 N.
GloveCalibration default_glove_calibration();

// Every value finite; open and closed readings differ; ranges and scales positive and
// within analog_max. The thread's error names the field.
frusta_result check_glove_calibration(const GloveCalibration& calibration);

// A glove's raw reading of one hand.
struct RawGloveReading {
  std::array<std::array<double, kFlexionJoints>, FRUSTA_FINGER_COUNT> curl{};
  std::array<double, FRUSTA_FINGER_COUNT> splay{};
  std::array<bool, FRUSTA_FINGER_COUNT> has_curl{};   // fingers the glove reported
  std::array<bool, FRUSTA_FINGER_COUNT> has_splay{};
};

// Joint angles (finger-major: abduction, flexion 1-3) from a raw reading. Readings
// beyond the calibrated open and closed ends are held at them (a sensor drifts; the
// hand must not bend backwards); fingers or splays not reported keep `previous`.
void raw_to_joint_angles(const GloveCalibration& calibration, const RawGloveReading& raw,
                         const std::array<double, FRUSTA_HAND_JOINT_COUNT>& previous,
                         std::array<double, FRUSTA_HAND_JOINT_COUNT>* angles);

// Brake units for a finger resistance (newtons), in [0, brake_units], rounded.
int32_t resistance_to_brake_units(const GloveCalibration& calibration, double newtons);

}  // namespace frusta
