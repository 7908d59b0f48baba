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
                            CandidateSet& out, const int32_t* only, int32_t only_count) {
  BodyPlacements& now = out.placed;
  now.palm_position = pose.palm_position;
  now.palm_rotation = pose.palm_rotation;
  std::array<double, kBodyCount> moves{};  // from where each body's cached walk looked
  uint32_t held = 0;  // bodies whose cached walk holds every sphere within their need now
  for (int body = 0; body < kBodyCount; ++body) {
    if (body == kPalmBody) {
      moves[body] = palm_move(model, wide_.placed.palm_position, wide_.placed.palm_rotation, pose);
    } else {
      now.segments[body] = finger_segment(model, pose, body / FRUSTA_SEGMENTS_PER_FINGER,
                                          body % FRUSTA_SEGMENTS_PER_FINGER);
      moves[body] = segment_move(wide_.placed.segments[body], now.segments[body]);
    }
    // a sphere within the need now was within need + move where the walk looked from
    if (valid_ && needs.body[body] + moves[body] <= margins_.body[body]) held |= 1u << body;
  }
  const uint32_t all = (1u << kBodyCount) - 1u;
  out.tree_nodes_visited = 0;
  if (held != all) {
    DetectionMargins wide;
    for (int body = 0; body < kBodyCount; ++body)
      wide.body[body] = ((held >> body) & 1u) != 0 ? margins_.body[body] : needs.body[body] + room;
    detect_candidates(model, reach, pose, objects, object_count, wide, cut, spare_, only,
                      only_count, {valid_ ? &wide_ : nullptr, held});
    std::swap(wide_, spare_);
    out.tree_nodes_visited = wide_.tree_nodes_visited;
    for (int body = 0; body < kBodyCount; ++body)
      if (((held >> body) & 1u) == 0) moves[body] = 0.0;  // walked from here
    margins_ = wide;
    valid_ = true;
  }

  // each body's cached spheres within its need, in their order in the walk's set (of their
  // gap bounds, CandidateSet), the bounds widened by the body's move since (which keeps it)
  out.candidates.clear();
  auto keep = [&](Candidate c, double move) {
    c.gap.least -= move;
    c.gap.most += move;
    out.candidates.push_back(c);
  };
  for (int body = 0; body < kBodyCount; ++body) {
    out.begin[body] = static_cast<int32_t>(out.candidates.size());
    const Candidate* c = wide_.of(body);
    const int32_t count = wide_.count(body);
    const double need = needs.body[body], move = moves[body];
    if (body == kPalmBody) {
      for (int32_t k = 0; k < count; ++k) {
        if (!may_be_within(c[k].gap, move, need)) break;  // and every one after
        if (decided_may_touch(c[k].gap, move, need, [&] {
              return may_touch_sphere(palm_sphere(model, pose, c[k].part), c[k].world, need);
            }))
          keep(c[k], move);
      }
    } else {
      const SegmentView view{make_segment_frame(now.segments[body]), move};
      for (int32_t k = 0; k < count; ++k) {
        if (!may_be_within(c[k].gap, move, need)) break;  // and every one after
        if (view.may_touch(c[k], need)) keep(c[k], move);
      }
    }
    out.end[body] = static_cast<int32_t>(out.candidates.size());
  }
}

}  // namespace frusta
