// SPDX-License-Identifier: MIT
using System;

namespace Frusta.Binding
{
    /// <summary>
    /// Unity's XR Hands (com.unity.xr.hands) joints as a <see cref="HandFitter"/> takes them. XR Hands
    /// reports OpenXR's 26 hand joints with three differences, each undone here: its joint array
    /// (<c>XRHandJointID.ToIndex()</c>) starts wrist, palm where OpenXR's starts palm, wrist; its poses
    /// are in Unity's left-handed frame (a joint's +Z, forward, runs along the bone towards the tip and
    /// +Y out of the back of the hand, which is OpenXR's -Z and +Y seen through the z flip); and its
    /// tracking state is <c>XRHandJointTrackingState</c>, not OpenXR's location flags. The values of that
    /// enum are mirrored here (<see cref="TrackingPose"/> ...) so that this binding needs no Unity
    /// assembly. Pure functions: any thread, no allocation.
    /// </summary>
    public static class XrHandsJoints
    {
        /// <summary>Joints of one XR Hands hand (<c>XRHandJointID.EndMarker.ToIndex()</c>), as OpenXR's.</summary>
        public const int Count = FrustaConstants.XrJointCount;

        /// <summary><c>XRHandJointTrackingState.Radius</c>: the joint's radius holds a value.</summary>
        public const int TrackingRadius = 1 << 0;
        /// <summary><c>XRHandJointTrackingState.Pose</c>: the joint's pose holds a value.</summary>
        public const int TrackingPose = 1 << 1;
        /// <summary><c>XRHandJointTrackingState.WillNeverBeValid</c>: the provider has no such joint.</summary>
        public const int TrackingWillNeverBeValid = 1 << 4;
        /// <summary><c>XRHandJointTrackingState.HighFidelityPose</c> (XR Hands 1.5 on): the pose is
        /// tracked by the runtime, not inferred.</summary>
        public const int TrackingHighFidelityPose = 1 << 5;

        /// <summary>Where a joint of XR Hands' array sits in OpenXR's order (and back: the map swaps
        /// wrist and palm, so it is its own inverse).</summary>
        /// <param name="index">0..25, <c>XRHandJointID.ToIndex()</c> (or an OpenXR index).</param>
        /// <returns>The same joint's index in the other order.</returns>
        /// <exception cref="ArgumentOutOfRangeException">Not 0..25.</exception>
        public static int OtherOrder(int index)
        {
            if ((uint)index >= Count) throw new ArgumentOutOfRangeException(nameof(index), $"{index} is not 0..{Count - 1}");
            return index == 0 ? 1 : index == 1 ? 0 : index;
        }

        /// <summary>A joint's <see cref="FrustaJointFlag"/> bits from its XR Hands tracking state.</summary>
        /// <param name="trackingState">The joint's <c>XRHandJointTrackingState</c> as an int.</param>
        /// <param name="reportsFidelity">true where the XR Hands version has
        /// <see cref="TrackingHighFidelityPose"/> (1.5 on): then a pose without it is inferred. false
        /// (older versions): every pose counts as tracked, as nothing says otherwise.</param>
        /// <returns>Position and orientation valid with a pose, tracked as said; nothing without.</returns>
        public static FrustaJointFlag Flags(int trackingState, bool reportsFidelity)
        {
            if ((trackingState & TrackingPose) == 0 || (trackingState & TrackingWillNeverBeValid) != 0) return 0;
            FrustaJointFlag flags = FrustaJointFlag.PositionValid | FrustaJointFlag.OrientationValid;
            if (!reportsFidelity || (trackingState & TrackingHighFidelityPose) != 0)
                flags |= FrustaJointFlag.PositionTracked | FrustaJointFlag.OrientationTracked;
            return flags;
        }

        /// <summary>One joint as XR Hands reports it (Unity's frame, relative to the XR origin's tracking
        /// space, metres) as a <see cref="FrustaTrackedJoint"/> in Frusta's frame with OpenXR's axes.</summary>
        /// <param name="position">The joint pose's position (<c>XRHandJoint.TryGetPose</c>).</param>
        /// <param name="rotation">The joint pose's rotation, (x, y, z, w).</param>
        /// <param name="radius">Metres (<c>XRHandJoint.TryGetRadius</c>), 0 when unknown.</param>
        /// <param name="trackingState">The joint's <c>XRHandJointTrackingState</c>.</param>
        /// <param name="reportsFidelity">As for <see cref="Flags"/>.</param>
        /// <returns>The joint; without a pose, its flags are 0 (missing) and its values unread.</returns>
        public static FrustaTrackedJoint FromUnity(Vector3d position, Quaterniond rotation, double radius,
                                                   int trackingState, bool reportsFidelity) =>
            new FrustaTrackedJoint(CoordinateConversion.VectorFromUnity(position),
                                   CoordinateConversion.RotationFromUnity(rotation),
                                   (trackingState & TrackingRadius) != 0 ? radius : 0.0,
                                   Flags(trackingState, reportsFidelity));

        /// <summary>A joint's pose as XR Hands would report it (Unity's frame): the inverse of
        /// <see cref="FromUnity"/>, for simulated tracking and tests.</summary>
        /// <param name="joint">In Frusta's frame, OpenXR's axes.</param>
        /// <returns>The pose in Unity's frame, XR Hands' axes.</returns>
        public static FrustaPose ToUnity(in FrustaTrackedJoint joint) =>
            new FrustaPose(CoordinateConversion.VectorToUnity(joint.Position),
                           CoordinateConversion.RotationToUnity(joint.Rotation));
    }
}
