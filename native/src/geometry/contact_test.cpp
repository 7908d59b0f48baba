// SPDX-License-Identifier: MIT
#include "geometry/contact_test.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace frusta {

bool may_touch_sphere(const Sphere& a, const Sphere& b, double margin) {
  const double scale = glm::length(a.center - b.center) + a.radius + b.radius + margin;
  return contact_detail::within_ball(a.center, a.radius, b.center,
                                     b.radius + margin + contact_detail::kRelativeSlack * scale);
}

}  // namespace frusta
