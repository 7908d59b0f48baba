// SPDX-License-Identifier: MIT
#include "geometry/wide_contact_test.h"

namespace frusta {

WideSegmentTest::WideSegmentTest(const SegmentFrame& frame, double margin_metres)
    : ex(static_cast<float>(frame.distal.x)),
      ey(static_cast<float>(frame.distal.y)),
      ez(static_cast<float>(frame.distal.z)),
      px(static_cast<float>(frame.proximal.x)),
      py(static_cast<float>(frame.proximal.y)),
      pz(static_cast<float>(frame.proximal.z)),
      ax(static_cast<float>(frame.axis.x)),
      ay(static_cast<float>(frame.axis.y)),
      az(static_cast<float>(frame.axis.z)),
      length(static_cast<float>(frame.length)),
      r_distal(static_cast<float>(frame.r_distal)),
      r_proximal(static_cast<float>(frame.r_proximal)),
      slope(static_cast<float>(frame.slope)),
      sec_alpha(static_cast<float>(frame.sec_alpha)),
      sin_alpha(static_cast<float>(frame.sin_alpha)),
      margin(static_cast<float>(margin_metres)),
      // the frame's coordinates round to single precision relative to their size
      base(static_cast<float>(frame.size + margin_metres + std::fabs(frame.distal.x) +
                              std::fabs(frame.distal.y) + std::fabs(frame.distal.z))),
      side(!frame.degenerate) {}

}  // namespace frusta
