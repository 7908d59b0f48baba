// SPDX-License-Identifier: MIT
// Tracked joints to a hand through the binding: the round trip (a def's joints at a pose
// fit back to that pose), the fit going into a world, calibration, held values, errors
// as exceptions, and a frame of fitting that allocates nothing.
using System;
using Frusta.Binding;
using Xunit;
using static Frusta.Binding.Tests.Assertions;

namespace Frusta.Binding.Tests
{
    public class HandFitterTests
    {
        internal static double[] InteriorAngles(in FrustaHandDef def, Random random)
        {
            var angles = new double[FrustaConstants.HandJointCount];
            for (int j = 0; j < angles.Length; ++j)
            {
                var finger = (FrustaFinger)(j / 4);
                double lo = def.GetJointMin(finger, j % 4), hi = def.GetJointMax(finger, j % 4);
                angles[j] = lo + (0.1 + 0.8 * random.NextDouble()) * (hi - lo);
            }
            return angles;
        }

        /// <summary>The default hand of a side.</summary>
        internal static FrustaHandDef HandOf(FrustaHandSide side)
        {
            FrustaHandDef hand = FrustaHandDef.Default;
            hand.Side = side;
            return hand;
        }

        internal static FrustaPose RandomPose(Random random)
        {
            var q = new Quaterniond(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5,
                                    random.NextDouble() + 0.1);
            double n = Math.Sqrt(q.X * q.X + q.Y * q.Y + q.Z * q.Z + q.W * q.W);
            return new FrustaPose(new Vector3d(random.NextDouble(), -random.NextDouble(), 0.5),
                                  new Quaterniond(q.X / n, q.Y / n, q.Z / n, q.W / n));
        }

        static FrustaHandFitDef FitDef(FrustaJointLayout layout)
        {
            FrustaHandFitDef def = FrustaHandFitDef.Default;
            def.Layout = layout;
            return def;
        }

        [Theory]
        [InlineData(FrustaJointLayout.Xr, FrustaHandSide.Right)]
        [InlineData(FrustaJointLayout.Xr, FrustaHandSide.Left)]
        [InlineData(FrustaJointLayout.Keypoints, FrustaHandSide.Right)]
        [InlineData(FrustaJointLayout.Keypoints, FrustaHandSide.Left)]
        public void JointsOfAPoseFitBackToThatPose(FrustaJointLayout layout, FrustaHandSide side)
        {
            FrustaHandDef hand = HandOf(side);
            hand.SetSize(0.17, 0.078);
            using var fitter = new HandFitter(hand, FitDef(layout));
            Assert.Equal(layout, fitter.Layout);
            Assert.Equal(layout == FrustaJointLayout.Xr ? 26 : 21, fitter.JointCount);
            var random = new Random(19);
            var joints = new FrustaTrackedJoint[fitter.JointCount];
            var fit = new FrustaHandFit();
            for (int trial = 0; trial < 20; ++trial)
            {
                FrustaPose palm = RandomPose(random);
                double[] angles = InteriorAngles(hand, random);
                Assert.Equal(fitter.JointCount, hand.GetJoints(layout, palm, angles, joints));
                fitter.Fit(joints, ref fit);
                Assert.Equal((FrustaFitFlag)0, fit.PalmFlags);
                Near(palm.Position, fit.Palm.Position, 1e-9, "palm position");
                SameRotation(palm.Rotation, fit.Palm.Rotation, 1e-12, "palm rotation");
                for (int j = 0; j < angles.Length; ++j) Near(angles[j], fit.GetAngle(j), 1e-9, $"angle {j}");
                for (int f = 0; f < FrustaConstants.FingerCount; ++f)
                {
                    Assert.Equal((FrustaFitFlag)0, fit.GetFingerFlags((FrustaFinger)f));
                    Assert.InRange(fit.GetFingerResidual((FrustaFinger)f), 0.0, 1e-9);
                }
                Assert.InRange(fit.PalmResidual, 0.0, 1e-9);
            }
        }

