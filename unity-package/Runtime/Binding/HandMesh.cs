// SPDX-License-Identifier: MIT
using System;

namespace Frusta.Binding
{
    /// <summary>The frame <see cref="HandMesh"/> writes its vertices in.</summary>
    public enum HandMeshFrame
    {
        /// <summary>Frusta's right-handed frame; triangles counter-clockwise seen from outside.</summary>
        Frusta = 0,
        /// <summary>Unity's left-handed frame (<see cref="CoordinateConversion.VectorToUnity"/> on every
        /// position and normal, and the winding turned with <see cref="CoordinateConversion.FlipWinding"/>),
        /// ready for <c>UnityEngine.Mesh</c>.</summary>
        Unity = 1,
    }

    /// <summary>
    /// A triangle mesh of a hand's exact solids, for display: one closed part per finger segment
    /// (the segment solid: its frustum union its two end balls, so the joint balls and the
    /// hemispherical fingertips come with the segments) and one per palm sphere. Each part is a
    /// surface of revolution whose every vertex lies on the part's true surface, with smooth
    /// outward normals. The layout (vertex and triangle counts, triangle indices) depends only
    /// on the part counts and the tessellation, so the caller sizes its arrays once
    /// (<see cref="VertexCount"/>, <see cref="IndexCount"/>), writes the triangles once
    /// (<see cref="WriteTriangles"/>) and calls <see cref="Update"/> each frame, which allocates
    /// nothing.
    /// <para>The segment solid's section at each point of its axis is a disc, so its surface is
    /// the revolved envelope of the three parts' section radii: the far half of the smaller ball,
    /// the frustum's straight side, and the larger ball from where it leaves the side (the
    /// side passes through the balls' end circles, as frusta.h defines it, not tangent to them:
    /// the larger ball stands out of it by up to r (1 / cos alpha - 1) near its end, and the
    /// solid has two shallow creases, where the side meets that ball and at the smaller ball's
    /// end circle). Where one ball swallows the frustum or the other ball, the envelope is
    /// that of the balls alone. Vertices are placed on those arcs and on the side's end circles;
    /// each vertex's normal is its ball's radial direction, which shades the side band smoothly.</para>
    /// <para>Thread: one thread at a time per instance (it keeps each segment's last frame, so
    /// the tessellation does not twist from frame to frame).</para>
    /// </summary>
    public sealed class HandMesh
    {
        /// <summary>Default vertices around each ring (16).</summary>
        public const int DefaultSlices = 16;
        /// <summary>Default rings per ball arc, poles excluded (4): a segment has twice as many
        /// rings, a sphere one fewer.</summary>
        public const int DefaultArcRings = 4;

        // below this axis length (metres) a segment's axis is taken from its last frame
        const double MinAxisLength = 1e-12;

        readonly int segmentCount, sphereCount, slices, arcRings;
        readonly HandMeshFrame frame;
        readonly double[] cosTheta, sinTheta;
        readonly Vector3d[] axes, references;  // per segment: last axis and perpendicular

