// SPDX-License-Identifier: MIT
using System;
using Frusta.Binding;
using UnityEngine;

namespace Frusta.Unity
{
    /// <summary>
    /// A hand of a <see cref="FrustaWorldBehaviour"/>. The haptic input (the tracked wrist and the
    /// glove's joint angles) goes in through <see cref="hapticSource"/> and <see cref="SetJointAngles"/>,
    /// or, while a <see cref="FrustaGloveDevice"/> drives the hand, comes from the glove itself;
    /// the graphic hand (the one that never sinks into objects) comes out each frame and drives the
    /// mapped bones of a skinned rig. Scene-view gizmos show its segments, joint balls and contacts.
    /// The hand joins its world when enabled and leaves it when disabled or destroyed, so a rig
    /// spawned (or removed) at run time, while the world runs, works as one in the scene.
    /// </summary>
    [AddComponentMenu("Frusta/Frusta Hand")]
    public sealed class FrustaHand : MonoBehaviour
    {
        /// <summary>One bone of a rig driven by one finger segment's joint angles.</summary>
        [Serializable]
        public struct BoneMapping
        {
            /// <summary>The rig's bone.</summary>
            [Tooltip("The rig's bone.")]
            public Transform bone;
            /// <summary>The finger.</summary>
            [Tooltip("The finger.")]
            public FrustaFinger finger;
            /// <summary>Segment 0..2, proximal to distal.</summary>
            [Tooltip("Segment 0..2, proximal to distal.")]
            [Range(0, 2)] public int segment;
            /// <summary>The bone's local axis the flexion turns about (towards the palm positive).</summary>
            [Tooltip("The bone's local axis the flexion turns about (towards the palm positive).")]
            public Vector3 flexionAxis;
            /// <summary>The bone's local axis the abduction turns about (first segment only).</summary>
            [Tooltip("The bone's local axis the abduction turns about (first segment only).")]
            public Vector3 abductionAxis;
            [NonSerialized] internal Quaternion rest;
        }

        /// <summary>A single segment's length and tip radius overriding the proportions.</summary>
        [Serializable]
        public struct SegmentOverride
        {
            /// <summary>The finger.</summary>
            [Tooltip("The finger.")]
            public FrustaFinger finger;
            /// <summary>Segment 0..2.</summary>
            [Tooltip("Segment 0..2, proximal to distal.")]
            [Range(0, 2)] public int segment;
            /// <summary>Metres; 0 keeps the proportional length.</summary>
            [Tooltip("Metres; 0 keeps the proportional length.")]
            public float length;
            /// <summary>Metres, the ball at the segment's distal end; 0 keeps it.</summary>
            [Tooltip("Metres, the ball at the segment's distal end; 0 keeps it.")]
            public float distalRadius;
        }

        [Tooltip("The world the hand belongs to. Empty: the Frusta World above it.")]
        [SerializeField] FrustaWorldBehaviour world;
        [Tooltip("Which hand this is.")]
        [SerializeField] FrustaHandSide handedness = FrustaHandSide.Right;
        [Tooltip("Metres, wrist crease to middle fingertip.")]
        [SerializeField, Range(0.12f, 0.26f)] float handLength = 0.19f;
        [Tooltip("Metres, across the metacarpal heads.")]
        [SerializeField, Range(0.06f, 0.12f)] float handBreadth = 0.085f;
        [Tooltip("Single segments whose length or tip radius differ from the hand's proportions.")]
        [SerializeField] SegmentOverride[] segmentOverrides = Array.Empty<SegmentOverride>();
        [Tooltip("The tracked wrist: its world pose is the haptic palm pose. Empty: this transform.")]
        [SerializeField] Transform hapticSource;
        [Tooltip("Moved to the graphic palm each frame (the rig's wrist bone). Empty: nothing moves.")]
        [SerializeField] Transform graphicWrist;
        [Tooltip("The rig's wrist bone's rotation relative to the palm frame (set by mapping a rig).")]
        [SerializeField] Quaternion graphicWristRotation = Quaternion.identity;
        [Tooltip("The rig's finger bones, each driven by one segment's joint angles.")]
        [SerializeField] BoneMapping[] bones = Array.Empty<BoneMapping>();
        [Tooltip("Draw the contacts and their forces (1 cm per newton) in the scene view.")]
        [SerializeField] bool drawContacts = true;

