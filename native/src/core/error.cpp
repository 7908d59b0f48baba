// SPDX-License-Identifier: MIT
#include "core/error.h"

#include <cstdarg>
#include <cstdio>

namespace frusta {

namespace {
// fixed storage: reporting an error must not itself fail to allocate
thread_local char t_message[512] = "";
}  // namespace

frusta_result fail(frusta_result code, const char* format, ...) {
  const int prefix = std::snprintf(t_message, sizeof t_message, "%s: ", frusta_result_name(code));
  std::va_list args;
  va_start(args, format);
  std::vsnprintf(t_message + prefix, sizeof t_message - static_cast<size_t>(prefix), format, args);
  va_end(args);
  return code;
}

const char* last_error_message() { return t_message; }
void clear_last_error() { t_message[0] = '\0'; }

}  // namespace frusta
