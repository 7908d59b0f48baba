// SPDX-License-Identifier: MIT
// The Grasp Scene sample (unity-package/Samples~/GraspScene) run as its component runs it, but
// stepped one millisecond at a time by the test: its own copies of the sample trees and of the
// glove recording, loaded through the binding, the hand picking the marble off its stand,
// carrying it and letting it fall onto the table, where it rests.
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
            double top = double.NegativeInfinity, liftedAt = double.NaN, restedAt = double.NaN, deepest = 0;
            int held = 0;
            Vector3d highest = start, end = start;
            int steps = (int)Math.Ceiling((recording.Duration + 0.5) * world.RateHz);
            for (int i = 0; i < steps; ++i)
            {
                scenario.Step();
                world.GetObject(marble, ref state);
                if (state.Held) ++held;
                Vector3d p = GraspScenario.ToRecording(state.Pose.Position);
                if (p.Z > top) { top = p.Z; highest = p; }
                if (double.IsNaN(liftedAt) && !scenario.IsResting(GraspScenario.Marble)) liftedAt = scenario.Time;
                if (!double.IsNaN(liftedAt) && double.IsNaN(restedAt) && scenario.IsResting(GraspScenario.Marble)) restedAt = scenario.Time;
                end = p;
                int n = world.GetContacts(hand, contacts);
                for (int c = 0; c < Math.Min(n, contacts.Length); ++c) deepest = Math.Min(deepest, contacts[c].Distance);
            }
            double carried = Math.Sqrt(Math.Pow(highest.X - start.X, 2) + Math.Pow(highest.Y - start.Y, 2));
            double moved = Math.Sqrt(Math.Pow(end.X - start.X, 2) + Math.Pow(end.Y - start.Y, 2));
            output.WriteLine($"lifted at {liftedAt:F3} s, rose {1e2 * (top - start.Z):F1} cm, carried {1e2 * carried:F1} cm along, " +
                             $"at rest at {restedAt:F3} s, {1e2 * moved:F1} cm from the stand, bottom {1e3 * (end.Z - 0.0087 - GraspScenario.TableTop):F3} mm " +
                             $"above the table; deepest contact {1e3 * deepest:F4} mm; held {held} steps");

            // picked up once pinched (the recording lifts from 2.2 s) and carried 15 cm up, 11 cm along
            Assert.InRange(liftedAt, 1.8, 2.6);
            Assert.True(top - start.Z >= 0.10, $"the marble rose {1e2 * (top - start.Z):F1} cm, not 10");
            Assert.True(carried >= 0.08, $"the marble was carried {1e2 * carried:F1} cm along, not 8");
            // in the pinch's grasp (FrustaObjectState.Held) for most of the carry (2.2 to 4.2 s)
            Assert.True(held >= 1500, $"held for {held} steps");
            // let go (4.2 s), it fell onto the table and rests there, still, far from its stand
            Assert.InRange(restedAt, 4.2, 5.0);
            Assert.True(scenario.IsResting(GraspScenario.Marble));
            Assert.False(state.Dynamic);
            Assert.Equal(GraspScenario.TableTop, end.Z - 0.0087, 9);
            Assert.Equal(0.0, state.LinearVelocity.Length, 12);
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
            double second = recording.Duration + GraspScenario.LoopPause;
            scenario.AdvanceTo(second + 0.01, int.MaxValue);
            var state = new FrustaObjectState();
            world.GetObject(scenario.GetObjectId(GraspScenario.Marble), ref state);
            Vector3d back = GraspScenario.ToRecording(state.Pose.Position);
            Vector3d start = GraspScenario.Objects[GraspScenario.Marble].Pose.Position;
            Assert.True((back - start).Length < 1e-9, $"the marble is at {back}, not back at {start}");
            Assert.True(scenario.IsResting(GraspScenario.Marble));
            // the second pass lifts it as the first did
            double top = double.NegativeInfinity;
            while (scenario.Time < second + 3.6)
            {
                scenario.Step();
                world.GetObject(scenario.GetObjectId(GraspScenario.Marble), ref state);
                top = Math.Max(top, GraspScenario.ToRecording(state.Pose.Position).Z);
            }
            Assert.True(top - start.Z >= 0.10, $"the second pass lifted it {1e2 * (top - start.Z):F1} cm");
        }
    }
}
