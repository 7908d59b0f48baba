// SPDX-License-Identifier: MIT
// frusta-make-recording OUT.csv [OUT.frrec [OUT_TRACKED.csv]]: writes the demo's
// scripted glove recording, built from the same hand scenarios the tests check (the
// pinch that carries a marble, the fingertip slide, the tile pinch), so the demo plays
// motions known to work. The recording is bundled (samples/data/demo_glove.csv); a test
// checks it is what this program writes. With OUT.frrec it also writes the glove part
// as a device recording (native/src/devices/recording.h): a tracked glove speaking our
// binary profile at 100 Hz, to open as replay:OUT.frrec (the Unity sample does). With
// OUT_TRACKED.csv it writes the marble part of the same script (reach, pinch, lift,
// carry, release: the first kTrackedSeconds) as a hand tracker would report it: the
// hand model's forward kinematics -> OpenXR's 26 joints (tracking/joints_from_hand.h)
// at 90 Hz, a tracked-joint recording (tracking/joint_recording.h) for
// frusta_tracked_demo.
//
// Format, one record per line (# starts a comment):
//   object,NAME,SAMPLE,x,y,z,qx,qy,qz,qw,DYNAMIC,mass,friction,normal_damping,
//          tangential_damping
//   event,TIME,dynamic|remove,NAME,VALUE
//   frame,TIME,px,py,pz,qx,qy,qz,qw,a0,...,a19   (palm pose, then 20 joint angles)
// Metres, radians, seconds, kilograms; right-handed, z up.
#include <array>
#include <cstdio>
#include <glm/gtc/quaternion.hpp>
#include <string>
#include <vector>

#include "core/error.h"
#include "devices/frusta_protocol.h"
#include "devices/recording.h"
#include "hand/anthropometry.h"
#include "meshes/meshes.h"
#include "scenes/hand_scenarios.h"
#include "tracking/joint_recording.h"
#include "tracking/joints_from_hand.h"

namespace {

using frusta::HandState;
using frusta::vec3;
namespace scenes = frusta::scenes;

constexpr double kFrameRate = 100.0;  // frames per second, as gloves commonly stream
// the table top, under every point the recorded hand reaches (0.1 mm at the tile, 3.7 mm
// under the marble's pinch)
constexpr double kTableTop = -0.065;
constexpr double kTrackedRate = 90.0;  // frames per second, as a Meta Quest tracks hands
// the marble's part of the script: released at 4.2 s, fallen out of reach by 4.8 s
constexpr double kTrackedSeconds = 5.0;

struct Key {
  double time;
  HandState state;
};

HandState moved(HandState s, const vec3& by) {
  s.palm_position += by;
  return s;
}

// smooth between keys: a hand starts and stops at rest
HandState at_time(const std::vector<Key>& keys, double t) {
  if (t <= keys.front().time) return keys.front().state;
  for (size_t k = 1; k < keys.size(); ++k) {
    if (t > keys[k].time) continue;
    const double u = (t - keys[k - 1].time) / (keys[k].time - keys[k - 1].time);
    return scenes::mix(keys[k - 1].state, keys[k].state, u * u * (3.0 - 2.0 * u));
  }
  return keys.back().state;
}

void write_pose(FILE* out, const frusta::RigidPose& pose) {
  const glm::dquat q = glm::quat_cast(pose.rotation);
  std::fprintf(out, "%.6f,%.6f,%.6f,%.9f,%.9f,%.9f,%.9f", pose.position.x, pose.position.y,
               pose.position.z, q.x, q.y, q.z, q.w);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc > 4) {
    std::fprintf(stderr, "usage: frusta-make-recording OUT.csv [OUT.frrec [OUT_TRACKED.csv]]\n");
    return 2;
  }
  // three stations, 25 cm apart along y, each a scenario at the palm's origin moved there
  const vec3 marble_at(0.0), slide_at(0.0, 0.25, 0.0), plate_at(0.0, 0.5, 0.0);
  const vec3 lift(0.0, 0.0, 0.08), carry(0.10, 0.05, 0.15);
  const scenes::HandScenario marble = scenes::ball_pinch(0.003);
  const scenes::HandScenario slide = scenes::make_hand_scenario("slide");
  const scenes::HandScenario plate = scenes::plate_pinch(0.001);
  const HandState pads_open = marble.haptic(120);  // the opened pinch, before the squeeze
  // the slide scenario's press, a third as deep: the fingertip rests on the box with a
  // few newtons rather than the device's limit
  const HandState touching = scenes::mix(scenes::open_hand(), slide.haptic(99), 0.3);
  const HandState slid = moved(touching, slide.held.palm_position - slide.haptic(99).palm_position);
  const HandState plate_open = plate.haptic(120), plate_held = plate.held;

