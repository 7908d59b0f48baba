// SPDX-License-Identifier: MIT
// Paths a host might be handed as a glove recording (replay:FILE) or as where to record
// one (&record=FILE) that are no such thing, made on disk for the test (POSIX): what
// each must be refused with, and a word its message must hold besides the path.
#pragma once

#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "frusta/frusta.h"
#include "scenes/process_probe.h"

namespace frusta::scenes {

struct HostilePath {
  std::string path;
  frusta_result code;
  std::string says;  // besides the path
};

class HostileRecordings {
 public:
  // largest: the most bytes a recording may have (a file one byte larger is made, sparse)
  explicit HostileRecordings(int64_t largest) {
    const std::string fifo = make("fifo");
    (void)!mkfifo(fifo.c_str(), 0600);
    const std::string folder = make("folder");
    (void)!mkdir(folder.c_str(), 0700);
    const std::string zero_link = make("zero-link");
    (void)!symlink("/dev/zero", zero_link.c_str());
    const std::string huge = file("huge", "frusta-recording 1 frusta\n");
    (void)!truncate(huge.c_str(), static_cast<off_t>(largest + 1));  // sparse: no disk used
    std::string garbage;
    uint32_t x = 12345;
    for (int i = 0; i < 4096; ++i) garbage += static_cast<char>((x = x * 1664525u + 1013904223u) >> 24);
    const std::string header = "frusta-recording 1 opengloves\n";
    // records: int64 time (ns), uint32 size, the bytes
    const std::string record = std::string("\x10\0\0\0\0\0\0\0\x03\0\0\0", 12) + "A1\n";
    const std::string claims_4g = std::string("\x10\0\0\0\0\0\0\0\xff\xff\xff\xff", 12) + "A1\n";
    const std::string earlier = std::string("\x08\0\0\0\0\0\0\0\x03\0\0\0", 12) + "A1\n";
    const std::string empty = std::string("\x20\0\0\0\0\0\0\0\0\0\0\0", 12);
    replay = {
        {"/dev/zero", FRUSTA_ERROR_IO, "not a regular file"},
        {zero_link, FRUSTA_ERROR_IO, "not a regular file"},
        {fifo, FRUSTA_ERROR_IO, "not a regular file"},
        {folder, FRUSTA_ERROR_IO, "not a regular file"},
        {huge, FRUSTA_ERROR_FILE_FORMAT, "larger than"},
        {file("cut", "frusta-recor"), FRUSTA_ERROR_FILE_FORMAT, "not a Frusta glove recording"},
        {file("garbage", garbage), FRUSTA_ERROR_FILE_FORMAT, "not a Frusta glove recording"},
        {file("no-newline", "frusta-recording 1 opengloves" + std::string(100000, 's')),
         FRUSTA_ERROR_FILE_FORMAT, "not a Frusta glove recording"},
        {file("binary-protocol", "frusta-recording 1 \x01\xfe\x7f\n"), FRUSTA_ERROR_FILE_FORMAT, "protocol"},
        {file("unknown-protocol", "frusta-recording 1 lucidgloves\n"), FRUSTA_ERROR_FILE_FORMAT,
         "unknown glove protocol"},
        {file("claims-4g", header + record + claims_4g + record), FRUSTA_ERROR_CORRUPT_FILE, "corrupt"},
        {file("back-in-time", header + record + earlier), FRUSTA_ERROR_CORRUPT_FILE, "corrupt"},
        {file("empty-record", header + empty + record), FRUSTA_ERROR_CORRUPT_FILE, "corrupt"},
    };
    record_to = {
        {fifo, FRUSTA_ERROR_IO, "not a regular file"},
        {"/dev/full", FRUSTA_ERROR_IO, "not a regular file"},
        {zero_link, FRUSTA_ERROR_IO, "not a regular file"},
        {folder, FRUSTA_ERROR_IO, "not a regular file"},
    };
    good = file("good", header + record);
  }
  ~HostileRecordings() {
    for (const std::string& p : made_) {
      std::remove(p.c_str());  // files, links, FIFOs and the (empty) folder alike
    }
  }
  HostileRecordings(const HostileRecordings&) = delete;
  HostileRecordings& operator=(const HostileRecordings&) = delete;

  std::vector<HostilePath> replay;     // as replay:FILE
  std::vector<HostilePath> record_to;  // as &record=FILE
  std::string good;                    // a short, sound OpenGloves recording

 private:
  std::string make(const std::string& name) {
    made_.push_back(temp_path("hostile-" + name));
    std::remove(made_.back().c_str());
    return made_.back();
  }
  std::string file(const std::string& name, const std::string& bytes) {
    const std::string path = make(name);
    if (std::FILE* f = std::fopen(path.c_str(), "wb")) {
      std::fwrite(bytes.data(), 1, bytes.size(), f);
      std::fclose(f);
    }
    return path;
  }
  std::vector<std::string> made_;
};

}  // namespace frusta::scenes
