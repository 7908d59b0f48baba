// SPDX-License-Identifier: MIT
#include "forces/contact_forces.h"

#include <algorithm>
#include <cassert>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <tuple>

#include "core/validate.h"

namespace frusta {

namespace {

const ForceMaterial kDefaultMaterial{};

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

// the frame a body's points are given in: the palm's, or a segment's at its proximal joint
RigidPose haptic_body_frame(const HandPose& haptic, int32_t body) {
  if (body == kPalmBody) return {haptic.palm_position, haptic.palm_rotation};
  const FingerPose& f = haptic.fingers[body / FRUSTA_SEGMENTS_PER_FINGER];
  const int segment = body % FRUSTA_SEGMENTS_PER_FINGER;
  return {f.joint[segment], f.segment_rotation[segment]};
}

}  // namespace

ContactForces::ContactForces(int32_t capacity) : capacity_(std::max(capacity, 0)) {
  order_.reserve(static_cast<size_t>(capacity_));
  prepared_.reserve(static_cast<size_t>(capacity_));
  patches_.reserve(static_cast<size_t>(capacity_));
  next_patches_.reserve(static_cast<size_t>(capacity_));
  forces_.reserve(static_cast<size_t>(capacity_));
}

bool ContactForces::precedes(const PatchKey& a, const PatchKey& b) {
  return std::tie(a.object, a.body) < std::tie(b.object, b.body);
}

void ContactForces::reset() { patches_.clear(); }

frusta_result ContactForces::set_time_step(double seconds) {
  if (frusta_result r = check_range(seconds, 0.0, 1.0, true, "time step")) return r;
  time_step_ = seconds;
  return FRUSTA_OK;
}

void ContactForces::update(const HandPose& graphic, const HandPose& haptic,
                           const SolverContact* contacts, int32_t contact_count,
                           const SolverObject* objects,
                           [[maybe_unused]] int32_t object_count,  // in the asserts only
                           const ForceMaterial* materials, ContactForceStats* stats) {
  assert(contact_count >= 0 && object_count >= 0);
  assert(check_hand_pose(graphic, "graphic") == FRUSTA_OK);
  assert(check_hand_pose(haptic, "haptic") == FRUSTA_OK);
  assert(check_force_objects(objects, object_count, materials) == FRUSTA_OK);
  assert(check_solver_contacts(contacts, contact_count, object_count) == FRUSTA_OK);

  ContactForceStats counts;
  const int32_t used = std::min(contact_count, capacity_);
  counts.dropped = contact_count - used;

  // this step's contacts grouped into patches (one object, one body), patches in key
  // order so the last step's are found by one merge walk
  order_.clear();
  for (int32_t i = 0; i < used; ++i) order_.push_back(i);
  std::sort(order_.begin(), order_.end(), [&](int32_t a, int32_t b) {
    const PatchKey ka{contacts[a].object, contacts[a].body}, kb{contacts[b].object, contacts[b].body};
    if (precedes(ka, kb)) return true;
    if (precedes(kb, ka)) return false;
    return a < b;
  });
  prepared_.resize(order_.size());  // within the reserved capacity
  for (size_t k = 0; k < order_.size(); ++k) {
    const SolverContact& c = contacts[order_[k]];
    Prepared& p = prepared_[k];
    p.haptic_point = same_point_on_haptic(graphic, haptic, c.body, c.hand_point);
    p.depth = glm::dot(c.hand_point - p.haptic_point, c.normal);
  }

  forces_.resize(static_cast<size_t>(used));
  next_patches_.clear();
  size_t old = 0;
  for (size_t begin = 0, end = 0; begin < order_.size(); begin = end) {
    const SolverContact& first = contacts[order_[begin]];
    const PatchKey key{first.object, first.body};
    // the patch's pressing contacts: how many, where on average, which way, how deep
    int32_t pressing = 0;
    vec3 haptic_sum(0.0), normal_sum(0.0);
    double depth_sum = 0.0;
    for (end = begin; end < order_.size(); ++end) {
      const SolverContact& c = contacts[order_[end]];
      if (c.object != key.object || c.body != key.body) break;
      if (prepared_[end].depth <= 0.0) continue;
      ++pressing;
      haptic_sum += prepared_[end].haptic_point;
      normal_sum += c.normal;
      depth_sum += prepared_[end].depth;
    }
    const RigidPose& object = objects[key.object].pose;
    const ForceMaterial& material = materials ? materials[key.object] : kDefaultMaterial;
    while (old < patches_.size() && precedes(patches_[old].key, key)) ++old;
    const bool known = old < patches_.size() && !precedes(key, patches_[old].key);

    // normal forces, seed eq. 12, each contact with 1/k of the patch's stiffness (G turned
    // from the object's frame into the world's), plus the patch's damping on how fast it
    // sinks in, never pulling
    const double share = pressing > 0 ? 1.0 / pressing : 1.0;
    const double depth = pressing > 0 ? depth_sum * share : 0.0;
    const double sink_rate = known && pressing > 0 ? (depth - patches_[old].depth) / time_step_ : 0.0;
    vec3 patch_force(0.0);
    for (size_t k = begin; k < end; ++k) {
      const SolverContact& c = contacts[order_[k]];
      const Prepared& p = prepared_[k];
      ContactForce& out = forces_[static_cast<size_t>(order_[k])];
      out.object = c.object;
      out.leaf = c.leaf;
      out.body = c.body;
      out.part = c.part;
      out.graphic_point = c.hand_point;
      out.haptic_point = p.haptic_point;
      out.normal = c.normal;
      out.normal_force = vec3(0.0);
      out.friction = vec3(0.0);
      out.slipping = false;
      if (p.depth <= 0.0) continue;
      const vec3& n = c.normal;
      const vec3 stiff_n =
          object.rotation * (material.normal_stiffness * (glm::transpose(object.rotation) * n));
      vec3 f = share * (stiff_n * glm::length(c.hand_point - p.haptic_point) +
                        material.normal_damping * sink_rate * n);
      if (glm::dot(f, n) < 0.0) f = vec3(0.0);
      out.normal_force = f;
      patch_force += f;
    }
    counts.pressing += pressing;
    if (pressing == 0) continue;  // nothing pressed, nothing held: the patch starts afresh

    // friction, seed eq. 13 made continuous, once per patch: a spring stretched by how
    // far the body's material (on the haptic hand) has moved over the object, in the
    // plane of the patch's mean normal. The motion is that of the body's frame, not of
    // the contacts' mean point, so leaves joining or leaving the patch move nothing
    const vec3 n = glm::normalize(normal_sum);
    const RigidPose body = haptic_body_frame(haptic, key.body);
    const glm::dmat3 to_object = glm::transpose(object.rotation);
    const RigidPose body_on_object{to_object * (body.position - object.position),
                                   to_object * body.rotation};
    vec3 stretch(0.0), before_held(0.0);
    if (known) {
      const Patch& before = patches_[old];
      const vec3 reference = haptic_sum * share;  // any material point of the body would do
      const vec3 local = glm::transpose(body.rotation) * (reference - body.position);
      const vec3 now = body_on_object.position + body_on_object.rotation * local;
      const vec3 then = before.body.position + before.body.rotation * local;
      stretch = object.rotation * (before.stretch + now - then);
      before_held = object.rotation * before.stretch;
      before_held -= glm::dot(before_held, n) * n;
    }
    vec3 held = stretch - glm::dot(stretch, n) * n;
    // the spring, and the damping on how fast it stretched this step
    const vec3 slide_rate = (held - before_held) / time_step_;
    vec3 friction = -material.tangential_stiffness * held - material.tangential_damping * slide_rate;
    const double limit = material.friction * glm::length(patch_force);
    const double pull = glm::length(friction);
    bool slipping = false;
    if (pull > limit) {
      // slip: the friction is projected onto the disc of radius mu |F|, against the
      // direction the finger slides, and the stretch cut back to match. A continuous
      // function of the motion, equal on both sides of the switch (scale = 1 there),
      // so there is no jump to chatter between. Reversing the motion unloads the
      // spring smoothly through zero, where seed eq. 13 taken literally (t from the
      // sliding velocity) would flip the full mu |F| every time a noisy velocity
      // crosses zero.
      friction *= limit / pull;
      const double spring = material.tangential_stiffness * glm::length(held);
      if (spring > limit) held *= limit / spring;
      slipping = limit > 0.0;
    }
    // the stretch kept is tangential only, so that when the normal turns (a finger
    // rolling over a curved surface) the depth does not leak into the friction
    next_patches_.push_back({key, body_on_object, to_object * held, depth});
    for (size_t k = begin; k < end; ++k) {
      if (prepared_[k].depth <= 0.0) continue;
      ContactForce& out = forces_[static_cast<size_t>(order_[k])];
      out.friction = share * friction;
      out.slipping = slipping;
      counts.slipping += slipping ? 1 : 0;
    }
  }
  // patches absent this step are not carried over: their stretch goes
  std::swap(patches_, next_patches_);
  if (stats) *stats = counts;
}

}  // namespace frusta
