// SPDX-License-Identifier: MIT
// Tests wait for the state they check, never for an amount of time: the deadline only
// turns a hang into a failure that shows the last state, so it is generous (a busy
// machine may be slow, and a long deadline costs nothing while things work).
using System;
using System.Diagnostics;
using System.Threading;
using Xunit;

namespace Frusta.Binding.Tests
{
    static class Waiting
    {
        /// <summary>How long a wait may take before the test fails.</summary>
        public const double DeadlineSeconds = 120;

        /// <summary>Call <paramref name="done"/> (which may also do the work that gets there) until it is
        /// true, a millisecond apart; fail after <see cref="DeadlineSeconds"/>, naming
        /// <paramref name="what"/> and the last state <paramref name="state"/> describes.</summary>
        public static void Until(Func<bool> done, string what, Func<string> state)
        {
            var clock = Stopwatch.StartNew();
            while (!done())
            {
                if (clock.Elapsed.TotalSeconds > DeadlineSeconds)
                    Assert.Fail($"waited {DeadlineSeconds} s for {what}; last state: {state()}");
                Thread.Sleep(1); // other threads (the world's, a glove's) get the core
            }
        }
    }
}
