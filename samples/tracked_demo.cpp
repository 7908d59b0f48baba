// SPDX-License-Identifier: MIT
// frusta_tracked_demo TRACKED.csv SCENE.csv OBJECTS_DIR [--trace TRACE.csv] [--host-steps]
//                     [--noise MM] [--seed N] [--noise-joints all|palm|fingers] [--min-cutoff HZ] [--beta B] [--d-cutoff HZ]
//                     [--smooth HZ] [--check] [--check-carry CM]
//
// The demo for hand tracking: a tracked-joint recording (samples/data/demo_tracked.csv,
// OpenXR's 26 joints at 90 Hz, written by frusta-make-recording) fitted frame by frame
// into the palm pose and joint angles of a world hand, which pinches a marble, lifts and
// carries it and lets it fall. The tracked hand closes into the marble as a real one
// would (a tracker knows nothing of the marble); the graphic hand stays outside it, and
// the forces printed are what a force-feedback glove on that hand would receive.
// SCENE.csv is the glove demo's recording (samples/data/demo_glove.csv), whose object
// and event rows are the scene this script was made in; its frames are not used.
//
// Everything but the recording goes through the C ABI (frusta.h), as a host would; the
// recording is read by Frusta's reader (tracking/joint_recording.h), which is not in the
// C ABI. The world runs on its own 1 kHz thread; every millisecond this thread sets the
// hand's input to the fits of the two tracked frames around that time, interpolated (the
// tracker's 90 Hz, played at the world's rate, as the glove demo plays its 100 Hz).
//
// --host-steps steps the world from this thread instead, one step per millisecond of
// recording time, as fast as it goes: deterministic, for tests.
// --noise MM adds Gaussian noise of MM millimetres (sigma, per axis) to every joint's
// position before the fit, as a tracker's jitter (seeded: the same on every run); the
// fit's residuals and the forces then show what an unfiltered real tracker would give.
// --seed N draws that noise from seed N (default 1); --noise-joints palm|fingers puts it
// on the palm-rigid joints only (the palm's fit) or on the fingers' moving joints only.
// Each frame is fitted at its time (frusta_hand_fitter_fit_at) through the fitter's One
// Euro filter, the default def's unless --min-cutoff (0: off), --beta or --d-cutoff say
// otherwise. The filtered palm's lag behind the true palm (a noise-free fit of the
// recording) is printed: the delay of the true palm that best matches the filtered one.
// --smooth HZ passes the fits through a first-order low-pass of that cutoff (palm,
// rotation and angles alike) before the world sees them, as a host would filter a
// real tracker's; the residuals are the unfiltered fits'.
// --check exits non-zero unless every frame fitted (finite residuals under 0.1 mm, no
// frame held), the graphic hand never sank more than 0.1 mm into an object, the marble
// was carried at least 10 cm up and then fell, and the thumb and index received finite
// forces through the carry (in 95 % of its steps at least); with noise, the residual and
// pinch-share checks are left out (a jittered fit cannot fit closely). --check-carry CM
// asks for CM cm of carry instead of 10.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "frusta/frusta.h"
#include "tracking/joint_recording.h"