        FrustaHandDef def;
        FrustaHandId id;                    // null while the hand is not in the world
        bool shown;                         // the latched step shows the hand (latest is its)
        readonly double[] angles = new double[FrustaConstants.HandJointCount];
        FrustaWorldHand latest;
        FrustaWorldContact[] contacts = Array.Empty<FrustaWorldContact>();
        int contactCount;
        readonly FrustaSegment[] segments = new FrustaSegment[FrustaConstants.HandSegmentCount];

        /// <summary>The hand's id in the world; null (<see cref="FrustaHandId.IsNull"/>) while it is not in
        /// the world (before it was enabled, once disabled).</summary>
        public FrustaHandId Id => id;

        /// <summary>The world component the hand belongs to (null if it found none).</summary>
        public FrustaWorldBehaviour WorldBehaviour => world;

        /// <summary>The tracked wrist whose world pose is the haptic palm pose: the inspector's
        /// haptic source, or this transform.</summary>
        public Transform HapticSource => hapticSource != null ? hapticSource : transform;

        /// <summary>true while a <see cref="FrustaGloveDevice"/> drives this hand: the glove's samples
        /// are the haptic input (the world refuses the host's), so <see cref="SetJointAngles"/> and the
        /// haptic source are not used.</summary>
        public bool DrivenByDevice { get; internal set; }

        /// <summary>A component that sets this hand's haptic input itself (hand tracking, e.g.
        /// FrustaXRHandsInput, through <see cref="World.SetHaptic(FrustaHandId, in FrustaHandFit)"/>
        /// with <see cref="Id"/>); while set, the hand does not send its haptic source and angles.</summary>
        public UnityEngine.Object InputOwner { get; set; }

        /// <summary>The def the hand is in its world with: the inspector's, or the last given to
        /// <see cref="Rebuild"/>.</summary>
        public FrustaHandDef Def => def;

        /// <summary>Put the hand in its world again with another def (a world hand's def is fixed):
        /// a calibrated size, say. Its <see cref="Id"/> changes; a glove driving it reopens.</summary>
        /// <param name="newDef">The hand's new def.</param>
        public void Rebuild(in FrustaHandDef newDef)
        {
            Release();
            def = newDef;
            handLength = (float)newDef.HandLength;
            handBreadth = (float)newDef.HandBreadth;
            if (isActiveAndEnabled) Register();
        }

        /// <summary>true while the latched step shows this hand solved, so that its geometry can be
        /// read from the world (<see cref="World.GetHandSegments"/>); false before its first solved
        /// step and once it left the world.</summary>
        public bool Shown => !id.IsNull && shown && latest.Solved;

        /// <summary>The latest graphic and haptic state (valid once <see cref="FrustaWorldHand.Solved"/>;
        /// unsolved until a step has taken in a hand added at run time).</summary>
        public ref readonly FrustaWorldHand State => ref latest;

        /// <summary>The latest contacts of this hand (world frame, Frusta's axes).</summary>
        public ReadOnlySpan<FrustaWorldContact> Contacts => new ReadOnlySpan<FrustaWorldContact>(contacts, 0, contactCount);

        /// <summary>Set the glove's 20 joint angles (radians, finger-major) for the next steps.</summary>
        public void SetJointAngles(ReadOnlySpan<double> radians) => radians.CopyTo(angles);

        /// <summary>The hand def built from the inspector fields.</summary>
        public FrustaHandDef BuildDef()
        {
            FrustaHandDef d = FrustaHandDef.Default;
            d.Side = handedness;
            d.SetSize(handLength, handBreadth);
            foreach (SegmentOverride o in segmentOverrides)
            {
                if (o.length > 0) d.SetSegmentLength(o.finger, o.segment, o.length);
                if (o.distalRadius > 0) d.SetJointRadius(o.finger, o.segment + 1, o.distalRadius);
            }
            return d;
        }

        // a glove driving this hand closes before the hand leaves its world (the world refuses
        // to destroy a hand a glove drives), and may open again once the hand is back
        internal event Action Registered, Releasing;

