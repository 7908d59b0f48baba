// SPDX-License-Identifier: MIT
// The world end to end through the managed API, as tests/abi/world_c_test.c does it
// from C: a hand pressed onto a baked sample box, a falling box, the own thread.
using System;
using System.Linq;
using System.Threading;
using Frusta.Binding;
using Xunit;
using static Frusta.Binding.Tests.Assertions;

namespace Frusta.Binding.Tests
{
    public class WorldTests
    {
        const double Stiffness = 400.0; // N/m, the default object def's
        const double BoxHalfHeight = 0.02; // the sample box is 0.10 x 0.06 x 0.04 m

        /// <summary>The open default hand's index distal segment at the identity pose.</summary>
        static FrustaSegment IndexTip()
        {
            using var hand = new Hand();
            var segments = new FrustaSegment[FrustaConstants.HandSegmentCount];
            Assert.Equal(15, hand.GetSegments(segments));
            return segments[(int)FrustaFinger.Index * 3 + 2];
        }

        /// <summary>The sample box under the index fingertip, its top face touching the tip from
        /// below, its corner 5 mm behind and 5 mm beside the tip's centre (towards the middle
        /// finger), so that it lies under the index fingertip only.</summary>
        static FrustaObjectDef BoxUnderTip(FrustaSegment tip)
        {
            FrustaObjectDef def = FrustaObjectDef.Default;
            def.Pose.Position = new Vector3d(tip.Distal.X + 0.05 - 0.005, tip.Distal.Y + 0.03 - 0.005,
                                             tip.Distal.Z - (tip.DistalRadius + BoxHalfHeight));
            return def;
        }

        static FrustaPose Lowered(double depth) => new FrustaPose(new Vector3d(0, 0, -depth), Quaterniond.Identity);

