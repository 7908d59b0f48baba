// SPDX-License-Identifier: MIT
// A glove on the far end of a real serial line: a pseudo-terminal whose slave side the
// engine opens through a stable symlink (as udev's /dev/serial/by-id names follow a
// glove across replugs), and whose master side this class drives from its own thread
// like firmware would: a frame at its rate, and everything the engine sends collected
// with the time it arrived. Unplugging closes the master (the engine's reads fail with
// EIO, as on a USB unplug); plugging in makes a new pty and re-points the symlink.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace frusta::scenes {

class SimulatedGlove {
 public:
  // The next frame's bytes, from the glove thread (tick counts from 0 at each plug-in).
  using Firmware = std::function<std::string(int64_t tick)>;
  // What the engine sent, as it arrives, on the glove thread (a firmware's input).
  using Listener = std::function<void(const std::string& bytes)>;

  // Creates the pty and the symlink `path` to it (replacing what is there).
  SimulatedGlove(std::string path, double rate_hz, Firmware firmware, Listener listener = nullptr);
  ~SimulatedGlove();

  const std::string& path() const { return path_; }
  void set_rate(double rate_hz);
  // Stop sending (the glove froze) or go on. Once set_sending(false) returns, no frame
  // is on its way: frames_sent() is every frame the other end will ever read.
  void set_sending(bool sending);

  // Raw bytes written now, between frames (corruption, handshakes).
  void write_raw(const std::string& bytes);

  void unplug();
  void plug_in();
  bool plugged_in() const { return master_ >= 0; }

  // What the engine sent so far, and when each chunk arrived (steady clock, ns, stamped
  // after the read: no earlier than the engine wrote it).
  struct Chunk {
    int64_t time_ns;
    std::string bytes;
  };
  std::string received() const;
  std::vector<Chunk> chunks() const;
  void clear_received();
  int64_t frames_sent() const { return frames_sent_.load(); }

 private:
  void run();
  void open_pty();

  std::string path_;
  std::atomic<double> rate_hz_;
  Firmware firmware_;
  Listener listener_;
  std::atomic<bool> sending_{true};  // changed under write_mutex_
  int master_ = -1;
  std::mutex write_mutex_;  // the glove thread's frames and write_raw's bytes
  mutable std::mutex received_mutex_;
  std::vector<Chunk> received_;
  std::atomic<int64_t> frames_sent_{0};
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace frusta::scenes
