// SPDX-License-Identifier: MIT
// A host on a busy machine, scripted: it stamps a haptic sample for every step of a
// 1 kHz world with the sample's time (plus noise, as a glove's or a host's clock
// reads), and hands each to the world just before that step, except during its
// stalls, after which the whole backlog arrives at once. Deterministic: the tests of
// timed input step the world themselves, on its step clock.
#pragma once

#include <cstdint>
#include <vector>

namespace frusta::scenes {

struct HostStall {
  int64_t from_step;  // the first step whose sample is held back
  int32_t steps;      // for this many steps (ms at 1 kHz); they arrive before step from + steps
};

class JitteryHost {
 public:
  // noise_s: each sample's stamp is off by up to this much either way (less than half
  // a period keeps the stamps in order); seed: which noise
  JitteryHost(std::vector<HostStall> stalls, double noise_s, uint32_t seed, double rate_hz = 1000.0);

  // The time sample n is stamped with: n / rate_hz, plus noise.
  double stamp(int64_t n) const { return stamps_at(n); }
  // The samples the host hands over just before step n (the step at time n / rate_hz),
  // oldest first: sample n itself, unless a stall holds it back; at a stall's end, the
  // backlog with it.
  void delivered_before(int64_t step, std::vector<int64_t>* samples) const;

  // Stalls of 5, 10, 20 and 50 ms, in turn, one every `every` steps from `first` on
  // until `last`: what the acceptance of timed input injects.
  static std::vector<HostStall> stall_cycle(int64_t first, int64_t last, int64_t every);

 private:
  double stamps_at(int64_t n) const;

  std::vector<HostStall> stalls_;
  double noise_s_;
  uint32_t seed_;
  double rate_hz_;
};

}  // namespace frusta::scenes