namespace {

constexpr int kMaxContacts = 256;
constexpr double kMaxDepth = 1e-4;      // metres: the graphic hand is outside the object
constexpr double kMaxResidual = 1e-4;   // metres: a model-made recording fits closely
constexpr double kCarryFrom = 2.2, kCarryTo = 3.8;  // seconds: the marble held in the pinch
const char* const kFingerNames[FRUSTA_FINGER_COUNT] = {"thumb", "index", "middle", "ring",
                                                       "little"};

struct SceneObject {
  std::string name, sample;
  frusta_object_def def{};
  frusta_object_id id{};
  frusta_tree_id tree{};
};

struct SceneEvent {
  double time = 0.0;
  std::string kind, name;
  int value = 0;
  bool done = false;
};

bool check(frusta_result result, const char* what) {
  if (result == FRUSTA_OK) return true;
  std::fprintf(stderr, "frusta_tracked_demo: %s failed: %s\n", what, frusta_last_error());
  return false;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  size_t start = 0;
  for (size_t comma; (comma = line.find(',', start)) != std::string::npos; start = comma + 1)
    fields.push_back(line.substr(start, comma - start));
  fields.push_back(line.substr(start));
  return fields;
}

// the object and event rows of the glove demo's recording (its format:
// samples/recording/make_recording.cpp); frames are skipped
bool load_scene(const char* path, std::vector<SceneObject>* objects, std::vector<SceneEvent>* events) {
  std::FILE* file = std::fopen(path, "r");
  if (!file) {
    std::fprintf(stderr, "frusta_tracked_demo: cannot open %s\n", path);
    return false;
  }
  char buffer[4096];
  bool ok = true;
  while (ok && std::fgets(buffer, sizeof buffer, file)) {
    std::string line(buffer);
    line.erase(line.find_last_not_of("\r\n") + 1);
    if (line.rfind("object,", 0) == 0) {
      const std::vector<std::string> f = split(line);
      ok = f.size() == 15;
      if (!ok) break;
      SceneObject o;
      o.name = f[1];
      o.sample = f[2];
      o.def = frusta_default_object_def();
      for (int k = 0; k < 3; ++k) o.def.pose.position[k] = std::atof(f[3 + k].c_str());
      for (int k = 0; k < 4; ++k) o.def.pose.rotation[k] = std::atof(f[6 + k].c_str());
      o.def.dynamic = std::atoi(f[10].c_str());
      o.def.mass = std::atof(f[11].c_str());
      o.def.friction = std::atof(f[12].c_str());
      o.def.normal_damping = std::atof(f[13].c_str());
      o.def.tangential_damping = std::atof(f[14].c_str());
      // as the glove demo: a solid of its mass about 2 cm across
      for (int k = 0; k < 3; ++k) o.def.inertia[k] = 0.4 * o.def.mass * 0.01 * 0.01;
      o.def.linear_damping = o.def.angular_damping = 0.5;
      objects->push_back(o);
    } else if (line.rfind("event,", 0) == 0) {
      const std::vector<std::string> f = split(line);
      ok = f.size() == 5;
      if (!ok) break;
      events->push_back({std::atof(f[1].c_str()), f[2], f[3], std::atoi(f[4].c_str()), false});
    }
  }
  std::fclose(file);
  if (!ok || objects->empty()) {
    std::fprintf(stderr, "frusta_tracked_demo: %s: not a demo scene (object and event rows)\n", path);
    return false;
  }
  return true;
}

// Whether joint j of a layout moves with the palm (the joints the palm is fitted to):
// OpenXR's palm, wrist and four metacarpals; the keypoints' wrist and four knuckles.
bool palm_rigid(int32_t layout, int j) {
  if (layout == FRUSTA_JOINT_LAYOUT_XR) return j == 0 || j == 1 || (j >= 6 && (j - 6) % 5 == 0);
  return j == 0 || (j >= 5 && (j - 5) % 4 == 0);
}

frusta_tracked_joint to_abi(const frusta::TrackedJoint& j) {
  frusta_tracked_joint out{};
  for (int k = 0; k < 3; ++k) out.position[k] = j.position[k];
  out.rotation[0] = j.rotation.x;
  out.rotation[1] = j.rotation.y;
  out.rotation[2] = j.rotation.z;
  out.rotation[3] = j.rotation.w;
  out.radius = j.radius;
  out.flags = j.flags;
  return out;
}

// a hand input between two fits: palm and angles straight, the rotation by the shorter way
void mix_fits(const frusta_hand_fit& a, const frusta_hand_fit& b, double u, frusta_pose* palm,
              double* angles) {
  double dot = 0.0;
  for (int k = 0; k < 4; ++k) dot += a.palm.rotation[k] * b.palm.rotation[k];
  const double sign = dot < 0.0 ? -1.0 : 1.0;
  for (int k = 0; k < 3; ++k)
    palm->position[k] = a.palm.position[k] + u * (b.palm.position[k] - a.palm.position[k]);
  for (int k = 0; k < 4; ++k)
    palm->rotation[k] = a.palm.rotation[k] + u * (sign * b.palm.rotation[k] - a.palm.rotation[k]);
  for (int j = 0; j < FRUSTA_HAND_JOINT_COUNT; ++j)
    angles[j] = a.angles[j] + u * (b.angles[j] - a.angles[j]);
}

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  return values[static_cast<size_t>(p * static_cast<double>(values.size() - 1) + 0.5)];
}

