// SPDX-License-Identifier: MIT
// The scripted haptic trajectories of the solver's acceptance list, shared by its
// tests and its benchmark: objects (the baked samples, or trees made here), a haptic
// hand per step, the pose it is then held at; and the exact reference for how deep
// a hand sinks into a set of leaves.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "hand/kinematics.h"
#include "scenes/baked_objects.h"
#include "solver/detection.h"
#include "spheretree/tree_file.h"

namespace frusta::scenes {

// N leaves on a sphere's surface (Fibonacci points), sized to overlap so their union
// is a closed shell whose outside stays within the radius: a ball of any leaf count.
std::shared_ptr<const TreeFile> ball_shell(int32_t leaves, double radius);

glm::dquat about(const vec3& axis, double angle);
HandState open_hand(const vec3& palm = vec3(0.0), const glm::dquat& rotation = glm::dquat(1, 0, 0, 0));
// Straight interpolation of palm and angles (slerp for the rotation), t clamped to [0, 1].
HandState mix(const HandState& a, const HandState& b, double t);
void set_flexion(HandState& s, int finger, double f1, double f2, double f3);

struct HandScenario {
  std::string name;
  std::vector<std::shared_ptr<const TreeFile>> trees;
  std::vector<SolverObject> objects;
  int32_t steps = 0;                         // the scripted part
  std::function<HandState(int32_t)> haptic;  // the haptic hand at each scripted step
  HandState held;                            // then held here
  vec3 anchor{0.0}, axis{0.0};               // a scenario's reference (plate centre, normal)

  void add(std::shared_ptr<const TreeFile> tree, const RigidPose& pose);
};

// box_press, ball_grasp, slide, plate_pinch, bowl_press, plate_teleport, start_inside,
// palm_then_fingers: the acceptance list, in that order.
std::vector<std::string> hand_scenario_names();
HandScenario make_hand_scenario(const std::string& name);
// A 4 mm plate between the thumb and index pads, each pushed `pressed` metres past
// it (0.01 in the acceptance scenario, a few mm for a hold); axis: the plate's normal,
// anchor: its centre.
HandScenario plate_pinch(double pressed);
// A marble (kMarbleRadius, 1.74 cm across) between the thumb and index pads, each pushed `pressed`
// metres into it; axis: from the thumb to the index pad, anchor: the marble's centre.
HandScenario ball_pinch(double pressed);
// The deep grasp (all fingers closing 1.6 rad) around any ball-like tree of radius 4 cm.
HandScenario ball_grasp(std::shared_ptr<const TreeFile> ball);

// Where a box of half-size `half` (a cube) lies `gap` metres from the open index
// fingertip of `model`, on the side a curling index moves to: a glove curling its index
// presses into it, and the world brakes that finger alone (the device tests and bench).
vec3 index_press_box_centre(const HandModel& model, double half, double gap);

// Deepest penetration (metres, 0 when apart) of the hand at `pose` into any leaf of any
// object: every leaf against every segment solid and palm sphere by the exact
// distance, behind bound tests that are exact too.
double deepest_penetration(const HandModel& model, const HandPose& pose,
                           const std::vector<SolverObject>& objects);

// The most any point of hand body `body` (finger * 3 + segment, or kPalmBody) moves from
// pose a to pose b, metres (a bound: its joints' or palm spheres' moves plus the turn
// times the radius). The per-body continuity bound's move.
double body_move(const HandModel& model, const HandPose& a, const HandPose& b, int body);

}  // namespace frusta::scenes
