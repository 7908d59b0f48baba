// SPDX-License-Identifier: MIT
#include "geometry/patent_test.h"

#include <glm/geometric.hpp>

namespace frusta {

double axial_fraction(const SegmentFrame& frame, const vec3& point) {
  if (frame.degenerate) return 0.0;
  return glm::dot(point - frame.distal, frame.axis) / frame.length;
}

bool patent_contact(const SegmentFrame& frame, const Sphere& sphere) {
  if (frame.degenerate) return false;
  const AxialSplit s = split_axial(frame, sphere.center);
  const double k = s.axial / frame.length;
  const double reach = sphere.radius / frame.length;
  if (k < -reach || k > 1.0 + reach) return false;
  const double threshold =
      sphere.radius / frame.cos_alpha + k * (frame.r_proximal - frame.r_distal) + frame.r_distal;
  return s.radial_length * s.radial_length <= threshold * threshold;
}

}  // namespace frusta
