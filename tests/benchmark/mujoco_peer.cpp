// SPDX-License-Identifier: MIT
#include "mujoco_peer.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <memory>
#include <sstream>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <mujoco/mujoco.h>

#include "percentile.h"

// later releases size contacts by an arena instead of nconmax/njmax and changed mjVFS
static_assert(mjVERSION_HEADER >= 220 && mjVERSION_HEADER < 230,
              "mujoco_peer is written against MuJoCo 2.2 (Debian's libmujoco-dev)");

namespace frusta::bench {

namespace {

// Position servo on every joint, tuned to track the haptic hand within a few ms in free
// space. A phalanx weighs a few grams, so at 1 ms any useful kp on its own inertia would
// be unstable (kp is explicit in MuJoCo's Euler step); a joint armature gives every
// joint about the same inertia instead, as MuJoCo's hand models do, and then
// kp = armature * w^2 with w = 1000 rad/s, critically damped (joint damping is implicit
// in the Euler step). In free space a finger lags a 6.4 rad/s ramp by ~2 / w = 2 ms
// (0.006 rad) and settles a 0.5 rad step to 0.01 rad in ~9 ms.
struct Servo {
  double kp, damping, armature;  // N m / rad, N m s / rad, kg m^2
};
constexpr Servo kServo{1000.0, 2.0, 1e-3};

// MuJoCo 2.2.2 preallocates the contact list (nconmax) and the constraint rows (njmax).
// Its mjData also holds efc_AR, njmax x njmax doubles and as many ints, in one buffer
// whose size is an int, so njmax must stay below ~13000. Each of the 15 capsules can
// touch each leaf once; a contact takes 4 rows (condim 3, MuJoCo's default pyramidal
// cone), a joint limit one.
struct Capacity {
  int nconmax, njmax;
};
constexpr size_t kMaxContacts = 3000;  // the grasp of 10^4 leaves peaks at ~2300

Capacity capacity(size_t leaves) {
  const int contacts = static_cast<int>(
      std::clamp<size_t>(FRUSTA_HAND_SEGMENT_COUNT * leaves, 1, kMaxContacts));
  return {contacts, 4 * contacts + FRUSTA_HAND_JOINT_COUNT};
}

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};
using ModelPtr = std::unique_ptr<mjModel, ModelDeleter>;
using DataPtr = std::unique_ptr<mjData, DataDeleter>;

// MuJoCo prints warnings to stdout, which would corrupt the benchmark's JSON; the run
// reads mjData::warning instead.
class QuietWarnings {
 public:
  QuietWarnings() : saved_(mju_user_warning) { mju_user_warning = [](const char*) {}; }
  ~QuietWarnings() { mju_user_warning = saved_; }
  QuietWarnings(const QuietWarnings&) = delete;
  QuietWarnings& operator=(const QuietWarnings&) = delete;

