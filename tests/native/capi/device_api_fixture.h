// SPDX-License-Identifier: MIT
// A world with one hand, driven by gloves opened through the C ABI: the host's loop
// and a glove's status, for the device tests on any platform.
#pragma once

#include <chrono>
#include <functional>
#include <thread>

#include "capi_fixture.h"

namespace frusta::testing {

class DeviceApiTest : public CapiTest {
 protected:
  void SetUp() override {
    CapiTest::SetUp();
    const frusta_world_def def = frusta_default_world_def();
    ASSERT_EQ(frusta_create_world(&def, &world_), FRUSTA_OK) << frusta_last_error();
    const frusta_hand_def hand = frusta_default_hand_def();
    ASSERT_EQ(frusta_create_world_hand(world_, &hand, &hand_), FRUSTA_OK);
  }
  void TearDown() override {
    if (frusta_world_is_valid(world_)) {
      EXPECT_EQ(frusta_destroy_world(world_), FRUSTA_OK);
    }
    CapiTest::TearDown();
  }

  // the host's loop: step and read until done() or the time is up
  bool run_until(const std::function<bool()>& done, double seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    frusta_world_state state{};
    state.struct_size = sizeof state;
    while (std::chrono::steady_clock::now() < end) {
      EXPECT_EQ(frusta_world_step(world_), FRUSTA_OK);
      EXPECT_EQ(frusta_world_read(world_, &state), FRUSTA_OK);
      if (done()) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return false;
  }

  // the defaults, driving the world's hand
  frusta_device_def device_def() const {
    frusta_device_def def = frusta_default_device_def();
    def.hand = hand_;
    return def;
  }

  frusta_device_status status(frusta_device_id device) {
    frusta_device_status s{};
    s.struct_size = sizeof s;
    EXPECT_EQ(frusta_device_get_status(device, &s), FRUSTA_OK) << frusta_last_error();
    return s;
  }

  frusta_world_id world_{};
  frusta_hand_id hand_{};
};

}  // namespace frusta::testing
