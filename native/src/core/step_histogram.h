// SPDX-License-Identifier: MIT
// Percentiles of step times without storing them: fixed log-spaced buckets (about
// 3 % apart from 0.1 us to 1 s), so the 1 kHz thread records a step with an increment
// and the host reads p50 / p99 / max from a snapshot copy.
#pragma once

#include <array>
#include <cstdint>

namespace frusta {

class StepHistogram {
 public:
  void record(double microseconds);
  void clear() { *this = StepHistogram(); }

  int64_t count() const { return count_; }
  double max() const { return max_; }
  // The value below which a fraction p (0..1) of the recorded steps fall, to within
  // one bucket (the bucket's upper edge, so it never flatters).
  double percentile(double p) const;

 private:
  static constexpr int kBuckets = 512;
  std::array<int64_t, kBuckets> buckets_{};
  int64_t count_ = 0;
  double max_ = 0.0;
};

}  // namespace frusta