        /// <summary>A mesh layout for <paramref name="segmentCount"/> segments and
        /// <paramref name="sphereCount"/> spheres.</summary>
        /// <param name="segmentCount">Segment parts (a hand has <see cref="FrustaConstants.HandSegmentCount"/>), &gt;= 0.</param>
        /// <param name="sphereCount">Sphere parts (a hand's palm spheres, <see cref="World.GetHandPalmSpheres"/>
        /// with an empty span), &gt;= 0.</param>
        /// <param name="slices">Vertices around each ring, 3..1024.</param>
        /// <param name="arcRings">Rings per ball arc, poles excluded, 1..256.</param>
        /// <param name="frame">The frame vertices, normals and winding are written in.</param>
        /// <exception cref="ArgumentOutOfRangeException">A count out of range, or more than
        /// <see cref="int.MaxValue"/> indices.</exception>
        public HandMesh(int segmentCount, int sphereCount, int slices = DefaultSlices, int arcRings = DefaultArcRings,
                        HandMeshFrame frame = HandMeshFrame.Frusta)
        {
            if (segmentCount < 0) throw new ArgumentOutOfRangeException(nameof(segmentCount), segmentCount, "must be >= 0");
            if (sphereCount < 0) throw new ArgumentOutOfRangeException(nameof(sphereCount), sphereCount, "must be >= 0");
            if (slices < 3 || slices > 1024) throw new ArgumentOutOfRangeException(nameof(slices), slices, "must be 3..1024");
            if (arcRings < 1 || arcRings > 256) throw new ArgumentOutOfRangeException(nameof(arcRings), arcRings, "must be 1..256");
            if (frame != HandMeshFrame.Frusta && frame != HandMeshFrame.Unity)
                throw new ArgumentOutOfRangeException(nameof(frame), frame, "not a HandMeshFrame");
            long indices = 3L * ((long)segmentCount * SegmentTriangles(slices, arcRings) +
                                 (long)sphereCount * SphereTriangles(slices, arcRings));
            if (indices > int.MaxValue)
                throw new ArgumentOutOfRangeException(nameof(segmentCount), "the mesh would need more than int.MaxValue indices");
            this.segmentCount = segmentCount;
            this.sphereCount = sphereCount;
            this.slices = slices;
            this.arcRings = arcRings;
            this.frame = frame;
            cosTheta = new double[slices];
            sinTheta = new double[slices];
            for (int j = 0; j < slices; ++j)
            {
                double theta = 2.0 * Math.PI * j / slices;
                cosTheta[j] = Math.Cos(theta);
                sinTheta[j] = Math.Sin(theta);
            }
            axes = new Vector3d[segmentCount];
            references = new Vector3d[segmentCount];
        }

        /// <summary>Segment parts, first in the vertex and index arrays.</summary>
        public int SegmentCount => segmentCount;
        /// <summary>Sphere parts, after the segments.</summary>
        public int SphereCount => sphereCount;
        /// <summary>Vertices around each ring.</summary>
        public int Slices => slices;
        /// <summary>Rings per ball arc, poles excluded.</summary>
        public int ArcRings => arcRings;
        /// <summary>The frame vertices are written in.</summary>
        public HandMeshFrame Frame => frame;

        /// <summary>Vertices of one segment part: two poles and 2 <see cref="ArcRings"/> rings.</summary>
        public int SegmentVertexCount => 2 + 2 * arcRings * slices;
        /// <summary>Vertices of one sphere part: two poles and 2 <see cref="ArcRings"/> - 1 rings.</summary>
        public int SphereVertexCount => 2 + (2 * arcRings - 1) * slices;
        /// <summary>Triangles of one segment part.</summary>
        public int SegmentTriangleCount => SegmentTriangles(slices, arcRings);
        /// <summary>Triangles of one sphere part.</summary>
        public int SphereTriangleCount => SphereTriangles(slices, arcRings);

        /// <summary>Vertices in all: the length of the position and normal arrays is 3 times this.</summary>
        public int VertexCount => segmentCount * SegmentVertexCount + sphereCount * SphereVertexCount;
        /// <summary>Triangles in all.</summary>
        public int TriangleCount => segmentCount * SegmentTriangleCount + sphereCount * SphereTriangleCount;
        /// <summary>Triangle indices in all (3 per triangle): the length of the index array.</summary>
        public int IndexCount => 3 * TriangleCount;

        /// <summary>Parts in all: the segments, then the spheres.</summary>
        public int PartCount => segmentCount + sphereCount;

        /// <summary>The first vertex of a part (segments first, then spheres).</summary>
        /// <param name="part">0..<see cref="PartCount"/> - 1.</param>
        /// <returns>A vertex index.</returns>
        public int PartVertexStart(int part) =>
            part <= segmentCount ? part * SegmentVertexCount
                                 : segmentCount * SegmentVertexCount + (part - segmentCount) * SphereVertexCount;

        /// <summary>The vertices of a part.</summary>
        /// <param name="part">0..<see cref="PartCount"/> - 1.</param>
        /// <returns>A vertex count.</returns>
        public int PartVertexCount(int part) => part < segmentCount ? SegmentVertexCount : SphereVertexCount;

