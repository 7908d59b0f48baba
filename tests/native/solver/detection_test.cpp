// SPDX-License-Identifier: MIT
// Contact prediction walks each tree once for many probes (issue 21), copies the
// candidates of the bodies that did not move since the last detection, and takes those of
// bodies that moved less than its room from a wider walk before: its candidates must be
// those of one walk per finger segment and per palm sphere, bit for bit, each body's in
// increasing order of their gap bounds (passes stop at the first out of reach), equal
// ones in the walk's order, since the solver's answer depends on their order.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include "hand/anthropometry.h"
#include "hand/hand_model.h"
#include "hand/kinematics.h"
#include "scenes/hand_scenarios.h"
#include "scenes/random_cases.h"
#include "solver/candidate_cache.h"
#include "solver/detection.h"
#include "solver/finger_motion.h"

namespace frusta {
namespace {

bool bounds_meet(const Sphere& a, const Sphere& b, double margin) {
  return glm::length(a.center - b.center) <= a.radius + b.radius + margin;
}

// Detection as it was: one walk per finger segment, then one per palm sphere, each from
// the root of every near object's tree.
std::vector<Candidate> walk_per_probe(const HandModel& model, const HandReach& reach,
                                      const HandPose& pose, const std::vector<SolverObject>& objects,
                                      double margin, TreeCut cut, int32_t begin[kBodyCount + 1],
                                      std::vector<TreeHit>& hits) {
  std::vector<Candidate> out;
  std::vector<int32_t> near;
  const Sphere hand_bound{pose.palm_position, reach.hand};
  for (int32_t o = 0; o < static_cast<int32_t>(objects.size()); ++o)
    if (!objects[o].tree->empty() && bounds_meet(hand_bound, object_bound(objects[o]), margin))
      near.push_back(o);
  const int32_t capacity = static_cast<int32_t>(hits.size());
  auto add = [&](int32_t o, int32_t count, int32_t part) {
    const SolverObject& obj = objects[static_cast<size_t>(o)];
    for (int32_t h = 0; h < count; ++h) {
      const TreeHit& hit = hits[static_cast<size_t>(h)];
      const Sphere local = hit.leaf >= 0 ? obj.tree->leaves[static_cast<size_t>(hit.leaf)]
                                         : obj.tree->node_sphere(hit.node);
      out.push_back({o,
                     hit.leaf,
                     part,
                     {obj.pose.rotation * local.center + obj.pose.position, local.radius},
                     {}});
    }
  };
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    const Sphere finger_bound{pose.fingers[f].joint[0], reach.finger[f]};
    for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s) {
      begin[f * FRUSTA_SEGMENTS_PER_FINGER + s] = static_cast<int32_t>(out.size());
      for (int32_t o : near) {
        const SolverObject& obj = objects[static_cast<size_t>(o)];
        if (!bounds_meet(finger_bound, object_bound(obj), margin)) continue;
        const SegmentFrame frame = make_segment_frame(to_object_frame(obj.pose, finger_segment(model, pose, f, s)));
        const TreeQueryStats stats = query_segment(*obj.tree, frame, margin, cut, hits.data(), capacity);
        EXPECT_LE(stats.hits, capacity);
        add(o, stats.hits, 0);
      }
    }
  }
  begin[kPalmBody] = static_cast<int32_t>(out.size());
  for (int32_t k = 0; k < static_cast<int32_t>(model.palm_spheres.size()); ++k) {
    const Sphere world = palm_sphere(model, pose, k);
    for (int32_t o : near) {
      const SolverObject& obj = objects[static_cast<size_t>(o)];
      if (!bounds_meet(world, object_bound(obj), margin)) continue;
      const TreeQueryStats stats =
          query_sphere(*obj.tree, to_object_frame(obj.pose, world), margin, cut, hits.data(), capacity);
      EXPECT_LE(stats.hits, capacity);
      add(o, stats.hits, k);
    }
  }
  begin[kBodyCount] = static_cast<int32_t>(out.size());
  return out;
}

// How far a body moved from where the set placed it to `pose`.
double moved_since_placed(const HandModel& model, const HandPose& pose, const CandidateSet& set, int body) {
  if (body == kPalmBody) return palm_move(model, set.placed.palm_position, set.placed.palm_rotation, pose);
  return segment_move(set.placed.segments[static_cast<size_t>(body)],
                      finger_segment(model, pose, body / FRUSTA_SEGMENTS_PER_FINGER, body % FRUSTA_SEGMENTS_PER_FINGER));
}