        void Awake()
        {
            def = BuildDef();
            for (int i = 0; i < bones.Length; ++i)
            {
                if (bones[i].bone == null) continue;
                bones[i].rest = bones[i].bone.localRotation;
                // a bone with no axis would silently never move
                if (bones[i].flexionAxis == Vector3.zero || (bones[i].segment == 0 && bones[i].abductionAxis == Vector3.zero))
                    Debug.LogWarning($"FrustaHand: bone {bones[i].bone.name} ({bones[i].finger} {bones[i].segment}) has no " +
                                     (bones[i].flexionAxis == Vector3.zero ? "flexion" : "abduction") + " axis: it will not turn " +
                                     "that way. Map the rig (the inspector's buttons) or set the axis.", this);
            }
        }

        // in the world while enabled; Start retries for a world that woke after this hand
        void OnEnable() => Register();

        void Start()
        {
            Register();
            if (world == null || world.World == null)
                Debug.LogError("FrustaHand needs a FrustaWorldBehaviour (set one or put the hand under it).", this);
        }

        void OnDisable() => Release();

        void OnDestroy() => Release();

        void Register()
        {
            if (!id.IsNull) return;
            if (world == null) world = GetComponentInParent<FrustaWorldBehaviour>();
            if (world == null || world.World == null) return;
            try
            {
                id = world.World.CreateHand(def);
            }
            catch (FrustaException e)
            {
                Debug.LogError($"FrustaHand did not join its world ({e.Result}): {e.NativeMessage}", this);
                return;
            }
            if (contacts.Length != world.World.MaxContactsPerHand)
                contacts = new FrustaWorldContact[world.World.MaxContactsPerHand];
            world.Latched += OnLatched;
            Registered?.Invoke();
        }

        void Release()
        {
            if (id.IsNull) return;
            Releasing?.Invoke();
            world.Latched -= OnLatched;
            World w = world.World;
            // a world destroyed first took its hands with it
            if (w != null && w.IsValid)
            {
                try { w.DestroyHand(id); }
                catch (FrustaException e) { Debug.LogError($"FrustaHand did not leave its world ({e.Result}): {e.NativeMessage}", this); }
            }
            id = default;
            shown = false;
            contactCount = 0;
        }

        void Update()
        {
            World w = world != null ? world.World : null;
            if (w == null || id.IsNull || DrivenByDevice || InputOwner != null) return;
            w.SetHaptic(id, HapticSource.ToFrustaPose(), angles);
        }

        void OnLatched(FrustaWorldBehaviour source)
        {
            World w = source.World;
            // a hand added since the latched step is not in it yet
            shown = w.TryGetHand(id, ref latest);
            contactCount = shown ? w.GetContacts(id, contacts) : 0;
        }

        // after the Animator has written its pose, so that it does not overwrite the hand's
        void LateUpdate()
        {
            if (!shown || !latest.Solved) return;
            if (graphicWrist != null)
            {
                graphicWrist.SetFrustaPose(latest.GraphicPalm);
                graphicWrist.rotation *= graphicWristRotation;
            }
            for (int i = 0; i < bones.Length; ++i)
            {
                BoneMapping b = bones[i];
                if (b.bone == null) continue;
                int joint = (int)b.finger * FrustaConstants.JointsPerFinger;
                float flexion = (float)(latest.GetGraphicAngle(joint + 1 + b.segment) * Mathf.Rad2Deg);
                float abduction = b.segment == 0 ? (float)(latest.GetGraphicAngle(joint) * Mathf.Rad2Deg) : 0f;
                b.bone.localRotation = b.rest * Quaternion.AngleAxis(abduction, b.abductionAxis) *
                                       Quaternion.AngleAxis(flexion, b.flexionAxis);
            }
        }

