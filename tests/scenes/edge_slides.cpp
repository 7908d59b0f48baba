// SPDX-License-Identifier: MIT
#include "scenes/edge_slides.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "forces/contact_forces.h"
#include "hand/anthropometry.h"
#include "hand/hand_model.h"
#include "solver/hand_solver.h"

namespace frusta::scenes {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kClear = 0.002;      // metres between tip and object at a path's ends
constexpr double kFaceLeg = 0.008;    // metres an across path runs down each face
constexpr double kRidgeRun = 0.010;   // metres an along path runs either side of the middle
constexpr double kArcStep = kPi / 180;  // an arc drawn in 1-degree chords (0.2 um off at 5 mm)

// the haptic hand the slides move: the index bent so its tip points down, the rest open
HandState slide_hand() {
  HandState s = open_hand();
  set_flexion(s, kEdgeSlideFinger, 0.5, 0.5, 0.3);
  return s;
}

// A path of the tip centre, drawn in straight pieces.
class Path {
 public:
  explicit Path(const vec3& start) : points_{start} {}
  void line_to(const vec3& p) { points_.push_back(p); }
  // round `centre` in the x-z plane, radius, from angle `from` to `to` (radians, from +x
  // towards +z)
  void arc(const vec3& centre, double radius, double from, double to) {
    const int n = std::max(1, static_cast<int>(std::ceil(std::fabs(to - from) / kArcStep)));
    for (int i = 1; i <= n; ++i) {
      const double a = from + (to - from) * i / n;
      line_to(centre + radius * vec3(std::cos(a), 0.0, std::sin(a)));
    }
  }
  // the way back, appended, the way there first lengthened along its last piece to a
  // whole number of `spacing`s: the turn falls on a step, so every step moves the tip
  // `spacing` (the solver's continuity allowance follows the haptic hand's recent
  // moves, SolverParams::follow_decay, and a turn inside a step is a shorter move)
  void and_back(double spacing) {
    double length = 0.0;
    for (size_t i = 1; i < points_.size(); ++i) length += glm::length(points_[i] - points_[i - 1]);
    const double pad = std::ceil(length / spacing) * spacing - length;
    const vec3 last = points_.back(), way = glm::normalize(last - points_[points_.size() - 2]);
    points_.back() = last + pad * way;
    for (size_t i = points_.size() - 1; i-- > 0;) points_.push_back(points_[i]);
  }
  // points `spacing` apart along the path, the last a little past its end
  std::vector<vec3> walk(double spacing) const {
    std::vector<vec3> out{points_.front()};
    double next = spacing;  // along the current piece, where the next point falls
    for (size_t i = 1; i < points_.size(); ++i) {
      const vec3 a = points_[i - 1], b = points_[i];
      const double length = glm::length(b - a);
      for (; next <= length; next += spacing) out.push_back(a + (next / length) * (b - a));
      next -= length;
    }
    // the last step as long as the others, a little past the end: the speed stays steady
    const vec3 end = points_.back(), from = out.back();
    if (glm::length(end - from) > 1e-9 * spacing)
      out.push_back(from + (spacing / glm::length(end - from)) * (end - from));
    return out;
  }

 private:
  std::vector<vec3> points_;
};

// A prism placed ridge up: its edge (section corner 0) along y through `edge`, the
// faces either side going down, A towards -x and B towards +x.
struct Ridge {
  RigidPose pose;       // the prism's
  vec3 edge{0.0};       // a point of the edge, halfway along it
  vec3 down_a{0.0}, down_b{0.0};      // unit, from the edge down each face
  vec3 normal_a{0.0}, normal_b{0.0};  // unit, outward
};

// x-z of (x, z)
vec3 in_plane(double x, double z) { return vec3(x, 0.0, z); }

Ridge place_ridge_up(const TestPrism& prism, const vec3& edge) {
  const auto& sec = prism.section;
  const vec3 corner = in_plane(sec[0].first, sec[0].second);
  const vec3 to_prev = glm::normalize(in_plane(sec.back().first, sec.back().second) - corner);
  const vec3 to_next = glm::normalize(in_plane(sec[1].first, sec[1].second) - corner);
  const vec3 outward = -glm::normalize(to_prev + to_next);  // the corner's bisector, out
  // about y by alpha: (x, z) -> (x cos a + z sin a, -x sin a + z cos a) takes outward to +z
  const double alpha = std::atan2(-outward.x, outward.z);
  Ridge r;
  r.pose.rotation = glm::mat3_cast(glm::angleAxis(alpha, vec3(0.0, 1.0, 0.0)));
  r.pose.position = edge - r.pose.rotation * corner;
  r.edge = edge;
  vec3 a = r.pose.rotation * to_prev, b = r.pose.rotation * to_next;
  if (a.x > b.x) std::swap(a, b);
  r.down_a = a;
  r.down_b = b;
  // perpendicular in the x-z plane, the upward one (the edge is convex and ridge up)
  r.normal_a = vec3(-a.z, 0.0, a.x);
  if (r.normal_a.z < 0.0) r.normal_a = -r.normal_a;
  r.normal_b = vec3(-b.z, 0.0, b.x);
  if (r.normal_b.z < 0.0) r.normal_b = -r.normal_b;
  return r;
}

double angle_of(const vec3& v) { return std::atan2(v.z, v.x); }

// the tip centre's path: `pressed` is its distance from the object where it presses
// `depth` (the tip's radius less the depth), `clear` where it is kClear off
Path tip_path(const Ridge& r, EdgePath kind, double pressed, double clear, double spacing) {
  const vec3 e = r.edge;
  switch (kind) {
    case EdgePath::kAcross: {
      const vec3 start = e + kFaceLeg * r.down_a;
      Path p(start + clear * r.normal_a);
      p.line_to(start + pressed * r.normal_a);
      p.line_to(e + pressed * r.normal_a);
      p.arc(e, pressed, angle_of(r.normal_a), angle_of(r.normal_b));
      p.line_to(e + kFaceLeg * r.down_b + pressed * r.normal_b);
      p.and_back(spacing);
      return p;
    }
    case EdgePath::kOver: {
      // level with the ridge's top, far enough out either way to clear both faces
      double reach = 0.0;
      for (const vec3& n : {r.normal_a, r.normal_b})
        reach = std::max(reach, (clear - pressed * n.z) / std::fabs(n.x));
      Path p(e + vec3(-reach, 0.0, pressed));
      p.line_to(e + vec3(reach, 0.0, pressed));
      p.and_back(spacing);
      return p;
    }
    case EdgePath::kAlong: {
      const vec3 side(0.0, kRidgeRun, 0.0), up(0.0, 0.0, 1.0);
      Path p(e - side + clear * up);
      p.line_to(e - side + pressed * up);
      p.line_to(e + side + pressed * up);
      p.and_back(spacing);
      return p;
    }
  }
  throw std::invalid_argument("no such edge path");
}

}  // namespace

