// SPDX-License-Identifier: MIT
#include "geometry/wide_contact_test.h"

#include <cmath>

namespace frusta {

namespace {
WideConstants<float> single_precision(const SegmentFrame& frame, double margin) {
  auto f = [](double v) { return static_cast<float>(v); };
  return {f(frame.distal.x), f(frame.distal.y), f(frame.distal.z), f(frame.proximal.x),
          f(frame.proximal.y), f(frame.proximal.z), f(frame.axis.x), f(frame.axis.y),
          f(frame.axis.z), f(frame.length), f(frame.r_distal), f(frame.r_proximal), f(frame.slope),
          f(frame.sec_alpha), f(frame.sin_alpha), f(margin),
          // the frame's coordinates round to single precision relative to their size
          f(frame.size + margin + std::fabs(frame.distal.x) + std::fabs(frame.distal.y) +
            std::fabs(frame.distal.z))};
}

#if defined(__GNUC__)
WideConstants<Floats4> in_every_lane(const WideConstants<float>& c) {
  auto l = [](float v) { return Floats4{v, v, v, v}; };
  return {l(c.ex),    l(c.ey),        l(c.ez),        l(c.px),     l(c.py),       l(c.pz),
          l(c.ax),    l(c.ay),        l(c.az),        l(c.length), l(c.r_distal), l(c.r_proximal),
          l(c.slope), l(c.sec_alpha), l(c.sin_alpha), l(c.margin), l(c.base)};
}
#endif
}  // namespace

WideSegmentTest::WideSegmentTest(const SegmentFrame& frame, double margin_metres)
    : single(single_precision(frame, margin_metres)),
#if defined(__GNUC__)
      lanes(in_every_lane(single)),
#endif
      side(!frame.degenerate) {
}

}  // namespace frusta
