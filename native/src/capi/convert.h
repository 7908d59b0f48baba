// SPDX-License-Identifier: MIT
// Checked conversions from the C ABI's structs to the engine's types. Each names
// the offending field in the thread's error and leaves *out untouched on failure.
#pragma once

#include <glm/gtc/quaternion.hpp>

#include "frusta/frusta.h"
#include "geometry/types.h"

namespace frusta {

struct Pose {
  vec3 position{0.0};
  glm::dquat rotation{1.0, 0.0, 0.0, 0.0};  // normalised
};

// name prefixes the field names in messages, e.g. "segment" -> "segment.distal[1]"
frusta_result read_segment(const frusta_segment* in, const char* name, Segment* out);
frusta_result read_sphere(const frusta_sphere* in, const char* name, Sphere* out);
// Positions within kMaxCoordinate; the quaternion's norm within [0.5, 2] is normalised.
frusta_result read_pose(const frusta_pose* in, const char* name, Pose* out);

void store(const vec3& v, double out[3]);

}  // namespace frusta
