// SPDX-License-Identifier: MIT
#include "runtime/step_thread.h"

#include <chrono>
#include <system_error>

#include "core/error.h"
#include "core/periodic_clock.h"
#include "core/thread_priority.h"
#include "core/timer_resolution.h"

namespace frusta {

frusta_result StepThread::start(double rate_hz, double spin_us, Step step, const Wakeup* sample_arrived,
                                bool realtime) {
  if (!(rate_hz >= 1.0 && rate_hz <= 100000.0))
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "rate is %g Hz, must be 1..100000", rate_hz);
  if (!(spin_us >= 0.0 && spin_us <= 1e6 / rate_hz))
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "spin is %g us, must be 0..one period", spin_us);
  if (running()) return fail(FRUSTA_ERROR_WRONG_STATE, "the world's thread is already running");
  if (thread_.joinable()) thread_.join();  // a thread stopped by itself is collected first
  running_.store(true, std::memory_order_release);
  try {
    thread_ = std::thread([this, rate_hz, spin_us, step = std::move(step), sample_arrived, realtime] {
      run(rate_hz, spin_us, step, sample_arrived, realtime);
    });
  } catch (const std::system_error& e) {
    running_.store(false, std::memory_order_release);
    return fail(FRUSTA_ERROR_INTERNAL, "the world's thread could not start: %s", e.what());
  }
  return FRUSTA_OK;
}

void StepThread::stop() {
  running_.store(false, std::memory_order_release);
  if (thread_.joinable()) thread_.join();
}

void StepThread::run(double rate_hz, double spin_us, const Step& step, const Wakeup* sample_arrived,
                     bool realtime) {
  using namespace std::chrono;
  using Duration = PeriodicClock::Clock::duration;
  const FineTimerResolution fine_sleeps;
  realtime_ = realtime && raise_to_realtime_priority();
  const Duration period = duration_cast<Duration>(duration<double>(1.0 / rate_hz));
  PeriodicClock clock(period, duration_cast<Duration>(duration<double, std::micro>(spin_us)));
  clock.start();
  const auto started = steady_clock::now();
  int64_t steps = 0;
  bool glove = false;  // the last step said when a glove's samples come
  while (running_.load(std::memory_order_acquire)) {
    const Duration late = glove ? clock.wait(sample_arrived, period * kEarlyWindowTenths / 10) : clock.wait();
    lateness_.record(duration<double, std::micro>(late).count());
    overruns_ = clock.missed();
    const int64_t tick_ns = duration_cast<nanoseconds>(clock.tick().time_since_epoch()).count();
    ++steps;
    achieved_rate_hz_ = static_cast<double>(steps) / duration<double>(steady_clock::now() - started).count();
    const int64_t sample_ns = step(1.0 / rate_hz, tick_ns);
    glove = sample_ns > 0;
    if (glove) clock.align(PeriodicClock::Clock::time_point(nanoseconds(sample_ns) + period / 2));
  }
}

}  // namespace frusta
