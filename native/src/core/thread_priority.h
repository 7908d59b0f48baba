// SPDX-License-Identifier: MIT
// A haptic loop's threads (the world's, a glove's) must not wait behind whatever else
// the machine runs: at normal priority, two busy processes on 2 cores put a glove's
// command 2-5 ms late at p99; at real-time priority it stays within a period
// (tools/bench devices). Linux: SCHED_FIFO at a middle priority, below the kernel's
// interrupt threads (50) that carry the glove's bytes; granted to root or a user with
// an rtprio limit (limits.conf), refused otherwise. Windows: THREAD_PRIORITY_TIME_CRITICAL,
// which any process may set for its own threads.
//
// Threads: the thread that asks, for itself.
#pragma once

namespace frusta {

// Raise the calling thread to real-time priority; false (and unchanged) where the
// system refuses.
bool raise_to_realtime_priority();

}  // namespace frusta
