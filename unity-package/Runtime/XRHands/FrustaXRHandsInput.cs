// SPDX-License-Identifier: MIT
using System.Collections.Generic;
using Frusta.Binding;
using UnityEngine;
using UnityEngine.XR.Hands;

namespace Frusta.Unity
{
    /// <summary>
    /// Drives a <see cref="FrustaHand"/> from hand tracking: each frame, the hand's 26 joints from Unity's
    /// XR Hands (<c>XRHandSubsystem</c>, the side of the hand's def) are fitted by the native library
    /// into the palm pose and 20 joint angles of the hand (<see cref="TrackedHandInput"/>) and become its
    /// haptic input; the graphic hand stays out of objects as with a glove, and the forces a glove would
    /// feel are in the hand's state. Compiled only where com.unity.xr.hands 1.1 or later is installed
    /// (this assembly's versionDefines). Allocation-free per frame.
    /// <para>The palm frame the hand then has (its graphic and haptic palm poses, the transform
    /// <see cref="FrustaHand"/> moves): the origin at the wrist joint, where XR Hands' wrist is (no
    /// offset to add); in Unity's axes, +X runs from the wrist towards the middle fingertip, +Z
    /// comes out of the palm (the side that grasps), and +Y points towards the thumb on a right hand
    /// and towards the little finger on a left one. (In Frusta's right-handed frame the same hand
    /// frame has +x to the fingers and +z out of the back of the hand.)</para>
    /// <para>Joints XR Hands reports without a pose keep their last good values; while the hand is not
    /// tracked, the last good fit is held. Call <see cref="Calibrate"/> (or set calibrate on start)
    /// with the user moving their fingers for a couple of seconds: the hand is then rebuilt with the
    /// user's hand length, breadth and segment lengths.</para>
    /// </summary>
    [AddComponentMenu("Frusta/Frusta XR Hands Input")]
    [RequireComponent(typeof(FrustaHand))]
    public sealed class FrustaXRHandsInput : MonoBehaviour
    {
        [Tooltip("The transform XR Hands' joint poses are relative to: the XR Origin's Camera Offset " +
                 "(the main camera's parent). Empty: the main camera's parent, else the scene's origin.")]
        [SerializeField] Transform trackingSpace;
        [Tooltip("Count a joint the runtime only infers (no high-fidelity pose; XR Hands 1.5 or later) as missing.")]
        [SerializeField] bool requireTrackedJoints;
        [Tooltip("Tracked frames a calibration gathers: about 2 s of the tracker's rate (180 at 90 Hz).")]
        [SerializeField, Range(30, 2000)] int calibrationFrames = 180;
        [Tooltip("Calibrate the hand's size as soon as it is tracked.")]
        [SerializeField] bool calibrateOnStart;

#if FRUSTA_XR_HANDS_1_5
        const bool ReportsFidelity = true;
#else
        const bool ReportsFidelity = false;
#endif
        static readonly List<XRHandSubsystem> found = new List<XRHandSubsystem>();
        FrustaHand hand;
        XRHandSubsystem subsystem;
        TrackedHandInput input;
        double lastFitTime = double.NegativeInfinity;  // seconds, the last sample's
        bool calibrationWanted, calibrating;
        bool reportedError;

        /// <summary>Raised on the main thread once a calibration has rebuilt the hand.</summary>
        public event System.Action Calibrated;

        /// <summary>true while a calibration gathers frames.</summary>
        public bool Calibrating => calibrating || calibrationWanted;

        /// <summary>The last fit: palm, angles, per-finger residuals and flags (empty before the first).</summary>
        public FrustaHandFit LastFit => input != null ? input.LastFit : default;

        /// <summary>Size the hand to the user's from the next tracked frames (move the fingers meanwhile);
        /// the hand is rebuilt with that size when they are in, and <see cref="Calibrated"/> is raised.</summary>
        public void Calibrate() => calibrationWanted = true;

