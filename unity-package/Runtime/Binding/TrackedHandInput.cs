// SPDX-License-Identifier: MIT
using System;

namespace Frusta.Binding
{
    /// <summary>
    /// A world hand's haptic input from hand tracking, frame after frame: the frame's joints go into
    /// <see cref="Joints"/> (or one by one from XR Hands through <see cref="SetXrHandsJoint"/>), then
    /// <see cref="Drive(World, FrustaHandId, in FrustaPose, double)"/> fits them (<see cref="HandFitter"/>) and hands the fit to the world. A fit
    /// with no good history yet is not sent, so a hand never jumps to the rest pose at the origin.
    /// On request it sizes the hand to the user's: <see cref="BeginCalibration"/> gathers the next
    /// frames, <see cref="TryCompleteCalibration"/> calibrates the def from them
    /// (<see cref="FrustaHandDef.Calibrate"/>) and refits with it; the caller then rebuilds its world
    /// hand with that def. Everything per frame allocates nothing (calibration allocates once, when
    /// asked). Thread: one host thread.
    /// </summary>
    public sealed class TrackedHandInput : IDisposable
    {
        readonly FrustaHandFitDef fitDef;
        readonly FrustaTrackedJoint[] joints;
        HandFitter fitter;
        FrustaHandDef hand;
        FrustaHandFit fit;
        FrustaTrackedJoint[] calibration = Array.Empty<FrustaTrackedJoint>();
        int calibrationFrames;  // gathered so far

        /// <summary>The input of a hand of <paramref name="hand"/>, reading joints as
        /// <paramref name="def"/> says.</summary>
        /// <param name="hand">The world hand's def: side, sizes, limits.</param>
        /// <param name="def">From <see cref="FrustaHandFitDef.Default"/>, then edited.</param>
        /// <exception cref="FrustaException">A def value out of range.</exception>
        public TrackedHandInput(in FrustaHandDef hand, in FrustaHandFitDef def)
        {
            fitDef = def;
            this.hand = hand;
            fitter = new HandFitter(hand, def);
            joints = new FrustaTrackedJoint[fitter.JointCount];
        }

        /// <summary>The hand def fitted to (after a calibration, the calibrated one).</summary>
        public FrustaHandDef Hand => hand;

        /// <summary>This frame's joints in the fit def's layout, in Frusta's frame relative to the frame
        /// given to <see cref="Drive(World, FrustaHandId, in FrustaPose)"/>. They stay as set until overwritten or <see cref="ClearJoints"/>.</summary>
        public Span<FrustaTrackedJoint> Joints => joints;

        /// <summary>The last fit (<see cref="FrustaHandFit.PalmFlags"/> says how good).</summary>
        public ref readonly FrustaHandFit LastFit => ref fit;

        /// <summary>Mark every joint missing (tracking lost): a fit then holds the last good pose.</summary>
        public void ClearJoints() => Array.Clear(joints, 0, joints.Length);

        /// <summary>Set one joint from XR Hands (<see cref="XrHandsJoints.FromUnity"/>): Unity's frame,
        /// relative to the XR origin's tracking space. Needs the OpenXR layout.</summary>
        /// <param name="xrHandsIndex">0..25, the joint's <c>XRHandJointID.ToIndex()</c>.</param>
        /// <param name="position">The joint pose's position, metres.</param>
        /// <param name="rotation">The joint pose's rotation.</param>
        /// <param name="radius">Metres, 0 when unknown.</param>
        /// <param name="trackingState">The joint's <c>XRHandJointTrackingState</c> as an int.</param>
        /// <param name="reportsFidelity">As for <see cref="XrHandsJoints.Flags"/>.</param>
        /// <exception cref="InvalidOperationException">The fit def's layout is not OpenXR's.</exception>
        public void SetXrHandsJoint(int xrHandsIndex, Vector3d position, Quaterniond rotation, double radius,
                                    int trackingState, bool reportsFidelity)
        {
            if (fitDef.Layout != FrustaJointLayout.Xr)
                throw new InvalidOperationException("XR Hands joints need the OpenXR layout (FrustaHandFitDef.Layout)");
            joints[XrHandsJoints.OtherOrder(xrHandsIndex)] =
                XrHandsJoints.FromUnity(position, rotation, radius, trackingState, reportsFidelity);
        }

