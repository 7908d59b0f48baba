// SPDX-License-Identifier: MIT
// The idiomatic side of the struct mirrors that Generated/Structs.g.cs writes from frusta.h:
// constructors, the native defaults, bool properties over 0/1 flags and accessors over
// fixed buffers (the generated fields they wrap are internal and keep their C names).
// Fields live only in the generated part: a second part with fields would leave their
// order, and so the layout, to the compiler.
using System;
using System.Text;

namespace Frusta.Binding
{
    /// <remarks>In Frusta's right-handed frame; convert with <see cref="CoordinateConversion"/>.</remarks>
    public partial struct FrustaPose
    {
        /// <summary>A pose from a position and a rotation.</summary>
        /// <param name="position">Metres.</param>
        /// <param name="rotation">A unit quaternion (norm 0.5..2 is accepted and normalised by the library).</param>
        public FrustaPose(Vector3d position, Quaterniond rotation)
        {
            Position = position;
            Rotation = rotation;
        }

        /// <summary>The identity pose: origin, no rotation.</summary>
        public static FrustaPose Identity => new FrustaPose(Vector3d.Zero, Quaterniond.Identity);

        /// <summary>A point of this pose's frame in the parent frame: R p + t.</summary>
        /// <param name="local">A point in this frame, metres.</param>
        /// <returns>The point in the parent frame, metres.</returns>
        public readonly Vector3d TransformPoint(Vector3d local) => Rotation.Rotate(local) + Position;
    }

    public partial struct FrustaSphere
    {
        /// <summary>A sphere from its centre and radius.</summary>
        /// <param name="center">Metres.</param>
        /// <param name="radius">Metres, &gt;= 0.</param>
        public FrustaSphere(Vector3d center, double radius)
        {
            Center = center;
            Radius = radius;
        }
    }

    /// <remarks>Get one from <see cref="Default"/>, resize it with <see cref="SetSize"/>, then
    /// override single entries through the accessors.</remarks>
    public unsafe partial struct FrustaHandDef
    {
        /// <summary>The library's default hand (<c>frusta_default_hand_def</c>): a right hand of
        /// 50th-percentile adult size. Thread: any.</summary>
        public static FrustaHandDef Default => FrustaLibrary.Compatible(() => Native.frusta_default_hand_def());

        /// <summary>Refill the geometry (segment lengths, joint radii, bases, palm) from a hand
        /// length and breadth with the library's anthropometric proportions; side and joint limits
        /// are kept (<c>frusta_hand_def_set_size</c>). On error this def is unchanged. Thread: any.</summary>
        /// <param name="handLength">Metres, wrist crease to middle fingertip.</param>
        /// <param name="handBreadth">Metres, across the metacarpal heads.</param>
        /// <exception cref="FrustaException">A length out of range or not finite.</exception>
        public void SetSize(double handLength, double handBreadth)
        {
            fixed (FrustaHandDef* self = &this)
                Errors.Check(Native.frusta_hand_def_set_size(self, handLength, handBreadth), "frusta_hand_def_set_size");
        }

        /// <summary>Size this def from tracked joints: hand length and breadth fitted to the distances
        /// between the palm's joints and the middle finger's bones, then each segment length measured
        /// (over the frames, less the noise's bias); side and joint limits are kept
        /// (<c>frusta_calibrate_hand_def</c>). A few seconds of tracking in any poses will do. A joint counts when its flags have
        /// <see cref="FrustaJointFlag.PositionValid"/> and <see cref="FrustaJointFlag.PositionTracked"/>.
        /// On error this def is unchanged. Thread: any.</summary>
        /// <param name="frames">Frame after frame, each the layout's joints
        /// (<see cref="HandFitter.JointCountOf"/>): at most 65536 frames.</param>
        /// <param name="layout">How each frame's joints are laid out.</param>
        /// <exception cref="ArgumentException">frames is not a whole number of frames.</exception>
        /// <exception cref="FrustaException">A joint breaking the rules of <see cref="FrustaTrackedJoint"/>,
        /// or no frame with the joints the hand's size needs (the message names them).</exception>
        public void Calibrate(ReadOnlySpan<FrustaTrackedJoint> frames, FrustaJointLayout layout)
        {
            int perFrame = HandFitter.JointCountOf(layout);
            if (frames.Length % perFrame != 0)
                throw new ArgumentException($"{frames.Length} joints are not whole frames of {perFrame}", nameof(frames));
            fixed (FrustaHandDef* self = &this)
            fixed (FrustaTrackedJoint* j = frames)
                Errors.Check(Native.frusta_calibrate_hand_def(j, frames.Length / perFrame, (int)layout, self),
                             "frusta_calibrate_hand_def");
        }

