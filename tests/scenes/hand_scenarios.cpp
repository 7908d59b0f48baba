// SPDX-License-Identifier: MIT
#include "scenes/hand_scenarios.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/gtx/quaternion.hpp>

#include "core/error.h"
#include "geometry/exact_distance.h"
#include "hand/anthropometry.h"
#include "hand/hand_model.h"
#include "meshes/meshes.h"
#include "spheretree/tree_builder.h"

namespace frusta::scenes {

std::shared_ptr<const TreeFile> ball_shell(int32_t leaves, double radius) {
  // spacing of N points over the sphere; a leaf of radius 0.75 spacing overlaps its
  // neighbours, and sits a radius deep so the union's outside touches the ball's
  const double spacing = std::sqrt(4.0 * 3.14159265358979323846 * radius * radius / leaves);
  const double r = std::min(0.75 * spacing, 0.5 * radius);
  const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
  std::vector<Sphere> spheres(static_cast<size_t>(leaves));
  for (int32_t i = 0; i < leaves; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / leaves;
    const double ring = std::sqrt(1.0 - z * z), phi = golden * i;
    spheres[static_cast<size_t>(i)] = {(radius - r) * vec3(ring * std::cos(phi), ring * std::sin(phi), z), r};
  }
  auto file = std::make_shared<TreeFile>();
  if (build_sphere_tree(spheres, {8}, &file->tree) != FRUSTA_OK)
    throw std::runtime_error(std::string("building a ball shell: ") + frusta::last_error_message());
  return file;
}

glm::dquat about(const vec3& axis, double angle) { return glm::angleAxis(angle, glm::normalize(axis)); }

HandState open_hand(const vec3& palm, const glm::dquat& rotation) {
  HandState s;
  s.palm_position = palm;
  s.palm_rotation = rotation;
  return s;
}

HandState mix(const HandState& a, const HandState& b, double t) {
  return interpolate(a, b, std::clamp(t, 0.0, 1.0));
}

void set_flexion(HandState& s, int finger, double f1, double f2, double f3) {
  s.angles[finger * 4 + 1] = f1;
  s.angles[finger * 4 + 2] = f2;
  s.angles[finger * 4 + 3] = f3;
}

void HandScenario::add(std::shared_ptr<const TreeFile> tree, const RigidPose& pose) {
  objects.push_back({&tree->tree, pose});
  trees.push_back(std::move(tree));
}

std::vector<std::string> hand_scenario_names() {
  return {"box_press",  "ball_grasp",     "slide",        "plate_pinch",
          "bowl_press", "plate_teleport", "start_inside", "palm_then_fingers"};
}

namespace {

RigidPose at(const vec3& position) { return {position, glm::dmat3(1.0)}; }

// an index fingertip pressed into the top face of a box (z = -25 mm)
HandScenario box_press() {
  HandScenario s;
  s.add(sample_tree("box"), at(vec3(0.175, 0.034, -0.045)));
  HandState pressed = open_hand();
  set_flexion(pressed, 1, 0.9, 0.9, 0.6);  // the index would end 3 cm inside the box
  s.steps = 200;
  s.haptic = [pressed](int32_t t) { return mix(open_hand(), pressed, t / 150.0); };
  s.held = pressed;
  return s;
}

// the index pressed into a box, then the palm slides 3 cm along it
HandScenario slide() {
  HandScenario s;
  s.add(sample_tree("box"), at(vec3(0.175, 0.034, -0.045)));
  HandState pressed = open_hand();
  set_flexion(pressed, 1, 0.6, 0.6, 0.4);
  HandState slid = pressed;
  slid.palm_position = vec3(0.03, 0.0, 0.0);
  s.steps = 400;
  s.haptic = [pressed, slid](int32_t t) {
    return t < 100 ? mix(open_hand(), pressed, t / 80.0) : mix(pressed, slid, (t - 100) / 250.0);
  };
  s.held = slid;
  return s;
}

// each pad pushed along a direction: the joint motion that moves its tip centre a
// distance that way, to first order (Jacobian transpose)
HandState pad_pushed(const HandPose& pose, const HandState& from, int finger,
                     const vec3& direction, double distance) {
  double j[3 * kJacobianColumns];
  point_jacobian(pose, finger, 2, pose.fingers[finger].joint[3], j);
  double step[4], tip[3] = {};
  for (int c = 0; c < 4; ++c)
    step[c] = j[c] * direction.x + j[kJacobianColumns + c] * direction.y + j[2 * kJacobianColumns + c] * direction.z;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) tip[r] += j[r * kJacobianColumns + c] * step[c];
  const double scale = distance / std::sqrt(tip[0] * tip[0] + tip[1] * tip[1] + tip[2] * tip[2]);
  HandState out = from;
  for (int c = 0; c < 4; ++c) out.angles[finger * 4 + c] += scale * step[c];
  return out;
}

}  // namespace

