// SPDX-License-Identifier: MIT
using System;

namespace Frusta.Binding
{
    /// <summary>
    /// A standalone hand: its geometry at a pose and joint angles, for queries, previews and
    /// gizmos outside a world (a world creates its own hands from defs: <see cref="World.CreateHand"/>).
    /// Thread: the creating thread, the hand's host (the native side serialises creation and
    /// destruction).
    /// </summary>
    public sealed unsafe class Hand : IDisposable
    {
        readonly HandHandle handle;

        /// <summary>A right hand of the default size at the identity pose, joints at zero.</summary>
        public Hand() : this(FrustaHandDef.Default) { }

        /// <summary>A hand built from <paramref name="def"/> at the identity pose with all joint angles
        /// zero (clamped into the limits) (<c>frusta_create_hand</c>).</summary>
        /// <param name="def">From <see cref="FrustaHandDef.Default"/>, then edited.</param>
        /// <exception cref="FrustaException">A def value out of range, with the native message.</exception>
        public Hand(in FrustaHandDef def)
        {
            FrustaLibrary.EnsureCompatible();
            handle = new HandHandle();
            handle.Create(def, Native.frusta_create_hand, "frusta_create_hand");
        }

        /// <summary>The native id (a value; stale once disposed).</summary>
        public FrustaHandId Id => handle.Id;

        /// <summary>false once disposed (<c>frusta_hand_is_valid</c>).</summary>
        public bool IsValid => !handle.IsClosed && Native.frusta_hand_is_valid(handle.Id) == 1;

        /// <summary>Set the palm pose, the hand frame in the world (<c>frusta_hand_set_palm_pose</c>).
        /// The quaternion is normalised; its norm must lie in [0.5, 2].</summary>
        /// <param name="pose">Metres, world frame.</param>
        public void SetPalmPose(in FrustaPose pose)
        {
            using (new HandleUse(handle))
            fixed (FrustaPose* p = &pose)
                Errors.Check(Native.frusta_hand_set_palm_pose(handle.Id, p), "frusta_hand_set_palm_pose");
        }

        /// <summary>Set all 20 joint angles, radians, finger-major (abduction, flexion 1, 2, 3); values
        /// beyond the limits are clamped (<c>frusta_hand_set_joint_angles</c>).</summary>
        /// <param name="angles">Exactly <see cref="FrustaConstants.HandJointCount"/> radians.</param>
        public void SetJointAngles(ReadOnlySpan<double> angles)
        {
            using (new HandleUse(handle))
            fixed (double* a = angles)
                Errors.Check(Native.frusta_hand_set_joint_angles(handle.Id, a, angles.Length), "frusta_hand_set_joint_angles");
        }

        /// <summary>Copy the (clamped) joint angles, radians, finger-major: the first
        /// min(destination.Length, 20) (<c>frusta_hand_get_joint_angles</c>).</summary>
        /// <param name="destination">Receives the angles; <see cref="FrustaConstants.HandJointCount"/> holds all.</param>
        /// <returns>How many angles the hand has (20).</returns>
        public int GetJointAngles(Span<double> destination) =>
            handle.CopyOut(destination, (id, a, capacity, count) => Native.frusta_hand_get_joint_angles(id, a, capacity, count),
                           "frusta_hand_get_joint_angles");

        /// <summary>Copy every finger segment in world coordinates, finger-major (thumb first),
        /// proximal to distal: the first min(destination.Length, 15) (<c>frusta_hand_get_segments</c>).</summary>
        /// <param name="destination">Receives the segments; <see cref="FrustaConstants.HandSegmentCount"/> holds all.</param>
        /// <returns>How many segments the hand has (15).</returns>
        public int GetSegments(Span<FrustaSegment> destination) =>
            handle.CopyOut(destination, (id, s, capacity, count) => Native.frusta_hand_get_segments(id, s, capacity, count),
                           "frusta_hand_get_segments");

