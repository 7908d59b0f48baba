// SPDX-License-Identifier: MIT
// Hands that come and go through the managed API: created and destroyed while the world
// runs on its own thread, their geometry read into caller arrays without allocating,
// and the objects a hand ignores because they were put inside it.
using System;
using Frusta.Binding;
using Xunit;
using static Frusta.Binding.Tests.Assertions;

namespace Frusta.Binding.Tests
{
    public class WorldHandsTests
    {
        static readonly double[] Open = new double[FrustaConstants.HandJointCount];

        // read until the latched step shows `hand` solved (or not there any more)
        static void ReadUntil(World world, Func<bool> done, string what)
        {
            var state = new FrustaWorldState();
            Waiting.Until(() => { world.Read(ref state); return done(); }, what, () => $"step {state.Step}");
        }

        static bool Shows(World world, FrustaHandId hand, bool solved)
        {
            var h = new FrustaWorldHand();
            try { world.GetHand(hand, ref h); }
            catch (FrustaException e) when (e.Result == FrustaResult.StaleId) { return false; }
            return !solved || h.Solved;
        }

        [Fact]
        public void HandsComeAndGoWhileTheWorldRunsOnItsOwnThread()
        {
            FrustaWorldDef def = FrustaWorldDef.Default;
            def.MaxHands = 2;
            using var world = new World(def);
            Assert.Equal(2, world.MaxHands);
            world.Start();
            FrustaHandId first = world.CreateHand(FrustaHandDef.Default);
            world.SetHaptic(first, FrustaPose.Identity, Open);
            ReadUntil(world, () => Shows(world, first, true), "the first hand solved");
            FrustaHandId second = world.CreateHand(FrustaHandDef.Default);
            Assert.Equal(new[] { first, second }, world.Hands);
            var h = new FrustaWorldHand();
            Assert.False(world.TryGetHand(second, ref h), "the latched step is older than the hand");
            Assert.True(world.TryGetHand(first, ref h) && h.Solved);
            Fails(FrustaResult.Capacity, () => world.CreateHand(FrustaHandDef.Default), "max_hands");

            world.DestroyHand(first);
            Assert.Equal(new[] { second }, world.Hands);
            Assert.Equal(1, world.HandCount);
            Assert.Equal(0, Native.frusta_hand_is_valid(first));
            Fails(FrustaResult.StaleId, () => world.SetHaptic(first, FrustaPose.Identity, Open), "no hand of this world");
            Fails(FrustaResult.StaleId, () => world.DestroyHand(first), "no hand of this world");
            // its slot takes a new hand once a read latched a step without it
            ReadUntil(world, () => !Shows(world, first, false), "the first hand gone from the latched step");
            FrustaHandId third = world.CreateHand(FrustaHandDef.Default);
            Assert.Equal(first.Index1, third.Index1);
            Assert.NotEqual(first.Generation, third.Generation);
            world.SetHaptic(third, FrustaPose.Identity, Open);
            world.SetHaptic(second, FrustaPose.Identity, Open);
            ReadUntil(world, () => Shows(world, third, true) && Shows(world, second, true), "both hands solved");

            // a snapshot holds the hands its step shows, with their ids
            WorldSnapshot snapshot = world.CreateSnapshot();
            world.ReadSnapshot(snapshot);
            Assert.Equal(2, snapshot.HandCount);
            Assert.Equal(second, snapshot.GetHandId(0));
            Assert.Equal(third, snapshot.GetHandId(1));
            world.Stop();

            // another world's hand is refused here
            using var other = new World();
            FrustaHandId foreign = other.CreateHand(FrustaHandDef.Default);
            Fails(FrustaResult.StaleId, () => world.DestroyHand(foreign), "another world");
            Assert.Equal(1, Native.frusta_hand_is_valid(foreign));
        }

        [Fact]
        public void AHandAGloveDrivesIsDestroyedOnlyOnceTheGloveIsDisposed()
        {
            using var world = new World();
            FrustaHandId hand = world.CreateHand(FrustaHandDef.Default);
            Device glove = world.CreateDevice($"replay:{TestEnv.Recording}?speed=max", hand);
            Fails(FrustaResult.WrongState, () => world.DestroyHand(hand), "glove", "frusta_destroy_device");
            Assert.Equal(new[] { hand }, world.Hands);
            glove.Dispose();
            world.DestroyHand(hand);
            Assert.Empty(world.Hands);
        }

