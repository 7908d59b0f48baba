// SPDX-License-Identifier: MIT
// Gloves through the managed API: the def's defaults, URIs the library refuses, and the
// bundled recording of the demo hand (samples/data/demo_glove.frrec, Frusta's binary
// profile at 100 Hz with a palm pose) replayed into a running world.
using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Threading;
using Frusta.Binding;
using Xunit;
using Xunit.Abstractions;
using static Frusta.Binding.Tests.Assertions;

namespace Frusta.Binding.Tests
{
    public class DeviceTests
    {
        readonly ITestOutputHelper output;

        public DeviceTests(ITestOutputHelper output) => this.output = output;

        static string Recording => TestEnv.Recording;
        static string ReplayAsFastAsRead => $"replay:{Recording}?speed=max";

        /// <summary>The CSV written with the recording by the same generator: one frame line per sample.</summary>
        static string[] CsvFrames() =>
            File.ReadLines(Path.Combine(TestEnv.Root, "samples", "data", "demo_glove.csv"))
                .Where(l => l.StartsWith("frame,", StringComparison.Ordinal)).ToArray();

        static double[] Numbers(string line) =>
            line.Split(',').Skip(1).Select(x => double.Parse(x, CultureInfo.InvariantCulture)).ToArray();

        /// <summary>A world of one default right hand; running on its own thread when asked.</summary>
        static World WorldWithHand(bool run)
        {
            var world = new World();
            Assert.Equal(1, world.CreateHand(FrustaHandDef.Default).Index1);
            if (run) world.Start();
            return world;
        }

        /// <summary>Poll the glove and read the world (as a host's frame does) until done; fails
        /// after <see cref="Waiting.DeadlineSeconds"/> showing the glove's last status.</summary>
        static void PollUntil(Device device, World world, Func<bool> done, string what)
        {
            var state = new FrustaWorldState();
            Waiting.Until(() =>
            {
                device.Poll();
                world.Read(ref state);
                return done();
            }, what, () => Describe(device.PolledStatus));
        }

        static string Describe(in FrustaDeviceStatus s) =>
            $"{s.State}, watchdog {s.Watchdog}, {s.FramesOk} frames, input {s.InputRateHz:R} Hz, " +
            $"last sample {s.LastSampleAgeS:R} s ago, {s.CommandsSent} commands, " +
            $"{s.Disconnects} disconnects, {s.Reconnects} reconnects";

        /// <summary>Latch a step taken after this call, then read one hand of it.</summary>
        static FrustaWorldHand HandAfterNextSteps(World world, FrustaHandId hand)
        {
            var state = new FrustaWorldState();
            world.Read(ref state);
            ulong after = state.Step + 2;
            Waiting.Until(() =>
            {
                world.Read(ref state);
                return state.Step >= after;
            }, $"the world to reach step {after}", () => $"step {state.Step}");
            var h = new FrustaWorldHand();
            world.GetHand(hand, ref h);
            return h;
        }

