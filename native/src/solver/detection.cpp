// SPDX-License-Identifier: MIT
#include "solver/detection.h"

#include <algorithm>
#include <cmath>

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

// Deal the hits of the walks for palm spheres [first, first + run) out to the spheres
// that reach them, sphere by sphere, keeping their order (object, then node): the order
// of one walk per sphere.
void deal_out(const SolverObject* objects, const Sphere* palm, int32_t first, int run,
              CandidateSet& out) {
  int32_t count[kMaxProbes] = {};
  for (const MaskedHit& h : out.masked_hits)
    for (uint64_t rest = h.probes; rest != 0; rest &= rest - 1) ++count[lowest_bit(rest)];
  int32_t next[kMaxProbes];
  int32_t end = static_cast<int32_t>(out.sorting.size());
  for (int k = 0; k < run; ++k) {
    next[k] = end;
    end += count[k];
  }
  out.sorting.resize(static_cast<size_t>(end));
  for (const MaskedHit& h : out.masked_hits) {
    // an inner node cut off by the level stands in for every leaf below it
    const RigidPose& pose = objects[h.object].pose;
    const Sphere world{pose.rotation * h.local.center + pose.position, h.local.radius};
    for (uint64_t rest = h.probes; rest != 0; rest &= rest - 1) {
      const int k = lowest_bit(rest);
      out.sorting[static_cast<size_t>(next[k]++)] = {h.object, h.hit.leaf, first + k, world,
                                                     gap_bounds_sphere(palm[k], world)};
    }
  }
}

// The palm's candidates, into out.sorting (append_by_gap orders them), in the order of
// one walk per palm sphere (sphere, then object, then node order): each object's tree is
// walked once for up to 64 palm spheres, skipping the nodes out of reach of the box
// around them all, and its hits are then dealt out to the spheres that reach them.
void detect_palm(const HandModel& model, const HandReach& reach, const HandPose& pose,
                 const SolverObject* objects, double margin, TreeCut cut, CandidateSet& out) {
  const int32_t palm_count = static_cast<int32_t>(model.palm_spheres.size());
  const glm::dmat3 to_palm = glm::transpose(pose.palm_rotation);
  Sphere world[kMaxProbes], local[kMaxProbes];
  out.sorting.clear();
  for (int32_t first = 0; first < palm_count; first += kMaxProbes) {
    const int run = static_cast<int>(std::min<int32_t>(kMaxProbes, palm_count - first));
    for (int k = 0; k < run; ++k) world[k] = palm_sphere(model, pose, first + k);
    out.masked_hits.clear();
    for (int32_t o : out.near_objects) {
      const SolverObject& obj = objects[o];
      const Sphere bound = object_bound(obj);
      uint64_t spheres = 0;
      for (int k = 0; k < run; ++k) {
        if (!bounds_meet(world[k], bound, margin)) continue;
        spheres |= uint64_t{1} << k;
        local[k] = to_object_frame(obj.pose, world[k]);
      }
      if (spheres == 0) continue;
      // a node's centre in the palm's frame: rotation * centre + shift; a node out of
      // reach of the centres' box (with a micron to spare for rounding) is out of reach
      // of every palm sphere, whose own test then fails
      const glm::dmat3 rotation = to_palm * obj.pose.rotation;
      const vec3 shift = to_palm * (obj.pose.position - pose.palm_position);
      const double spare =
          1e-6 + 1e-12 * (glm::length(shift) + glm::length(bound.center - obj.pose.position) + bound.radius);
      auto near = [&](const Sphere& s) {
        const vec3 p = rotation * s.center + shift;
        const vec3 outside = glm::max(reach.palm_low - p, glm::max(vec3(0.0), p - reach.palm_high));
        const double within = s.radius + reach.palm_radius + margin + spare;
        return glm::dot(outside, outside) <= within * within;
      };
      const TreeQueryStats stats = walk_tree_masked(
          *obj.tree, spheres, near, [&](int k, const Sphere& s) { return may_touch_sphere(local[k], s, margin); },
          cut, [&](const TreeHit& hit, uint64_t reached, const Sphere& tested) {
          out.masked_hits.push_back({o, hit, reached, tested});
        });
      out.tree_nodes_visited += stats.visited;
    }
    deal_out(objects, world, first, run, out);
  }
}

