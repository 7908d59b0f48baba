// SPDX-License-Identifier: MIT
// The sections a custom-JSON bench was asked for: its arguments not starting with '-'
// (tools/bench passes Google Benchmark's flags to every suite); none named, all wanted.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

namespace frusta::bench {

class Sections {
 public:
  Sections(int argc, char** argv) {
    for (int i = 1; i < argc; ++i)
      if (argv[i][0] != '-') names_.push_back(argv[i]);
  }
  bool wanted(const char* section) const {
    return names_.empty() || std::find(names_.begin(), names_.end(), section) != names_.end();
  }

 private:
  std::vector<std::string> names_;
};

}  // namespace frusta::bench
