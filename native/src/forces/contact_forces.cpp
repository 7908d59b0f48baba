// SPDX-License-Identifier: MIT
#include "forces/contact_forces.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>
#include <tuple>

#include "core/error.h"
#include "core/validate.h"

namespace frusta {

namespace {

const ForceMaterial kDefaultMaterial{};

// a normal further than this from unit length was not made by the solver
constexpr double kUnitTolerance = 1e-6;

frusta_result check_vector(const vec3& v, double limit, const char* format, int32_t index) {
  char field[96];
  std::snprintf(field, sizeof field, format, index);
  return check_bounded(glm::value_ptr(v), 3, limit, field);
}

frusta_result check_rotation(const glm::dmat3& m, const char* format, int32_t index) {
  char field[96];
  std::snprintf(field, sizeof field, format, index);
  return check_finite(glm::value_ptr(m), 9, field);
}

frusta_result check_contact(const SolverContact& c, int32_t i, int32_t object_count) {
  if (c.object < 0 || c.object >= object_count)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "contacts[%d].object is %d, must be in [0, %d)", i,
                c.object, object_count);
  if (c.body < 0 || c.body >= kBodyCount)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "contacts[%d].body is %d, must be in [0, %d]", i, c.body,
                kPalmBody);
  if (c.leaf < -1 || c.part < 0)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE,
                "contacts[%d] has leaf %d and part %d; a leaf is >= -1, a part >= 0", i, c.leaf,
                c.part);
  if (!std::isfinite(c.distance))
    return fail(FRUSTA_ERROR_NOT_FINITE, "contacts[%d].distance is %g", i, c.distance);
  if (frusta_result r = check_vector(c.hand_point, kMaxCoordinate, "contacts[%d].hand_point", i))
    return r;
  if (frusta_result r =
          check_vector(c.object_point, kMaxCoordinate, "contacts[%d].object_point", i))
    return r;
  if (frusta_result r = check_vector(c.normal, 2.0, "contacts[%d].normal", i)) return r;
  const double length = glm::length(c.normal);
  if (std::fabs(length - 1.0) > kUnitTolerance)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "contacts[%d].normal has length %g, must be unit", i,
                length);
  return FRUSTA_OK;
}

frusta_result check_material(const ForceMaterial& m, int32_t i) {
  char field[96];
  for (int k = 0; k < 3; ++k) {
    std::snprintf(field, sizeof field, "materials[%d].normal_stiffness[%d]", i, k);
    if (frusta_result r =
            check_range(m.normal_stiffness[k], 0.0, kMaxContactStiffness, false, field))
      return r;
  }
  std::snprintf(field, sizeof field, "materials[%d].tangential_stiffness", i);
  if (frusta_result r =
          check_range(m.tangential_stiffness, 0.0, kMaxContactStiffness, false, field))
    return r;
  // a friction coefficient above a few is not a material but a typo; 100 leaves room
  std::snprintf(field, sizeof field, "materials[%d].friction", i);
  return check_range(m.friction, 0.0, 100.0, false, field);
}

frusta_result check_objects(const SolverObject* objects, int32_t object_count,
                            const ForceMaterial* materials) {
  for (int32_t o = 0; o < object_count; ++o) {
    if (frusta_result r =
            check_vector(objects[o].pose.position, kMaxCoordinate, "objects[%d].pose.position", o))
      return r;
    if (frusta_result r = check_rotation(objects[o].pose.rotation, "objects[%d].pose.rotation", o))
      return r;
    if (materials)
      if (frusta_result r = check_material(materials[o], o)) return r;
  }
  return FRUSTA_OK;
}

// P_ih: the graphic point in its body's frame on the graphic hand, placed by the same
// body's frame on the haptic hand (frames are rotations: the transpose inverts them)
vec3 same_point_on_haptic(const HandPose& graphic, const HandPose& haptic, int32_t body,
                          const vec3& graphic_point) {
  if (body == kPalmBody) {
    const vec3 local =
        glm::transpose(graphic.palm_rotation) * (graphic_point - graphic.palm_position);
    return haptic.palm_position + haptic.palm_rotation * local;
  }
  const int finger = body / FRUSTA_SEGMENTS_PER_FINGER;
  const int segment = body % FRUSTA_SEGMENTS_PER_FINGER;
  const FingerPose& g = graphic.fingers[finger];
  const vec3 local =
      glm::transpose(g.segment_rotation[segment]) * (graphic_point - g.joint[segment]);
  return segment_point(haptic, finger, segment, local);
}

}  // namespace

