// SPDX-License-Identifier: MIT
// The benches' percentile of a sample: the value at rank p * size (the largest for p = 1),
// 0 for none. One rule, so that a p99 in one suite's document means what it means in
// another's.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace frusta::bench {

inline double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const double last = static_cast<double>(v.size()) - 1.0;
  return v[static_cast<std::size_t>(std::min(last, p * static_cast<double>(v.size())))];
}

}  // namespace frusta::bench