struct Tally {
  double deepest = 0.0;         // metres, the graphic hand into any object
  double haptic_deepest = 0.0;  // metres, the tracked hand past the graphic one's surface
  double peak[FRUSTA_FINGER_COUNT] = {}, sum[FRUSTA_FINGER_COUNT] = {};
  long touching[FRUSTA_FINGER_COUNT] = {};
  bool finite = true;
  long carry_ticks = 0, carry_pinched = 0;  // steps of the carry, and those thumb and index push
  double peak_palm = 0.0;
  double marble_start_z = NAN, marble_top_z = -1e9, marble_end_z = NAN;
  long ticks = 0;
};

bool observe(frusta_world_id world, frusta_hand_id hand_id, const SceneObject& marble, double now,
             Tally* t, std::FILE* trace) {
  frusta_world_state state{};
  state.struct_size = sizeof state;
  frusta_world_hand hand{};
  hand.struct_size = sizeof hand;
  static frusta_world_contact contacts[kMaxContacts];
  int32_t count = 0;
  if (!check(frusta_world_read(world, &state), "frusta_world_read")) return false;
  if (state.step == 0) return true;
  if (!check(frusta_world_get_hand(world, hand_id, &hand), "frusta_world_get_hand")) return false;
  if (!check(frusta_world_get_contacts(world, hand_id, contacts, kMaxContacts, &count), "get_contacts"))
    return false;
  count = std::min(count, kMaxContacts);  // the rest were not copied
  double deepest = 0.0, haptic = 0.0;
  for (int i = 0; i < count; ++i) {
    const frusta_world_contact& c = contacts[i];
    deepest = std::max(deepest, -c.distance);
    // how far the tracked hand's point lies past the graphic hand's, along the normal
    double past = -c.distance;
    for (int k = 0; k < 3; ++k) past += (c.graphic_point[k] - c.haptic_point[k]) * c.normal[k];
    haptic = std::max(haptic, past);
  }
  t->deepest = std::max(t->deepest, deepest);
  t->haptic_deepest = std::max(t->haptic_deepest, haptic);
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    const double force = hand.finger_resistance[f];
    if (!std::isfinite(force)) t->finite = false;
    t->peak[f] = std::max(t->peak[f], force);
    if (force > 0.0) {
      t->sum[f] += force;
      ++t->touching[f];
    }
  }
  if (now >= kCarryFrom && now <= kCarryTo) {
    ++t->carry_ticks;
    if (hand.finger_resistance[FRUSTA_FINGER_THUMB] > 0.0 &&
        hand.finger_resistance[FRUSTA_FINGER_INDEX] > 0.0)
      ++t->carry_pinched;
  }
  const double palm = std::sqrt(hand.palm_force[0] * hand.palm_force[0] +
                                hand.palm_force[1] * hand.palm_force[1] +
                                hand.palm_force[2] * hand.palm_force[2]);
  t->peak_palm = std::max(t->peak_palm, palm);
  double marble_z = NAN;
  frusta_object_state object{};
  object.struct_size = sizeof object;
  if (!FRUSTA_IS_NULL(marble.id) && frusta_world_get_object(world, marble.id, &object) == FRUSTA_OK) {
    marble_z = object.pose.position[2];
    if (std::isnan(t->marble_start_z)) t->marble_start_z = marble_z;
    t->marble_top_z = std::max(t->marble_top_z, marble_z);
    t->marble_end_z = marble_z;
  }
  ++t->ticks;
  if (trace) {
    std::fprintf(trace, "%.4f,%llu,%.2f,%lld,%d,%.4f", state.time,
                 static_cast<unsigned long long>(state.step), state.step_us,
                 static_cast<long long>(state.overruns), count, 1e3 * deepest);
    for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) std::fprintf(trace, ",%.4f", hand.finger_resistance[f]);
    std::fprintf(trace, ",%.4f,%.5f,%.4f\n", palm, marble_z, 1e3 * haptic);
  }
  return true;
}