  const std::vector<Key> keys = {
      {0.0, moved(scenes::open_hand(), marble_at + lift)},  // reach
      {1.0, moved(pads_open, marble_at)},
      {1.8, moved(marble.held, marble_at)},                  // pinch the marble
      {2.2, moved(marble.held, marble_at)},                  // (it is handed to gravity)
      {3.4, moved(marble.held, marble_at + carry)},          // lift and carry
      {3.8, moved(marble.held, marble_at + carry)},
      {4.2, moved(pads_open, marble_at + carry)},            // release: it falls
      {5.0, moved(scenes::open_hand(), slide_at + lift)},
      {5.6, moved(scenes::open_hand(), slide_at)},
      {6.2, moved(touching, slide_at)},                      // fingertip onto the box
      {7.8, moved(slid, slide_at)},                          // slide it along
      {8.4, moved(scenes::open_hand(), slide_at + lift)},
      {9.0, moved(scenes::open_hand(), plate_at + lift)},
      {9.6, moved(plate_open, plate_at)},
      {10.4, moved(plate_held, plate_at)},                   // pinch the tile
      {11.0, moved(plate_held, plate_at)},
      {11.6, moved(scenes::open_hand(), plate_at + lift)},   // let go, withdraw
  };

  FILE* out = std::fopen(argv[1], "w");
  if (!out) {
    std::perror(argv[1]);
    return 1;
  }
  std::fprintf(out,
               "# Frusta demo glove recording, written by frusta-make-recording: a right hand\n"
               "# pinches a marble, lifts and carries it, lets it fall; slides a fingertip\n"
               "# along a box; pinches a tile; withdraws. Format: see make_recording.cpp.\n");
  const auto object = [&](const char* name, const char* sample, const frusta::RigidPose& pose,
                          int dynamic, double mass, double friction, double damping,
                          double tangential_damping) {
    std::fprintf(out, "object,%s,%s,", name, sample);
    write_pose(out, pose);
    std::fprintf(out, ",%d,%.3f,%.2f,%.2f,%.2f\n", dynamic, mass, friction, damping,
                 tangential_damping);
  };
  frusta::RigidPose pose = marble.objects[0].pose;
  pose.position += marble_at;
  // 50 g. Normal damping 2 sqrt(k m) settles it on the pads; the tangential damping
  // is kept low (critical would be 45): it acts on how fast the pads slide, and a
  // host's input timing noise reads as sliding (measured in real time: the whole carry
  // held in 5 of 6 runs at 10, 3 of 6 at 45)
  object("marble", "marble", pose, 0, 0.05, 0.8, 9.0, 10.0);
  pose = slide.objects[0].pose;
  pose.position += slide_at;
  object("box", "box", pose, 0, 0.5, 0.6, 0.0, 0.0);
  pose = plate.objects[0].pose;
  pose.position += plate_at;
  object("tile", "tile", pose, 0, 0.1, 0.6, 0.0, 0.0);
  // the table under all three stations and the stand the marble lies on, where the Unity
  // sample has them (GraspScenario.cs: TableTop, the table's and the stand's poses)
  const vec3 marble_centre = marble.objects[0].pose.position + marble_at;
  frusta::RigidPose table;
  table.position = vec3(0.15, 0.28, kTableTop - 0.015);  // samples/objects' table: 3 cm thick
  object("table", "table", table, 0, 1.0, 0.6, 0.0, 0.0);
  frusta::RigidPose stand;
  const double stand_height = marble_centre.z - scenes::kMarbleRadius - kTableTop;
  stand.position = vec3(marble_centre.x, marble_centre.y, kTableTop + 0.5 * stand_height);
  object("stand", "stand", stand, 0, 1.0, 0.6, 0.0, 0.0);
  // the host lets go once it is pinched; let go of by the hand, it falls onto the table
  std::fprintf(out, "event,2.000,dynamic,marble,1\n");