        [Fact]
        public void DefaultsAreTheHeadersDocumentedDefaults()
        {
            FrustaDeviceDef d = FrustaDeviceDef.Default;
            Assert.Equal(728, d.struct_size);
            Assert.NotEqual(0, d.internal_value);
            Assert.Equal(0, d.reserved0);
            Assert.True(d.Hand.IsNull, "the caller names the hand");
            Assert.Equal(0, d.reserved1);
            Assert.Equal(0.0, d.OutputRateHz);
            Assert.Equal((0.05, 0.05, 0.25, 0.2), (d.WatchdogS, d.EngineTimeoutS, d.HostTimeoutS, d.ReconnectIntervalS));
            Assert.Equal((500.0, 25.0), (d.MaxForceRate, d.MaxTorqueRate));
            Assert.Equal((10.0, 10.0, 0.5), (d.MaxFingerResistance, d.MaxFingertipForce, d.MaxJointTorque));
            Assert.Equal((10.0, 1000.0, 4095.0), (d.BrakeFullScale, d.BrakeUnits, d.AnalogMax));
            for (int f = 0; f < FrustaConstants.FingerCount; ++f)
            {
                var finger = (FrustaFinger)f;
                Assert.Equal(2048.0, d.GetSplayCenter(finger));
                Assert.Equal(2047.0, d.GetSplaySpan(finger));
                Near(15 * Math.PI / 180, d.GetAbductionRange(finger), 1e-12, $"{finger} abduction range");
                for (int j = 0; j < FrustaConstants.FlexionJointsPerFinger; ++j)
                {
                    // straight at raw 0, a fist at the full reading
                    Assert.Equal(0.0, d.GetCurlOpen(finger, j));
                    Assert.Equal(d.AnalogMax, d.GetCurlClosed(finger, j));
                    Assert.Equal(0.0, d.GetFlexionOpen(finger, j));
                    double fist = d.GetFlexionClosed(finger, j);
                    Assert.True(fist >= 30 * Math.PI / 180 && fist <= 95 * Math.PI / 180, $"{finger} joint {j} fist {fist} rad");
                }
            }
            // a fist bends the fingers more than the thumb, whose first segment is the metacarpal
            Assert.True(d.GetFlexionClosed(FrustaFinger.Index, 0) > d.GetFlexionClosed(FrustaFinger.Thumb, 0));
            Assert.Equal(FrustaLibrary.GetNativeStructSize("frusta_device_def"), d.struct_size);
        }

        [Fact]
        public void CalibrationAccessorsCheckTheirRangeAndWriteTheRightSlot()
        {
            FrustaDeviceDef d = FrustaDeviceDef.Default;
            Assert.Throws<ArgumentOutOfRangeException>(() => d.GetCurlOpen(FrustaFinger.Thumb, 3));
            Assert.Throws<ArgumentOutOfRangeException>(() => d.GetCurlClosed(FrustaFinger.Little, -1));
            Assert.Throws<ArgumentOutOfRangeException>(() => d.SetFlexionClosed((FrustaFinger)5, 0, 1.0));
            Assert.Throws<ArgumentOutOfRangeException>(() => d.GetSplaySpan((FrustaFinger)(-1)));
            d.SetCurlOpen(FrustaFinger.Ring, 2, 123);
            d.SetFlexionClosed(FrustaFinger.Middle, 1, 1.25);
            d.SetSplayCenter(FrustaFinger.Little, 2000);
            Assert.Equal(123.0, d.GetCurlOpen(FrustaFinger.Ring, 2));
            Assert.Equal(0.0, d.GetCurlOpen(FrustaFinger.Ring, 1));
            Assert.Equal(0.0, d.GetCurlOpen(FrustaFinger.Little, 0));
            Assert.Equal(1.25, d.GetFlexionClosed(FrustaFinger.Middle, 1));
            Assert.Equal(2000.0, d.GetSplayCenter(FrustaFinger.Little));
            Assert.Equal(2048.0, d.GetSplayCenter(FrustaFinger.Ring));
        }

