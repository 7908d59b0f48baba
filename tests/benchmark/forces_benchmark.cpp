// SPDX-License-Identifier: MIT
// tools/bench forces: the contact forces' cost next to their error, in one run.
//  - ContactForces::update + compute_device_outputs per step for 1..256 contacts over
//    the hand's 16 bodies and 4 objects: p50 / p99 per step and per contact, and how far
//    the objects' reactions are from balancing the hand's forces (0 but for rounding);
//  - an index fingertip pressed 1, 3, 6 mm into the top face of a box baked to 1, 0.25,
//    0.1 mm, stepped through a World: its total normal force against the exact
//    stiffness x depth of the haptic fingertip below the true face, next to the world's
//    step time and the leaves it touches; then slid along the face at constant speed:
//    the steady friction against mu |F| (exact Coulomb).
// Prints one JSON document. Arguments name the sections to run (time press; default
// all); flags such as tools/bench's --benchmark_format are ignored.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include <glm/geometric.hpp>

#include "forces/contact_forces.h"
#include "core/error.h"
#include "forces/device_outputs.h"
#include "hand/anthropometry.h"
#include "hand/hand_model.h"
#include "core/step_histogram.h"
#include "runtime/world.h"
#include "bench_sections.h"
#include "scenes/baked_objects.h"
#include "scenes/hand_scenarios.h"

