// SPDX-License-Identifier: MIT
// The Windows build's serial path end to end: a binary-profile glove on a COM port
// opened by URI through the Win32 serial API, driving its hand and reading commands
// back. tools/test runs it under Wine with FRUSTA_TEST_COM_PORT=COM42, a pseudo-
// terminal with frusta-com-port-glove on the far end; without a port it skips.
#include <cstdlib>
#include <string>

#include "device_api_fixture.h"
#include "devices/frusta_protocol.h"
#include "scenes/com_port_glove.h"

namespace frusta::testing {
namespace {

namespace spec = scenes::com_port_glove;

TEST_F(DeviceApiTest, ABinaryProfileGloveOnACOMPortDrivesItsHand) {
  const char* port = std::getenv("FRUSTA_TEST_COM_PORT");
  if (port == nullptr)
    GTEST_SKIP() << "no FRUSTA_TEST_COM_PORT: tools/test sets COM42 with a glove behind it";
  const frusta_device_def def = device_def();
  frusta_device_id device{};
  const std::string uri = std::string("serial:") + port + "?baud=921600";
  ASSERT_EQ(frusta_create_device(world_, uri.c_str(), &def, &device), FRUSTA_OK)
      << frusta_last_error();
  ASSERT_TRUE(run_until([&] { return status(device).frames_ok > 100; }, 5.0))
      << "frames taken: " << status(device).frames_ok;

  frusta_world_hand hand{};
  hand.struct_size = sizeof hand;
  ASSERT_EQ(frusta_world_get_hand(world_, hand_, &hand), FRUSTA_OK);
  EXPECT_NEAR(hand.haptic_angles[spec::kIndexFlexion1], spec::kIndexFlexion,
              0.5 * binary_profile::kAngleUnit);
  const frusta_device_status before = status(device);
  EXPECT_EQ(before.state, FRUSTA_DEVICE_CONNECTED);
  EXPECT_EQ(before.protocol_version, binary_profile::kVersion);
  EXPECT_EQ(before.outputs, FRUSTA_DEVICE_OUTPUT_FINGER_RESISTANCE | FRUSTA_DEVICE_OUTPUT_FINGERTIP_FORCE);
  EXPECT_DOUBLE_EQ(before.output_rate_hz, spec::kRateHz) << "the glove's, under the world's 1 kHz";

  run_until([] { return false; }, 0.5);
  const frusta_device_status after = status(device);
  // 250 at 500 a second; Wine's serial layer and a loaded machine may cost some
  EXPECT_GT(after.commands_sent - before.commands_sent, 100);
  EXPECT_EQ(after.commands_dropped, 0);
  EXPECT_EQ(after.frames_corrupt + after.frames_truncated + after.frames_out_of_range, 0);
  EXPECT_EQ(after.disconnects, 0);
  EXPECT_EQ(after.watchdog, FRUSTA_WATCHDOG_NONE);
  EXPECT_EQ(frusta_destroy_device(device), FRUSTA_OK);
}

}  // namespace
}  // namespace frusta::testing