        /// <summary>
        /// Fit this frame's joints and, unless the fit has no good history yet
        /// (<see cref="FrustaFitFlag.NoHistory"/>), set it as the hand's haptic input
        /// (<see cref="World.SetHaptic(FrustaHandId, in FrustaHandFit)"/>). While a calibration gathers,
        /// a frame whose palm fitted (not held) is kept for it.
        /// </summary>
        /// <param name="world">The hand's world.</param>
        /// <param name="id">The hand, created from <see cref="Hand"/>.</param>
        /// <param name="frame">The joints' frame in the world, Frusta's frame (e.g. the XR origin's
        /// tracking space, converted with <see cref="CoordinateConversion.PoseFromUnity"/>).</param>
        /// <returns>true when the fit went to the world.</returns>
        /// <exception cref="FrustaException">A joint breaking the rules of <see cref="FrustaTrackedJoint"/>
        /// (named in the message), or the world refusing the input.</exception>
        public bool Drive(World world, FrustaHandId id, in FrustaPose frame) => Drive(world, id, frame, double.NaN);

        /// <summary>
        /// <see cref="Drive(World, FrustaHandId, in FrustaPose)"/> of joints the tracker took at
        /// <paramref name="time"/> (seconds, strictly increasing; e.g. the XR frame's time), through the
        /// fitter's One Euro filter (<see cref="HandFitter.Fit(double, ReadOnlySpan{FrustaTrackedJoint}, in FrustaPose, ref FrustaHandFit)"/>):
        /// what real trackers' jitter needs for a stable grasp.
        /// </summary>
        /// <param name="world">The hand's world.</param>
        /// <param name="id">The hand, created from <see cref="Hand"/>.</param>
        /// <param name="frame">The joints' frame in the world, Frusta's frame.</param>
        /// <param name="time">Seconds; NaN: an unfiltered fit.</param>
        /// <returns>true when the fit went to the world.</returns>
        /// <exception cref="FrustaException">A time not after the previous one, a bad joint, or the
        /// world refusing the input.</exception>
        public bool Drive(World world, FrustaHandId id, in FrustaPose frame, double time)
        {
            if (double.IsNaN(time)) fitter.Fit(joints, frame, ref fit);
            else fitter.Fit(time, joints, frame, ref fit);
            if ((fit.PalmFlags & FrustaFitFlag.Held) == 0 && calibrationFrames < CalibrationFrameCapacity)
            {
                joints.AsSpan().CopyTo(calibration.AsSpan(calibrationFrames * joints.Length));
                ++calibrationFrames;
            }
            if ((fit.PalmFlags & FrustaFitFlag.NoHistory) != 0) return false;
            world.SetHaptic(id, fit);
            return true;
        }

        /// <summary>Frames the calibration asked for (0 when none was).</summary>
        public int CalibrationFrameCapacity => calibration.Length / joints.Length;

        /// <summary>Frames gathered for the calibration so far.</summary>
        public int CalibrationFrames => calibrationFrames;

        /// <summary>Gather the next <paramref name="frames"/> frames whose palm fits (a few seconds of
        /// tracking in varied poses: 2 s at the tracker's rate does) for a calibration. Allocates once.</summary>
        /// <param name="frames">1..65536.</param>
        /// <exception cref="ArgumentOutOfRangeException">Not 1..65536.</exception>
        public void BeginCalibration(int frames)
        {
            if (frames < 1 || frames > 65536)
                throw new ArgumentOutOfRangeException(nameof(frames), $"{frames} is not 1..65536");
            calibration = new FrustaTrackedJoint[frames * joints.Length];
            calibrationFrames = 0;
        }

        /// <summary>Once the calibration's frames are gathered: size <see cref="Hand"/> from them, refit
        /// with it from the next frame, and end the calibration. The caller rebuilds its world hand
        /// with <see cref="Hand"/> (a world hand's def is fixed).</summary>
        /// <returns>true when calibrated; false while frames are missing or none was asked for.</returns>
        /// <exception cref="FrustaException">The frames never held the joints the size needs (the
        /// message names them); the calibration ends, nothing changes.</exception>
        public bool TryCompleteCalibration()
        {
            int capacity = CalibrationFrameCapacity;
            if (capacity == 0 || calibrationFrames < capacity) return false;
            FrustaHandDef sized = hand;
            try
            {
                sized.Calibrate(calibration, fitDef.Layout);
            }
            finally
            {
                calibration = Array.Empty<FrustaTrackedJoint>();
                calibrationFrames = 0;
            }
            var refit = new HandFitter(sized, fitDef);
            fitter.Dispose();
            fitter = refit;
            hand = sized;
            return true;
        }

        /// <summary>Destroy the native fitter. Safe to call twice.</summary>
        public void Dispose() => fitter.Dispose();
    }
}
