// SPDX-License-Identifier: MIT
// Random objects and haptic paths for the random-scene tests of the solver and the world
// (and the bitwise equality by which each compares itself with a twin):
// trees of random leaves (clouds, thin shells, duplicated and zero-radius leaves, a lone
// leaf) at random scales, and paths that drift, sweep centimetres a step, jump deep into
// objects, land anywhere near and aim past the joints' limits.
#pragma once

#include <cstring>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.h"
#include "hand/kinematics.h"
#include "scenes/random_hands.h"
#include "scenes/random_trees.h"
#include "spheretree/tree_builder.h"
#include "spheretree/tree_file.h"

namespace frusta::scenes {

// a and b equal to the bit (for types whose bytes are all their fields: HandState,
// SolverContact, vectors of doubles)
template <class T>
bool same_bits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

inline glm::dquat random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  return glm::normalize(glm::dquat(g(rng), g(rng), g(rng), g(rng)));
}

// 1-1500 leaves of one of random_leaves' kinds, or a lone leaf; scaled 0.2-1.5 (objects
// of 4 cm to 30 cm); branching 2-8.
inline std::shared_ptr<const TreeFile> random_object_tree(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> kind(0, 4), branching(2, 8), count(1, 1500);
  std::uniform_real_distribution<double> scale(0.2, 1.5);
  const int k = kind(rng);
  std::vector<Sphere> leaves =
      k == 4 ? std::vector<Sphere>{{vec3(0.0), 0.01}} : testing::random_leaves(rng, count(rng), k);
  const double s = scale(rng);
  for (Sphere& leaf : leaves) {
    leaf.center *= s;
    leaf.radius *= s;
  }
  auto file = std::make_shared<TreeFile>();
  if (build_sphere_tree(leaves, {branching(rng)}, &file->tree) != FRUSTA_OK)
    throw std::runtime_error(std::string("a random tree: ") + last_error_message());
  return file;
}

// The next haptic hand after `now` (its angles within the limits first): a drift, a sweep
// of 1-6 cm, a jump with the palm into one of `centres` (the objects'), or a hand
// anywhere within 15 cm of `origin` in any pose; its angles at times aimed up to 2 rad
// past the joints' limits (which the solver clamps), always a valid input.
inline HandState next_random_haptic(std::mt19937_64& rng, const HandModel& model,
                                    const std::vector<vec3>& centres, const vec3& origin,
                                    const HandState& now) {
  std::uniform_real_distribution<double> u(0.0, 1.0), unit(-1.0, 1.0);
  std::normal_distribution<double> g;
  HandState next = now;
  clamp_to_limits(model, next);  // an aim past the limits is one step's, not a drift's
  const double kind = u(rng);
  if (kind < 0.55) {
    next.palm_position += 0.003 * vec3(g(rng), g(rng), g(rng));
    for (double& a : next.angles) a += 0.05 * g(rng);
    next.palm_rotation = glm::normalize(
        next.palm_rotation * glm::dquat(1.0, 0.02 * g(rng), 0.02 * g(rng), 0.02 * g(rng)));
  } else if (kind < 0.8) {
    next.palm_position += (0.01 + 0.05 * u(rng)) * glm::normalize(vec3(g(rng), g(rng), g(rng)));
    for (double& a : next.angles) a += 0.3 * g(rng);
  } else if (kind < 0.92 && !centres.empty()) {
    std::uniform_int_distribution<size_t> which(0, centres.size() - 1);
    next.palm_position = centres[which(rng)] + 0.02 * vec3(unit(rng), unit(rng), unit(rng));
    next.palm_rotation = random_rotation(rng);
  } else {
    next = random_hand_state(model, rng);
    next.palm_position = origin + 0.15 * vec3(unit(rng), unit(rng), unit(rng));
  }
  if (u(rng) < 0.1)
    for (double& a : next.angles) a += 2.0 * unit(rng);
  return next;
}

}  // namespace frusta::scenes
