// SPDX-License-Identifier: MIT
#include "tracking/one_euro.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace frusta {

namespace {

double magnitude(double x) { return std::abs(x); }
double magnitude(const vec3& x) { return glm::length(x); }

}  // namespace

double one_euro_alpha(double cutoff, double dt) {
  // exact for a first-order low-pass sampled every dt: tau = 1 / (2 pi cutoff)
  const double tau = 1.0 / (2.0 * 3.141592653589793 * cutoff);
  return 1.0 / (1.0 + tau / dt);
}

template <typename T>
T OneEuro<T>::filter(const T& x, double dt, const OneEuroParams& p) {
  if (!started_) {
    started_ = true;
    value_ = x;
    speed_ = T{};
    return x;
  }
  // the speed, low-passed at d_cutoff, sets this sample's cutoff
  const T speed = (x - value_) / dt;
  speed_ += one_euro_alpha(p.d_cutoff, dt) * (speed - speed_);
  const double cutoff = p.min_cutoff + p.beta * magnitude(speed_);
  value_ += one_euro_alpha(cutoff, dt) * (x - value_);
  return value_;
}

template class OneEuro<double>;
template class OneEuro<vec3>;

glm::dquat OneEuroRotation::filter(const glm::dquat& q, double dt, const OneEuroParams& p) {
  if (!started_) {
    started_ = true;
    value_ = q;
    speed_ = vec3(0.0);
    return q;
  }
  // the rotation from the filtered one to the new, the shorter way, as a rotation vector
  glm::dquat delta = q * glm::conjugate(value_);
  if (delta.w < 0.0) delta = -delta;
  const vec3 v(delta.x, delta.y, delta.z);
  const double s = glm::length(v);
  const double angle = 2.0 * std::atan2(s, delta.w);
  const vec3 axis = s > 0.0 ? v / s : vec3(1.0, 0.0, 0.0);
  speed_ += one_euro_alpha(p.d_cutoff, dt) * ((angle / dt) * axis - speed_);
  const double cutoff = p.min_cutoff + p.beta * glm::length(speed_);
  // slerp towards q by the low-pass's weight
  const double t = one_euro_alpha(cutoff, dt) * angle;
  value_ = glm::normalize(glm::dquat(std::cos(0.5 * t), std::sin(0.5 * t) * axis) * value_);
  return value_;
}

}  // namespace frusta