        [Fact]
        public void BadUrisAndDefsAreRefusedNamingTheProblem()
        {
            using World world = WorldWithHand(run: false);
            Fails(FrustaResult.OutOfRange, () => world.CreateDevice("bogus:x", world.Hands[0]), "\"bogus:x\"", "unknown scheme", "opengloves:");
            Fails(FrustaResult.OutOfRange, () => world.CreateDevice("no-scheme", world.Hands[0]), "\"no-scheme\"", "no scheme");
            Fails(FrustaResult.OutOfRange, () => world.CreateDevice("opengloves:", world.Hands[0]), "\"opengloves:\"", "no device path");
            Fails(FrustaResult.Io, () => world.CreateDevice("serial:/nonexistent/tty", world.Hands[0]), "/nonexistent/tty", "cannot open");
            Fails(FrustaResult.OutOfRange, () => world.CreateDevice("hid:zz:1", world.Hands[0]), "\"hid:zz:1\"", "hid:VID:PID", "hexadecimal");
            Fails(FrustaResult.OutOfRange, () => world.CreateDevice($"replay:{Recording}?speed=fast", world.Hands[0]), "unknown parameter", "speed=1|max");
            Fails(FrustaResult.Io, () => world.CreateDevice("replay:/nonexistent/glove.frrec", world.Hands[0]), "/nonexistent/glove.frrec");

            FrustaDeviceDef def = FrustaDeviceDef.Default;
            def.Hand = world.Hands[0];
            def.WatchdogS = 0;
            Fails(FrustaResult.OutOfRange, () => world.CreateDevice(ReplayAsFastAsRead, def), "watchdog_s");
            def = FrustaDeviceDef.Default;
            Fails(FrustaResult.NullId, () => world.CreateDevice(ReplayAsFastAsRead, def), "frusta_device_def.hand", "null");
            def.Hand = world.Hands[0];
            def.Hand.Index1 = 2;
            Fails(FrustaResult.StaleId, () => world.CreateDevice(ReplayAsFastAsRead, def), "frusta_device_def.hand", "no hand of this world");
            using (var hand = new Hand())
            {
                def.Hand = hand.Id;
                Fails(FrustaResult.StaleId, () => world.CreateDevice(ReplayAsFastAsRead, def), "frusta_device_def.hand", "standalone");
            }
            def = FrustaDeviceDef.Default;
            def.Hand = world.Hands[0];
            def.SetCurlClosed(FrustaFinger.Index, 0, 0);
            Fails(FrustaResult.OutOfRange, () => world.CreateDevice(ReplayAsFastAsRead, def), "curl_open and curl_closed");
            Assert.Throws<ArgumentNullException>(() => world.CreateDevice(null, world.Hands[0]));

            // nothing was opened: the host still drives the hand
            world.SetHaptic(world.Hands[0], FrustaPose.Identity, new double[FrustaConstants.HandJointCount]);
        }

