// SPDX-License-Identifier: MIT
// GloveRecording reads a .frrec glove recording as its CSV twin says it was written, and
// refuses what is not one, naming it.
using System;
using System.Globalization;
using System.IO;
using System.Linq;
using Frusta.Binding;
using Xunit;

namespace Frusta.Binding.Tests
{
    public class GloveRecordingTests
    {
        [Fact]
        public void ARecordingReadsAsItsCsvTwinSays()
        {
            // demo_glove.frrec and demo_glove.csv come from one script, frame for frame at 100 Hz
            GloveRecording recording = GloveRecording.Load(TestEnv.Recording);
            string[] frames = File.ReadAllLines(Path.Combine(TestEnv.Root, "samples", "data", "demo_glove.csv"))
                .Where(l => l.StartsWith("frame,", StringComparison.Ordinal)).ToArray();
            Assert.Equal(frames.Length, recording.SampleCount);
            var angles = new double[FrustaConstants.HandJointCount];
            for (int i = 0; i < frames.Length; ++i)
            {
                double[] v = frames[i].Split(',').Skip(1).Select(s => double.Parse(s, CultureInfo.InvariantCulture)).ToArray();
                Assert.Equal(v[0], recording.GetTime(i), 9);
                Assert.True(recording.GetSample(i, out FrustaPose palm, angles));
                for (int k = 0; k < 3; ++k) Assert.True(Math.Abs(v[1 + k] - Get(palm.Position, k)) <= 0.5e-5 + 1e-6, $"frame {i} palm {k}");
                Quaterniond q = palm.Rotation, r = new Quaterniond(v[4], v[5], v[6], v[7]);
                double dot = Math.Abs(q.X * r.X + q.Y * r.Y + q.Z * r.Z + q.W * r.W);
                Assert.True(dot > 1 - 1e-8, $"frame {i} rotation {q} vs {r}");
                for (int j = 0; j < angles.Length; ++j) Assert.True(Math.Abs(v[8 + j] - angles[j]) <= 0.5e-4 + 1e-6, $"frame {i} angle {j}");
            }
            Assert.Equal(recording.GetTime(recording.SampleCount - 1), recording.Duration);
        }

        static double Get(Vector3d v, int k) => k == 0 ? v.X : k == 1 ? v.Y : v.Z;

        [Fact]
        public void ARecordingThatIsNotOneIsRefusedWithItsName()
        {
            var e = Assert.Throws<FrustaException>(() => GloveRecording.Parse(new byte[] { 1, 2, 3 }, "junk.frrec"));
            Assert.Equal(FrustaResult.FileFormat, e.Result);
            Assert.Contains("junk.frrec", e.NativeMessage);
            byte[] text = System.Text.Encoding.ASCII.GetBytes("frusta-recording 1 opengloves\n");
            e = Assert.Throws<FrustaException>(() => GloveRecording.Parse(text, "glove.frrec"));
            Assert.Equal(FrustaResult.FileFormat, e.Result);
            Assert.Contains("opengloves", e.NativeMessage);
            // a record that runs past the end
            byte[] cut = File.ReadAllBytes(TestEnv.Recording);
            e = Assert.Throws<FrustaException>(() => GloveRecording.Parse(cut.AsSpan(0, cut.Length - 3), "cut.frrec"));
            Assert.Equal(FrustaResult.CorruptFile, e.Result);
            e = Assert.Throws<FrustaException>(() => GloveRecording.Load("/nonexistent/glove.frrec"));
            Assert.Equal(FrustaResult.Io, e.Result);
        }
    }
}
