// SPDX-License-Identifier: MIT
#include "forces/contact_patches.h"

#include <algorithm>
#include <cassert>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "solver/detection.h"

namespace frusta {

// The point in its body's frame on `from`, placed by the same body's frame on `to`
// (frames are rotations: the transpose inverts them)
vec3 same_material_point(const HandPose& from, const HandPose& to, int32_t body, const vec3& point) {
  if (body == kPalmBody) {
    const vec3 local = glm::transpose(from.palm_rotation) * (point - from.palm_position);
    return to.palm_position + to.palm_rotation * local;
  }
  const int finger = body / FRUSTA_SEGMENTS_PER_FINGER;
  const int segment = body % FRUSTA_SEGMENTS_PER_FINGER;
  const FingerPose& g = from.fingers[finger];
  const vec3 local = glm::transpose(g.segment_rotation[segment]) * (point - g.joint[segment]);
  return segment_point(to, finger, segment, local);
}

namespace {

// How near a contact is: 1 touching (or a hair inside), 0 at `fade` and beyond,
// straight in between.
double nearness(double distance, double fade) {
  return !(distance > 0.0) ? 1.0 : distance < fade ? 1.0 - distance / fade : 0.0;
}

// How a contact presses, from its depth (P_ig - P_ih) . n: 0 not pressing, 1 from `ramp`
// on, straight in between.
double pressing(double depth, double ramp) {
  return !(depth > 0.0) ? 0.0 : depth < ramp ? depth / ramp : 1.0;
}

}  // namespace

ContactPatches::ContactPatches(int32_t capacity, double contact_distance)
    : contact_distance_(contact_distance) {
  const size_t n = static_cast<size_t>(std::max(capacity, 0));
  order_.reserve(n);
  contacts_.reserve(n);
  patches_.reserve(n);
}

void ContactPatches::group(const HandPose& graphic, const HandPose& haptic,
                           const SolverContact* contacts, int32_t count) {
  assert(count >= 0 && static_cast<size_t>(count) <= order_.capacity());
  // patches in key order, so that a table of the last step's is found by one merge walk
  order_.clear();
  for (int32_t i = 0; i < count; ++i) order_.push_back(i);
  std::sort(order_.begin(), order_.end(), [&](int32_t a, int32_t b) {
    const PatchKey ka{contacts[a].object, contacts[a].body},
        kb{contacts[b].object, contacts[b].body};
    if (precedes(ka, kb)) return true;
    if (precedes(kb, ka)) return false;
    return a < b;
  });
  contacts_.resize(order_.size());  // within the reserved capacity
  for (size_t k = 0; k < order_.size(); ++k) {
    const SolverContact& c = contacts[order_[k]];
    PatchContact& p = contacts_[k];
    p.index = order_[k];
    p.haptic_point = same_material_point(graphic, haptic, c.body, c.hand_point);  // P_ih
    p.press = pressing(glm::dot(c.hand_point - p.haptic_point, c.normal), 0.5 * contact_distance_);
    p.weight = nearness(c.distance, contact_distance_) * p.press;
  }

  patches_.clear();
  for (int32_t begin = 0, end = 0; begin < count; begin = end) {
    const SolverContact& first = contacts[order_[static_cast<size_t>(begin)]];
    ContactPatch patch;
    patch.key = {first.object, first.body};
    for (end = begin; end < count; ++end) {
      const PatchContact& p = contacts_[static_cast<size_t>(end)];
      const SolverContact& c = contacts[p.index];
      if (c.object != patch.key.object || c.body != patch.key.body) break;
      patch.weight_sum += p.weight;
      if (p.weight > 0.0) patch.press_sum += p.press;
      patch.gap_sum += p.weight * (c.hand_point - p.haptic_point);
      patch.normal_sum += p.weight * c.normal;
      patch.haptic_sum += p.weight * p.haptic_point;
    }
    patch.begin = begin;
    patch.end = end;
    patches_.push_back(patch);
  }
}

}  // namespace frusta