        /// <summary>The joints a tracker would report for a hand of this def at a palm pose and joint
        /// angles (clamped into the limits), every flag set: the first min(destination.Length, count)
        /// (<c>frusta_hand_joints_from_pose</c>). For tests, recordings and demos. Thread: any.</summary>
        /// <param name="layout">The joints' layout.</param>
        /// <param name="palm">The hand frame, metres.</param>
        /// <param name="angles">Exactly <see cref="FrustaConstants.HandJointCount"/> radians, finger-major.</param>
        /// <param name="destination">Receives the joints; <see cref="HandFitter.JointCountOf"/> holds all.</param>
        /// <returns>How many joints the layout has.</returns>
        public readonly int GetJoints(FrustaJointLayout layout, in FrustaPose palm, ReadOnlySpan<double> angles,
                                      Span<FrustaTrackedJoint> destination)
        {
            int count;
            fixed (FrustaHandDef* self = &this)
            fixed (FrustaPose* p = &palm)
            fixed (double* a = angles)
            fixed (FrustaTrackedJoint* d = destination)
                Errors.Check(Native.frusta_hand_joints_from_pose(self, (int)layout, p, a, angles.Length, d,
                                                                  destination.Length, &count),
                             "frusta_hand_joints_from_pose");
            return count;
        }

        static int Index(FrustaFinger finger, int k, int count)
        {
            if ((uint)finger >= FrustaConstants.FingerCount) throw new ArgumentOutOfRangeException(nameof(finger));
            if ((uint)k >= (uint)count) throw new ArgumentOutOfRangeException(nameof(k), $"must be 0..{count - 1}");
            return (int)finger * count + k;
        }

        /// <summary>Joint centre to joint centre of one segment, metres (the third runs to the tip
        /// hemisphere's centre).</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="segment">0..2, proximal to distal.</param>
        /// <returns>Metres.</returns>
        public double GetSegmentLength(FrustaFinger finger, int segment) =>
            segment_length[Index(finger, segment, FrustaConstants.SegmentsPerFinger)];

        /// <summary>Override one segment length (see <see cref="GetSegmentLength"/>).</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="segment">0..2, proximal to distal.</param>
        /// <param name="metres">The length, metres.</param>
        public void SetSegmentLength(FrustaFinger finger, int segment, double metres) =>
            segment_length[Index(finger, segment, FrustaConstants.SegmentsPerFinger)] = metres;

        /// <summary>Ball radius at the first, second, third joint (0..2) or the tip hemisphere (3), metres.</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="ball">0..3.</param>
        /// <returns>Metres.</returns>
        public double GetJointRadius(FrustaFinger finger, int ball) => joint_radius[Index(finger, ball, 4)];

        /// <summary>Override one ball radius (see <see cref="GetJointRadius"/>).</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="ball">0..3.</param>
        /// <param name="metres">The radius, metres.</param>
        public void SetJointRadius(FrustaFinger finger, int ball, double metres) =>
            joint_radius[Index(finger, ball, 4)] = metres;