// The exact gaps between a body at `pose` and each of its candidates in a set.
std::vector<double> exact_gaps(const HandModel& model, const HandPose& pose, const CandidateSet& set, int body) {
  std::vector<double> gaps;
  const Candidate* c = set.of(body);
  const SegmentFrame frame = body == kPalmBody ? SegmentFrame{}
                                               : make_segment_frame(finger_segment(model, pose, body / FRUSTA_SEGMENTS_PER_FINGER,
                                                                                   body % FRUSTA_SEGMENTS_PER_FINGER));
  for (int32_t i = 0; i < set.count(body); ++i) {
    if (body != kPalmBody) {
      gaps.push_back(exact_distance(frame, c[i].world));
      continue;
    }
    const Sphere hand = palm_sphere(model, pose, c[i].part);
    gaps.push_back(glm::length(hand.center - c[i].world.center) - hand.radius - c[i].world.radius);
  }
  return gaps;
}

// A body's candidates in increasing order of their bounds' least, equal ones in the order
// they were found (`found`, where given: the k-th's position in a walk's list).
void expect_sorted(const CandidateSet& got, int body, const std::vector<int32_t>* found, const std::string& what) {
  const Candidate* c = got.of(body);
  for (int32_t i = 1; i < got.count(body); ++i) {
    ASSERT_LE(c[i - 1].gap.least, c[i].gap.least) << what << ", body " << body << ", candidate " << i;
    if (found && c[i - 1].gap.least == c[i].gap.least) {
      ASSERT_LT((*found)[static_cast<size_t>(i - 1)], (*found)[static_cast<size_t>(i)])
          << what << ", body " << body << ", candidate " << i;
    }
  }
}

// A body's candidates' bounds, widened by its move since the set placed it, hold the exact
// gap at `pose`.
void expect_bounds_hold(const HandModel& model, const HandPose& pose, const CandidateSet& got, int body,
                        const std::string& what) {
  const Candidate* c = got.of(body);
  const double moved = moved_since_placed(model, pose, got, body);
  const std::vector<double> exact = exact_gaps(model, pose, got, body);
  for (int32_t i = 0; i < got.count(body); ++i)
    ASSERT_TRUE(c[i].gap.least - moved <= std::max(exact[static_cast<size_t>(i)], 0.0) &&
                exact[static_cast<size_t>(i)] <= c[i].gap.most + moved)
        << what << ", body " << body << ", candidate " << i;
}

// A candidate's sphere, to match two lists by: its object, leaf, palm sphere and bits.
auto sphere_key(const Candidate& c) {
  return std::make_tuple(c.object, c.leaf, c.part, c.world.center.x, c.world.center.y, c.world.center.z,
                         c.world.radius);
}

// ... hashed, to sort by (a tuple's comparisons made the test four times slower).
uint64_t sphere_hash(const Candidate& c) {
  uint64_t h = 0xcbf29ce484222325ull;
  auto mix = [&](uint64_t v) { h = (h ^ v) * 0x100000001b3ull; };
  mix(static_cast<uint32_t>(c.object));
  mix(static_cast<uint32_t>(c.leaf));
  mix(static_cast<uint32_t>(c.part));
  for (double v : {c.world.center.x, c.world.center.y, c.world.center.z, c.world.radius}) {
    uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    mix(bits);
  }
  return h;
}

// The positions of `count` candidates in order of their spheres' hashes.
std::vector<int32_t> by_key(const Candidate* c, int32_t count) {
  std::vector<std::pair<uint64_t, int32_t>> keyed(static_cast<size_t>(count));
  for (int32_t i = 0; i < count; ++i) keyed[static_cast<size_t>(i)] = {sphere_hash(c[i]), i};
  std::sort(keyed.begin(), keyed.end());
  std::vector<int32_t> order(static_cast<size_t>(count));
  for (int32_t i = 0; i < count; ++i) order[static_cast<size_t>(i)] = keyed[static_cast<size_t>(i)].second;
  return order;
}

