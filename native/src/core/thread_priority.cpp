// SPDX-License-Identifier: MIT
#include "core/thread_priority.h"

#ifdef _WIN32
#define WIN32_LEAN_AND_MEAN
#include <windows.h>
#else
#include <pthread.h>
#include <sched.h>
#endif

namespace frusta {

bool raise_to_realtime_priority() {
#ifdef _WIN32
  return SetThreadPriority(GetCurrentThread(), THREAD_PRIORITY_TIME_CRITICAL) != 0;
#else
  constexpr int kPriority = 40;  // of 1..99; interrupt threads run at 50
  sched_param param{};
  param.sched_priority = kPriority;
  return pthread_setschedparam(pthread_self(), SCHED_FIFO, &param) == 0;
#endif
}

}  // namespace frusta