        [Fact]
        public void AHandPressedOntoABakedSampleBoxStaysOutsideAndIsPushedBack()
        {
            FrustaSegment tip = IndexTip();
            Assert.InRange(tip.Distal.X, 0.15, 0.2);
            using var box = SphereTree.Load(TestEnv.SampleObject("box"));
            FrustaSphereTreeInfo info = box.Info;
            Near(new Vector3d(0.05, 0.03, 0.02), info.BoundsMax, 0.0015, "box bounds max");
            Assert.True(info.TargetMet);

            using var world = new World();
            FrustaHandId hand = world.CreateHand(FrustaHandDef.Default);
            Assert.Equal(1, hand.Index1);
            Assert.NotEqual(0, hand.World0);
            Assert.Equal(hand, world.Hands[0]);
            Assert.Equal(1, Native.frusta_hand_is_valid(hand));
            FrustaObjectDef boxDef = BoxUnderTip(tip);
            FrustaObjectId boxId = world.CreateObject(box, boxDef);
            Assert.False(boxId.IsNull);

            // the haptic hand 3 mm below the surface, 50 steps
            const double depth = 0.003;
            FrustaPose palm = Lowered(depth);
            var angles = new double[FrustaConstants.HandJointCount];
            for (int t = 0; t < 50; ++t)
            {
                world.SetHaptic(hand, palm, angles);
                world.Step();
            }
            var state = new FrustaWorldState();
            world.Read(ref state);
            Assert.Equal(50UL, state.Step);
            Near(0.05, state.Time, 1e-12, "time");
            Assert.Equal((1, 1, 0L), (state.HandCount, state.ObjectCount, state.RejectedInputs));
            Assert.True(state.StepUs > 0 && state.StepUsP50 > 0 && state.StepUsP99 >= state.StepUsP50 && state.StepUsMax >= state.StepUsP99);
            Assert.Equal(0.0, state.AchievedRateHz);
            Assert.False(state.Realtime, "a host-stepped world has no thread of its own");

            // the graphic hand stays above the haptic one, which sank 3 mm (that it stays
            // outside the leaves, the contacts' distances tell below)
            var h = new FrustaWorldHand();
            world.GetHand(hand, ref h);
            Assert.True(h.Solved);
            Assert.True(h.ContactCount > 0 && h.Pressing > 0, $"{h.ContactCount} contacts, {h.Pressing} pressing");
            Assert.Equal(-depth, h.HapticPalm.Position.Z);
            Assert.True(h.GraphicPalm.Position.Z > h.HapticPalm.Position.Z,
                $"graphic palm z {h.GraphicPalm.Position.Z}, haptic {-depth}");
            Span<double> graphic = stackalloc double[20];
            h.CopyGraphicAngles(graphic);
            Assert.All(graphic.ToArray(), a => Assert.True(double.IsFinite(a)));
            Assert.Equal(0.0, h.GetHapticAngle(7));

            // the index fingertip is pushed up by about k * depth (eq. 12), nothing else pulls
            Vector3d tipForce = h.GetFingertipForce(FrustaFinger.Index);
            Assert.True(tipForce.Z > 0.5 * Stiffness * depth && tipForce.Z < 1.5 * Stiffness * depth,
                $"index fingertip force {tipForce} N, expected about {Stiffness * depth} N up");
            Assert.True(h.GetFingerResistance(FrustaFinger.Index) >= tipForce.Z);
            foreach (FrustaFinger f in Enum.GetValues(typeof(FrustaFinger)))
                if (f != FrustaFinger.Index) Assert.True(h.GetFingerResistance(f) == 0.0, $"{f} feels {h.GetFingerResistance(f)} N");

            // contacts: count query, then the copy into a reused buffer
            Assert.Equal(h.ContactCount, world.GetContactCount(hand));
            var contacts = new FrustaWorldContact[world.MaxContactsPerHand];
            int n = world.GetContacts(hand, contacts);
            Assert.Equal(h.ContactCount, n);
            var sum = Vector3d.Zero;
            var torque = Vector3d.Zero;
            foreach (var c in contacts.Take(n))
            {
                Assert.Equal(boxId, c.Object);
                Assert.False(c.IsPalm);
                Assert.True(c.Distance >= -1e-6, $"graphic hand inside the box by {-c.Distance} m");
                Near(1.0, c.Normal.Length, 1e-9, "unit normal");
                Assert.True(Vector3d.Dot(c.NormalForce, c.Normal) >= 0, "the normal force never pulls");
                Assert.True(c.Leaf >= -1);
                Vector3d total = c.NormalForce + c.Friction;
                sum += total;
                torque += Vector3d.Cross(c.GraphicPoint - boxDef.Pose.Position, total);
            }
            // each patch (one body on the box) pushes once, k times its contacts' weighted
            // mean gap P_g - P_h along their mean normal, shared by weight: its contacts push
            // the same way, and in all by no more than k times their largest gap and no less
            // than k times their smallest gap along that way (3 mm deep, every contact presses
            // fully)
            foreach (var patch in contacts.Take(n).Where(c => c.NormalForce.Length > 0).GroupBy(c => c.Body))
            {
                Vector3d push = patch.Aggregate(Vector3d.Zero, (a, c) => a + c.NormalForce);
                Vector3d way = push * (1.0 / push.Length);
                foreach (var c in patch)
                    Near(0.0, Vector3d.Cross(c.NormalForce, way).Length, 1e-9 * push.Length,
                         $"normal force of a contact on body {c.Body} along its patch's");
                double largest = patch.Max(c => (c.GraphicPoint - c.HapticPoint).Length);
                double smallest = patch.Min(c => Vector3d.Dot(c.GraphicPoint - c.HapticPoint, way));
                Assert.InRange(push.Length, Stiffness * smallest * (1 - 1e-9), Stiffness * largest * (1 + 1e-9));
            }
            Assert.Contains(contacts.Take(n), c => c.Body == (int)FrustaFinger.Index * 3 + 2);
            Assert.True(sum.Z > 0, $"the contacts push the hand up: {sum}");

            // what the box receives is what the hand feels, reversed
            var o = new FrustaObjectState();
            world.GetObject(boxId, ref o);
            Near(-sum, o.ReactionForce, 1e-9 * sum.Length, "reaction force");
            Near(-torque, o.ReactionTorque, 1e-9 * torque.Length + 1e-15, "reaction torque");
            Assert.False(o.Dynamic);
            Near(boxDef.Pose.Position, o.Pose.Position, 1e-15, "the kinematic box stays");
            Assert.Equal(Vector3d.Zero, o.LinearVelocity);
        }