        /// <summary>The first triangle of a part (its indices start at 3 times this).</summary>
        /// <param name="part">0..<see cref="PartCount"/> - 1.</param>
        /// <returns>A triangle index.</returns>
        public int PartTriangleStart(int part) =>
            part <= segmentCount ? part * SegmentTriangleCount
                                 : segmentCount * SegmentTriangleCount + (part - segmentCount) * SphereTriangleCount;

        /// <summary>The triangles of a part.</summary>
        /// <param name="part">0..<see cref="PartCount"/> - 1.</param>
        /// <returns>A triangle count.</returns>
        public int PartTriangleCount(int part) => part < segmentCount ? SegmentTriangleCount : SphereTriangleCount;

        static int SegmentTriangles(int slices, int arcRings) => 2 * slices * (2 * arcRings);
        static int SphereTriangles(int slices, int arcRings) => 2 * slices * (2 * arcRings - 1);

        /// <summary>Write the triangle indices, which never change: once, after sizing the array.
        /// Counter-clockwise seen from outside in Frusta's frame; reversed in Unity's.</summary>
        /// <param name="indices">At least <see cref="IndexCount"/> long.</param>
        /// <exception cref="ArgumentException">The span is too short.</exception>
        public void WriteTriangles(Span<int> indices)
        {
            if (indices.Length < IndexCount)
                throw new ArgumentException($"holds {indices.Length} indices, the mesh has {IndexCount}", nameof(indices));
            int t = 0;
            for (int part = 0; part < PartCount; ++part)
            {
                int rings = part < segmentCount ? 2 * arcRings : 2 * arcRings - 1;
                WritePartTriangles(indices, ref t, PartVertexStart(part), rings);
            }
            if (frame == HandMeshFrame.Unity) CoordinateConversion.FlipWinding(indices.Slice(0, IndexCount));
        }

        // pole, rings of `slices` vertices from the top pole down, pole: fans at the poles,
        // quads between rings; with the ring's angle growing towards c = a x b seen from
        // outside, (upper j, lower j, lower j+1) turns counter-clockwise
        void WritePartTriangles(Span<int> indices, ref int t, int start, int rings)
        {
            int top = start, bottom = start + 1 + rings * slices;
            for (int j = 0; j < slices; ++j)
            {
                int k = (j + 1) % slices;
                indices[t++] = top;
                indices[t++] = start + 1 + j;
                indices[t++] = start + 1 + k;
            }
            for (int r = 0; r + 1 < rings; ++r)
            {
                int upper = start + 1 + r * slices, lower = upper + slices;
                for (int j = 0; j < slices; ++j)
                {
                    int k = (j + 1) % slices;
                    indices[t++] = upper + j;
                    indices[t++] = lower + j;
                    indices[t++] = lower + k;
                    indices[t++] = upper + j;
                    indices[t++] = lower + k;
                    indices[t++] = upper + k;
                }
            }
            int last = start + 1 + (rings - 1) * slices;
            for (int j = 0; j < slices; ++j)
            {
                int k = (j + 1) % slices;
                indices[t++] = last + j;
                indices[t++] = bottom;
                indices[t++] = last + k;
            }
        }

