// SPDX-License-Identifier: MIT
using System;

namespace Frusta.Binding
{
    /// <summary>
    /// Turns tracked hand joints (OpenXR's 26 joint poses, as XR Hands reports them, or the 21
    /// keypoints of camera trackers) into what a world hand takes: the palm pose and the 20
    /// joint angles of a hand def, clamped into its limits, with a residual per finger
    /// (<c>frusta_create_hand_fitter</c>). Joints that are missing or, with
    /// <see cref="FrustaHandFitDef.RequireTracked"/>, only inferred keep their last good value and
    /// the fit says so (<see cref="FrustaFitFlag"/>). Size the def to the user's hand first
    /// (<see cref="FrustaHandDef.Calibrate"/>).
    /// <para>Frames: everything is Frusta's right-handed frame (convert Unity's with
    /// <see cref="CoordinateConversion"/>). The hand frame the fit returns: origin at the wrist,
    /// +x towards the fingertips, +z out of the back of the hand, +y towards the thumb on a right
    /// hand and away from it on a left one. Thread: the creating thread, the fitter's host.</para>
    /// </summary>
    public sealed unsafe class HandFitter : IDisposable
    {
        readonly FitterHandle handle;

        /// <summary>A fitter of a hand of <paramref name="hand"/> reading joints as
        /// <paramref name="def"/> says.</summary>
        /// <param name="hand">The hand: side, sizes, limits.</param>
        /// <param name="def">From <see cref="FrustaHandFitDef.Default"/>, then edited.</param>
        /// <exception cref="FrustaException">A def value out of range, with the native message.</exception>
        public HandFitter(in FrustaHandDef hand, in FrustaHandFitDef def)
        {
            FrustaLibrary.EnsureCompatible();
            handle = new FitterHandle();
            FrustaHandFitterId id;
            FrustaResult r;
            fixed (FrustaHandDef* h = &hand)
            fixed (FrustaHandFitDef* d = &def)
                r = Native.frusta_create_hand_fitter(h, d, &id);
            handle.Own(r, id, "frusta_create_hand_fitter");
            Layout = def.Layout;
            JointCount = JointCountOf(def.Layout);
        }

        /// <summary>The joints of one sample in a layout: 26 (OpenXR) or 21 (keypoints).</summary>
        /// <param name="layout">The layout.</param>
        /// <returns><see cref="FrustaConstants.XrJointCount"/> or <see cref="FrustaConstants.KeypointCount"/>.</returns>
        /// <exception cref="ArgumentOutOfRangeException">Not a layout.</exception>
        public static int JointCountOf(FrustaJointLayout layout)
        {
            switch (layout)
            {
                case FrustaJointLayout.Xr: return FrustaConstants.XrJointCount;
                case FrustaJointLayout.Keypoints: return FrustaConstants.KeypointCount;
                default: throw new ArgumentOutOfRangeException(nameof(layout));
            }
        }

        /// <summary>The native id (a value; stale once disposed).</summary>
        public FrustaHandFitterId Id => handle.Id;

        /// <summary>false once disposed (<c>frusta_hand_fitter_is_valid</c>).</summary>
        public bool IsValid => !handle.IsClosed && Native.frusta_hand_fitter_is_valid(handle.Id) == 1;

        /// <summary>How the joints given to <see cref="Fit(ReadOnlySpan{FrustaTrackedJoint}, ref FrustaHandFit)"/> are laid out.</summary>
        public FrustaJointLayout Layout { get; }

        /// <summary>The joints one sample has (<see cref="JointCountOf"/> of <see cref="Layout"/>).</summary>
        public int JointCount { get; }

        /// <summary>Fit one sample whose joints are in the world's frame.</summary>
        /// <param name="joints">Exactly <see cref="JointCount"/> joints.</param>
        /// <param name="fit">Filled: palm, angles, residuals, flags.</param>
        public void Fit(ReadOnlySpan<FrustaTrackedJoint> joints, ref FrustaHandFit fit) =>
            Fit(joints, FrustaPose.Identity, ref fit);

