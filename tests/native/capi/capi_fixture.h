// SPDX-License-Identifier: MIT
// Shared by the C ABI tests: a fixture that fails any test leaving an unexpected
// error message behind, and an RAII owner for hand ids.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "frusta/frusta.h"

namespace frusta::testing {

// The message is thread-local and survives successful calls (like errno), so it is
// cleared before each test; any message still set at the end is a failure nobody
// checked. Expected failures go through ExpectError(), which consumes the message.
class CapiTest : public ::testing::Test {
 protected:
  void SetUp() override { clear_last_error(); }
  void TearDown() override {
    const std::string message = frusta_last_error();
    if (!message.empty()) ADD_FAILURE() << "unexpected frusta_last_error(): " << message;
  }

  // got == want and the message names `needle`; then the message is cleared.
  static void ExpectError(frusta_result got, frusta_result want, const char* needle) {
    const std::string message = frusta_last_error();
    EXPECT_EQ(got, want) << frusta_result_name(got) << ": " << message;
    EXPECT_NE(message.find(needle), std::string::npos)
        << "message \"" << message << "\" does not name " << needle;
    clear_last_error();
  }
};

// Owns a standalone hand; the test fails if creation fails.
class ScopedHand {
 public:
  explicit ScopedHand(const frusta_hand_def& def) {
    const frusta_result r = frusta_create_hand(&def, &id_);
    EXPECT_EQ(r, FRUSTA_OK) << frusta_last_error();
  }
  ~ScopedHand() {
    if (!FRUSTA_IS_NULL(id_)) frusta_destroy_hand(id_);
  }
  ScopedHand(const ScopedHand&) = delete;
  ScopedHand& operator=(const ScopedHand&) = delete;
  frusta_hand_id get() const { return id_; }

 private:
  frusta_hand_id id_{};
};

}  // namespace frusta::testing
