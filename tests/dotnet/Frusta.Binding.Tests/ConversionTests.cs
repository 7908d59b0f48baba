// SPDX-License-Identifier: MIT
// Frusta's right-handed frame against Unity's left-handed one, and right hands mirrored
// into left hands, checked on the native hand model.
using System;
using Frusta.Binding;
using Xunit;
using static Frusta.Binding.Tests.Assertions;

namespace Frusta.Binding.Tests
{
    public class ConversionTests
    {
        const int Cases = 1000;

        static Vector3d RandomVector(Random r, double scale) =>
            new Vector3d(scale * (2 * r.NextDouble() - 1), scale * (2 * r.NextDouble() - 1), scale * (2 * r.NextDouble() - 1));

        internal static Quaterniond RandomRotation(Random r)
        {
            // uniform over rotations (Shoemake)
            double u1 = r.NextDouble(), u2 = 2 * Math.PI * r.NextDouble(), u3 = 2 * Math.PI * r.NextDouble();
            double a = Math.Sqrt(1 - u1), b = Math.Sqrt(u1);
            return new Quaterniond(a * Math.Sin(u2), a * Math.Cos(u2), b * Math.Sin(u3), b * Math.Cos(u3));
        }

        /// <summary>The matrix of a unit quaternion, row-major.</summary>
        static double[,] Matrix(Quaterniond q)
        {
            var m = new double[3, 3];
            var axes = new[] { new Vector3d(1, 0, 0), new Vector3d(0, 1, 0), new Vector3d(0, 0, 1) };
            for (int c = 0; c < 3; ++c)
            {
                Vector3d col = q.Rotate(axes[c]);
                m[0, c] = col.X;
                m[1, c] = col.Y;
                m[2, c] = col.Z;
            }
            return m;
        }

        [Fact]
        public void AReactionTorqueMovedToTheCentreOfMassIsWhatPhysXNeedsInUnitysFrame()
        {
            var r = new Random(18);
            for (int i = 0; i < Cases; ++i)
            {
                // forces at points; the world reports their sum and torque about the object's origin
                Vector3d origin = RandomVector(r, 1), centre = RandomVector(r, 1);
                Vector3d force = Vector3d.Zero, aboutOrigin = Vector3d.Zero, aboutCentre = Vector3d.Zero;
                Vector3d unityAboutCentre = Vector3d.Zero;
                for (int k = 0; k < 3; ++k)
                {
                    Vector3d p = RandomVector(r, 1), f = RandomVector(r, 10);
                    force += f;
                    aboutOrigin += Vector3d.Cross(p - origin, f);
                    aboutCentre += Vector3d.Cross(p - centre, f);
                    // what Unity's Vector3.Cross makes of the same forces in its frame
                    unityAboutCentre += Vector3d.Cross(CoordinateConversion.VectorToUnity(p) - CoordinateConversion.VectorToUnity(centre),
                                                       CoordinateConversion.VectorToUnity(f));
                }
                Vector3d moved = Wrench.TorqueAbout(aboutOrigin, force, origin, centre);
                Near(aboutCentre, moved, 1e-12, "torque about the centre of mass");
                Near(unityAboutCentre, CoordinateConversion.AxialToUnity(moved), 1e-12, "in Unity's frame (Rigidbody.AddTorque)");
            }
        }

        [Fact]
        public void PositionsAndRotationsRoundTrip()
        {
            var r = new Random(20261201);
            for (int i = 0; i < Cases; ++i)
            {
                Vector3d p = RandomVector(r, 10);
                Quaterniond q = RandomRotation(r);
                Near(p, CoordinateConversion.VectorFromUnity(CoordinateConversion.VectorToUnity(p)), 0, "position");
                Near(p, CoordinateConversion.AxialFromUnity(CoordinateConversion.AxialToUnity(p)), 0, "axial");
                Assert.Equal(q, CoordinateConversion.RotationFromUnity(CoordinateConversion.RotationToUnity(q)));
                var pose = new FrustaPose(p, q);
                FrustaPose back = CoordinateConversion.PoseFromUnity(CoordinateConversion.PoseToUnity(pose));
                Assert.Equal(pose.Position, back.Position);
                Assert.Equal(pose.Rotation, back.Rotation);
            }
        }

        [Fact]
        public void ConversionCommutesWithRotatingAndTransforming()
        {
            var r = new Random(7);
            for (int i = 0; i < Cases; ++i)
            {
                Vector3d v = RandomVector(r, 1);
                Quaterniond q = RandomRotation(r);
                var pose = new FrustaPose(RandomVector(r, 2), q);
                // rotating in Frusta then converting = converting then rotating in Unity
                Near(CoordinateConversion.VectorToUnity(q.Rotate(v)),
                     CoordinateConversion.RotationToUnity(q).Rotate(CoordinateConversion.VectorToUnity(v)), 1e-12, "rotated vector");
                Near(CoordinateConversion.VectorToUnity(pose.TransformPoint(v)),
                     CoordinateConversion.PoseToUnity(pose).TransformPoint(CoordinateConversion.VectorToUnity(v)), 1e-12, "transformed point");
                // the converted quaternion is a unit quaternion with matrix S R S
                Quaterniond u = CoordinateConversion.RotationToUnity(q);
                Near(1.0, u.Norm, 1e-12, "norm");
                double[,] m = Matrix(q), mu = Matrix(u);
                double[] s = { 1, 1, -1 };
                for (int a = 0; a < 3; ++a)
                    for (int b = 0; b < 3; ++b)
                        Near(s[a] * m[a, b] * s[b], mu[a, b], 1e-12, $"matrix[{a},{b}]");
                // a torque r x F converts as an axial vector: it equals the same cross-product
                // formula (Unity's Vector3.Cross) applied to the converted arm and force
                Vector3d arm = RandomVector(r, 1), force = RandomVector(r, 1);
                Near(CoordinateConversion.AxialToUnity(Vector3d.Cross(arm, force)),
                     Vector3d.Cross(CoordinateConversion.VectorToUnity(arm), CoordinateConversion.VectorToUnity(force)),
                     1e-12, "torque");
            }
        }

