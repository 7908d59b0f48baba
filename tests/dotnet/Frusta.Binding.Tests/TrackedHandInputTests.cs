// SPDX-License-Identifier: MIT
// XR Hands' joints into a world hand: the order and axes XR Hands reports in (Unity's frame),
// its tracking states, a round trip through the fit into a world with the tracking space
// moved, frames with no good history kept out, calibration on request, and a frame that
// allocates nothing.
using System;
using Frusta.Binding;
using Xunit;
using static Frusta.Binding.Tests.Assertions;
using static Frusta.Binding.Tests.HandFitterTests;

namespace Frusta.Binding.Tests
{
    public class TrackedHandInputTests
    {
        // the joints of a def at a pose, as XR Hands reports them: its order, Unity's frame
        static void AsXrHands(in FrustaHandDef hand, in FrustaPose palm, double[] angles, FrustaPose[] unityPoses)
        {
            var joints = new FrustaTrackedJoint[XrHandsJoints.Count];
            hand.GetJoints(FrustaJointLayout.Xr, palm, angles, joints);
            for (int i = 0; i < XrHandsJoints.Count; ++i)
                unityPoses[i] = XrHandsJoints.ToUnity(joints[XrHandsJoints.OtherOrder(i)]);
        }

        static void Feed(TrackedHandInput input, FrustaPose[] unityPoses, int trackingState = XrHandsJoints.TrackingPose)
        {
            for (int i = 0; i < XrHandsJoints.Count; ++i)
                input.SetXrHandsJoint(i, unityPoses[i].Position, unityPoses[i].Rotation, 0.0, trackingState, false);
        }

        [Fact]
        public void XrHandsOrderStartsWristThenPalm()
        {
            Assert.Equal(1, XrHandsJoints.OtherOrder(0));
            Assert.Equal(0, XrHandsJoints.OtherOrder(1));
            for (int i = 2; i < XrHandsJoints.Count; ++i) Assert.Equal(i, XrHandsJoints.OtherOrder(i));
            Assert.Throws<ArgumentOutOfRangeException>(() => XrHandsJoints.OtherOrder(26));
            Assert.Throws<ArgumentOutOfRangeException>(() => XrHandsJoints.OtherOrder(-1));
        }

        [Theory]
        [InlineData(FrustaHandSide.Right)]
        [InlineData(FrustaHandSide.Left)]
        public void InUnitysFrameABoneRunsAlongItsJointsForwardAndTheBackOfTheHandIsUp(FrustaHandSide side)
        {
            FrustaHandDef hand = HandOf(side);
            var random = new Random(31);
            FrustaPose palm = RandomPose(random);
            var poses = new FrustaPose[XrHandsJoints.Count];
            AsXrHands(hand, palm, InteriorAngles(hand, random), poses);
            // XR Hands' order: 0 wrist, 1 palm, 2..5 thumb metacarpal..tip, 6.. index metacarpal..tip
            for (int finger = 0; finger < FrustaConstants.FingerCount; ++finger)
            {
                int first = finger == 0 ? 2 : 6 + 5 * (finger - 1);
                int last = finger == 0 ? 5 : first + 4;
                for (int j = first; j < last; ++j)
                {
                    Vector3d bone = poses[j + 1].Position - poses[j].Position;
                    Near(bone * (1.0 / bone.Length), poses[j].Rotation.Rotate(new Vector3d(0, 0, 1)), 1e-9,
                         $"joint {j}'s forward along its bone");
                }
            }
            // the wrist: forward towards the fingers, up out of the back of the hand (Frusta's hand +z)
            Vector3d back = CoordinateConversion.VectorToUnity(palm.Rotation.Rotate(new Vector3d(0, 0, 1)));
            Vector3d fingers = CoordinateConversion.VectorToUnity(palm.Rotation.Rotate(new Vector3d(1, 0, 0)));
            Near(back, poses[0].Rotation.Rotate(new Vector3d(0, 1, 0)), 1e-9, "the wrist's up");
            Near(fingers, poses[0].Rotation.Rotate(new Vector3d(0, 0, 1)), 1e-9, "the wrist's forward");
        }