        [Fact]
        public void ABoxBakedInCSharpFallsUnderGravityExactly()
        {
            using var tree = Box.Bake();
            FrustaWorldDef def = FrustaWorldDef.Default;
            def.Gravity = new Vector3d(0, 0, -9.81);
            using var world = new World(def);
            FrustaObjectDef objectDef = FrustaObjectDef.Default;
            objectDef.Dynamic = true;
            FrustaObjectId falling = world.CreateObject(tree, objectDef);
            objectDef.Dynamic = false;
            objectDef.Pose.Position = new Vector3d(1, 0, 0);
            FrustaObjectId still = world.CreateObject(tree, objectDef);

            // semi-implicit Euler at 1 kHz; after n steps the box was integrated n - 1 times
            const int n = 100;
            const double dt = 0.001, g = 9.81;
            world.Step(n);
            var state = new FrustaWorldState();
            world.Read(ref state);
            var o = new FrustaObjectState();
            world.GetObject(falling, ref o);
            Assert.True(o.Dynamic);
            Near(-g * dt * (n - 1), o.LinearVelocity.Z, 1e-12, "vz");
            Near(-g * dt * dt * (n - 1) * n / 2.0, o.Pose.Position.Z, 1e-12, "z");
            world.GetObject(still, ref o);
            Assert.False(o.Dynamic);
            Assert.Equal(0.0, o.Pose.Position.Z);

            // hand it over and back
            world.SetObjectDynamic(still, true);
            world.SetObjectDynamic(falling, false);
            world.Step(10);
            world.Read(ref state);
            world.GetObject(still, ref o);
            Assert.True(o.Dynamic && o.Pose.Position.Z < 0 && o.LinearVelocity.Z < 0);
            world.GetObject(falling, ref o);
            Assert.False(o.Dynamic);
            Assert.Equal(0.0, o.LinearVelocity.Z);
        }

        [Fact]
        public void ObjectsMoveAtTheNextStepAndRemovedOnesTurnStale()
        {
            using var tree = Box.Bake();
            using var world = new World();
            FrustaObjectId id = world.CreateObject(tree, FrustaObjectDef.Default);
            world.Step();
            var state = new FrustaWorldState();
            world.Read(ref state);
            Assert.Equal(1, state.ObjectCount);

            var moved = new FrustaPose(new Vector3d(0.2, 0.5, -0.1), new Quaterniond(0, 0, 0.6, 0.8));
            world.SetObjectPose(id, moved);
            var o = new FrustaObjectState();
            world.GetObject(id, ref o);
            Assert.Equal(Vector3d.Zero, o.Pose.Position); // queued: the latched step has the old pose
            world.Step();
            world.Read(ref state);
            world.GetObject(id, ref o);
            Near(moved.Position, o.Pose.Position, 1e-15, "moved");
            SameRotation(moved.Rotation, o.Pose.Rotation, 1e-15, "turned");

            world.DestroyObject(id);
            Fails(FrustaResult.StaleId, () => world.SetObjectPose(id, moved), "names no object");
            world.Step();
            world.Read(ref state);
            Assert.Equal(0, state.ObjectCount);
            var before = o;
            Fails(FrustaResult.StaleId, () => world.GetObject(id, ref o), "latched step");
            Assert.Equal(before.Pose.Position, o.Pose.Position);
        }

        [Fact]
        public void TheOwnThreadStepsUntilStopped()
        {
            using var tree = Box.Bake();
            using var world = new World();
            FrustaHandId hand = world.CreateHand(FrustaHandDef.Default);
            FrustaSegment tip = IndexTip();
            FrustaObjectDef def = FrustaObjectDef.Default;
            def.Pose.Position = new Vector3d(tip.Distal.X + Box.Half - 0.005, tip.Distal.Y, tip.Distal.Z - (tip.DistalRadius + Box.Half));
            world.CreateObject(tree, def);
            var angles = new double[20];
            world.SetHaptic(hand, Lowered(0.002), angles);

            world.Stop(); // nothing to stop
            world.Start();
            Assert.True(world.IsRunning);
            Fails(FrustaResult.WrongState, () => world.Start(), "already running");
            Fails(FrustaResult.WrongState, () => world.Step(), "own thread");
            world.DestroyHand(world.CreateHand(FrustaHandDef.Default)); // hands come and go while it runs

            var state = new FrustaWorldState();
            Waiting.Until(() =>
            {
                world.SetHaptic(hand, Lowered(0.002), angles);
                world.Read(ref state);
                return state.Step >= 20;
            }, "20 steps on the world's own thread", () => $"step {state.Step}");
            world.Stop();
            Assert.False(world.IsRunning);
            world.Read(ref state);
            ulong stoppedAt = state.Step;
            Assert.True(stoppedAt >= 20, $"{stoppedAt} steps");
            Assert.True(state.AchievedRateHz > 0);
            var h = new FrustaWorldHand();
            world.GetHand(hand, ref h);
            Assert.True(h.Solved && h.Pressing > 0, $"{h.Pressing} pressing");
            // Stop joined the thread, so no step can follow it: the pause only gives a thread that
            // wrongly outlived Stop the time to show itself (however long it lasts, this can't flake)
            Thread.Sleep(10);
            world.Read(ref state);
            Assert.Equal(stoppedAt, state.Step);
            world.Step();
            world.Read(ref state);
            Assert.Equal(stoppedAt + 1, state.Step);

            // disposing a running world stops its thread first
            world.Start();
            world.Dispose();
            Assert.False(world.IsValid);
            Assert.False(world.IsRunning);
        }