        [Fact]
        public void AHandsGeometryIsReadIntoCallerArraysWithoutAllocating()
        {
            using var world = new World();
            FrustaHandId hand = world.CreateHand(FrustaHandDef.Default);
            var palm = new FrustaPose(new Vector3d(0.1, -0.2, 0.3), Quaterniond.Identity);
            var angles = new double[FrustaConstants.HandJointCount];
            for (int j = 0; j < angles.Length; ++j) angles[j] = j % 4 == 0 ? 0.05 : 0.4;
            world.SetHaptic(hand, palm, angles);
            world.Step(2);
            var state = new FrustaWorldState();
            world.Read(ref state);
            var h = new FrustaWorldHand();
            world.GetHand(hand, ref h);

            var segments = new FrustaSegment[FrustaConstants.HandSegmentCount];
            int palmCount = world.GetHandPalmSpheres(hand, FrustaHandKind.Graphic, Span<FrustaSphere>.Empty);
            var spheres = new FrustaSphere[palmCount];
            var hapticSegments = new FrustaSegment[FrustaConstants.HandSegmentCount];
            int n = 0;
            AllocatesNothing(() =>
            {
                n = world.GetHandSegments(hand, FrustaHandKind.Graphic, segments);
                world.GetHandSegments(hand, FrustaHandKind.Haptic, hapticSegments);
                world.GetHandPalmSpheres(hand, FrustaHandKind.Graphic, spheres);
            });
            Assert.Equal(FrustaConstants.HandSegmentCount, n);

            // the geometry of a standalone hand in the latched state
            using var alone = new Hand();
            alone.SetPalmPose(h.GraphicPalm);
            Span<double> graphic = stackalloc double[FrustaConstants.HandJointCount];
            h.CopyGraphicAngles(graphic);
            alone.SetJointAngles(graphic);
            var want = new FrustaSegment[FrustaConstants.HandSegmentCount];
            alone.GetSegments(want);
            for (int s = 0; s < n; ++s)
            {
                Near(want[s].Proximal, segments[s].Proximal, 1e-12, $"segment {s} proximal");
                Near(want[s].Distal, segments[s].Distal, 1e-12, $"segment {s} distal");
                Assert.Equal(want[s].DistalRadius, segments[s].DistalRadius);
            }
            var wantSpheres = new FrustaSphere[palmCount];
            Assert.Equal(palmCount, alone.GetPalmSpheres(wantSpheres));
            for (int s = 0; s < palmCount; ++s) Near(wantSpheres[s].Center, spheres[s].Center, 1e-12, $"palm sphere {s}");
            // nothing touched: the haptic hand is where the graphic one is
            for (int s = 0; s < n; ++s) Near(segments[s].Distal, hapticSegments[s].Distal, 1e-12, $"haptic segment {s}");

            // a short buffer gets what fits and the count of all
            Assert.Equal(FrustaConstants.HandSegmentCount, world.GetHandSegments(hand, FrustaHandKind.Graphic, segments.AsSpan(0, 3)));
            Fails(FrustaResult.OutOfRange, () => world.GetHandSegments(hand, (FrustaHandKind)2, segments), "which", "2");
            FrustaHandId late = world.CreateHand(FrustaHandDef.Default);
            Fails(FrustaResult.StaleId, () => world.GetHandSegments(late, FrustaHandKind.Graphic, segments), "latched step");
            world.Step();
            world.Read(ref state);
            Fails(FrustaResult.WrongState, () => world.GetHandSegments(late, FrustaHandKind.Graphic, segments), "solved");
        }

        [Fact]
        public void AnObjectPutInsideAHandIsIgnoredByItUntilTheyPart()
        {
            using var tree = Box.Bake();
            using var world = new World();
            FrustaHandId hand = world.CreateHand(FrustaHandDef.Default);
            world.SetHaptic(hand, FrustaPose.Identity, Open);
            world.Step();
            // a box around the open index fingertip
            using var standalone = new Hand();
            var segments = new FrustaSegment[FrustaConstants.HandSegmentCount];
            standalone.GetSegments(segments);
            FrustaObjectDef inside = FrustaObjectDef.Default;
            inside.Pose.Position = segments[(int)FrustaFinger.Index * 3 + 2].Distal;
            FrustaObjectId box = world.CreateObject(tree, inside);
            world.Step(3);
            var state = new FrustaWorldState();
            world.Read(ref state);
            Assert.True(world.IsObjectIgnoredBy(box, hand));
            var o = new FrustaObjectState();
            world.GetObject(box, ref o);
            Assert.Equal(1, o.IgnoringHands);
            var h = new FrustaWorldHand();
            world.GetHand(hand, ref h);
            Assert.Equal((1, 0), (h.IgnoredObjects, h.ContactCount));

            // the hand backs out: the box is solid to it again
            for (int t = 0; t < 20; ++t)
            {
                world.SetHaptic(hand, new FrustaPose(new Vector3d(-0.2, 0, 0), Quaterniond.Identity), Open);
                world.Step();
            }
            world.Read(ref state);
            Assert.False(world.IsObjectIgnoredBy(box, hand));
            world.GetObject(box, ref o);
            Assert.Equal(0, o.IgnoringHands);
            Fails(FrustaResult.NullId, () => world.IsObjectIgnoredBy(FrustaObjectId.Null, hand), "object");
        }
    }
}