        /// <summary>First joint centre of a finger in the hand frame, metres.</summary>
        /// <param name="finger">The finger.</param>
        /// <returns>Metres, hand frame.</returns>
        public Vector3d GetBasePosition(FrustaFinger finger)
        {
            fixed (double* p = base_position) return Vector3d.Read(p + Index(finger, 0, 3));
        }

        /// <summary>Override a finger's first joint centre (see <see cref="GetBasePosition"/>).</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="metres">Metres, hand frame.</param>
        public void SetBasePosition(FrustaFinger finger, Vector3d metres)
        {
            fixed (double* p = base_position) metres.Write(p + Index(finger, 0, 3));
        }

        /// <summary>The x-y-z rotation of a finger's rest frame, radians.</summary>
        /// <param name="finger">The finger.</param>
        /// <returns>Radians about x, y, z.</returns>
        public Vector3d GetBaseRotation(FrustaFinger finger)
        {
            fixed (double* p = base_rotation) return Vector3d.Read(p + Index(finger, 0, 3));
        }

        /// <summary>Override a finger's rest frame rotation (see <see cref="GetBaseRotation"/>).</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="radians">Radians about x, y, z.</param>
        public void SetBaseRotation(FrustaFinger finger, Vector3d radians)
        {
            fixed (double* p = base_rotation) radians.Write(p + Index(finger, 0, 3));
        }

        /// <summary>Lower limit of a joint angle, radians.</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="joint">0 abduction, 1..3 flexion of the first, second, third joint.</param>
        /// <returns>Radians.</returns>
        public double GetJointMin(FrustaFinger finger, int joint) =>
            joint_min[Index(finger, joint, FrustaConstants.JointsPerFinger)];

        /// <summary>Override a joint's lower limit.</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="joint">0 abduction, 1..3 flexion.</param>
        /// <param name="radians">Radians.</param>
        public void SetJointMin(FrustaFinger finger, int joint, double radians) =>
            joint_min[Index(finger, joint, FrustaConstants.JointsPerFinger)] = radians;

        /// <summary>Upper limit of a joint angle, radians.</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="joint">0 abduction, 1..3 flexion of the first, second, third joint.</param>
        /// <returns>Radians.</returns>
        public double GetJointMax(FrustaFinger finger, int joint) =>
            joint_max[Index(finger, joint, FrustaConstants.JointsPerFinger)];

        /// <summary>Override a joint's upper limit.</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="joint">0 abduction, 1..3 flexion.</param>
        /// <param name="radians">Radians.</param>
        public void SetJointMax(FrustaFinger finger, int joint, double radians) =>
            joint_max[Index(finger, joint, FrustaConstants.JointsPerFinger)] = radians;
    }

    /// <remarks>In Frusta's right-handed frame; convert with <see cref="CoordinateConversion"/>. An
    /// OpenXR joint's pose and locationFlags go in as they are.</remarks>
    public partial struct FrustaTrackedJoint
    {
        /// <summary>A joint from its pose, radius and flags.</summary>
        /// <param name="position">Metres.</param>
        /// <param name="rotation">OpenXR's joint axes: -Z along the bone towards the tip, +Y out of its back.</param>
        /// <param name="radius">Metres, 0 when unknown.</param>
        /// <param name="flags">Which fields hold values.</param>
        public FrustaTrackedJoint(Vector3d position, Quaterniond rotation, double radius, FrustaJointFlag flags)
        {
            Position = position;
            Rotation = rotation;
            Radius = radius;
            Flags = flags;
            reserved0 = 0;
        }

        /// <summary>A keypoint: a position alone, valid and tracked.</summary>
        /// <param name="position">Metres.</param>
        /// <returns>The joint.</returns>
        public static FrustaTrackedJoint Keypoint(Vector3d position) =>
            new FrustaTrackedJoint(position, Quaterniond.Identity, 0.0,
                                   FrustaJointFlag.PositionValid | FrustaJointFlag.PositionTracked);
    }

