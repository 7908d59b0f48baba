// SPDX-License-Identifier: MIT
// The Grasp Scene sample (unity-package/Samples~/GraspScene) run as its component runs it, but
// stepped one millisecond at a time by the test: its own copies of the sample trees and of the
// glove recording, loaded through the binding, the hand picking the marble off its stand,
// carrying it and letting it fall onto the table, where it comes to rest: every part of it the
// world's (the marble is dynamic throughout; the scenario only feeds the recording).
using System;
using System.IO;
using Frusta.Binding;
using Frusta.Samples;
using Xunit;
using Xunit.Abstractions;

namespace Frusta.Binding.Tests
{
    public class GraspSceneTests
    {
        readonly ITestOutputHelper output;

        public GraspSceneTests(ITestOutputHelper output) => this.output = output;

        static string Resources => Path.Combine(TestEnv.Package, "Samples~", "GraspScene", "Resources", "FrustaGraspScene");

        static byte[] Tree(string name) => File.ReadAllBytes(Path.Combine(Resources, name + SphereTree.FileExtension));

        static GloveRecording Recording() =>
            GloveRecording.Parse(File.ReadAllBytes(Path.Combine(Resources, "demo_glove.bytes")), "demo_glove.bytes");

        // the world's sleep speed (runtime/scene_objects.h kSleepSpeed): under it an object is still
        const double Still = 1e-3;
        // the marble's tree rests on the table's a contact depth (about 0.3 mm) into it, and the table's
        // tree stands out of its box by up to 1 mm and falls short by up to 1.4 mm (its bake): where the
        // marble's bottom may rest off the nominal table top (the native test saw -1.06 mm)
        const double RestAbove = 1.0e-3, RestBelow = 2.0e-3;

        static double Radius => GraspScenario.Objects[GraspScenario.Marble].Bottom;

        [Fact]
        public void TheHandPicksTheMarbleUpCarriesItAndItComesToRestOnTheTable()
        {
            GloveRecording recording = Recording();
            using var world = new World(GraspScenario.WorldDef());
            FrustaHandId hand = world.CreateHand(GraspScenario.HandDef());
            var scenario = new GraspScenario(world, hand, Tree, recording);
            FrustaObjectId marble = scenario.GetObjectId(GraspScenario.Marble);
            Vector3d start = GraspScenario.Objects[GraspScenario.Marble].Pose.Position;
            var state = new FrustaObjectState();
            var contacts = new FrustaWorldContact[world.MaxContactsPerHand];
            double low = start.Z, top = double.NegativeInfinity, deepest = 0;
            double standLow = double.PositiveInfinity, heldAt = double.NaN, liftedAt = double.NaN, releasedAt = double.NaN, restedAt = 0;
            int held = 0, droppedInCarry = 0, releases = 0;
            bool wasHeld = false;
            Vector3d highest = start, released = start, end = start;
            int steps = (int)Math.Ceiling((recording.Duration + 0.5) * world.RateHz);
            for (int i = 0; i < steps; ++i)
            {
                scenario.Step();
                world.GetObject(marble, ref state);
                Vector3d p = GraspScenario.ToRecording(state.Pose.Position);
                if (state.Held)
                {
                    ++held;
                    if (double.IsNaN(heldAt)) heldAt = scenario.Time;
                }
                else if (wasHeld)
                {
                    ++releases;
                    if (double.IsNaN(releasedAt)) { releasedAt = scenario.Time; released = p; }
                }
                wasHeld = state.Held;
                // lifted: 1 mm above the lowest it sat on its stand (where its tree rests on the stand's)
                if (double.IsNaN(liftedAt))
                {
                    low = Math.Min(low, p.Z);
                    if (scenario.Time < 0.8) standLow = Math.Min(standLow, p.Z);  // before the hand comes
                    if (p.Z > low + 1e-3) liftedAt = scenario.Time;
                }
                if (!double.IsNaN(liftedAt) && double.IsNaN(releasedAt) && !state.Held) ++droppedInCarry;
                if (p.Z > top) { top = p.Z; highest = p; }
                if (state.LinearVelocity.Length >= Still) restedAt = scenario.Time + 1.0 / world.RateHz;
                end = p;
                int n = world.GetContacts(hand, contacts);
                for (int c = 0; c < Math.Min(n, contacts.Length); ++c) deepest = Math.Min(deepest, contacts[c].Distance);
            }
            double carried = Math.Sqrt(Math.Pow(highest.X - start.X, 2) + Math.Pow(highest.Y - start.Y, 2));
            double moved = Math.Sqrt(Math.Pow(end.X - start.X, 2) + Math.Pow(end.Y - start.Y, 2));
            double restOff = end.Z - Radius - GraspScenario.TableTop;
            output.WriteLine($"on its stand {1e3 * (standLow - start.Z):F3} mm off nominal; held from {heldAt:F3} s; " +
                             $"lifted at {liftedAt:F3} s, rose {1e2 * (top - start.Z):F1} cm, carried {1e2 * carried:F1} cm along; " +
                             $"let go at {releasedAt:F3} s, {1e2 * (released.Z - start.Z):F1} cm up; held {held} steps; " +
                             $"at rest from {restedAt:F3} s, {1e2 * moved:F1} cm from the stand, bottom {1e3 * restOff:F3} mm " +
                             $"off the table top, speed {state.LinearVelocity.Length:G3} m/s; deepest contact {1e3 * deepest:F4} mm");

            // on its stand until the hand comes (its tree a fraction of a millimetre into the stand's)
            Assert.InRange(standLow - start.Z, -RestBelow, RestAbove);
            // picked up once pinched (the recording lifts from 2.2 s) and carried 15 cm up, 11 cm along
            Assert.InRange(liftedAt, 1.8, 2.6);
            Assert.True(top - start.Z >= 0.10, $"the marble rose {1e2 * (top - start.Z):F1} cm, not 10");
            Assert.True(carried >= 0.08, $"the marble was carried {1e2 * carried:F1} cm along, not 8");
            // in the pinch's grasp (FrustaObjectState.Held) from before the lift to the top, let go once
            Assert.True(heldAt < liftedAt, $"held at {heldAt:F3} s, lifted at {liftedAt:F3} s");
            Assert.Equal(0, droppedInCarry);
            Assert.Equal(1, releases);
            Assert.True(released.Z - start.Z >= 0.10, $"let go {1e2 * (released.Z - start.Z):F1} cm up, not at the top");
            // it fell onto the table and came to rest there on its own, far from its stand, and sleeps
            Assert.InRange(restedAt, releasedAt + 0.1, releasedAt + 2.5);
            Assert.True(state.Dynamic);
            Assert.False(state.Held);
            Assert.InRange(restOff, -RestBelow, RestAbove);
            Assert.True(state.LinearVelocity.Length < 1e-9, $"the marble moves at {state.LinearVelocity.Length} m/s");
            Assert.True(state.AngularVelocity.Length < 1e-9, $"the marble turns at {state.AngularVelocity.Length} rad/s");
            Assert.True(moved >= 0.08, $"the marble rests {1e2 * moved:F1} cm from its stand");
            // the graphic hand stayed outside every object (0.1 mm, as the demo's check)
            Assert.True(deepest >= -1e-4, $"the hand sank {1e3 * -deepest:F3} mm");
        }

