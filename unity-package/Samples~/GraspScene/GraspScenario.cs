// SPDX-License-Identifier: MIT
// The Grasp Scene's scenario in plain C# (no UnityEngine: the dotnet tests compile this file
// and run it as the scene does): a table with objects baked by samples/objects, a marble on a
// stand, and a right hand played from the bundled glove recording (samples/data/demo_glove.frrec)
// on the world's own step clock. The hand pinches the marble, lifts and carries it 15 cm up and
// 11 cm along, and opens: the marble falls onto the table and rests there.
//
// The world does all of it: the table, the stand and the other fixed objects are kinematic
// objects of the world, and the marble is dynamic from the start, resting on its stand by the
// world's contact between objects (it sleeps once still); the pinch's grasp holds it while the
// hand carries it (FrustaObjectState.Held), and let go it falls onto the table and comes to rest
// there by the same contact. The host only feeds the recording and, when looping, puts the
// marble back on its stand.
using System;
using System.Collections.Generic;
using Frusta.Binding;

namespace Frusta.Samples
{
    /// <summary>How the scene draws an object (its tree is what the hands touch).</summary>
    public enum GraspShape
    {
        /// <summary>A box; <see cref="GraspSceneObject.Size"/> is its extents along its axes.</summary>
        Box,
        /// <summary>A sphere; <see cref="GraspSceneObject.Size"/>.X is its diameter.</summary>
        Sphere,
        /// <summary>An octahedron; <see cref="GraspSceneObject.Size"/>.X is its centre-to-vertex radius.</summary>
        Octahedron,
    }

    /// <summary>One object of the scene, in the recording's frame (z up, metres).</summary>
    public sealed class GraspSceneObject
    {
        /// <summary>The object's name.</summary>
        public string Name { get; set; }
        /// <summary>Its baked tree: a .frtree of samples/objects, by name.</summary>
        public string Tree { get; set; }
        /// <summary>How it is drawn.</summary>
        public GraspShape Shape { get; set; }
        /// <summary>Display size, metres (see <see cref="GraspShape"/>).</summary>
        public Vector3d Size { get; set; }
        /// <summary>Where it starts, recording frame.</summary>
        public FrustaPose Pose { get; set; }
        /// <summary>Dynamic: moved by the world (gravity, the hands, the objects it rests on) and put
        /// back where it started when the scene loops; else kinematic, where it is put.</summary>
        public bool Movable { get; set; }
        /// <summary>Kilograms.</summary>
        public double Mass { get; set; } = 0.1;
        /// <summary>Coulomb friction coefficient of the hand on it.</summary>
        public double Friction { get; set; } = 0.6;
        /// <summary>N s/m (see frusta_object_def.normal_damping).</summary>
        public double NormalDamping { get; set; }
        /// <summary>N s/m (see frusta_object_def.tangential_damping).</summary>
        public double TangentialDamping { get; set; }
        /// <summary>A movable object's height from its centre to its bottom, metres: its centre rests
        /// this high over what it lies on.</summary>
        public double Bottom { get; set; }
    }

    /// <summary>
    /// The scene's world content and its clock: creates the objects in a world, plays the glove
    /// recording into a hand at the world's step times, and puts movable objects back when it
    /// loops. Deterministic: it never reads a wall clock.
    /// </summary>
    public sealed class GraspScenario
    {
        /// <summary>The recording's frame (a glove tracker's: z up) in the world: turned so that its
        /// up is the world's +y (Unity's up; Frusta's frame maps to Unity's by z -> -z) and raised so
        /// that the table top is 0.75 m above the floor.</summary>
        public static readonly FrustaPose RecordingToWorld =
            new FrustaPose(new Vector3d(0, 0.815, 0), new Quaterniond(-Math.Sqrt(0.5), 0, 0, Math.Sqrt(0.5)));

        /// <summary>The table top's height in the recording's frame: just under the box resting on
        /// it, and under every point the recorded hand reaches (0.1 mm above at the tile, 3.7 mm under the
        /// marble's pinch).</summary>
        public const double TableTop = -0.065;

        /// <summary>Gravity, m/s², recording frame.</summary>
        public const double GravityZ = -9.81;

        const double MarbleRadius = 0.0087;                   // samples/meshes/meshes.h kMarbleRadius
        static readonly Vector3d MarbleAt = new Vector3d(0.129533, 0.025947, -0.044486);  // demo_glove.csv
        static readonly double StandHeight = MarbleAt.Z - MarbleRadius - TableTop;

