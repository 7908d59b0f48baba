// SPDX-License-Identifier: MIT
#include "runtime/object_contact.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/matrix.hpp>

#include "forces/friction.h"
#include "spheretree/tree_pairs.h"

namespace frusta {

void ContactPatchSums::add(const Sphere& la, const Sphere& lb) {
  const vec3 d = la.center - lb.center;
  const double reach = la.radius + lb.radius;
  const double squared = glm::dot(d, d);
  // apart, as many a walk with a margin and the cache hand over are: no root taken
  if (!(squared < reach * reach)) return;
  const double distance = std::sqrt(squared);
  const double depth = reach - distance;
  if (!(depth > 0.0) || !(distance > 0.0)) return;  // concentric: no direction to push in
  const vec3 n = d * (1.0 / distance);              // from b towards a
  deepest = std::max(deepest, depth);
  weight += depth;
  normal_sum += depth * n;
  point_sum += depth * (lb.center + (lb.radius - 0.5 * depth) * n);
}

bool add_object_contact(const ContactSide& a, const ContactSide& b, double dt, PatchStick* stick,
                        ObjectWrench* on_a, ObjectWrench* on_b) {
  ContactPatchSums patch;
  walk_overlapping_leaves(*a.tree, *b.tree, relative_pose(a.def->pose, b.def->pose),
                          [&](int32_t, int32_t, const Sphere& la, const Sphere& lb) { patch.add(la, lb); });
  return add_patch_wrench(patch, a, b, dt, stick, on_a, on_b);
}

bool add_patch_wrench(const ContactPatchSums& patch, const ContactSide& a, const ContactSide& b,
                      double dt, PatchStick* stick, ObjectWrench* on_a, ObjectWrench* on_b) {
  assert(a.mass > 0.0 || b.mass > 0.0);
  const RigidPose& pa = a.def->pose;
  const RigidPose& pb = b.def->pose;
  const double turn = glm::length(patch.normal_sum);
  if (!(patch.weight > 0.0) || !(turn > 0.0)) {
    *stick = PatchStick{};
    return false;
  }
  const double deepest = patch.deepest;
  const vec3 n = pa.rotation * (patch.normal_sum / turn);
  const vec3 point = pa.position + pa.rotation * (patch.point_sum / patch.weight);

  // the pair's relative velocity at the patch (a's over b's)
  auto velocity_at = [&](const ObjectDef& o) {
    return o.linear_velocity + glm::cross(o.angular_velocity, point - o.pose.position);
  };
  const vec3 slide = velocity_at(*a.def) - velocity_at(*b.def);
  // a side's inverse inertia about a world axis (its moments are in its own frame)
  auto turns = [](const ContactSide& side, const vec3& axis) {
    const vec3 body = glm::transpose(side.def->pose.rotation) * axis;
    return glm::dot(body, body / side.def->inertia);
  };
  // how readily the pair gives at the patch along a direction: the effective mass's
  // inverse, turning included (a box pushed at its corner turns as much as it moves)
  auto give = [&](const vec3& direction) {
    double sum = 0.0;
    for (const ContactSide* side : {&a, &b})
      if (side->mass > 0.0)
        sum += 1.0 / side->mass + turns(*side, glm::cross(point - side->def->pose.position, direction));
    return sum;
  };
  const double omega = std::min(2.0 * glm::pi<double>() * kObjectContactHz, 0.25 / dt);
  const double along = 1.0 / give(n);
  const double push =
      std::max(0.0, along * omega * (omega * deepest - 2.0 * glm::dot(slide, n)));
  vec3 force = push * n;
  // friction: the stick spring, stretched by this step's slide, in the patch's plane
  // (it turns with a, and a turned patch leaves the part along its new normal behind)
  const vec3 tangential = slide - glm::dot(slide, n) * n;
  vec3 stretch = pa.rotation * stick->stretch + dt * tangential;
  stretch -= glm::dot(stretch, n) * n;
  vec3 friction(0.0);
  double spring = 0.0;  // the spring's pull alone
  const double stretched = glm::length(stretch), speed = glm::length(tangential);
  if (stretched > 0.0) {
    const double stiffness = omega * omega / give(stretch / stretched);
    friction -= stiffness * stretch;
    spring = stiffness * stretched;
  }
  if (speed > 0.0) friction -= 2.0 * omega / give(tangential / speed) * tangential;
  slip_at_limit(std::sqrt(a.def->material.friction * b.def->material.friction) * push, spring,
                &friction, &stretch);
  stick->stretch = glm::transpose(pa.rotation) * stretch;
  force += friction;
  // rolling and spinning meet a little resistance too, or a ball dropped on a bumpy tree
  // would roll on for ever: a torque against the pair's relative turn, at most
  // kRollingLength x the push, damped like the rest
  vec3 torque(0.0);
  const vec3 turn_rate = a.def->angular_velocity - b.def->angular_velocity;
  const double rate = glm::length(turn_rate);
  if (rate > 0.0) {
    const vec3 u = turn_rate / rate;
    double turn_give = 0.0;
    for (const ContactSide* side : {&a, &b})
      if (side->mass > 0.0) turn_give += turns(*side, u);
    torque = -std::min(kRollingLength * push, 2.0 * omega * rate / turn_give) * u;
  }
  on_a->force += force;
  on_a->torque += glm::cross(point - pa.position, force) + torque;
  on_b->force -= force;
  on_b->torque += glm::cross(point - pb.position, -force) - torque;
  return true;
}

}  // namespace frusta