        [Theory]
        [InlineData(FrustaHandSide.Right)]
        [InlineData(FrustaHandSide.Left)]
        public void InUnitysFrameThePalmFramesXIsTheFingersZThePalmAndYTheThumbOnARightHand(FrustaHandSide side)
        {
            // what FrustaXRHandsInput's docs promise of a palm transform (Transform.SetFrustaPose)
            FrustaHandDef hand = HandOf(side);
            var random = new Random(36);
            FrustaPose palm = RandomPose(random);
            var joints = new FrustaTrackedJoint[XrHandsJoints.Count];
            hand.GetJoints(FrustaJointLayout.Xr, palm, new double[20], joints);
            Quaterniond unity = CoordinateConversion.PoseToUnity(palm).Rotation;
            Vector3d ToUnity(int xrJoint) => CoordinateConversion.VectorToUnity(joints[xrJoint].Position);
            Vector3d Unit(Vector3d v) => v * (1.0 / v.Length);
            Vector3d x = unity.Rotate(new Vector3d(1, 0, 0)), y = unity.Rotate(new Vector3d(0, 1, 0)),
                     z = unity.Rotate(new Vector3d(0, 0, 1));
            // OpenXR's order: 1 wrist, 3 thumb proximal, 7 index proximal, 12 middle proximal, 22 little proximal
            Vector3d wrist = ToUnity(1);
            Assert.True(Vector3d.Dot(Unit(ToUnity(12) - wrist), x) > 0.95, "+X towards the middle finger");
            double thumbward = Vector3d.Dot(ToUnity(3) - ToUnity(22), y);
            Assert.True(side == FrustaHandSide.Right ? thumbward > 0.03 : thumbward < -0.03,
                        $"+Y towards the thumb on a right hand, away on a left: {thumbward} m");
            // the palm side: the fingers' joints lie on it when they curl
            hand.GetJoints(FrustaJointLayout.Xr, palm, InteriorAngles(hand, random), joints);
            Assert.True(Vector3d.Dot(ToUnity(14) - ToUnity(12), z) > 0.0, "+Z out of the palm, where the fingers curl");
        }

        [Fact]
        public void TrackingStatesBecomeJointFlags()
        {
            const FrustaJointFlag valid = FrustaJointFlag.PositionValid | FrustaJointFlag.OrientationValid;
            const FrustaJointFlag tracked = FrustaJointFlag.PositionTracked | FrustaJointFlag.OrientationTracked;
            Assert.Equal((FrustaJointFlag)0, XrHandsJoints.Flags(0, false));
            Assert.Equal((FrustaJointFlag)0, XrHandsJoints.Flags(XrHandsJoints.TrackingRadius, false));
            Assert.Equal(valid | tracked, XrHandsJoints.Flags(XrHandsJoints.TrackingPose, false));
            Assert.Equal(valid, XrHandsJoints.Flags(XrHandsJoints.TrackingPose, true));
            Assert.Equal(valid | tracked,
                         XrHandsJoints.Flags(XrHandsJoints.TrackingPose | XrHandsJoints.TrackingHighFidelityPose, true));
            Assert.Equal((FrustaJointFlag)0,
                         XrHandsJoints.Flags(XrHandsJoints.TrackingPose | XrHandsJoints.TrackingWillNeverBeValid, false));
            // a radius is taken only where the state says it holds one
            Assert.Equal(0.0, XrHandsJoints.FromUnity(Vector3d.Zero, Quaterniond.Identity, 0.01, XrHandsJoints.TrackingPose, false).Radius);
            Assert.Equal(0.01, XrHandsJoints.FromUnity(Vector3d.Zero, Quaterniond.Identity, 0.01,
                                                       XrHandsJoints.TrackingPose | XrHandsJoints.TrackingRadius, false).Radius);
        }

        [Theory]
        [InlineData(FrustaHandSide.Right)]
        [InlineData(FrustaHandSide.Left)]
        public void XrHandsJointsInAMovedTrackingSpaceDriveTheWorldHandToTheirPose(FrustaHandSide side)
        {
            FrustaHandDef hand = HandOf(side);
            hand.SetSize(0.2, 0.09);
            using var world = new World();
            FrustaHandId id = world.CreateHand(hand);
            using var input = new TrackedHandInput(hand, FrustaHandFitDef.Default);
            var random = new Random(32);
            var poses = new FrustaPose[XrHandsJoints.Count];
            var h = new FrustaWorldHand();
            var state = new FrustaWorldState();
            for (int trial = 0; trial < 10; ++trial)
            {
                // the XR origin's tracking space somewhere in the Unity scene
                FrustaPose spaceInUnity = RandomPose(random);
                FrustaPose space = CoordinateConversion.PoseFromUnity(spaceInUnity);
                FrustaPose palm = RandomPose(random);
                double[] angles = InteriorAngles(hand, random);
                AsXrHands(hand, palm, angles, poses);
                Feed(input, poses);
                Assert.True(input.Drive(world, id, space));
                world.Step();
                world.Read(ref state);
                world.GetHand(id, ref h);
                Near(space.TransformPoint(palm.Position), h.HapticPalm.Position, 1e-9, "haptic palm position");
                SameRotation(space.Rotation * palm.Rotation, h.HapticPalm.Rotation, 1e-12, "haptic palm rotation");
                for (int j = 0; j < angles.Length; ++j) Near(angles[j], h.GetHapticAngle(j), 1e-9, $"angle {j}");
            }
        }

