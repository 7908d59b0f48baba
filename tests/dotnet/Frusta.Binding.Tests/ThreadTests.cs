// SPDX-License-Identifier: MIT
// Several threads read snapshots while the world runs on its own 1 kHz thread and the
// host feeds input.
using System;
using System.Collections.Generic;
using System.Linq;
using System.Threading;
using Frusta.Binding;
using Xunit;

namespace Frusta.Binding.Tests
{
    public class ThreadTests
    {
        [Fact]
        public void ReadersOnSeveralThreadsSeeConsistentMonotonicSnapshots()
        {
            using var tree = SphereTree.Load(TestEnv.SampleObject("ball"));
            using var world = new World();
            FrustaHandId right = world.CreateHand(FrustaHandDef.Default);
            FrustaHandDef leftDef = FrustaHandDef.Default;
            leftDef.Side = FrustaHandSide.Left;
            FrustaHandId left = world.CreateHand(leftDef);
            FrustaObjectDef ball = FrustaObjectDef.Default;
            ball.Pose.Position = new Vector3d(0.15, 0.0, -0.04);
            world.CreateObject(tree, ball);
            var angles = new double[20];
            var palm = FrustaPose.Identity;
            world.SetHaptic(right, palm, angles);
            world.SetHaptic(left, palm, angles);

            const int readers = 3;
            // counts reached, not rates: a busy machine takes longer, and the wait below lets it
            const ulong steps = 500;
            const long readsEach = 50;
            var stop = new ManualResetEventSlim();
            var failures = new List<string>();
            var reads = new long[readers];
            var lastSteps = new ulong[readers];
            double period = 1.0 / world.RateHz;
            var threads = Enumerable.Range(0, readers).Select(r => new Thread(() =>
            {
                WorldSnapshot snapshot = world.CreateSnapshot();
                ulong previous = 0;
                try
                {
                    while (!stop.IsSet)
                    {
                        world.ReadSnapshot(snapshot);
                        ref readonly FrustaWorldState s = ref snapshot.State;
                        if (s.Step < previous) throw new Exception($"step went back from {previous} to {s.Step}");
                        // one step: the time, the hands and their contacts belong together
                        if (Math.Abs(s.Time - s.Step * period) > 1e-9) throw new Exception($"time {s.Time} at step {s.Step}");
                        // hands and objects come at the first step
                        int present = s.Step == 0 ? 0 : 2;
                        if (s.HandCount != present || snapshot.HandCount != present || s.ObjectCount != present / 2)
                            throw new Exception($"{s.HandCount} hands ({snapshot.HandCount} copied), {s.ObjectCount} objects at step {s.Step}");
                        for (int h = 0; h < snapshot.HandCount; ++h)
                        {
                            ref readonly FrustaWorldHand hand = ref snapshot.GetHand(h);
                            if (hand.ContactCount != snapshot.GetContacts(h).Length)
                                throw new Exception($"hand {h}: {hand.ContactCount} contacts, {snapshot.GetContacts(h).Length} copied");
                            foreach (var c in snapshot.GetContacts(h))
                                if (!double.IsFinite(c.Distance) || Math.Abs(c.Normal.Length - 1) > 1e-9)
                                    throw new Exception($"hand {h}: a torn contact");
                        }
                        previous = s.Step;
                        Volatile.Write(ref lastSteps[r], previous);
                        Interlocked.Increment(ref reads[r]);
                    }
                }
                catch (Exception e)
                {
                    lock (failures) failures.Add($"reader {r}: {e}");
                }
            })).ToArray();

            world.Start();
            foreach (var t in threads) t.Start();
            // the host moves the hands into the ball and back, by the world's time, until the
            // world has taken its steps and every reader has read its snapshots of stepped worlds
            // (or one failed)
            var state = new FrustaWorldState();
            bool Failed() { lock (failures) return failures.Count > 0; }
            Waiting.Until(() =>
            {
                world.Read(ref state);
                double z = -0.02 * (0.5 + 0.5 * Math.Sin(state.Time * 20));
                palm.Position = new Vector3d(0, 0, z);
                world.SetHaptic(right, palm, angles);
                world.SetHaptic(left, palm, angles);
                return Failed() || (state.Step >= steps && Enumerable.Range(0, readers).All(r =>
                    Interlocked.Read(ref reads[r]) >= readsEach && Volatile.Read(ref lastSteps[r]) > 0));
            }, $"{steps} steps and {readsEach} reads by each reader", () =>
                $"step {state.Step}; reads {string.Join(", ", reads)}; " +
                $"last steps read {string.Join(", ", lastSteps)}");
            stop.Set();
            foreach (var t in threads) t.Join();
            world.Stop();

            Assert.Empty(failures);
            world.Read(ref state);
            Assert.True(state.Step >= steps, $"{state.Step} steps");
            for (int r = 0; r < readers; ++r)
            {
                Assert.True(reads[r] >= readsEach, $"reader {r} read {reads[r]} snapshots");
                Assert.True(lastSteps[r] > 0 && lastSteps[r] <= state.Step, $"reader {r} ended at step {lastSteps[r]}");
            }
        }

        [Fact]
        public void DisposeWaitsForAReaderInFlightAndThenRefusesIt()
        {
            var world = new World();
            world.CreateHand(FrustaHandDef.Default);
            world.Start();
            var snapshot = world.CreateSnapshot();
            Exception end = null;
            long reads = 0;
            var reader = new Thread(() =>
            {
                try
                {
                    while (true)
                    {
                        world.ReadSnapshot(snapshot);
                        Interlocked.Increment(ref reads);
                    }
                }
                catch (Exception e)
                {
                    Volatile.Write(ref end, e);
                }
            });
            reader.Start();
            // dispose while the reader is reading: once it has read (not after a pause, which a
            // busy machine may spend without ever running the reader)
            Waiting.Until(() => Interlocked.Read(ref reads) >= 100 || Volatile.Read(ref end) != null,
                          "the reader to read 100 snapshots", () => $"{Interlocked.Read(ref reads)} reads, ended by {end}");
            Assert.Null(Volatile.Read(ref end));
            world.Dispose();
            reader.Join();
            Assert.IsType<ObjectDisposedException>(end);
            Assert.False(world.IsValid);
        }
    }
}