        [Fact]
        public void TheDemoRecordingDrivesTheHandToItsLastPoseThenTheReplayEnds()
        {
            string[] frames = CsvFrames();
            double[] last = Numbers(frames[^1]);
            using World world = WorldWithHand(run: true);
            using Device glove = world.CreateDevice(ReplayAsFastAsRead, world.Hands[0]);
            Assert.Equal(ReplayAsFastAsRead, glove.Uri);
            Assert.Equal(world.Hands[0], glove.Hand);
            Assert.Same(world, glove.World);
            Assert.False(glove.Id.IsNull);
            Assert.True(glove.IsValid);
            Assert.Equal(FrustaDeviceState.Connected, glove.State);

            var states = new List<(FrustaDeviceState Old, FrustaDeviceState New, long FramesOk)>();
            var reasons = new List<(FrustaWatchdogReason Old, FrustaWatchdogReason New)>();
            glove.StateChanged += (sender, e) =>
            {
                Assert.Same(glove, sender);
                states.Add((e.OldState, e.NewState, e.Status.FramesOk));
            };
            glove.WatchdogChanged += (sender, e) => reasons.Add((e.OldReason, e.NewReason));

            // speed=max is checked by what it does (every frame taken, then the end), not by how
            // long it took: a loaded machine may take any time
            var clock = Stopwatch.StartNew();
            PollUntil(glove, world, () => glove.State == FrustaDeviceState.Disconnected, "the replay to end");
            double seconds = clock.Elapsed.TotalSeconds;

            Assert.Equal(new[] { (FrustaDeviceState.Connected, FrustaDeviceState.Disconnected, (long)frames.Length) }, states.ToArray());
            Assert.NotEmpty(reasons);
            Assert.Equal(FrustaWatchdogReason.Disconnected, reasons[^1].New);
            FrustaDeviceStatus s = glove.Status;
            Assert.Equal(FrustaDeviceState.Disconnected, s.State);
            Assert.Equal(FrustaWatchdogReason.Disconnected, s.Watchdog);
            Assert.Equal(frames.Length, s.FramesOk);
            Assert.Equal((0L, 0L, 0L, 0L), (s.FramesCorrupt, s.FramesTruncated, s.FramesOutOfRange, s.SamplesRejected));
            Assert.Equal((1L, 0L), (s.Disconnects, s.Reconnects));
            Assert.True(s.HasPalmPose, "the recording's glove announces a tracker");
            Assert.Equal(FrustaConstants.FingerCount, s.Fingers);
            Assert.False(s.RecordingFailed);
            output.WriteLine($"speed=max: {s.FramesOk} samples ({frames.Length} frames in the CSV), disconnected " +
                             $"after {seconds * 1000:0.#} ms of polling, {s.CommandsSent} commands sent");

            // the world's haptic hand took the recording's last sample: palm (1e-5 m steps on the wire)
            // and joint angles (1e-4 rad steps)
            FrustaWorldHand h = HandAfterNextSteps(world, world.Hands[0]);
            Assert.True(h.Solved);
            Near(new Vector3d(last[1], last[2], last[3]), h.HapticPalm.Position, 1e-5, "haptic palm");
            SameRotation(new Quaterniond(last[4], last[5], last[6], last[7]), h.HapticPalm.Rotation, 1e-8, "haptic palm rotation");
            for (int j = 0; j < FrustaConstants.HandJointCount; ++j)
                Near(last[8 + j], h.GetHapticAngle(j), 1e-4, $"haptic angle {j}");

            // the ended replay stays disconnected: reopening it fails every reconnect interval. The
            // glove's thread republishes the status as it tries, the last sample ageing by its own
            // clock: wait until that clock is two intervals past the last sample (not for a time
            // on ours, which says nothing about whether that thread got to run)
            double reopenedBy = 2 * FrustaDeviceDef.Default.ReconnectIntervalS;
            PollUntil(glove, world, () => glove.PolledStatus.LastSampleAgeS > reopenedBy,
                      $"the glove's thread to be {reopenedBy} s past the last sample");
            Assert.True(glove.Poll());
            Assert.Equal((FrustaDeviceState.Disconnected, 1L, 0L), (glove.PolledStatus.State, glove.PolledStatus.Disconnects, glove.PolledStatus.Reconnects));
            Assert.Single(states);
        }

        [Fact]
        public void AGloveOwnsItsHandUntilDisposed()
        {
            using World world = WorldWithHand(run: true);
            var angles = new double[FrustaConstants.HandJointCount];
            world.SetHaptic(world.Hands[0], FrustaPose.Identity, angles);
            Device glove = world.CreateDevice(ReplayAsFastAsRead, world.Hands[0]);
            FrustaDeviceId first = glove.Id;

            Fails(FrustaResult.WrongState, () => world.SetHaptic(world.Hands[0], FrustaPose.Identity, angles), "glove");
            Fails(FrustaResult.WrongState, () => world.CreateDevice(ReplayAsFastAsRead, world.Hands[0]), "hand 0 already has a glove");
            Assert.True(glove.IsValid);

            glove.Dispose();
            glove.Dispose();
            Assert.False(glove.IsValid);
            Assert.Equal(0, Native.frusta_device_is_valid(first));
            Assert.False(glove.Poll());
            Assert.Throws<ObjectDisposedException>(() => glove.Status);
            Assert.Throws<ObjectDisposedException>(() => glove.SetPalmPose(FrustaPose.Identity));
            world.SetHaptic(world.Hands[0], FrustaPose.Identity, angles);

            // the hand takes a glove again, under a new id; the old one stays stale
            using Device again = world.CreateDevice(ReplayAsFastAsRead, world.Hands[0]);
            Assert.NotEqual(first, again.Id);
            Assert.True(again.IsValid);
            Assert.Equal(0, Native.frusta_device_is_valid(first));
        }

