// SPDX-License-Identifier: MIT
// A host's random session with the world, stepped on the host's thread: hands of random
// sizes added and removed, random objects added, moved, made dynamic and kinematic and
// removed (gravity on in some worlds, a level of detail in some), every hand driven
// along a random path, stale handles used as a host with old ones would. Every call is
// taken or refused with its code, and after every step each hand, force, device output
// and object in the snapshot is finite (a hand as valid as an input), each device output
// within its limits. A twin world fed the same calls makes the same snapshot to the bit:
// the runtime is deterministic, whatever its slots' history. FRUSTA_PROPERTY_CASES=N
// runs 8 N / 10^6 sessions (at least 2).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/gtc/quaternion.hpp>
#include <memory>
#include <random>
#include <vector>

#include "core/error.h"
#include "core/validate.h"
#include "hand/hand_model.h"
#include "hand/kinematics.h"
#include "runtime/world.h"
#include "scenes/random_cases.h"
#include "scenes/random_hands.h"
#include "scenes/random_scenes.h"

namespace frusta {
namespace {

using scenes::same_bits;

constexpr int kSessions = 8;
constexpr int kSteps = 150;

bool finite(const vec3& v) { return all_finite(&v[0], 3); }

// The same calls, made on both worlds, must answer alike.
struct Twins {
  World a, b;
  explicit Twins(const WorldDef& def) : a(def), b(def) {}
  template <class Call>
  frusta_result both(Call call) {
    const frusta_result r = call(a);
    EXPECT_EQ(call(b), r);
    return r;
  }
};

TEST(WorldRandom, RandomSessionsKeepEverythingFiniteAndTwinWorldsAlike) {
  const int sessions = scenes::scaled_case_count(kSessions, 2);
  std::mt19937_64 rng(scenes::kPropertySeed + 307);
  std::uniform_real_distribution<double> u(0.0, 1.0), unit(-1.0, 1.0);
  int64_t steps = 0, contacts = 0, refused = 0, forces = 0;
  for (int session = 0; session < sessions; ++session) {
    WorldDef def;
    def.max_objects = 12;
    def.max_hands = 3;
    def.realtime_priority = false;
    if (u(rng) < 0.5) def.gravity = vec3(0.0, 0.0, -9.81);
    if (u(rng) < 0.25) def.solver.lod_error = 0.002;
    Twins worlds(def);
    const vec3 origin =
        (u(rng) < 0.3 ? 50.0 : 0.0) * glm::normalize(vec3(unit(rng), unit(rng), unit(rng)));
    std::vector<HandHandle> hands, gone_hands;
    std::vector<HandModel> models;
    std::vector<HandState> haptics;
    std::vector<ObjectHandle> objects, gone_objects;
    std::vector<vec3> centres;
    for (int t = 0; t < kSteps; ++t) {
      SCOPED_TRACE(::testing::Message() << "session " << session << " step " << t);
      // hands come and go
      if (hands.size() < static_cast<size_t>(def.max_hands) && (hands.empty() || u(rng) < 0.02)) {
        models.push_back(make_hand_model(scenes::random_hand_def(u(rng) < 0.5 ? 0 : 1, rng)));
        HandHandle ha, hb;
        ASSERT_EQ(worlds.a.add_hand(models.back(), &ha), FRUSTA_OK);
        ASSERT_EQ(worlds.b.add_hand(models.back(), &hb), FRUSTA_OK);
        ASSERT_TRUE(same_bits(ha, hb));
        hands.push_back(ha);
        HandState start = scenes::random_hand_state(models.back(), rng);
        start.palm_position = origin + 0.1 * vec3(unit(rng), unit(rng), unit(rng));
        haptics.push_back(start);
      } else if (hands.size() > 1 && u(rng) < 0.01) {
        const size_t h = std::uniform_int_distribution<size_t>(0, hands.size() - 1)(rng);
        ASSERT_EQ(worlds.both([&](World& w) { return w.remove_hand(hands[h]); }), FRUSTA_OK);
        gone_hands.push_back(hands[h]);
        hands.erase(hands.begin() + static_cast<std::ptrdiff_t>(h));
        models.erase(models.begin() + static_cast<std::ptrdiff_t>(h));
        haptics.erase(haptics.begin() + static_cast<std::ptrdiff_t>(h));
      }
      // objects come, move, change kind and go
      const double action = u(rng);
      if (action < 0.08 && objects.size() < static_cast<size_t>(def.max_objects)) {
        ObjectDef object;
        object.pose = {origin + 0.12 * vec3(unit(rng), unit(rng), unit(rng)),
                       glm::mat3_cast(scenes::random_rotation(rng))};
        object.dynamic = u(rng) < 0.4;
        object.mass = 0.05 + u(rng);
        std::shared_ptr<const TreeFile> tree = scenes::random_object_tree(rng);
        ObjectHandle oa, ob;
        ASSERT_EQ(worlds.a.add_object(tree, object, &oa), FRUSTA_OK);
        ASSERT_EQ(worlds.b.add_object(tree, object, &ob), FRUSTA_OK);
        ASSERT_TRUE(same_bits(oa, ob));
        objects.push_back(oa);
        centres.push_back(object.pose.position);
      } else if (!objects.empty()) {
        const size_t o = std::uniform_int_distribution<size_t>(0, objects.size() - 1)(rng);
        if (action < 0.12) {
          ASSERT_EQ(worlds.both([&](World& w) { return w.remove_object(objects[o]); }), FRUSTA_OK);
          gone_objects.push_back(objects[o]);
          objects.erase(objects.begin() + static_cast<std::ptrdiff_t>(o));
          centres.erase(centres.begin() + static_cast<std::ptrdiff_t>(o));
        } else if (action < 0.3) {
          const RigidPose pose{
              centres[o] + (u(rng) < 0.1 ? 0.05 : 0.003) * vec3(unit(rng), unit(rng), unit(rng)),
              glm::mat3_cast(scenes::random_rotation(rng))};
          ASSERT_EQ(worlds.both([&](World& w) { return w.set_object_pose(objects[o], pose); }),
                    FRUSTA_OK);
          centres[o] = pose.position;
        } else if (action < 0.33) {
          const bool dynamic = u(rng) < 0.5;
          ASSERT_EQ(
              worlds.both([&](World& w) { return w.set_object_dynamic(objects[o], dynamic); }),
              FRUSTA_OK);
        }
      }
      // a host with stale handles is refused, and nothing changes
      if (!gone_objects.empty() && u(rng) < 0.05) {
        const ObjectHandle stale = gone_objects[gone_objects.size() - 1];
        EXPECT_NE(worlds.both([&](World& w) { return w.set_object_pose(stale, RigidPose{}); }),
                  FRUSTA_OK);
        ++refused;
      }
      if (!gone_hands.empty() && u(rng) < 0.05) {
        const HandHandle stale = gone_hands[gone_hands.size() - 1];
        EXPECT_NE(worlds.both([&](World& w) { return w.set_haptic(stale, HandState{}); }),
                  FRUSTA_OK);
        ++refused;
      }
      for (size_t h = 0; h < hands.size(); ++h) {
        haptics[h] = scenes::next_random_haptic(rng, models[h], centres, origin, haptics[h]);
        ASSERT_EQ(worlds.both([&](World& w) { return w.set_haptic(hands[h], haptics[h]); }),
                  FRUSTA_OK);
      }
      ASSERT_EQ(worlds.both([](World& w) { return w.step(); }), FRUSTA_OK);
      ++steps;

      const WorldSnapshot& a = worlds.a.read();
      const WorldSnapshot& b = worlds.b.read();
      for (const HandHandle& hand : hands) {
        const HandSnapshot* x = a.hand(hand);
        const HandSnapshot* y = b.hand(hand);
        ASSERT_NE(x, nullptr);
        ASSERT_NE(y, nullptr);
        ASSERT_EQ(check_hand_state(x->graphic, "graphic"), FRUSTA_OK) << last_error_message();
        ASSERT_TRUE(same_bits(x->graphic, y->graphic)) << "the twin worlds' hands differ";
        ASSERT_EQ(x->contact_count, y->contact_count);
        contacts += x->contact_count;
        // the kept contacts' forces (the snapshot's arrays are sized once, at the most kept)
        const size_t kept = std::min(static_cast<size_t>(x->contact_count), x->forces.size());
        for (size_t i = 0; i < kept; ++i) {
          const ContactForce& f = x->forces[i];
          ASSERT_TRUE(finite(f.normal_force) && finite(f.friction) && finite(f.graphic_point));
          ASSERT_TRUE(same_bits(f.normal_force, y->forces[i].normal_force) &&
                      same_bits(f.friction, y->forces[i].friction))
              << "the twin worlds' forces differ";
          ++forces;
        }
        const DeviceOutputs& d = x->device;
        const DeviceLimits& limits = def.device_limits;
        constexpr double kRounding = 1.0 + 1e-12;
        for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
          ASSERT_TRUE(finite(d.fingertip_force[f]) && std::isfinite(d.finger_resistance[f]));
          ASSERT_LE(glm::length(d.fingertip_force[f]), limits.max_fingertip_force * kRounding);
          ASSERT_LE(std::fabs(d.finger_resistance[f]), limits.max_finger_resistance * kRounding);
        }
        for (double torque : d.joint_torque)
          ASSERT_LE(std::fabs(torque), limits.max_joint_torque * kRounding);  // (false for NaN)
        ASSERT_TRUE(finite(d.palm_force) && finite(d.palm_torque));
        ASSERT_LE(glm::length(d.palm_force), limits.max_palm_force * kRounding);
        ASSERT_LE(glm::length(d.palm_torque), limits.max_palm_torque * kRounding);
      }
      for (size_t s = 0; s < a.objects.size(); ++s) {
        const ObjectSnapshot& x = a.objects[s];
        ASSERT_EQ(x.present, b.objects[s].present);
        if (!x.present) continue;
        ASSERT_TRUE(finite(x.pose.position) && finite(x.linear_velocity) &&
                    finite(x.angular_velocity));
        ASSERT_TRUE(finite(x.reaction.force) && finite(x.reaction.torque));
        ASSERT_TRUE(same_bits(x.pose.position, b.objects[s].pose.position) &&
                    same_bits(x.linear_velocity, b.objects[s].linear_velocity))
            << "the twin worlds' objects differ";
      }
    }
  }
  std::printf(
      "[ random sessions ] %d sessions, %lld steps, %lld contacts, %lld forces, %lld "
      "stale calls refused\n",
      sessions, static_cast<long long>(steps), static_cast<long long>(contacts),
      static_cast<long long>(forces), static_cast<long long>(refused));
  EXPECT_GT(contacts, steps / 4);  // the hands meet the objects
}

}  // namespace
}  // namespace frusta
