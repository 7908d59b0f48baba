// SPDX-License-Identifier: MIT
// Windows wakes sleeping threads on the system timer's tick, 15.6 ms unless some
// program asks for finer: a 1 kHz loop that sleeps part of each period would run in
// bursts. Each real-time thread (the world's, a glove's) holds a FineTimerResolution
// while it runs, which asks for 1 ms (timeBeginPeriod) and gives it back after. Linux
// and macOS sleeps are already fine-grained: there it does nothing.
#pragma once

namespace frusta {

class FineTimerResolution {
 public:
  FineTimerResolution();
  ~FineTimerResolution();
  FineTimerResolution(const FineTimerResolution&) = delete;
  FineTimerResolution& operator=(const FineTimerResolution&) = delete;

 private:
  bool granted_ = false;
};

}  // namespace frusta
