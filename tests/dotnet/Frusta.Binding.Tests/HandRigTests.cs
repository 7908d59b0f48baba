// SPDX-License-Identifier: MIT
// Driving a skinned rig: bone names of humanoid avatars and XR Hands rigs, and the axes that
// put every joint of a rig where the Frusta hand's is. The rig here is the hand model itself,
// in Unity's frame, with bones whose local frames are random (as a real rig's are), driven as
// FrustaHand drives bones: rest * AngleAxis(abduction, a) * AngleAxis(flexion, f).
using System;
using Frusta.Binding;
using Xunit;
using static Frusta.Binding.Tests.Assertions;
using static Frusta.Binding.Tests.ConversionTests;
using static Frusta.Binding.Tests.HandFitterTests;

namespace Frusta.Binding.Tests
{
    public class HandRigTests
    {
        [Fact]
        public void BoneNamesOfHumanoidAvatarsAndXrHandsRigs()
        {
            Assert.Equal("RightThumbProximal", HandRig.HumanoidBoneName(FrustaHandSide.Right, FrustaFinger.Thumb, 0));
            Assert.Equal("LeftLittleDistal", HandRig.HumanoidBoneName(FrustaHandSide.Left, FrustaFinger.Little, 2));
            Assert.Equal("ThumbMetacarpal", HandRig.XrHandsJointName(FrustaFinger.Thumb, 0));
            Assert.Equal("ThumbDistal", HandRig.XrHandsJointName(FrustaFinger.Thumb, 2));
            Assert.Equal("IndexIntermediate", HandRig.XrHandsJointName(FrustaFinger.Index, 1));
            Assert.Throws<ArgumentOutOfRangeException>(() => HandRig.XrHandsJointName(FrustaFinger.Index, 3));
            Assert.Throws<ArgumentOutOfRangeException>(() => HandRig.HumanoidBoneName(FrustaHandSide.Left, (FrustaFinger)5, 0));

            foreach (string name in new[] { "R_IndexProximal", "Right Hand Index Proximal", "index_proximal.R", "IndexProximal",
                                            "hand_r/index-proximal-r" })
                Assert.True(HandRig.NamesXrHandsJoint(name, "IndexProximal", FrustaHandSide.Right), name);
            foreach (string name in new[] { "L_IndexProximal", "Left Hand Index Proximal", "index_proximal.L", "R_IndexIntermediate",
                                            "R_IndexProximalEnd" })
                Assert.False(HandRig.NamesXrHandsJoint(name, "IndexProximal", FrustaHandSide.Right), name);
            Assert.True(HandRig.NamesXrHandsJoint("L_Wrist", "Wrist", FrustaHandSide.Left));
        }

        // Unity's Quaternion.AngleAxis: degrees about an axis, the same formula on Unity's components
        static Quaterniond AngleAxis(double radians, Vector3d axis) => Quaterniond.AxisAngle(axis * (1.0 / axis.Length), radians);

        [Theory]
        [InlineData(FrustaHandSide.Right)]
        [InlineData(FrustaHandSide.Left)]
        public void ARigMappedAtRestPutsEveryJointWhereTheHandsIs(FrustaHandSide side)
        {
            FrustaHandDef hand = HandOf(side);
            hand.SetSize(0.2, 0.088);
            var random = new Random(side == FrustaHandSide.Right ? 41 : 42);
            Span<Vector3d> flexion = stackalloc Vector3d[15];
            Span<Vector3d> abduction = stackalloc Vector3d[5];
            HandRig.Axes(hand, flexion, abduction);
            var rest = new FrustaTrackedJoint[26];
            var posed = new FrustaTrackedJoint[26];
            var zero = new double[20];
            double worst = 0;
            for (int trial = 0; trial < 20; ++trial)
            {
                // the rig: the hand at rest somewhere, in Unity's frame, its bones' frames random
                FrustaPose palm = RandomPose(random);
                hand.GetJoints(FrustaJointLayout.Xr, palm, zero, rest);
                Quaterniond frame = HandRig.HandFrame(hand, rest[1].Position, rest[7].Position, rest[12].Position, rest[22].Position);
                SameRotation(palm.Rotation, frame, 1e-12, "the rig's hand frame");

                double[] angles = InteriorAngles(hand, random);
                hand.GetJoints(FrustaJointLayout.Xr, palm, angles, posed);
                for (int f = 0; f < 5; ++f)
                {
                    // the finger's chain in OpenXR's order: its three segments' start joints, then the tip
                    int first = f == 0 ? 2 : 6 + 5 * (f - 1) + 1;
                    Vector3d at = CoordinateConversion.VectorToUnity(rest[first].Position);
                    Quaterniond parent = Quaterniond.Identity; // the wrist bone, which keeps the palm pose here
                    Quaterniond parentRest = Quaterniond.Identity;
                    for (int s = 0; s < 3; ++s)
                    {
                        Quaterniond boneRest = RandomRotation(random);
                        Quaterniond local = parentRest.Conjugate * boneRest; // the bone's rest local rotation
                        Vector3d a = HandRig.BoneAxis(boneRest, frame, abduction[f]);
                        Vector3d x = HandRig.BoneAxis(boneRest, frame, flexion[f * 3 + s]);
                        double abducted = s == 0 ? angles[f * 4] : 0.0;
                        Quaterniond bone = parent * local * AngleAxis(abducted, a) * AngleAxis(angles[f * 4 + 1 + s], x);
                        // the next joint: the rest offset in the bone's frame, turned with the bone
                        Vector3d offset = boneRest.Conjugate.Rotate(CoordinateConversion.VectorToUnity(rest[first + s + 1].Position) -
                                                                     CoordinateConversion.VectorToUnity(rest[first + s].Position));
                        at += bone.Rotate(offset);
                        Vector3d expected = CoordinateConversion.VectorToUnity(posed[first + s + 1].Position);
                        worst = Math.Max(worst, (expected - at).Length);
                        Near(expected, at, 1e-9, $"finger {f} joint {s + 1}");
                        parent = bone;
                        parentRest = boneRest;
                    }
                }
            }
            Assert.True(worst < 1e-9, $"{worst} m");
        }
    }
}
