// SPDX-License-Identifier: MIT
using System;
using System.IO;
using System.Linq;
using System.Reflection;
using Frusta.Binding;
using Xunit;

namespace Frusta.Binding.Tests
{
    /// <summary>Where the repository and the CMake-built files are (set by the csproj).</summary>
    static class TestEnv
    {
        static string Metadata(string key) =>
            typeof(TestEnv).Assembly.GetCustomAttributes<AssemblyMetadataAttribute>().Single(a => a.Key == key).Value;

        public static string Root => Metadata("FrustaRoot");
        public static string SampleObjects => Metadata("FrustaSampleObjectsDir");
        public static string Package => Path.Combine(Root, "unity-package");

        /// <summary>The bundled glove recording, for replayed gloves.</summary>
        public static string Recording => Path.Combine(Root, "samples", "data", "demo_glove.frrec");

        /// <summary>A sample object baked by the samples/objects target; fails (not skips) when missing.</summary>
        public static string SampleObject(string name)
        {
            string path = Path.Combine(SampleObjects, name + SphereTree.FileExtension);
            Assert.True(File.Exists(path),
                $"{path} is missing: build the frusta_sample_objects target (or set FRUSTA_SAMPLE_OBJECTS_DIR)");
            return path;
        }

        public static string TempPath(string name) =>
            Path.Combine(Path.GetTempPath(), $"frusta-dotnet-{Environment.ProcessId}-{Guid.NewGuid():N}-{name}");
    }

    /// <summary>A 2 cm box baked in C# the way world_c_test.c bakes it: 8 corners, 12 triangles.</summary>
    static class Box
    {
        public const double Half = 0.01;

        public static readonly int[] Triangles =
        {
            0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
            1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7,
        };

        public static float[] Vertices(double half)
        {
            double[,] corners = { { -1, -1, -1 }, { 1, -1, -1 }, { 1, 1, -1 }, { -1, 1, -1 },
                                  { -1, -1, 1 }, { 1, -1, 1 }, { 1, 1, 1 }, { -1, 1, 1 } };
            var v = new float[24];
            for (int i = 0; i < 8; ++i)
                for (int k = 0; k < 3; ++k) v[3 * i + k] = (float)(half * corners[i, k]);
            return v;
        }

        public static SphereTree Bake() => SphereTree.Bake(Vertices(Half), Triangles);
    }

    static class Assertions
    {
        /// <summary>A frame of work, warmed up (JIT, first-use paths), then run 100 times with not a
        /// byte allocated on this thread.</summary>
        public static void AllocatesNothing(Action frame)
        {
            for (int i = 0; i < 20; ++i) frame();
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int i = 0; i < 100; ++i) frame();
            long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
            Assert.True(allocated == 0, $"{allocated} bytes allocated over 100 frames");
        }

        public static void Near(double expected, double actual, double tolerance, string what = null) =>
            Assert.True(Math.Abs(expected - actual) <= tolerance,
                $"{what ?? "value"}: expected {expected:R} within {tolerance:R}, got {actual:R}");

        public static void Near(Vector3d expected, Vector3d actual, double tolerance, string what = null) =>
            Assert.True((expected - actual).Length <= tolerance,
                $"{what ?? "vector"}: expected {expected} within {tolerance:R}, got {actual} (off by {(expected - actual).Length:R})");

        /// <summary>Equal rotations: q and -q are the same rotation.</summary>
        public static void SameRotation(Quaterniond expected, Quaterniond actual, double tolerance, string what = null)
        {
            double d = Math.Abs(expected.X * actual.X + expected.Y * actual.Y + expected.Z * actual.Z + expected.W * actual.W);
            Assert.True(1.0 - d <= tolerance, $"{what ?? "rotation"}: expected {expected}, got {actual}");
        }

        public static FrustaException Fails(FrustaResult result, Action call, params string[] messageParts)
        {
            var e = Assert.Throws<FrustaException>(call);
            Assert.Equal(result, e.Result);
            foreach (string part in messageParts)
                Assert.True(e.NativeMessage.Contains(part),
                    $"the native message \"{e.NativeMessage}\" should contain \"{part}\"");
            Assert.Contains(e.NativeMessage, e.Message);
            return e;
        }
    }
}