        /// <summary>
        /// Map a rig's bones to this hand and compute each bone's axes from the hand's own
        /// kinematics (<see cref="HandRig"/>): the rig must be in its rest pose now (fingers
        /// straight, as a humanoid's T-pose has them), which becomes the hand's rest pose; the wrist
        /// bone becomes <see cref="GraphicWrist"/>, turned to the palm frame the rig's knuckles span.
        /// Bones left null (a rig without them) are left out.
        /// </summary>
        /// <param name="wrist">The rig's wrist bone.</param>
        /// <param name="segmentBones">15 bones, finger-major (thumb first), proximal to distal: the bone
        /// each segment turns (the thumb's first is its metacarpal).</param>
        /// <returns>null when mapped; else what is missing (the mapping is then unchanged).</returns>
        public string MapRig(Transform wrist, Transform[] segmentBones)
        {
            if (wrist == null) return "no wrist bone";
            if (segmentBones == null || segmentBones.Length != FrustaConstants.HandSegmentCount)
                return $"needs {FrustaConstants.HandSegmentCount} segment bones";
            foreach (int f in new[] { 1, 2, 4 })
                if (segmentBones[f * FrustaConstants.SegmentsPerFinger] == null)
                    return $"no first bone of the {(FrustaFinger)f} finger: the palm frame needs the index, middle and little knuckles";
            FrustaHandDef d = BuildDef();
            Span<Vector3d> flexion = stackalloc Vector3d[FrustaConstants.HandSegmentCount];
            Span<Vector3d> abduction = stackalloc Vector3d[FrustaConstants.FingerCount];
            HandRig.Axes(d, flexion, abduction);
            Quaterniond frame;
            try
            {
                frame = HandRig.HandFrame(d, wrist.position.ToFrustaVector(),
                                          segmentBones[3].position.ToFrustaVector(), segmentBones[6].position.ToFrustaVector(),
                                          segmentBones[12].position.ToFrustaVector());
            }
            catch (ArgumentException e)
            {
                return e.Message;
            }
            var mapped = new System.Collections.Generic.List<BoneMapping>();
            for (int k = 0; k < segmentBones.Length; ++k)
            {
                Transform bone = segmentBones[k];
                if (bone == null) continue;
                int f = k / FrustaConstants.SegmentsPerFinger, s = k % FrustaConstants.SegmentsPerFinger;
                Quaternion r = bone.rotation;
                var rest = new Quaterniond(r.x, r.y, r.z, r.w); // its world rotation, Unity's frame
                mapped.Add(new BoneMapping
                {
                    bone = bone,
                    finger = (FrustaFinger)f,
                    segment = s,
                    flexionAxis = ToVector3(HandRig.BoneAxis(rest, frame, flexion[k])),
                    abductionAxis = s == 0 ? ToVector3(HandRig.BoneAxis(rest, frame, abduction[f])) : Vector3.zero,
                    rest = bone.localRotation,
                });
            }
            bones = mapped.ToArray();
            graphicWrist = wrist;
            graphicWristRotation = Quaternion.Inverse(frame.ToUnityRotation()) * wrist.rotation;
            return null;
        }

        static Vector3 ToVector3(Vector3d v) => new Vector3((float)v.X, (float)v.Y, (float)v.Z);

        /// <summary>The rig's wrist bone, moved to the graphic palm each frame.</summary>
        public Transform GraphicWrist => graphicWrist;

        /// <summary>The mapped bones (read-only view; <see cref="MapRig"/> or the inspector set them).</summary>
        public ReadOnlySpan<BoneMapping> Bones => bones;

        void OnDrawGizmos()
        {
            World w = world != null ? world.World : null;
            if (w == null || !shown || !latest.Solved) return;
            // the graphic hand's geometry, from the latched step
            int n = w.GetHandSegments(id, FrustaHandKind.Graphic, segments);
            Gizmos.color = new Color(0.9f, 0.75f, 0.6f);
            for (int s = 0; s < n; ++s)
            {
                Vector3 d = segments[s].Proximal.ToUnityVector(), e = segments[s].Distal.ToUnityVector();
                Gizmos.DrawLine(d, e);
                Gizmos.DrawWireSphere(d, (float)segments[s].ProximalRadius);
                Gizmos.DrawWireSphere(e, (float)segments[s].DistalRadius);
            }
            if (!drawContacts) return;
            for (int i = 0; i < contactCount; ++i)
            {
                Vector3 p = contacts[i].GraphicPoint.ToUnityVector();
                Gizmos.color = contacts[i].Slipping ? Color.yellow : Color.red;
                Gizmos.DrawSphere(p, 0.001f);
                // 1 cm per newton
                Gizmos.DrawLine(p, p + 0.01f * (contacts[i].NormalForce + contacts[i].Friction).ToUnityVector());
            }
        }
    }
}