namespace frusta {
namespace {

using Clock = std::chrono::steady_clock;

double micros(Clock::duration d) { return std::chrono::duration<double, std::micro>(d).count(); }

void check(frusta_result r, const char* what) {
  if (r == FRUSTA_OK) return;
  std::fprintf(stderr, "frusta_bench_forces: %s failed: %s\n", what, frusta::last_error_message());
  std::exit(1);
}

// --- time: the forces alone, on made-up contacts -------------------------------------

void time_forces(int32_t n, bool last) {
  const HandModel model = make_hand_model(default_hand_def());
  HandState state = scenes::open_hand();
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) scenes::set_flexion(state, f, 0.5, 0.5, 0.5);
  HandPose graphic, haptic;
  haptic_hand_pose(model, state, graphic);
  const std::shared_ptr<const TreeFile> ball = scenes::ball_shell(50, 0.03);
  constexpr int32_t kObjects = 4;
  std::vector<SolverObject> objects;
  for (int o = 0; o < kObjects; ++o)
    objects.push_back({&ball->tree, {vec3(0.1, 0.03 * o - 0.045, -0.05), glm::dmat3(1.0)}});
  const std::vector<ForceMaterial> materials(kObjects);
  // contact i on body i mod 16 and object (i / 16) mod 4: patches of up to 4 contacts,
  // each on its body's surface with a normal within 17 degrees of +z
  std::vector<SolverContact> contacts(static_cast<size_t>(n));
  for (int32_t i = 0; i < n; ++i) {
    SolverContact& c = contacts[static_cast<size_t>(i)];
    c.body = i % kBodyCount;
    c.object = (i / kBodyCount) % kObjects;
    c.leaf = i;
    c.normal = glm::normalize(vec3(0.3 * std::sin(i), 0.3 * std::cos(i), 1.0));
    if (c.body == kPalmBody) {
      c.part = i % static_cast<int32_t>(model.palm_spheres.size());
      const Sphere p = palm_sphere(model, graphic, c.part);
      c.hand_point = p.center - p.radius * c.normal;
    } else {
      const Segment s = finger_segment(model, graphic, c.body / FRUSTA_SEGMENTS_PER_FINGER,
                                       c.body % FRUSTA_SEGMENTS_PER_FINGER);
      c.hand_point = 0.5 * (s.proximal + s.distal) - s.distal_radius * c.normal;
    }
    c.object_point = c.hand_point;
  }
  // the haptic hand 1 mm lower (every contact presses) and swaying 0.5 mm to and fro
  // along x, so that patches stick and slip in turn
  ContactForces forces(n);
  DeviceOutputs out;
  std::vector<ObjectWrench> reactions(kObjects);
  StepHistogram update_us, device_us, both_us;
  int64_t pressing = 0, slipping = 0;
  constexpr int kWarm = 500, kMeasured = 20000;
  for (int t = 0; t < kWarm + kMeasured; ++t) {
    HandState moved = state;
    moved.palm_position = vec3(0.0005 * std::sin(2.0 * M_PI * t / 200.0), 0.0, -0.001);
    haptic_hand_pose(model, moved, haptic);
    ContactForceStats stats;
    // the objects no force names keep their reaction: zero, as the world keeps them
    std::fill(reactions.begin(), reactions.end(), ObjectWrench{});
    const Clock::time_point t0 = Clock::now();
    forces.update(graphic, haptic, contacts.data(), n, objects.data(), kObjects, materials.data(),
                  &stats);
    const Clock::time_point t1 = Clock::now();
    compute_device_outputs(haptic, forces.forces().data(), n, objects.data(), kObjects,
                           DeviceLimits{}, &out, reactions.data());
    const Clock::time_point t2 = Clock::now();
    if (t < kWarm) continue;
    update_us.record(micros(t1 - t0));
    device_us.record(micros(t2 - t1));
    both_us.record(micros(t2 - t0));
    pressing += stats.pressing;
    slipping += stats.slipping;
  }
  // Newton's third law, which compute_device_outputs must keep exactly
  vec3 on_hand(0.0), on_objects(0.0);
  double scale = 0.0;
  for (const ContactForce& c : forces.forces()) {
    on_hand += c.normal_force + c.friction;
    scale += glm::length(c.normal_force + c.friction);
  }
  for (const ObjectWrench& w : reactions) on_objects += w.force;
  std::printf("  {\"contacts\": %d, \"patches\": %d, \"steps\": %d, \"p50_ns\": %.0f, \"p99_ns\": %.0f, "
              "\"max_ns\": %.0f, \"p50_ns_per_contact\": %.1f, \"p99_ns_per_contact\": %.1f, "
              "\"update_p50_ns\": %.0f, \"device_outputs_p50_ns\": %.0f, \"slipping_share\": %.2f, "
              "\"reaction_imbalance\": %.2e}%s\n",
              n, std::min(n, kBodyCount * kObjects), kMeasured, 1e3 * both_us.percentile(0.5),
              1e3 * both_us.percentile(0.99), 1e3 * both_us.max(), 1e3 * both_us.percentile(0.5) / n,
              1e3 * both_us.percentile(0.99) / n, 1e3 * update_us.percentile(0.5),
              1e3 * device_us.percentile(0.5), static_cast<double>(slipping) / static_cast<double>(std::max<int64_t>(1, pressing)),
              glm::length(on_hand + on_objects) / std::max(scale, 1e-300), last ? "" : ",");
}

// --- press and slide: a fingertip on a baked box, through a World ---------------------

constexpr int kIndex = 1;
constexpr int kIndexTip = kIndex * FRUSTA_SEGMENTS_PER_FINGER + 2;
const vec3 kBoxSize(0.03, 0.03, 0.02);  // metres

// The index fingertip's lowest point (world z) at `state`: the lower of its two end balls,
// since the frustum between them is the hull of their rims, which lie on the balls. In
// the pose below it is the tip ball's, over the face.
double lowest_tip_z(const HandModel& model, const HandState& state) {
  HandPose pose;
  haptic_hand_pose(model, state, pose);
  const Segment s = finger_segment(model, pose, kIndex, 2);
  return std::min(s.proximal.z - s.proximal_radius, s.distal.z - s.distal_radius);
}

struct TipForces {
  vec3 normal{0.0}, friction{0.0};
  double gap = 0.0;  // mean |P_ig - P_ih| over the pressing contacts, metres
  int32_t contacts = 0, pressing = 0, elsewhere = 0, dropped = 0;
};

TipForces tip_forces(const HandSnapshot& h) {
  TipForces t;
  const int32_t kept = std::min(h.contact_count, static_cast<int32_t>(h.forces.size()));
  for (int32_t i = 0; i < kept; ++i) {
    const ContactForce& c = h.forces[static_cast<size_t>(i)];
    if (c.body != kIndexTip) {
      ++t.elsewhere;
      continue;
    }
    ++t.contacts;
    if (glm::length(c.normal_force) == 0.0) continue;
    ++t.pressing;
    t.gap += glm::length(c.graphic_point - c.haptic_point);
    t.normal += c.normal_force;
    t.friction += c.friction;
  }
  t.gap /= std::max(1, t.pressing);
  t.dropped = h.force_stats.dropped;
  return t;
}

// The index, bent to point down, is lowered `depth` onto the top face of a 3 x 3 x 2 cm
// box (kinematic: once the solver has converged the press has settled), then slides
// 1 cm along +x at 2 cm/s.
void press_and_slide(std::shared_ptr<const TreeFile> box, double bake_error, double depth, bool last) {
  const HandModel model = make_hand_model(default_hand_def());
  HandState hand = scenes::open_hand();
  scenes::set_flexion(hand, kIndex, 0.6, 0.6, 0.4);
  HandPose pose;
  haptic_hand_pose(model, hand, pose);
  const vec3 tip = pose.fingers[kIndex].joint[3];
  const double face = lowest_tip_z(model, hand);  // the true face touches the unlowered tip
  ObjectDef def;
  def.pose.position = vec3(tip.x + 0.005, tip.y, face - 0.5 * kBoxSize.z);  // 5 mm to slide into
  World world(WorldDef{});
  HandHandle index;
  check(world.add_hand(model, &index), "add_hand");
  ObjectHandle handle;
  check(world.add_object(box, def, &handle), "add_object");
  const double k = def.material.normal_stiffness.z, mu = def.material.friction;

  // lowered over 100 steps, held 200
  StepHistogram press_us;
  HandState haptic = hand;
  for (int t = 0; t < 300; ++t) {
    haptic.palm_position.z = -depth * std::min(1.0, t / 100.0);
    world.set_haptic(index, haptic);
    world.step();
    press_us.record(world.read().step_us);
  }
  const HandSnapshot& held = *world.read().hand(index);
  const TipForces pressed = tip_forces(held);
  const double exact_depth = face - lowest_tip_z(model, held.haptic);
  const double exact = k * exact_depth;
  const double above = lowest_tip_z(model, held.graphic) - face;  // the graphic tip's standoff
  const double turn = 2.0 * std::acos(std::min(1.0, std::fabs(glm::dot(held.graphic.palm_rotation,
                                                                       held.haptic.palm_rotation))));

  // slide 1 cm; the second half is steady sliding (the stick spring slips within
  // ~0.1 mm): the friction against mu |F| of the same step and of the exact force
  constexpr int kSlide = 500;
  constexpr double kSpeed = 0.02;  // m/s
  StepHistogram slide_us;
  double worst_coulomb = 0.0, worst_exact = 0.0, worst_normal = 0.0, worst_against = 1.0, sum = 0.0;
  int32_t slipping = 0, window = 0, most_pressing = 0;
  for (int t = 1; t <= kSlide; ++t) {
    haptic.palm_position.x = kSpeed * 1e-3 * t;
    world.set_haptic(index, haptic);
    world.step();
    const HandSnapshot& h = *world.read().hand(index);
    slide_us.record(world.read().step_us);
    if (t <= kSlide / 2) continue;
    const TipForces f = tip_forces(h);
    const double exact_now = k * (face - lowest_tip_z(model, h.haptic));
    const double friction = glm::length(f.friction), normal = glm::length(f.normal);
    worst_coulomb = std::max(worst_coulomb, std::fabs(friction - mu * normal) / (mu * normal));
    worst_exact = std::max(worst_exact, std::fabs(friction - mu * exact_now) / (mu * exact_now));
    worst_normal = std::max(worst_normal, std::fabs(normal - exact_now) / exact_now);
    worst_against = std::min(worst_against, -f.friction.x / std::max(friction, 1e-300));
    most_pressing = std::max(most_pressing, f.pressing);
    slipping += h.force_stats.slipping > 0 ? 1 : 0;
    sum += friction;
    ++window;
  }
  // rel_error < 0: weaker than exact; tilt: the force's angle off the face's normal; the
  // gap, the graphic tip's standoff from the true face (< 0: inside it) and the palm's
  // turn say where an error comes from
  std::printf("  {\"bake_error_mm\": %g, \"leaves\": %zu, \"depth_mm\": %g, \"exact_depth_mm\": %.4f, "
              "\"force_n\": %.5f, \"exact_n\": %.5f, \"rel_error\": %.4f, \"tilt_deg\": %.2f, "
              "\"gap_mm\": %.4f, \"graphic_above_face_mm\": %.4f, \"palm_turn_deg\": %.3f, \"contacts\": %d, "
              "\"leaves_pressing\": %d, \"contacts_elsewhere\": %d, \"dropped\": %d, "
              "\"step_p50_us\": %.1f, \"step_p99_us\": %.1f,\n"
              "   \"slide\": {\"speed_mm_s\": %g, \"steps\": %d, \"slipping_share\": %.2f, "
              "\"friction_mean_n\": %.5f, \"rel_error_vs_mu_F\": %.2e, \"rel_error_vs_mu_exact\": %.4f, "
              "\"normal_rel_error\": %.4f, \"min_cos_against_slide\": %.5f, \"max_leaves_pressing\": %d, "
              "\"step_p50_us\": %.1f, \"step_p99_us\": %.1f}}%s\n",
              bake_error * 1e3, box->tree.leaves.size(), depth * 1e3, exact_depth * 1e3,
              glm::length(pressed.normal), exact, glm::length(pressed.normal) / exact - 1.0,
              std::acos(std::min(1.0, pressed.normal.z / glm::length(pressed.normal))) * 180.0 / M_PI,
              pressed.gap * 1e3, above * 1e3, turn * 180.0 / M_PI, pressed.contacts, pressed.pressing, pressed.elsewhere,
              pressed.dropped, press_us.percentile(0.5), press_us.percentile(0.99), kSpeed * 1e3, window,
              static_cast<double>(slipping) / std::max(1, window), sum / std::max(1, window), worst_coulomb,
              worst_exact, worst_normal, worst_against, most_pressing, slide_us.percentile(0.5),
              slide_us.percentile(0.99), last ? "" : ",");
}

}  // namespace
}  // namespace frusta

