// SPDX-License-Identifier: MIT
// What a test may ask of its own process: how many threads it runs now (Linux's
// /proc/self/task), a temporary path no other test process shares, and (POSIX) a call
// run in a child process that may hang or eat memory without taking the test with it.
#pragma once

#include <dirent.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>

#ifndef _WIN32
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <functional>
#endif

namespace frusta::scenes {

inline int thread_count() {
  int count = 0;
  if (DIR* tasks = opendir("/proc/self/task")) {
    while (dirent* entry = readdir(tasks)) count += entry->d_name[0] != '.';
    closedir(tasks);
  }
  return count;
}

// Waits (at most `seconds`, which only turns a hang into a failure) for the thread count
// to be `expected`: a joined thread leaves /proc/self/task a moment after join returns.
inline bool thread_count_becomes(int expected, double seconds = 120.0) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (thread_count() != expected) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return true;
}

inline std::string temp_path(const std::string& name) {
  const char* folder = std::getenv("TMPDIR");
  return std::string(folder != nullptr ? folder : "/tmp") + "/frusta-" + std::to_string(getpid()) +
         "-" + name;
}

#ifndef _WIN32
// What a call run by run_in_child came to: its result and message if it returned, else
// why not (it was killed: past the deadline, or its memory grew past the cap).
struct ChildOutcome {
  bool returned = false;
  int result = -1;
  std::string message;
};

namespace detail {
inline int64_t resident_bytes(pid_t pid) {
  const std::string path = "/proc/" + std::to_string(pid) + "/status";
  std::FILE* f = std::fopen(path.c_str(), "r");
  if (f == nullptr) return 0;
  char line[256];
  long long kb = 0;
  while (std::fgets(line, sizeof line, f) != nullptr)
    if (std::sscanf(line, "VmRSS: %lld kB", &kb) == 1) break;
  std::fclose(f);
  return kb * 1024;
}
}  // namespace detail

// Runs call(&message) in a forked child and brings back its result and message. A child
// still running after `deadline_s`, or whose resident memory grew by more than
// `memory_cap` bytes, is killed: a call that hangs or reads without end fails the test
// instead of hanging it or exhausting the machine. Fork from a test with no other
// threads running.
inline ChildOutcome run_in_child(const std::function<int(std::string*)>& call, double deadline_s = 60.0,
                                 int64_t memory_cap = int64_t{256} << 20) {
  ChildOutcome outcome;
  int fds[2];
  if (pipe(fds) != 0) {
    outcome.message = "no pipe";
    return outcome;
  }
  std::fflush(nullptr);  // nothing buffered is written twice
  const pid_t pid = fork();
  if (pid == 0) {
    // the child never returns into the test: whatever the call does, it ends here
    close(fds[0]);
    std::string message;
    int result = -1;
    try {
      result = call(&message);
    } catch (const std::exception& e) {
      message = std::string("exception: ") + e.what();
    } catch (...) {
      message = "exception";
    }
    const std::string report = std::to_string(result) + "\n" + message;
    for (size_t at = 0; at < report.size();) {
      const ssize_t n = write(fds[1], report.data() + at, report.size() - at);
      if (n <= 0) break;
      at += static_cast<size_t>(n);
    }
    _exit(0);
  }
  close(fds[1]);
  if (pid < 0) {
    close(fds[0]);
    outcome.message = "no fork";
    return outcome;
  }
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(deadline_s);
  const int64_t baseline = detail::resident_bytes(pid);
  std::string report;
  for (;;) {
    pollfd p{fds[0], POLLIN, 0};
    if (poll(&p, 1, 10) > 0) {
      char buffer[4096];
      const ssize_t n = read(fds[0], buffer, sizeof buffer);
      if (n > 0) {
        report.append(buffer, static_cast<size_t>(n));
        continue;
      }
      if (n == 0 || errno != EINTR) break;  // the child is done
    }
    const int64_t grown = detail::resident_bytes(pid) - baseline;
    const bool late = std::chrono::steady_clock::now() > end;
    if (late || grown > memory_cap) {
      kill(pid, SIGKILL);
      char why[128];
      if (late)
        std::snprintf(why, sizeof why, "no answer within %g s (it hangs)", deadline_s);
      else
        std::snprintf(why, sizeof why, "its memory grew by %lld MiB (it reads without end)",
                      static_cast<long long>(grown >> 20));
      outcome.message = why;
      break;
    }
  }
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  const size_t newline = report.find('\n');
  if (outcome.message.empty() && newline != std::string::npos) {
    outcome.returned = true;
    outcome.result = std::atoi(report.substr(0, newline).c_str());
    outcome.message = report.substr(newline + 1);
  } else if (outcome.message.empty()) {
    outcome.message = "the child died (status " + std::to_string(status) + ")";
  }
  return outcome;
}
#endif

}  // namespace frusta::scenes
