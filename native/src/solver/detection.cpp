// SPDX-License-Identifier: MIT
#include "solver/detection.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "geometry/contact_test.h"
#include "geometry/exact_distance.h"
#include "geometry/segment_frame.h"

namespace frusta {

namespace {

bool bounds_meet(const Sphere& a, const Sphere& b, double margin) {
  return glm::length(a.center - b.center) <= a.radius + b.radius + margin;
}

// Run a tree query into the scratch buffer, growing it once when it was too small.
template <class Query>
int32_t query_into(std::vector<TreeHit>& hits, Query query) {
  TreeQueryStats stats = query(hits.data(), static_cast<int32_t>(hits.size()));
  if (stats.hits > static_cast<int32_t>(hits.size())) {
    hits.resize(static_cast<size_t>(stats.hits) * 2);
    stats = query(hits.data(), static_cast<int32_t>(hits.size()));
  }
  return stats.hits;
}

}  // namespace

HandReach hand_reach(const HandModel& model) {
  HandReach reach;
  for (const Sphere& s : model.palm_spheres)
    reach.hand = std::max(reach.hand, glm::length(s.center) + s.radius);
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    const FingerModel& finger = model.fingers[f];
    const double radius = *std::max_element(finger.radius.begin(), finger.radius.end());
    double beyond[FRUSTA_SEGMENTS_PER_FINGER + 1] = {};  // length from joint s to the tip
    for (int s = FRUSTA_SEGMENTS_PER_FINGER - 1; s >= 0; --s)
      beyond[s] = beyond[s + 1] + finger.length[s];
    reach.finger[f] = beyond[0] + radius;
    reach.lever[f][0] = beyond[0] + radius;  // abduction turns about the first joint
    for (int j = 1; j < FRUSTA_JOINTS_PER_FINGER; ++j) reach.lever[f][j] = beyond[j - 1] + radius;
    reach.hand = std::max(reach.hand, glm::length(finger.base_position) + reach.finger[f]);
  }
  return reach;
}

Sphere object_bound(const SolverObject& object) {
  const Sphere local = object.tree->node_sphere(0);
  return {object.pose.rotation * local.center + object.pose.position, local.radius};
}

double body_clearance(const HandModel& model, const HandPose& pose, const CandidateSet& candidates,
                      int body) {
  double gap = 0.0;
  const Candidate* c = candidates.of(body);
  if (body == kPalmBody) {
    for (int32_t i = 0; i < candidates.count(body); ++i) {
      const Sphere hand = palm_sphere(model, pose, c[i].part);
      gap = std::min(gap, glm::length(hand.center - c[i].world.center) - hand.radius -
                              c[i].world.radius);
    }
    return gap;
  }
  if (candidates.count(body) == 0) return gap;
  const SegmentFrame frame = make_segment_frame(finger_segment(
      model, pose, body / FRUSTA_SEGMENTS_PER_FINGER, body % FRUSTA_SEGMENTS_PER_FINGER));
  for (int32_t i = 0; i < candidates.count(body); ++i)
    // the cheap conservative test first: only a sphere that may touch can sink in
    if (may_touch(frame, c[i].world, 0.0)) gap = std::min(gap, exact_distance(frame, c[i].world));
  return gap;
}

double bound_clearance(const HandReach& reach, const HandPose& pose, const SolverObject* objects,
                       int32_t object_count, const int32_t* only, int32_t only_count) {
  double clearance = INFINITY;
  const int32_t n = only ? only_count : object_count;
  for (int32_t i = 0; i < n; ++i) {
    const int32_t o = only ? only[i] : i;
    if (objects[o].tree->empty()) continue;
    const Sphere b = object_bound(objects[o]);
    clearance = std::min(clearance, glm::length(b.center - pose.palm_position) - b.radius - reach.hand);
  }
  return clearance;
}

void detect_candidates(const HandModel& model, const HandReach& reach, const HandPose& pose,
                       const SolverObject* objects, int32_t object_count, double margin,
                       TreeCut cut, CandidateSet& out, const int32_t* only, int32_t only_count) {
  out.candidates.clear();
  out.tree_nodes_visited = 0;
  out.near_objects.clear();
  if (out.hits.empty()) out.hits.resize(256);
  const Sphere hand_bound{pose.palm_position, reach.hand};
  const int32_t n = only ? only_count : object_count;
  for (int32_t i = 0; i < n; ++i) {
    const int32_t o = only ? only[i] : i;
    if (!objects[o].tree->empty() && bounds_meet(hand_bound, object_bound(objects[o]), margin))
      out.near_objects.push_back(o);
  }

  auto add_hits = [&](int32_t object, int32_t count, int32_t part) {
    const SolverObject& obj = objects[object];
    for (int32_t h = 0; h < count; ++h) {
      const TreeHit& hit = out.hits[static_cast<size_t>(h)];
      // an inner node cut off by the level stands in for every leaf below it
      const Sphere local = hit.leaf >= 0 ? obj.tree->leaves[static_cast<size_t>(hit.leaf)]
                                         : obj.tree->node_sphere(hit.node);
      out.candidates.push_back({object, hit.leaf, part,
                                {obj.pose.rotation * local.center + obj.pose.position, local.radius}});
    }
  };

  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    const Sphere finger_bound{pose.fingers[f].joint[0], reach.finger[f]};
    for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s) {
      const int body = f * FRUSTA_SEGMENTS_PER_FINGER + s;
      out.begin[body] = static_cast<int32_t>(out.candidates.size());
      for (int32_t o : out.near_objects) {
        const SolverObject& obj = objects[o];
        if (!bounds_meet(finger_bound, object_bound(obj), margin)) continue;
        const SegmentFrame frame =
            make_segment_frame(to_object_frame(obj.pose, finger_segment(model, pose, f, s)));
        const int32_t count = query_into(out.hits, [&](TreeHit* hits, int32_t capacity) {
          const TreeQueryStats stats = query_segment(*obj.tree, frame, margin, cut, hits, capacity);
          out.tree_nodes_visited += stats.visited;
          return stats;
        });
        add_hits(o, count, 0);
      }
    }
  }
  out.begin[kPalmBody] = static_cast<int32_t>(out.candidates.size());
  for (int32_t k = 0; k < static_cast<int32_t>(model.palm_spheres.size()); ++k) {
    const Sphere world = palm_sphere(model, pose, k);
    for (int32_t o : out.near_objects) {
      const SolverObject& obj = objects[o];
      if (!bounds_meet(world, object_bound(obj), margin)) continue;
      const Sphere local = to_object_frame(obj.pose, world);
      const int32_t count = query_into(out.hits, [&](TreeHit* hits, int32_t capacity) {
        const TreeQueryStats stats = query_sphere(*obj.tree, local, margin, cut, hits, capacity);
        out.tree_nodes_visited += stats.visited;
        return stats;
      });
      add_hits(o, count, k);
    }
  }
  out.begin[kBodyCount] = static_cast<int32_t>(out.candidates.size());
}

}  // namespace frusta
