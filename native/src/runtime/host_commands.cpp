// SPDX-License-Identifier: MIT
#include "runtime/host_commands.h"

#include "core/error.h"

namespace frusta {

frusta_result HostCommands::push(const WorldCommand& command) {
  if (!queue_.push(command))
    return fail(FRUSTA_ERROR_CAPACITY, "the world's command queue is full (%zu): step the world",
                queue_.capacity());
  ++pushed_;
  return FRUSTA_OK;
}

}  // namespace frusta