int main(int argc, char** argv) {
  using namespace frusta;
  const bench::Sections sections(argc, argv);
  auto wanted = [&](const char* section) { return sections.wanted(section); };
  std::printf("{\n\"suite\": \"forces\",\n\"hardware_threads\": %u,\n", std::thread::hardware_concurrency());
  std::printf("\"material\": {\"normal_stiffness_n_per_m\": %g, \"friction\": %g, \"tangential_stiffness_n_per_m\": %g},\n",
              kDefaultContactStiffness, ForceMaterial{}.friction, ForceMaterial{}.tangential_stiffness);
  if (wanted("time")) {
    std::printf("\"update_and_device_outputs\": [\n");
    const int32_t counts[] = {1, 8, 32, 128, 256};
    for (size_t i = 0; i < std::size(counts); ++i) time_forces(counts[i], i + 1 == std::size(counts));
    std::printf("],\n");
  }
  if (wanted("press")) {
    std::printf("\"fingertip_on_box\": [\n");
    const double errors[] = {0.001, 0.00025, 0.0001}, depths[] = {0.001, 0.003, 0.006};
    for (size_t e = 0; e < std::size(errors); ++e) {
      const std::shared_ptr<const TreeFile> box = scenes::baked_box(kBoxSize, errors[e]);
      for (size_t d = 0; d < std::size(depths); ++d)
        press_and_slide(box, errors[e], depths[d], e + 1 == std::size(errors) && d + 1 == std::size(depths));
    }
    std::printf("],\n");
  }
  std::printf("\"end\": true\n}\n");
  return 0;
}