    public partial struct FrustaHandFitDef
    {
        /// <summary>The library's defaults (<c>frusta_default_hand_fit_def</c>): OpenXR's 26 joints,
        /// inferred joints taken, 10 refining steps, orientations only when points fall short, the
        /// One Euro filter of timed fits on (<see cref="FilterMinCutoff"/>; 0 turns it off).
        /// Thread: any.</summary>
        public static FrustaHandFitDef Default => FrustaLibrary.Compatible(() => Native.frusta_default_hand_fit_def());

        /// <summary>true: a joint whose position is valid but not tracked (inferred by the runtime)
        /// counts as missing; default false.</summary>
        public bool RequireTracked
        {
            readonly get => require_tracked != 0;
            set => require_tracked = value ? 1 : 0;
        }
    }

    /// <remarks>Filled by <see cref="HandFitter.Fit(ReadOnlySpan{FrustaTrackedJoint}, in FrustaPose, ref FrustaHandFit)"/>;
    /// feed it to <see cref="World.SetHaptic(FrustaHandId, in FrustaHandFit)"/>. Reuse one instance
    /// per frame: nothing is allocated.</remarks>
    public unsafe partial struct FrustaHandFit
    {
        static int Finger(FrustaFinger finger)
        {
            if ((uint)finger >= FrustaConstants.FingerCount) throw new ArgumentOutOfRangeException(nameof(finger));
            return (int)finger;
        }

        /// <summary>One fitted joint angle, radians, within the hand's limits.</summary>
        /// <param name="joint">finger * 4 + k; k 0 abduction, 1..3 flexion.</param>
        /// <returns>Radians.</returns>
        public readonly double GetAngle(int joint)
        {
            if ((uint)joint >= FrustaConstants.HandJointCount)
                throw new ArgumentOutOfRangeException(nameof(joint), "must be 0..19");
            fixed (double* a = angles) return a[joint];
        }

        /// <summary>Copy the fitted angles, radians, finger-major: the first min(destination.Length, 20).</summary>
        /// <param name="destination">Receives the angles.</param>
        /// <returns>How many angles there are (20).</returns>
        public readonly int CopyAngles(Span<double> destination)
        {
            fixed (double* a = angles)
                new ReadOnlySpan<double>(a, FrustaConstants.HandJointCount)
                    .Slice(0, Math.Min(destination.Length, FrustaConstants.HandJointCount)).CopyTo(destination);
            return FrustaConstants.HandJointCount;
        }

        /// <summary>RMS distance of a finger's moving joints present from the fitted hand's, metres
        /// (0 when none is).</summary>
        /// <param name="finger">The finger.</param>
        /// <returns>Metres.</returns>
        public readonly double GetFingerResidual(FrustaFinger finger)
        {
            fixed (double* r = finger_residual) return r[Finger(finger)];
        }

        /// <summary>How a finger's angles came about: fitted (none), held, partly held, clamped.</summary>
        /// <param name="finger">The finger.</param>
        /// <returns>The flags.</returns>
        public readonly FrustaFitFlag GetFingerFlags(FrustaFinger finger)
        {
            fixed (int* f = finger_flags) return (FrustaFitFlag)f[Finger(finger)];
        }
    }

    /// <remarks>From <see cref="Geometry.QueryContact"/>.</remarks>
    public partial struct FrustaContactQuery
    {
        /// <summary>true if seed eq. 5 reports contact (for comparison only).</summary>
        public readonly bool PatentContact => patent_contact != 0;

        /// <summary>true if the engine's conservative test reports contact.</summary>
        public readonly bool Contact => contact != 0;
    }

    public partial struct FrustaBakeDef
    {
        /// <summary>The library's defaults (<c>frusta_default_bake_def</c>). Thread: any.</summary>
        public static FrustaBakeDef Default => FrustaLibrary.Compatible(() => Native.frusta_default_bake_def());
    }

