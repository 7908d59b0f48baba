// SPDX-License-Identifier: MIT
// Contact prediction (seed FIG. 7): every object sphere within Delta_r of the graphic
// hand, found through bounds (hand, finger) and then the trees with culling.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "geometry/contact_test.h"
#include "geometry/exact_distance.h"
#include "geometry/segment_frame.h"
#include "geometry/types.h"
#include "hand/kinematics.h"
#include "spheretree/sphere_tree.h"

namespace frusta {

// An object in a scene: its tree (owned elsewhere) and where it is.
struct SolverObject {
  const SphereTree* tree = nullptr;
  RigidPose pose;
};

// The palm body: its spheres. Finger segment f * 3 + s: bodies 0..14.
constexpr int kPalmBody = FRUSTA_HAND_SEGMENT_COUNT;
constexpr int kBodyCount = FRUSTA_HAND_SEGMENT_COUNT + 1;

struct Candidate {
  int32_t object = 0;
  int32_t leaf = 0;  // -1: an inner node standing in for its leaves (a level cut)
  int32_t part = 0;  // the palm sphere's index on the palm body, else 0
  Sphere world;      // the leaf in world coordinates
  // bounds of its exact gap to its body (its palm sphere) where the set placed the body
  // (CandidateSet::placed): a pass over a body's candidates decides most with one
  // comparison (SegmentView)
  GapBounds gap;
};

// Where a candidate set's bodies stood when their candidates' gap bounds were measured.
struct BodyPlacements {
  std::array<Segment, FRUSTA_HAND_SEGMENT_COUNT> segments{};
  vec3 palm_position{0.0};
  glm::dmat3 palm_rotation{1.0};
};

// A node one walk for many probes reached (walk_tree_masked), with the probes that reach
// it: palm spheres, bits of a run of 64.
struct MaskedHit {
  int32_t object = 0;
  TreeHit hit{};
  uint64_t probes = 0;
  Sphere local;  // the leaf (or cut node) in the object's frame, as the walk read it
};

// Candidates grouped by body: body b owns [begin[b], end[b]), in increasing order of
// their gap bounds' least (ties in the order of the walk). A pass for the spheres within
// some margin of a body stops at the first whose bound rules it out: every one after is
// ruled out too. Grasping a ball, 9 in 10 of a segment's candidates lie further than the
// clearance and the rows look, and each pass over them had cost a tenth of a step. The
// bodies' runs lie in any order, with walks they replaced between them
// (detect_candidates' `kept`).
struct CandidateSet {
  std::vector<Candidate> candidates;
  int32_t begin[kBodyCount] = {};
  int32_t end[kBodyCount] = {};
  // How far from each body its candidates were asked for: a set may hold spheres a little
  // further (CandidateCache), which every pass leaves out, so that its answers are those
  // of a set of exactly the spheres within (whatever the detection's history). `near`,
  // bit b: body b has a candidate within need[b].
  std::array<double, kBodyCount> need{};
  uint32_t near = 0;
  BodyPlacements placed;
  int32_t tree_nodes_visited = 0;
  // scratch kept between calls
  std::vector<TreeHit> hits;
  std::vector<MaskedHit> masked_hits;
  std::vector<int32_t> near_objects;
  std::vector<int32_t> order;
  std::vector<Candidate> sorting;  // a body's, as found, before they are ordered

  // Room for `spheres` candidates (a body's scratch for as many) among `objects` near,
  // and for as many walks replaced, every page written now, on the thread that makes the
  // hand: a first contact on the 1 kHz thread then neither allocates nor faults memory
  // in. A denser scene grows them.
  void reserve(int32_t spheres, int32_t objects);
  int32_t count(int body) const { return end[body] - begin[body]; }
  const Candidate* of(int body) const { return candidates.data() + begin[body]; }
  void clear() {
    candidates.clear();
    std::fill(std::begin(begin), std::end(begin), 0);
    std::fill(std::begin(end), std::end(end), 0);
    near = 0;
  }
  bool body_near(int body) const { return ((near >> body) & 1u) != 0; }
  bool finger_near(int finger) const {
    return ((near >> (finger * FRUSTA_SEGMENTS_PER_FINGER)) & ((1u << FRUSTA_SEGMENTS_PER_FINGER) - 1u)) != 0;
  }
  int32_t finger_count(int finger) const {
    int32_t sum = 0;
    for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s) sum += count(finger * FRUSTA_SEGMENTS_PER_FINGER + s);
    return sum;
  }
  int32_t size() const {
    int32_t sum = 0;
    for (int body = 0; body < kBodyCount; ++body) sum += count(body);
    return sum;
  }
};