void haptic_hand_pose(const HandModel& model, const HandState& haptic, HandPose& pose) {
  HandState aimed = haptic;
  aimed.palm_rotation = glm::normalize(aimed.palm_rotation);
  clamp_to_limits(model, aimed);
  forward_kinematics(model, aimed, pose);
}

frusta_result check_hand_pose(const HandPose& pose, const char* which) {
  char field[96];
  std::snprintf(field, sizeof field, "%s pose palm_position", which);
  if (frusta_result r = check_bounded(glm::value_ptr(pose.palm_position), 3, kMaxCoordinate, field))
    return r;
  std::snprintf(field, sizeof field, "%s pose palm_rotation", which);
  if (frusta_result r = check_finite(glm::value_ptr(pose.palm_rotation), 9, field)) return r;
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    const FingerPose& finger = pose.fingers[f];
    for (size_t j = 0; j < finger.joint.size(); ++j) {
      std::snprintf(field, sizeof field, "%s pose finger %d joint %zu", which, f, j);
      if (frusta_result r =
              check_bounded(glm::value_ptr(finger.joint[j]), 3, kMaxCoordinate, field))
        return r;
    }
    for (size_t s = 0; s < finger.segment_rotation.size(); ++s) {
      std::snprintf(field, sizeof field, "%s pose finger %d segment_rotation %zu", which, f, s);
      if (frusta_result r = check_finite(glm::value_ptr(finger.segment_rotation[s]), 9, field))
        return r;
    }
    std::snprintf(field, sizeof field, "%s pose finger %d axes", which, f);
    if (frusta_result r = check_finite(glm::value_ptr(finger.abduction_axis), 3, field)) return r;
    if (frusta_result r = check_finite(glm::value_ptr(finger.flexion_axis), 3, field)) return r;
  }
  return FRUSTA_OK;
}

ContactForces::ContactForces(int32_t capacity) : capacity_(std::max(capacity, 0)) {
  order_.reserve(static_cast<size_t>(capacity_));
  anchors_.reserve(static_cast<size_t>(capacity_));
  next_anchors_.reserve(static_cast<size_t>(capacity_));
  forces_.reserve(static_cast<size_t>(capacity_));
  prepared_.reserve(static_cast<size_t>(capacity_));
}

bool ContactForces::precedes(const Key& a, const Key& b) {
  return std::tie(a.object, a.body, a.part, a.leaf, a.ordinal) <
         std::tie(b.object, b.body, b.part, b.leaf, b.ordinal);
}

void ContactForces::reset() { anchors_.clear(); }