        [Fact]
        public void DisposingTheWorldClosesItsGloves()
        {
            World world = WorldWithHand(run: true);
            using Device glove = world.CreateDevice(ReplayAsFastAsRead + "&loop=1", world.Hands[0]);
            FrustaDeviceId id = glove.Id;
            var closed = new List<(FrustaDeviceState, FrustaDeviceState)>();
            glove.StateChanged += (_, e) => closed.Add((e.OldState, e.NewState));
            Assert.True(glove.Poll());
            FrustaDeviceState before = glove.State;

            world.Dispose();
            Assert.False(glove.IsValid);
            Assert.Equal(0, Native.frusta_device_is_valid(id));
            Fails(FrustaResult.StaleId, () =>
            {
                var status = new FrustaDeviceStatus();
                glove.GetStatus(ref status);
            }, "world was disposed");
            Fails(FrustaResult.StaleId, () => glove.SetPalmPose(FrustaPose.Identity), "world was disposed");

            // Poll reports the close once, then nothing more
            Assert.False(glove.Poll());
            Assert.False(glove.Poll());
            Assert.Equal((before, FrustaDeviceState.Closed), closed[^1]);
            Assert.Equal(FrustaDeviceState.Closed, glove.State);
            Assert.Equal(FrustaDeviceState.Closed, glove.PolledStatus.State);
            Assert.Equal(1, closed.Count(c => c.Item2 == FrustaDeviceState.Closed));
            glove.Dispose(); // the stale id is fine
        }

        [Fact]
        public void APalmPoseIsCheckedAndTakenWhileOpen()
        {
            using World world = WorldWithHand(run: false);
            using Device glove = world.CreateDevice(ReplayAsFastAsRead, world.Hands[0]);
            glove.SetPalmPose(new FrustaPose(new Vector3d(0.1, 0.2, 0.3), Quaterniond.Identity));
            Fails(FrustaResult.NotFinite, () => glove.SetPalmPose(new FrustaPose(new Vector3d(double.NaN, 0, 0), Quaterniond.Identity)), "palm");
            var zero = new FrustaPose(Vector3d.Zero, new Quaterniond(0, 0, 0, 0));
            Fails(FrustaResult.OutOfRange, () => glove.SetPalmPose(zero), "palm");
        }