bool apply_events(std::vector<SceneEvent>* events, std::vector<SceneObject>* objects,
                  frusta_world_id world, double now) {
  for (SceneEvent& e : *events) {
    if (e.done || e.time > now) continue;
    e.done = true;
    for (SceneObject& o : *objects) {
      if (o.name != e.name || FRUSTA_IS_NULL(o.id)) continue;
      if (e.kind == "dynamic") {
        if (!check(frusta_world_set_object_dynamic(world, o.id, e.value), "set_object_dynamic"))
          return false;
      } else if (e.kind == "remove") {
        if (!check(frusta_destroy_object(o.id), "destroy_object")) return false;
        o.id = frusta_object_id{};
      }
    }
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: frusta_tracked_demo TRACKED.csv SCENE.csv OBJECTS_DIR "
                         "[--trace TRACE.csv] [--host-steps] [--noise MM] [--seed N] [--noise-joints WHICH] "
                         "[--min-cutoff HZ] [--beta B] [--d-cutoff HZ] [--smooth HZ] [--check] "
                         "[--check-carry CM]\n");
    return 2;
  }
  const char* trace_path = nullptr;
  bool check_mode = false, host_steps = false;
  double noise = 0.0;   // metres
  double smooth = 0.0;  // Hz; 0: none
  unsigned long seed = 1;
  int noise_joints = 0;  // 0 all, 1 the palm-rigid ones, 2 the fingers' moving ones
  double check_carry = 0.10;  // metres
  frusta_hand_fit_def fit_def = frusta_default_hand_fit_def();
  const auto number = [&](int* i, const char* name, double lo, double hi, double* out) {
    *out = std::atof(argv[++*i]);
    if (*out >= lo && *out <= hi) return true;
    std::fprintf(stderr, "frusta_tracked_demo: %s takes %g..%g\n", name, lo, hi);
    return false;
  };
  for (int i = 4; i < argc; ++i) {
    if (std::strcmp(argv[i], "--check") == 0) {
      check_mode = true;
    } else if (std::strcmp(argv[i], "--host-steps") == 0) {
      host_steps = true;
    } else if (std::strcmp(argv[i], "--trace") == 0 && i + 1 < argc) {
      trace_path = argv[++i];
    } else if (std::strcmp(argv[i], "--noise") == 0 && i + 1 < argc) {
      noise = 1e-3 * std::atof(argv[++i]);
      if (!(noise >= 0.0 && noise <= 0.05)) {
        std::fprintf(stderr, "frusta_tracked_demo: --noise takes 0..50 mm\n");
        return 2;
      }
    } else if (std::strcmp(argv[i], "--noise-joints") == 0 && i + 1 < argc) {
      const char* which = argv[++i];
      noise_joints = std::strcmp(which, "all") == 0 ? 0 : std::strcmp(which, "palm") == 0 ? 1
                     : std::strcmp(which, "fingers") == 0 ? 2 : -1;
      if (noise_joints < 0) {
        std::fprintf(stderr, "frusta_tracked_demo: --noise-joints takes all, palm or fingers\n");
        return 2;
      }
    } else if (std::strcmp(argv[i], "--seed") == 0 && i + 1 < argc) {
      seed = std::strtoul(argv[++i], nullptr, 10);
    } else if (std::strcmp(argv[i], "--min-cutoff") == 0 && i + 1 < argc) {
      if (!number(&i, "--min-cutoff", 0.0, 1000.0, &fit_def.filter_min_cutoff)) return 2;
    } else if (std::strcmp(argv[i], "--beta") == 0 && i + 1 < argc) {
      if (!number(&i, "--beta", 0.0, 1000.0, &fit_def.filter_beta)) return 2;
    } else if (std::strcmp(argv[i], "--d-cutoff") == 0 && i + 1 < argc) {
      if (!number(&i, "--d-cutoff", 1e-3, 1000.0, &fit_def.filter_d_cutoff)) return 2;
    } else if (std::strcmp(argv[i], "--check-carry") == 0 && i + 1 < argc) {
      if (!number(&i, "--check-carry", 0.0, 100.0, &check_carry)) return 2;
      check_carry *= 1e-2;
    } else if (std::strcmp(argv[i], "--smooth") == 0 && i + 1 < argc) {
      smooth = std::atof(argv[++i]);
      if (!(smooth >= 0.0 && smooth <= 1000.0)) {
        std::fprintf(stderr, "frusta_tracked_demo: --smooth takes 0..1000 Hz\n");
        return 2;
      }
    } else {
      std::fprintf(stderr, "frusta_tracked_demo: unknown argument %s\n", argv[i]);
      return 2;
    }
  }
  if (!check(FRUSTA_CHECK_ABI(), "the ABI check")) return 1;
  frusta::JointRecording rec;
  if (!check(frusta::load_joint_recording(argv[1], &rec), argv[1])) return 1;
  std::vector<SceneObject> objects;
  std::vector<SceneEvent> events;
  if (!load_scene(argv[2], &objects, &events)) return 1;
  const int joint_count =
      rec.layout == FRUSTA_JOINT_LAYOUT_XR ? FRUSTA_XR_JOINT_COUNT : FRUSTA_KEYPOINT_COUNT;
  // a tracker's jitter, on every joint the calibration and the fit see
  // the true palm, for the lag: the noise-free recording's fits
  const std::vector<frusta::TrackedJoint> clean_joints = rec.joints;
  if (noise > 0.0) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> jitter(0.0, noise);
    size_t index = 0;
    for (frusta::TrackedJoint& joint : rec.joints) {
      const bool palm = palm_rigid(rec.layout, static_cast<int>(index++ % static_cast<size_t>(joint_count)));
      const bool jittered = noise_joints == 0 || (noise_joints == 1) == palm;
      for (int k = 0; k < 3; ++k) {
        const double n = jitter(rng);  // drawn for every joint: the same draw whichever are jittered
        if (jittered) joint.position[k] += n;
      }
    }
  }

  // the hand the joints are of, sized from the recording's first second as a game would
  // size its user's, then a fitter for it
  frusta_hand_def hand_def = frusta_default_hand_def();
  hand_def.side = rec.side;
  const double default_length = hand_def.hand_length, default_breadth = hand_def.hand_breadth;
  {
    const int32_t frames = std::min<int32_t>(rec.frame_count(), 90);
    std::vector<frusta_tracked_joint> calibration;
    for (int32_t i = 0; i < frames; ++i)
      for (int j = 0; j < joint_count; ++j) calibration.push_back(to_abi(rec.frame(i)[j]));
    if (!check(frusta_calibrate_hand_def(calibration.data(), frames, rec.layout, &hand_def),
               "frusta_calibrate_hand_def"))
      return 1;
  }
  fit_def.layout = rec.layout;
  frusta_hand_fitter_id fitter;
  if (!check(frusta_create_hand_fitter(&hand_def, &fit_def, &fitter), "frusta_create_hand_fitter"))
    return 1;
  std::vector<frusta_pose> true_palm;
  {
    frusta_hand_fit_def unfiltered = fit_def;
    unfiltered.filter_min_cutoff = 0.0;
    frusta_hand_fitter_id clean;
    if (!check(frusta_create_hand_fitter(&hand_def, &unfiltered, &clean), "frusta_create_hand_fitter"))
      return 1;
    frusta_tracked_joint joints[frusta::kMaxTrackedJoints];
    for (int32_t i = 0; i < rec.frame_count(); ++i) {
      for (int j = 0; j < joint_count; ++j)
        joints[j] = to_abi(clean_joints[static_cast<size_t>(i * joint_count + j)]);
      frusta_hand_fit fit{};
      fit.struct_size = sizeof fit;
      if (!check(frusta_hand_fitter_fit(clean, joints, joint_count, nullptr, &fit), "the true fit"))
        return 1;
      true_palm.push_back(fit.palm);
    }
    frusta_destroy_hand_fitter(clean);
  }

  frusta_world_def def = frusta_default_world_def();
  def.gravity[2] = -9.81;
  frusta_world_id world;
  if (!check(frusta_create_world(&def, &world), "frusta_create_world")) return 1;
  frusta_hand_id hand;
  if (!check(frusta_create_world_hand(world, &hand_def, &hand), "frusta_create_world_hand")) return 1;
  for (SceneObject& o : objects) {
    const std::string path = std::string(argv[3]) + "/" + o.sample + ".frtree";
    if (!check(frusta_create_sphere_tree_from_file(path.c_str(), &o.tree), path.c_str())) return 1;
    if (!check(frusta_create_object(world, o.tree, &o.def, &o.id), o.name.c_str())) return 1;
  }
  std::FILE* trace = nullptr;
  if (trace_path) {
    trace = std::fopen(trace_path, "w");
    if (!trace) {
      std::fprintf(stderr, "frusta_tracked_demo: cannot write %s\n", trace_path);
      return 1;
    }
    std::fprintf(trace, "time_s,step,step_us,overruns,contacts,penetration_mm");
    for (const char* name : kFingerNames) std::fprintf(trace, ",%s_N", name);
    std::fprintf(trace, ",palm_N,marble_z_m,tracked_past_graphic_mm\n");
  }

  const double start = rec.times.front(), duration = rec.times.back() - start;
  char noise_text[48] = "";
  if (noise > 0.0)
    std::snprintf(noise_text, sizeof noise_text, " with %.1f mm of noise (seed %lu)%s", 1e3 * noise,
                  seed, smooth > 0.0 ? ", smoothed" : "");
  std::printf("Frusta %d.%d.%d tracked-hand demo: %d objects, %.1f s of %s joints of a %s hand "
              "at %.0f Hz%s, %s\n",
              FRUSTA_VERSION_MAJOR, FRUSTA_VERSION_MINOR, FRUSTA_VERSION_PATCH,
              static_cast<int>(objects.size()), duration,
              rec.layout == FRUSTA_JOINT_LAYOUT_XR ? "OpenXR's 26" : "21 keypoint",
              rec.side == FRUSTA_HAND_LEFT ? "left" : "right", (rec.frame_count() - 1) / duration,
              noise_text,
              host_steps ? "stepped by the host" : "the world on its own thread");

  std::printf("  hand calibrated from the first %.1f s: length %.1f mm, breadth %.1f mm (the "
              "default hand that made it: %.1f, %.1f)\n",
              rec.times[static_cast<size_t>(std::min<int32_t>(rec.frame_count(), 90) - 1)] - start,
              1e3 * hand_def.hand_length, 1e3 * hand_def.hand_breadth, 1e3 * default_length,
              1e3 * default_breadth);

  // the fits of the frames so far (a frame is fitted once, when the replay reaches it)
  std::vector<frusta_hand_fit> fits;
  std::vector<double> residuals[FRUSTA_FINGER_COUNT], palm_residuals, fit_us;
  long held = 0, clamped = 0;
  frusta_tracked_joint joints[frusta::kMaxTrackedJoints];
  const auto fit_next = [&]() -> bool {
    const int32_t i = static_cast<int32_t>(fits.size());
    for (int j = 0; j < joint_count; ++j) joints[j] = to_abi(rec.frame(i)[j]);
    frusta_hand_fit fit{};
    fit.struct_size = sizeof fit;
    const auto before = std::chrono::steady_clock::now();
    if (!check(frusta_hand_fitter_fit_at(fitter, rec.times[static_cast<size_t>(i)], joints,
                                         joint_count, nullptr, &fit),
               "frusta_hand_fitter_fit_at"))
      return false;
    fit_us.push_back(
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - before).count());
    if (fit.palm_flags & (FRUSTA_FIT_HELD | FRUSTA_FIT_NO_HISTORY)) ++held;
    palm_residuals.push_back(fit.palm_residual);
    for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
      residuals[f].push_back(fit.finger_residual[f]);
      if (fit.finger_flags[f] & FRUSTA_FIT_HELD) ++held;
      if (fit.finger_flags[f] & FRUSTA_FIT_CLAMPED) ++clamped;
    }
    // a first-order low-pass of the fits, frame by frame (the shorter way round for the
    // rotation; the world normalises it)
    if (smooth > 0.0 && !fits.empty()) {
      const double dt = rec.times[static_cast<size_t>(i)] - rec.times[static_cast<size_t>(i) - 1];
      const double a = 1.0 - std::exp(-2.0 * 3.141592653589793 * smooth * dt);
      frusta_hand_fit filtered = fit;
      mix_fits(fits.back(), fit, a, &filtered.palm, filtered.angles);
      double norm = 0.0;
      for (double q : filtered.palm.rotation) norm += q * q;
      for (double& q : filtered.palm.rotation) q /= std::sqrt(norm);
      fit.palm = filtered.palm;
      std::copy(filtered.angles, filtered.angles + FRUSTA_HAND_JOINT_COUNT, fit.angles);
    }
    fits.push_back(fit);
    return true;
  };

  Tally t;
  const long tick_ns = static_cast<long>(1e9 / def.rate_hz);
  bool ok = host_steps || check(frusta_world_start(world), "frusta_world_start");
  const SceneObject& marble = objects.front();
  auto deadline = std::chrono::steady_clock::now();
  int32_t frame = 0;  // the tracked frame at or before now
  for (long tick = 0; ok && static_cast<double>(tick) * 1e-9 * static_cast<double>(tick_ns) <= duration;
       ++tick) {
    const double now = static_cast<double>(tick) * 1e-9 * static_cast<double>(tick_ns);
    while (frame + 2 < rec.frame_count() && rec.times[static_cast<size_t>(frame + 1)] - start <= now) ++frame;
    while (ok && static_cast<int32_t>(fits.size()) < std::min(frame + 2, rec.frame_count())) ok = fit_next();
    if (!ok) break;
    const int32_t next = std::min(frame + 1, rec.frame_count() - 1);
    const double span = rec.times[static_cast<size_t>(next)] - rec.times[static_cast<size_t>(frame)];
    const double u = span > 0.0 ? std::clamp((now - (rec.times[static_cast<size_t>(frame)] - start)) / span, 0.0, 1.0)
                                : 0.0;
    frusta_pose palm;
    double angles[FRUSTA_HAND_JOINT_COUNT];
    mix_fits(fits[static_cast<size_t>(frame)], fits[static_cast<size_t>(next)], u, &palm, angles);
    ok = check(frusta_world_set_haptic(world, hand, &palm, angles, FRUSTA_HAND_JOINT_COUNT), "set_haptic") &&
         apply_events(&events, &objects, world, now);
    if (ok && host_steps) ok = check(frusta_world_step(world), "frusta_world_step");
    if (ok) ok = observe(world, hand, marble, now, &t, trace);
    if (!host_steps) {
      deadline += std::chrono::nanoseconds(tick_ns);
      std::this_thread::sleep_until(deadline);
    }
  }
  if (!host_steps) frusta_world_stop(world);
  frusta_world_state state{};
  state.struct_size = sizeof state;
  if (ok) ok = check(frusta_world_read(world, &state), "frusta_world_read");
  if (trace) std::fclose(trace);
  if (!ok) return 1;

  std::printf("\n  steps %llu in %.2f s of world time", static_cast<unsigned long long>(state.step),
              state.time);
  if (!host_steps)
    std::printf(", achieved %.1f Hz, %lld overruns", state.achieved_rate_hz,
                static_cast<long long>(state.overruns));
  std::printf("\n  step time        p50 %7.1f us   p99 %7.1f us   max %7.1f us\n", state.step_us_p50,
              state.step_us_p99, state.step_us_max);
  if (!host_steps)
    std::printf("  wake-up late     p50 %7.1f us   p99 %7.1f us   max %7.1f us\n",
                state.wake_late_us_p50, state.wake_late_us_p99, state.wake_late_us_max);
  std::printf("  fit              p50 %7.1f us   max %7.1f us   (%zu frames; %ld held, %ld clamped)\n",
              percentile(fit_us, 0.5), percentile(fit_us, 1.0), fits.size(), held, clamped);

  // the lag: the delay of the true palm that best matches the filtered one (1 ms steps)
  double lag = 0.0, lag_rms = INFINITY, peak_speed = 0.0;
  for (size_t i = 1; i < true_palm.size(); ++i) {
    double d2 = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double d = true_palm[i].position[k] - true_palm[i - 1].position[k];
      d2 += d * d;
    }
    peak_speed = std::max(peak_speed, std::sqrt(d2) / (rec.times[i] - rec.times[i - 1]));
  }
  for (int shift_ms = 0; shift_ms <= 300; ++shift_ms) {
    double sum = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < fits.size(); ++i) {
      const double when = rec.times[i] - 1e-3 * shift_ms;
      if (when < rec.times.front()) continue;
      const size_t k = static_cast<size_t>(
          std::upper_bound(rec.times.begin(), rec.times.end(), when) - rec.times.begin() - 1);
      const size_t k1 = std::min(k + 1, true_palm.size() - 1);
      const double span = rec.times[k1] - rec.times[k];
      const double u = span > 0.0 ? (when - rec.times[k]) / span : 0.0;
      for (int c = 0; c < 3; ++c) {
        const double truth = true_palm[k].position[c] + u * (true_palm[k1].position[c] - true_palm[k].position[c]);
        const double d = fits[i].palm.position[c] - truth;
        sum += d * d;
      }
      ++n;
    }
    const double rms = std::sqrt(sum / static_cast<double>(n));
    if (rms < lag_rms) {
      lag_rms = rms;
      lag = 1e-3 * shift_ms;
    }
  }
  if (fit_def.filter_min_cutoff > 0.0)
    std::printf("  filter           One Euro, min_cutoff %g Hz, beta %g /m, d_cutoff %g Hz\n",
                fit_def.filter_min_cutoff, fit_def.filter_beta, fit_def.filter_d_cutoff);
  else
    std::printf("  filter           off\n");
  std::printf("  palm lag         %.0f ms behind the true palm (RMS %.2f mm there; peak palm "
              "speed %.2f m/s)\n", 1e3 * lag, 1e3 * lag_rms, peak_speed);

  double worst_residual = percentile(palm_residuals, 1.0);
  std::printf("\n  fit residual (RMS over the joints, per frame)\n  %-8s %10s %10s\n", "", "p50 mm",
              "max mm");
  std::printf("  %-8s %10.4f %10.4f\n", "palm", 1e3 * percentile(palm_residuals, 0.5),
              1e3 * percentile(palm_residuals, 1.0));
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    std::printf("  %-8s %10.4f %10.4f\n", kFingerNames[f], 1e3 * percentile(residuals[f], 0.5),
                1e3 * percentile(residuals[f], 1.0));
    worst_residual = std::max(worst_residual, percentile(residuals[f], 1.0));
  }
  std::printf("\n  deepest penetration of the graphic hand %.4f mm (exact, against the leaves);\n"
              "  the tracked hand reached %.2f mm past it; rejected inputs %lld\n",
              1e3 * t.deepest, 1e3 * t.haptic_deepest, static_cast<long long>(state.rejected_inputs));
  std::printf("\n  force a glove would receive (finger resistance)\n  %-8s %10s %10s %12s\n", "finger",
              "peak N", "mean N", "touching s");
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
    std::printf("  %-8s %10.3f %10.3f %12.2f\n", kFingerNames[f], t.peak[f],
                t.touching[f] ? t.sum[f] / static_cast<double>(t.touching[f]) : 0.0,
                static_cast<double>(t.touching[f]) * 1e-9 * static_cast<double>(tick_ns));
  std::printf("  %-8s %10.3f\n", "palm", t.peak_palm);
  const double lifted = t.marble_top_z - t.marble_start_z;
  const double pinched = t.carry_ticks ? static_cast<double>(t.carry_pinched) / static_cast<double>(t.carry_ticks) : 0.0;
  std::printf("\n  marble: carried %.1f cm up in the pinch (thumb and index pushing in %.1f %% of the "
              "carry's steps), then fell to %.1f cm below where it lay\n",
              1e2 * lifted, 1e2 * pinched, 1e2 * (t.marble_start_z - t.marble_end_z));
  if (trace_path) std::printf("  trace: %s\n", trace_path);

  for (SceneObject& o : objects) frusta_destroy_sphere_tree(o.tree);
  frusta_destroy_world(world);
  frusta_destroy_hand_fitter(fitter);
  if (!check_mode) return 0;
  int failed = 0;
  const auto failure = [&](const char* format, double value) {
    std::fprintf(stderr, "check: ");
    std::fprintf(stderr, format, value);
    std::fprintf(stderr, "\n");
    failed = 1;
  };
  if (noise == 0.0 && !(worst_residual <= kMaxResidual))
    failure("a fit residual of %.4f mm", 1e3 * worst_residual);
  if (held > 0) failure("%.0f fits held a finger or the palm", static_cast<double>(held));
  if (!(t.deepest <= kMaxDepth)) failure("the graphic hand sank %.4f mm", 1e3 * t.deepest);
  if (!(lifted >= check_carry))
    failure("the marble rose %.1f cm, short of the carry asked for", 1e2 * lifted);
  if (!(t.marble_end_z < t.marble_start_z)) failure("the marble did not fall (%.3f m)", t.marble_end_z);
  if (!t.finite) failure("a force was not finite (%g)", NAN);
  if (noise == 0.0 && !(pinched >= 0.95)) failure("thumb and index pushed in %.1f %% of the carry", 1e2 * pinched);
  if (!(t.peak[FRUSTA_FINGER_THUMB] > 0.0 && t.peak[FRUSTA_FINGER_INDEX] > 0.0))
    failure("no pinch force (index %.3f N)", t.peak[FRUSTA_FINGER_INDEX]);
  if (state.rejected_inputs != 0)
    failure("%.0f inputs were rejected", static_cast<double>(state.rejected_inputs));
  return failed;
}