        [Fact]
        public void AFitInTheTrackingFrameDrivesAWorldHand()
        {
            FrustaHandDef hand = FrustaHandDef.Default;
            using var world = new World();
            FrustaHandId id = world.CreateHand(hand);
            using var fitter = new HandFitter(hand, FrustaHandFitDef.Default);
            var random = new Random(20);
            FrustaPose palm = RandomPose(random);
            double[] angles = InteriorAngles(hand, random);
            var joints = new FrustaTrackedJoint[26];
            hand.GetJoints(FrustaJointLayout.Xr, palm, angles, joints);
            // the tracking space's origin stands 1.5 m up in the world
            var origin = new FrustaPose(new Vector3d(0, 0, 1.5), Quaterniond.Identity);
            var fit = new FrustaHandFit();
            fitter.Fit(joints, origin, ref fit);
            world.SetHaptic(id, fit);
            world.Step();
            var state = new FrustaWorldState();
            world.Read(ref state);
            var h = new FrustaWorldHand();
            world.GetHand(id, ref h);
            Near(palm.Position + new Vector3d(0, 0, 1.5), h.HapticPalm.Position, 1e-9, "haptic palm");
            for (int j = 0; j < angles.Length; ++j) Near(angles[j], h.GetHapticAngle(j), 1e-9, $"angle {j}");
        }

        [Fact]
        public void MissingJointsKeepTheLastGoodFitAndSaySo()
        {
            FrustaHandDef hand = FrustaHandDef.Default;
            using var fitter = new HandFitter(hand, FrustaHandFitDef.Default);
            var joints = new FrustaTrackedJoint[26];
            var fit = new FrustaHandFit();
            fitter.Fit(joints, ref fit); // nothing tracked yet
            Assert.Equal(FrustaFitFlag.Held | FrustaFitFlag.NoHistory, fit.PalmFlags);

            var random = new Random(21);
            FrustaPose palm = RandomPose(random);
            double[] angles = InteriorAngles(hand, random);
            hand.GetJoints(FrustaJointLayout.Xr, palm, angles, joints);
            fitter.Fit(joints, ref fit);
            // the middle finger's moving joints lost (XR joints 13..15: intermediate, distal, tip)
            var lost = (FrustaTrackedJoint[])joints.Clone();
            for (int i = 13; i <= 15; ++i) lost[i].Flags = 0;
            fitter.Fit(lost, ref fit);
            Assert.Equal(FrustaFitFlag.Held, fit.GetFingerFlags(FrustaFinger.Middle));
            Assert.Equal((FrustaFitFlag)0, fit.GetFingerFlags(FrustaFinger.Index));
            for (int j = 8; j < 12; ++j) Near(angles[j], fit.GetAngle(j), 1e-9, $"held angle {j}");
        }

        [Fact]
        public void CalibrationSizesTheDefFromJoints()
        {
            FrustaHandDef truth = FrustaHandDef.Default;
            truth.SetSize(0.21, 0.095);
            var random = new Random(22);
            const int frames = 12;
            var joints = new FrustaTrackedJoint[frames * 21];
            for (int f = 0; f < frames; ++f)
                truth.GetJoints(FrustaJointLayout.Keypoints, RandomPose(random), InteriorAngles(truth, random),
                                joints.AsSpan(f * 21, 21));
            FrustaHandDef def = FrustaHandDef.Default;
            def.Calibrate(joints, FrustaJointLayout.Keypoints);
            Near(0.21, def.HandLength, 1e-9, "hand length");
            Near(0.095, def.HandBreadth, 1e-9, "hand breadth");
            Near(truth.GetSegmentLength(FrustaFinger.Thumb, 0), def.GetSegmentLength(FrustaFinger.Thumb, 0), 1e-9);
            Assert.Throws<ArgumentException>(() => def.Calibrate(joints.AsSpan(0, 30), FrustaJointLayout.Keypoints));
        }

        [Fact]
        public void BadJointsAndDefsAreExceptionsNamingTheField()
        {
            FrustaHandDef hand = FrustaHandDef.Default;
            FrustaHandFitDef bad = FrustaHandFitDef.Default;
            bad.MaxIterations = 0;
            Fails(FrustaResult.OutOfRange, () => new HandFitter(hand, bad), "max_iterations");
            bad = FrustaHandFitDef.Default;
            bad.Layout = (FrustaJointLayout)7;
            Fails(FrustaResult.OutOfRange, () => new HandFitter(hand, bad), "layout");

            using var fitter = new HandFitter(hand, FrustaHandFitDef.Default);
            var joints = new FrustaTrackedJoint[26];
            hand.GetJoints(FrustaJointLayout.Xr, FrustaPose.Identity, new double[20], joints);
            var fit = new FrustaHandFit();
            Fails(FrustaResult.OutOfRange, () => fitter.Fit(joints.AsSpan(0, 21), ref fit), "count is 21, must be 26");
            joints[9].Position = new Vector3d(double.NaN, 0, 0);
            FrustaException e = Fails(FrustaResult.NotFinite, () => fitter.Fit(joints, ref fit), "joints[9].position");
            Assert.Equal("frusta_hand_fitter_fit", e.Call);
            joints[9].Flags = 0; // not valid: not read
            fitter.Fit(joints, ref fit);
            Assert.Throws<ArgumentOutOfRangeException>(() => fit.GetAngle(20));
            Assert.Throws<ArgumentOutOfRangeException>(() => HandFitter.JointCountOf((FrustaJointLayout)2));

            fitter.Dispose();
            fitter.Dispose();
            Assert.False(fitter.IsValid);
            Assert.Throws<ObjectDisposedException>(() => fitter.Fit(joints, ref fit));
        }