    /// <remarks>From <see cref="SphereTree.Info"/>.</remarks>
    public partial struct FrustaSphereTreeInfo
    {
        /// <summary>true if both error figures are within <see cref="TargetError"/>.</summary>
        public readonly bool TargetMet => target_met != 0;
    }

    public partial struct FrustaWorldDef
    {
        /// <summary>true (default): the world's own thread and the threads of gloves driving its
        /// hands ask the system for real-time priority, so a glove is answered within a period
        /// whatever else the machine runs; they run at normal priority where it is refused
        /// (<see cref="FrustaWorldState.Realtime"/> says which).</summary>
        public bool RealtimePriority
        {
            readonly get => realtime_priority != 0;
            set => realtime_priority = value ? 1 : 0;
        }

        /// <summary>The library's defaults (<c>frusta_default_world_def</c>). Thread: any.</summary>
        public static FrustaWorldDef Default => FrustaLibrary.Compatible(() => Native.frusta_default_world_def());
    }

    public partial struct FrustaObjectDef
    {
        /// <summary>true: the world moves the object under the hands' reactions and gravity;
        /// false (default): kinematic.</summary>
        public bool Dynamic
        {
            readonly get => dynamic != 0;
            set => dynamic = value ? 1 : 0;
        }

        /// <summary>The library's defaults (<c>frusta_default_object_def</c>). Thread: any.</summary>
        public static FrustaObjectDef Default => FrustaLibrary.Compatible(() => Native.frusta_default_object_def());
    }

    /// <remarks>Filled by <see cref="World.GetHand"/>. The graphic hand is the displayed one (it
    /// never sinks into objects); the haptic hand is the input the step used. Reuse one instance
    /// per frame: nothing is allocated.</remarks>
    public unsafe partial struct FrustaWorldHand
    {
        /// <summary>false until the hand's first valid input.</summary>
        public readonly bool Solved => solved != 0;

        /// <summary>true when the step budget (the sub-step cap, or the world thread's share of the period) stopped
        /// the hand short of its input this step; the pushes then change gradually until they are their own again.</summary>
        public readonly bool Lagging => lagging != 0;

        /// <summary>true when a contact QP had no point meeting every row it was given this
        /// step (nearly parallel or contradictory constraints): the hand stayed at its last safe
        /// estimate, short of its input.</summary>
        public readonly bool Infeasible => infeasible != 0;

        /// <summary>true when the step played a time past the hand's newest timed sample (its
        /// driver is late or stopped): the input was extrapolated, at most
        /// <see cref="FrustaWorldDef.MaxExtrapolation"/>, then held.</summary>
        public readonly bool InputLate => input_late != 0;

        static int Joint(int joint)
        {
            if ((uint)joint >= FrustaConstants.HandJointCount)
                throw new ArgumentOutOfRangeException(nameof(joint), "must be 0..19");
            return joint;
        }

        static int Finger(FrustaFinger finger)
        {
            if ((uint)finger >= FrustaConstants.FingerCount) throw new ArgumentOutOfRangeException(nameof(finger));
            return (int)finger;
        }

        /// <summary>One displayed joint angle, radians.</summary>
        /// <param name="joint">finger * 4 + k; k 0 abduction, 1..3 flexion.</param>
        /// <returns>Radians.</returns>
        public double GetGraphicAngle(int joint) => graphic_angles[Joint(joint)];

        /// <summary>One input joint angle the step used, radians.</summary>
        /// <param name="joint">finger * 4 + k; k 0 abduction, 1..3 flexion.</param>
        /// <returns>Radians.</returns>
        public double GetHapticAngle(int joint) => haptic_angles[Joint(joint)];

        /// <summary>Copy the 20 displayed joint angles (radians, finger-major) without allocating.</summary>
        /// <param name="destination">At least 20 doubles.</param>
        public void CopyGraphicAngles(Span<double> destination)
        {
            if (destination.Length < FrustaConstants.HandJointCount) throw new ArgumentException("needs 20 doubles", nameof(destination));
            for (int j = 0; j < FrustaConstants.HandJointCount; ++j) destination[j] = graphic_angles[j];
        }