// The spheres of one walk per probe, each body's bit for bit, in the set's order (above).
void expect_same(const std::vector<Candidate>& expected,
                 const int32_t* expected_begin, const CandidateSet& got, const std::string& what) {
  int32_t total = 0;
  for (int body = 0; body < kBodyCount; ++body) {
    const int32_t count = expected_begin[body + 1] - expected_begin[body];
    ASSERT_EQ(count, got.count(body)) << what << ", body " << body;
    total += count;
    const Candidate* e = expected.data() + expected_begin[body];
    const Candidate* g = got.of(body);
    const std::vector<int32_t> e_order = by_key(e, count), g_order = by_key(g, count);
    std::vector<int32_t> found(static_cast<size_t>(count));  // each got's position in the walk's
    for (size_t k = 0; k < e_order.size(); ++k) {
      const Candidate &a = e[e_order[k]], &b = g[g_order[k]];
      ASSERT_TRUE(sphere_key(a) == sphere_key(b))
          << what << ", body " << body << ": object " << a.object << "/" << b.object << ", leaf " << a.leaf << "/"
          << b.leaf << ", part " << a.part << "/" << b.part;
      found[static_cast<size_t>(g_order[k])] = e_order[k];
    }
    expect_sorted(got, body, &found, what);
    if (testing::Test::HasFatalFailure()) return;
  }
  EXPECT_EQ(total, got.size()) << what;
}

glm::dmat3 random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> gauss;
  return glm::mat3_cast(glm::normalize(glm::dquat{gauss(rng), gauss(rng), gauss(rng), gauss(rng)}));
}

// A hand closed by a random amount and turned at random, and its pose.
void random_hand(const HandModel& model, std::mt19937_64& rng, HandState& state, HandPose& pose) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  state = scenes::open_hand();
  const double closed = unit(rng);
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) scenes::set_flexion(state, f, 1.6 * closed, 1.6 * closed, 1.6 * closed);
  state.palm_rotation = glm::quat_cast(random_rotation(rng));
  forward_kinematics(model, state, pose);
}

// Each body's clearance after the hand moved from where `set` was found, as a pass over
// the set finds it (stopping at the first candidate whose bound and the body's move rule
// it out, measuring only those that may sink in) and as every candidate measured: to the bit.
void expect_clearances(const HandModel& model, const HandPose& moved, const CandidateSet& set,
                       const std::string& what) {
  for (int body = 0; body < kBodyCount; ++body) {
    double every = 0.0;
    const Candidate* c = set.of(body);
    for (int32_t i = 0; i < set.count(body); ++i) {
      if (body == kPalmBody) {
        const Sphere hand = palm_sphere(model, moved, c[i].part);
        every = std::min(
            every, glm::length(hand.center - c[i].world.center) - hand.radius - c[i].world.radius);
      } else {
        const SegmentFrame frame = make_segment_frame(finger_segment(
            model, moved, body / FRUSTA_SEGMENTS_PER_FINGER, body % FRUSTA_SEGMENTS_PER_FINGER));
        every = std::min(every, exact_distance(frame, c[i].world));
      }
    }
    EXPECT_EQ(body_clearance(model, moved, set, body), every) << what << ", body " << body;
  }
}