        /// <summary>The number of palm spheres.</summary>
        public int PalmSphereCount => GetPalmSpheres(default);

        /// <summary>Copy the palm's spheres in world coordinates: the first min(destination.Length, count)
        /// (<c>frusta_hand_get_palm_spheres</c>).</summary>
        /// <param name="destination">Receives the spheres; <see cref="PalmSphereCount"/> holds all.</param>
        /// <returns>How many palm spheres the hand has.</returns>
        public int GetPalmSpheres(Span<FrustaSphere> destination) =>
            handle.CopyOut(destination, (id, s, capacity, count) => Native.frusta_hand_get_palm_spheres(id, s, capacity, count),
                           "frusta_hand_get_palm_spheres");

        /// <summary>
        /// The Jacobian of a material point of one segment with respect to the finger's four joint
        /// angles followed by the palm's 6 DOF, row-major 3 x 10 (<c>frusta_hand_point_jacobian</c>).
        /// </summary>
        /// <param name="finger">The finger.</param>
        /// <param name="segment">0..2, proximal to distal.</param>
        /// <param name="localPoint">Metres in the segment frame: origin at the proximal joint, +x along the segment.</param>
        /// <param name="jacobian">Receives the first min(jacobian.Length, 30) entries;
        /// <see cref="FrustaConstants.PointJacobianLength"/> holds all.</param>
        /// <returns>The point's world position, metres.</returns>
        public Vector3d GetPointJacobian(FrustaFinger finger, int segment, Vector3d localPoint, Span<double> jacobian)
        {
            Vector3d point = default;
            int count;
            using (new HandleUse(handle))
            fixed (double* j = jacobian)
                Errors.Check(Native.frusta_hand_point_jacobian(handle.Id, (int)finger, segment, &localPoint.X, &point.X, j,
                                                               jacobian.Length, &count), "frusta_hand_point_jacobian");
            return point;
        }

        /// <summary>Destroy the native hand (<c>frusta_destroy_hand</c>). Safe to call twice.</summary>
        public void Dispose() => handle.Dispose();
    }

    /// <summary>Sphere/segment queries of the contact geometry (<c>frusta_query_contact</c>,
    /// <c>frusta_constraint_eval</c>). Thread: any; allocation-free.</summary>
    public static unsafe class Geometry
    {
        /// <summary>Query one sphere against one segment solid.</summary>
        /// <param name="segment">Radii &gt;= 0, values within 1e6 m.</param>
        /// <param name="sphere">Radius &gt;= 0.</param>
        /// <returns>The nearest feature, signed distance, points and normal.</returns>
        public static FrustaContactQuery QueryContact(in FrustaSegment segment, in FrustaSphere sphere)
        {
            FrustaLibrary.EnsureCompatible();
            var q = new FrustaContactQuery { struct_size = sizeof(FrustaContactQuery) };
            fixed (FrustaSegment* s = &segment)
            fixed (FrustaSphere* o = &sphere)
                Errors.Check(Native.frusta_query_contact(s, o, &q), "frusta_query_contact");
            return q;
        }

        /// <summary>The constraint (g &lt; 0 exactly when the sphere overlaps the solid) with its gradient.</summary>
        /// <param name="segment">Radii &gt;= 0, values within 1e6 m.</param>
        /// <param name="sphere">Radius &gt;= 0.</param>
        /// <param name="form">Squared or distance form.</param>
        /// <returns>The value and its gradient with respect to D, E and the sphere's centre.</returns>
        public static FrustaConstraint EvaluateConstraint(in FrustaSegment segment, in FrustaSphere sphere, FrustaConstraintForm form)
        {
            FrustaLibrary.EnsureCompatible();
            var c = new FrustaConstraint { struct_size = sizeof(FrustaConstraint) };
            fixed (FrustaSegment* s = &segment)
            fixed (FrustaSphere* o = &sphere)
                Errors.Check(Native.frusta_constraint_eval(s, o, (int)form, &c), "frusta_constraint_eval");
            return c;
        }
    }
}