        [Fact]
        public void ARealTimeReplayArrivesAtTheRecordingsRate()
        {
            // each frame's stamp in the recording: the CSV's time, the record's time to the ns
            double[] stamps = CsvFrames().Select(l => Numbers(l)[0]).ToArray();
            const long enough = 100; // frames: past the input rate's 64-sample window
            using World world = WorldWithHand(run: true);
            // timed from before the open: frame i is due i/100 s after the open, never sooner.
            // Looped, so that on a busy machine the wait below may last its whole deadline.
            var clock = Stopwatch.StartNew();
            using Device glove = world.CreateDevice($"replay:{Recording}?speed=1&loop=1", world.Hands[0]);
            FrustaDeviceStatus flowing = default;
            bool sawFlowing = false;
            double tookSeconds = 0;
            PollUntil(glove, world, () =>
            {
                ref readonly FrustaDeviceStatus s = ref glove.PolledStatus;
                // the stopwatch and the replay share the monotonic clock; read after the status
                double seconds = clock.ElapsedTicks / (double)Stopwatch.Frequency;
                // a real-time replay is never ahead of its recording (how far behind, a busy
                // machine decides: only this lower bound is checked)
                if (s.FramesOk > 0 && s.FramesOk <= stamps.Length)
                    Assert.True(seconds >= stamps[s.FramesOk - 1],
                        $"frame {s.FramesOk - 1}, stamped {stamps[s.FramesOk - 1]:R} s, taken by {seconds:R} s after the open");
                // one status in which samples flowed, the world stepped and the host read: the
                // watchdog let the output through (whether it does at any given moment, the
                // scheduler decides)
                if (!sawFlowing && s.Watchdog == FrustaWatchdogReason.None && s.FramesOk >= 2)
                {
                    flowing = s;
                    sawFlowing = true;
                }
                tookSeconds = seconds;
                return sawFlowing && s.FramesOk >= enough;
            }, $"{enough} frames and a status with the watchdog clear");
            FrustaDeviceStatus last = glove.PolledStatus;
            output.WriteLine($"speed=1: {last.FramesOk} samples in {tookSeconds * 1000:0.#} ms; first clear watchdog at " +
                             $"frame {flowing.FramesOk}: {Describe(flowing)}");

            // the rate comes from the recording's own stamps (exactly 10 ms apart), not from
            // when the samples arrived
            Assert.Equal(100.0, last.InputRateHz);
            Assert.Equal(0L, last.FramesCorrupt);
            Assert.Equal(FrustaDeviceState.Connected, flowing.State);
            Assert.Equal(100.0, flowing.InputRateHz);
            // the watchdog was clear in that status because its sample was fresh by the same clock
            Assert.InRange(flowing.LastSampleAgeS, 0.0, FrustaDeviceDef.Default.WatchdogS);
            // the world's 1 kHz, cut to the 100 commands per second the recorded glove announced
            Assert.Equal(100.0, flowing.OutputRateHz);
            Assert.True(flowing.CommandsSent > 0);
        }

        [Fact]
        public void AFrameOfPollingAllocatesNothing()
        {
            using World world = WorldWithHand(run: true);
            using Device glove = world.CreateDevice(ReplayAsFastAsRead, world.Hands[0]);
            int changes = 0;
            glove.StateChanged += (_, e) => ++changes;
            glove.WatchdogChanged += (_, e) => ++changes;
            // the replay over, the state stays put: no event, so nothing to allocate for
            PollUntil(glove, world, () => glove.State == FrustaDeviceState.Disconnected, "the replay to end");
            var status = new FrustaDeviceStatus();
            var palm = new FrustaPose(new Vector3d(0, 0, 0.1), Quaterniond.Identity);
            void Frame()
            {
                Assert.True(glove.Poll());
                glove.GetStatus(ref status);
                glove.SetPalmPose(palm);
                Assert.True(glove.IsValid);
            }
            Frame();
            int seen = changes;
            AllocatesNothing(Frame);
            Assert.Equal(seen, changes);
        }

        [Fact]
        public void EnumerationListsOnlyUrisTheLibraryOpens()
        {
            FrustaDeviceInfo[] found = Device.Enumerate();
            foreach (FrustaDeviceInfo d in found)
            {
                string uri = d.Uri;
                FrustaDeviceKind expected = uri.StartsWith("serial:", StringComparison.Ordinal) ? FrustaDeviceKind.Serial
                    : uri.StartsWith("hid:", StringComparison.Ordinal) ? FrustaDeviceKind.Hid
                    : uri.StartsWith("usb:", StringComparison.Ordinal) ? FrustaDeviceKind.Usb
                    : (FrustaDeviceKind)0;
                Assert.True(expected != 0, $"\"{uri}\" starts with none of serial:, hid:, usb:");
                Assert.Equal(expected, d.Kind);
                Assert.True(d.VendorId >= -1 && d.VendorId <= 0xffff && d.ProductId >= -1 && d.ProductId <= 0xffff, uri);
            }
            Assert.True(Device.Enumerate(Span<FrustaDeviceInfo>.Empty) >= 0);
            Span<FrustaDeviceInfo> one = stackalloc FrustaDeviceInfo[1];
            int count = Device.Enumerate(one);
            if (count > 0) Assert.False(string.IsNullOrEmpty(one[0].Uri));
        }
    }
}
