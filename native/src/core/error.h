// SPDX-License-Identifier: MIT
// The thread-local error message behind frusta_last_error(). Every failing C ABI
// call sets it; a succeeding call leaves it as it was (like errno).
#pragma once

#include <exception>
#include <new>

#include "core/base.h"

namespace frusta {

// Record message (printf-style) for this thread and return code, so a shim can
// `return fail(FRUSTA_ERROR_..., "field %s ...", ...)`.
frusta_result fail(frusta_result code, const char* format, ...)
#if defined(__MINGW32__)  // MinGW's printf is C99's (__USE_MINGW_ANSI_STDIO), not msvcrt's
    __attribute__((format(gnu_printf, 2, 3)))
#elif defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

// Run a C ABI body so that no exception crosses the boundary.
template <class Body>
frusta_result guarded(const char* function, Body&& body) noexcept {
  try {
    return body();
  } catch (const std::bad_alloc&) {
    return fail(FRUSTA_ERROR_OUT_OF_MEMORY, "%s: out of memory", function);
  } catch (const std::exception& e) {
    return fail(FRUSTA_ERROR_INTERNAL, "%s: %s", function, e.what());
  } catch (...) {
    return fail(FRUSTA_ERROR_INTERNAL, "%s: unknown exception", function);
  }
}

// The static name of a result code, e.g. "FRUSTA_ERROR_STALE_ID" ("FRUSTA_ERROR_UNKNOWN"
// for a value that is none).
const char* result_name(int32_t result);

const char* last_error_message();
// The message after fail()'s "FRUSTA_ERROR_...: " prefix for code, to hand on to a
// fail() that adds it again (from another library or another thread).
const char* last_error_detail(frusta_result code);
void clear_last_error();

}  // namespace frusta
