// SPDX-License-Identifier: MIT
// An editor's bake through the binding: a job with progress that makes the tree a blocking
// bake makes, a cancelled job, a mesh the bake refuses, and trees loaded from a file's bytes
// in memory (an asset's, with no temporary file). No timing: polls wait for the state.
using System;
using System.IO;
using System.Threading;
using Frusta.Binding;
using Xunit;

namespace Frusta.Binding.Tests
{
    public class BakeJobTests
    {
        static void SameLeaves(SphereTree expected, SphereTree actual)
        {
            var a = new FrustaSphere[expected.LeafCount];
            var b = new FrustaSphere[actual.LeafCount];
            Assert.Equal(a.Length, b.Length);
            expected.GetLeaves(a);
            actual.GetLeaves(b);
            for (int i = 0; i < a.Length; ++i)
            {
                Assert.Equal(a[i].Center, b[i].Center);
                Assert.Equal(a[i].Radius, b[i].Radius);
            }
        }

        [Fact]
        public void AJobReportsProgressToTheEndAndMakesTheTreeABlockingBakeMakes()
        {
            using SphereTree blocking = Box.Bake();
            using BakeJob job = BakeJob.Start(Box.Vertices(Box.Half), Box.Triangles, FrustaBakeDef.Default);
            double last = 0;
            while (!job.IsDone)
            {
                double now = job.Progress;
                Assert.InRange(now, last, 1.0);
                last = now;
                Thread.Yield();
            }
            Assert.Equal(1.0, job.Progress);
            using SphereTree tree = job.Finish();
            SameLeaves(blocking, tree);
            Assert.Throws<ObjectDisposedException>(() => job.Progress);
            job.Dispose(); // spent: nothing left to do
        }

        [Fact]
        public void ACancelledJobThrowsCancelledAndADroppedOneCleansUp()
        {
            FrustaBakeDef slow = FrustaBakeDef.Default;
            slow.TargetError = 1e-4;
            slow.ErrorSamples = 10_000_000;
            using (BakeJob job = BakeJob.Start(Box.Vertices(Box.Half), Box.Triangles, slow))
            {
                job.Cancel();
                var e = Assert.Throws<FrustaException>(() => job.Finish());
                Assert.Equal(FrustaResult.Cancelled, e.Result);
            }
            // disposed unfinished: cancelled and ended natively (the id goes stale)
            BakeJob dropped = BakeJob.Start(Box.Vertices(Box.Half), Box.Triangles, slow);
            dropped.Dispose();
            dropped.Dispose();
            Assert.Throws<ObjectDisposedException>(() => dropped.Cancel());
        }

        [Fact]
        public void TheMeshsErrorsComeFromTheFinishAndTheDefsFromTheStart()
        {
            using (BakeJob job = BakeJob.Start(Box.Vertices(Box.Half), new[] { 0, 1, 9 }, FrustaBakeDef.Default))
            {
                var e = Assert.Throws<FrustaException>(() => job.Finish());
                Assert.Equal(FrustaResult.OutOfRange, e.Result);
                Assert.Contains("indices[2] is 9", e.NativeMessage);
            }
            FrustaBakeDef bad = FrustaBakeDef.Default;
            bad.Branching = 1;
            var refused = Assert.Throws<FrustaException>(() => BakeJob.Start(Box.Vertices(Box.Half), Box.Triangles, bad));
            Assert.Contains("branching", refused.NativeMessage);
            Assert.Throws<ArgumentException>(() => BakeJob.Start(new float[4], Box.Triangles, FrustaBakeDef.Default));
        }

        [Fact]
        public void AFilesBytesInMemoryLoadTheTreeTheFileLoads()
        {
            using SphereTree baked = Box.Bake();
            string path = TestEnv.TempPath("memory.frtree");
            try
            {
                baked.Save(path);
                byte[] bytes = File.ReadAllBytes(path);
                using SphereTree fromMemory = SphereTree.LoadFromMemory(bytes);
                SameLeaves(baked, fromMemory);
                Assert.Equal(baked.Info.UncoveredError, fromMemory.Info.UncoveredError);
                var e = Assert.Throws<FrustaException>(() => SphereTree.LoadFromMemory(bytes.AsSpan(0, bytes.Length / 2)));
                Assert.Equal(FrustaResult.CorruptFile, e.Result);
                Assert.Contains("data", e.NativeMessage);
                Assert.Throws<FrustaException>(() => SphereTree.LoadFromMemory(ReadOnlySpan<byte>.Empty));
            }
            finally
            {
                File.Delete(path);
            }
        }
    }
}