// A body's candidates (found into out.sorting) appended to the set in order of their
// gap bounds' least, each least lowered to a multiple of a 32nd of the walk's margin (those
// below 0 to the least of them): still a bound, and equal ones keep the order they were
// found in. Sorted so in one pass over them; std::sort's mispredicted comparisons cost the
// steps that walk most a tenth more.
void append_by_gap(CandidateSet& out, int body, double margin) {
  constexpr int kBuckets = 33;  // below 0, then 32 of a 32nd of the margin each (the last open)
  const std::vector<Candidate>& found = out.sorting;
  const int32_t count = static_cast<int32_t>(found.size());
  out.begin[body] = static_cast<int32_t>(out.candidates.size());
  out.end[body] = out.begin[body] + count;
  double lowest = 0.0;
  for (const Candidate& c : found) lowest = std::min(lowest, c.gap.least);
  const double width = margin / (kBuckets - 1);
  auto bucket = [&](double least) {
    if (!(least >= 0.0)) return 0;
    if (!(width > 0.0)) return kBuckets - 1;
    // truncation is the floor of a quotient >= 0 (std::floor is a call without SSE4.1)
    const int k = static_cast<int>(std::min(least / width, kBuckets - 2.0));
    return k * width > least ? k : k + 1;  // the bucket's floor, (b - 1) * width, <= least
  };
  int32_t start[kBuckets + 1] = {};
  out.order.resize(static_cast<size_t>(2 * count));
  int32_t* in_bucket = out.order.data();       // each found one's bucket
  int32_t* in_order = out.order.data() + count;  // the found ones' indices, sorted
  for (int32_t i = 0; i < count; ++i) {
    const int b = bucket(found[static_cast<size_t>(i)].gap.least);
    in_bucket[i] = b;
    ++start[b + 1];
  }
  for (int b = 0; b < kBuckets; ++b) start[b + 1] += start[b];
  for (int32_t i = 0; i < count; ++i) in_order[start[in_bucket[i]]++] = i;
  // appended in order, each written once (a resize first had every new one zeroed)
  for (int32_t k = 0; k < count; ++k) {
    const int32_t i = in_order[k];
    const int b = in_bucket[i];
    out.candidates.push_back(found[static_cast<size_t>(i)]);
    out.candidates.back().gap.least = b == 0 ? lowest : (b - 1) * width;
  }
}

// Move the kept bodies' runs down over the walks they replaced, in place, in the order
// they lie: once the replaced outnumber the kept (so each kept candidate is moved no more
// often than as many are walked), and a set that kept its runs as they were walked does
// not grow without end.
void compact_kept(CandidateSet& out, uint32_t kept_bodies) {
  int32_t kept = 0;
  int order[kBodyCount];
  int n = 0;
  for (int body = 0; body < kBodyCount; ++body)
    if (((kept_bodies >> body) & 1u) != 0) {
      kept += out.count(body);
      order[n++] = body;
    }
  if (static_cast<int32_t>(out.candidates.size()) - kept <= kept) return;
  std::sort(order, order + n, [&](int a, int b) { return out.begin[a] < out.begin[b]; });
  Candidate* c = out.candidates.data();
  int32_t next = 0;
  for (int k = 0; k < n; ++k) {
    const int body = order[k];
    const int32_t count = out.count(body);
    if (next < out.begin[body]) std::copy(c + out.begin[body], c + out.end[body], c + next);
    out.begin[body] = next;
    out.end[body] = next + count;
    next += count;
  }
  out.candidates.resize(static_cast<size_t>(next));
}

}  // namespace

void CandidateSet::reserve(int32_t spheres, int32_t objects) {
  const size_t n = static_cast<size_t>(spheres);
  // resized and cleared, not reserved: resizing writes every element
  auto written = [n](auto& v, size_t size) {
    v.resize(std::max(v.size(), size));
    v.clear();
  };
  written(candidates, 2 * n);  // and the walks the next ones replace (compact_kept)
  written(sorting, n);
  written(masked_hits, n);
  written(order, 2 * n);
  written(near_objects, static_cast<size_t>(objects));
  hits.resize(std::max(hits.size(), n));  // its size is the walks' capacity
}

double segment_move(const Segment& then, const Segment& now) {
  return std::max(glm::length(now.proximal - then.proximal), glm::length(now.distal - then.distal));
}

