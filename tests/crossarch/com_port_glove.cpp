// SPDX-License-Identifier: MIT
// frusta-com-port-glove LINK SECONDS
// A binary-profile glove on a pseudo-terminal, symlinked at LINK (tools/test: Wine's
// dosdevices/com42, so Windows programs under Wine open it as COM42). It reports the
// index flexion of com_port_glove.h at 500 Hz and reads back what the engine sends,
// until SIGTERM or SECONDS; then prints what it saw as JSON and exits 0 only if the
// engine handshook, sent enough commands, in sequence, and no frame was broken.
#include <signal.h>

#include <cstdio>
#include <cstdlib>
#include <ctime>

#include "devices/device_types.h"
#include "scenes/binary_glove.h"
#include "scenes/com_port_glove.h"

int main(int argc, char** argv) {
  using namespace frusta;
  namespace spec = scenes::com_port_glove;
  if (argc != 3) {
    std::fprintf(stderr, "usage: frusta-com-port-glove LINK SECONDS\n");
    return 2;
  }
  // blocked before any thread starts, so only sigtimedwait below takes them
  sigset_t stop;
  sigemptyset(&stop);
  sigaddset(&stop, SIGTERM);
  sigaddset(&stop, SIGINT);
  pthread_sigmask(SIG_BLOCK, &stop, nullptr);

  DeviceCapabilities caps;
  caps.outputs = kOutputFingerResistance | kOutputFingertipForce;
  caps.input_rate_hz = spec::kRateHz;
  caps.output_rate_hz = spec::kRateHz;
  scenes::BinaryGlove firmware(caps);
  firmware.set_angle(spec::kIndexFlexion1, spec::kIndexFlexion);
  scenes::SimulatedGlove glove(argv[1], spec::kRateHz, firmware.firmware(), firmware.listener());

  const timespec timeout{static_cast<time_t>(std::atof(argv[2])), 0};
  sigtimedwait(&stop, nullptr, &timeout);

  const auto commands = firmware.commands();
  int gaps = 0;
  for (size_t i = 1; i < commands.size(); ++i)
    if (static_cast<uint16_t>(commands[i].command.sequence - commands[i - 1].command.sequence) != 1)
      ++gaps;
  std::printf("{\"hellos\": %d, \"faults\": %d, \"samples_sent\": %lld, \"commands\": %zu, "
              "\"sequence_gaps\": %d}\n",
              firmware.hellos(), firmware.faults(), static_cast<long long>(firmware.samples_sent()),
              commands.size(), gaps);
  const bool ok = firmware.hellos() >= 1 && firmware.faults() == 0 &&
                  commands.size() >= static_cast<size_t>(spec::kMinCommands) && gaps == 0;
  // no destructors: once the engine has closed the port, nothing drains the line, and
  // the glove's thread waits in write for room that never comes
  std::fflush(stdout);
  std::_Exit(ok ? 0 : 1);
}