// The most any point of a segment solid moved between two placements: the solid is the
// union of balls centred along its axis with radii interpolated along it, each of which
// moves as the same interpolation of its ends' moves.
double segment_move(const Segment& then, const Segment& now);

// ... of the palm's spheres, from a placement to `now`.
double palm_move(const HandModel& model, const vec3& position, const glm::dmat3& rotation,
                 const HandPose& now);

// A body at a pose, for a pass over its candidates: how far it moved from where the set
// measured their gap bounds, and how far the set was asked to look from it
// (CandidateSet::need). A pass looks no further than that, whatever margin it asks for:
// the spheres a set holds beyond it are left out, and its answers are those of a set of
// exactly the spheres within.
struct BodyBounds {
  double moved = 0.0;
  double need = INFINITY;
  double within(double margin) const { return std::min(margin, need); }
  // Whether `c`, and so every candidate after it in the set's order, lies further than
  // `margin`: where a pass over the set in order stops.
  bool beyond(const Candidate& c, double margin) const {
    return !may_be_within(c.gap, moved, within(margin));
  }
  // The same at margin 0, which every need covers: what clearances ask, the passes run
  // most, with the margin a constant the tests fold away.
  bool clear_from(const Candidate& c) const { return !may_be_within(c.gap, moved, 0.0); }
};

// A finger segment: its frame.
struct SegmentView : BodyBounds {
  SegmentFrame frame;
  // may_touch, its answer known from the bounds for all but the spheres near the margin
  bool may_touch(const Candidate& c, double margin) const {
    const double w = within(margin);
    return decided_may_touch(c.gap, moved, w, [&] { return frusta::may_touch(frame, c.world, w); });
  }
  bool may_sink(const Candidate& c) const {  // may_touch at 0 (clear_from)
    return decided_may_touch(c.gap, moved, 0.0,
                             [&] { return frusta::may_touch(frame, c.world, 0.0); });
  }
};
SegmentView segment_view(const HandModel& model, const HandPose& pose, const CandidateSet& set,
                         int body);

// The palm: each candidate's palm sphere (Candidate::part) placed only where a test needs
// it, and `moved` the most any of them moved. Its passes placed every candidate's sphere
// and measured it, and were a third of a palm pressing a box (palm_then_fingers).
struct PalmView : BodyBounds {
  const HandModel* model = nullptr;
  const HandPose* pose = nullptr;
  Sphere sphere(const Candidate& c) const { return palm_sphere(*model, *pose, c.part); }
  bool may_touch(const Candidate& c, double margin) const {
    const double w = within(margin);
    return decided_may_touch(c.gap, moved, w,
                             [&] { return may_touch_sphere(sphere(c), c.world, w); });
  }
  bool may_sink(const Candidate& c) const {  // may_touch at 0 (clear_from)
    return decided_may_touch(c.gap, moved, 0.0,
                             [&] { return may_touch_sphere(sphere(c), c.world, 0.0); });
  }
};
PalmView palm_view(const HandModel& model, const HandPose& pose, const CandidateSet& set);

// Bounds of a hand model that do not depend on its pose.
struct HandReach {
  double hand = 0.0;  // every hand point lies within this of the palm position
  std::array<double, FRUSTA_FINGER_COUNT> finger{};  // ... of the finger's first joint
  // how far a finger point can move per radian of each joint (lever arm bound)
  std::array<std::array<double, FRUSTA_JOINTS_PER_FINGER>, FRUSTA_FINGER_COUNT> lever{};
  // ... a point of one segment: a joint beyond it moves it not at all, one before it by
  // no more than the links in between (the fingertip's row is `lever`)
  std::array<std::array<std::array<double, FRUSTA_JOINTS_PER_FINGER>, FRUSTA_SEGMENTS_PER_FINGER>,
             FRUSTA_FINGER_COUNT>
      segment_lever{};
  // the most of a finger's motion bound a segment's can be: its largest lever's share
  std::array<std::array<double, FRUSTA_SEGMENTS_PER_FINGER>, FRUSTA_FINGER_COUNT> segment_share{};
  // the palm spheres' centres lie in this box of the palm's frame; none is larger
  vec3 palm_low{0.0}, palm_high{0.0};
  double palm_radius = 0.0;
};

