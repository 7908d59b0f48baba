// SPDX-License-Identifier: MIT
#include "core/step_histogram.h"

#include <gtest/gtest.h>

namespace frusta {
namespace {

TEST(StepHistogram, PercentilesWithinABucketAndNeverFlattering) {
  StepHistogram h;
  for (int us = 1; us <= 1000; ++us) h.record(us);
  EXPECT_EQ(h.count(), 1000);
  EXPECT_EQ(h.max(), 1000.0);
  const double p50 = h.percentile(0.5), p99 = h.percentile(0.99);
  EXPECT_GE(p50, 500.0) << "an upper edge: never below the true value";
  EXPECT_LE(p50, 500.0 * 1.034);
  EXPECT_GE(p99, 990.0);
  EXPECT_LE(p99, 1000.0) << "capped by the largest seen";
  EXPECT_EQ(h.percentile(1.0), 1000.0);
}

TEST(StepHistogram, ExtremesLandInTheEndBucketsAndEmptyIsZero) {
  StepHistogram h;
  EXPECT_EQ(h.percentile(0.5), 0.0);
  h.record(0.0);
  h.record(1e9);  // a 15-minute stall still counts
  EXPECT_EQ(h.count(), 2);
  EXPECT_EQ(h.max(), 1e9);
  EXPECT_LE(h.percentile(0.5), 0.1);
}

}  // namespace
}  // namespace frusta