// Hands closed by random amounts and moved about a ball, a box and a plate turned at
// random, so that fingers and palm cross them at every depth; leaves and both cuts.
// `full_draws` of them at the property tests' default count (scaled_case_count).
void check_random_hands(const HandModel& model, int32_t full_draws, uint64_t seed) {
  const int32_t draws = scenes::scaled_case_count(full_draws, 10);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0), offset(-0.06, 0.06);
  const HandReach reach = hand_reach(model);
  const std::shared_ptr<const TreeFile> ball = scenes::ball_shell(4000, 0.04);
  const std::shared_ptr<const TreeFile> box = scenes::sample_tree("box"), plate = scenes::sample_tree("plate");
  const TreeCut cuts[] = {TreeCut(), TreeCut(2), TreeCut(-1, 0.0005)};
  CandidateSet set, reused;
  std::vector<TreeHit> hits(1 << 16);
  int64_t finger_candidates = 0, palm_candidates = 0;
  for (int32_t draw = 0; draw < draws; ++draw) {
    HandState state;
    HandPose pose;
    random_hand(model, rng, state, pose);
    // each object near a random point of the hand: a fingertip, a knuckle or the palm
    std::vector<SolverObject> objects;
    for (const auto& tree : {ball, box, plate}) {
      const int finger = static_cast<int>(unit(rng) * FRUSTA_FINGER_COUNT) % FRUSTA_FINGER_COUNT;
      const vec3 at = unit(rng) < 0.4 ? pose.palm_position + pose.palm_rotation * vec3(0.05, 0.0, 0.0)
                                      : pose.fingers[finger].joint[static_cast<int>(unit(rng) * 4) % 4];
      const Sphere local = tree->tree.node_sphere(0);
      const glm::dmat3 rotation = random_rotation(rng);
      // the tree's surface within a few centimetres of that point
      const vec3 toward = glm::normalize(vec3(offset(rng), offset(rng), offset(rng)) + vec3(1e-9));
      objects.push_back({&tree->tree, {at - rotation * local.center + toward * local.radius * unit(rng), rotation}});
    }
    // then one finger bent further at its middle joint, and half the time the palm
    // moved too: a detection keeps what did not move from the one before, in place
    HandState moved_state = state;
    const int bent = static_cast<int>(unit(rng) * FRUSTA_FINGER_COUNT) % FRUSTA_FINGER_COUNT;
    moved_state.angles[bent * FRUSTA_JOINTS_PER_FINGER + 2] += 0.01;
    if (unit(rng) < 0.5) {  // moved and turned: each palm sphere by another amount
      moved_state.palm_position.x += 0.001;
      const vec3 axis = glm::normalize(vec3(offset(rng), offset(rng), offset(rng)) + vec3(1e-9));
      moved_state.palm_rotation =
          glm::normalize(glm::angleAxis(0.02, axis) * moved_state.palm_rotation);
    }
    HandPose moved;
    forward_kinematics(model, moved_state, moved);
    const uint32_t unmoved = bodies_unmoved(pose, moved);
    EXPECT_EQ(unmoved & (1u << (bent * FRUSTA_SEGMENTS_PER_FINGER + 2)), 0u) << "its distal segment moved";
    EXPECT_EQ((unmoved >> kPalmBody) & 1u, moved_state.palm_position == state.palm_position ? 1u : 0u);
    for (const TreeCut& cut : cuts)
      for (double margin : {0.002, 0.0}) {
        const std::string what = "draw " + std::to_string(draw) + ", level " + std::to_string(cut.max_level) +
                                 ", radius " + std::to_string(cut.max_error) + ", margin " + std::to_string(margin);
        int32_t begin[kBodyCount + 1];
        const std::vector<Candidate> expected = walk_per_probe(model, reach, pose, objects, margin, cut, begin, hits);
        detect_candidates(model, reach, pose, objects.data(), static_cast<int32_t>(objects.size()), margin, cut, set);
        expect_same(expected, begin, set, what);
        if (testing::Test::HasFatalFailure()) return;
        expect_clearances(model, moved, set, what + ", clearances moved");
        finger_candidates += set.size() - set.count(kPalmBody);
        palm_candidates += set.count(kPalmBody);
        const std::vector<Candidate> expected_moved =
            walk_per_probe(model, reach, moved, objects, margin, cut, begin, hits);
        reused = set;
        detect_candidates(model, reach, moved, objects.data(), static_cast<int32_t>(objects.size()), margin, cut,
                          reused, nullptr, 0, unmoved);
        expect_same(expected_moved, begin, reused, what + ", moved");
        if (testing::Test::HasFatalFailure()) return;
        // again, keeping only the palm's (if it did not move) and the bent finger's
        // neighbours': the walks replaced now outnumber those kept, which move down
        const uint32_t few = unmoved & ((1u << kPalmBody) | (7u << (((bent + 1) % FRUSTA_FINGER_COUNT) * 3)));
        detect_candidates(model, reach, moved, objects.data(), static_cast<int32_t>(objects.size()), margin, cut,
                          reused, nullptr, 0, few);
        expect_same(expected_moved, begin, reused, what + ", moved, kept few");
        if (testing::Test::HasFatalFailure()) return;
      }
  }
  // the draws put both the fingers and the palm into the objects, often
  EXPECT_GT(finger_candidates, 100 * draws);
  EXPECT_GT(palm_candidates, 100 * draws);
}

TEST(SolverDetection, OneWalkForManyProbesFindsWhatOneWalkPerProbeFindsInItsOrder) {
  check_random_hands(make_hand_model(default_hand_def()), 300, 21);
}

