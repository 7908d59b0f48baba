// SPDX-License-Identifier: MIT
// The displayed hand's mesh against the exact geometry the contacts use: every vertex on
// its part's surface by the native exact distance, every part closed and consistently
// wound, normals outward, and a frame's update free of allocation.
using System;
using System.Collections.Generic;
using Frusta.Binding;
using Xunit;
using static Frusta.Binding.Tests.Assertions;
using Xunit.Abstractions;

namespace Frusta.Binding.Tests
{
    public class HandMeshTests
    {
        // the acceptance bound: 0.1 mm
        const double SurfaceTolerance = 1e-4;
        // how far along a normal a point must leave (or enter) the solid
        const double NormalStep = 1e-4;

        readonly ITestOutputHelper output;

        public HandMeshTests(ITestOutputHelper output) => this.output = output;

        // a grasp-like pose: the palm turned off every axis, each finger flexed differently
        static (FrustaSegment[] segments, FrustaSphere[] spheres) PosedHand()
        {
            using var hand = new Hand();
            hand.SetPalmPose(new FrustaPose(new Vector3d(0.12, -0.35, 0.9),
                                            Quaterniond.AxisAngle(new Vector3d(0.3, -0.5, 0.8) * (1.0 / Math.Sqrt(0.98)), 1.1)));
            var angles = new double[FrustaConstants.HandJointCount];
            for (int f = 0; f < FrustaConstants.FingerCount; ++f)
            {
                angles[4 * f] = 0.1 - 0.05 * f;
                for (int j = 1; j < 4; ++j) angles[4 * f + j] = 0.25 * j + 0.1 * f;
            }
            hand.SetJointAngles(angles);
            var segments = new FrustaSegment[FrustaConstants.HandSegmentCount];
            hand.GetSegments(segments);
            var spheres = new FrustaSphere[hand.PalmSphereCount];
            hand.GetPalmSpheres(spheres);
            return (segments, spheres);
        }

        static Vector3d Read(float[] xyz, int vertex) =>
            new Vector3d(xyz[3 * vertex], xyz[3 * vertex + 1], xyz[3 * vertex + 2]);

        // signed distance from a point to a part's exact solid: the native exact reference
        // for segments, the ball for spheres
        static double Distance(HandMesh mesh, FrustaSegment[] segments, FrustaSphere[] spheres, int part, Vector3d p)
        {
            if (part < mesh.SegmentCount)
                return Geometry.QueryContact(segments[part], new FrustaSphere(p, 0.0)).Distance;
            FrustaSphere s = spheres[part - mesh.SegmentCount];
            return (p - s.Center).Length - s.Radius;
        }

        // the nearest point of a part's axis (a segment's DE, a sphere's centre)
        static Vector3d AxisFoot(HandMesh mesh, FrustaSegment[] segments, FrustaSphere[] spheres, int part, Vector3d p)
        {
            if (part >= mesh.SegmentCount) return spheres[part - mesh.SegmentCount].Center;
            FrustaSegment s = segments[part];
            Vector3d de = s.Proximal - s.Distal;
            double l2 = Vector3d.Dot(de, de);
            double k = l2 > 0 ? Math.Clamp(Vector3d.Dot(p - s.Distal, de) / l2, 0.0, 1.0) : 0.0;
            return s.Distal + k * de;
        }

        sealed class Built
        {
            public HandMesh Mesh;
            public float[] Positions, Normals;
            public int[] Indices;
            public Vector3d Min, Max;
        }

        static Built Build(FrustaSegment[] segments, FrustaSphere[] spheres, HandMeshFrame frame = HandMeshFrame.Frusta,
                           int slices = HandMesh.DefaultSlices, int arcRings = HandMesh.DefaultArcRings)
        {
            var b = new Built { Mesh = new HandMesh(segments.Length, spheres.Length, slices, arcRings, frame) };
            b.Positions = new float[3 * b.Mesh.VertexCount];
            b.Normals = new float[3 * b.Mesh.VertexCount];
            b.Indices = new int[b.Mesh.IndexCount];
            b.Mesh.WriteTriangles(b.Indices);
            b.Mesh.Update(segments, spheres, b.Positions, b.Normals, out b.Min, out b.Max);
            return b;
        }

