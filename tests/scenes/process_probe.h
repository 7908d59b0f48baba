// SPDX-License-Identifier: MIT
// What a test may ask of its own process: how many threads it runs now (Linux's
// /proc/self/task), and a temporary path no other test process shares.
#pragma once

#include <dirent.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

namespace frusta::scenes {

inline int thread_count() {
  int count = 0;
  if (DIR* tasks = opendir("/proc/self/task")) {
    while (dirent* entry = readdir(tasks)) count += entry->d_name[0] != '.';
    closedir(tasks);
  }
  return count;
}

inline std::string temp_path(const std::string& name) {
  const char* folder = std::getenv("TMPDIR");
  return std::string(folder != nullptr ? folder : "/tmp") + "/frusta-" + std::to_string(getpid()) +
         "-" + name;
}

}  // namespace frusta::scenes