// the pinch pose the pinch scenarios start from: thumb and index pads 4 mm apart
HandState pads_together() {
  HandState pinch = open_hand();
  const double angles[8] = {-0.1, 0.4, 0.4, 0.3, 0.0, 0.4, 1.1, 0.3};  // found by search
  std::copy(angles, angles + 8, pinch.angles.begin());
  return pinch;
}

HandScenario ball_pinch(double pressed) {
  const HandModel model = make_hand_model(default_hand_def());
  HandPose pose;
  forward_kinematics(model, pads_together(), pose);
  vec3 axis = glm::normalize(pose.fingers[1].joint[3] - pose.fingers[0].joint[3]);
  // the pads opened to about 3 cm, a ball fitted between them with 0.5 mm to spare
  const HandState opened = pad_pushed(pose, pad_pushed(pose, pads_together(), 0, -axis, 0.013), 1,
                                      axis, 0.013);
  forward_kinematics(model, opened, pose);
  const vec3 thumb = pose.fingers[0].joint[3], index = pose.fingers[1].joint[3];
  axis = glm::normalize(index - thumb);
  const double gap = glm::length(index - thumb) - model.fingers[0].radius[3] - model.fingers[1].radius[3];
  HandScenario s;
  s.axis = axis;
  s.anchor = thumb + axis * (model.fingers[0].radius[3] + gap / 2);
  s.add(ball_shell(800, kMarbleRadius), {s.anchor, glm::dmat3(1.0)});
  // each pad pushed to the marble's surface, then `pressed` into it
  const double push = gap / 2 - kMarbleRadius + pressed;
  const HandState held = pad_pushed(pose, pad_pushed(pose, opened, 0, axis, push), 1, -axis, push);
  s.steps = 300;
  s.haptic = [opened, held](int32_t t) {
    return t < 120 ? mix(open_hand(), opened, t / 100.0) : mix(opened, held, (t - 120) / 120.0);
  };
  s.held = held;
  return s;
}

HandScenario plate_pinch(double pressed) {
  HandScenario s;
  const HandState pinch = pads_together();
  const HandModel model = make_hand_model(default_hand_def());
  HandPose pose;
  forward_kinematics(model, pinch, pose);
  const vec3 thumb = pose.fingers[0].joint[3], index = pose.fingers[1].joint[3];
  s.axis = glm::normalize(index - thumb);
  s.anchor = thumb + s.axis * (model.fingers[0].radius[3] + 0.002);
  s.add(test_box("pinch_plate"), {s.anchor, glm::mat3_cast(glm::rotation(vec3(0, 0, 1), s.axis))});
  const HandState before = pad_pushed(pose, pad_pushed(pose, pinch, 0, -s.axis, 0.008), 1, s.axis, 0.008);
  const HandState held = pad_pushed(pose, pad_pushed(pose, pinch, 0, s.axis, pressed), 1, -s.axis, pressed);
  s.steps = 300;
  s.haptic = [before, held](int32_t t) {
    return t < 120 ? mix(open_hand(), before, t / 100.0) : mix(before, held, (t - 120) / 120.0);
  };
  s.held = held;
  return s;
}

