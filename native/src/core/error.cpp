// SPDX-License-Identifier: MIT
#include "core/error.h"

#include <cstdarg>
#include <cstdio>
#include <cstring>

namespace frusta {

namespace {
// fixed storage: reporting an error must not itself fail to allocate
thread_local char t_message[512] = "";
}  // namespace

frusta_result fail(frusta_result code, const char* format, ...) {
  const int prefix = std::snprintf(t_message, sizeof t_message, "%s: ", result_name(code));
  std::va_list args;
  va_start(args, format);
  std::vsnprintf(t_message + prefix, sizeof t_message - static_cast<size_t>(prefix), format, args);
  va_end(args);
  return code;
}

const char* result_name(int32_t result) {
  switch (result) {
    case FRUSTA_OK: return "FRUSTA_OK";
    case FRUSTA_ERROR_NULL_POINTER: return "FRUSTA_ERROR_NULL_POINTER";
    case FRUSTA_ERROR_STRUCT_SIZE: return "FRUSTA_ERROR_STRUCT_SIZE";
    case FRUSTA_ERROR_DEF_NOT_DEFAULTED: return "FRUSTA_ERROR_DEF_NOT_DEFAULTED";
    case FRUSTA_ERROR_NULL_ID: return "FRUSTA_ERROR_NULL_ID";
    case FRUSTA_ERROR_STALE_ID: return "FRUSTA_ERROR_STALE_ID";
    case FRUSTA_ERROR_NOT_FINITE: return "FRUSTA_ERROR_NOT_FINITE";
    case FRUSTA_ERROR_OUT_OF_RANGE: return "FRUSTA_ERROR_OUT_OF_RANGE";
    case FRUSTA_ERROR_CAPACITY: return "FRUSTA_ERROR_CAPACITY";
    case FRUSTA_ERROR_ABI_MISMATCH: return "FRUSTA_ERROR_ABI_MISMATCH";
    case FRUSTA_ERROR_OUT_OF_MEMORY: return "FRUSTA_ERROR_OUT_OF_MEMORY";
    case FRUSTA_ERROR_INTERNAL: return "FRUSTA_ERROR_INTERNAL";
    case FRUSTA_ERROR_IO: return "FRUSTA_ERROR_IO";
    case FRUSTA_ERROR_FILE_FORMAT: return "FRUSTA_ERROR_FILE_FORMAT";
    case FRUSTA_ERROR_CORRUPT_FILE: return "FRUSTA_ERROR_CORRUPT_FILE";
    case FRUSTA_ERROR_WRONG_STATE: return "FRUSTA_ERROR_WRONG_STATE";
    case FRUSTA_ERROR_UNAVAILABLE: return "FRUSTA_ERROR_UNAVAILABLE";
    case FRUSTA_ERROR_CANCELLED: return "FRUSTA_ERROR_CANCELLED";
    default: return "FRUSTA_ERROR_UNKNOWN";
  }
}
const char* last_error_message() { return t_message; }

const char* last_error_detail(frusta_result code) {
  const size_t prefix = std::strlen(result_name(code));
  if (std::strncmp(t_message, result_name(code), prefix) != 0 || t_message[prefix] != ':')
    return t_message;
  return t_message + prefix + (t_message[prefix + 1] == ' ' ? 2 : 1);
}
void clear_last_error() { t_message[0] = '\0'; }

}  // namespace frusta