 private:
  void (*saved_)(const char*);
};

std::string finger_joint_name(int finger, int joint) {
  return "f" + std::to_string(finger) + "j" + std::to_string(joint);
}

void write_vec(std::ostream& out, const vec3& v) { out << v.x << ' ' << v.y << ' ' << v.z; }

void write_quat(std::ostream& out, const glm::dquat& q) {
  out << q.w << ' ' << q.x << ' ' << q.y << ' ' << q.z;  // MJCF order: w x y z
}

// A body's placement in its parent's frame.
void write_placement(std::ostream& out, const vec3& position, const glm::dmat3& rotation) {
  out << " pos=\"";
  write_vec(out, position);
  out << "\" quat=\"";
  write_quat(out, glm::quat_cast(rotation));
  out << '"';
}

void write_hinge(std::ostream& out, const HandModel& model, int finger, int joint, const vec3& axis) {
  const FingerModel& f = model.fingers[finger];
  out << "<joint name=\"" << finger_joint_name(finger, joint) << "\" axis=\"";
  write_vec(out, axis);
  out << "\" range=\"" << f.joint_min[joint] << ' ' << f.joint_max[joint] << "\"/>\n";
}

// The MJCF of the grasp. Each phalanx is a body whose frame is Frusta's segment frame
// at zero angles (origin at the proximal joint, x along the segment), taken from
// forward_kinematics in the hand frame, so MuJoCo's hinges reproduce Frusta's chain
// exactly, left hands (mirrored frames) included: abduction and flexion 1 in the first
// body (MuJoCo turns a body's later joints with its earlier ones, as Frusta's
// base * Rz(abduction) * Ry(flexion) does), flexions 2 and 3 in the next two.
std::string grasp_xml(const HandModel& model, const std::vector<Sphere>& leaves,
                      const HandState& palm, const Servo& servo, const Capacity& cap,
                      double contact_time_constant) {
  HandPose rest;
  forward_kinematics(model, HandState{}, rest);  // hand frame: palm at the origin

  std::ostringstream out;
  out.precision(17);
  out << "<mujoco model=\"frusta_peer\">\n"
         "<compiler angle=\"radian\"/>\n"
         "<option timestep=\"0.001\"/>\n"
      << "<size nconmax=\"" << cap.nconmax << "\" njmax=\"" << cap.njmax << "\"/>\n"
      << "<default>\n"
         "<joint type=\"hinge\" limited=\"true\" damping=\"" << servo.damping
      << "\" armature=\"" << servo.armature << "\"/>\n"
      << "<position kp=\"" << servo.kp << "\"/>\n"
      // fingers collide only with the ball: finger-finger and leaf-leaf pairs fail
      // MuJoCo's contype/conaffinity test
      << "<geom contype=\"1\" conaffinity=\"0\"";
  // on every geom: MuJoCo mixes the two geoms' solref of a contact
  if (contact_time_constant > 0.0) out << " solref=\"" << contact_time_constant << " 1\"";
  out << "/>\n"
         "<default class=\"leaf\"><geom type=\"sphere\" contype=\"0\" conaffinity=\"1\"/></default>\n"
         "</default>\n"
         "<worldbody>\n";
  if (!leaves.empty()) {
    out << "<body name=\"ball\" childclass=\"leaf\">\n";  // no joint: fixed in the world
    for (const Sphere& leaf : leaves) {
      out << "<geom size=\"" << leaf.radius << "\" pos=\"";
      write_vec(out, leaf.center);
      out << "\"/>\n";
    }
    out << "</body>\n";
  }
  out << "<body name=\"palm\" mocap=\"true\"";
  write_placement(out, palm.palm_position, glm::mat3_cast(palm.palm_rotation));
  out << ">\n";
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    const FingerPose& p = rest.fingers[f];
    for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s) {
      const glm::dmat3& frame = p.segment_rotation[s];
      const glm::dmat3 parent = s == 0 ? glm::dmat3(1.0) : p.segment_rotation[s - 1];
      const vec3 parent_origin = s == 0 ? vec3(0.0) : p.joint[s - 1];
      out << "<body name=\"f" << f << 's' << s << '"';
      write_placement(out, glm::transpose(parent) * (p.joint[s] - parent_origin),
                      glm::transpose(parent) * frame);
      out << ">\n";
      if (s == 0) write_hinge(out, model, f, 0, glm::transpose(frame) * p.abduction_axis);
      write_hinge(out, model, f, s + 1, glm::transpose(frame) * p.flexion_axis);
      // a capsule of the mean of the frustum's end radii: MuJoCo has no frustum
      const FingerModel& fm = model.fingers[f];
      out << "<geom type=\"capsule\" fromto=\"0 0 0 " << fm.length[s] << " 0 0\" size=\""
          << 0.5 * (fm.radius[s] + fm.radius[s + 1]) << "\"/>\n";
    }
    for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s) out << "</body>\n";
  }
  out << "</body>\n</worldbody>\n<actuator>\n";
  // declared in Frusta's finger-major order, so ctrl[i] drives HandState::angles[i]; the
  // joints are declared in that order too, so qpos[i] is angles[i]
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
    for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j)
      out << "<position joint=\"" << finger_joint_name(f, j) << "\"/>\n";
  out << "</actuator>\n</mujoco>\n";
  return out.str();
}