namespace {

// the hand lowered into a bowl with its fingers curling
HandScenario bowl_press() {
  HandScenario s;
  s.add(sample_tree("bowl"), at(vec3(0.13, 0.0, -0.01)));
  const HandState above = open_hand(vec3(0.0, 0.0, 0.06));
  HandState pressed = open_hand(vec3(0.0, 0.0, -0.02));
  for (int f = 1; f < 5; ++f) set_flexion(pressed, f, 0.5, 0.6, 0.4);
  s.steps = 300;
  s.haptic = [above, pressed](int32_t t) { return mix(above, pressed, t / 250.0); };
  s.held = pressed;
  return s;
}

// the haptic hand jumps 5 cm, through a 4 mm plate (top at z = -25 mm), in one step
HandScenario plate_teleport() {
  HandScenario s;
  s.add(sample_tree("plate"), at(vec3(0.10, 0.0, -0.027)));
  s.anchor = vec3(0.10, 0.0, -0.025);
  s.axis = vec3(0.0, 0.0, 1.0);
  const HandState below = open_hand(vec3(0.0, 0.0, -0.05));  // wholly under the plate
  s.steps = 300;
  s.haptic = [below](int32_t t) { return t < 10 ? open_hand() : below; };
  s.held = below;
  return s;
}

// a haptic hand that starts inside a box larger than itself (coarse: the interior fill
// is what matters) and stays there
HandScenario start_inside() {
  HandScenario s;
  s.add(test_box("room_box"), at(vec3(0.08, 0.0, 0.0)));
  HandState inside = open_hand();
  set_flexion(inside, 2, 0.3, 0.3, 0.3);
  s.steps = 200;
  s.haptic = [inside](int32_t) { return inside; };
  s.held = inside;
  return s;
}

// the palm pressed flat onto a box, then every finger closing. The box sits off to the
// little finger's side: the thumb's metacarpal hangs below the palm's plane and would
// otherwise carry the hand.
HandScenario palm_then_fingers() {
  HandScenario s;
  s.add(sample_tree("box"), at(vec3(0.05, -0.02, -0.0359)));  // top face 1 mm under the palm
  const HandState pressed = open_hand(vec3(0.0, 0.0, -0.01));
  HandState closed = pressed;
  for (int f = 0; f < 5; ++f) set_flexion(closed, f, 1.6, 1.6, 1.6);
  s.steps = 400;
  s.haptic = [pressed, closed](int32_t t) {
    return t < 100 ? mix(open_hand(), pressed, t / 80.0) : mix(pressed, closed, (t - 100) / 250.0);
  };
  s.held = closed;
  return s;
}

}  // namespace

HandScenario ball_grasp(std::shared_ptr<const TreeFile> ball) {
  HandScenario s;
  s.add(std::move(ball), at(vec3(0.10, 0.0, -0.058)));  // 4 cm radius, 3 mm under the palm
  HandState closed = open_hand();
  for (int f = 0; f < 5; ++f) set_flexion(closed, f, 1.6, 1.6, 1.6);
  s.steps = 300;
  s.haptic = [closed](int32_t t) { return mix(open_hand(), closed, t / 250.0); };
  s.held = closed;
  return s;
}

HandScenario make_hand_scenario(const std::string& name) {
  HandScenario s;
  if (name == "box_press") s = box_press();
  else if (name == "ball_grasp") s = ball_grasp(sample_tree("ball"));
  else if (name == "slide") s = slide();
  else if (name == "plate_pinch") s = plate_pinch(0.01);  // pads pushed 1 cm through
  else if (name == "bowl_press") s = bowl_press();
  else if (name == "plate_teleport") s = plate_teleport();
  else if (name == "start_inside") s = start_inside();
  else if (name == "palm_then_fingers") s = palm_then_fingers();
  else throw std::invalid_argument("no hand scenario named " + name);
  s.name = name;
  return s;
}