        /// <summary>
        /// Place every vertex for the given parts (world coordinates, Frusta's frame, as
        /// <see cref="World.GetHandSegments"/> and <see cref="World.GetHandPalmSpheres"/> give them)
        /// and write positions and unit normals, three floats per vertex, in <see cref="Frame"/>.
        /// Allocation-free.
        /// </summary>
        /// <param name="segments">Exactly <see cref="SegmentCount"/> segments; radii &gt;= 0.</param>
        /// <param name="spheres">Exactly <see cref="SphereCount"/> spheres; radii &gt;= 0.</param>
        /// <param name="positions">At least 3 <see cref="VertexCount"/> floats, metres.</param>
        /// <param name="normals">At least 3 <see cref="VertexCount"/> floats, unit outward normals.</param>
        /// <param name="boundsMin">The smallest corner of the vertices' box, metres, in <see cref="Frame"/>.</param>
        /// <param name="boundsMax">The largest corner.</param>
        /// <exception cref="ArgumentException">A span of the wrong size.</exception>
        public void Update(ReadOnlySpan<FrustaSegment> segments, ReadOnlySpan<FrustaSphere> spheres,
                           Span<float> positions, Span<float> normals, out Vector3d boundsMin, out Vector3d boundsMax)
        {
            if (segments.Length != segmentCount)
                throw new ArgumentException($"holds {segments.Length} segments, the mesh has {segmentCount}", nameof(segments));
            if (spheres.Length != sphereCount)
                throw new ArgumentException($"holds {spheres.Length} spheres, the mesh has {sphereCount}", nameof(spheres));
            int floats = 3 * VertexCount;
            if (positions.Length < floats)
                throw new ArgumentException($"holds {positions.Length} floats, the mesh needs {floats}", nameof(positions));
            if (normals.Length < floats)
                throw new ArgumentException($"holds {normals.Length} floats, the mesh needs {floats}", nameof(normals));

            var w = new Writer(positions, normals, frame == HandMeshFrame.Unity);
            for (int s = 0; s < segmentCount; ++s) WriteSegment(ref w, s, segments[s]);
            for (int s = 0; s < sphereCount; ++s) WriteSphere(ref w, spheres[s]);
            boundsMin = w.Min;
            boundsMax = w.Max;
        }

        // writes vertices in order and tracks their box
        ref struct Writer
        {
            readonly Span<float> positions, normals;
            readonly bool unity;
            int next;
            public Vector3d Min, Max;

            public Writer(Span<float> positions, Span<float> normals, bool unity)
            {
                this.positions = positions;
                this.normals = normals;
                this.unity = unity;
                next = 0;
                Min = new Vector3d(double.PositiveInfinity, double.PositiveInfinity, double.PositiveInfinity);
                Max = new Vector3d(double.NegativeInfinity, double.NegativeInfinity, double.NegativeInfinity);
            }

            // a ball's surface point: centre + radius * unit direction, the direction its normal
            public void Put(Vector3d center, double radius, Vector3d direction)
            {
                Vector3d p = center + radius * direction;
                if (unity)
                {
                    p = CoordinateConversion.VectorToUnity(p);
                    direction = CoordinateConversion.VectorToUnity(direction);
                }
                // the box of the rounded values, which are what the caller gets
                float x = (float)p.X, y = (float)p.Y, z = (float)p.Z;
                positions[next] = x;
                positions[next + 1] = y;
                positions[next + 2] = z;
                normals[next] = (float)direction.X;
                normals[next + 1] = (float)direction.Y;
                normals[next + 2] = (float)direction.Z;
                next += 3;
                if (x < Min.X) Min.X = x;
                if (y < Min.Y) Min.Y = y;
                if (z < Min.Z) Min.Z = z;
                if (x > Max.X) Max.X = x;
                if (y > Max.Y) Max.Y = y;
                if (z > Max.Z) Max.Z = z;
            }
        }

        // one ring of a ball at polar angle phi from `pole` (a unit axis), around b and c
        void PutRing(ref Writer w, Vector3d center, double radius, Vector3d pole, double phi, Vector3d b, Vector3d c)
        {
            double cp = Math.Cos(phi), sp = Math.Sin(phi);
            for (int j = 0; j < slices; ++j)
                w.Put(center, radius, cp * pole + sp * (cosTheta[j] * b + sinTheta[j] * c));
        }

        // how far (polar angle from its own pole, radians) each of two balls' arcs runs on the
        // envelope; big radius qb >= small qs, centres `length` apart. swallowed: the small ball
        // lies inside the big one, whose arc then runs from pole to pole.
        static void Envelope(double length, double qb, double qs, out double phiBig, out double phiSmall, out bool swallowed)
        {
            swallowed = false;
            if (length + qs <= qb)
            {
                phiBig = Math.PI;
                phiSmall = 0.0;
                swallowed = true;
            }
            else if (length * length > (qb - qs) * (qb + qs))
            {
                // the side leaves the big ball at qb sin 2 alpha from its centre, tan alpha =
                // (qb - qs) / length; the small ball is inside the frustum past its equator
                double alpha = Math.Atan2(qb - qs, length);
                phiBig = 0.5 * Math.PI + 2.0 * alpha;
                phiSmall = 0.5 * Math.PI;
            }
            else
            {
                // the big ball holds the whole frustum: the two balls' spheres cross at x from
                // the small centre (towards the big one), x <= 0, behind the small centre
                double x = (qs * qs - qb * qb + length * length) / (2.0 * length);
                phiSmall = Math.Acos(Clamp(-x / qs));
                phiBig = Math.Acos(Clamp((x - length) / qb));
            }
        }