        // every check of the acceptance on one mesh (Frusta's frame); returns the largest
        // vertex distance from its part's surface
        static double CheckMesh(Built b, FrustaSegment[] segments, FrustaSphere[] spheres)
        {
            HandMesh mesh = b.Mesh;
            double worst = 0.0;
            for (int part = 0; part < mesh.PartCount; ++part)
            {
                int v0 = mesh.PartVertexStart(part), vn = mesh.PartVertexCount(part);
                for (int v = v0; v < v0 + vn; ++v)
                {
                    Vector3d p = Read(b.Positions, v), n = Read(b.Normals, v);
                    double d = Distance(mesh, segments, spheres, part, p);
                    worst = Math.Max(worst, Math.Abs(d));
                    Assert.True(Math.Abs(d) <= SurfaceTolerance, $"part {part} vertex {v} at {p} is {d:R} m off its surface");
                    Near(1.0, n.Length, 1e-6, $"part {part} vertex {v}: normal length");
                    // outward: away from the axis, out of the solid ahead and into it behind
                    // (a vertex on the axis, to float rounding, is the apex of a ball of no radius: it has no outside)
                    Vector3d foot = AxisFoot(mesh, segments, spheres, part, p);
                    if ((p - foot).Length <= 1e-6) continue;
                    Assert.True(Vector3d.Dot(n, p - foot) > 0, $"part {part} vertex {v}: normal {n} points towards the axis");
                    Assert.True(Distance(mesh, segments, spheres, part, p + NormalStep * n) > 0,
                                $"part {part} vertex {v}: a step along the normal stays inside");
                    Assert.True(Distance(mesh, segments, spheres, part, p - NormalStep * n) < 0,
                                $"part {part} vertex {v}: a step against the normal stays outside");
                }
                CheckClosed(b, part);
            }
            // the box holds every vertex
            for (int v = 0; v < mesh.VertexCount; ++v)
            {
                Vector3d p = Read(b.Positions, v);
                Assert.True(p.X >= b.Min.X && p.Y >= b.Min.Y && p.Z >= b.Min.Z &&
                            p.X <= b.Max.X && p.Y <= b.Max.Y && p.Z <= b.Max.Z, $"vertex {v} outside the bounds");
            }
            return worst;
        }

        // closed and consistently wound: every edge of the part's triangles is used by exactly
        // two triangles, once in each direction; a closed genus-0 surface (V - E + F = 2); each
        // triangle's face normal agrees with its vertex normals
        static void CheckClosed(Built b, int part)
        {
            HandMesh mesh = b.Mesh;
            int v0 = mesh.PartVertexStart(part), vn = mesh.PartVertexCount(part);
            int t0 = mesh.PartTriangleStart(part), tn = mesh.PartTriangleCount(part);
            var directed = new Dictionary<(int, int), int>();
            for (int t = t0; t < t0 + tn; ++t)
            {
                for (int k = 0; k < 3; ++k)
                {
                    int i = b.Indices[3 * t + k], j = b.Indices[3 * t + (k + 1) % 3];
                    Assert.True(i >= v0 && i < v0 + vn, $"part {part} triangle {t} uses vertex {i} of another part");
                    Assert.NotEqual(i, j);
                    directed.TryGetValue((i, j), out int c);
                    directed[(i, j)] = c + 1;
                }
                Vector3d a = Read(b.Positions, b.Indices[3 * t]), p1 = Read(b.Positions, b.Indices[3 * t + 1]),
                         p2 = Read(b.Positions, b.Indices[3 * t + 2]);
                Vector3d face = Vector3d.Cross(p1 - a, p2 - a);
                // slivers (a ring collapsed onto a pole in a degenerate solid) have no direction
                if (face.Length > 1e-12)
                {
                    Vector3d normals = Read(b.Normals, b.Indices[3 * t]) + Read(b.Normals, b.Indices[3 * t + 1]) +
                                       Read(b.Normals, b.Indices[3 * t + 2]);
                    Assert.True(Vector3d.Dot(face, normals) > 0, $"part {part} triangle {t} is wound inwards");
                }
            }
            foreach (var e in directed)
            {
                Assert.True(e.Value == 1, $"part {part}: edge {e.Key} is used {e.Value} times in one direction");
                Assert.True(directed.ContainsKey((e.Key.Item2, e.Key.Item1)),
                            $"part {part}: edge {e.Key} has no twin: the part is open there");
            }
            int edges = directed.Count / 2;
            Assert.Equal(2, vn - edges + tn);
        }

        static void Near(double expected, double actual, double tolerance, string what) =>
            Assert.True(Math.Abs(expected - actual) <= tolerance, $"{what}: expected {expected:R}, got {actual:R}");

