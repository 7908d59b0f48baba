// SPDX-License-Identifier: MIT
#include "solver/finger_motion.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace frusta {

double segment_lever_motion(const HandReach& reach, int finger, int segment,
                            const FingerAngles& from, const FingerAngles& to) {
  double motion = 0.0;
  for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j)
    motion += std::fabs(to[j] - from[j]) * reach.segment_lever[finger][segment][j];
  return motion;
}

double finger_lever_motion(const HandReach& reach, int finger, const FingerAngles& from,
                           const FingerAngles& to) {
  // the fingertip's segment moves furthest: its levers are the finger's
  return segment_lever_motion(reach, finger, FRUSTA_SEGMENTS_PER_FINGER - 1, from, to);
}

void finger_jacobian(const FingerPose& p, uint32_t segments, FingerJacobian& jacobian) {
  jacobian.abduction_axis = p.abduction_axis;
  jacobian.flexion_axis = p.flexion_axis;
  // axis x (X - pivot) = axis x X - axis x pivot: a cross product per joint centre and axis
  vec3 abducted[FRUSTA_SEGMENTS_PER_FINGER + 1], flexed[FRUSTA_SEGMENTS_PER_FINGER + 1];
  for (int k = 0; k <= FRUSTA_SEGMENTS_PER_FINGER; ++k) {
    abducted[k] = glm::cross(p.abduction_axis, p.joint[k]);
    flexed[k] = glm::cross(p.flexion_axis, p.joint[k]);
  }
  for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s) {
    if (((segments >> s) & 1u) == 0) continue;
    // D = joint s, E = joint s + 1; abduction turns about joint 0, flexion j about joint j - 1
    jacobian.proximal[s][0] = abducted[s] - abducted[0];
    jacobian.distal[s][0] = abducted[s + 1] - abducted[0];
    for (int j = 1; j < FRUSTA_JOINTS_PER_FINGER; ++j) {
      const bool moves = j - 1 <= s;
      jacobian.proximal[s][j] = moves ? flexed[s] - flexed[j - 1] : vec3(0.0);
      jacobian.distal[s][j] = moves ? flexed[s + 1] - flexed[j - 1] : vec3(0.0);
    }
  }
}

double finger_motion(const HandModel& model, const HandReach& reach, const FingerJacobian& jacobian,
                     int finger, const FingerAngles& turn, uint32_t segments) {
  const FingerModel& m = model.fingers[finger];
  double motion = 0.0;
  for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s) {
    if (((segments >> s) & 1u) == 0) continue;
    double levers = 0.0, turned = 0.0, flexion = 0.0;
    vec3 at_d(0.0), at_e(0.0);
    for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j) {
      if (!(reach.segment_lever[finger][s][j] > 0.0)) continue;  // beyond the segment
      levers += std::fabs(turn[j]) * reach.segment_lever[finger][s][j];
      turned += std::fabs(turn[j]);
      if (j > 0) flexion += turn[j];
      at_d += turn[j] * jacobian.proximal[s][j];
      at_e += turn[j] * jacobian.distal[s][j];
    }
    // The velocity field is rigid (spin x P + shift), so over a ball it is largest by
    // |spin| * radius beyond its centre's
    const double spin =
        glm::length(turn[0] * jacobian.abduction_axis + flexion * jacobian.flexion_axis);
    const double first = std::max(glm::length(at_d) + spin * m.radius[s],
                                  glm::length(at_e) + spin * m.radius[s + 1]);
    // Along the move each term axis_j x (P - pivot_j) changes: the flexion axis turns with
    // the abduction (by at most t |turn_0| a fraction t of the way), and P and the pivot
    // each move by at most t times the levers' bound. Integrated over the move: at most
    // levers * (|turn_0| / 2 + sum_j |turn_j|) beyond the first-order motion.
    const double second = levers * (0.5 * std::fabs(turn[0]) + turned);
    motion = std::max(motion, std::min(levers, first + second) / reach.segment_share[finger][s]);
  }
  return motion;
}

namespace {

// what within_cap cuts a move to, the pose's bound worked out by `posed` where needed
template <class Posed>
double cap_share(const HandReach& reach, int finger, const FingerAngles& from,
                 const FingerAngles& to, const FingerCap& cap, Posed posed) {
  const double levers = finger_lever_motion(reach, finger, from, to);
  double share = levers > cap.levers ? cap.levers / levers : 1.0;
  // the pose's bound is no more than the levers': it cuts the move shorter only where the
  // levers' would by its cap
  if (levers * share > cap.pose) {
    const double motion = posed();
    if (motion > cap.pose) share = std::min(share, cap.pose / motion);
  }
  return share;
}

FingerAngles turn_between(const FingerAngles& from, const FingerAngles& to) {
  FingerAngles turn;
  for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j) turn[j] = to[j] - from[j];
  return turn;
}

}  // namespace

double finger_motion(const HandModel& model, const HandReach& reach, const FingerPose& pose,
                     int finger, const FingerAngles& from, const FingerAngles& to) {
  FingerJacobian jacobian;
  finger_jacobian(pose, kEverySegment, jacobian);
  return finger_motion(model, reach, jacobian, finger, turn_between(from, to), kEverySegment);
}

double within_cap(const HandModel& model, const HandReach& reach, const FingerPose& pose,
                  int finger, const FingerAngles& from, const FingerAngles& to,
                  const FingerCap& cap) {
  return cap_share(reach, finger, from, to, cap,
                   [&] { return finger_motion(model, reach, pose, finger, from, to); });
}

double within_cap(const HandModel& model, const HandReach& reach, const FingerJacobian& jacobian,
                  int finger, const FingerAngles& from, const FingerAngles& to,
                  const FingerCap& cap) {
  return cap_share(reach, finger, from, to, cap, [&] {
    return finger_motion(model, reach, jacobian, finger, turn_between(from, to), kEverySegment);
  });
}

}  // namespace frusta