        [Fact]
        public void FlippedWindingKeepsTrianglesFacingOutAfterConversion()
        {
            float[] v = Box.Vertices(0.01);
            int[] tris = (int[])Box.Triangles.Clone();
            for (int i = 0; i < 8; ++i) v[3 * i + 2] = -v[3 * i + 2];
            CoordinateConversion.FlipWinding(tris);
            for (int t = 0; t < tris.Length; t += 3)
            {
                Vector3d P(int k) => new Vector3d(v[3 * tris[k]], v[3 * tris[k] + 1], v[3 * tris[k] + 2]);
                Vector3d a = P(t), b = P(t + 1), c = P(t + 2);
                Vector3d normal = Vector3d.Cross(b - a, c - a);
                Vector3d centre = (a + b + c) * (1.0 / 3);
                Assert.True(Vector3d.Dot(normal, centre) > 0, $"triangle {t / 3} faces in");
            }
        }

        [Theory]
        [InlineData(Axis.X)]
        [InlineData(Axis.Y)]
        [InlineData(Axis.Z)]
        public void AMirroredRightHandIsTheNativeLeftHand(Axis axis)
        {
            var r = new Random(100 + (int)axis);
            FrustaHandDef rightDef = FrustaHandDef.Default;
            FrustaHandDef leftDef = FrustaHandDef.Default;
            leftDef.Side = FrustaHandSide.Left;
            using var right = new Hand(rightDef);
            using var left = new Hand(leftDef);
            var angles = new double[20];
            var rs = new FrustaSegment[15];
            var ls = new FrustaSegment[15];
            var rp = new FrustaSphere[right.PalmSphereCount];
            var lp = new FrustaSphere[left.PalmSphereCount];
            Assert.Equal(rp.Length, lp.Length);
            for (int i = 0; i < 50; ++i)
            {
                var palm = new FrustaPose(RandomVector(r, 0.5), RandomRotation(r));
                for (int j = 0; j < 20; ++j) angles[j] = (j % 4 == 0 ? 0.3 : 1.2) * r.NextDouble() - (j % 4 == 0 ? 0.15 : 0.1);
                double offset = 0.2 * r.NextDouble() - 0.1;
                right.SetPalmPose(palm);
                right.SetJointAngles(angles);
                left.SetPalmPose(CoordinateConversion.MirrorHandPose(palm, axis, offset));
                left.SetJointAngles(angles); // the same anatomical motion on both sides
                right.GetSegments(rs);
                left.GetSegments(ls);
                for (int s = 0; s < 15; ++s)
                {
                    Near(CoordinateConversion.MirrorPoint(rs[s].Proximal, axis, offset), ls[s].Proximal, 1e-12, $"segment {s} D");
                    Near(CoordinateConversion.MirrorPoint(rs[s].Distal, axis, offset), ls[s].Distal, 1e-12, $"segment {s} E");
                    Assert.Equal(rs[s].ProximalRadius, ls[s].ProximalRadius);
                    Assert.Equal(rs[s].DistalRadius, ls[s].DistalRadius);
                }
                right.GetPalmSpheres(rp);
                left.GetPalmSpheres(lp);
                for (int s = 0; s < rp.Length; ++s)
                    Near(CoordinateConversion.MirrorPoint(rp[s].Center, axis, offset), lp[s].Center, 1e-12, $"palm sphere {s}");
                // and mirroring twice gives the hand back
                FrustaPose twice = CoordinateConversion.MirrorHandPose(CoordinateConversion.MirrorHandPose(palm, axis, offset), axis, offset);
                Near(palm.Position, twice.Position, 1e-12, "twice");
                SameRotation(palm.Rotation, twice.Rotation, 1e-12, "twice");
            }
        }

        [Fact]
        public void ARightHandSeenInUnityIsTheMirrorOfTheLeftHand()
        {
            // Unity's frame is Frusta's mirrored through z: a right hand's points converted to
            // Unity are the points of the left hand posed by MirrorHandPose(palm, Z)
            var r = new Random(3);
            using var right = new Hand();
            FrustaHandDef leftDef = FrustaHandDef.Default;
            leftDef.Side = FrustaHandSide.Left;
            using var left = new Hand(leftDef);
            var palm = new FrustaPose(RandomVector(r, 0.3), RandomRotation(r));
            right.SetPalmPose(palm);
            left.SetPalmPose(CoordinateConversion.MirrorHandPose(palm, Axis.Z));
            var rs = new FrustaSegment[15];
            var ls = new FrustaSegment[15];
            right.GetSegments(rs);
            left.GetSegments(ls);
            for (int s = 0; s < 15; ++s)
                Near(CoordinateConversion.VectorToUnity(rs[s].Distal), ls[s].Distal, 1e-12, $"segment {s}");
        }
    }
}
