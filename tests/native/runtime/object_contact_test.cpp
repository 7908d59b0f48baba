// SPDX-License-Identifier: MIT
// Objects on objects (runtime/object_contact.h): dropped onto a table they come to rest
// on it, whatever their mass, stay there over a long run, and stack; a static table does
// not move. Host-stepped: no clocks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "runtime/scene_objects.h"
#include "runtime/world.h"
#include "scenes/baked_objects.h"

namespace frusta {
namespace {

constexpr double kTableTop = 0.015;  // samples/objects' table: a 3 cm top centred at 0
// the trees' bakes stand out of (or fall short of) their surfaces by up to this much
constexpr double kBakeSlack = 0.0025;

struct Dropped {
  const char* tree;
  double mass, half_height;  // kg; metres from its centre to the table when resting
  vec3 from;
};

WorldDef falling_world() {
  WorldDef def;
  def.gravity = vec3(0.0, 0.0, -9.81);
  return def;
}

ObjectHandle add(World& world, const char* tree, const vec3& at, double mass, bool dynamic) {
  ObjectHandle handle;
  EXPECT_EQ(world.add_object(scenes::sample_tree(tree), scenes::object_at(at, mass, dynamic), &handle),
            FRUSTA_OK);
  return handle;
}

TEST(ObjectContact, ObjectsDroppedOnATableComeToRestOnItAndStay) {
  World world(falling_world());
  const ObjectHandle table = add(world, "table", vec3(0.0), 1.0, false);
  // a 50 g marble, a 1 kg box (10 x 6 x 4 cm) and a 5 g ball: the contact is tuned to each
  // pair's mass, so each settles alike
  const Dropped dropped[] = {{"marble", 0.05, 0.0087, vec3(0.0, 0.0, 0.05)},
                             {"box", 1.0, 0.02, vec3(0.15, 0.2, 0.08)},
                             {"ball", 0.005, 0.04, vec3(-0.15, -0.2, 0.12)}};
  ObjectHandle handles[3];
  for (int i = 0; i < 3; ++i) handles[i] = add(world, dropped[i].tree, dropped[i].from, dropped[i].mass, true);
  // settled within 5 s (a tree's bumps slope its surface: an object rolls or slides into a
  // hollow of them before it rests; the ball, held by static friction, rolls to and fro
  // in one until rolling resistance stops it, 4.1 s); then 5 s more (a long run: an object
  // that creeps or sinks, or a contact that pumps energy in, shows)
  vec3 settled[3];
  double worst_drift = 0.0;
  for (int t = 1; t <= 10000; ++t) {
    world.step();
    const WorldSnapshot& snap = world.read();
    for (int i = 0; i < 3; ++i) {
      const ObjectSnapshot& o = snap.objects[static_cast<size_t>(handles[i].slot)];
      ASSERT_TRUE(std::isfinite(o.pose.position.z));
      EXPECT_GT(o.pose.position.z, kTableTop + dropped[i].half_height - kBakeSlack)
          << dropped[i].tree << ", step " << t << ": it sinks into the table";
      if (t == 5000) {
        settled[i] = o.pose.position;
        EXPECT_NEAR(o.pose.position.z, kTableTop + dropped[i].half_height, kBakeSlack) << dropped[i].tree;
        EXPECT_LT(glm::length(o.linear_velocity), SceneObjects::kSleepSpeed) << dropped[i].tree;
        std::printf("%-6s rests %.3f mm above the table top's nominal height\n", dropped[i].tree,
                    1e3 * (o.pose.position.z - kTableTop - dropped[i].half_height));
      }
      if (t > 5000) worst_drift = std::max(worst_drift, glm::length(o.pose.position - settled[i]));
    }
    const ObjectSnapshot& t0 = snap.objects[static_cast<size_t>(table.slot)];
    ASSERT_EQ(t0.pose.position, vec3(0.0)) << "the static table does not move";
  }
  EXPECT_LT(worst_drift, 1e-4) << "settled after 5 s, it stays for 5 more";
}

TEST(ObjectContact, ABoxStandsOnABoxOnTheTable) {
  World world(falling_world());
  add(world, "table", vec3(0.0), 1.0, false);
  const ObjectHandle lower = add(world, "box", vec3(0.0, 0.0, 0.04), 0.5, true);
  const ObjectHandle upper = add(world, "box", vec3(0.01, 0.0, 0.09), 0.2, true);
  for (int t = 0; t < 3000; ++t) world.step();
  const WorldSnapshot& snap = world.read();
  const ObjectSnapshot& a = snap.objects[static_cast<size_t>(lower.slot)];
  const ObjectSnapshot& b = snap.objects[static_cast<size_t>(upper.slot)];
  EXPECT_NEAR(a.pose.position.z, kTableTop + 0.02, kBakeSlack);
  EXPECT_NEAR(b.pose.position.z, kTableTop + 0.06, 2 * kBakeSlack) << "on the lower box";
  EXPECT_LT(glm::length(a.linear_velocity) + glm::length(b.linear_velocity), SceneObjects::kSleepSpeed);
}

// A 1 kg box let down onto the table tilted by `degrees` about y: where it rests on the
// slope, and its velocity down it, after `steps`.
struct OnSlope {
  vec3 settled, last;  // after 1 s, and at the end (the table's frame)
  double speed = 0.0;  // m/s, at the end
  bool asleep = false;
};
OnSlope box_on_slope(double degrees, int steps) {
  World world(falling_world());
  ObjectDef table = scenes::object_at(vec3(0.0), 1.0, false);
  table.pose.rotation =
      glm::dmat3(glm::rotate(glm::dmat4(1.0), glm::radians(degrees), vec3(0.0, 1.0, 0.0)));
  ObjectHandle handle;
  EXPECT_EQ(world.add_object(scenes::sample_tree("table"), table, &handle), FRUSTA_OK);
  ObjectDef box =
      scenes::object_at(table.pose.rotation * vec3(0.0, 0.0, kTableTop + 0.0205), 1.0, true);
  box.pose.rotation = table.pose.rotation;
  EXPECT_EQ(world.add_object(scenes::sample_tree("box"), box, &handle), FRUSTA_OK);
  OnSlope out;
  for (int t = 1; t <= steps; ++t) {
    world.step();
    const ObjectSnapshot& o = world.read().objects[static_cast<size_t>(handle.slot)];
    EXPECT_TRUE(std::isfinite(o.pose.position.x)) << "step " << t;
    const vec3 local = glm::transpose(table.pose.rotation) * o.pose.position;
    if (t == 1000) out.settled = local;
    out.last = local;
    out.speed = glm::length(o.linear_velocity);
    out.asleep = o.linear_velocity == vec3(0.0) && o.angular_velocity == vec3(0.0);
  }
  return out;
}

// Static friction: on a slope friction can hold (tan 15 degrees = 0.27, under the
// materials' 0.6) the box stays where it came to rest, and sleeps. With friction only
// damping the slide it crept down at g sin(theta) / (2 omega), 6.7 mm/s, for ever.
TEST(ObjectContact, ABoxStaysOnASlopeFrictionHolds) {
  const OnSlope s = box_on_slope(15.0, 4000);
  EXPECT_LT(glm::length(s.last - s.settled), 1e-4) << "from 1 s to 4 s it stays put";
  EXPECT_TRUE(s.asleep);
}

// ... and where the slope is steeper than friction holds (tan 40 degrees = 0.84), it
// slides down, at g (sin - 0.6 cos) = 1.8 m/s^2 (once the stick spring let go)
TEST(ObjectContact, ABoxSlidesDownASlopeSteeperThanFrictionHolds) {
  const OnSlope s = box_on_slope(40.0, 300);
  EXPECT_GT(s.speed, 0.3) << "0.3 s down the slope";
  EXPECT_LT(s.speed, 0.6) << "friction still brakes it";
}

// A stack falls asleep (SceneObjects::kSleepSeconds) and then costs nothing: an awake
// object that is itself still no longer wakes the sleeping one it rests on or under.
// Each woke the other in turn before, for ever: a box on a box stepped ~10 us a step
// at rest, and walked the pair (~0.5 ms) whenever their creep added up to the cache's
// margin.
TEST(ObjectContact, AStackOfBoxesFallsAsleep) {
  World world(falling_world());
  add(world, "table", vec3(0.0), 1.0, false);
  const ObjectHandle lower = add(world, "box", vec3(0.0, 0.0, kTableTop + 0.021), 1.0, true);
  const ObjectHandle upper = add(world, "box", vec3(0.005, 0.0, kTableTop + 0.08), 0.2, true);
  for (int t = 0; t < 4000; ++t) world.step();
  const ObjectSnapshot a = world.read().objects[static_cast<size_t>(lower.slot)];
  const ObjectSnapshot b = world.read().objects[static_cast<size_t>(upper.slot)];
  for (int t = 0; t < 1000; ++t) world.step();
  for (const auto& [then, handle] : {std::pair{a, lower}, std::pair{b, upper}}) {
    const ObjectSnapshot& now = world.read().objects[static_cast<size_t>(handle.slot)];
    EXPECT_EQ(now.linear_velocity, vec3(0.0)) << "slot " << handle.slot << " is asleep";
    EXPECT_EQ(now.angular_velocity, vec3(0.0)) << "slot " << handle.slot;
    EXPECT_EQ(now.pose.position, then.pose.position) << "slot " << handle.slot << " stays put";
  }
  EXPECT_NEAR(world.read().objects[static_cast<size_t>(upper.slot)].pose.position.z,
              kTableTop + 0.06, 2 * kBakeSlack)
      << "on the lower box";
}

}  // namespace
}  // namespace frusta
