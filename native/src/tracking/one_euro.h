// SPDX-License-Identifier: MIT
// The One Euro filter (Casiez, Roussel, Vogel, CHI 2012): a first-order low-pass whose
// cutoff rises with the signal's speed, cutoff = min_cutoff + beta * |speed|, the speed
// itself low-passed at d_cutoff. At rest it removes jitter; moving, it lags little.
// Scalars, 3-vectors and rotations (slerp towards the new one, speed from the angular
// velocity). Plain values, no allocation.
#pragma once

#include <glm/gtc/quaternion.hpp>

#include "geometry/types.h"

namespace frusta {

struct OneEuroParams {
  double min_cutoff = 0.0;  // Hz; 0: off (callers skip the filter)
  double beta = 0.0;        // Hz per unit of speed
  double d_cutoff = 1.0;    // Hz, > 0
};

// the low-pass's weight of a new sample dt seconds after the last, at cutoff Hz
double one_euro_alpha(double cutoff, double dt);

// One value; T is double or vec3 (|speed| is its length).
template <typename T>
class OneEuro {
 public:
  // the filtered value of x, dt > 0 seconds after the previous sample
  T filter(const T& x, double dt, const OneEuroParams& p);
  void reset() { started_ = false; }
  bool started() const { return started_; }

 private:
  bool started_ = false;
  T value_{};
  T speed_{};
};

// A unit quaternion; beta is per rad/s of angular speed.
class OneEuroRotation {
 public:
  glm::dquat filter(const glm::dquat& q, double dt, const OneEuroParams& p);
  void reset() { started_ = false; }

 private:
  bool started_ = false;
  glm::dquat value_{1.0, 0.0, 0.0, 0.0};
  vec3 speed_{0.0};  // rad/s, angular velocity in the fixed frame
};

extern template class OneEuro<double>;
extern template class OneEuro<vec3>;

}  // namespace frusta
