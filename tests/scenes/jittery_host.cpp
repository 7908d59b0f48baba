// SPDX-License-Identifier: MIT
#include "scenes/jittery_host.h"

#include <algorithm>

namespace frusta::scenes {

namespace {

// a uniform number in [-1, 1] for (seed, n): a hash, so any sample's noise is known
// without drawing the ones before it
double noise_unit(uint32_t seed, int64_t n) {
  uint64_t x = static_cast<uint64_t>(n) * 0x9E3779B97F4A7C15ull + seed * 0xBF58476D1CE4E5B9ull + 1;
  x ^= x >> 30;
  x *= 0xBF58476D1CE4E5B9ull;
  x ^= x >> 27;
  x *= 0x94D049BB133111EBull;
  x ^= x >> 31;
  return static_cast<double>(x >> 11) / static_cast<double>(1ull << 52) - 1.0;
}

}  // namespace

JitteryHost::JitteryHost(std::vector<HostStall> stalls, double noise_s, uint32_t seed, double rate_hz)
    : stalls_(std::move(stalls)), noise_s_(noise_s), seed_(seed), rate_hz_(rate_hz) {}

double JitteryHost::stamps_at(int64_t n) const {
  return static_cast<double>(n) / rate_hz_ + noise_s_ * noise_unit(seed_, n);
}

void JitteryHost::delivered_before(int64_t step, std::vector<int64_t>* samples) const {
  samples->clear();
  for (const HostStall& s : stalls_) {
    if (step >= s.from_step && step < s.from_step + s.steps) return;  // stalled: nothing
    if (step == s.from_step + s.steps) {
      for (int64_t n = s.from_step; n <= step; ++n) samples->push_back(n);  // the burst
      return;
    }
  }
  samples->push_back(step);
}

std::vector<HostStall> JitteryHost::stall_cycle(int64_t first, int64_t last, int64_t every) {
  static const int32_t kLengths[] = {5, 10, 20, 50};
  std::vector<HostStall> stalls;
  for (int64_t at = first, i = 0; at < last; at += every, ++i) stalls.push_back({at, kLengths[i % 4]});
  return stalls;
}

}  // namespace frusta::scenes