double palm_move(const HandModel& model, const vec3& position, const glm::dmat3& rotation,
                 const HandPose& now) {
  // a palm that did not move (a grasp's, every pass) moved 0 by the loop below too
  if (position == now.palm_position && rotation == now.palm_rotation) return 0.0;
  const vec3 shift = now.palm_position - position;
  const glm::dmat3 turn = now.palm_rotation - rotation;
  // one square root, of the largest square, rather than one per palm sphere: the same
  // answer (a rounded root is monotonic), and the palm's views take it every trial
  double largest = 0.0;
  for (const Sphere& s : model.palm_spheres) {
    const vec3 d = shift + turn * s.center;
    largest = std::max(largest, glm::dot(d, d));
  }
  return std::sqrt(largest);
}

SegmentView segment_view(const HandModel& model, const HandPose& pose, const CandidateSet& set,
                         int body) {
  const Segment now = finger_segment(model, pose, body / FRUSTA_SEGMENTS_PER_FINGER,
                                     body % FRUSTA_SEGMENTS_PER_FINGER);
  SegmentView view;
  view.frame = make_segment_frame(now);
  view.moved = segment_move(set.placed.segments[static_cast<size_t>(body)], now);
  view.need = set.need[static_cast<size_t>(body)];
  return view;
}

PalmView palm_view(const HandModel& model, const HandPose& pose, const CandidateSet& set) {
  PalmView view;
  view.model = &model;
  view.pose = &pose;
  view.moved = palm_move(model, set.placed.palm_position, set.placed.palm_rotation, pose);
  view.need = set.need[kPalmBody];
  return view;
}

HandReach hand_reach(const HandModel& model) {
  HandReach reach;
  for (size_t k = 0; k < model.palm_spheres.size(); ++k) {
    const Sphere& s = model.palm_spheres[k];
    reach.hand = std::max(reach.hand, glm::length(s.center) + s.radius);
    reach.palm_low = k == 0 ? s.center : glm::min(reach.palm_low, s.center);
    reach.palm_high = k == 0 ? s.center : glm::max(reach.palm_high, s.center);
    reach.palm_radius = std::max(reach.palm_radius, s.radius);
  }
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    const FingerModel& finger = model.fingers[f];
    const double radius = *std::max_element(finger.radius.begin(), finger.radius.end());
    double beyond[FRUSTA_SEGMENTS_PER_FINGER + 1] = {};  // length from joint s to the tip
    for (int s = FRUSTA_SEGMENTS_PER_FINGER - 1; s >= 0; --s)
      beyond[s] = beyond[s + 1] + finger.length[s];
    reach.finger[f] = beyond[0] + radius;
    reach.lever[f][0] = beyond[0] + radius;  // abduction turns about the first joint
    for (int j = 1; j < FRUSTA_JOINTS_PER_FINGER; ++j) reach.lever[f][j] = beyond[j - 1] + radius;
    for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s) {
      for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j) {
        const int pivot = j == 0 ? 0 : j - 1;  // abduction and the first flexion turn about joint 0
        reach.segment_lever[f][s][j] = pivot <= s ? beyond[pivot] - beyond[s + 1] + radius : 0.0;
        reach.segment_share[f][s] =
            std::max(reach.segment_share[f][s], reach.segment_lever[f][s][j] / reach.lever[f][j]);
      }
    }
    reach.hand = std::max(reach.hand, glm::length(finger.base_position) + reach.finger[f]);
  }
  return reach;
}

Sphere object_bound(const SolverObject& object) {
  const SphereTree& tree = *object.tree;
  Sphere local = tree.node_sphere(0);
  if (!tree.node_overhang.empty()) local.radius += static_cast<double>(tree.node_overhang[0]);
  return {object.pose.rotation * local.center + object.pose.position, local.radius};
}

uint32_t bodies_unmoved(const HandPose& then, const HandPose& now) {
  uint32_t bodies = 0;
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    const FingerPose &a = then.fingers[f], &b = now.fingers[f];
    for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s)
      if (a.joint[s] == b.joint[s] && a.joint[s + 1] == b.joint[s + 1])
        bodies |= 1u << (f * FRUSTA_SEGMENTS_PER_FINGER + s);
  }
  if (then.palm_position == now.palm_position && then.palm_rotation == now.palm_rotation)
    bodies |= 1u << kPalmBody;
  return bodies;
}