        /// <summary>
        /// Fit one sample, unfiltered (<c>frusta_hand_fitter_fit</c>; it restarts the filter of timed
        /// fits): joints in a frame whose pose in the world is
        /// <paramref name="frame"/> (e.g. the XR origin's), into <paramref name="fit"/>, whose palm is
        /// then in the world. Feed it to <see cref="World.SetHaptic(FrustaHandId, in FrustaHandFit)"/>.
        /// Allocation-free; microseconds.
        /// </summary>
        /// <param name="joints">Exactly <see cref="JointCount"/> joints. Fields a joint's flags do not
        /// declare valid are ignored; missing joints are no error.</param>
        /// <param name="frame">The joints' frame in the world, metres.</param>
        /// <param name="fit">Filled: palm, angles, residuals, flags. Reuse one per hand.</param>
        /// <exception cref="FrustaException">A wrong count, or a joint breaking the rules of
        /// <see cref="FrustaTrackedJoint"/> (named in the message); the fitter and
        /// <paramref name="fit"/> are then as they were.</exception>
        public void Fit(ReadOnlySpan<FrustaTrackedJoint> joints, in FrustaPose frame, ref FrustaHandFit fit)
        {
            fit.struct_size = sizeof(FrustaHandFit);
            using (new HandleUse(handle))
            fixed (FrustaTrackedJoint* j = joints)
            fixed (FrustaPose* p = &frame)
            fixed (FrustaHandFit* f = &fit)
                Errors.Check(Native.frusta_hand_fitter_fit(handle.Id, j, joints.Length, p, f), "frusta_hand_fitter_fit");
        }

        /// <summary>
        /// Fit one sample taken at <paramref name="time"/> through the fitter's One Euro filter
        /// (<c>frusta_hand_fitter_fit_at</c>; <see cref="FrustaHandFitDef.FilterMinCutoff"/>,
        /// <see cref="FrustaHandFitDef.FilterBeta"/>, <see cref="FrustaHandFitDef.FilterDCutoff"/>): a
        /// tracker's jitter is smoothed away at rest, motion lags little. Give each sample the time the
        /// tracker took it (e.g. the XR frame's predicted display time), seconds, strictly increasing;
        /// tracking lost (a held palm) restarts the filter. Allocation-free; microseconds.
        /// </summary>
        /// <param name="time">Seconds, any origin, after the previous timed sample's.</param>
        /// <param name="joints">Exactly <see cref="JointCount"/> joints.</param>
        /// <param name="frame">The joints' frame in the world, metres.</param>
        /// <param name="fit">Filled: the filtered palm and angles, the unfiltered fit's residuals and flags.</param>
        /// <exception cref="FrustaException">A time not after the previous one (naming "time"), a wrong
        /// count, or a bad joint; the fitter and <paramref name="fit"/> are then as they were.</exception>
        public void Fit(double time, ReadOnlySpan<FrustaTrackedJoint> joints, in FrustaPose frame, ref FrustaHandFit fit)
        {
            fit.struct_size = sizeof(FrustaHandFit);
            using (new HandleUse(handle))
            fixed (FrustaTrackedJoint* j = joints)
            fixed (FrustaPose* p = &frame)
            fixed (FrustaHandFit* f = &fit)
                Errors.Check(Native.frusta_hand_fitter_fit_at(handle.Id, time, j, joints.Length, p, f),
                             "frusta_hand_fitter_fit_at");
        }

        /// <summary>Fit one sample taken at <paramref name="time"/>, joints in the world's frame
        /// (<see cref="Fit(double, ReadOnlySpan{FrustaTrackedJoint}, in FrustaPose, ref FrustaHandFit)"/>).</summary>
        /// <param name="time">Seconds, after the previous timed sample's.</param>
        /// <param name="joints">Exactly <see cref="JointCount"/> joints.</param>
        /// <param name="fit">Filled: palm, angles, residuals, flags.</param>
        public void Fit(double time, ReadOnlySpan<FrustaTrackedJoint> joints, ref FrustaHandFit fit) =>
            Fit(time, joints, FrustaPose.Identity, ref fit);

        /// <summary>Destroy the native fitter (<c>frusta_destroy_hand_fitter</c>). Safe to call twice.</summary>
        public void Dispose() => handle.Dispose();
    }
}