HandReach hand_reach(const HandModel& model);

// World bound of an object's whole tree.
Sphere object_bound(const SolverObject& object);

// How far a detection looks from each body (metres): a segment that can move less than
// its finger's tip looks less far. A single number looks as far from every body.
struct DetectionMargins {
  std::array<double, kBodyCount> body{};
  DetectionMargins() = default;
  DetectionMargins(double every) { body.fill(every); }  // NOLINT: one margin for all
  double largest() const { return *std::max_element(body.begin(), body.end()); }
};

static_assert(kBodyCount <= 32, "a bit per body");

// The bodies (bit b: body b) whose solid is exactly where it was: a segment whose two
// joint centres, the palm whose position and rotation, are equal in both poses.
uint32_t bodies_unmoved(const HandPose& then, const HandPose& now);

// Fill `out` with every leaf within its body's margin of the hand at `pose`, or with the
// nodes where the cut stops standing in for theirs. The vector keeps its capacity
// between calls, so a steady scene allocates nothing. `only` (null: every object) lists
// the objects to look at, in increasing order: a broad phase's answer, which must hold
// every object whose bound comes within the largest margin of the hand's. `kept` (bit b:
// body b): bodies whose candidates `out` holds from an earlier detection among the same
// objects, which hold what the caller needs of them now, and stay as they are (where
// they lie in `out`, and where `out` placed the body); the others' are walked again.
// CandidateSet::reserve leaves room for the walks they leave behind, which the kept
// ones are moved down over once they outnumber them.
void detect_candidates(const HandModel& model, const HandReach& reach, const HandPose& pose,
                       const SolverObject* objects, int32_t object_count, const DetectionMargins& margins,
                       TreeCut cut, CandidateSet& out, const int32_t* only = nullptr,
                       int32_t only_count = 0, uint32_t kept = 0);

// How deep one body of the hand at `pose` sinks into its candidates, as a negative
// exact gap; 0 when it touches none (callers compare it with thresholds <= 0 only, so
// spheres apart are skipped after a cheap conservative test). What every accepted
// step is checked against.
double body_clearance(const HandModel& model, const HandPose& pose, const CandidateSet& candidates,
                      int body);

// The same over `count` of the body's candidates, the k-th candidates.candidates[index(k)]:
// those a step can reach (a stage's rows), when the others cannot touch. The indices
// increase (the rows are made in the set's order), so the pass stops at the first sphere
// out of reach.
template <class Index>
double body_clearance_over(const HandModel& model, const HandPose& pose,
                           const CandidateSet& candidates, int body, int32_t count, Index index) {
  double gap = 0.0;
  if (count == 0) return gap;
  const Candidate* all = candidates.candidates.data();
  if (body == kPalmBody) {
    const PalmView view = palm_view(model, pose, candidates);
    for (int32_t k = 0; k < count; ++k) {
      const Candidate& c = all[index(k)];
      if (view.clear_from(c)) break;  // and so is every one after
      if (!view.may_sink(c)) continue;
      gap = std::min(gap, exact_distance(view.sphere(c), c.world));
    }
    return gap;
  }
  const SegmentView view = segment_view(model, pose, candidates, body);
  for (int32_t k = 0; k < count; ++k) {
    const Candidate& c = all[index(k)];
    if (view.clear_from(c)) break;  // and so is every one after
    // the cheap conservative test first: only a sphere that may touch can sink in
    if (view.may_sink(c)) gap = std::min(gap, exact_distance(view.frame, c.world));
  }
  return gap;
}

// The smallest gap between the hand's bound and any object's bound (infinite with no
// objects): the hand can move that far without meeting anything. With `only` (null:
// every object), among those objects: the same answer wherever it is below a
// threshold, if `only` holds every object within that threshold of the hand's bound.
double bound_clearance(const HandReach& reach, const HandPose& pose, const SolverObject* objects,
                       int32_t object_count, const int32_t* only = nullptr, int32_t only_count = 0);

}  // namespace frusta
