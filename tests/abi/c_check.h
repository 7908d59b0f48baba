/* SPDX-License-Identifier: MIT */
/* The C tests' reporting: each check prints "ok   <what>" or "FAIL <what>" and counts
 * it; main prints the tally. Included by each C test (one translation unit each); the
 * helpers are inline so a test that uses only some of them compiles without warnings. */
#ifndef FRUSTA_TESTS_ABI_C_CHECK_H
#define FRUSTA_TESTS_ABI_C_CHECK_H

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "frusta/frusta.h"

static int g_passed;
static int g_failed;

/* One check: prints "ok   <what>" or "FAIL <what>" and counts it; returns ok. */
static int check(int ok, const char* format, ...)
#if defined(__MINGW32__)  /* MinGW's printf is C99's (__USE_MINGW_ANSI_STDIO), not msvcrt's */
    __attribute__((format(gnu_printf, 2, 3)))
#elif defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

static int check(int ok, const char* format, ...) {
  va_list args;
  va_start(args, format);
  fputs(ok ? "ok   " : "FAIL ", stdout);
  vprintf(format, args);
  fputc('\n', stdout);
  va_end(args);
  if (ok)
    ++g_passed;
  else
    ++g_failed;
  return ok;
}

static int contains(const char* haystack, const char* needle) {
  return haystack && needle && strstr(haystack, needle) != NULL;
}

/* One check: the call returned `want`, and frusta_last_error() names `field` and
 * (unless null) `value`, the text %g or %d prints for the offending number. */
static inline int expect_error(const char* what, frusta_result got, frusta_result want, const char* field,
                        const char* value) {
  const char* message = frusta_last_error();
  const int ok = got == want && contains(message, field) && (!value || contains(message, value));
  return check(ok, "%s -> %s (want %s naming '%s'%s%s): \"%s\"", what, frusta_result_name(got),
               frusta_result_name(want), field, value ? " and " : "", value ? value : "",
               message ? message : "(null)");
}

static inline int expect_ok(const char* what, frusta_result got) {
  return check(got == FRUSTA_OK, "%s -> %s%s%s", what, frusta_result_name(got),
               got == FRUSTA_OK ? "" : ": ", got == FRUSTA_OK ? "" : frusta_last_error());
}

static inline int near(double a, double b, double tolerance) { return fabs(a - b) <= tolerance; }

#endif /* FRUSTA_TESTS_ABI_C_CHECK_H */