// A palm of more spheres than one mask holds is walked in runs of 64.
TEST(SolverDetection, APalmOfMoreThan64SpheresFindsWhatOneWalkPerSphereFinds) {
  HandDef def = default_hand_def();
  def.palm_thickness *= 0.5;
  const HandModel model = make_hand_model(def);
  ASSERT_GT(model.palm_spheres.size(), 64u);
  check_random_hands(model, 60, 22);
}

// The motion bounds the solver's margins and rows stand on (issue 21: a segment near the
// knuckles looks only as far as it can move; a row is made for a sphere a step can
// reach): along a straight move of the joint angles, no point of a segment's solid moves
// further than its levers say, nor than its share of the fingertip's bound, nor than its
// share of the pose's bound (finger_motion). Points of the solid are sampled on the
// capsule of the finger's largest radius round each segment, and their paths summed in
// small chords.
TEST(SolverDetection, NoPointOfASegmentMovesFurtherThanItsBounds) {
  const HandModel model = make_hand_model(default_hand_def());
  const HandReach reach = hand_reach(model);
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double lever_sum = 0.0, posed_sum = 0.0;
  const int trials = scenes::scaled_case_count(200, 20);
  for (int trial = 0; trial < trials; ++trial) {
    HandState from, to;
    for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
      for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j) {
        const FingerModel& finger = model.fingers[f];
        const double span = finger.joint_max[j] - finger.joint_min[j];
        const size_t k = static_cast<size_t>(f * FRUSTA_JOINTS_PER_FINGER + j);
        from.angles[k] = finger.joint_min[j] + span * unit(rng);
        // small moves and whole-range ones
        const double reach_of_move = trial % 2 ? 0.05 : 1.0;
        to.angles[k] = std::clamp(from.angles[k] + reach_of_move * span * (2.0 * unit(rng) - 1.0),
                                  finger.joint_min[j], finger.joint_max[j]);
      }
    constexpr int kChords = 64;
    std::vector<HandPose> path(kChords + 1);
    for (int i = 0; i <= kChords; ++i) forward_kinematics(model, interpolate(from, to, double(i) / kChords), path[i]);
    for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
      std::array<double, FRUSTA_JOINTS_PER_FINGER> a{}, b{};
      for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j) {
        a[j] = from.angles[static_cast<size_t>(f * FRUSTA_JOINTS_PER_FINGER + j)];
        b[j] = to.angles[static_cast<size_t>(f * FRUSTA_JOINTS_PER_FINGER + j)];
      }
      const FingerModel& finger = model.fingers[f];
      double tip_bound = 0.0;
      for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j) tip_bound += std::fabs(b[j] - a[j]) * reach.lever[f][j];
      FingerJacobian jacobian;
      finger_jacobian(path[0].fingers[f], kEverySegment, jacobian);
      FingerAngles delta;
      for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j) delta[j] = b[j] - a[j];
      for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s) {
        double bound = 0.0;
        for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j)
          bound += std::fabs(b[j] - a[j]) * reach.segment_lever[f][s][j];
        EXPECT_LE(bound, reach.segment_share[f][s] * tip_bound * (1.0 + 1e-12));
        const double posed =
            reach.segment_share[f][s] * finger_motion(model, reach, jacobian, f, delta, 1u << s);
        EXPECT_LE(posed, bound * (1.0 + 1e-12));
        if (trial % 2) {  // the small moves
          lever_sum += bound;
          posed_sum += posed;
        }
        // points of the solid: on the ball at a fraction `along` of the axis, of the radius
        // interpolated there, in a ring of directions tilted back, across and forward
        for (double along : {0.0, 0.5, 1.0})
          for (double tilt : {-1.0, 0.0, 1.0})
            for (int k = 0; k < 8; ++k) {
              const double angle = 2.0 * glm::pi<double>() * k / 8.0;
              const double ball = (1.0 - along) * finger.radius[s] + along * finger.radius[s + 1];
              const vec3 out = glm::normalize(vec3(tilt, std::cos(angle), std::sin(angle)));
              auto point = [&](const HandPose& pose) {
                const FingerPose& p = pose.fingers[f];
                const double length = glm::length(p.joint[s + 1] - p.joint[s]);
                return p.joint[s] + p.segment_rotation[s] * (vec3(along * length, 0.0, 0.0) + ball * out);
              };
              double travelled = 0.0;
              for (int i = 0; i < kChords; ++i) travelled += glm::length(point(path[i + 1]) - point(path[i]));
              ASSERT_LE(travelled, posed * (1.0 + 1e-9) + 1e-15)
                  << "trial " << trial << " finger " << f << " segment " << s;
            }
      }
    }
  }
  // over small moves the pose's bound is the tighter by far: what keeps a step's rows few
  EXPECT_LT(posed_sum, 0.8 * lever_sum);
  // the knuckle's segment moves by well under its fingertip's bound: what makes it look less far
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    EXPECT_LT(reach.segment_share[f][0], 0.75) << "finger " << f;
    EXPECT_EQ(reach.segment_share[f][FRUSTA_SEGMENTS_PER_FINGER - 1], 1.0) << "finger " << f;
  }
}