        /// <summary>The objects, recording frame: the three the recording touches where its hand
        /// expects them (samples/data/demo_glove.csv), a stand holding the marble at its height, the
        /// table, and two more shapes out of the hand's way.</summary>
        public static IReadOnlyList<GraspSceneObject> Objects { get; } = new[]
        {
            new GraspSceneObject { Name = "Table", Tree = "table", Shape = GraspShape.Box, Size = new Vector3d(0.60, 0.90, 0.03),
                                   Pose = At(0.15, 0.28, TableTop - 0.015) },
            new GraspSceneObject { Name = "Stand", Tree = "stand", Shape = GraspShape.Box, Size = new Vector3d(0.008, 0.008, StandHeight),
                                   Pose = At(MarbleAt.X, MarbleAt.Y, TableTop + 0.5 * StandHeight) },
            // 50 g, the recording's settings (damping settles it in the pinch)
            new GraspSceneObject { Name = "Marble", Tree = "marble", Shape = GraspShape.Sphere, Size = new Vector3d(2 * MarbleRadius, 0, 0),
                                   Pose = At(MarbleAt.X, MarbleAt.Y, MarbleAt.Z), Movable = true, Mass = 0.05, Friction = 0.8,
                                   NormalDamping = 9, TangentialDamping = 10, Bottom = MarbleRadius },
            new GraspSceneObject { Name = "Box", Tree = "box", Shape = GraspShape.Box, Size = new Vector3d(0.10, 0.06, 0.04),
                                   Pose = At(0.175, 0.284, -0.045), Mass = 0.5 },
            new GraspSceneObject { Name = "Tile", Tree = "tile", Shape = GraspShape.Box, Size = new Vector3d(0.03, 0.03, 0.004),
                                   Pose = new FrustaPose(new Vector3d(0.123276, 0.529578, -0.050322),
                                                         new Quaterniond(-0.224914496, 0.881724078, 0.0, 0.414700035)) },
            new GraspSceneObject { Name = "Ball", Tree = "ball", Shape = GraspShape.Sphere, Size = new Vector3d(0.08, 0, 0),
                                   Pose = At(0.36, -0.08, TableTop + 0.04) },
            new GraspSceneObject { Name = "Octahedron", Tree = "octahedron", Shape = GraspShape.Octahedron, Size = new Vector3d(0.05, 0, 0),
                                   Pose = At(0.36, 0.62, TableTop + 0.05) },
        };

        /// <summary>The index of the marble in <see cref="Objects"/>.</summary>
        public const int Marble = 2;

        /// <summary>Seconds the hand rests after the recording before it starts again (looping).</summary>
        public const double LoopPause = 1.0;

        readonly World world;
        readonly FrustaHandId hand;
        readonly GloveRecording recording;
        readonly FrustaObjectId[] ids;
        readonly double[] angles = new double[FrustaConstants.HandJointCount];
        FrustaWorldState state;
        long steps;
        double origin;      // the recording's time 0 on the world's step clock
        int next;           // the next sample to feed

        /// <summary>Gravity on dynamic objects for the world, m/s², Frusta's world frame.</summary>
        public static Vector3d Gravity => RecordingToWorld.Rotation.Rotate(new Vector3d(0, 0, GravityZ));

        /// <summary>A world def for the scene: gravity on, otherwise the defaults.</summary>
        public static FrustaWorldDef WorldDef()
        {
            FrustaWorldDef def = FrustaWorldDef.Default;
            def.Gravity = Gravity;
            return def;
        }

        /// <summary>The hand the recording was made with: the default hand, as the Frusta Hand
        /// component builds it with its default size (190 mm long, 85 mm across).</summary>
        public static FrustaHandDef HandDef()
        {
            FrustaHandDef def = FrustaHandDef.Default;
            def.SetSize(0.19, 0.085);
            return def;
        }

