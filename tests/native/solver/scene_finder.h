// SPDX-License-Identifier: MIT
// A broad phase over a test's objects, as the runtime's scene gives the solver, counting
// how often the solver asks it.
#pragma once

#include <cstdint>
#include <vector>

#include "solver/broad_phase.h"
#include "solver/detection.h"

namespace frusta::testing {

class SceneFinder final : public ObjectFinder {
 public:
  explicit SceneFinder(const std::vector<SolverObject>& objects)
      : broad_phase_(static_cast<int32_t>(objects.size())) {
    for (size_t o = 0; o < objects.size(); ++o)
      proxies_.push_back(
          broad_phase_.create_proxy(sphere_box(object_bound(objects[o])), static_cast<int32_t>(o)));
  }
  void moved(const std::vector<SolverObject>& objects, size_t o) {
    broad_phase_.move_proxy(proxies_[o], sphere_box(object_bound(objects[o])));
  }
  int32_t find(const Aabb& box, int32_t* out, int32_t capacity) const override {
    ++finds_;
    int32_t count = 0;
    broad_phase_.query(box, [&](int32_t o) {
      if (count < capacity) out[count] = o;
      ++count;
    });
    return count;
  }
  int64_t finds() const { return finds_; }

 private:
  BroadPhase broad_phase_;
  std::vector<int32_t> proxies_;
  mutable int64_t finds_ = 0;
};

}  // namespace frusta::testing