        static double Clamp(double c) => c < -1.0 ? -1.0 : c > 1.0 ? 1.0 : c;

        void WriteSegment(ref Writer w, int index, in FrustaSegment segment)
        {
            Vector3d d = segment.Proximal, e = segment.Distal;
            double r1 = segment.ProximalRadius, r2 = segment.DistalRadius;
            Vector3d along = d - e;
            double length = along.Length;

            // the axis points from E to D (the top pole is D's); a vanishing one keeps the last
            Vector3d a = length > MinAxisLength ? along * (1.0 / length) : axes[index];
            if (Vector3d.Dot(a, a) < 0.5) a = new Vector3d(1, 0, 0);
            if (length <= MinAxisLength) length = 0.0;

            // b: the last perpendicular turned onto the new axis, so the rings do not twist
            Vector3d b = references[index];
            b = b - Vector3d.Dot(b, a) * a;
            double bl = b.Length;
            if (bl < 0.5) b = AnyPerpendicular(a);
            else b = b * (1.0 / bl);
            Vector3d c = Vector3d.Cross(a, b);
            axes[index] = a;
            references[index] = b;

            // top arc on D's ball from +a, bottom arc on E's ball from -a
            Vector3d topCenter = d, bottomCenter = e;
            double topRadius = r1, bottomRadius = r2, topPhi, bottomPhi;
            bool swallowed;
            if (r1 >= r2)
            {
                Envelope(length, r1, r2, out topPhi, out bottomPhi, out swallowed);
                if (swallowed)
                {
                    bottomCenter = d;
                    bottomRadius = r1;
                }
            }
            else
            {
                Envelope(length, r2, r1, out bottomPhi, out topPhi, out swallowed);
                if (swallowed)
                {
                    topCenter = e;
                    topRadius = r2;
                }
            }

            Vector3d down = -a;
            w.Put(topCenter, topRadius, a);
            for (int k = 1; k <= arcRings; ++k)
                PutRing(ref w, topCenter, topRadius, a, topPhi * k / arcRings, b, c);
            for (int k = arcRings; k >= 1; --k)
                PutRing(ref w, bottomCenter, bottomRadius, down, bottomPhi * k / arcRings, b, c);
            w.Put(bottomCenter, bottomRadius, down);
        }

        void WriteSphere(ref Writer w, in FrustaSphere sphere)
        {
            // a fixed frame: a sphere looks the same turned
            var a = new Vector3d(0, 0, 1);
            var b = new Vector3d(1, 0, 0);
            var c = new Vector3d(0, 1, 0);
            int rings = 2 * arcRings - 1;
            w.Put(sphere.Center, sphere.Radius, a);
            for (int k = 1; k <= rings; ++k)
                PutRing(ref w, sphere.Center, sphere.Radius, a, Math.PI * k / (rings + 1), b, c);
            w.Put(sphere.Center, sphere.Radius, -a);
        }

        // a unit vector perpendicular to the unit a, from the world axis least along it
        static Vector3d AnyPerpendicular(Vector3d a)
        {
            double ax = Math.Abs(a.X), ay = Math.Abs(a.Y), az = Math.Abs(a.Z);
            Vector3d axis = ax <= ay && ax <= az ? new Vector3d(1, 0, 0)
                          : ay <= az ? new Vector3d(0, 1, 0) : new Vector3d(0, 0, 1);
            Vector3d p = Vector3d.Cross(a, axis);
            return p * (1.0 / p.Length);
        }
    }
}