        [Fact]
        public void APosedHandsMeshLiesOnItsSolidsClosedAndOutward()
        {
            var (segments, spheres) = PosedHand();
            Assert.True(spheres.Length > 0, "the default hand has palm spheres");
            Built b = Build(segments, spheres);
            double worst = CheckMesh(b, segments, spheres);
            output.WriteLine($"default tessellation: {b.Mesh.SegmentCount} segments + {b.Mesh.SphereCount} palm spheres, " +
                             $"{b.Mesh.VertexCount} vertices, {b.Mesh.TriangleCount} triangles; " +
                             $"largest vertex distance from the exact surface {worst * 1e3:G3} mm");
            // floats a metre from the origin: rounding only
            Assert.True(worst < 1e-6, $"{worst:R} m is more than float rounding");

            // coarser and finer tessellations obey the same rules
            CheckMesh(Build(segments, spheres, slices: 3, arcRings: 1), segments, spheres);
            CheckMesh(Build(segments, spheres, slices: 40, arcRings: 9), segments, spheres);
        }

        [Fact]
        public void UnitysFrameMirrorsThePositionsAndTurnsTheWinding()
        {
            var (segments, spheres) = PosedHand();
            Built frusta = Build(segments, spheres);
            Built unity = Build(segments, spheres, HandMeshFrame.Unity);
            for (int v = 0; v < frusta.Mesh.VertexCount; ++v)
            {
                Assert.Equal(CoordinateConversion.VectorToUnity(Read(frusta.Positions, v)), Read(unity.Positions, v));
                Assert.Equal(CoordinateConversion.VectorToUnity(Read(frusta.Normals, v)), Read(unity.Normals, v));
            }
            int[] flipped = (int[])frusta.Indices.Clone();
            CoordinateConversion.FlipWinding(flipped);
            Assert.Equal(flipped, unity.Indices);
            Assert.Equal(CoordinateConversion.VectorToUnity(frusta.Min).X, unity.Min.X);
            Assert.Equal(-frusta.Max.Z, unity.Min.Z);
            Assert.Equal(-frusta.Min.Z, unity.Max.Z);
            // Unity's numbers wind clockwise seen from outside in its left-handed frame: the plain
            // cross product of a triangle's edges still points out
            for (int t = 0; t < unity.Mesh.TriangleCount; ++t)
            {
                Vector3d a = Read(unity.Positions, unity.Indices[3 * t]);
                Vector3d face = Vector3d.Cross(Read(unity.Positions, unity.Indices[3 * t + 1]) - a,
                                               Read(unity.Positions, unity.Indices[3 * t + 2]) - a);
                Vector3d n = Read(unity.Normals, unity.Indices[3 * t]);
                if (face.Length > 1e-12) Assert.True(Vector3d.Dot(face, n) > 0, $"triangle {t} faces inwards in Unity's frame");
            }
        }

        // segments no hand has, for the envelope's other cases: the reversed taper, equal
        // radii, a ball holding the frustum, a ball holding everything, a point-like tip, a
        // zero-length segment, a steep cone
        [Theory]
        [InlineData(0.02, 0.006, 0.009, "the distal ball the larger")]
        [InlineData(0.03, 0.008, 0.008, "a capsule")]
        [InlineData(0.009, 0.012, 0.007, "the proximal ball holds the frustum")]
        [InlineData(0.004, 0.012, 0.007, "the proximal ball holds the distal one")]
        [InlineData(0.009, 0.007, 0.012, "the distal ball holds the frustum")]
        [InlineData(0.03, 0.008, 0.0, "a cone to a point")]
        [InlineData(0.0, 0.008, 0.005, "no length")]
        [InlineData(0.012, 0.011, 0.001, "a steep cone")]
        public void EverySegmentShapeMeshesOntoItsSurface(double length, double proximalRadius, double distalRadius, string what)
        {
            Vector3d axis = new Vector3d(0.2, -0.7, 0.4) * (1.0 / new Vector3d(0.2, -0.7, 0.4).Length);
            var origin = new Vector3d(-0.03, 0.05, 0.2);
            var segments = new[]
            {
                new FrustaSegment { Proximal = origin + length * axis, Distal = origin,
                                    ProximalRadius = proximalRadius, DistalRadius = distalRadius },
            };
            var spheres = new[] { new FrustaSphere(origin, 0.004) };
            double worst = CheckMesh(Build(segments, spheres), segments, spheres);
            Assert.True(worst < 1e-6, $"{what}: {worst:R} m off");
        }