double body_clearance(const HandModel& model, const HandPose& pose, const CandidateSet& candidates,
                      int body) {
  const int32_t first = candidates.begin[body];
  return body_clearance_over(model, pose, candidates, body, candidates.count(body),
                             [first](int32_t k) { return first + k; });
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
                       const SolverObject* objects, int32_t object_count, const DetectionMargins& margins,
                       TreeCut cut, CandidateSet& out, const int32_t* only, int32_t only_count,
                       uint32_t kept) {
  if (kept == 0)
    out.candidates.clear();
  else
    compact_kept(out, kept);
  out.tree_nodes_visited = 0;
  out.near_objects.clear();
  if (out.hits.empty()) out.hits.resize(256);
  const Sphere hand_bound{pose.palm_position, reach.hand};
  const int32_t n = only ? only_count : object_count;
  for (int32_t i = 0; i < n; ++i) {
    const int32_t o = only ? only[i] : i;
    if (!objects[o].tree->empty() && bounds_meet(hand_bound, object_bound(objects[o]), margins.largest()))
      out.near_objects.push_back(o);
  }

  auto add_hits = [&](int32_t object, int32_t count, const SegmentFrame& body, double margin) {
    const SolverObject& obj = objects[object];
    auto candidate = [&](int32_t h) {
      const TreeHit& hit = out.hits[static_cast<size_t>(h)];
      // an inner node cut off by the level stands in for every leaf below it
      const Sphere local = hit.leaf >= 0 ? obj.tree->leaves[static_cast<size_t>(hit.leaf)]
                                         : obj.tree->node_sphere(hit.node);
      return Candidate{object,
                       hit.leaf,
                       0,
                       {obj.pose.rotation * local.center + obj.pose.position, local.radius},
                       {}};
    };
    // bounded two at a time (gap_bounds_of); a hit the loose walk kept whose bounds rule
    // it out lies beyond the margin and is left out: what is kept is what the exact walk
    // kept, up to spheres within rounding of the margin
    auto keep = [&](const Candidate& c) {
      if (may_be_within(c.gap, 0.0, margin)) out.sorting.push_back(c);
    };
    int32_t h = 0;
    for (; h + 1 < count; h += 2) {
      Candidate a = candidate(h), b = candidate(h + 1);
      gap_bounds(body, a.world, b.world, a.gap, b.gap);
      keep(a);
      keep(b);
    }
    if (h < count) {
      Candidate a = candidate(h);
      a.gap = gap_bounds(body, a.world);
      keep(a);
    }
  };

  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    const Sphere finger_bound{pose.fingers[f].joint[0], reach.finger[f]};
    for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s) {
      const int body = f * FRUSTA_SEGMENTS_PER_FINGER + s;
      const double margin = margins.body[body];
      if (((kept >> body) & 1u) != 0) continue;
      const Segment segment = finger_segment(model, pose, f, s);
      out.placed.segments[static_cast<size_t>(body)] = segment;
      const SegmentFrame world = make_segment_frame(segment);
      out.sorting.clear();
      for (int32_t o : out.near_objects) {
        const SolverObject& obj = objects[o];
        if (!bounds_meet(finger_bound, object_bound(obj), margin)) continue;
        const SegmentFrame frame = make_segment_frame(to_object_frame(obj.pose, segment));
        const int32_t count = query_into(out.hits, [&](TreeHit* hits, int32_t capacity) {
          const TreeQueryStats stats =
              query_segment_loose(*obj.tree, frame, margin, cut, hits, capacity);
          out.tree_nodes_visited += stats.visited;
          return stats;
        });
        add_hits(o, count, world, margin);
      }
      append_by_gap(out, body, margin);
    }
  }
  out.need = margins.body;
  if (((kept >> kPalmBody) & 1u) == 0) {
    out.placed.palm_position = pose.palm_position;
    out.placed.palm_rotation = pose.palm_rotation;
    detect_palm(model, reach, pose, objects, margins.body[kPalmBody], cut, out);
    append_by_gap(out, kPalmBody, margins.body[kPalmBody]);
  }
  out.near = 0;
  for (int body = 0; body < kBodyCount; ++body)
    if (out.count(body) > 0) out.near |= 1u << body;
}

}  // namespace frusta
