// SPDX-License-Identifier: MIT
// Input checks shared by the C ABI shims. Each returns FRUSTA_OK or sets the
// thread's error message naming the field (e.g. "segment.distal[1]") and value.
#pragma once

#include <cstdint>
#include <cstdio>

#include "core/base.h"

namespace frusta {

// Largest coordinate accepted anywhere: beyond it a double cannot resolve
// micrometres, so the value is corrupt rather than a real scene.
constexpr double kMaxCoordinate = 1e6;
// Largest coordinate of a point of a hand or an object (a finger joint, a contact
// point): their poses lie within kMaxCoordinate, and the parts around a pose add
// metres to it, not another kMaxCoordinate.
constexpr double kMaxPointCoordinate = 2.0 * kMaxCoordinate;
// Largest joint angle accepted from any input (C ABI, C++ entry points, gloves), in
// radians: a reading beyond two turns is garbage; anything within is clamped to the
// hand's joint limits.
constexpr double kMaxJointAngle = FRUSTA_MAX_JOINT_ANGLE;
// A rotation quaternion from any input may have a norm in this range; it is normalised.
constexpr double kMinQuaternionNorm = 0.5;
constexpr double kMaxQuaternionNorm = 2.0;

// Written into defs by frusta_default_*_def(); a def without it was built by hand.
constexpr int32_t kDefCookie = 0x46525354;  // "FRST"
frusta_result check_def_cookie(int32_t internal_value, const char* def_name);

frusta_result check_pointer(const void* pointer, const char* field);
frusta_result check_struct_size(int32_t given, int32_t expected, const char* struct_name);
frusta_result check_finite(const double* values, int count, const char* field);
// finite and |value| <= limit for every element
frusta_result check_bounded(const double* values, int count, double limit, const char* field);
// finite and min <= value (strict when strict_min), value <= max
frusta_result check_range(double value, double min, double max, bool strict_min, const char* field);

// The same checks with the field's name given as a printf format and its arguments,
// formatted only when the check fails: checks on the 1 kHz path then cost a pass over
// the values, not a snprintf per field (measured: 75 % of the forces' time was naming
// fields that were fine).
bool all_finite(const double* values, int count);
bool all_bounded(const double* values, int count, double limit);

template <class... Args>
frusta_result check_finite_named(const double* values, int count, const char* format, Args... args) {
  if (all_finite(values, count)) return FRUSTA_OK;
  char field[128];
  std::snprintf(field, sizeof field, format, args...);
  return check_finite(values, count, field);
}

template <class... Args>
frusta_result check_bounded_named(const double* values, int count, double limit, const char* format,
                                  Args... args) {
  if (all_bounded(values, count, limit)) return FRUSTA_OK;
  char field[128];
  std::snprintf(field, sizeof field, format, args...);
  return check_bounded(values, count, limit, field);
}

template <class... Args>
frusta_result check_range_named(double value, double min, double max, bool strict_min,
                                const char* format, Args... args) {
  if (strict_min ? value > min && value <= max : value >= min && value <= max) return FRUSTA_OK;
  char field[128];
  std::snprintf(field, sizeof field, format, args...);
  return check_range(value, min, max, strict_min, field);
}

}  // namespace frusta