        [Fact]
        public void DisposeIsSafeTwiceAndLaterCallsThrowObjectDisposed()
        {
            var world = new World();
            FrustaWorldId id = world.Id;
            Assert.True(world.IsValid);
            world.Dispose();
            world.Dispose();
            Assert.False(world.IsValid);
            Assert.Throws<ObjectDisposedException>(() => world.Step());
            var state = new FrustaWorldState();
            Assert.Throws<ObjectDisposedException>(() => world.Read(ref state));

            // the id itself is stale natively: a second World reusing the slot is not confused
            using var other = new World();
            Assert.True(other.IsValid);
            Assert.NotEqual(id, other.Id);

            var tree = Box.Bake();
            tree.Dispose();
            tree.Dispose();
            Assert.False(tree.IsValid);
            Assert.Throws<ObjectDisposedException>(() => tree.Info);
        }

        [Fact]
        public void TheWorldKeepsATreeItUsesAfterTheTreeIsDisposed()
        {
            using var world = new World();
            var tree = Box.Bake();
            FrustaObjectId id = world.CreateObject(tree, FrustaObjectDef.Default);
            tree.Dispose();
            world.Step(3);
            var state = new FrustaWorldState();
            world.Read(ref state);
            Assert.Equal(1, state.ObjectCount);
            var o = new FrustaObjectState();
            world.GetObject(id, ref o);
            Assert.Equal(Quaterniond.Identity, o.Pose.Rotation);
        }

        [Fact]
        public void ReadingAllocatesNothingPerFrame()
        {
            using var tree = SphereTree.Load(TestEnv.SampleObject("box"));
            using var world = new World();
            FrustaHandId hand = world.CreateHand(FrustaHandDef.Default);
            FrustaObjectId box = world.CreateObject(tree, BoxUnderTip(IndexTip()));
            var angles = new double[20];
            var palm = Lowered(0.003);
            var state = new FrustaWorldState();
            var h = new FrustaWorldHand();
            var o = new FrustaObjectState();
            var contacts = new FrustaWorldContact[world.MaxContactsPerHand];
            WorldSnapshot snapshot = world.CreateSnapshot();
            void Frame()
            {
                world.SetHaptic(hand, palm, angles);
                world.Step();
                world.Read(ref state);
                world.GetHand(hand, ref h);
                world.GetContacts(hand, contacts);
                world.GetObject(box, ref o);
                world.ReadSnapshot(snapshot);
            }
            AllocatesNothing(Frame);
            Assert.True(snapshot.GetContacts(0).Length > 0);
        }

        [Fact]
        public void TimedSamplesArePlayedInputDelayBehindTheStepInterpolatedAndThenHeld()
        {
            // a host that steps the world stamps its samples on the step clock: the step
            // after n steps is at (n + 1) ms; each plays its time minus the 10 ms delay
            using var world = new World();
            FrustaHandId hand = world.CreateHand(FrustaHandDef.Default);
            var angles = new double[FrustaConstants.HandJointCount];
            var h = new FrustaWorldHand();
            // every other millisecond a sample, the palm lowered 1 mm per ms
            for (int n = 1; n <= 60; ++n)
            {
                if (n % 2 == 0 && n <= 40) world.SetHaptic(hand, n * 1e-3, Lowered(n * 1e-3), angles);
                world.Step();
            }
            var state = new FrustaWorldState();
            world.Read(ref state);
            world.GetHand(hand, ref h);
            // step 60 plays 50 ms: 10 ms past the newest sample (40 ms), extrapolated at its velocity
            Assert.True(h.InputLate);
            Near(-0.050, h.HapticPalm.Position.Z, 1e-9, "extrapolated palm");
            // an odd step between two samples: interpolated
            using var second = new World();
            FrustaHandId other = second.CreateHand(FrustaHandDef.Default);
            for (int n = 1; n <= 25; ++n)
            {
                if (n % 2 == 0) second.SetHaptic(other, n * 1e-3, Lowered(n * 1e-3), angles);
                second.Step();
            }
            second.Read(ref state);
            second.GetHand(other, ref h);
            Assert.False(h.InputLate);
            Near(-0.015, h.HapticPalm.Position.Z, 1e-12, "interpolated palm (15 ms)");
            // out of order: refused, naming the time
            var e = Assert.Throws<FrustaException>(() => second.SetHaptic(other, 0.001, Lowered(0), angles));
            Assert.Equal(FrustaResult.OutOfRange, e.Result);
            Assert.Contains("time", e.Message);
            double now = World.Now;
            Assert.True(now > 0 && World.Now >= now);
        }
    }
}