        [Fact]
        public void AFitWithNoGoodHistoryNeverReachesTheWorld()
        {
            FrustaHandDef hand = FrustaHandDef.Default;
            using var world = new World();
            FrustaHandId id = world.CreateHand(hand);
            using var input = new TrackedHandInput(hand, FrustaHandFitDef.Default);
            Assert.False(input.Drive(world, id, FrustaPose.Identity)); // nothing tracked yet
            Assert.Equal(FrustaFitFlag.Held | FrustaFitFlag.NoHistory, input.LastFit.PalmFlags);

            var poses = new FrustaPose[XrHandsJoints.Count];
            var random = new Random(33);
            AsXrHands(hand, RandomPose(random), InteriorAngles(hand, random), poses);
            // with tracked joints required, inferred ones (no high-fidelity bit) are missing
            FrustaHandFitDef strict = FrustaHandFitDef.Default;
            strict.RequireTracked = true;
            using var picky = new TrackedHandInput(hand, strict);
            for (int i = 0; i < XrHandsJoints.Count; ++i)
                picky.SetXrHandsJoint(i, poses[i].Position, poses[i].Rotation, 0, XrHandsJoints.TrackingPose, true);
            Assert.False(picky.Drive(world, id, FrustaPose.Identity));
            Feed(input, poses);
            Assert.True(input.Drive(world, id, FrustaPose.Identity));
            // tracking lost: the last good fit is held, and still sent
            input.ClearJoints();
            Assert.True(input.Drive(world, id, FrustaPose.Identity));
            Assert.Equal(FrustaFitFlag.Held, input.LastFit.PalmFlags);

            FrustaHandFitDef keypoints = FrustaHandFitDef.Default;
            keypoints.Layout = FrustaJointLayout.Keypoints;
            using var camera = new TrackedHandInput(hand, keypoints);
            Assert.Equal(21, camera.Joints.Length);
            Assert.Throws<InvalidOperationException>(
                () => camera.SetXrHandsJoint(0, Vector3d.Zero, Quaterniond.Identity, 0, XrHandsJoints.TrackingPose, false));
        }

        [Fact]
        public void CalibrationOnRequestSizesTheHandFromTwoSecondsOfNoisyTracking()
        {
            FrustaHandDef truth = FrustaHandDef.Default;
            truth.SetSize(0.205, 0.092);
            FrustaHandDef guess = FrustaHandDef.Default; // 0.19 x 0.085
            using var world = new World();
            FrustaHandId id = world.CreateHand(guess);
            using var input = new TrackedHandInput(guess, FrustaHandFitDef.Default);
            Assert.False(input.TryCompleteCalibration()); // none asked for
            Assert.Throws<ArgumentOutOfRangeException>(() => input.BeginCalibration(0));
            const int frames = 180; // 2 s at 90 Hz
            input.BeginCalibration(frames);
            var random = new Random(34);
            var joints = new FrustaTrackedJoint[XrHandsJoints.Count];
            for (int f = 0; f < frames; ++f)
            {
                Assert.False(input.TryCompleteCalibration());
                truth.GetJoints(FrustaJointLayout.Xr, RandomPose(random), InteriorAngles(truth, random), joints);
                for (int i = 0; i < joints.Length; ++i)
                {
                    // 2 mm of Gaussian noise per axis (Box-Muller)
                    Vector3d noise = new Vector3d(Gaussian(random), Gaussian(random), Gaussian(random)) * 0.002;
                    joints[i].Position += noise;
                }
                joints.CopyTo(input.Joints);
                input.Drive(world, id, FrustaPose.Identity);
            }
            Assert.Equal(frames, input.CalibrationFrames);
            Assert.True(input.TryCompleteCalibration());
            Assert.Equal(0, input.CalibrationFrameCapacity);
            Near(0.205, input.Hand.HandLength, 0.02 * 0.205, "hand length");
            Near(0.092, input.Hand.HandBreadth, 0.02 * 0.092, "hand breadth");
            // the world hand is rebuilt with the calibrated def; fits now use it
            world.DestroyHand(id);
            id = world.CreateHand(input.Hand);
            truth.GetJoints(FrustaJointLayout.Xr, FrustaPose.Identity, new double[20], joints);
            joints.CopyTo(input.Joints);
            Assert.True(input.Drive(world, id, FrustaPose.Identity));
            Assert.InRange(input.LastFit.PalmResidual, 0.0, 0.004);
        }

        static double Gaussian(Random random) =>
            Math.Sqrt(-2.0 * Math.Log(1.0 - random.NextDouble())) * Math.Cos(2.0 * Math.PI * random.NextDouble());

        [Fact]
        public void AFrameOfXrHandsInputAllocatesNothing()
        {
            FrustaHandDef hand = FrustaHandDef.Default;
            using var world = new World();
            FrustaHandId id = world.CreateHand(hand);
            using var input = new TrackedHandInput(hand, FrustaHandFitDef.Default);
            var poses = new FrustaPose[XrHandsJoints.Count];
            var random = new Random(35);
            AsXrHands(hand, RandomPose(random), InteriorAngles(hand, random), poses);
            AllocatesNothing(() =>
            {
                Feed(input, poses);
                input.Drive(world, id, FrustaPose.Identity);
            });
        }
    }
}
