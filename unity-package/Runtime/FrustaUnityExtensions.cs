// SPDX-License-Identifier: MIT
using Frusta.Binding;
using UnityEngine;

namespace Frusta.Unity
{
    /// <summary>UnityEngine types to and from the binding's, through <see cref="CoordinateConversion"/>
    /// (the one place that knows Frusta is right-handed and Unity left-handed).</summary>
    public static class FrustaUnityExtensions
    {
        /// <summary>A Frusta position, direction or force as a Unity vector (metres, Unity frame).</summary>
        public static Vector3 ToUnityVector(this Vector3d v)
        {
            Vector3d u = CoordinateConversion.VectorToUnity(v);
            return new Vector3((float)u.X, (float)u.Y, (float)u.Z);
        }

        /// <summary>A Unity position, direction or force in Frusta's frame.</summary>
        public static Vector3d ToFrustaVector(this Vector3 v) => CoordinateConversion.VectorFromUnity(new Vector3d(v.x, v.y, v.z));

        /// <summary>A Frusta torque or angular velocity as a Unity one (for Rigidbody.AddTorque).</summary>
        public static Vector3 ToUnityAxial(this Vector3d w)
        {
            Vector3d u = CoordinateConversion.AxialToUnity(w);
            return new Vector3((float)u.X, (float)u.Y, (float)u.Z);
        }

        /// <summary>A Frusta rotation as a Unity quaternion.</summary>
        public static Quaternion ToUnityRotation(this Quaterniond q)
        {
            Quaterniond u = CoordinateConversion.RotationToUnity(q);
            return new Quaternion((float)u.X, (float)u.Y, (float)u.Z, (float)u.W);
        }

        /// <summary>A Unity rotation in Frusta's frame.</summary>
        public static Quaterniond ToFrustaRotation(this Quaternion q) =>
            CoordinateConversion.RotationFromUnity(new Quaterniond(q.x, q.y, q.z, q.w));

        /// <summary>A transform's world pose in Frusta's frame (scale is ignored).</summary>
        public static FrustaPose ToFrustaPose(this Transform t) =>
            new FrustaPose(t.position.ToFrustaVector(), t.rotation.ToFrustaRotation());

        /// <summary>A mesh as <see cref="SphereTree.Bake(System.ReadOnlySpan{float}, System.ReadOnlySpan{int}, in FrustaBakeDef)"/>
        /// takes it: each vertex scaled per axis, then in Frusta's frame, and each triangle's winding
        /// turned to match (<see cref="CoordinateConversion.FlipWinding"/>).</summary>
        /// <param name="mesh">A readable mesh.</param>
        /// <param name="scale">Metres per mesh unit along each of the mesh's axes.</param>
        /// <param name="vertices">xyz triples, metres.</param>
        /// <param name="indices">Three per triangle, counter-clockwise seen from outside.</param>
        public static void ToFrustaMesh(this Mesh mesh, Vector3 scale, out float[] vertices, out int[] indices)
        {
            Vector3[] v = mesh.vertices;
            vertices = new float[v.Length * 3];
            for (int i = 0; i < v.Length; ++i)
            {
                // scaled in double: the product of two floats is exact there, so each vertex is
                // rounded to float once
                Vector3d p = CoordinateConversion.VectorFromUnity(
                    new Vector3d((double)v[i].x * scale.x, (double)v[i].y * scale.y, (double)v[i].z * scale.z));
                vertices[3 * i] = (float)p.X;
                vertices[3 * i + 1] = (float)p.Y;
                vertices[3 * i + 2] = (float)p.Z;
            }
            indices = mesh.triangles;
            CoordinateConversion.FlipWinding(indices);
        }

        /// <summary>Put a transform at a Frusta pose (world space).</summary>
        public static void SetFrustaPose(this Transform t, in FrustaPose pose) =>
            t.SetPositionAndRotation(pose.Position.ToUnityVector(), pose.Rotation.ToUnityRotation());
    }
}
