// SPDX-License-Identifier: MIT
// Writes a few valid tracked-joint recordings into DIR: the fuzzer's starting points
// (both layouts and sides, one to three frames of a moving default hand).
#include <array>
#include <string>

#include "hand/anthropometry.h"
#include "hand/kinematics.h"
#include "tracking/joint_recording.h"
#include "tracking/joints_from_hand.h"

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  for (int32_t layout : {FRUSTA_JOINT_LAYOUT_XR, FRUSTA_JOINT_LAYOUT_KEYPOINTS})
    for (int32_t side : {FRUSTA_HAND_RIGHT, FRUSTA_HAND_LEFT}) {
      frusta::HandDef def = frusta::default_hand_def();
      def.side = side;
      const frusta::HandModel model = frusta::make_hand_model(def);
      const std::string path = std::string(argv[1]) + "/seed" + std::to_string(layout) +
                               std::to_string(side) + ".csv";
      frusta::JointRecorder recorder;
      if (recorder.open(path, layout, side, "a seed") != FRUSTA_OK) return 1;
      for (int i = 0; i < 1 + layout + side; ++i) {
        frusta::HandState state;
        state.palm_position = frusta::vec3(0.01 * i, 0.0, 0.1);
        for (double& a : state.angles) a = 0.1 * i;
        frusta::clamp_to_limits(model, state);
        frusta::HandPose pose;
        frusta::forward_kinematics(model, state, pose);
        std::array<frusta::TrackedJoint, frusta::kMaxTrackedJoints> joints;
        frusta::joints_from_hand(model, pose, layout, joints.data());
        if (recorder.add(i / 90.0, joints.data()) != FRUSTA_OK) return 1;
      }
      if (recorder.close() != FRUSTA_OK) return 1;
    }
  return 0;
}