        /// <summary>Copy the 20 input joint angles (radians, finger-major) without allocating.</summary>
        /// <param name="destination">At least 20 doubles.</param>
        public void CopyHapticAngles(Span<double> destination)
        {
            if (destination.Length < FrustaConstants.HandJointCount) throw new ArgumentException("needs 20 doubles", nameof(destination));
            for (int j = 0; j < FrustaConstants.HandJointCount; ++j) destination[j] = haptic_angles[j];
        }

        /// <summary>The force on a finger's distal segment, newtons, world frame.</summary>
        /// <param name="finger">The finger.</param>
        /// <returns>Newtons.</returns>
        public Vector3d GetFingertipForce(FrustaFinger finger)
        {
            fixed (double* f = fingertip_force) return Vector3d.Read(f + Finger(finger) * 3);
        }

        /// <summary>|force| on a whole finger, newtons: what a brake glove renders.</summary>
        /// <param name="finger">The finger.</param>
        /// <returns>Newtons, &gt;= 0.</returns>
        public double GetFingerResistance(FrustaFinger finger) => finger_resistance[Finger(finger)];

        /// <summary>J^T F at one joint, newton-metres.</summary>
        /// <param name="joint">finger * 4 + k; k 0 abduction, 1..3 flexion.</param>
        /// <returns>Newton-metres.</returns>
        public double GetJointTorque(int joint) => joint_torque[Joint(joint)];
    }

    /// <remarks>Filled by <see cref="World.GetContacts(FrustaHandId, Span{FrustaWorldContact})"/>.</remarks>
    public partial struct FrustaWorldContact
    {
        /// <summary>true when friction is at mu |F| (sliding).</summary>
        public readonly bool Slipping => slipping != 0;

        /// <summary>true when the contact is on the palm.</summary>
        public readonly bool IsPalm => Body == FrustaConstants.PalmBody;

        /// <summary>The finger of a finger contact (meaningless for the palm: see <see cref="IsPalm"/>).</summary>
        public readonly FrustaFinger Finger => (FrustaFinger)(Body / FrustaConstants.SegmentsPerFinger);

        /// <summary>The segment of a finger contact, 0..2 proximal to distal.</summary>
        public readonly int Segment => Body % FrustaConstants.SegmentsPerFinger;
    }

    public partial struct FrustaWorldState
    {
        /// <summary>true when the world's own thread runs at real-time priority.</summary>
        public readonly bool Realtime => realtime != 0;
    }

    /// <remarks>Filled by <see cref="World.GetObject"/>.</remarks>
    public partial struct FrustaObjectState
    {
        /// <summary>true when the world integrates this object.</summary>
        public readonly bool Dynamic => dynamic != 0;

        /// <summary>true while a hand's grasp holds this dynamic object: it moves with that
        /// hand's palm, and <see cref="ReactionForce"/> is what carrying it takes.</summary>
        public readonly bool Held => held != 0;
    }

    /// <remarks>From <see cref="Default"/>, then edited, then passed to
    /// <see cref="World.CreateDevice(string, in FrustaDeviceDef)"/>. The OpenGloves calibration (raw
    /// readings to radians, newtons to brake units) is read only by <c>opengloves:</c> gloves;
    /// gloves that speak Frusta's binary profile send radians.</remarks>
    public unsafe partial struct FrustaDeviceDef
    {
        const int Flexions = FrustaConstants.FlexionJointsPerFinger;

        /// <summary>The library's defaults (<c>frusta_default_device_def</c>): no hand (set
        /// <see cref="Hand"/> to an id from <see cref="World.CreateHand"/>), the world's
        /// rate, the timeouts and limits above, and a calibration from a straight hand (raw 0, 0 rad)
        /// to a fist (raw 4095). Thread: any.</summary>
        public static FrustaDeviceDef Default => FrustaLibrary.Compatible(() => Native.frusta_default_device_def());

