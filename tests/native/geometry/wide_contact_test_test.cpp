// SPDX-License-Identifier: MIT
// The single-precision contact test a tree walk culls with: over a million seeded cases
// and several margins it holds wherever may_touch holds, four lanes answer as four
// single tests, and it stays close enough to the exact gap to cull.
#include "geometry/wide_contact_test.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "geometry/contact_test.h"
#include "geometry/exact_distance.h"
#include "geometry/segment_frame.h"
#include "property_support.h"
#include "scenes/random_cases.h"

namespace frusta {
namespace {

using property::format;
using scenes::Case;

// The case's sphere as a tree stores a node's: in single precision.
struct StoredSphere {
  float x, y, z, radius;
  Sphere exact() const { return {vec3(x, y, z), radius}; }
};
StoredSphere stored(const Sphere& s) {
  return {static_cast<float>(s.center.x), static_cast<float>(s.center.y),
          static_cast<float>(s.center.z), static_cast<float>(s.radius)};
}

TEST(WideContactTestProperty, HoldsWhereverMayTouchHoldsAndLanesAnswerAlike) {
  const std::uint64_t n = scenes::property_case_count();
  scenes::CaseGenerator gen(scenes::kPropertySeed + 31);
  property::PropertyLog log("wide_contact_test");
  constexpr std::array<double, 4> kMargins = {0.0, 1e-4, 2e-3, 1e-2};
  std::uint64_t contacts = 0, extra = 0, negatives = 0;
  double loosest = 0.0;  // the largest exact gap beyond the margin it held at, by the case's scale
  std::array<Case, 4> lane_cases;
  for (std::uint64_t i = 0; i < n; ++i) {
    const Case c = gen.next();
    log.seen(c);
    const SegmentFrame f = make_segment_frame(c.segment);
    const StoredSphere s = stored(c.sphere);
    const double gap = exact_distance(f, s.exact());
    for (double margin : kMargins) {
      const WideSegmentTest wide(f, margin);
      const bool touch = may_touch(f, s.exact(), margin);
      const bool culls = wide(s.x, s.y, s.z, s.radius) == 0;
      contacts += touch;
      log.check(!(touch && culls), "holds wherever may_touch holds", c, [&] {
        return format("margin=%.3g exact gap=%.17g", margin, gap);
      });
      if (!touch) {
        ++negatives;
        if (!culls) {
          ++extra;
          loosest = std::max(loosest, (gap - margin) / property::world_scale(c));
        }
      }
    }
    lane_cases[i % 4] = c;
#if defined(__GNUC__)
    if (i % 4 == 3) {
      // four spheres against the last case's segment, a lane each, as four single tests
      const StoredSphere lanes[4] = {stored(lane_cases[0].sphere), stored(lane_cases[1].sphere),
                                     stored(lane_cases[2].sphere), stored(lane_cases[3].sphere)};
      for (double margin : kMargins) {
        const WideSegmentTest wide(f, margin);
        const unsigned bits = lane_bits(wide(Floats4{lanes[0].x, lanes[1].x, lanes[2].x, lanes[3].x},
                                             Floats4{lanes[0].y, lanes[1].y, lanes[2].y, lanes[3].y},
                                             Floats4{lanes[0].z, lanes[1].z, lanes[2].z, lanes[3].z},
                                             Floats4{lanes[0].radius, lanes[1].radius,
                                                     lanes[2].radius, lanes[3].radius}));
        for (int k = 0; k < 4; ++k) {
          const StoredSphere& l = lanes[k];
          log.check(((bits >> k) & 1u) == (wide(l.x, l.y, l.z, l.radius) != 0 ? 1u : 0u),
                    "a lane answers as a single test", c,
                    [&] { return format("margin=%.3g lane %d", margin, k); });
        }
      }
    }
#endif
  }
  log.report();
  std::printf("[ wide test ] %llu contacts, %llu of %llu apart kept (%.3g), the furthest %.3g of "
              "the case's scale beyond the margin\n",
              static_cast<unsigned long long>(contacts), static_cast<unsigned long long>(extra),
              static_cast<unsigned long long>(negatives),
              negatives > 0 ? double(extra) / double(negatives) : 0.0, loosest);
  EXPECT_GT(contacts, n / 4);
  // it culls: what it keeps apart lies beyond the margin by no more than a few times its
  // slack (2^-17 of the sizes in the test; most such cases are the boundary family's)
  EXPECT_LT(loosest, 1e-4);
}

}  // namespace
}  // namespace frusta
