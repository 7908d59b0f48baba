// SPDX-License-Identifier: MIT
using System;

namespace Frusta.Binding
{
    /// <summary>A coordinate axis, naming the normal of a mirror plane.</summary>
    public enum Axis
    {
        /// <summary>The x axis.</summary>
        X = 0,
        /// <summary>The y axis.</summary>
        Y = 1,
        /// <summary>The z axis.</summary>
        Z = 2,
    }

    /// <summary>
    /// The one place where Frusta's frame meets Unity's. Frusta is right-handed, in metres;
    /// Unity is left-handed (x right, y up, z forward), in metres (1 unit = 1 m). The conversion
    /// flips the z axis: a point (x, y, z) is (x, y, -z) in the other frame, and it is its own
    /// inverse, so each ...ToUnity has an equal ...FromUnity. Quaternions are (x, y, z, w) on
    /// both sides. Pure functions: any thread, no allocation.
    /// <para>Which value is which kind: positions, directions, normals, linear velocities and
    /// forces are vectors (<see cref="VectorToUnity"/>); torques and angular velocities are axial
    /// vectors (<see cref="AxialToUnity"/>), which a reflection also turns around; rotations are
    /// <see cref="RotationToUnity"/>. A mesh's triangle winding reverses (<see cref="FlipWinding"/>).</para>
    /// </summary>
    public static class CoordinateConversion
    {
        /// <summary>A position, direction, normal, velocity or force from Frusta to Unity: (x, y, -z).</summary>
        /// <param name="v">Frusta frame.</param>
        /// <returns>Unity frame.</returns>
        public static Vector3d VectorToUnity(Vector3d v) => new Vector3d(v.X, v.Y, -v.Z);

        /// <summary>A position, direction, normal, velocity or force from Unity to Frusta: (x, y, -z).</summary>
        /// <param name="v">Unity frame.</param>
        /// <returns>Frusta frame.</returns>
        public static Vector3d VectorFromUnity(Vector3d v) => new Vector3d(v.X, v.Y, -v.Z);

        /// <summary>A torque or angular velocity (an axial vector) from Frusta to Unity: (-x, -y, z),
        /// so that Unity's left-hand rule turns the same way the right-hand rule did.</summary>
        /// <param name="w">Frusta frame.</param>
        /// <returns>Unity frame.</returns>
        public static Vector3d AxialToUnity(Vector3d w) => new Vector3d(-w.X, -w.Y, w.Z);

        /// <summary>A torque or angular velocity from Unity to Frusta: (-x, -y, z).</summary>
        /// <param name="w">Unity frame.</param>
        /// <returns>Frusta frame.</returns>
        public static Vector3d AxialFromUnity(Vector3d w) => new Vector3d(-w.X, -w.Y, w.Z);

        /// <summary>A rotation from Frusta to Unity: the matrix S R S with S = diag(1, 1, -1), which
        /// is the quaternion (-x, -y, z, w).</summary>
        /// <param name="q">Frusta frame (x, y, z, w).</param>
        /// <returns>Unity frame (x, y, z, w).</returns>
        public static Quaterniond RotationToUnity(Quaterniond q) => new Quaterniond(-q.X, -q.Y, q.Z, q.W);

        /// <summary>A rotation from Unity to Frusta: (-x, -y, z, w).</summary>
        /// <param name="q">Unity frame.</param>
        /// <returns>Frusta frame.</returns>
        public static Quaterniond RotationFromUnity(Quaterniond q) => new Quaterniond(-q.X, -q.Y, q.Z, q.W);

        /// <summary>A pose from Frusta to Unity.</summary>
        /// <param name="pose">Frusta frame.</param>
        /// <returns>Unity frame.</returns>
        public static FrustaPose PoseToUnity(in FrustaPose pose) =>
            new FrustaPose(VectorToUnity(pose.Position), RotationToUnity(pose.Rotation));

