// SPDX-License-Identifier: MIT
#include "core/step_histogram.h"

#include <algorithm>
#include <cmath>

namespace frusta {

namespace {

constexpr double kLowest = 0.1;     // us: the first bucket's upper edge
constexpr double kGrowth = 1.0333;  // each bucket ~3 % wider than the last: 1e7 span in 512

int bucket_of(double us) {
  if (!(us > kLowest)) return 0;
  return static_cast<int>(std::ceil(std::log(us / kLowest) / std::log(kGrowth)));
}

double upper_edge(int bucket) { return kLowest * std::pow(kGrowth, bucket); }

}  // namespace

void StepHistogram::record(double microseconds) {
  ++buckets_[static_cast<size_t>(std::clamp(bucket_of(microseconds), 0, kBuckets - 1))];
  ++count_;
  max_ = std::max(max_, microseconds);
}

double StepHistogram::percentile(double p) const {
  if (count_ == 0) return 0.0;
  const double wanted = std::clamp(p, 0.0, 1.0) * static_cast<double>(count_);
  int64_t seen = 0;
  for (int b = 0; b < kBuckets; ++b) {
    seen += buckets_[static_cast<size_t>(b)];
    if (static_cast<double>(seen) >= wanted && seen > 0) return std::min(upper_edge(b), max_);
  }
  return max_;
}

}  // namespace frusta
