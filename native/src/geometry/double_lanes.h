// SPDX-License-Identifier: MIT
// Two doubles in one register (SSE2 on x86-64, NEON on arm64), by the vector extension
// GCC and Clang share, and the few operations that code written once for a double or
// two of them needs beyond + - * / and comparisons: each lane's IEEE answer is the
// scalar one's, so a computation run two at a time gives a single one's bits. Zen 1
// takes a square root or a division of two lanes as fast as of one.
#pragma once

#include <cmath>
#include <cstdint>

#if defined(__GNUC__) && defined(__SSE2__)
#include <emmintrin.h>
#elif defined(__GNUC__) && defined(__aarch64__)
#include <arm_neon.h>
#endif

namespace frusta {

#if defined(__GNUC__)
#define FRUSTA_DOUBLE_LANES 1
typedef double Doubles2 __attribute__((vector_size(16)));
typedef int64_t Mask2 __attribute__((vector_size(16)));

namespace lanes {
inline Doubles2 root(Doubles2 v) {
#if defined(__SSE2__)
  return reinterpret_cast<Doubles2>(_mm_sqrt_pd(reinterpret_cast<__m128d>(v)));
#elif defined(__aarch64__)
  return reinterpret_cast<Doubles2>(vsqrtq_f64(reinterpret_cast<float64x2_t>(v)));
#else
  return Doubles2{std::sqrt(v[0]), std::sqrt(v[1])};
#endif
}
inline Doubles2 magnitude(Doubles2 v) {
  return reinterpret_cast<Doubles2>(reinterpret_cast<Mask2>(v) & INT64_MAX);
}
inline Doubles2 splat(Doubles2, double v) { return Doubles2{v, v}; }  // (the first names the type)
}  // namespace lanes
#endif

namespace lanes {
inline double root(double v) { return std::sqrt(v); }
inline double magnitude(double v) { return std::fabs(v); }
inline double splat(double, double v) { return v; }
// std::min and std::max, lane by lane: the same operand where both compare equal
template <class D>
D lesser(D a, D b) {
  return b < a ? b : a;
}
template <class D>
D greater(D a, D b) {
  return a < b ? b : a;
}
}  // namespace lanes

}  // namespace frusta