const char* edge_path_name(EdgePath path) {
  switch (path) {
    case EdgePath::kAcross: return "across";
    case EdgePath::kOver: return "over";
    case EdgePath::kAlong: return "along";
  }
  return "?";
}

std::vector<std::string> edge_shape_names() { return {"hex_prism", "edge_box", "wedge"}; }

HandScenario edge_slide(const std::string& shape, EdgePath path, double speed, double depth) {
  const HandModel model = make_hand_model(default_hand_def());
  const HandState hand = slide_hand();
  HandPose pose;
  forward_kinematics(model, hand, pose);
  const vec3 tip = pose.fingers[kEdgeSlideFinger].joint[3];
  const double radius = model.fingers[kEdgeSlideFinger].radius[3];
  if (!(depth > 0.0 && depth < radius) || !(speed > 0.0))
    throw std::invalid_argument("an edge slide needs 0 < depth < the tip's radius and a speed > 0");

  HandScenario s;
  char name[96];
  std::snprintf(name, sizeof name, "%s/%s/%.1fm/s/%.0fmm", shape.c_str(), edge_path_name(path), speed,
                depth * 1e3);
  s.name = name;
  // the ridge 1 cm under the tip of the hand at the origin
  const Ridge ridge = place_ridge_up(test_prism_spec(shape), tip - vec3(0.0, 0.0, 0.01));
  s.add(test_prism(shape), ridge.pose);
  s.anchor = ridge.edge;
  s.axis = vec3(0.0, 1.0, 0.0);
  const double spacing = speed * kEdgeSlideStep;
  const std::vector<vec3> centres =
      tip_path(ridge, path, radius - depth, radius + kClear, spacing).walk(spacing);
  s.steps = static_cast<int32_t>(centres.size());
  s.haptic = [centres, hand, tip](int32_t t) {
    HandState h = hand;
    h.palm_position = centres[static_cast<size_t>(std::clamp<int32_t>(t, 0, static_cast<int32_t>(centres.size()) - 1))] - tip;
    return h;
  };
  s.held = s.haptic(s.steps - 1);
  return s;
}

std::vector<EdgeSlideStep> run_edge_slide(const HandScenario& s, const SolverParams& params,
                                          bool check_penetration, bool timed) {
  using Clock = std::chrono::steady_clock;
  const HandModel model = make_hand_model(default_hand_def());
  HandSolver solver(model, params);
  ContactForces forces;
  const int32_t object_count = static_cast<int32_t>(s.objects.size());
  std::vector<EdgeSlideStep> log;
  log.reserve(static_cast<size_t>(s.steps));
  vec3 haptic_before(0.0), graphic_before(0.0), force_before(0.0), friction_before(0.0);
  for (int32_t t = 0; t < s.steps; ++t) {
    const HandState haptic = s.haptic(t);
    const Clock::time_point start = timed ? Clock::now() : Clock::time_point();
    StepStats stats;
    if (solver.step(haptic, s.objects.data(), object_count, &stats) != FRUSTA_OK) break;
    const std::vector<SolverContact>& contacts = solver.contacts();
    forces.update(solver.graphic_pose(), solver.target_pose(), contacts.data(),
                  static_cast<int32_t>(contacts.size()), s.objects.data(), object_count, nullptr,
                  nullptr, stats.lagging);
    EdgeSlideStep step;
    if (timed) step.step_us = std::chrono::duration<double, std::micro>(Clock::now() - start).count();
    vec3 force(0.0), friction(0.0);
    for (const ContactForce& f : forces.forces()) {
      force += f.normal_force;
      friction += f.friction;
    }
    const vec3 haptic_tip = solver.target_pose().fingers[kEdgeSlideFinger].joint[3];
    const vec3 graphic_tip = solver.graphic_pose().fingers[kEdgeSlideFinger].joint[3];
    step.force = glm::length(force);
    step.lagging = stats.lagging;
    if (t > 0) {
      step.haptic_move = glm::length(haptic_tip - haptic_before);
      step.graphic_move = glm::length(graphic_tip - graphic_before);
      step.force_change = std::fabs(step.force - glm::length(force_before));
      step.force_turn = glm::length(force - force_before);
      step.friction_change = glm::length(friction - friction_before);
    }
    if (check_penetration) step.penetration = deepest_penetration(model, solver.graphic_pose(), s.objects);
    haptic_before = haptic_tip;
    graphic_before = graphic_tip;
    force_before = force;
    friction_before = friction;
    log.push_back(step);
  }
  return log;
}

}  // namespace frusta::scenes