// Under a cut, the nodes standing in for their leaves may stick out of the root's sphere
// (node_overhang): an object's bound includes that, or a palm sphere just outside the
// root's sphere missed the node it touches (found by the cached detection, which looked
// further, while a fresh one did not).
TEST(SolverDetection, ACutNodeStickingOutOfTheRootsSphereIsFound) {
  const HandModel model = make_hand_model(default_hand_def());
  const HandReach reach = hand_reach(model);
  const std::shared_ptr<const TreeFile> ball = scenes::ball_shell(4000, 0.04);
  const SphereTree& tree = ball->tree;
  const TreeCut cut(2);
  // the level-2 node sticking out furthest, and the palm's first sphere half that far
  // outside the root's sphere, towards it
  const Sphere root = tree.node_sphere(0);
  double out = 0.0;
  vec3 toward(1.0, 0.0, 0.0);
  for (int32_t a = 0; a < tree.nodes[0].count; ++a)
    for (int32_t c = 0; c < tree.nodes[static_cast<size_t>(tree.nodes[0].first + a)].count; ++c) {
      const int32_t node = tree.nodes[static_cast<size_t>(tree.nodes[0].first + a)].first + c;
      const Sphere s = tree.node_sphere(node);
      const double beyond = glm::length(s.center - root.center) + s.radius - root.radius;
      if (beyond > out) {
        out = beyond;
        toward = glm::normalize(s.center - root.center);
      }
    }
  ASSERT_GT(out, 1e-4) << "the cut's nodes stick out of the root's sphere";
  HandState state = scenes::open_hand();
  const Sphere& palm = model.palm_spheres[0];
  state.palm_position = root.center + toward * (root.radius + palm.radius + 0.5 * out) - palm.center;
  HandPose pose;
  forward_kinematics(model, state, pose);
  const SolverObject object{&tree, {}};
  CandidateSet set;
  detect_candidates(model, reach, pose, &object, 1, 0.0, cut, set);
  std::vector<TreeHit> hits(4096);
  const TreeQueryStats walked = query_sphere(tree, palm_sphere(model, pose, 0), 0.0, cut, hits.data(), 4096);
  ASSERT_GT(walked.hits, 0);
  int32_t found = 0;
  for (int32_t i = 0; i < set.count(kPalmBody); ++i) found += set.of(kPalmBody)[i].part == 0 ? 1 : 0;
  EXPECT_EQ(found, walked.hits);
}