frusta_result ContactForces::update(const HandPose& graphic, const HandPose& haptic,
                                    const SolverContact* contacts, int32_t contact_count,
                                    const SolverObject* objects, int32_t object_count,
                                    const ForceMaterial* materials, ContactForceStats* stats) {
  // every check before anything changes, so bad input leaves forces and anchors intact
  if (contact_count < 0 || object_count < 0)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "contact_count (%d) and object_count (%d) must be >= 0",
                contact_count, object_count);
  if (contact_count > 0)
    if (frusta_result r = check_pointer(contacts, "contacts")) return r;
  if (object_count > 0)
    if (frusta_result r = check_pointer(objects, "objects")) return r;
  if (frusta_result r = check_hand_pose(graphic, "graphic")) return r;
  if (frusta_result r = check_hand_pose(haptic, "haptic")) return r;
  if (frusta_result r = check_objects(objects, object_count, materials)) return r;
  for (int32_t i = 0; i < contact_count; ++i)
    if (frusta_result r = check_contact(contacts[i], i, object_count)) return r;

  ContactForceStats counts;
  const int32_t used = std::min(contact_count, capacity_);
  counts.dropped = contact_count - used;

  // this step's keys in order, so the last step's anchors are found by one merge walk
  order_.clear();
  for (int32_t i = 0; i < used; ++i) {
    const SolverContact& c = contacts[i];
    order_.push_back({Key{c.object, c.body, c.part, c.leaf, 0}, i});
  }
  std::sort(order_.begin(), order_.end(), [](const Slot& a, const Slot& b) {
    if (precedes(a.key, b.key)) return true;
    if (precedes(b.key, a.key)) return false;
    return a.contact < b.contact;
  });
  for (size_t k = 1; k < order_.size(); ++k) {
    Key& key = order_[k].key;
    const Key& before = order_[k - 1].key;
    if (key.object == before.object && key.body == before.body && key.part == before.part &&
        key.leaf == before.leaf)
      key.ordinal = before.ordinal + 1;
  }

  // P_ih of every contact, and how many press on each (object, body): a body resting on
  // a face made of k leaves meets k contacts with one gap, and must feel one surface, so
  // each of them gets 1/k of the stiffness (keys sort by object then body: groups are runs)
  forces_.resize(static_cast<size_t>(used));
  prepared_.resize(order_.size());  // within the reserved capacity
  for (size_t k = 0; k < order_.size(); ++k) {
    const SolverContact& c = contacts[order_[k].contact];
    Prepared& p = prepared_[k];
    p.haptic_point = same_point_on_haptic(graphic, haptic, c.body, c.hand_point);
    p.pressing = glm::dot(c.hand_point - p.haptic_point, c.normal) > 0.0;
  }
  for (size_t begin = 0, end = 0; begin < order_.size(); begin = end) {
    int32_t pressing = 0;
    for (end = begin; end < order_.size() && order_[end].key.object == order_[begin].key.object &&
                      order_[end].key.body == order_[begin].key.body;
         ++end)
      pressing += prepared_[end].pressing ? 1 : 0;
    for (size_t k = begin; k < end; ++k) prepared_[k].share = pressing > 1 ? 1.0 / pressing : 1.0;
  }

  next_anchors_.clear();
  size_t old = 0;
  for (size_t k = 0; k < order_.size(); ++k) {
    const Slot& slot = order_[k];
    const SolverContact& c = contacts[slot.contact];
    const RigidPose& object = objects[c.object].pose;
    const ForceMaterial& material = materials ? materials[c.object] : kDefaultMaterial;
    const double share = prepared_[k].share;
    const vec3& n = c.normal;

    // normal force, seed eq. 12, with G turned from the object's frame into the world's
    const vec3 haptic_point = prepared_[k].haptic_point;
    const vec3 gap = c.hand_point - haptic_point;
    const bool pressing = prepared_[k].pressing;
    vec3 normal_force(0.0);
    if (pressing) {
      const vec3 stiff_n =
          object.rotation * (material.normal_stiffness * (glm::transpose(object.rotation) * n));
      normal_force = share * stiff_n * glm::length(gap);
    }

    // the anchor the contact left last step, or (a new contact) its haptic point
    while (old < anchors_.size() && precedes(anchors_[old].key, slot.key)) ++old;
    const bool known = old < anchors_.size() && !precedes(slot.key, anchors_[old].key);
    const vec3 anchor =
        known ? object.position + object.rotation * anchors_[old].local : haptic_point;

    // stick: a spring from the anchor to the haptic point, in the tangent plane
    const vec3 stretch = haptic_point - anchor;
    vec3 held = stretch - glm::dot(stretch, n) * n;
    const double limit = material.friction * glm::length(normal_force);
    const double tangential_stiffness = share * material.tangential_stiffness;
    const double spring = tangential_stiffness * glm::length(held);
    bool slipping = false;
    if (spring > limit) {
      // slip: drag the anchor along the stretch until the spring pulls with exactly
      // mu |F|, against the direction the finger slides. The friction is thus the stick
      // spring projected onto the disc of radius mu |F|: a continuous function of the
      // motion, equal on both sides of the switch (scale = 1 there), so there is no
      // jump to chatter between. Reversing the motion unloads the spring smoothly
      // through zero, where seed eq. 13 taken literally (t from the sliding velocity)
      // would flip the full mu |F| every time a noisy velocity crosses zero.
      held *= limit / spring;
      slipping = limit > 0.0;
    }
    const vec3 friction = -tangential_stiffness * held;
    // the anchor keeps the tangential stretch only, so that when the normal turns (a
    // finger rolling over a curved surface) the depth does not leak into the friction
    const vec3 kept = haptic_point - held;
    next_anchors_.push_back({slot.key, glm::transpose(object.rotation) * (kept - object.position)});

    ContactForce& out = forces_[static_cast<size_t>(slot.contact)];
    out.object = c.object;
    out.leaf = c.leaf;
    out.body = c.body;
    out.part = c.part;
    out.graphic_point = c.hand_point;
    out.haptic_point = haptic_point;
    out.normal = n;
    out.normal_force = normal_force;
    out.friction = friction;
    out.slipping = slipping;
    counts.pressing += pressing ? 1 : 0;
    counts.slipping += slipping ? 1 : 0;
  }
  // contacts absent this step are not carried over: their anchors go
  std::swap(anchors_, next_anchors_);
  if (stats) *stats = counts;
  return FRUSTA_OK;
}

}  // namespace frusta