        void OnEnable()
        {
            hand = GetComponent<FrustaHand>();
            hand.InputOwner = this;
        }

        void Start()
        {
            if (trackingSpace == null && Camera.main != null) trackingSpace = Camera.main.transform.parent;
            calibrationWanted |= calibrateOnStart;
        }

        void OnDisable()
        {
            if (hand != null && hand.InputOwner == this) hand.InputOwner = null;
            if (subsystem != null) subsystem.updatedHands -= OnUpdatedHands;
            subsystem = null;
            input?.Dispose();
            input = null;
            calibrating = calibrationWanted = false;
        }

        // the subsystem may start after this component (XR loads late); looking is cheap and
        // allocates nothing once the list has grown
        void Update()
        {
            if (subsystem != null && subsystem.running) return;
            if (subsystem != null) subsystem.updatedHands -= OnUpdatedHands;
            subsystem = null;
            SubsystemManager.GetSubsystems(found);
            for (int i = 0; i < found.Count; ++i)
            {
                if (!found[i].running) continue;
                subsystem = found[i];
                subsystem.updatedHands += OnUpdatedHands;
                break;
            }
        }

        bool EnsureInput()
        {
            if (input != null) return true;
            if (hand == null || hand.Id.IsNull) return false;
            FrustaHandFitDef def = FrustaHandFitDef.Default;
            def.RequireTracked = requireTrackedJoints;
            input = new TrackedHandInput(hand.Def, def);
            return true;
        }

        // the Dynamic update, before Update: the input of this frame's steps (XR Hands' advice for
        // what affects physics; BeforeRender comes too late for the world's thread)
        void OnUpdatedHands(XRHandSubsystem source, XRHandSubsystem.UpdateSuccessFlags flags,
                            XRHandSubsystem.UpdateType type)
        {
            if (type != XRHandSubsystem.UpdateType.Dynamic || hand.DrivenByDevice) return;
            FrustaWorldBehaviour behaviour = hand.WorldBehaviour;
            World world = behaviour != null ? behaviour.World : null;
            if (world == null || !EnsureInput()) return;
            if (calibrationWanted)
            {
                input.BeginCalibration(calibrationFrames);
                calibrating = true;
                calibrationWanted = false;
            }
            XRHand tracked = hand.Def.Side == FrustaHandSide.Right ? source.rightHand : source.leftHand;
            if (!tracked.isTracked) input.ClearJoints();
            else
                for (int i = 0; i < XrHandsJoints.Count; ++i)
                {
                    XRHandJoint joint = tracked.GetJoint(XRHandJointIDUtility.FromIndex(i));
                    joint.TryGetPose(out Pose pose);
                    joint.TryGetRadius(out float radius);
                    input.SetXrHandsJoint(i, new Vector3d(pose.position.x, pose.position.y, pose.position.z),
                                          new Quaterniond(pose.rotation.x, pose.rotation.y, pose.rotation.z, pose.rotation.w),
                                          radius, (int)joint.trackingState, ReportsFidelity);
                }
            FrustaPose frame = trackingSpace != null ? trackingSpace.ToFrustaPose() : FrustaPose.Identity;
            try
            {
                // the fitter's One Euro filter needs each sample's time, strictly increasing
                double now = Time.unscaledTimeAsDouble;
                if (now <= lastFitTime) now = lastFitTime + 1e-4;
                lastFitTime = now;
                input.Drive(world, hand.Id, frame, now);
                if (calibrating && input.TryCompleteCalibration())
                {
                    calibrating = false;
                    hand.Rebuild(input.Hand);
                    Calibrated?.Invoke();
                }
            }
            catch (FrustaException e)
            {
                calibrating = false;
                // once: a runtime reporting broken joints every frame must not flood the log
                if (reportedError) return;
                reportedError = true;
                Debug.LogError($"FrustaXRHandsInput: {e.Call} refused ({e.Result}): {e.NativeMessage}", this);
            }
        }
    }
}
