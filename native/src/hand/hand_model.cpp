// SPDX-License-Identifier: MIT
#include "hand/hand_model.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "core/validate.h"

namespace frusta {

namespace {

constexpr double kPi = 3.14159265358979323846;

frusta_result check_part(double value, const char* field) {
  return check_range(value, kMinHandPart, kMaxHandSize, false, field);
}

// the palm grid's rows and columns (at least 2 each), in double: no int can overflow
double palm_grid(double extent, double radius) { return std::max(2.0, std::ceil(extent / radius)); }

// x-y-z extrinsic rotation: first about x, then y, then z
glm::dmat3 rotation_xyz(const double angles[3]) {
  glm::dmat4 r(1.0);
  r = glm::rotate(r, angles[2], vec3(0, 0, 1));
  r = glm::rotate(r, angles[1], vec3(0, 1, 0));
  r = glm::rotate(r, angles[0], vec3(1, 0, 0));
  return glm::dmat3(r);
}

// Spheres of the palm's thickness on a grid over its rectangle, spaced at most one
// radius apart so their union has no gaps deeper than a seventh of the thickness.
std::vector<Sphere> make_palm_spheres(double length, double breadth, double thickness) {
  const double r = 0.5 * thickness;
  const int along = static_cast<int>(palm_grid(length, r));  // checked by check_hand_def
  const int across = static_cast<int>(palm_grid(breadth, r));
  std::vector<Sphere> spheres;
  spheres.reserve(static_cast<size_t>(along * across));
  for (int i = 0; i < along; ++i) {
    const double x = r + (length - 2.0 * r) * i / (along - 1);
    for (int j = 0; j < across; ++j) {
      const double y = -0.5 * breadth + r + (breadth - 2.0 * r) * j / (across - 1);
      spheres.push_back({vec3(x, y, 0.0), r});
    }
  }
  return spheres;
}

}  // namespace

frusta_result check_hand_def(const HandDef& def) {
  if (def.side != FRUSTA_HAND_RIGHT && def.side != FRUSTA_HAND_LEFT)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "hand_def.side is %d, must be FRUSTA_HAND_RIGHT (0) "
                "or FRUSTA_HAND_LEFT (1)", def.side);
  if (frusta_result r = check_range(def.hand_length, kMinHandSize, kMaxHandSize, false,
                                    "hand_def.hand_length"))
    return r;
  if (frusta_result r = check_range(def.hand_breadth, kMinHandSize, kMaxHandSize, false,
                                    "hand_def.hand_breadth"))
    return r;
  if (frusta_result r = check_part(def.palm_length, "hand_def.palm_length")) return r;
  if (frusta_result r = check_part(def.palm_breadth, "hand_def.palm_breadth")) return r;
  if (frusta_result r = check_part(def.palm_thickness, "hand_def.palm_thickness")) return r;
  const double radius = 0.5 * def.palm_thickness;
  const double spheres =
      palm_grid(def.palm_length, radius) * palm_grid(def.palm_breadth, radius);
  if (spheres > kMaxPalmSpheres)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE,
                "hand_def.palm_thickness is %g m: a %g x %g m palm would take %.0f spheres of that "
                "diameter, at most %d; make it thicker", def.palm_thickness, def.palm_length,
                def.palm_breadth, spheres, kMaxPalmSpheres);
  char field[64];
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s) {
      std::snprintf(field, sizeof field, "hand_def.segment_length[%d][%d]", f, s);
      if (frusta_result r = check_part(def.segment_length[f][s], field)) return r;
    }
    for (int j = 0; j < 4; ++j) {
      std::snprintf(field, sizeof field, "hand_def.joint_radius[%d][%d]", f, j);
      if (frusta_result r = check_part(def.joint_radius[f][j], field)) return r;
    }
    std::snprintf(field, sizeof field, "hand_def.base_position[%d]", f);
    if (frusta_result r = check_bounded(def.base_position[f], 3, kMaxHandSize, field)) return r;
    std::snprintf(field, sizeof field, "hand_def.base_rotation[%d]", f);
    if (frusta_result r = check_bounded(def.base_rotation[f], 3, 2.0 * kPi, field)) return r;
    for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j) {
      std::snprintf(field, sizeof field, "hand_def.joint_min[%d][%d]", f, j);
      if (frusta_result r = check_range(def.joint_min[f][j], -kPi, kPi, false, field)) return r;
      std::snprintf(field, sizeof field, "hand_def.joint_max[%d][%d]", f, j);
      if (frusta_result r = check_range(def.joint_max[f][j], def.joint_min[f][j], kPi, false, field))
        return r;
    }
  }
  return FRUSTA_OK;
}

HandModel make_hand_model(const HandDef& def) {
  HandModel m;
  m.left = def.side == FRUSTA_HAND_LEFT;
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    FingerModel& finger = m.fingers[f];
    std::copy(def.segment_length[f], def.segment_length[f] + 3, finger.length.begin());
    std::copy(def.joint_radius[f], def.joint_radius[f] + 4, finger.radius.begin());
    finger.base_position = vec3(def.base_position[f][0], def.base_position[f][1],
                                def.base_position[f][2]);
    finger.base_rotation = rotation_xyz(def.base_rotation[f]);
    std::copy(def.joint_min[f], def.joint_min[f] + 4, finger.joint_min.begin());
    std::copy(def.joint_max[f], def.joint_max[f] + 4, finger.joint_max.begin());
  }
  m.palm_spheres = make_palm_spheres(def.palm_length, def.palm_breadth, def.palm_thickness);
  if (m.left)
    for (Sphere& s : m.palm_spheres) s.center.y = -s.center.y;
  return m;
}

}  // namespace frusta