        [Fact]
        public void TheRingsFollowTheSegmentWithoutTwisting()
        {
            // a segment sweeping a cone, through directions where the world axis least along it
            // changes: the first vertex of its distal end circle (normal: the ring's first radial
            // direction) turns a little each degree, never jumps about the axis
            var mesh = new HandMesh(1, 0);
            var positions = new float[3 * mesh.VertexCount];
            var normals = new float[3 * mesh.VertexCount];
            int endCircle = 1 + mesh.ArcRings * mesh.Slices;  // the first ring of the distal arc
            Vector3d previous = default;
            for (int i = 0; i <= 180; ++i)
            {
                double angle = i * Math.PI / 180.0;
                var dir = new Vector3d(0.5, Math.Cos(angle), Math.Sin(angle));
                dir = dir * (1.0 / dir.Length);
                var segments = new[] { new FrustaSegment { Proximal = 0.04 * dir, Distal = default, ProximalRadius = 0.01, DistalRadius = 0.008 } };
                mesh.Update(segments, ReadOnlySpan<FrustaSphere>.Empty, positions, normals, out _, out _);
                Vector3d radial = Read(normals, endCircle);
                Near(0.0, Vector3d.Dot(radial, dir), 1e-6, $"step {i}: the end circle's normal is radial");
                if (i > 0) Assert.True(Vector3d.Dot(radial, previous) > 0.99, $"step {i}: the rings jumped about the axis");
                previous = radial;
            }
        }

        [Fact]
        public void AFramesUpdateAllocatesNothing()
        {
            using var world = new World();
            FrustaHandId hand = world.CreateHand(FrustaHandDef.Default);
            var angles = new double[FrustaConstants.HandJointCount];
            for (int j = 0; j < angles.Length; ++j) angles[j] = j % 4 == 0 ? 0.05 : 0.4;
            world.SetHaptic(hand, new FrustaPose(new Vector3d(0.1, -0.2, 0.3), Quaterniond.Identity), angles);
            world.Step(2);
            var state = new FrustaWorldState();
            world.Read(ref state);

            // what FrustaHandMesh does: size once, then per frame read the graphic hand and update
            var segments = new FrustaSegment[FrustaConstants.HandSegmentCount];
            var spheres = new FrustaSphere[world.GetHandPalmSpheres(hand, FrustaHandKind.Graphic, Span<FrustaSphere>.Empty)];
            var mesh = new HandMesh(segments.Length, spheres.Length, frame: HandMeshFrame.Unity);
            var positions = new float[3 * mesh.VertexCount];
            var normals = new float[3 * mesh.VertexCount];
            var indices = new int[mesh.IndexCount];
            mesh.WriteTriangles(indices);
            void Frame()
            {
                world.GetHandSegments(hand, FrustaHandKind.Graphic, segments);
                world.GetHandPalmSpheres(hand, FrustaHandKind.Graphic, spheres);
                mesh.Update(segments, spheres, positions, normals, out _, out _);
            }
            AllocatesNothing(Frame);
        }

        [Fact]
        public void SizesFollowThePartsAndTheTessellation()
        {
            var mesh = new HandMesh(FrustaConstants.HandSegmentCount, 10);
            Assert.Equal(2 + 2 * 4 * 16, mesh.SegmentVertexCount);
            Assert.Equal(2 + 7 * 16, mesh.SphereVertexCount);
            Assert.Equal(15 * 130 + 10 * 114, mesh.VertexCount);
            Assert.Equal(15 * 256 + 10 * 224, mesh.TriangleCount);
            Assert.Equal(3 * mesh.TriangleCount, mesh.IndexCount);
            Assert.Equal(15 * 130, mesh.PartVertexStart(15));
            Assert.Equal(15 * 130 + 114, mesh.PartVertexStart(16));
            Assert.Equal(15 * 256 + 224, mesh.PartTriangleStart(16));

            Assert.Throws<ArgumentOutOfRangeException>(() => new HandMesh(-1, 0));
            Assert.Throws<ArgumentOutOfRangeException>(() => new HandMesh(1, 0, slices: 2));
            Assert.Throws<ArgumentOutOfRangeException>(() => new HandMesh(1, 0, arcRings: 0));
            var e = Assert.Throws<ArgumentException>(() => mesh.WriteTriangles(new int[10]));
            Assert.Equal("indices", e.ParamName);
            var positions = new float[3 * mesh.VertexCount];
            e = Assert.Throws<ArgumentException>(() => mesh.Update(new FrustaSegment[14], new FrustaSphere[10], positions, positions, out _, out _));
            Assert.Equal("segments", e.ParamName);
            e = Assert.Throws<ArgumentException>(() => mesh.Update(new FrustaSegment[15], new FrustaSphere[10], positions, new float[3], out _, out _));
            Assert.Equal("normals", e.ParamName);
        }
    }
}
