// SPDX-License-Identifier: MIT
// The glove tools/test puts on a COM port for the Windows build under Wine: our binary
// profile from a Linux program on a pseudo-terminal (frusta-com-port-glove) that Wine
// maps to COM42, opened by the Windows build through the Win32 serial API
// (api_com_port_test). Both sides check what they see against these.
#pragma once

#include "frusta/frusta.h"

namespace frusta::scenes::com_port_glove {

constexpr double kRateHz = 500.0;  // samples and commands each way
constexpr int kIndexFlexion1 = 1 * FRUSTA_JOINTS_PER_FINGER + 1;
constexpr double kIndexFlexion = 0.8;  // radians, what the glove reports
constexpr int kMinCommands = 100;      // what the glove must have read back

}  // namespace frusta::scenes::com_port_glove
