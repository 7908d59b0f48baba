// SPDX-License-Identifier: MIT
// Bookkeeping for the geometry property tests: a million cases must not make a
// million EXPECT calls, so each check counts its failures per family, keeps the first
// few cases verbatim and reports once at the end.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "scenes/random_cases.h"

namespace frusta::property {

using scenes::Case;
using scenes::Family;
using scenes::kFamilyCount;

// Relative rounding allowance: 256 ulps of the quantities involved.
constexpr double kRoundingUlps = 256.0 * DBL_EPSILON;

// The size of a case in metres, ignoring any far offset: the scale of its rounding.
inline double case_scale(const Case& c) {
  const vec3 w = c.sphere.center - c.segment.distal;
  const vec3 d = c.segment.proximal - c.segment.distal;
  return std::sqrt(w.x * w.x + w.y * w.y + w.z * w.z) + std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z) +
         c.segment.proximal_radius + c.segment.distal_radius + c.sphere.radius;
}

// Largest absolute world coordinate of a case: the rounding scale of world points.
inline double world_scale(const Case& c) {
  double m = 0.0;
  for (const vec3* p : {&c.segment.proximal, &c.segment.distal, &c.sphere.center})
    for (int k = 0; k < 3; ++k) m = std::max(m, std::fabs((*p)[k]));
  return m + case_scale(c);
}

class PropertyLog {
 public:
  explicit PropertyLog(std::string property) : property_(std::move(property)) {}
  PropertyLog(const PropertyLog&) = delete;
  PropertyLog& operator=(const PropertyLog&) = delete;

  void seen(const Case& c) { ++cases_[static_cast<size_t>(c.family)]; }

  // Records a failed check; `detail` is called only on failure.
  template <class Detail>
  void check(bool ok, const char* name, const Case& c, Detail&& detail) {
    if (ok) return;
    Entry& e = entries_[name];
    ++e.checks;
    if (e.last_case == c.index && e.any) return;  // count each case once
    e.last_case = c.index;
    e.any = true;
    ++e.failures[static_cast<size_t>(c.family)];
    if (e.examples.size() < 5) e.examples.push_back(scenes::describe(c) + "\n      " + detail());
  }

  // Counts a case a check had to skip (e.g. a non-smooth point) under a reason.
  void skip(const char* reason, const Case& c) { ++skips_[reason][static_cast<size_t>(c.family)]; }

  std::uint64_t skipped(const char* reason) const {
    auto it = skips_.find(reason);
    if (it == skips_.end()) return 0;
    std::uint64_t n = 0;
    for (std::uint64_t k : it->second) n += k;
    return n;
  }

  std::uint64_t cases(Family f) const { return cases_[static_cast<size_t>(f)]; }
  std::uint64_t total_cases() const {
    std::uint64_t n = 0;
    for (std::uint64_t k : cases_) n += k;
    return n;
  }

  // One ADD_FAILURE per failed check, with counts per family and the first cases.
  void report() const {
    for (const auto& [name, e] : entries_) {
      std::ostringstream out;
      std::uint64_t total = 0;
      for (std::uint64_t k : e.failures) total += k;
      out << property_ << ": check '" << name << "' failed " << e.checks << " times in " << total
          << " of " << total_cases() << " cases (";
      for (int f = 0; f < kFamilyCount; ++f)
        if (e.failures[static_cast<size_t>(f)] > 0)
          out << scenes::family_name(f) << ' ' << e.failures[static_cast<size_t>(f)] << ' ';
      out << ")\n  first:\n";
      for (const std::string& x : e.examples) out << "    " << x << '\n';
      ADD_FAILURE() << out.str();
    }
    for (const auto& [reason, counts] : skips_) {
      std::ostringstream out;
      out << "[ " << property_ << " ] skipped (" << reason << "):";
      for (int f = 0; f < kFamilyCount; ++f)
        if (counts[static_cast<size_t>(f)] > 0)
          out << ' ' << scenes::family_name(f) << '=' << counts[static_cast<size_t>(f)];
      std::printf("%s\n", out.str().c_str());
    }
  }

  bool passed() const { return entries_.empty(); }

 private:
  struct Entry {
    std::array<std::uint64_t, kFamilyCount> failures{};  // failing cases per family
    std::uint64_t checks = 0;                            // failing checks
    std::uint64_t last_case = 0;
    bool any = false;
    std::vector<std::string> examples;
  };
  std::string property_;
  std::array<std::uint64_t, kFamilyCount> cases_{};
  std::map<std::string, Entry> entries_;
  std::map<std::string, std::array<std::uint64_t, kFamilyCount>> skips_;
};

// printf into a std::string, for check details.
template <class... Args>
std::string format(const char* fmt, Args... args) {
  char buf[512];
  std::snprintf(buf, sizeof buf, fmt, args...);
  return buf;
}

// RecordProperty takes strings and ints; rates go in as text.
inline void record(const std::string& key, double value) {
  ::testing::Test::RecordProperty(key, format("%.9g", value));
}

}  // namespace frusta::property
