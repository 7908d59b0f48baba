// SPDX-License-Identifier: MIT
#include "solver/candidate_cache.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "geometry/contact_test.h"
#include "geometry/segment_frame.h"

namespace frusta {

void CandidateCache::detect(const HandModel& model, const HandReach& reach, const HandPose& pose,
                            const SolverObject* objects, int32_t object_count,
                            const DetectionMargins& needs, double room, TreeCut cut,
                            CandidateSet& set, const int32_t* only, int32_t only_count) {
  std::array<double, kBodyCount> moves{};  // from where each body's walk looked
  uint32_t held = 0;  // bodies whose walk holds every sphere within their need now
  for (int body = 0; body < kBodyCount; ++body) {
    if (!valid_) break;
    moves[body] = body == kPalmBody
                      ? palm_move(model, set.placed.palm_position, set.placed.palm_rotation, pose)
                      : segment_move(set.placed.segments[body],
                                     finger_segment(model, pose, body / FRUSTA_SEGMENTS_PER_FINGER,
                                                    body % FRUSTA_SEGMENTS_PER_FINGER));
    // a sphere within the need now was within need + move where the walk looked from;
    // a body that moved further than the room walks again although its walk still holds
    // its need (the need shrank): the set holds the spheres within need + move, which
    // passes test one by one
    if (moves[body] <= room && needs.body[body] + moves[body] <= margins_.body[body])
      held |= 1u << body;
  }
  const uint32_t all = (1u << kBodyCount) - 1u;
  set.tree_nodes_visited = 0;
  if (held != all) {
    DetectionMargins wide;
    for (int body = 0; body < kBodyCount; ++body) {
      wide.body[body] = ((held >> body) & 1u) != 0 ? margins_.body[body] : needs.body[body] + room;
      set.end[body] = walked_end_[body];  // the whole walk, for the bodies it serves again
    }
    // the bodies held keep their walks where they lie in the set: copying them into a
    // set of their own each time another body walked, and alternating between the two,
    // had been a third of the cache misses of the grasp's dearest steps
    detect_candidates(model, reach, pose, objects, object_count, wide, cut, set, only, only_count,
                      valid_ ? held : 0u);
    for (int body = 0; body < kBodyCount; ++body) {
      walked_end_[body] = set.end[body];
      if (((held >> body) & 1u) == 0) moves[body] = 0.0;  // walked from here
    }
    margins_ = wide;
    valid_ = true;
  }

  // Each body's walk, cut after the last sphere its gap bound (the body having moved since)
  // leaves within its need: the set holds every sphere within it, and some a little
  // further, which passes leave out (CandidateSet::need). Copying out those within,
  // exactly, was a tenth of a closing grasp's step.
  set.near = 0;
  for (int body = 0; body < kBodyCount; ++body) {
    const Candidate* c = set.candidates.data();
    const double need = needs.body[body], move = moves[body];
    // (found by halving: the bounds' least rise along the walk's order)
    const int32_t k = static_cast<int32_t>(
        std::partition_point(c + set.begin[body], c + walked_end_[body],
                             [&](const Candidate& x) { return may_be_within(x.gap, move, need); }) -
        c);
    set.end[body] = k;
    set.need[body] = need;
    // whether one is within it: most often a bound says so of the first, and the body's
    // view (a segment's frame) is made only where none does
    auto any_within = [&](const auto& make_view) {
      for (int32_t i = set.begin[body]; i < k; ++i)
        if (surely_within(c[i].gap, move, need)) return true;
      const auto view = make_view();
      for (int32_t i = set.begin[body]; i < k; ++i)
        if (view.may_touch(c[i], need)) return true;
      return false;
    };
    const bool near =
        k > set.begin[body] &&
        (body == kPalmBody ? any_within([&] { return palm_view(model, pose, set); })
                           : any_within([&] { return segment_view(model, pose, set, body); }));
    if (near) set.near |= 1u << body;
  }
}

}  // namespace frusta
