// SPDX-License-Identifier: MIT
using System;
using System.Runtime.InteropServices;

namespace Frusta.Binding
{
    /// <summary>
    /// Three doubles laid out as a C <c>double[3]</c>: a position (metres), a direction, a
    /// force (newtons) or a torque (newton-metres), in whatever frame the field that holds
    /// it documents. Blittable; kept here so that the binding needs no UnityEngine (the
    /// Unity layer converts to <c>UnityEngine.Vector3</c> through <see cref="CoordinateConversion"/>).
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Vector3d : IEquatable<Vector3d>
    {
        /// <summary>The x component.</summary>
        public double X;
        /// <summary>The y component.</summary>
        public double Y;
        /// <summary>The z component.</summary>
        public double Z;

        /// <summary>A vector from its three components.</summary>
        /// <param name="x">The x component.</param>
        /// <param name="y">The y component.</param>
        /// <param name="z">The z component.</param>
        public Vector3d(double x, double y, double z)
        {
            X = x;
            Y = y;
            Z = z;
        }

        /// <summary>The zero vector.</summary>
        public static Vector3d Zero => default;

        // three consecutive doubles of a mirror's fixed buffer (a row of a C double[N][3])
        internal static unsafe Vector3d Read(double* p) => new Vector3d(p[0], p[1], p[2]);

        internal readonly unsafe void Write(double* p)
        {
            p[0] = X;
            p[1] = Y;
            p[2] = Z;
        }

        /// <summary>The Euclidean length.</summary>
        public double Length => Math.Sqrt(X * X + Y * Y + Z * Z);

        /// <summary>The dot product of two vectors.</summary>
        /// <param name="a">The first vector.</param>
        /// <param name="b">The second vector.</param>
        /// <returns>a . b</returns>
        public static double Dot(Vector3d a, Vector3d b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;

        /// <summary>The cross product of two vectors, by the usual component formula (as Unity's Vector3.Cross).</summary>
        /// <param name="a">The first vector.</param>
        /// <param name="b">The second vector.</param>
        /// <returns>a x b</returns>
        public static Vector3d Cross(Vector3d a, Vector3d b) =>
            new Vector3d(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X);

        /// <summary>Component-wise sum.</summary>
        /// <param name="a">The first vector.</param>
        /// <param name="b">The second vector.</param>
        /// <returns>a + b</returns>
        public static Vector3d operator +(Vector3d a, Vector3d b) => new Vector3d(a.X + b.X, a.Y + b.Y, a.Z + b.Z);

        /// <summary>Component-wise difference.</summary>
        /// <param name="a">The first vector.</param>
        /// <param name="b">The second vector.</param>
        /// <returns>a - b</returns>
        public static Vector3d operator -(Vector3d a, Vector3d b) => new Vector3d(a.X - b.X, a.Y - b.Y, a.Z - b.Z);

        /// <summary>The negated vector.</summary>
        /// <param name="a">The vector.</param>
        /// <returns>-a</returns>
        public static Vector3d operator -(Vector3d a) => new Vector3d(-a.X, -a.Y, -a.Z);

        /// <summary>The vector scaled by a number.</summary>
        /// <param name="a">The vector.</param>
        /// <param name="s">The scale.</param>
        /// <returns>s a</returns>
        public static Vector3d operator *(Vector3d a, double s) => new Vector3d(a.X * s, a.Y * s, a.Z * s);

        /// <summary>The vector scaled by a number.</summary>
        /// <param name="s">The scale.</param>
        /// <param name="a">The vector.</param>
        /// <returns>s a</returns>
        public static Vector3d operator *(double s, Vector3d a) => a * s;

        /// <summary>Exact component-wise equality.</summary>
        /// <param name="other">The vector to compare with.</param>
        /// <returns>true when every component is equal.</returns>
        public bool Equals(Vector3d other) => X.Equals(other.X) && Y.Equals(other.Y) && Z.Equals(other.Z);

        /// <summary>Exact component-wise equality with a boxed <see cref="Vector3d"/>.</summary>
        /// <param name="obj">The object to compare with.</param>
        /// <returns>true when obj is an equal <see cref="Vector3d"/>.</returns>
        public override bool Equals(object obj) => obj is Vector3d v && Equals(v);

        /// <summary>A hash of the three components.</summary>
        /// <returns>The hash code.</returns>
        public override int GetHashCode() => (X.GetHashCode() * 397 ^ Y.GetHashCode()) * 397 ^ Z.GetHashCode();

        /// <summary>"(x, y, z)" with round-trip precision.</summary>
        /// <returns>The text.</returns>
        public override string ToString() => $"({X:R}, {Y:R}, {Z:R})";
    }

    /// <summary>
    /// A rotation as a quaternion laid out as a C <c>double[4]</c> in the order (x, y, z, w),
    /// the order of <c>frusta_pose.rotation</c> and of <c>UnityEngine.Quaternion</c>.
    /// Blittable; <c>default</c> is the zero quaternion, not the identity: use
    /// <see cref="Identity"/>.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Quaterniond : IEquatable<Quaterniond>
    {
        /// <summary>The x component of the vector part.</summary>
        public double X;
        /// <summary>The y component of the vector part.</summary>
        public double Y;
        /// <summary>The z component of the vector part.</summary>
        public double Z;
        /// <summary>The scalar part.</summary>
        public double W;

        /// <summary>A quaternion from its components (x, y, z, w).</summary>
        /// <param name="x">The x component.</param>
        /// <param name="y">The y component.</param>
        /// <param name="z">The z component.</param>
        /// <param name="w">The scalar part.</param>
        public Quaterniond(double x, double y, double z, double w)
        {
            X = x;
            Y = y;
            Z = z;
            W = w;
        }

        /// <summary>The identity rotation (0, 0, 0, 1).</summary>
        public static Quaterniond Identity => new Quaterniond(0, 0, 0, 1);

        /// <summary>The rotation by <paramref name="radians"/> about a unit axis (right-hand rule).</summary>
        /// <param name="axis">A unit axis.</param>
        /// <param name="radians">The angle in radians.</param>
        /// <returns>The unit quaternion.</returns>
        public static Quaterniond AxisAngle(Vector3d axis, double radians)
        {
            double s = Math.Sin(0.5 * radians);
            return new Quaterniond(axis.X * s, axis.Y * s, axis.Z * s, Math.Cos(0.5 * radians));
        }

        /// <summary>The rotation whose matrix has the columns <paramref name="x"/>, <paramref name="y"/>,
        /// <paramref name="z"/>: the frame with those axes (orthonormal, right-handed).</summary>
        /// <param name="x">The frame's x axis.</param>
        /// <param name="y">The frame's y axis.</param>
        /// <param name="z">The frame's z axis (x cross y).</param>
        /// <returns>The unit quaternion.</returns>
        public static Quaterniond FromAxes(Vector3d x, Vector3d y, Vector3d z)
        {
            // Shepperd's method: divide by the largest of the four candidates
            double trace = x.X + y.Y + z.Z;
            Quaterniond q;
            if (trace > 0)
            {
                double s = 2 * Math.Sqrt(1 + trace);
                q = new Quaterniond((y.Z - z.Y) / s, (z.X - x.Z) / s, (x.Y - y.X) / s, 0.25 * s);
            }
            else if (x.X > y.Y && x.X > z.Z)
            {
                double s = 2 * Math.Sqrt(1 + x.X - y.Y - z.Z);
                q = new Quaterniond(0.25 * s, (y.X + x.Y) / s, (z.X + x.Z) / s, (y.Z - z.Y) / s);
            }
            else if (y.Y > z.Z)
            {
                double s = 2 * Math.Sqrt(1 + y.Y - x.X - z.Z);
                q = new Quaterniond((y.X + x.Y) / s, 0.25 * s, (z.Y + y.Z) / s, (z.X - x.Z) / s);
            }
            else
            {
                double s = 2 * Math.Sqrt(1 + z.Z - x.X - y.Y);
                q = new Quaterniond((z.X + x.Z) / s, (z.Y + y.Z) / s, 0.25 * s, (x.Y - y.X) / s);
            }
            return q.Normalized;
        }

        /// <summary>The norm sqrt(x² + y² + z² + w²); 1 for a rotation.</summary>
        public double Norm => Math.Sqrt(X * X + Y * Y + Z * Z + W * W);

        /// <summary>This quaternion scaled to norm 1.</summary>
        public Quaterniond Normalized
        {
            get
            {
                double n = Norm;
                return new Quaterniond(X / n, Y / n, Z / n, W / n);
            }
        }

        /// <summary>The conjugate (-x, -y, -z, w): the inverse rotation of a unit quaternion.</summary>
        public Quaterniond Conjugate => new Quaterniond(-X, -Y, -Z, W);

        /// <summary>The Hamilton product: the rotation <paramref name="b"/>, then <paramref name="a"/>.</summary>
        /// <param name="a">The outer rotation.</param>
        /// <param name="b">The inner rotation.</param>
        /// <returns>a b</returns>
        public static Quaterniond operator *(Quaterniond a, Quaterniond b) => new Quaterniond(
            a.W * b.X + a.X * b.W + a.Y * b.Z - a.Z * b.Y,
            a.W * b.Y - a.X * b.Z + a.Y * b.W + a.Z * b.X,
            a.W * b.Z + a.X * b.Y - a.Y * b.X + a.Z * b.W,
            a.W * b.W - a.X * b.X - a.Y * b.Y - a.Z * b.Z);

        /// <summary>The vector rotated by this unit quaternion (q v q*).</summary>
        /// <param name="v">The vector.</param>
        /// <returns>The rotated vector.</returns>
        public Vector3d Rotate(Vector3d v)
        {
            var u = new Vector3d(X, Y, Z);
            Vector3d t = 2.0 * Vector3d.Cross(u, v);
            return v + W * t + Vector3d.Cross(u, t);
        }

        /// <summary>Exact component-wise equality.</summary>
        /// <param name="other">The quaternion to compare with.</param>
        /// <returns>true when every component is equal.</returns>
        public bool Equals(Quaterniond other) =>
            X.Equals(other.X) && Y.Equals(other.Y) && Z.Equals(other.Z) && W.Equals(other.W);

        /// <summary>Exact component-wise equality with a boxed <see cref="Quaterniond"/>.</summary>
        /// <param name="obj">The object to compare with.</param>
        /// <returns>true when obj is an equal <see cref="Quaterniond"/>.</returns>
        public override bool Equals(object obj) => obj is Quaterniond q && Equals(q);

        /// <summary>A hash of the four components.</summary>
        /// <returns>The hash code.</returns>
        public override int GetHashCode() =>
            ((X.GetHashCode() * 397 ^ Y.GetHashCode()) * 397 ^ Z.GetHashCode()) * 397 ^ W.GetHashCode();

        /// <summary>"(x, y, z, w)" with round-trip precision.</summary>
        /// <returns>The text.</returns>
        public override string ToString() => $"({X:R}, {Y:R}, {Z:R}, {W:R})";
    }
}