// A hand wandering about a ball, a box and a plate, each step a random move of every
// joint and the palm (some within the cache's room, some beyond, some none), asking
// each body for a random margin (some the contact distance of a body that stays): the
// cache answers what a fresh detection finds, in its order, whether it walked or not.
TEST(SolverDetection, ACachedDetectionFindsWhatAFreshOneFinds) {
  const HandModel model = make_hand_model(default_hand_def());
  const HandReach reach = hand_reach(model);
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> unit(0.0, 1.0), offset(-0.04, 0.04);
  const std::shared_ptr<const TreeFile> ball = scenes::ball_shell(4000, 0.04);
  const std::shared_ptr<const TreeFile> box = scenes::sample_tree("box"), plate = scenes::sample_tree("plate");
  const TreeCut cuts[] = {TreeCut(), TreeCut(2), TreeCut(-1, 0.0005)};
  constexpr double kRoom = 0.0005;
  CandidateSet cached, fresh;
  int64_t calls = 0, from_cache = 0, walked = 0, candidates = 0;
  const int runs = scenes::scaled_case_count(24, 4);
  for (int run = 0; run < runs; ++run) {
    HandState state;
    HandPose pose;
    random_hand(model, rng, state, pose);
    std::vector<SolverObject> objects;
    for (const auto& tree : {ball, box, plate}) {
      const Sphere local = tree->tree.node_sphere(0);
      const glm::dmat3 rotation = random_rotation(rng);
      const vec3 at = pose.fingers[static_cast<int>(unit(rng) * 5) % 5].joint[3];
      const vec3 toward = glm::normalize(vec3(offset(rng), offset(rng), offset(rng)) + vec3(1e-9));
      objects.push_back({&tree->tree, {at - rotation * local.center + toward * local.radius * unit(rng), rotation}});
    }
    const TreeCut cut = cuts[run % 3];
    CandidateCache cache;
    for (int step = 0; step < 40; ++step) {
      // no move, a few microns, a tenth of a millimetre, or a millimetre
      const double size = std::array<double, 4>{0.0, 2e-4, 2e-3, 2e-2}[static_cast<size_t>(unit(rng) * 4) % 4];
      for (double& a : state.angles) a += size * (2.0 * unit(rng) - 1.0);
      clamp_to_limits(model, state);
      if (unit(rng) < 0.5) {
        state.palm_position += 0.05 * size * vec3(offset(rng), offset(rng), offset(rng));
        state.palm_rotation = glm::normalize(
            state.palm_rotation * glm::dquat(1.0, size * offset(rng), size * offset(rng), size * offset(rng)));
      }
      forward_kinematics(model, state, pose);
      DetectionMargins needs;
      for (double& need : needs.body) need = unit(rng) < 0.2 ? 1e-4 : 0.002 * unit(rng);
      cache.detect(model, reach, pose, objects.data(), static_cast<int32_t>(objects.size()), needs, kRoom, cut,
                   cached);
      detect_candidates(model, reach, pose, objects.data(), static_cast<int32_t>(objects.size()), needs, cut, fresh);
      const std::string what = "run " + std::to_string(run) + ", step " + std::to_string(step);
      // every sphere a fresh detection finds, and only spheres whose bounds from where the
      // walk looked leave them within the need of the body as it moved: so within the
      // need, twice the room (a sphere kept as the move may have brought it nearer is as
      // far again if the body moved away) and their bounds' width (the least lowered to a
      // 32nd of the walk's margin); the same bodies near, each body's in order of its
      // bounds where its walk looked from (another order than a fresh walk's), which hold
      // the exact gap as the body moved since
      ASSERT_EQ(cached.near, fresh.near) << what;
      for (int body = 0; body < kBodyCount; ++body) {
        ASSERT_EQ(cached.need[body], needs.body[body]) << what << ", body " << body;
        ASSERT_LE(moved_since_placed(model, pose, cached, body), kRoom) << what << ", body " << body;
        const Candidate* c = cached.of(body);
        const Candidate* f = fresh.of(body);
        const std::vector<int32_t> in_cache = by_key(c, cached.count(body));
        for (int32_t i = 0; i < fresh.count(body); ++i)
          ASSERT_TRUE(std::binary_search(in_cache.begin(), in_cache.end(), -1, [&](int32_t a, int32_t b) {
            return sphere_hash(a < 0 ? f[i] : c[a]) < sphere_hash(b < 0 ? f[i] : c[b]);
          })) << what << ", body " << body << ": fresh candidate " << i << " is not cached";
        const std::vector<double> exact = exact_gaps(model, pose, cached, body);
        for (int32_t i = 0; i < cached.count(body); ++i)
          ASSERT_LE(exact[static_cast<size_t>(i)],
                    needs.body[body] + 2.0 * kRoom + (c[i].gap.most - c[i].gap.least))
              << what << ", body " << body << ", candidate " << i;
        expect_sorted(cached, body, nullptr, what);
        expect_bounds_hold(model, pose, cached, body, what);
        if (testing::Test::HasFatalFailure()) return;
      }
      ++calls;
      (cached.tree_nodes_visited == 0 ? from_cache : walked) += 1;
      candidates += cached.size();
    }
  }
  // the moves both keep to the room and leave it, near many spheres
  EXPECT_GT(from_cache, calls / 8);
  EXPECT_GT(walked, calls / 5);
  EXPECT_GT(candidates, 50 * calls);
}

}  // namespace
}  // namespace frusta
