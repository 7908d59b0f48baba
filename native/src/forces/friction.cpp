// SPDX-License-Identifier: MIT
#include "forces/friction.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace frusta {

bool slip_at_limit(double limit, double spring, vec3* force, vec3* held) {
  const double pull = glm::length(*force);
  if (!(pull > limit)) return false;
  *force *= limit / pull;
  if (spring > limit) *held *= limit / spring;
  return limit > 0.0;
}

PatchFriction patch_friction(const ForceMaterial& material, const RigidPose& object,
                             const RigidPose& body, const vec3& normal, const vec3& reference,
                             const vec3& normal_force, const FrictionAnchor* before,
                             double time_step) {
  // the spring is stretched by how far the body's material has moved over the object,
  // in the plane of the patch's mean normal. The motion is that of the body's frame, not
  // of the contacts' mean point, so leaves joining or leaving the patch move nothing
  const glm::dmat3 to_object = glm::transpose(object.rotation);
  const RigidPose body_on_object = relative_pose(object, body);
  vec3 stretch(0.0), before_held(0.0);
  if (before) {
    const vec3 local = glm::transpose(body.rotation) * (reference - body.position);
    const vec3 now = body_on_object.position + body_on_object.rotation * local;
    const vec3 then = before->body.position + before->body.rotation * local;
    stretch = object.rotation * (before->stretch + now - then);
    before_held = object.rotation * before->stretch;
    before_held -= glm::dot(before_held, normal) * normal;
  }
  vec3 held = stretch - glm::dot(stretch, normal) * normal;
  // the spring, and the damping on how fast it stretched this step
  const vec3 slide_rate = (held - before_held) / time_step;
  PatchFriction out;
  out.force = -material.tangential_stiffness * held - material.tangential_damping * slide_rate;
  // (seed eq. 13 taken literally, t from the sliding velocity, would flip the full
  // mu |F| every time a noisy velocity crosses zero)
  out.slipping = slip_at_limit(material.friction * glm::length(normal_force),
                               material.tangential_stiffness * glm::length(held), &out.force,
                               &held);
  // the stretch kept is tangential only, so that when the normal turns (a finger rolling
  // over a curved surface) the depth does not leak into the friction
  out.anchor = {body_on_object, to_object * held};
  return out;
}

}  // namespace frusta
