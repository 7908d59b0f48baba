// SPDX-License-Identifier: MIT
#include "solver/candidate_cache.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "geometry/contact_test.h"
#include "geometry/segment_frame.h"

namespace frusta {

namespace {

// The most any point of a segment solid moved between two placements: the solid is the
// union of balls centred along its axis with radii interpolated along it, each of which
// moves as the same interpolation of its ends' moves.
double segment_move(const Segment& then, const Segment& now) {
  return std::max(glm::length(now.proximal - then.proximal), glm::length(now.distal - then.distal));
}

double palm_move(const HandModel& model, const vec3& position, const glm::dmat3& rotation,
                 const HandPose& now) {
  const vec3 shift = now.palm_position - position;
  const glm::dmat3 turn = now.palm_rotation - rotation;
  double move = 0.0;
  for (const Sphere& s : model.palm_spheres)
    move = std::max(move, glm::length(shift + turn * s.center));
  return move;
}

}  // namespace

void CandidateCache::detect(const HandModel& model, const HandReach& reach, const HandPose& pose,
                            const SolverObject* objects, int32_t object_count,
                            const DetectionMargins& needs, double room, TreeCut cut,
                            CandidateSet& out, const int32_t* only, int32_t only_count) {
  Segment segments[FRUSTA_HAND_SEGMENT_COUNT];
  uint32_t held = 0;  // bodies whose cached walk holds every sphere within their need now
  for (int body = 0; body < kBodyCount; ++body) {
    double move = 0.0;
    if (body == kPalmBody) {
      move = palm_move(model, palm_position_, palm_rotation_, pose);
    } else {
      segments[body] = finger_segment(model, pose, body / FRUSTA_SEGMENTS_PER_FINGER,
                                      body % FRUSTA_SEGMENTS_PER_FINGER);
      move = segment_move(segments_[body], segments[body]);
    }
    // a sphere within the need now was within need + move where the walk looked from
    if (valid_ && needs.body[body] + move <= margins_.body[body]) held |= 1u << body;
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
    for (int body = 0; body < kBodyCount; ++body) {
      if (((held >> body) & 1u) != 0) continue;
      if (body == kPalmBody) {
        palm_position_ = pose.palm_position;
        palm_rotation_ = pose.palm_rotation;
      } else {
        segments_[body] = segments[body];
      }
    }
    margins_ = wide;
    valid_ = true;
  }

  // each body's cached spheres within its need, in their walk's order
  out.candidates.clear();
  for (int body = 0; body < kBodyCount; ++body) {
    out.begin[body] = static_cast<int32_t>(out.candidates.size());
    const Candidate* c = wide_.of(body);
    const int32_t count = wide_.count(body);
    const double need = needs.body[body];
    if (body == kPalmBody) {
      for (int32_t k = 0; k < count; ++k)
        if (may_touch_sphere(palm_sphere(model, pose, c[k].part), c[k].world, need))
          out.candidates.push_back(c[k]);
    } else {
      const SegmentFrame frame = make_segment_frame(segments[body]);
      for (int32_t k = 0; k < count; ++k)
        if (may_touch(frame, c[k].world, need)) out.candidates.push_back(c[k]);
    }
  }
  out.begin[kBodyCount] = static_cast<int32_t>(out.candidates.size());
}

}  // namespace frusta