        /// <summary>A pose from Unity to Frusta.</summary>
        /// <param name="pose">Unity frame.</param>
        /// <returns>Frusta frame.</returns>
        public static FrustaPose PoseFromUnity(in FrustaPose pose) =>
            new FrustaPose(VectorFromUnity(pose.Position), RotationFromUnity(pose.Rotation));

        /// <summary>Reverse each triangle's winding in place (swap its second and third index): a
        /// mesh converted with <see cref="VectorFromUnity"/> needs it to stay counter-clockwise seen
        /// from outside.</summary>
        /// <param name="indices">Three per triangle.</param>
        public static void FlipWinding(Span<int> indices)
        {
            if (indices.Length % 3 != 0) throw new ArgumentException("must hold triangles", nameof(indices));
            for (int i = 0; i < indices.Length; i += 3)
            {
                int t = indices[i + 1];
                indices[i + 1] = indices[i + 2];
                indices[i + 2] = t;
            }
        }

        /// <summary>A point mirrored through the plane {p : p[axis] = offset}.</summary>
        /// <param name="p">A point, metres.</param>
        /// <param name="planeNormal">The plane's normal axis.</param>
        /// <param name="offset">The plane's coordinate along that axis, metres.</param>
        /// <returns>The mirrored point.</returns>
        public static Vector3d MirrorPoint(Vector3d p, Axis planeNormal, double offset = 0.0)
        {
            switch (planeNormal)
            {
                case Axis.X: return new Vector3d(2 * offset - p.X, p.Y, p.Z);
                case Axis.Y: return new Vector3d(p.X, 2 * offset - p.Y, p.Z);
                case Axis.Z: return new Vector3d(p.X, p.Y, 2 * offset - p.Z);
                default: throw new ArgumentOutOfRangeException(nameof(planeNormal));
            }
        }

        /// <summary>
        /// The palm pose of the other hand that is the mirror image of this one through the plane
        /// {p : p[axis] = offset}: a right hand's pose gives the left hand's and back. With the
        /// same joint angles (they mean the same anatomical motion on both sides) the other hand's
        /// every point is the mirror of this hand's. Both poses are in one frame (Frusta's or
        /// Unity's). The rotation is M R S_y, where M is the reflection and S_y the hand frame's
        /// own mirror (a left hand is a right hand reflected through its x-z plane).
        /// </summary>
        /// <param name="palm">This hand's palm pose.</param>
        /// <param name="planeNormal">The mirror plane's normal axis.</param>
        /// <param name="offset">The plane's coordinate along that axis, metres.</param>
        /// <returns>The other hand's palm pose.</returns>
        public static FrustaPose MirrorHandPose(in FrustaPose palm, Axis planeNormal, double offset = 0.0)
        {
            Quaterniond q = palm.Rotation;
            // M R M as a quaternion, then the rotation M S_y on the right
            Quaterniond reflected;
            Quaterniond fix;
            switch (planeNormal)
            {
                case Axis.X:
                    reflected = new Quaterniond(q.X, -q.Y, -q.Z, q.W);
                    fix = new Quaterniond(0, 0, 1, 0); // diag(-1, -1, 1): pi about z
                    break;
                case Axis.Y:
                    reflected = new Quaterniond(-q.X, q.Y, -q.Z, q.W);
                    fix = Quaterniond.Identity;
                    break;
                case Axis.Z:
                    reflected = new Quaterniond(-q.X, -q.Y, q.Z, q.W);
                    fix = new Quaterniond(1, 0, 0, 0); // diag(1, -1, -1): pi about x
                    break;
                default: throw new ArgumentOutOfRangeException(nameof(planeNormal));
            }
            return new FrustaPose(MirrorPoint(palm.Position, planeNormal, offset), reflected * fix);
        }

        /// <summary>The other side: right for left and left for right.</summary>
        /// <param name="side">A hand side.</param>
        /// <returns>The opposite side.</returns>
        public static FrustaHandSide Opposite(FrustaHandSide side) =>
            side == FrustaHandSide.Right ? FrustaHandSide.Left : FrustaHandSide.Right;
    }
}
