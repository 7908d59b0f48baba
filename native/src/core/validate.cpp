// SPDX-License-Identifier: MIT
#include "core/validate.h"

#include <cmath>

#include "core/error.h"

namespace frusta {

frusta_result check_def_cookie(int32_t internal_value, const char* def_name) {
  if (internal_value == kDefCookie) return FRUSTA_OK;
  return fail(FRUSTA_ERROR_DEF_NOT_DEFAULTED,
              "%s.internal_value is %d: start every %s from frusta_default_%s() and change "
              "fields afterwards", def_name, internal_value, def_name, def_name + 7);
}

frusta_result check_pointer(const void* pointer, const char* field) {
  if (pointer) return FRUSTA_OK;
  return fail(FRUSTA_ERROR_NULL_POINTER, "%s is null", field);
}

frusta_result check_struct_size(int32_t given, int32_t expected, const char* struct_name) {
  if (given == expected) return FRUSTA_OK;
  return fail(FRUSTA_ERROR_STRUCT_SIZE,
              "%s.struct_size is %d but this library's %s is %d bytes: the caller was built "
              "against another frusta.h, or its struct mirror has drifted",
              struct_name, given, struct_name, expected);
}

bool all_finite(const double* values, int count) {
  for (int i = 0; i < count; ++i)
    if (!std::isfinite(values[i])) return false;
  return true;
}

bool all_bounded(const double* values, int count, double limit) {
  for (int i = 0; i < count; ++i)
    if (!(std::fabs(values[i]) <= limit)) return false;  // NaN fails too
  return true;
}

frusta_result check_finite(const double* values, int count, const char* field) {
  for (int i = 0; i < count; ++i) {
    if (!std::isfinite(values[i])) {
      if (count == 1) return fail(FRUSTA_ERROR_NOT_FINITE, "%s is %g", field, values[i]);
      return fail(FRUSTA_ERROR_NOT_FINITE, "%s[%d] is %g", field, i, values[i]);
    }
  }
  return FRUSTA_OK;
}

frusta_result check_bounded(const double* values, int count, double limit, const char* field) {
  if (frusta_result r = check_finite(values, count, field); r != FRUSTA_OK) return r;
  for (int i = 0; i < count; ++i) {
    if (std::fabs(values[i]) > limit) {
      return fail(FRUSTA_ERROR_OUT_OF_RANGE, "%s[%d] is %g, beyond the limit of +-%g", field, i,
                  values[i], limit);
    }
  }
  return FRUSTA_OK;
}

frusta_result check_range(double value, double min, double max, bool strict_min,
                          const char* field) {
  if (frusta_result r = check_finite(&value, 1, field); r != FRUSTA_OK) return r;
  const bool low = strict_min ? !(value > min) : value < min;
  if (low || value > max) {
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "%s is %g, must be %s %g and <= %g", field, value,
                strict_min ? ">" : ">=", min, max);
  }
  return FRUSTA_OK;
}

}  // namespace frusta