ModelPtr load_xml(const std::string& xml, std::string& error) {
  constexpr const char* kName = "frusta_peer.xml";
  const auto vfs = std::make_unique<mjVFS>();  // megabytes of name slots: not on the stack
  mj_defaultVFS(vfs.get());
  if (mj_makeEmptyFileVFS(vfs.get(), kName, static_cast<int>(xml.size())) != 0) {
    error = "MuJoCo VFS refused the model file";
    return nullptr;
  }
  std::memcpy(vfs->filedata[mj_findFileVFS(vfs.get(), kName)], xml.data(), xml.size());
  char message[1000] = "";
  ModelPtr model(mj_loadXML(kName, vfs.get(), message, sizeof message));
  mj_deleteVFS(vfs.get());
  if (!model) error = std::string("mj_loadXML: ") + message;
  return model;
}

// The haptic hand as MuJoCo inputs: the palm's mocap pose and the servos' targets.
void apply_haptic(const HandState& haptic, mjData* d) {
  d->mocap_pos[0] = haptic.palm_position.x;
  d->mocap_pos[1] = haptic.palm_position.y;
  d->mocap_pos[2] = haptic.palm_position.z;
  d->mocap_quat[0] = haptic.palm_rotation.w;
  d->mocap_quat[1] = haptic.palm_rotation.x;
  d->mocap_quat[2] = haptic.palm_rotation.y;
  d->mocap_quat[3] = haptic.palm_rotation.z;
  std::copy(haptic.angles.begin(), haptic.angles.end(), d->ctrl);
}


// A warning that makes the run's numbers meaningless, if MuJoCo raised one.
const char* fatal_warning(const mjData* d) {
  struct Named {
    int warning;
    const char* what;
  };
  static const Named kFatal[] = {
      {mjWARN_CONTACTFULL, "contact list full (nconmax): contacts were dropped"},
      {mjWARN_CNSTRFULL, "constraint rows full (njmax): contacts were dropped"},
      {mjWARN_BADQPOS, "bad qpos: the simulation diverged and was reset"},
      {mjWARN_BADQVEL, "bad qvel: the simulation diverged and was reset"},
      {mjWARN_BADQACC, "bad qacc: the simulation diverged and was reset"},
  };
  for (const Named& w : kFatal)
    if (d->warning[w.warning].number > 0) return w.what;
  return nullptr;
}

}  // namespace

PeerResult run_mujoco_grasp(const HandModel& model, const std::vector<Sphere>& leaves,
                            int32_t steps, const std::function<HandState(int32_t)>& haptic,
                            double contact_time_constant) {
  PeerResult result;
  if (steps <= 0) {
    result.error = "no steps to run";
    return result;
  }
  const QuietWarnings quiet;
  HandState start = haptic(0);
  clamp_to_limits(model, start);
  const std::string xml = grasp_xml(model, leaves, start, kServo, capacity(leaves.size()), contact_time_constant);
  const auto load_begin = std::chrono::steady_clock::now();
  ModelPtr m = load_xml(xml, result.error);
  result.load_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - load_begin).count();
  if (!m) return result;
  DataPtr d(mj_makeData(m.get()));
  if (!d) {
    result.error = "mj_makeData failed";
    return result;
  }
  // start at rest on the first haptic hand
  std::copy(start.angles.begin(), start.angles.end(), d->qpos);
  apply_haptic(start, d.get());
  mj_forward(m.get(), d.get());

  std::vector<double> step_us(static_cast<size_t>(steps));
  double deepest = 0.0;
  for (int32_t t = 0; t < steps; ++t) {
    HandState target = haptic(t);
    clamp_to_limits(model, target);  // a servo told past a joint limit only pushes into it
    apply_haptic(target, d.get());
    const auto begin = std::chrono::steady_clock::now();
    mj_step(m.get(), d.get());
    const auto end = std::chrono::steady_clock::now();
    step_us[static_cast<size_t>(t)] = std::chrono::duration<double, std::micro>(end - begin).count();
    for (int i = 0; i < d->ncon; ++i) deepest = std::max(deepest, -d->contact[i].dist);
    result.max_contacts = std::max(result.max_contacts, static_cast<int32_t>(d->ncon));
  }

  result.steps = steps;
  result.p50_us = percentile(step_us, 0.5);
  result.p99_us = percentile(step_us, 0.99);
  result.max_us = percentile(step_us, 1.0);
  result.max_penetration_mm = deepest * 1e3;
  if (const char* warning = fatal_warning(d.get())) result.error = warning;
  result.ok = result.error.empty();
  return result;
}

}  // namespace frusta::bench
