// SPDX-License-Identifier: MIT
// The bake's parameters and their ranges, checked once where they enter: the C ABI
// (before the baker library is even loaded), frusta-bake's options, and
// bake_sphere_tree for C++ callers. Header-only: the runtime checks a def without
// linking the baker (Embree).
#pragma once

#include <cmath>
#include <cstdint>

#include "core/error.h"
#include "spheretree/tree_limits.h"

namespace frusta {

// Below 10 um a float (Embree) cannot resolve a hand-sized object's surface, and the
// cover's sample cap (4e6 points) cannot meet it on anything larger than a coin;
// past 1 m the spheres are larger than any hand and their query points leave the
// range Embree accepts.
constexpr double kMinTargetError = 1e-5;
constexpr double kMaxTargetError = 1.0;
// Each figure keeps its sample points in memory (48 bytes each): 1e7 is 480 MB.
constexpr int64_t kMinErrorSamples = 1000;
constexpr int64_t kMaxErrorSamples = 10000000;

struct BakeParams {
  double target_error = 0.001;  // metres: bound on both error figures
  int64_t max_leaves = 200000;
  // 64-bit so that frusta-bake's options land here unnarrowed and out-of-range
  // values are reported as given
  int64_t branching = 4;
  int64_t max_depth = kMaxTreeDepth;
  int64_t error_samples = 100000;  // points on the surface, and as many on the leaves
  uint64_t seed = 1;               // any value
};

// The bake's values between the structs that carry them by the same names: the C ABI's
// def, the baker plugin's params and BakeParams. The def's 32-bit fields receive only
// the defaults, so the casts lose nothing.
template <class From, class To>
void copy_bake_params(const From& in, To& out) {
  out.target_error = in.target_error;
  out.max_leaves = in.max_leaves;
  out.branching = static_cast<decltype(out.branching)>(in.branching);
  out.max_depth = static_cast<decltype(out.max_depth)>(in.max_depth);
  out.error_samples = in.error_samples;
  out.seed = in.seed;
}

enum class BakeField { kNone, kTarget, kLeaves, kBranching, kDepth, kSamples };

// FRUSTA_OK, or FRUSTA_ERROR_NOT_FINITE / FRUSTA_ERROR_OUT_OF_RANGE with a message
// naming the field, its value and its range; *field (when given) says which.
inline frusta_result check_bake_params(const BakeParams& p, BakeField* field = nullptr) {
  BakeField bad = BakeField::kNone;
  frusta_result r = FRUSTA_OK;
  if (!std::isfinite(p.target_error)) {
    bad = BakeField::kTarget;
    r = fail(FRUSTA_ERROR_NOT_FINITE, "target_error is %g, must be a finite length in metres",
             p.target_error);
  } else if (!(p.target_error >= kMinTargetError && p.target_error <= kMaxTargetError)) {
    bad = BakeField::kTarget;
    r = fail(FRUSTA_ERROR_OUT_OF_RANGE, "target_error is %g m, must be %g..%g m", p.target_error,
             kMinTargetError, kMaxTargetError);
  } else if (p.max_leaves < 1 || p.max_leaves > kMaxLeaves) {
    bad = BakeField::kLeaves;
    r = fail(FRUSTA_ERROR_OUT_OF_RANGE, "max_leaves is %lld, must be 1..%lld",
             static_cast<long long>(p.max_leaves), static_cast<long long>(kMaxLeaves));
  } else if (p.branching < 2 || p.branching > kMaxBranching) {
    bad = BakeField::kBranching;
    r = fail(FRUSTA_ERROR_OUT_OF_RANGE, "branching is %lld, must be 2..%d",
             static_cast<long long>(p.branching), kMaxBranching);
  } else if (p.max_depth < 1 || p.max_depth > kMaxTreeDepth) {
    bad = BakeField::kDepth;
    r = fail(FRUSTA_ERROR_OUT_OF_RANGE, "max_depth is %lld, must be 1..%d",
             static_cast<long long>(p.max_depth), kMaxTreeDepth);
  } else if (p.error_samples < kMinErrorSamples || p.error_samples > kMaxErrorSamples) {
    bad = BakeField::kSamples;
    r = fail(FRUSTA_ERROR_OUT_OF_RANGE, "error_samples is %lld, must be %lld..%lld",
             static_cast<long long>(p.error_samples), static_cast<long long>(kMinErrorSamples),
             static_cast<long long>(kMaxErrorSamples));
  }
  if (field) *field = bad;
  return r;
}

}  // namespace frusta