        [Fact]
        public void LoopingPutsTheMarbleBackOnItsStandAndPicksItUpAgain()
        {
            GloveRecording recording = Recording();
            using var world = new World(GraspScenario.WorldDef());
            FrustaHandId hand = world.CreateHand(GraspScenario.HandDef());
            var scenario = new GraspScenario(world, hand, Tree, recording) { Loop = true };
            FrustaObjectId marble = scenario.GetObjectId(GraspScenario.Marble);
            Vector3d start = GraspScenario.Objects[GraspScenario.Marble].Pose.Position;
            double second = recording.Duration + GraspScenario.LoopPause;
            var state = new FrustaObjectState();
            // the first pass left it on the table, asleep
            scenario.AdvanceTo(second - 0.01, int.MaxValue);
            world.GetObject(marble, ref state);
            Vector3d before = GraspScenario.ToRecording(state.Pose.Position);
            Assert.InRange(before.Z - Radius - GraspScenario.TableTop, -RestBelow, RestAbove);
            // the host's pose command puts it back on its stand, where it rests again by itself
            scenario.AdvanceTo(second + 0.5, int.MaxValue);
            world.GetObject(marble, ref state);
            Vector3d back = GraspScenario.ToRecording(state.Pose.Position);
            output.WriteLine($"back at {1e3 * (back - start).Length:F3} mm from its start, {state.LinearVelocity.Length:G3} m/s");
            Assert.True((back - start).Length < RestBelow, $"the marble is at {back}, not back at {start}");
            Assert.True(state.LinearVelocity.Length < Still, $"the marble moves at {state.LinearVelocity.Length} m/s on its stand");
            Assert.False(state.Held);
            // the second pass lifts it as the first did
            double top = double.NegativeInfinity;
            while (scenario.Time < second + 3.6)
            {
                scenario.Step();
                world.GetObject(marble, ref state);
                top = Math.Max(top, GraspScenario.ToRecording(state.Pose.Position).Z);
            }
            Assert.True(top - start.Z >= 0.10, $"the second pass lifted it {1e2 * (top - start.Z):F1} cm");
        }
    }
}
