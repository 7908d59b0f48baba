// SPDX-License-Identifier: MIT
using System;

namespace Frusta.Binding
{
    /// <summary>
    /// What driving a skinned hand rig from a Frusta hand needs: the bones' names in a humanoid
    /// avatar and in rigs named after XR Hands' joints, the rig's hand frame from four of its
    /// joints, and for each finger bone the local axes its flexion and abduction turn about, from
    /// the hand def's own kinematics. The rig's pose when mapped is taken as the hand's rest pose
    /// (every angle 0: fingers straight); each frame a bone's local rotation is then its rest one
    /// times the abduction, then the flexion, about those axes (Unity's
    /// <c>rest * AngleAxis(abduction, a) * AngleAxis(flexion, f)</c>), which puts every joint where the
    /// Frusta hand's is. Pure functions on Unity-frame rotations: any thread; <see cref="Axes"/>
    /// calls the native library.
    /// </summary>
    public static class HandRig
    {
        static readonly string[] FingerNames = { "Thumb", "Index", "Middle", "Ring", "Little" };
        static readonly string[] HumanoidSegments = { "Proximal", "Intermediate", "Distal" };
        static readonly string[] XrThumbSegments = { "Metacarpal", "Proximal", "Distal" };

        /// <summary>The <c>HumanBodyBones</c> name of a segment's bone: a humanoid avatar's three bones
        /// per finger are the three segments (the thumb's first, "ThumbProximal", is its metacarpal,
        /// as Frusta's thumb's first segment is).</summary>
        /// <param name="side">Which hand.</param>
        /// <param name="finger">The finger.</param>
        /// <param name="segment">0..2, proximal to distal.</param>
        /// <returns>E.g. "RightIndexIntermediate".</returns>
        public static string HumanoidBoneName(FrustaHandSide side, FrustaFinger finger, int segment) =>
            $"{side}{FingerNames[FingerIndex(finger)]}{HumanoidSegments[SegmentIndex(segment)]}";

        /// <summary>The <c>XRHandJointID</c> name of the joint a segment's bone starts at: the thumb's
        /// segments start at ThumbMetacarpal, ThumbProximal, ThumbDistal; the others' at Proximal,
        /// Intermediate, Distal.</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="segment">0..2, proximal to distal.</param>
        /// <returns>E.g. "IndexIntermediate".</returns>
        public static string XrHandsJointName(FrustaFinger finger, int segment)
        {
            int f = FingerIndex(finger);
            return FingerNames[f] + (f == 0 ? XrThumbSegments : HumanoidSegments)[SegmentIndex(segment)];
        }

        /// <summary>Whether a rig's bone name names an XR Hands joint of a side, as rigs made for XR
        /// Hands do ("R_IndexProximal", "Left Hand Index Proximal", "index_proximal.L"): the joint's
        /// name, ignoring case, spaces, '_', '-' and '.', ends the name or precedes a side suffix,
        /// and no marker of the other side is there.</summary>
        /// <param name="boneName">The bone's name.</param>
        /// <param name="jointName">An XR Hands joint name (<see cref="XrHandsJointName"/>, "Wrist").</param>
        /// <param name="side">The hand the rig is.</param>
        /// <returns>true when the bone is that joint.</returns>
        public static bool NamesXrHandsJoint(string boneName, string jointName, FrustaHandSide side)
        {
            string bone = Squeeze(boneName), joint = Squeeze(jointName);
            string[] mine = side == FrustaHandSide.Right ? new[] { "right", "r" } : new[] { "left", "l" };
            string[] other = side == FrustaHandSide.Right ? new[] { "left", "l" } : new[] { "right", "r" };
            foreach (string suffix in mine)
                if (bone.EndsWith(joint + suffix, StringComparison.Ordinal)) return true;
            if (!bone.EndsWith(joint, StringComparison.Ordinal)) return false;
            string prefix = bone.Substring(0, bone.Length - joint.Length);
            foreach (string o in other)
                if (prefix.StartsWith(o, StringComparison.Ordinal) && !prefix.StartsWith(mine[0], StringComparison.Ordinal))
                    return false;
            return true;
        }

        static string Squeeze(string name)
        {
            var chars = new System.Text.StringBuilder(name.Length);
            foreach (char c in name)
                if (c != ' ' && c != '_' && c != '-' && c != '.') chars.Append(char.ToLowerInvariant(c));
            return chars.ToString();
        }

        static int FingerIndex(FrustaFinger finger)
        {
            if ((uint)finger >= FrustaConstants.FingerCount) throw new ArgumentOutOfRangeException(nameof(finger));
            return (int)finger;
        }

        static int SegmentIndex(int segment)
        {
            if ((uint)segment >= FrustaConstants.SegmentsPerFinger)
                throw new ArgumentOutOfRangeException(nameof(segment), $"{segment} is not 0..2");
            return segment;
        }

