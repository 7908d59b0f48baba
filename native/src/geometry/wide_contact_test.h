// SPDX-License-Identifier: MIT
// may_touch for a node's children at once, in single precision: a tree walk culls with
// it and leaves the exact test to the nodes it reports (query_segment), or to its caller
// (query_segment_loose). It holds wherever may_touch holds (its slack is a hundred times
// what single precision rounds), and may hold a hair beyond. The closing grasp's segment
// walks, 2.5 mm margins: 10^4 leaves 4.68 -> 3.55 us, 10^5 leaves 24.6 -> 22.1 us, the
// same hits.
#pragma once

#include <cmath>
#include <cstdint>

#include "geometry/segment_frame.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace frusta {

#if defined(__GNUC__)
// Four lanes in one register (SSE2 on x86-64, NEON on arm64), by the vector extension
// GCC and Clang share: the same IEEE single-precision arithmetic as four scalar tests.
typedef float Floats4 __attribute__((vector_size(16)));
typedef int32_t Mask4 __attribute__((vector_size(16)));

// Four spheres' (x, y, z, radius) rows turned into a register per coordinate.
inline void transpose(const Floats4 (&row)[4], Floats4& x, Floats4& y, Floats4& z, Floats4& radius) {
#if defined(__clang__)
#define FRUSTA_LANES(a, b, i, j, k, l) __builtin_shufflevector(a, b, i, j, k, l)
#else
#define FRUSTA_LANES(a, b, i, j, k, l) __builtin_shuffle(a, b, Mask4{i, j, k, l})
#endif
  const Floats4 xy01 = FRUSTA_LANES(row[0], row[1], 0, 4, 1, 5);
  const Floats4 xy23 = FRUSTA_LANES(row[2], row[3], 0, 4, 1, 5);
  const Floats4 zr01 = FRUSTA_LANES(row[0], row[1], 2, 6, 3, 7);
  const Floats4 zr23 = FRUSTA_LANES(row[2], row[3], 2, 6, 3, 7);
  x = FRUSTA_LANES(xy01, xy23, 0, 1, 4, 5);
  y = FRUSTA_LANES(xy01, xy23, 2, 3, 6, 7);
  z = FRUSTA_LANES(zr01, zr23, 0, 1, 4, 5);
  radius = FRUSTA_LANES(zr01, zr23, 2, 3, 6, 7);
#undef FRUSTA_LANES
}

// Bit k set where lane k of a comparison's answer is true.
inline unsigned lane_bits(Mask4 mask) {
#if defined(__SSE2__)
  return static_cast<unsigned>(_mm_movemask_ps(_mm_castsi128_ps(reinterpret_cast<__m128i>(mask))));
#else
  return static_cast<unsigned>((mask[0] & 1) | (mask[1] & 2) | (mask[2] & 4) | (mask[3] & 8));
#endif
}
#endif

// A segment, a margin and the rounding slack, as single-precision constants: one of each
// (L = float), or each held in every lane (L = Floats4).
template <class L>
struct WideConstants {
  L ex, ey, ez;  // E, the distal centre
  L px, py, pz;  // D, the proximal centre
  L ax, ay, az;  // the unit axis from E towards D
  L length, r_distal, r_proximal, slope, sec_alpha, sin_alpha;
  L margin;
  L base;  // what every test's rounding scale holds besides the sphere's own sizes
};

struct WideSegmentTest {
  WideConstants<float> single;
#if defined(__GNUC__)
  // the same in every lane, which a test of four reads as they are: it had broadcast each
  // from `single` per four spheres, a fifth of a walk's culling
  WideConstants<Floats4> lanes;
#endif
  bool side;  // the side is tested (the segment is not degenerate)

  WideSegmentTest(const SegmentFrame& frame, double margin_metres);

  // The test for one sphere, or (F = Floats4) four: the same expressions lane by lane.
  template <class F>
  auto operator()(F cx, F cy, F cz, F radius) const;

 private:
  // the constants a test of F reads
  const WideConstants<float>& constants(float) const { return single; }
#if defined(__GNUC__)
  const WideConstants<Floats4>& constants(Floats4) const { return lanes; }
#endif
};

namespace wide_detail {
// relative slack of the single-precision test, 2^-17: a hundred times what its dozen
// steps of 2^-24 each round, converting the frame to single precision included
constexpr float kSlack = 1.0f / 131072.0f;
inline float magnitude(float v) { return std::fabs(v); }
#if defined(__GNUC__)
inline Floats4 magnitude(Floats4 v) {
  return reinterpret_cast<Floats4>(reinterpret_cast<Mask4>(v) & 0x7fffffff);
}
#endif
}  // namespace wide_detail

template <class F>
auto WideSegmentTest::operator()(F cx, F cy, F cz, F radius) const {
  using wide_detail::magnitude;
  const WideConstants<F>& k = constants(cx);
  const F wx = cx - k.ex, wy = cy - k.ey, wz = cz - k.ez;
  const F scale = magnitude(wx) + magnitude(wy) + magnitude(wz) + radius + k.base;
  const F reach = radius + k.margin + wide_detail::kSlack * scale;
  const F l2 = reach + k.r_distal, l1 = reach + k.r_proximal;
  const F dx = cx - k.px, dy = cy - k.py, dz = cz - k.pz;
  auto near_ends = (wx * wx + wy * wy + wz * wz <= l2 * l2) | (dx * dx + dy * dy + dz * dz <= l1 * l1);
  if (!side) return near_ends;
  const F axial = wx * k.ax + wy * k.ay + wz * k.az;
  const F shift = reach * k.sin_alpha;
  const F threshold = reach * k.sec_alpha + k.r_distal + axial * k.slope;
  const F qx = wx - axial * k.ax, qy = wy - axial * k.ay, qz = wz - axial * k.az;
  return near_ends | ((axial >= -shift) & (axial <= k.length - shift) & (threshold >= 0.0f) &
                      (qx * qx + qy * qy + qz * qz <= threshold * threshold));
}

}  // namespace frusta
