// SPDX-License-Identifier: MIT
#include "runtime/object_dynamics.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/quaternion.hpp>
#include <glm/matrix.hpp>

#include "core/validate.h"

namespace frusta {

namespace {

vec3 clamp_length(const vec3& v, double limit) {
  // scaled by the largest component first: a length past 1e154 squares to infinity,
  // and limit / infinity would zero a finite vector (or turn an infinite one into NaN)
  const double largest = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  if (!(largest > limit / 2.0)) return v;  // also 0 and NaN, which stay as they are
  const vec3 unit = v / largest;
  const double length = largest * glm::length(unit);
  return length > limit ? unit * (limit / glm::length(unit)) : v;
}

}  // namespace

void advance_object(ObjectDef& o, const ObjectWrench& reaction, const vec3& gravity, double dt) {
  // semi-implicit Euler: velocities first, then the pose with the new velocities,
  // stable for the contact springs at the world's rate (stiffness / mass << rate^2)
  const vec3 force = reaction.force + o.mass * gravity;
  o.linear_velocity += dt / o.mass * force;
  // Euler's equations in the body frame, where the inertia is the diagonal it was
  // given: the world-frame tensor of moments 1e-13 and 1e4 turned off the axes is
  // singular in doubles, and its inverse turned the spin into NaN
  const glm::dmat3& r = o.pose.rotation;
  const vec3 body_spin = glm::transpose(r) * o.angular_velocity;
  const vec3 body_torque =
      glm::transpose(r) * reaction.torque - glm::cross(body_spin, o.inertia * body_spin);
  o.angular_velocity += dt * (r * (body_torque / o.inertia));
  o.linear_velocity = clamp_length(o.linear_velocity * std::max(0.0, 1.0 - o.linear_damping * dt),
                                   kMaxLinearSpeed);
  o.angular_velocity = clamp_length(
      o.angular_velocity * std::max(0.0, 1.0 - o.angular_damping * dt), kMaxAngularSpeed);

  vec3 position = o.pose.position + dt * o.linear_velocity;
  if (glm::any(glm::greaterThan(glm::abs(position), vec3(kMaxCoordinate)))) {
    // the world's edge: an object dropped with nothing below stops there
    position = glm::clamp(position, vec3(-kMaxCoordinate), vec3(kMaxCoordinate));
    o.linear_velocity = vec3(0.0);
  }
  o.pose.position = position;
  const glm::dquat q = glm::quat_cast(r);
  const glm::dquat turn(0.0, o.angular_velocity * (0.5 * dt));
  o.pose.rotation = glm::mat3_cast(glm::normalize(q + turn * q));
}

}  // namespace frusta