        /// <summary>Create the objects in a world the caller steps only through <see cref="Step"/>.</summary>
        /// <param name="world">A world made from <see cref="WorldDef"/> (its rate and gravity),
        /// stepped by the host (not started).</param>
        /// <param name="hand">The right hand the recording drives, in that world.</param>
        /// <param name="treeBytes">A .frtree file's bytes by tree name (<see cref="GraspSceneObject.Tree"/>).</param>
        /// <param name="recording">The glove recording.</param>
        public GraspScenario(World world, FrustaHandId hand, Func<string, byte[]> treeBytes, GloveRecording recording)
        {
            this.world = world ?? throw new ArgumentNullException(nameof(world));
            this.hand = hand;
            this.recording = recording ?? throw new ArgumentNullException(nameof(recording));
            ids = new FrustaObjectId[Objects.Count];
            for (int i = 0; i < Objects.Count; ++i)
            {
                GraspSceneObject o = Objects[i];
                FrustaObjectDef def = FrustaObjectDef.Default;
                def.Pose = ToWorld(o.Pose);
                def.Mass = o.Mass;
                def.Dynamic = o.Movable;
                def.Friction = o.Friction;
                def.NormalDamping = o.NormalDamping;
                def.TangentialDamping = o.TangentialDamping;
                byte[] bytes = treeBytes(o.Tree) ?? throw new ArgumentException($"no tree \"{o.Tree}\" for {o.Name}", nameof(treeBytes));
                using (SphereTree tree = SphereTree.LoadFromMemory(bytes))
                    ids[i] = world.CreateObject(tree, def);
            }
            origin = 1.0 / world.RateHz;  // the first step's time
        }

        /// <summary>Feed the recording to the hand (true, the default) or leave the hand's input to
        /// another driver (hand tracking: FrustaXRHandsInput).</summary>
        public bool DriveHand { get; set; } = true;

        /// <summary>Start the recording again after it ends and a pause (<see cref="LoopPause"/>),
        /// with the marble back on its stand.</summary>
        public bool Loop { get; set; }

        /// <summary>Seconds of world time stepped so far.</summary>
        public double Time => steps / world.RateHz;

        /// <summary>Seconds into the recording at the latest step (past its end: the hand holds
        /// its last sample).</summary>
        public double RecordingTime => Time - origin;

        /// <summary>An object's id in the world, by its index in <see cref="Objects"/>.</summary>
        /// <param name="index">0..<see cref="Objects"/>.Count - 1.</param>
        public FrustaObjectId GetObjectId(int index) => ids[index];

        /// <summary>A pose of the recording's frame in the world.</summary>
        /// <param name="pose">Recording frame.</param>
        public static FrustaPose ToWorld(in FrustaPose pose) =>
            new FrustaPose(RecordingToWorld.TransformPoint(pose.Position), RecordingToWorld.Rotation * pose.Rotation);

        /// <summary>A world point in the recording's frame (z up).</summary>
        /// <param name="world">World frame, metres.</param>
        public static Vector3d ToRecording(Vector3d world) =>
            RecordingToWorld.Rotation.Conjugate.Rotate(world - RecordingToWorld.Position);

        /// <summary>Step the world until its time reaches <paramref name="seconds"/>, at most
        /// <paramref name="maxSteps"/> steps (a long frame catches up over the next ones).</summary>
        /// <returns>The steps taken.</returns>
        public int AdvanceTo(double seconds, int maxSteps)
        {
            int taken = 0;
            while (taken < maxSteps && (steps + 1) / world.RateHz <= seconds + 1e-9)
            {
                Step();
                ++taken;
            }
            return taken;
        }

        /// <summary>One step: the recording's samples up to the step's time go to the hand, the world
        /// steps, and the step is latched (<see cref="World.Read"/>) for the caller's reads.</summary>
        public void Step()
        {
            double stepTime = (steps + 1) / world.RateHz;  // the world's step clock
            if (DriveHand) Feed(stepTime);
            world.Step();
            ++steps;
            world.Read(ref state);
        }

        // every sample whose time has come, stamped with it: the world plays them input_delay late
        void Feed(double stepTime)
        {
            if (next == recording.SampleCount && Loop && stepTime >= origin + recording.Duration + LoopPause)
            {
                origin += recording.Duration + LoopPause;
                next = 0;
                Reset();
            }
            while (next < recording.SampleCount && origin + recording.GetTime(next) <= stepTime)
            {
                recording.GetSample(next, out FrustaPose palm, angles);
                world.SetHaptic(hand, origin + recording.GetTime(next), ToWorld(palm), angles);
                ++next;
            }
        }

        // the movable objects back where they started, at rest (a pose command wakes them)
        void Reset()
        {
            for (int i = 0; i < ids.Length; ++i)
            {
                if (!Objects[i].Movable) continue;
                world.SetObjectPose(ids[i], ToWorld(Objects[i].Pose));
            }
        }

        static FrustaPose At(double x, double y, double z) => new FrustaPose(new Vector3d(x, y, z), Quaterniond.Identity);
    }
}
