// SPDX-License-Identifier: MIT
// Blittable mirrors of every struct of frusta.h, member for member in declaration order
// (tests/abi/abi_layout_test.cpp freezes the offsets; the dotnet tests check these
// against that table and against frusta_struct_size). A C double[3] is a Vector3d, a
// double[4] quaternion a Quaterniond, other arrays are fixed buffers behind accessors.
// struct_size, internal_value and reserved fields are internal: the binding fills them.
// Defs come only from the native defaults (the Default properties), never from `new`.
using System;
using System.Runtime.InteropServices;
using System.Text;

namespace Frusta.Binding
{
    /// <summary>A rigid pose (<c>frusta_pose</c>): position in metres and a unit quaternion,
    /// in Frusta's right-handed frame. Convert with <see cref="CoordinateConversion"/>.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct FrustaPose
    {
        /// <summary>Position, metres.</summary>
        public Vector3d Position;
        /// <summary>Rotation, unit quaternion (x, y, z, w).</summary>
        public Quaterniond Rotation;

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

    /// <summary>A sphere (<c>frusta_sphere</c>): centre and radius in metres.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct FrustaSphere
    {
        /// <summary>Centre, metres.</summary>
        public Vector3d Center;
        /// <summary>Radius, metres (&gt;= 0).</summary>
        public double Radius;

        /// <summary>A sphere from its centre and radius.</summary>
        /// <param name="center">Metres.</param>
        /// <param name="radius">Metres, &gt;= 0.</param>
        public FrustaSphere(Vector3d center, double radius)
        {
            Center = center;
            Radius = radius;
        }
    }

    /// <summary>One frustum segment of a finger with its end balls (<c>frusta_segment</c>):
    /// the union of a ball of <see cref="ProximalRadius"/> at D, one of <see cref="DistalRadius"/>
    /// at E and the frustum between them.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct FrustaSegment
    {
        /// <summary>D, the proximal end, metres.</summary>
        public Vector3d Proximal;
        /// <summary>E, the distal end, metres.</summary>
        public Vector3d Distal;
        /// <summary>r1, the ball radius at D, metres.</summary>
        public double ProximalRadius;
        /// <summary>r2, the ball radius at E, metres.</summary>
        public double DistalRadius;
    }

    /// <summary>
    /// Creation parameters of a hand (<c>frusta_hand_def</c>). Get one from <see cref="Default"/>
    /// (a right hand, length 0.19 m, breadth 0.085 m), resize it with <see cref="SetSize"/>, then
    /// override single entries. Hand frame (right hand): origin at the wrist centre, +x towards
    /// the fingertips, +z out of the back of the hand, +y towards the thumb; a left hand is its
    /// mirror image through the x-z plane.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct FrustaHandDef
    {
        internal int StructSize;
        /// <summary>Which hand.</summary>
        public FrustaHandSide Side;
        /// <summary>Metres, wrist crease to middle fingertip (&gt; 0). Changing it alone does not
        /// refill the arrays: use <see cref="SetSize"/>.</summary>
        public double HandLength;
        /// <summary>Metres, across the metacarpal heads (&gt; 0). See <see cref="SetSize"/>.</summary>
        public double HandBreadth;
        fixed double segmentLength[FrustaConstants.FingerCount * FrustaConstants.SegmentsPerFinger];
        fixed double jointRadius[FrustaConstants.FingerCount * 4];
        fixed double basePosition[FrustaConstants.FingerCount * 3];
        fixed double baseRotation[FrustaConstants.FingerCount * 3];
        fixed double jointMin[FrustaConstants.HandJointCount];
        fixed double jointMax[FrustaConstants.HandJointCount];
        /// <summary>Metres, wrist to the metacarpal heads (&gt; 0).</summary>
        public double PalmLength;
        /// <summary>Metres (&gt; 0).</summary>
        public double PalmBreadth;
        /// <summary>Metres (&gt; 0); also the palm spheres' diameter.</summary>
        public double PalmThickness;
        internal int InternalValue;
        internal int Reserved0;

        /// <summary>The library's default hand (<c>frusta_default_hand_def</c>): a right hand of
        /// 50th-percentile adult size. Thread: any.</summary>
        public static FrustaHandDef Default
        {
            get
            {
                FrustaLibrary.EnsureCompatible();
                return Native.frusta_default_hand_def();
            }
        }

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
        public double GetSegmentLength(FrustaFinger finger, int segment) => segmentLength[Index(finger, segment, 3)];

        /// <summary>Override one segment length (see <see cref="GetSegmentLength"/>).</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="segment">0..2, proximal to distal.</param>
        /// <param name="metres">The length, metres.</param>
        public void SetSegmentLength(FrustaFinger finger, int segment, double metres) =>
            segmentLength[Index(finger, segment, 3)] = metres;

        /// <summary>Ball radius at the first, second, third joint (0..2) or the tip hemisphere (3), metres.</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="ball">0..3.</param>
        /// <returns>Metres.</returns>
        public double GetJointRadius(FrustaFinger finger, int ball) => jointRadius[Index(finger, ball, 4)];

        /// <summary>Override one ball radius (see <see cref="GetJointRadius"/>).</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="ball">0..3.</param>
        /// <param name="metres">The radius, metres.</param>
        public void SetJointRadius(FrustaFinger finger, int ball, double metres) =>
            jointRadius[Index(finger, ball, 4)] = metres;

        /// <summary>First joint centre of a finger in the hand frame, metres.</summary>
        /// <param name="finger">The finger.</param>
        /// <returns>Metres, hand frame.</returns>
        public Vector3d GetBasePosition(FrustaFinger finger)
        {
            int i = Index(finger, 0, 3);
            return new Vector3d(basePosition[i], basePosition[i + 1], basePosition[i + 2]);
        }

        /// <summary>Override a finger's first joint centre (see <see cref="GetBasePosition"/>).</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="metres">Metres, hand frame.</param>
        public void SetBasePosition(FrustaFinger finger, Vector3d metres)
        {
            int i = Index(finger, 0, 3);
            basePosition[i] = metres.X;
            basePosition[i + 1] = metres.Y;
            basePosition[i + 2] = metres.Z;
        }

        /// <summary>The x-y-z rotation of a finger's rest frame, radians.</summary>
        /// <param name="finger">The finger.</param>
        /// <returns>Radians about x, y, z.</returns>
        public Vector3d GetBaseRotation(FrustaFinger finger)
        {
            int i = Index(finger, 0, 3);
            return new Vector3d(baseRotation[i], baseRotation[i + 1], baseRotation[i + 2]);
        }

        /// <summary>Override a finger's rest frame rotation (see <see cref="GetBaseRotation"/>).</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="radians">Radians about x, y, z.</param>
        public void SetBaseRotation(FrustaFinger finger, Vector3d radians)
        {
            int i = Index(finger, 0, 3);
            baseRotation[i] = radians.X;
            baseRotation[i + 1] = radians.Y;
            baseRotation[i + 2] = radians.Z;
        }

        /// <summary>Lower limit of a joint angle, radians.</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="joint">0 abduction, 1..3 flexion of the first, second, third joint.</param>
        /// <returns>Radians.</returns>
        public double GetJointMin(FrustaFinger finger, int joint) => jointMin[Index(finger, joint, 4)];

        /// <summary>Override a joint's lower limit.</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="joint">0 abduction, 1..3 flexion.</param>
        /// <param name="radians">Radians.</param>
        public void SetJointMin(FrustaFinger finger, int joint, double radians) => jointMin[Index(finger, joint, 4)] = radians;

        /// <summary>Upper limit of a joint angle, radians.</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="joint">0 abduction, 1..3 flexion of the first, second, third joint.</param>
        /// <returns>Radians.</returns>
        public double GetJointMax(FrustaFinger finger, int joint) => jointMax[Index(finger, joint, 4)];

        /// <summary>Override a joint's upper limit.</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="joint">0 abduction, 1..3 flexion.</param>
        /// <param name="radians">Radians.</param>
        public void SetJointMax(FrustaFinger finger, int joint, double radians) => jointMax[Index(finger, joint, 4)] = radians;
    }

    /// <summary>Everything one sphere/segment query knows (<c>frusta_contact_query</c>);
    /// from <see cref="Geometry.QueryContact"/>.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct FrustaContactQuery
    {
        internal int StructSize;
        /// <summary>The feature nearest the sphere (exact reference).</summary>
        public FrustaFeature Feature;
        int patentContact;
        int contact;
        /// <summary>Metres, exact signed gap between the sphere and the segment solid;
        /// negative is penetration.</summary>
        public double Distance;
        /// <summary>Metres, nearest point on the segment solid's surface.</summary>
        public Vector3d HandPoint;
        /// <summary>Metres, the sphere's surface point nearest the hand.</summary>
        public Vector3d ObjectPoint;
        /// <summary>Unit, from the sphere's centre towards the hand.</summary>
        public Vector3d Normal;
        /// <summary>k of seed eq. 4: 0 at E, 1 at D (0 if the segment's length is 0).</summary>
        public double Axial;

        /// <summary>true if seed eq. 5 reports contact (for comparison only).</summary>
        public readonly bool PatentContact => patentContact != 0;

        /// <summary>true if the engine's conservative test reports contact.</summary>
        public readonly bool Contact => contact != 0;
    }

    /// <summary>A constraint value g &gt;= 0 (non-penetrating) with its analytic gradient
    /// (<c>frusta_constraint</c>); from <see cref="Geometry.EvaluateConstraint"/>.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct FrustaConstraint
    {
        internal int StructSize;
        /// <summary>The feature whose constraint this is.</summary>
        public FrustaFeature Feature;
        /// <summary>Metres or metres squared, by form.</summary>
        public double Value;
        /// <summary>dg/dD.</summary>
        public Vector3d GradProximal;
        /// <summary>dg/dE.</summary>
        public Vector3d GradDistal;
        /// <summary>dg/dO, the sphere's centre.</summary>
        public Vector3d GradCenter;
    }

    /// <summary>Bake parameters (<c>frusta_bake_def</c>); from <see cref="Default"/>.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct FrustaBakeDef
    {
        internal int StructSize;
        /// <summary>Children per node, 2..16; default 4.</summary>
        public int Branching;
        /// <summary>Metres, bound on both error figures; default 0.001.</summary>
        public double TargetError;
        /// <summary>Leaf budget, 1..2^24; default 200000.</summary>
        public long MaxLeaves;
        /// <summary>1..40; a deeper tree is refused; default 40.</summary>
        public int MaxDepth;
        internal int Reserved0;
        /// <summary>Points behind each error figure, 1e3..1e8; default 100000.</summary>
        public long ErrorSamples;
        /// <summary>Sampling seed: same mesh and seed, same tree; default 1.</summary>
        public ulong Seed;
        internal int InternalValue;
        internal int Reserved1;

        /// <summary>The library's defaults (<c>frusta_default_bake_def</c>). Thread: any.</summary>
        public static FrustaBakeDef Default
        {
            get
            {
                FrustaLibrary.EnsureCompatible();
                return Native.frusta_default_bake_def();
            }
        }
    }

    /// <summary>What a tree holds and how well it fits the mesh it was baked from
    /// (<c>frusta_sphere_tree_info</c>); <see cref="SphereTree.Info"/>.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct FrustaSphereTreeInfo
    {
        internal int StructSize;
        /// <summary>Children per node.</summary>
        public int Branching;
        /// <summary>Levels below the root.</summary>
        public int Depth;
        /// <summary>Leaf spheres.</summary>
        public int LeafCount;
        /// <summary>All nodes, leaves included.</summary>
        public int NodeCount;
        /// <summary>Triangles of the baked mesh.</summary>
        public int TriangleCount;
        /// <summary>Metres, lower corner of the leaves' bounds, object frame.</summary>
        public Vector3d BoundsMin;
        /// <summary>Metres, upper corner of the leaves' bounds, object frame.</summary>
        public Vector3d BoundsMax;
        /// <summary>Metres, the target the tree was baked for.</summary>
        public double TargetError;
        /// <summary>Metres: largest distance from the mesh surface to the leaves.</summary>
        public double UncoveredError;
        /// <summary>Metres: largest height of the leaves above the mesh surface.</summary>
        public double ProtrudingError;
        /// <summary>Seconds the bake took.</summary>
        public double BakeSeconds;
        /// <summary>Points behind each error figure.</summary>
        public long ErrorSamples;
        int targetMet;
        internal int Reserved0;

        /// <summary>true if both error figures are within <see cref="TargetError"/>.</summary>
        public readonly bool TargetMet => targetMet != 0;
    }

    /// <summary>One node a tree query found (<c>frusta_tree_hit</c>).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct FrustaTreeHit
    {
        /// <summary>The node's index in the tree.</summary>
        public int Node;
        /// <summary>The leaf's stable number, or -1 for an inner node standing in for its subtree.</summary>
        public int Leaf;
        /// <summary>The node's sphere in the world frame (through the pose given to the query).</summary>
        public FrustaSphere Sphere;
    }

    /// <summary>World creation parameters (<c>frusta_world_def</c>); from <see cref="Default"/>.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct FrustaWorldDef
    {
        internal int StructSize;
        /// <summary>Object slots, 1..65535; default 64.</summary>
        public int MaxObjects;
        /// <summary>The own thread's rate and the dynamic objects' time step 1/RateHz, Hz,
        /// 1..100000; default 1000.</summary>
        public double RateHz;
        /// <summary>Microseconds the own thread spins before each tick for an on-time wake,
        /// 0..one period; default 200.</summary>
        public double SpinUs;
        /// <summary>m/s² on dynamic objects, world frame; default zero (off).</summary>
        public Vector3d Gravity;
        /// <summary>Metres: detection margin and the most any hand point moves per sub-step,
        /// 1e-5..0.1 and below the smallest finger radius; default 0.002.</summary>
        public double PredictionMargin;
        /// <summary>Metres: tree nodes no larger stand in for their leaves (0: leaves); default 0.</summary>
        public double NodeRadius;
        /// <summary>Re-linearisations per solver stage, 1..100; default 2.</summary>
        public int MaxIterations;
        /// <summary>Sub-steps per step, 1..1024; default 64.</summary>
        public int MaxSubsteps;
        /// <summary>Contacts kept per hand per step, 0..65536; default 256.</summary>
        public int MaxContactsPerHand;
        /// <summary>Object commands queued between steps, 1..2^20 (rounded up to a power of two); default 256.</summary>
        public int CommandCapacity;
        /// <summary>Newtons per finger; default 10. Every device output is scaled down to fit, never turned.</summary>
        public double MaxFingertipForce;
        /// <summary>Newtons per finger; default 10.</summary>
        public double MaxFingerResistance;
        /// <summary>Newton-metres per joint; default 0.5.</summary>
        public double MaxJointTorque;
        /// <summary>Newtons; default 20.</summary>
        public double MaxPalmForce;
        /// <summary>Newton-metres; default 1.</summary>
        public double MaxPalmTorque;
        internal int InternalValue;
        internal int Reserved0;

        /// <summary>The library's defaults (<c>frusta_default_world_def</c>). Thread: any.</summary>
        public static FrustaWorldDef Default
        {
            get
            {
                FrustaLibrary.EnsureCompatible();
                return Native.frusta_default_world_def();
            }
        }
    }

    /// <summary>An object as it is added (<c>frusta_object_def</c>); from <see cref="Default"/>.
    /// Kinematic objects stay where the host puts them (a host with its own rigid-body engine
    /// applies the reaction wrench itself); dynamic ones the world integrates.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct FrustaObjectDef
    {
        internal int StructSize;
        int dynamic;
        /// <summary>The object frame in the world (its origin is the centre of mass); default identity.</summary>
        public FrustaPose Pose;
        /// <summary>Contact stiffness, diagonal in the object frame, N/m, 0..1e9; default 400.</summary>
        public Vector3d Stiffness;
        /// <summary>Friction coefficient mu, 0..100; default 0.6.</summary>
        public double Friction;
        /// <summary>The stick spring, N/m, 0..1e9; default 1e4.</summary>
        public double TangentialStiffness;
        /// <summary>On how fast a contact sinks in, N s/m, 0..1e9; default 0.</summary>
        public double NormalDamping;
        /// <summary>On how fast a sticking contact slides, N s/m, 0..1e9; default 0.</summary>
        public double TangentialDamping;
        /// <summary>kg, &gt; 0; default 0.1.</summary>
        public double Mass;
        /// <summary>Principal moments in the object frame, kg m², &gt; 0; default 4e-5.</summary>
        public Vector3d Inertia;
        /// <summary>m/s, world; |each| &lt;= 100; default 0.</summary>
        public Vector3d LinearVelocity;
        /// <summary>rad/s, world; |each| &lt;= 1000; default 0.</summary>
        public Vector3d AngularVelocity;
        /// <summary>1/s, 0..1000; default 0.</summary>
        public double LinearDamping;
        /// <summary>1/s, 0..1000; default 0.</summary>
        public double AngularDamping;
        internal int InternalValue;
        internal int Reserved0;

        /// <summary>true: the world moves the object under the hands' reactions and gravity;
        /// false (default): kinematic.</summary>
        public bool Dynamic
        {
            readonly get => dynamic != 0;
            set => dynamic = value ? 1 : 0;
        }

        /// <summary>The library's defaults (<c>frusta_default_object_def</c>). Thread: any.</summary>
        public static FrustaObjectDef Default
        {
            get
            {
                FrustaLibrary.EnsureCompatible();
                return Native.frusta_default_object_def();
            }
        }
    }

    /// <summary>The latched step's summary (<c>frusta_world_state</c>), filled by
    /// <see cref="World.Read"/>. Reuse one instance per frame: nothing is allocated.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct FrustaWorldState
    {
        internal int StructSize;
        /// <summary>Hands in the world.</summary>
        public int HandCount;
        /// <summary>Steps so far; 0 before the first.</summary>
        public ulong Step;
        /// <summary>Seconds: steps times 1/RateHz.</summary>
        public double Time;
        /// <summary>This step's duration, microseconds.</summary>
        public double StepUs;
        /// <summary>Median step duration so far, microseconds.</summary>
        public double StepUsP50;
        /// <summary>99th percentile step duration so far, microseconds.</summary>
        public double StepUsP99;
        /// <summary>Longest step so far, microseconds.</summary>
        public double StepUsMax;
        /// <summary>Own thread's median lateness of a wake, microseconds.</summary>
        public double WakeLateUsP50;
        /// <summary>Own thread's 99th percentile lateness, microseconds.</summary>
        public double WakeLateUsP99;
        /// <summary>Own thread's largest lateness, microseconds.</summary>
        public double WakeLateUsMax;
        /// <summary>Own thread: steps per second since start, Hz; 0 if it never ran.</summary>
        public double AchievedRateHz;
        /// <summary>Ticks the own thread lost to late steps.</summary>
        public long Overruns;
        /// <summary>Haptic inputs the solver refused.</summary>
        public long RejectedInputs;
        /// <summary>Objects present at the step.</summary>
        public int ObjectCount;
        internal int Reserved0;
    }

    /// <summary>
    /// One hand as the latched step left it (<c>frusta_world_hand</c>), world frame; filled by
    /// <see cref="World.GetHand"/>. The graphic hand is the displayed one (it never sinks into
    /// objects); the haptic hand is the input the step used. Device outputs are clamped to the
    /// world's limits. Reuse one instance per frame: nothing is allocated.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct FrustaWorldHand
    {
        internal int StructSize;
        int solved;
        /// <summary>The displayed hand's palm pose, metres, world frame.</summary>
        public FrustaPose GraphicPalm;
        fixed double graphicAngles[FrustaConstants.HandJointCount];
        /// <summary>The input palm pose the step used, metres, world frame.</summary>
        public FrustaPose HapticPalm;
        fixed double hapticAngles[FrustaConstants.HandJointCount];
        /// <summary>All contacts, even beyond MaxContactsPerHand.</summary>
        public int ContactCount;
        /// <summary>Contacts whose haptic point lies inside an object.</summary>
        public int Pressing;
        /// <summary>Pressing contacts sliding (friction at mu |F|).</summary>
        public int Slipping;
        /// <summary>Solver sub-steps this step.</summary>
        public int Substeps;
        int lagging;
        int infeasible;
        fixed double fingertipForce[FrustaConstants.FingerCount * 3];
        fixed double fingerResistance[FrustaConstants.FingerCount];
        fixed double jointTorque[FrustaConstants.HandJointCount];
        /// <summary>Force on the palm, newtons, world frame.</summary>
        public Vector3d PalmForce;
        /// <summary>Torque on the palm about the haptic palm origin, newton-metres, world frame.</summary>
        public Vector3d PalmTorque;

        /// <summary>false until the hand's first valid input.</summary>
        public readonly bool Solved => solved != 0;

        /// <summary>true when the sub-step cap stopped the hand short of its input this step.</summary>
        public readonly bool Lagging => lagging != 0;

        /// <summary>true when a contact QP had no point meeting every row it was given this
        /// step (nearly parallel or contradictory constraints): the hand stayed at its last safe
        /// estimate, short of its input.</summary>
        public readonly bool Infeasible => infeasible != 0;

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
        public double GetGraphicAngle(int joint) => graphicAngles[Joint(joint)];

        /// <summary>One input joint angle the step used, radians.</summary>
        /// <param name="joint">finger * 4 + k; k 0 abduction, 1..3 flexion.</param>
        /// <returns>Radians.</returns>
        public double GetHapticAngle(int joint) => hapticAngles[Joint(joint)];

        /// <summary>Copy the 20 displayed joint angles (radians, finger-major) without allocating.</summary>
        /// <param name="destination">At least 20 doubles.</param>
        public void CopyGraphicAngles(Span<double> destination)
        {
            if (destination.Length < FrustaConstants.HandJointCount) throw new ArgumentException("needs 20 doubles", nameof(destination));
            for (int j = 0; j < FrustaConstants.HandJointCount; ++j) destination[j] = graphicAngles[j];
        }

        /// <summary>Copy the 20 input joint angles (radians, finger-major) without allocating.</summary>
        /// <param name="destination">At least 20 doubles.</param>
        public void CopyHapticAngles(Span<double> destination)
        {
            if (destination.Length < FrustaConstants.HandJointCount) throw new ArgumentException("needs 20 doubles", nameof(destination));
            for (int j = 0; j < FrustaConstants.HandJointCount; ++j) destination[j] = hapticAngles[j];
        }

        /// <summary>The force on a finger's distal segment, newtons, world frame.</summary>
        /// <param name="finger">The finger.</param>
        /// <returns>Newtons.</returns>
        public Vector3d GetFingertipForce(FrustaFinger finger)
        {
            int i = Finger(finger) * 3;
            return new Vector3d(fingertipForce[i], fingertipForce[i + 1], fingertipForce[i + 2]);
        }

        /// <summary>|force| on a whole finger, newtons: what a brake glove renders.</summary>
        /// <param name="finger">The finger.</param>
        /// <returns>Newtons, &gt;= 0.</returns>
        public double GetFingerResistance(FrustaFinger finger) => fingerResistance[Finger(finger)];

        /// <summary>J^T F at one joint, newton-metres.</summary>
        /// <param name="joint">finger * 4 + k; k 0 abduction, 1..3 flexion.</param>
        /// <returns>Newton-metres.</returns>
        public double GetJointTorque(int joint) => jointTorque[Joint(joint)];
    }

    /// <summary>One contact of a hand and the force on the hand there (<c>frusta_world_contact</c>),
    /// world frame; filled by <see cref="World.GetContacts(int, Span{FrustaWorldContact})"/>.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct FrustaWorldContact
    {
        /// <summary>The object touched.</summary>
        public FrustaObjectId Object;
        /// <summary>finger * 3 + segment, or 15 (<see cref="FrustaConstants.PalmBody"/>) for the palm.</summary>
        public int Body;
        /// <summary>The object's leaf, or -1 for an inner node.</summary>
        public int Leaf;
        int slipping;
        internal int Reserved0;
        /// <summary>Metres, exact gap (&gt;= -tolerance).</summary>
        public double Distance;
        /// <summary>P_ig, the contact point on the displayed hand, metres.</summary>
        public Vector3d GraphicPoint;
        /// <summary>P_ih, the same material point on the haptic hand, metres.</summary>
        public Vector3d HapticPoint;
        /// <summary>Unit, from the object towards the hand.</summary>
        public Vector3d Normal;
        /// <summary>Normal force on the hand, newtons.</summary>
        public Vector3d NormalForce;
        /// <summary>Friction force on the hand, newtons.</summary>
        public Vector3d Friction;

        /// <summary>true when friction is at mu |F| (sliding).</summary>
        public readonly bool Slipping => slipping != 0;

        /// <summary>true when the contact is on the palm.</summary>
        public readonly bool IsPalm => Body == FrustaConstants.PalmBody;

        /// <summary>The finger of a finger contact (meaningless for the palm: see <see cref="IsPalm"/>).</summary>
        public readonly FrustaFinger Finger => (FrustaFinger)(Body / FrustaConstants.SegmentsPerFinger);

        /// <summary>The segment of a finger contact, 0..2 proximal to distal.</summary>
        public readonly int Segment => Body % FrustaConstants.SegmentsPerFinger;
    }

    /// <summary>One object as the latched step left it (<c>frusta_object_state</c>); filled by
    /// <see cref="World.GetObject"/>.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct FrustaObjectState
    {
        internal int StructSize;
        int dynamic;
        /// <summary>Where the hands met it this step, world frame.</summary>
        public FrustaPose Pose;
        /// <summary>m/s, world.</summary>
        public Vector3d LinearVelocity;
        /// <summary>rad/s, world.</summary>
        public Vector3d AngularVelocity;
        /// <summary>From every hand, newtons, world: what a host engine applies to its body.</summary>
        public Vector3d ReactionForce;
        /// <summary>About the pose position, newton-metres, world.</summary>
        public Vector3d ReactionTorque;

        /// <summary>true when the world integrates this object.</summary>
        public readonly bool Dynamic => dynamic != 0;
    }

    /// <summary>
    /// How a glove is opened (<c>frusta_device_def</c>, 720 bytes); from <see cref="Default"/>, then
    /// edited, then passed to <see cref="World.OpenDevice(string, in FrustaDeviceDef)"/>. Times are
    /// seconds, forces newtons, torques newton-metres. The OpenGloves calibration (raw readings to
    /// radians, newtons to brake units) is read only by <c>opengloves:</c> gloves; gloves that speak
    /// Frusta's binary profile send radians.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct FrustaDeviceDef
    {
        const int Flexions = FrustaConstants.FlexionJointsPerFinger;

        internal int StructSize;
        /// <summary>The world's hand the glove drives (the index from <see cref="World.AddHand"/>); default 0.</summary>
        public int Hand;
        /// <summary>Commands per second, Hz; 0: the world's rate, never above what the glove takes
        /// (100 for OpenGloves); default 0.</summary>
        public double OutputRateHz;
        /// <summary>Seconds without a valid sample before the output drops to zero, 0.001..10; default 0.05.</summary>
        public double WatchdogS;
        /// <summary>Seconds without a world step before the output drops to zero, 0.001..10; default 0.05.</summary>
        public double EngineTimeoutS;
        /// <summary>Seconds without a <see cref="World.Read"/> before the output drops to zero, 0.001..60,
        /// or 0 (not watched); default 0.25.</summary>
        public double HostTimeoutS;
        /// <summary>Seconds between attempts to reopen a disconnected glove, 0.001..60; default 0.2.</summary>
        public double ReconnectIntervalS;
        /// <summary>Newtons per second a resistance or fingertip force may rise (falls are immediate); default 500.</summary>
        public double MaxForceRate;
        /// <summary>Newton-metres per second a joint torque may rise; default 25.</summary>
        public double MaxTorqueRate;
        /// <summary>Newtons per finger; the glove's own limit if lower; default 10.</summary>
        public double MaxFingerResistance;
        /// <summary>Newtons per fingertip; default 10.</summary>
        public double MaxFingertipForce;
        /// <summary>Newton-metres per joint; default 0.5.</summary>
        public double MaxJointTorque;
        fixed double curlOpen[FrustaConstants.FingerCount * Flexions];
        fixed double curlClosed[FrustaConstants.FingerCount * Flexions];
        fixed double flexionOpen[FrustaConstants.FingerCount * Flexions];
        fixed double flexionClosed[FrustaConstants.FingerCount * Flexions];
        fixed double splayCenter[FrustaConstants.FingerCount];
        fixed double splaySpan[FrustaConstants.FingerCount];
        fixed double abductionRange[FrustaConstants.FingerCount];
        /// <summary>Newtons that set a brake to <see cref="BrakeUnits"/>, (0, 1e6]; default 10.</summary>
        public double BrakeFullScale;
        /// <summary>The glove's full brake in its own units, 1..65535; default 1000.</summary>
        public double BrakeUnits;
        /// <summary>The largest raw reading, 1..1e9; default 4095.</summary>
        public double AnalogMax;
        internal int InternalValue;
        internal int Reserved0;

        /// <summary>The library's defaults (<c>frusta_default_device_def</c>): hand 0, the world's
        /// rate, the timeouts and limits above, and a calibration from a straight hand (raw 0, 0 rad)
        /// to a fist (raw 4095). Thread: any.</summary>
        public static FrustaDeviceDef Default
        {
            get
            {
                FrustaLibrary.EnsureCompatible();
                return Native.frusta_default_device_def();
            }
        }

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
        public double GetCurlOpen(FrustaFinger finger, int joint) => curlOpen[Flexion(finger, joint)];

        /// <summary>Set the raw reading of a straight flexion joint (see <see cref="GetCurlOpen"/>).</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="joint">0..2.</param>
        /// <param name="raw">Raw units, 0..<see cref="AnalogMax"/>; at least 1 from the closed reading.</param>
        public void SetCurlOpen(FrustaFinger finger, int joint, double raw) => curlOpen[Flexion(finger, joint)] = raw;

        /// <summary>The raw reading of a flexion joint in a fist; default 4095.</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="joint">0..2: the first, second, third flexion joint.</param>
        /// <returns>Raw units, 0..<see cref="AnalogMax"/>.</returns>
        public double GetCurlClosed(FrustaFinger finger, int joint) => curlClosed[Flexion(finger, joint)];

        /// <summary>Set the raw reading of a flexion joint in a fist (see <see cref="GetCurlClosed"/>).</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="joint">0..2.</param>
        /// <param name="raw">Raw units, 0..<see cref="AnalogMax"/>.</param>
        public void SetCurlClosed(FrustaFinger finger, int joint, double raw) => curlClosed[Flexion(finger, joint)] = raw;

        /// <summary>The flexion angle at the open reading; default 0.</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="joint">0..2: the first, second, third flexion joint.</param>
        /// <returns>Radians, |angle| &lt;= pi.</returns>
        public double GetFlexionOpen(FrustaFinger finger, int joint) => flexionOpen[Flexion(finger, joint)];

        /// <summary>Set the flexion angle at the open reading (see <see cref="GetFlexionOpen"/>).</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="joint">0..2.</param>
        /// <param name="radians">Radians, |angle| &lt;= pi.</param>
        public void SetFlexionOpen(FrustaFinger finger, int joint, double radians) => flexionOpen[Flexion(finger, joint)] = radians;

        /// <summary>The flexion angle at the closed reading; default a fist (80, 90, 70 degrees; the
        /// thumb 45, 40, 60).</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="joint">0..2: the first, second, third flexion joint.</param>
        /// <returns>Radians, |angle| &lt;= pi.</returns>
        public double GetFlexionClosed(FrustaFinger finger, int joint) => flexionClosed[Flexion(finger, joint)];

        /// <summary>Set the flexion angle at the closed reading (see <see cref="GetFlexionClosed"/>).</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="joint">0..2.</param>
        /// <param name="radians">Radians, |angle| &lt;= pi.</param>
        public void SetFlexionClosed(FrustaFinger finger, int joint, double radians) => flexionClosed[Flexion(finger, joint)] = radians;

        /// <summary>The raw splay reading of a straight finger; default 2048.</summary>
        /// <param name="finger">The finger.</param>
        /// <returns>Raw units, 0..<see cref="AnalogMax"/>.</returns>
        public double GetSplayCenter(FrustaFinger finger) => splayCenter[Finger(finger)];

        /// <summary>Set the raw splay reading of a straight finger (see <see cref="GetSplayCenter"/>).</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="raw">Raw units, 0..<see cref="AnalogMax"/>.</param>
        public void SetSplayCenter(FrustaFinger finger, double raw) => splayCenter[Finger(finger)] = raw;

        /// <summary>The raw splay change that means <see cref="GetAbductionRange"/>; default 2047.</summary>
        /// <param name="finger">The finger.</param>
        /// <returns>Raw units, 1..<see cref="AnalogMax"/>.</returns>
        public double GetSplaySpan(FrustaFinger finger) => splaySpan[Finger(finger)];

        /// <summary>Set a finger's raw splay span (see <see cref="GetSplaySpan"/>).</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="raw">Raw units, 1..<see cref="AnalogMax"/>.</param>
        public void SetSplaySpan(FrustaFinger finger, double raw) => splaySpan[Finger(finger)] = raw;

        /// <summary>The abduction a full splay span means; default 15 degrees.</summary>
        /// <param name="finger">The finger.</param>
        /// <returns>Radians, 0..pi/2.</returns>
        public double GetAbductionRange(FrustaFinger finger) => abductionRange[Finger(finger)];

        /// <summary>Set a finger's abduction range (see <see cref="GetAbductionRange"/>).</summary>
        /// <param name="finger">The finger.</param>
        /// <param name="radians">Radians, 0..pi/2.</param>
        public void SetAbductionRange(FrustaFinger finger, double radians) => abductionRange[Finger(finger)] = radians;
    }

    /// <summary>
    /// A glove's state and counters (<c>frusta_device_status</c>, 320 bytes), filled by
    /// <see cref="Device.GetStatus"/>. Read-only; reuse one instance per frame: nothing is allocated.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct FrustaDeviceStatus
    {
        internal int StructSize;
        FrustaDeviceState state;
        FrustaWatchdogReason watchdog;
        FrustaDeviceOutput outputs;
        int fingers;
        int hasPalmPose;
        int protocolVersion;
        int recordingFailed;
        long framesOk;
        long framesCorrupt;
        long framesTruncated;
        long framesOutOfRange;
        long samplesRejected;
        long commandsSent;
        long commandsDropped;
        long reconnects;
        long disconnects;
        long watchdogTrips;
        double inputRateHz;
        double outputRateHz;
        double lastSampleAgeS;
        double maxFingerResistance;
        double maxFingertipForce;
        double maxJointTorque;
        fixed double fingerResistance[FrustaConstants.FingerCount];
        fixed double fingertipForce[FrustaConstants.FingerCount * 3];

        /// <summary>Connected, Disconnected (retrying) or Closed.</summary>
        public readonly FrustaDeviceState State => state;

        // the binding's own word when the world closed the glove and native can no longer be asked
        internal void MarkClosed() => state = FrustaDeviceState.Closed;

        /// <summary>Why the output is held at zero now; <see cref="FrustaWatchdogReason.None"/> when it is not.</summary>
        public readonly FrustaWatchdogReason Watchdog => watchdog;

        /// <summary>The outputs the glove renders (as it announced them).</summary>
        public readonly FrustaDeviceOutput Outputs => outputs;

        /// <summary>The glove's fingers, thumb first (0..5).</summary>
        public readonly int Fingers => fingers;

        /// <summary>true when the glove reports the palm pose itself (a tracker); otherwise the palm
        /// comes from <see cref="Device.SetPalmPose"/>.</summary>
        public readonly bool HasPalmPose => hasPalmPose != 0;

        /// <summary>The protocol version the glove announced (0: none).</summary>
        public readonly int ProtocolVersion => protocolVersion;

        /// <summary>true when the disk refused the <c>record=</c> recording; the glove runs on.</summary>
        public readonly bool RecordingFailed => recordingFailed != 0;

        /// <summary>Samples taken since open.</summary>
        public readonly long FramesOk => framesOk;

        /// <summary>Frames dropped for a bad checksum or syntax.</summary>
        public readonly long FramesCorrupt => framesCorrupt;

        /// <summary>Frames dropped because they were cut short.</summary>
        public readonly long FramesTruncated => framesTruncated;

        /// <summary>Well-formed frames dropped for impossible values.</summary>
        public readonly long FramesOutOfRange => framesOutOfRange;

        /// <summary>Decoded samples dropped: NaN, or beyond any joint's range.</summary>
        public readonly long SamplesRejected => samplesRejected;

        /// <summary>Commands written to the glove.</summary>
        public readonly long CommandsSent => commandsSent;

        /// <summary>Commands dropped because the glove did not drain its input in time.</summary>
        public readonly long CommandsDropped => commandsDropped;

        /// <summary>Times the glove came back after a disconnect.</summary>
        public readonly long Reconnects => reconnects;

        /// <summary>Times the glove went away.</summary>
        public readonly long Disconnects => disconnects;

        /// <summary>Times the output was forced to zero (each entry into a watchdog reason).</summary>
        public readonly long WatchdogTrips => watchdogTrips;

        /// <summary>The measured sample rate, Hz (the inverse of a running mean interval).</summary>
        public readonly double InputRateHz => inputRateHz;

        /// <summary>The command rate in use, Hz.</summary>
        public readonly double OutputRateHz => outputRateHz;

        /// <summary>Seconds since the newest valid sample; -1 before the first.</summary>
        public readonly double LastSampleAgeS => lastSampleAgeS;

        /// <summary>The finger resistance limit in use, newtons (the lower of the def's and the glove's).</summary>
        public readonly double MaxFingerResistance => maxFingerResistance;

        /// <summary>The fingertip force limit in use, newtons.</summary>
        public readonly double MaxFingertipForce => maxFingertipForce;

        /// <summary>The joint torque limit in use, newton-metres.</summary>
        public readonly double MaxJointTorque => maxJointTorque;

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
            fixed (double* r = fingerResistance) return r[i];
        }

        /// <summary>The last command's force on a fingertip, newtons, palm frame.</summary>
        /// <param name="finger">The finger.</param>
        /// <returns>Newtons, palm frame (right-handed, as <see cref="FrustaHandDef"/>'s hand frame).</returns>
        public readonly Vector3d GetFingertipForce(FrustaFinger finger)
        {
            int i = Finger(finger) * 3;
            fixed (double* f = fingertipForce) return new Vector3d(f[i], f[i + 1], f[i + 2]);
        }
    }

    /// <summary>One device <see cref="Device.Enumerate()"/> found (<c>frusta_device_info</c>, 272 bytes).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public unsafe struct FrustaDeviceInfo
    {
        internal int StructSize;
        FrustaDeviceKind kind;
        int vendorId;
        int productId;
        fixed byte uri[FrustaConstants.DeviceUriCapacity];

        /// <summary>A serial port, a HID device or a USB device.</summary>
        public readonly FrustaDeviceKind Kind => kind;

        /// <summary>The USB/HID vendor id; -1 when unknown.</summary>
        public readonly int VendorId => vendorId;

        /// <summary>The USB/HID product id; -1 when unknown.</summary>
        public readonly int ProductId => productId;

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
