// SPDX-License-Identifier: MIT
// The contact forces against values worked out here: a fingertip sunk a known depth into
// a face is pushed out with stiffness times depth along the normal; friction is the stick
// spring below mu |F| and exactly mu |F| beyond, continuously, over a slow ramp there and
// back; anchors ride with their objects, belong to one contact each and go with it; and a
// long steady run allocates nothing.
#include "forces/contact_forces.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <new>
#include <vector>

#include "forces/device_outputs.h"
#include "hand/anthropometry.h"
#include "hand/hand_model.h"
#include "spheretree/tree_builder.h"

// Every allocation in this test binary is counted, so a test can require none.
static std::atomic<int64_t> g_allocations{0};
void* operator new(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
// kept out of line: inlined, GCC 12 takes free() of an operator new pointer for a
// mismatch (-Wmismatched-new-delete), not knowing the replacement above uses malloc
[[gnu::noinline]] void operator delete(void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace frusta {
namespace {

constexpr int kIndex = 1;
constexpr int kIndexTip = kIndex * FRUSTA_SEGMENTS_PER_FINGER + 2;  // the index's distal segment
const vec3 kUp(0.0, 0.0, 1.0);

HandModel right_hand() { return make_hand_model(default_hand_def()); }

HandState hand_at(const vec3& palm) {
  HandState s;
  s.palm_position = palm;
  return s;
}

HandPose pose_of(const HandModel& model, const HandState& state) {
  HandPose pose;
  forward_kinematics(model, state, pose);
  return pose;
}

// The open hand's index fingertip resting on a face below it: its lowest point touches,
// the normal points up, out of the face.
SolverContact tip_on_face(const HandModel& model, const HandPose& graphic, int32_t object) {
  SolverContact c;
  c.object = object;
  c.leaf = 7;
  c.body = kIndexTip;
  c.normal = kUp;
  c.hand_point = graphic.fingers[kIndex].joint[3] - model.fingers[kIndex].radius[3] * kUp;
  c.object_point = c.hand_point;
  return c;
}

const SolverObject kFace{nullptr, {vec3(0.15, 0.03, -0.05), glm::dmat3(1.0)}};

TEST(ContactForces, FingertipSunkIntoAFaceIsPushedOutWithStiffnessTimesDepth) {
  const HandModel model = right_hand();
  const HandPose graphic = pose_of(model, hand_at(vec3(0.0)));
  const SolverContact c = tip_on_face(model, graphic, 0);
  ContactForces forces;
  for (double depth : {0.0001, 0.001, 0.003, 0.02}) {
    // the haptic hand is the graphic one sunk `depth` straight into the face
    const HandPose haptic = pose_of(model, hand_at(-depth * kUp));
    ContactForceStats stats;
    forces.update(graphic, haptic, &c, 1, &kFace, 1, nullptr, &stats);
    ASSERT_EQ(forces.forces().size(), 1u);
    const ContactForce& f = forces.forces()[0];
    EXPECT_NEAR(glm::length(f.haptic_point - (c.hand_point - depth * kUp)), 0.0, 1e-15);
    EXPECT_NEAR(f.normal_force.x, 0.0, 1e-12);
    EXPECT_NEAR(f.normal_force.y, 0.0, 1e-12);
    EXPECT_NEAR(f.normal_force.z, kDefaultContactStiffness * depth, 1e-12) << depth << " m deep";
    EXPECT_NEAR(glm::length(f.friction), 0.0, 1e-12) << "straight in: nothing to resist sideways";
    EXPECT_EQ(stats.pressing, 1);
    EXPECT_EQ(stats.slipping, 0);
  }
  // the haptic fingertip above the face: the contact is reported but pushes nothing
  const HandPose above = pose_of(model, hand_at(0.001 * kUp));
  ContactForceStats stats;
  forces.update(graphic, above, &c, 1, &kFace, 1, nullptr, &stats);
  EXPECT_EQ(forces.forces()[0].normal_force, vec3(0.0));
  EXPECT_EQ(forces.forces()[0].friction, vec3(0.0));
  EXPECT_EQ(stats.pressing, 0);
}

TEST(ContactForces, AnisotropicStiffnessTurnsWithItsObject) {
  const HandModel model = right_hand();
  const HandPose graphic = pose_of(model, hand_at(vec3(0.0)));
  const SolverContact c = tip_on_face(model, graphic, 0);
  // the object turned 90 degrees about x: its own y axis faces up, towards the finger
  SolverObject turned = kFace;
  turned.pose.rotation = glm::dmat3(1, 0, 0, 0, 0, 1, 0, -1, 0);  // columns: x, y -> z, z -> -y
  ForceMaterial material;
  material.normal_stiffness = vec3(100.0, 250.0, 400.0);
  const double depth = 0.004;
  ContactForces forces;
  forces.update(graphic, pose_of(model, hand_at(-depth * kUp)), &c, 1, &turned, 1, &material,
                nullptr);
  const vec3 expected = 250.0 * depth * kUp;  // the material's y stiffness
  EXPECT_NEAR(glm::length(forces.forces()[0].normal_force - expected), 0.0, 1e-12);
}

TEST(ContactForces, FingerContactFollowsItsSegmentFrame) {
  // the haptic index bends its last joint by theta; the graphic one stays open
  const HandModel model = right_hand();
  const HandPose graphic = pose_of(model, hand_at(vec3(0.0)));
  const double theta = 0.2;
  HandState bent = hand_at(vec3(0.0));
  bent.angles[kIndex * FRUSTA_JOINTS_PER_FINGER + 3] = theta;
  const HandPose haptic = pose_of(model, bent);

  // the pad under the fingertip: (L, 0, -r) in the distal frame (x along the segment,
  // z out of the back of the finger), pressed by a face under it
  const double length = model.fingers[kIndex].length[2], radius = model.fingers[kIndex].radius[3];
  const glm::dmat3& frame = graphic.fingers[kIndex].segment_rotation[2];
  const vec3& joint = graphic.fingers[kIndex].joint[2];
  SolverContact c;
  c.body = kIndexTip;
  c.normal = frame[2];
  c.hand_point = joint + frame * vec3(length, 0.0, -radius);
  ContactForces forces;
  forces.update(graphic, haptic, &c, 1, &kFace, 1, nullptr, nullptr);

  // flexion turns the segment's x towards -z about its y: x -> (cos, 0, -sin), z -> (sin, 0, cos)
  const double cs = std::cos(theta), sn = std::sin(theta);
  const vec3 expected =
      joint + frame * vec3(length * cs - radius * sn, 0.0, -length * sn - radius * cs);
  const ContactForce& f = forces.forces()[0];
  EXPECT_NEAR(glm::length(f.haptic_point - expected), 0.0, 1e-15);
  const double gap = glm::length(c.hand_point - expected);
  EXPECT_NEAR(glm::length(f.normal_force - kDefaultContactStiffness * gap * c.normal), 0.0, 1e-12)
      << "the whole gap, not only its normal part (seed eq. 12)";
}

TEST(ContactForces, PalmContactFollowsThePalmFrame) {
  // the haptic palm moved 1 cm along x and turned 90 degrees about x; the graphic one
  // at the origin, unturned
  const HandModel model = right_hand();
  const HandPose graphic = pose_of(model, hand_at(vec3(0.0)));
  const double half = std::sqrt(0.5);
  const HandPose haptic =
      pose_of(model, {vec3(0.01, 0.0, 0.0), glm::dquat(half, half, 0.0, 0.0), {}});
  SolverContact c;
  c.body = kPalmBody;
  c.part = 2;
  c.normal = vec3(0.0, 0.0, -1.0);
  const vec3 local(0.05, 0.01, -0.02);
  c.hand_point = local;
  ContactForces forces;
  forces.update(graphic, haptic, &c, 1, &kFace, 1, nullptr, nullptr);
  // about x by 90 degrees: (x, y, z) -> (x, -z, y)
  const vec3 expected = vec3(0.01, 0.0, 0.0) + vec3(local.x, -local.z, local.y);
  const ContactForce& f = forces.forces()[0];
  EXPECT_NEAR(glm::length(f.haptic_point - expected), 0.0, 1e-15);
  const vec3 gap = c.hand_point - expected;
  ASSERT_GT(glm::dot(gap, c.normal), 0.0) << "the case is meant to press";
  EXPECT_NEAR(glm::length(f.normal_force - kDefaultContactStiffness * glm::length(gap) * c.normal),
              0.0, 1e-12);
}

TEST(ContactForces, AGloveReadingPastAJointLimitMakesNoForce) {
  const HandModel model = right_hand();
  HandState glove = hand_at(vec3(0.0));
  const int joint = kIndex * FRUSTA_JOINTS_PER_FINGER + 1;
  glove.angles[joint] = model.fingers[kIndex].joint_max[1] + 0.5;
  HandState graphic_state = glove;  // what the solver shows in free space: the clamped hand
  graphic_state.angles[joint] = model.fingers[kIndex].joint_max[1];
  const HandPose graphic = pose_of(model, graphic_state);
  SolverContact c = tip_on_face(model, graphic, 0);
  HandPose haptic;
  haptic_hand_pose(model, glove, haptic);
  ContactForces forces;
  forces.update(graphic, haptic, &c, 1, &kFace, 1, nullptr, nullptr);
  EXPECT_EQ(forces.forces()[0].haptic_point, c.hand_point);
  EXPECT_EQ(forces.forces()[0].normal_force, vec3(0.0));
}

TEST(ContactForces, FrictionSticksBelowMuFThenSlipsAtExactlyMuFWithoutChatter) {
  const HandModel model = right_hand();
  ForceMaterial material;
  material.friction = 0.5;
  material.tangential_stiffness = 1000.0;
  const double depth = 0.005;                                      // metres
  const double normal = kDefaultContactStiffness * depth;          // |F| = 2 N
  const double limit = material.friction * normal;                 // mu |F| = 1 N
  const double threshold = limit / material.tangential_stiffness;  // reached at 1 mm
  const double step = 1e-5;                                        // 10 um a step: a slow ramp
  const int ramp = 300;  // out to 3 mm, three times the threshold, then back to 0
  const double turn = ramp * step;

  ContactForces forces;
  vec3 previous(0.0);
  double last_sign = 0.0;
  int sign_changes = 0;
  for (int k = 0; k <= 2 * ramp; ++k) {
    // the graphic hand slides along the face (as the solver keeps it), the haptic hand
    // the same depth below it: the normal force stays 2 N
    const double s = (k <= ramp ? k : 2 * ramp - k) * step;
    const HandPose graphic = pose_of(model, hand_at(vec3(s, 0.0, 0.0)));
    const HandPose haptic = pose_of(model, hand_at(vec3(s, 0.0, -depth)));
    const SolverContact c = tip_on_face(model, graphic, 0);
    ContactForceStats stats;
    forces.update(graphic, haptic, &c, 1, &kFace, 1, &material, &stats);
    const ContactForce& f = forces.forces()[0];
    EXPECT_NEAR(glm::length(f.normal_force), normal, 1e-12);

    // out: the spring k s from the first contact until it reaches mu |F|, then mu |F|.
    // Back: the anchor was left `threshold` behind the turn; the spring unloads through
    // zero and slips the other way once stretched as far the other side
    const double spring = k <= ramp ? material.tangential_stiffness * s
                                    : material.tangential_stiffness * (s - (turn - threshold));
    const double expected = -std::clamp(spring, -limit, limit);
    EXPECT_NEAR(f.friction.x, expected, 1e-9) << "step " << k << ", " << s << " m";
    EXPECT_NEAR(f.friction.y, 0.0, 1e-12);
    EXPECT_NEAR(f.friction.z, 0.0, 1e-12);
    if (std::fabs(std::fabs(spring) - limit) > 1e-9) {
      EXPECT_EQ(f.slipping, std::fabs(spring) > limit) << "step " << k;
      EXPECT_EQ(stats.slipping, std::fabs(spring) > limit ? 1 : 0);
    }
    if (std::fabs(spring) >= limit) {
      EXPECT_NEAR(glm::length(f.friction), limit, 1e-12) << "at and beyond the switch: mu |F|";
    }

    // continuous: no step changes the friction more than the spring over one step's motion
    if (k > 0) {
      EXPECT_LE(glm::length(f.friction - previous), material.tangential_stiffness * step + 1e-9)
          << "step " << k;
    }
    previous = f.friction;
    if (std::fabs(f.friction.x) > 1e-9) {
      const double sign = f.friction.x > 0.0 ? 1.0 : -1.0;
      if (last_sign != 0.0 && sign != last_sign) ++sign_changes;
      last_sign = sign;
    }
  }
  EXPECT_EQ(sign_changes, 1) << "once, where the reversed motion unloads the spring; never chatter";
}

TEST(ContactForces, TangentialDampingAddsToTheSpringWhileStickingAndStaysInTheDisc) {
  // a fingertip pressed 5 mm (|F| = 2 N) slides at a steady 1 mm/s: while it sticks the
  // friction is the spring on the stretch plus the damping on the rate, -(k s + c v);
  // at the switch the sum is held to mu |F| like the spring alone
  const HandModel model = right_hand();
  ForceMaterial material;
  material.tangential_stiffness = 1000.0;
  material.tangential_damping = 200.0;
  material.friction = 0.5;  // mu |F| = 1 N
  const double depth = 0.005, dt = 1e-3, speed = 1e-3;
  ContactForces forces;
  ASSERT_EQ(forces.set_time_step(dt), FRUSTA_OK);
  for (int k = 0; k <= 1200; ++k) {
    const double s = k * speed * dt;
    const HandPose graphic = pose_of(model, hand_at(vec3(s, 0.0, 0.0)));
    const HandPose haptic = pose_of(model, hand_at(vec3(s, 0.0, -depth)));
    const SolverContact c = tip_on_face(model, graphic, 0);
    forces.update(graphic, haptic, &c, 1, &kFace, 1, &material, nullptr);
    const double rate = k == 0 ? 0.0 : speed;  // a new patch has no rate yet
    const double expected = std::min(material.tangential_stiffness * s +
                                         material.tangential_damping * rate,
                                     1.0);
    EXPECT_NEAR(forces.forces()[0].friction.x, -expected, 1e-9) << "step " << k;
    EXPECT_LE(glm::length(forces.forces()[0].friction), 1.0 + 1e-12);
  }
  EXPECT_TRUE(forces.forces()[0].slipping);
  EXPECT_EQ(forces.set_time_step(0.0), FRUSTA_ERROR_OUT_OF_RANGE);
}

TEST(ContactForces, AnchorRidesWithItsObject) {
  // the hand holds still, pressed in; the object slides under it along y and drags the
  // finger along until the spring reaches mu |F|
  const HandModel model = right_hand();
  const HandPose graphic = pose_of(model, hand_at(vec3(0.0)));
  const double depth = 0.005;
  const HandPose haptic = pose_of(model, hand_at(-depth * kUp));
  const SolverContact c = tip_on_face(model, graphic, 0);
  const ForceMaterial material;
  const double limit = material.friction * kDefaultContactStiffness * depth;
  ContactForces forces;
  for (int k = 0; k <= 100; ++k) {
    const double s = k * 5e-5;
    SolverObject moved = kFace;
    moved.pose.position.y += s;
    forces.update(graphic, haptic, &c, 1, &moved, 1, nullptr, nullptr);
    const vec3 expected(0.0, std::min(material.tangential_stiffness * s, limit), 0.0);
    EXPECT_NEAR(glm::length(forces.forces()[0].friction - expected), 0.0, 1e-9) << "step " << k;
  }
}

TEST(ContactForces, PressingDeeperThenTurningTheNormalMakesNoFriction) {
  // the finger sinks straight in from 1 to 5 mm, then the surface under it turns 0.2 rad
  // (rolling over a curve): no tangential motion happened, so no friction. An anchor
  // that kept the first depth would now read 4 mm x sin 0.2 of stretch: 0.32 N
  const HandModel model = right_hand();
  const HandPose graphic = pose_of(model, hand_at(vec3(0.0)));
  SolverContact c = tip_on_face(model, graphic, 0);
  ContactForces forces;
  for (double depth : {0.001, 0.005}) {
    forces.update(graphic, pose_of(model, hand_at(-depth * kUp)), &c, 1, &kFace, 1, nullptr,
                  nullptr);
  }
  c.normal = vec3(std::sin(0.2), 0.0, std::cos(0.2));
  forces.update(graphic, pose_of(model, hand_at(-0.005 * kUp)), &c, 1, &kFace, 1, nullptr, nullptr);
  EXPECT_NEAR(glm::length(forces.forces()[0].friction), 0.0, 1e-12);
}

TEST(ContactForces, AVanishedContactTakesItsAnchorWithIt) {
  const HandModel model = right_hand();
  const double depth = 0.005, slide = 0.00005;  // a stick stretch: 0.5 N of 1.2 N allowed
  const ForceMaterial material;
  auto run = [&](ContactForces& forces, double s, bool touching) {
    const HandPose graphic = pose_of(model, hand_at(vec3(s, 0.0, 0.0)));
    const HandPose haptic = pose_of(model, hand_at(vec3(s, 0.0, -depth)));
    const SolverContact c = tip_on_face(model, graphic, 0);
    forces.update(graphic, haptic, &c, touching ? 1 : 0, &kFace, 1, nullptr, nullptr);
  };
  ContactForces forces;
  run(forces, 0.0, true);
  run(forces, slide, true);
  EXPECT_NEAR(forces.forces()[0].friction.x, -material.tangential_stiffness * slide, 1e-9);
  run(forces, slide, false);
  EXPECT_TRUE(forces.forces().empty());
  run(forces, slide, true);
  EXPECT_NEAR(glm::length(forces.forces()[0].friction), 0.0, 1e-12)
      << "a new contact, a new anchor";
  run(forces, 2.0 * slide, true);
  forces.reset();
  run(forces, 2.0 * slide, true);
  EXPECT_NEAR(glm::length(forces.forces()[0].friction), 0.0, 1e-12) << "reset forgets anchors";
}

TEST(ContactForces, ALeafJoiningAPatchLeavesItsFrictionAsItWas) {
  // a fingertip sliding over an object meets new leaves as it goes; the friction is the
  // patch's (one body on one object), so a leaf joining it only splits it
  const HandModel model = right_hand();
  const double depth = 0.005, slide = 0.00005;  // a stick stretch
  ContactForces forces;
  auto contacts_at = [&](double s, int count) {
    const HandPose graphic = pose_of(model, hand_at(vec3(s, 0.0, 0.0)));
    std::vector<SolverContact> cs(2, tip_on_face(model, graphic, 0));
    cs[1].leaf = 8;
    cs[1].hand_point.y += 0.002;  // a second leaf beside the first
    cs.resize(static_cast<size_t>(count));
    return std::make_pair(graphic, cs);
  };
  {
    const auto [graphic, cs] = contacts_at(0.0, 1);
    forces.update(graphic, pose_of(model, hand_at(-depth * kUp)), cs.data(), 1, &kFace, 1, nullptr,
                  nullptr);
  }
  const auto [graphic, cs] = contacts_at(slide, 2);
  forces.update(graphic, pose_of(model, hand_at(vec3(slide, 0.0, -depth))), cs.data(), 2, &kFace, 1,
                nullptr, nullptr);
  const double expected = -ForceMaterial{}.tangential_stiffness * slide;
  EXPECT_NEAR(forces.forces()[0].friction.x + forces.forces()[1].friction.x, expected, 1e-9);
  EXPECT_NEAR(forces.forces()[0].friction.x, forces.forces()[1].friction.x, 1e-12);
  EXPECT_NEAR(forces.forces()[0].friction.y + forces.forces()[1].friction.y, 0.0, 1e-12);
}

TEST(ContactForces, ABodyOnAFaceOfManyLeavesFeelsOneSurface) {
  // a fingertip on a face the tree covers with several leaves meets a contact per leaf,
  // all with one gap: together they push as one face, k G / k, not k times as hard
  const HandModel model = right_hand();
  const HandPose graphic = pose_of(model, hand_at(vec3(0.0)));
  const HandPose haptic = pose_of(model, hand_at(-0.002 * kUp));
  const SolverObject objects[2] = {kFace, kFace};
  for (int leaves : {1, 2, 5}) {
    std::vector<SolverContact> cs(static_cast<size_t>(leaves), tip_on_face(model, graphic, 0));
    for (int i = 0; i < leaves; ++i) cs[static_cast<size_t>(i)].leaf = 20 + i;
    // the same fingertip on a second object, and the palm-side segment on the first: each
    // their own surface, unshared
    SolverContact other = tip_on_face(model, graphic, 1);
    SolverContact middle = tip_on_face(model, graphic, 0);
    middle.body = kIndexTip - 1;
    middle.hand_point = graphic.fingers[kIndex].joint[2] - model.fingers[kIndex].radius[2] * kUp;
    cs.push_back(other);
    cs.push_back(middle);
    ContactForces forces;
    forces.update(graphic, haptic, cs.data(), static_cast<int32_t>(cs.size()), objects, 2, nullptr,
                  nullptr);
    vec3 tip_on_first(0.0);
    for (int i = 0; i < leaves; ++i) tip_on_first += forces.forces()[static_cast<size_t>(i)].normal_force;
    const double expected = kDefaultContactStiffness * 0.002;
    EXPECT_NEAR(tip_on_first.z, expected, 1e-12) << leaves << " leaves";
    EXPECT_NEAR(forces.forces()[static_cast<size_t>(leaves)].normal_force.z, expected, 1e-12);
    EXPECT_NEAR(forces.forces()[static_cast<size_t>(leaves) + 1].normal_force.z, expected, 1e-12);
  }
}

TEST(ContactForces, ContactsBeyondCapacityAreLeftOutAndCounted) {
  const HandModel model = right_hand();
  const HandPose graphic = pose_of(model, hand_at(vec3(0.0)));
  std::vector<SolverContact> cs(3, tip_on_face(model, graphic, 0));
  for (int i = 0; i < 3; ++i) cs[static_cast<size_t>(i)].leaf = 10 + i;
  ContactForces forces(2);
  ContactForceStats stats;
  forces.update(graphic, pose_of(model, hand_at(-0.001 * kUp)), cs.data(), 3, &kFace, 1, nullptr,
                &stats);
  EXPECT_EQ(stats.dropped, 1);
  ASSERT_EQ(forces.forces().size(), 2u);
  EXPECT_EQ(forces.forces()[0].leaf, 10);
  EXPECT_EQ(forces.forces()[1].leaf, 11);
}

TEST(ContactForces, FingertipPressedIntoALargeSphereByTheSolver) {
  // one leaf of radius 5 cm, its top 2 mm under the open hand's index fingertip and
  // clear of the other fingers; the haptic index bends into it, the graphic one stops
  const HandModel model = right_hand();
  const HandPose open = pose_of(model, hand_at(vec3(0.0)));
  const double big = 0.05;
  const vec3 tip_bottom = open.fingers[kIndex].joint[3] - model.fingers[kIndex].radius[3] * kUp;
  const Sphere leaf{tip_bottom - (0.002 + big) * kUp, big};
  SphereTree tree;
  ASSERT_EQ(build_sphere_tree({leaf}, TreeBuildOptions{}, &tree), FRUSTA_OK);
  const SolverObject ball{&tree, {vec3(0.0), glm::dmat3(1.0)}};
  HandSolver solver(model, SolverParams{});
  HandState glove = hand_at(vec3(0.0));
  for (int t = 0; t <= 100; ++t) {
    glove.angles[kIndex * FRUSTA_JOINTS_PER_FINGER + 1] = 0.2 * std::min(t, 50) / 50.0;
    ASSERT_EQ(solver.step(glove, &ball, 1, nullptr), FRUSTA_OK);
  }
  HandPose haptic;
  haptic_hand_pose(model, glove, haptic);
  ContactForces forces;
  ContactForceStats stats;
  forces.update(solver.graphic_pose(), haptic, solver.contacts().data(),
                static_cast<int32_t>(solver.contacts().size()), &ball, 1, nullptr, &stats);
  ASSERT_GT(stats.pressing, 0);
  const FingerPose& g = solver.graphic_pose().fingers[kIndex];
  const FingerPose& h = haptic.fingers[kIndex];
  for (const ContactForce& f : forces.forces()) {
    EXPECT_EQ(f.body / FRUSTA_SEGMENTS_PER_FINGER, kIndex) << "only the index bends";
    if (f.normal_force == vec3(0.0)) continue;
    // the same material point: as far from its segment's two joint centres on both hands
    const int s = f.body % FRUSTA_SEGMENTS_PER_FINGER;
    for (int j = s; j <= s + 1; ++j)
      EXPECT_NEAR(glm::length(f.haptic_point - h.joint[j]),
                  glm::length(f.graphic_point - g.joint[j]), 1e-12);
    // pushed straight out, by the stiffness times the gap, which is at least how deep
    // the haptic point lies under the surface
    const double gap = glm::length(f.graphic_point - f.haptic_point);
    EXPECT_NEAR(glm::length(f.normal_force - kDefaultContactStiffness * gap * f.normal), 0.0,
                1e-12);
    const double under = big - glm::length(f.haptic_point - leaf.center);
    EXPECT_GT(under, 0.0) << "the haptic point is inside";
    EXPECT_GE(gap, under - 1e-12);
    EXPECT_NEAR(glm::length(f.graphic_point - leaf.center), big, 2e-6) << "P_ig on the surface";
  }
}

TEST(ContactForces, TenThousandSteadyStepsAllocateNothing) {
  const HandModel model = right_hand();
  constexpr int32_t kCapacity = 64;
  constexpr int32_t kPool = 100;
  constexpr int32_t kObjects = 3;
  ContactForces forces(kCapacity);
  std::array<ObjectWrench, kObjects> reactions{};
  std::array<SolverObject, kObjects> objects{};
  DeviceOutputs outputs;

  // a pool of contacts over every body and object; each step takes a changing run of
  // them, so contacts come and go and the table sometimes overflows
  const HandPose rest = pose_of(model, hand_at(vec3(0.0)));
  std::vector<SolverContact> pool(static_cast<size_t>(kPool));
  for (int32_t i = 0; i < kPool; ++i) {
    SolverContact& c = pool[static_cast<size_t>(i)];
    c.object = i % kObjects;
    c.body = i % kBodyCount;
    c.leaf = i % 10 == 0 ? -1 : i;
    c.normal = glm::normalize(vec3(0.1 * (i % 3), 0.05 * (i % 5), 1.0));
    c.part = c.body == kPalmBody ? i % static_cast<int32_t>(model.palm_spheres.size()) : 0;
    c.hand_point = c.body == kPalmBody
                       ? palm_sphere(model, rest, c.part).center
                       : rest.fingers[c.body / 3].joint[c.body % 3 + 1] - 0.008 * c.normal;
    c.object_point = c.hand_point;
  }

  int32_t most_dropped = 0, most_slipping = 0;
  const int64_t before = g_allocations.load();
  for (int32_t t = 0; t < 10000; ++t) {
    // the haptic hand circles 4 mm about 1 mm deep (sticking, then slipping), the
    // objects sway, and every 25 steps another run of contacts (one more every other step)
    const double phase = 0.02 * t;
    for (int32_t o = 0; o < kObjects; ++o)
      objects[static_cast<size_t>(o)].pose.position = vec3(0.1 * o, 0.001 * std::sin(phase), 0.0);
    HandPose haptic;
    forward_kinematics(model,
                       hand_at(vec3(0.004 * std::sin(phase), 0.004 * std::cos(phase),
                                    -0.001 - 0.0005 * std::sin(2.5 * phase))),
                       haptic);
    const int32_t run = t / 25;
    const int32_t first = (run * 13) % 37;
    const int32_t count = (run * 29) % (kPool - first) + t % 2;
    ContactForceStats stats;
    forces.update(rest, haptic, pool.data() + first, count, objects.data(), kObjects, nullptr,
                  &stats);
    compute_device_outputs(haptic, forces.forces().data(),
                           static_cast<int32_t>(forces.forces().size()), objects.data(), kObjects,
                           DeviceLimits{}, &outputs, reactions.data());
    most_dropped = std::max(most_dropped, stats.dropped);
    most_slipping = std::max(most_slipping, stats.slipping);
  }
  const int64_t allocated = g_allocations.load() - before;
  EXPECT_EQ(allocated, 0) << "steady steps must not allocate";
  EXPECT_GT(most_dropped, 0) << "the run meant to overflow the table";
  EXPECT_GT(most_slipping, 0) << "the run meant to slip";
}

}  // namespace
}  // namespace frusta