        [Fact]
        public void TimedFitsAreFilteredAndTimeMustIncrease()
        {
            FrustaHandDef hand = FrustaHandDef.Default;
            FrustaHandFitDef def = FrustaHandFitDef.Default;
            Assert.True(def.FilterMinCutoff > 0.0 && def.FilterBeta >= 0.0 && def.FilterDCutoff > 0.0);
            FrustaHandFitDef off = def;
            off.FilterMinCutoff = 0.0;
            using var filtered = new HandFitter(hand, def);
            using var plain = new HandFitter(hand, off);
            var at = new FrustaTrackedJoint[26];
            var moved = new FrustaTrackedJoint[26];
            hand.GetJoints(FrustaJointLayout.Xr, FrustaPose.Identity, new double[20], at);
            hand.GetJoints(FrustaJointLayout.Xr, new FrustaPose(new Vector3d(0.1, 0, 0), Quaterniond.Identity),
                           new double[20], moved);
            FrustaHandFit a = new FrustaHandFit(), b = new FrustaHandFit(), u = new FrustaHandFit();
            for (int i = 0; i < 10; ++i)
            {
                filtered.Fit(i / 90.0, at, ref a);
                plain.Fit(i / 90.0, at, ref b);
            }
            Near(0.0, a.Palm.Position.X, 1e-9);
            // a step of 10 cm: the filter follows it part way, off follows it at once
            filtered.Fit(10 / 90.0, moved, ref a);
            plain.Fit(10 / 90.0, moved, ref b);
            Assert.InRange(a.Palm.Position.X, 0.001, 0.099);
            Near(0.1, b.Palm.Position.X, 1e-9);
            // off: the untimed fit's to the bit
            plain.Fit(moved, ref u);
            Assert.Equal(b.Palm.Position.X, u.Palm.Position.X);

            FrustaException e = Fails(FrustaResult.OutOfRange, () => filtered.Fit(10 / 90.0, moved, ref a), "time");
            Assert.Equal("frusta_hand_fitter_fit_at", e.Call);
            Fails(FrustaResult.NotFinite, () => filtered.Fit(double.NaN, moved, ref a), "time");
            FrustaHandFitDef bad = def;
            bad.FilterDCutoff = 0.0;
            Fails(FrustaResult.OutOfRange, () => new HandFitter(hand, bad), "filter_d_cutoff");
            bad = def;
            bad.FilterBeta = -1.0;
            Fails(FrustaResult.OutOfRange, () => new HandFitter(hand, bad), "filter_beta");
        }

        [Fact]
        public void AFrameOfTimedFittingAllocatesNothing()
        {
            FrustaHandDef hand = FrustaHandDef.Default;
            using var fitter = new HandFitter(hand, FrustaHandFitDef.Default);
            var joints = new FrustaTrackedJoint[26];
            hand.GetJoints(FrustaJointLayout.Xr, FrustaPose.Identity, new double[20], joints);
            var fit = new FrustaHandFit();
            var origin = FrustaPose.Identity;
            double time = 0.0;
            AllocatesNothing(() =>
            {
                time += 1.0 / 90.0;
                fitter.Fit(time, joints, origin, ref fit);
            });
        }

        [Fact]
        public void AFrameOfFittingAllocatesNothing()
        {
            FrustaHandDef hand = FrustaHandDef.Default;
            using var world = new World();
            FrustaHandId id = world.CreateHand(hand);
            using var fitter = new HandFitter(hand, FrustaHandFitDef.Default);
            var joints = new FrustaTrackedJoint[26];
            hand.GetJoints(FrustaJointLayout.Xr, FrustaPose.Identity, new double[20], joints);
            var fit = new FrustaHandFit();
            var origin = FrustaPose.Identity;
            AllocatesNothing(() =>
            {
                fitter.Fit(joints, origin, ref fit);
                world.SetHaptic(id, fit);
            });
        }
    }
}