        /// <summary>
        /// The axes a hand's segments turn about at rest, in its hand frame (Frusta's, right-handed):
        /// each segment's flexion axis (a positive angle curls it towards the palm) and each finger's
        /// abduction axis (a positive angle turns the first segment towards the thumb). They are the
        /// def's own kinematics, read off the joints it reports (<see cref="FrustaHandDef.GetJoints"/>:
        /// a joint's -Z runs along its bone, +Y out of its back): flexion is back x bone, abduction
        /// the back on a right hand and the palm side on a left one.
        /// </summary>
        /// <param name="def">The hand.</param>
        /// <param name="flexion">Receives 15 unit axes, finger-major (segments proximal to distal).</param>
        /// <param name="abduction">Receives 5 unit axes, thumb first.</param>
        /// <exception cref="ArgumentException">A span too short.</exception>
        public static void Axes(in FrustaHandDef def, Span<Vector3d> flexion, Span<Vector3d> abduction)
        {
            if (flexion.Length < FrustaConstants.HandSegmentCount || abduction.Length < FrustaConstants.FingerCount)
                throw new ArgumentException("needs 15 flexion and 5 abduction axes");
            Span<FrustaTrackedJoint> joints = stackalloc FrustaTrackedJoint[FrustaConstants.XrJointCount];
            Span<double> rest = stackalloc double[FrustaConstants.HandJointCount];
            def.GetJoints(FrustaJointLayout.Xr, FrustaPose.Identity, rest, joints);
            double sign = def.Side == FrustaHandSide.Right ? 1.0 : -1.0;
            for (int f = 0; f < FrustaConstants.FingerCount; ++f)
                for (int s = 0; s < FrustaConstants.SegmentsPerFinger; ++s)
                {
                    // OpenXR's order: the thumb's segments start at joints 2..4, a finger's at its
                    // proximal joint and on (its metacarpal joint comes first)
                    Quaterniond q = joints[f == 0 ? 2 + s : 6 + 5 * (f - 1) + 1 + s].Rotation;
                    Vector3d bone = q.Rotate(new Vector3d(0, 0, -1)), back = q.Rotate(new Vector3d(0, 1, 0));
                    Vector3d axis = Vector3d.Cross(back, bone);
                    flexion[f * FrustaConstants.SegmentsPerFinger + s] = axis * (1.0 / axis.Length);
                    if (s == 0) abduction[f] = back * sign;
                }
        }

        /// <summary>
        /// The frame of a rig's hand (Frusta's frame, as a rotation): the rotation that takes the def's
        /// hand frame to the rig's, matching the frame their wrist and index, middle and little
        /// knuckles span (x from the wrist to the middle knuckle, y across from the little knuckle to
        /// the index one on a right hand and back on a left one, z = x cross y). A rig in the def's
        /// rest pose at a palm pose gives that pose's rotation exactly.
        /// </summary>
        /// <param name="def">The hand.</param>
        /// <param name="wrist">The rig's wrist joint, metres, Frusta's frame.</param>
        /// <param name="indexKnuckle">The index finger's first joint (its MCP).</param>
        /// <param name="middleKnuckle">The middle finger's first joint.</param>
        /// <param name="littleKnuckle">The little finger's first joint.</param>
        /// <returns>The rig's hand frame.</returns>
        /// <exception cref="ArgumentException">The joints are degenerate (coincide or in a line).</exception>
        public static Quaterniond HandFrame(in FrustaHandDef def, Vector3d wrist, Vector3d indexKnuckle,
                                            Vector3d middleKnuckle, Vector3d littleKnuckle)
        {
            Span<FrustaTrackedJoint> joints = stackalloc FrustaTrackedJoint[FrustaConstants.XrJointCount];
            Span<double> rest = stackalloc double[FrustaConstants.HandJointCount];
            def.GetJoints(FrustaJointLayout.Xr, FrustaPose.Identity, rest, joints);
            // OpenXR's order: 1 wrist, 7 index proximal, 12 middle proximal, 22 little proximal
            Quaterniond own = LandmarkFrame(joints[1].Position, joints[7].Position, joints[12].Position,
                                            joints[22].Position, def.Side);
            Quaterniond rig = LandmarkFrame(wrist, indexKnuckle, middleKnuckle, littleKnuckle, def.Side);
            return (rig * own.Conjugate).Normalized;
        }

        static Quaterniond LandmarkFrame(Vector3d wrist, Vector3d index, Vector3d middle, Vector3d little,
                                         FrustaHandSide side)
        {
            Vector3d x = middle - wrist;
            Vector3d across = index - little;
            if (!(x.Length > 0)) throw new ArgumentException("the wrist and the middle knuckle coincide");
            x *= 1.0 / x.Length;
            Vector3d y = across - x * Vector3d.Dot(across, x);
            if (!(y.Length > 1e-9 * across.Length) || !(across.Length > 0))
                throw new ArgumentException("the knuckles are in a line with the wrist");
            y *= (side == FrustaHandSide.Right ? 1.0 : -1.0) / y.Length;
            return Quaterniond.FromAxes(x, y, Vector3d.Cross(x, y));
        }

        /// <summary>A hand-frame axis as the local axis of a bone (Unity's frame: what
        /// <c>Quaternion.AngleAxis</c> after the bone's rest local rotation takes).</summary>
        /// <param name="boneRest">The bone's world rotation in the rest pose, Unity's frame.</param>
        /// <param name="handFrame">The rig's hand frame (<see cref="HandFrame"/>), Frusta's frame.</param>
        /// <param name="axis">An axis in the hand frame (<see cref="Axes"/>).</param>
        /// <returns>The unit axis in the bone's local frame, Unity's frame.</returns>
        public static Vector3d BoneAxis(Quaterniond boneRest, Quaterniond handFrame, Vector3d axis) =>
            boneRest.Conjugate.Rotate(CoordinateConversion.AxialToUnity(handFrame.Rotate(axis)));
    }
}