        static int Flexion(FrustaFinger finger, int joint)
        {
            if ((uint)finger >= FrustaConstants.FingerCount) throw new ArgumentOutOfRangeException(nameof(finger));
            if ((uint)joint >= Flexions) throw new ArgumentOutOfRangeException(nameof(joint), "must be 0..2");
            return (int)finger * Flexions + joint;
        }

        static int Finger(FrustaFinger finger)
        {
            if ((uint)finger >= FrustaConstants.FingerCount) throw new ArgumentOutOfRangeException(nameof(finger));
            return (int)finger;
        }

        /// <summary>The raw reading of a flexion joint with the finger straight; default 0.</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="joint">0..2: the first, second, third flexion joint.</param>
        /// <returns>Raw units, 0..<see cref="AnalogMax"/>.</returns>
        public double GetCurlOpen(FrustaFinger finger, int joint) => curl_open[Flexion(finger, joint)];

        /// <summary>Set the raw reading of a straight flexion joint (see <see cref="GetCurlOpen"/>).</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="joint">0..2.</param>
        /// <param name="raw">Raw units, 0..<see cref="AnalogMax"/>; at least 1 from the closed reading.</param>
        public void SetCurlOpen(FrustaFinger finger, int joint, double raw) => curl_open[Flexion(finger, joint)] = raw;

        /// <summary>The raw reading of a flexion joint in a fist; default 4095.</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="joint">0..2: the first, second, third flexion joint.</param>
        /// <returns>Raw units, 0..<see cref="AnalogMax"/>.</returns>
        public double GetCurlClosed(FrustaFinger finger, int joint) => curl_closed[Flexion(finger, joint)];

        /// <summary>Set the raw reading of a flexion joint in a fist (see <see cref="GetCurlClosed"/>).</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="joint">0..2.</param>
        /// <param name="raw">Raw units, 0..<see cref="AnalogMax"/>.</param>
        public void SetCurlClosed(FrustaFinger finger, int joint, double raw) => curl_closed[Flexion(finger, joint)] = raw;

        /// <summary>The flexion angle at the open reading; default 0.</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="joint">0..2: the first, second, third flexion joint.</param>
        /// <returns>Radians, |angle| &lt;= pi.</returns>
        public double GetFlexionOpen(FrustaFinger finger, int joint) => flexion_open[Flexion(finger, joint)];

        /// <summary>Set the flexion angle at the open reading (see <see cref="GetFlexionOpen"/>).</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="joint">0..2.</param>
        /// <param name="radians">Radians, |angle| &lt;= pi.</param>
        public void SetFlexionOpen(FrustaFinger finger, int joint, double radians) => flexion_open[Flexion(finger, joint)] = radians;

        /// <summary>The flexion angle at the closed reading; default a fist (80, 90, 70 degrees; the
        /// thumb 45, 40, 60).</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="joint">0..2: the first, second, third flexion joint.</param>
        /// <returns>Radians, |angle| &lt;= pi.</returns>
        public double GetFlexionClosed(FrustaFinger finger, int joint) => flexion_closed[Flexion(finger, joint)];

        /// <summary>Set the flexion angle at the closed reading (see <see cref="GetFlexionClosed"/>).</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="joint">0..2.</param>
        /// <param name="radians">Radians, |angle| &lt;= pi.</param>
        public void SetFlexionClosed(FrustaFinger finger, int joint, double radians) => flexion_closed[Flexion(finger, joint)] = radians;

        /// <summary>The raw splay reading of a straight finger; default 2048.</summary>
        /// <param name="finger">The finger.</param>
        /// <returns>Raw units, 0..<see cref="AnalogMax"/>.</returns>
        public double GetSplayCenter(FrustaFinger finger) => splay_center[Finger(finger)];

