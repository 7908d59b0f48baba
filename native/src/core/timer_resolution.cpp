// SPDX-License-Identifier: MIT
#include "core/timer_resolution.h"

#ifdef _WIN32
#define WIN32_LEAN_AND_MEAN
#include <windows.h>
#include <timeapi.h>
#endif

namespace frusta {

#ifdef _WIN32
FineTimerResolution::FineTimerResolution() : granted_(timeBeginPeriod(1) == TIMERR_NOERROR) {}
FineTimerResolution::~FineTimerResolution() {
  if (granted_) timeEndPeriod(1);
}
#else
FineTimerResolution::FineTimerResolution() = default;
FineTimerResolution::~FineTimerResolution() = default;
#endif

}  // namespace frusta
