// SPDX-License-Identifier: MIT
// Time per HandMesh.Update (the per-frame work of FrustaHandMesh, Unity's frame) for a
// posed default hand, with and without its palm spheres, and for 20 segments, at the
// default tessellation and a finer one; and the mesh's error against the exact solids:
// vertices (on the surface up to float rounding) and the chords between them (triangle
// edge midpoints and centroids, which cut inside the curved parts). One JSON document.
using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.Linq;
using Frusta.Binding;

static class HandMeshBench
{
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

    static double Distance(HandMesh mesh, FrustaSegment[] segments, FrustaSphere[] spheres, int part, Vector3d p)
    {
        if (part < mesh.SegmentCount) return Geometry.QueryContact(segments[part], new FrustaSphere(p, 0.0)).Distance;
        FrustaSphere s = spheres[part - mesh.SegmentCount];
        return (p - s.Center).Length - s.Radius;
    }

    static Vector3d At(float[] xyz, int v) => new Vector3d(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);

    static string Case(string name, FrustaSegment[] segments, FrustaSphere[] spheres, int slices, int arcRings)
    {
        var mesh = new HandMesh(segments.Length, spheres.Length, slices, arcRings, HandMeshFrame.Unity);
        var positions = new float[3 * mesh.VertexCount];
        var normals = new float[3 * mesh.VertexCount];
        var indices = new int[mesh.IndexCount];
        mesh.WriteTriangles(indices);

        // minimum and median over batches of updates
        const int batch = 200, batches = 50;
        var perUpdate = new List<double>();
        for (int b = 0; b < batches + 5; ++b)
        {
            long start = Stopwatch.GetTimestamp();
            for (int i = 0; i < batch; ++i) mesh.Update(segments, spheres, positions, normals, out _, out _);
            double us = (Stopwatch.GetTimestamp() - start) * 1e6 / Stopwatch.Frequency / batch;
            if (b >= 5) perUpdate.Add(us);  // the first batches warm the JIT up
        }
        perUpdate.Sort();

        // errors in Frusta's frame: the same mesh mirrored back
        var check = new HandMesh(segments.Length, spheres.Length, slices, arcRings, HandMeshFrame.Frusta);
        check.WriteTriangles(indices);
        check.Update(segments, spheres, positions, normals, out _, out _);
        double vertexError = 0, chordError = 0;
        for (int part = 0; part < check.PartCount; ++part)
        {
            int v0 = check.PartVertexStart(part);
            for (int v = v0; v < v0 + check.PartVertexCount(part); ++v)
                vertexError = Math.Max(vertexError, Math.Abs(Distance(check, segments, spheres, part, At(positions, v))));
            int t0 = check.PartTriangleStart(part);
            for (int t = t0; t < t0 + check.PartTriangleCount(part); ++t)
            {
                Vector3d a = At(positions, indices[3 * t]), b = At(positions, indices[3 * t + 1]), c = At(positions, indices[3 * t + 2]);
                foreach (Vector3d p in new[] { (a + b) * 0.5, (b + c) * 0.5, (c + a) * 0.5, (a + b + c) * (1.0 / 3.0) })
                    chordError = Math.Max(chordError, Math.Abs(Distance(check, segments, spheres, part, p)));
            }
        }
        return string.Format(CultureInfo.InvariantCulture,
            "{{\"name\": \"{0}\", \"segments\": {1}, \"spheres\": {2}, \"slices\": {3}, \"arc_rings\": {4}, " +
            "\"vertices\": {5}, \"triangles\": {6}, \"update_us_min\": {7:F2}, \"update_us_median\": {8:F2}, " +
            "\"vertex_error_mm\": {9:G3}, \"chord_error_mm\": {10:G3}}}",
            name, segments.Length, spheres.Length, slices, arcRings, mesh.VertexCount, mesh.TriangleCount,
            perUpdate[0], perUpdate[perUpdate.Count / 2], vertexError * 1e3, chordError * 1e3);
    }

    static void Main()
    {
        var (segments, spheres) = PosedHand();
        // 20 segments: the hand's 15 and its five distal ones again, moved aside
        var twenty = segments.Concat(segments.Where((s, i) => i % 3 == 2).Select(s =>
        {
            var shift = new Vector3d(0.0, 0.0, 0.05);
            s.Proximal += shift;
            s.Distal += shift;
            return s;
        })).ToArray();
        var none = Array.Empty<FrustaSphere>();
        var cases = new[]
        {
            Case("hand with palm spheres", segments, spheres, HandMesh.DefaultSlices, HandMesh.DefaultArcRings),
            Case("hand segments only", segments, none, HandMesh.DefaultSlices, HandMesh.DefaultArcRings),
            Case("20 segments", twenty, none, HandMesh.DefaultSlices, HandMesh.DefaultArcRings),
            Case("hand with palm spheres, fine", segments, spheres, 32, 8),
        };
        Console.WriteLine("{\"suite\": \"handmesh\", \"unit_note\": \"microseconds per HandMesh.Update, millimetres\", \"cases\": [");
        Console.WriteLine("  " + string.Join(",\n  ", cases));
        Console.WriteLine("]}");
    }
}