        /// <summary>Set the raw splay reading of a straight finger (see <see cref="GetSplayCenter"/>).</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="raw">Raw units, 0..<see cref="AnalogMax"/>.</param>
        public void SetSplayCenter(FrustaFinger finger, double raw) => splay_center[Finger(finger)] = raw;

        /// <summary>The raw splay change that means <see cref="GetAbductionRange"/>; default 2047.</summary>
        /// <param name="finger">The finger.</param>
        /// <returns>Raw units, 1..<see cref="AnalogMax"/>.</returns>
        public double GetSplaySpan(FrustaFinger finger) => splay_span[Finger(finger)];

        /// <summary>Set a finger's raw splay span (see <see cref="GetSplaySpan"/>).</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="raw">Raw units, 1..<see cref="AnalogMax"/>.</param>
        public void SetSplaySpan(FrustaFinger finger, double raw) => splay_span[Finger(finger)] = raw;

        /// <summary>The abduction a full splay span means; default 15 degrees.</summary>
        /// <param name="finger">The finger.</param>
        /// <returns>Radians, 0..pi/2.</returns>
        public double GetAbductionRange(FrustaFinger finger) => abduction_range[Finger(finger)];

        /// <summary>Set a finger's abduction range (see <see cref="GetAbductionRange"/>).</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="radians">Radians, 0..pi/2.</param>
        public void SetAbductionRange(FrustaFinger finger, double radians) => abduction_range[Finger(finger)] = radians;
    }

    /// <remarks>Filled by <see cref="Device.GetStatus"/>. Reuse one instance per frame: nothing is
    /// allocated.</remarks>
    public unsafe partial struct FrustaDeviceStatus
    {
        // the binding's own word when the world closed the glove and native can no longer be asked
        internal void MarkClosed() => State = FrustaDeviceState.Closed;

        /// <summary>true when the glove reports the palm pose itself (a tracker); otherwise the palm
        /// comes from <see cref="Device.SetPalmPose"/>.</summary>
        public readonly bool HasPalmPose => has_palm_pose != 0;

        /// <summary>true when the disk refused the <c>record=</c> recording; the glove runs on.</summary>
        public readonly bool RecordingFailed => recording_failed != 0;

        static int Finger(FrustaFinger finger)
        {
            if ((uint)finger >= FrustaConstants.FingerCount) throw new ArgumentOutOfRangeException(nameof(finger));
            return (int)finger;
        }

        /// <summary>The last command's resistance on a finger, newtons.</summary>
        /// <param name="finger">The finger.</param>
        /// <returns>Newtons, &gt;= 0.</returns>
        public readonly double GetFingerResistance(FrustaFinger finger)
        {
            int i = Finger(finger);
            fixed (double* r = finger_resistance) return r[i];
        }

        /// <summary>The last command's force on a fingertip, newtons, palm frame.</summary>
        /// <param name="finger">The finger.</param>
        /// <returns>Newtons, palm frame (right-handed, as <see cref="FrustaHandDef"/>'s hand frame).</returns>
        public readonly Vector3d GetFingertipForce(FrustaFinger finger)
        {
            fixed (double* f = fingertip_force) return Vector3d.Read(f + Finger(finger) * 3);
        }
    }

    public unsafe partial struct FrustaDeviceInfo
    {
        /// <summary>A URI to open: <c>serial:PATH</c> for a serial port (use <c>opengloves:PATH</c>
        /// for an OpenGloves glove on it), <c>hid:VID:PID[:SERIAL]</c>, or <c>usb:</c> for a USB device
        /// (not opened directly). Decoded from UTF-8: allocates a string.</summary>
        public readonly string Uri
        {
            get
            {
                fixed (byte* p = uri)
                {
                    int n = 0;
                    while (n < FrustaConstants.DeviceUriCapacity && p[n] != 0) ++n;
                    return Encoding.UTF8.GetString(p, n);
                }
            }
        }
    }
}