double deepest_penetration(const HandModel& model, const HandPose& pose,
                           const std::vector<SolverObject>& objects) {
  const HandReach reach = hand_reach(model);
  SegmentFrame frames[FRUSTA_HAND_SEGMENT_COUNT];
  Sphere bounds[FRUSTA_HAND_SEGMENT_COUNT];  // each segment solid lies inside its bound
  for (int b = 0; b < FRUSTA_HAND_SEGMENT_COUNT; ++b) {
    const Segment seg = finger_segment(model, pose, b / 3, b % 3);
    frames[b] = make_segment_frame(seg);
    bounds[b] = {0.5 * (seg.proximal + seg.distal),
                 0.5 * glm::length(seg.proximal - seg.distal) + std::max(seg.proximal_radius, seg.distal_radius)};
  }
  std::vector<Sphere> palm;
  for (int k = 0; k < static_cast<int>(model.palm_spheres.size()); ++k) palm.push_back(palm_sphere(model, pose, k));
  double deepest = 0.0;
  for (const SolverObject& object : objects) {
    for (const Sphere& local : object.tree->leaves) {
      const Sphere leaf{object.pose.rotation * local.center + object.pose.position, local.radius};
      if (glm::length(leaf.center - pose.palm_position) > reach.hand + leaf.radius) continue;
      for (int b = 0; b < FRUSTA_HAND_SEGMENT_COUNT; ++b)
        if (glm::length(leaf.center - bounds[b].center) < bounds[b].radius + leaf.radius)
          deepest = std::max(deepest, -exact_distance(frames[b], leaf));
      for (const Sphere& p : palm)
        deepest = std::max(deepest, p.radius + leaf.radius - glm::length(p.center - leaf.center));
    }
  }
  return deepest;
}

vec3 index_press_box_centre(const HandModel& model, double half, double gap) {
  constexpr int kIndex = FRUSTA_FINGER_INDEX;
  HandState curled = open_hand();
  set_flexion(curled, kIndex, 0.01, 0.01, 0.01);  // which way the tip starts
  HandPose open, bent;
  forward_kinematics(model, open_hand(), open);
  forward_kinematics(model, curled, bent);
  const vec3 tip = open.fingers[kIndex].joint[3];
  const vec3 toward = glm::normalize(bent.fingers[kIndex].joint[3] - tip);
  return tip + toward * (model.fingers[kIndex].radius[3] + gap + half);
}

namespace {

// The angle (radians) of the turn from rotation a to rotation b.
double turn(const glm::dmat3& a, const glm::dmat3& b) {
  const glm::dmat3 r = glm::transpose(a) * b;
  return std::acos(std::clamp(0.5 * (r[0][0] + r[1][1] + r[2][2] - 1.0), -1.0, 1.0));
}

}  // namespace

double body_move(const HandModel& model, const HandPose& a, const HandPose& b, int body) {
  if (body == kPalmBody) {
    double most = 0.0;
    for (int k = 0; k < static_cast<int>(model.palm_spheres.size()); ++k)
      most = std::max(most, glm::length(palm_sphere(model, a, k).center - palm_sphere(model, b, k).center) +
                                turn(a.palm_rotation, b.palm_rotation) * model.palm_spheres[static_cast<size_t>(k)].radius);
    return most;
  }
  const int f = body / FRUSTA_SEGMENTS_PER_FINGER, s = body % FRUSTA_SEGMENTS_PER_FINGER;
  const FingerPose &fa = a.fingers[f], &fb = b.fingers[f];
  const double ends = std::max(glm::length(fa.joint[s] - fb.joint[s]), glm::length(fa.joint[s + 1] - fb.joint[s + 1]));
  return ends + turn(fa.segment_rotation[s], fb.segment_rotation[s]) * model.fingers[f].radius[s];
}

}  // namespace frusta::scenes