  frusta::Recorder glove;
  std::vector<uint8_t> bytes;
  if (argc >= 3) {
    if (glove.open(argv[2], "frusta") != FRUSTA_OK) {
      std::fprintf(stderr, "%s\n", frusta::last_error_message());
      return 1;
    }
    // the glove's answer to the host's HELLO: 100 Hz, a tracker, brakes
    frusta::DeviceCapabilities caps;
    caps.has_palm_pose = true;
    frusta::binary_profile::encode_caps(caps, &bytes);
    glove.write(0, bytes.data(), bytes.size());
  }
  const double end = keys.back().time + 0.5;
  for (int i = 0; i <= static_cast<int>(end * kFrameRate); ++i) {
    const double t = i / kFrameRate;
    const HandState s = at_time(keys, t);
    if (argc >= 3) {
      frusta::DeviceSample sample;
      sample.angles = s.angles;
      sample.has_palm_pose = true;
      sample.palm_position = s.palm_position;
      sample.palm_rotation = s.palm_rotation;
      sample.device_time_us = static_cast<int64_t>(i * 1e6 / kFrameRate);
      bytes.clear();
      frusta::binary_profile::encode_sample(sample, static_cast<uint16_t>(i), &bytes);
      glove.write(static_cast<int64_t>(i * 1e9 / kFrameRate), bytes.data(), bytes.size());
    }
    std::fprintf(out, "frame,%.3f,%.6f,%.6f,%.6f,%.9f,%.9f,%.9f,%.9f", t, s.palm_position.x,
                 s.palm_position.y, s.palm_position.z, s.palm_rotation.x, s.palm_rotation.y,
                 s.palm_rotation.z, s.palm_rotation.w);
    for (double a : s.angles) std::fprintf(out, ",%.6f", a);
    std::fprintf(out, "\n");
  }
  if (std::fclose(out) != 0 || glove.failed()) return 1;
  if (argc < 4) return 0;

  // the tracked hand: what a tracker would report for the scenarios' (default) hand
  const frusta::HandModel model = frusta::make_hand_model(frusta::default_hand_def());
  frusta::JointRecorder tracked;
  if (tracked.open(argv[3], FRUSTA_JOINT_LAYOUT_XR, FRUSTA_HAND_RIGHT,
                   "Frusta demo tracked-hand recording, written by frusta-make-recording: the\n"
                   "right hand of demo_glove.csv's script (pinch a marble, lift and carry it,\n"
                   "let it fall) as OpenXR's 26 joints at 90 Hz, from the default hand's forward\n"
                   "kinematics, in the world frame. Format: native/src/tracking/joint_recording.h.") !=
      FRUSTA_OK) {
    std::fprintf(stderr, "%s\n", frusta::last_error_message());
    return 1;
  }
  std::array<frusta::TrackedJoint, frusta::kMaxTrackedJoints> joints;
  for (int i = 0; i <= static_cast<int>(kTrackedSeconds * kTrackedRate); ++i) {
    const double t = i / kTrackedRate;
    frusta::HandPose hand_pose;
    frusta::forward_kinematics(model, at_time(keys, t), hand_pose);
    frusta::joints_from_hand(model, hand_pose, FRUSTA_JOINT_LAYOUT_XR, joints.data());
    if (tracked.add(t, joints.data()) != FRUSTA_OK) {
      std::fprintf(stderr, "%s\n", frusta::last_error_message());
      return 1;
    }
  }
  if (tracked.close() != FRUSTA_OK) {
    std::fprintf(stderr, "%s\n", frusta::last_error_message());
    return 1;
  }
  return 0;
}
