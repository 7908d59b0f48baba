// SPDX-License-Identifier: MIT
using System;
using System.Collections.Generic;
using System.IO;
using System.Text;

namespace Frusta.Binding
{
    /// <summary>
    /// A glove recording (a <c>.frrec</c> file of Frusta's binary profile, as a glove opened with
    /// <c>&amp;record=FILE</c> writes it, or <c>samples/data/demo_glove.frrec</c>) read into its
    /// samples, each at its time in the recording. A glove device replays such a file in real time
    /// on its own thread (<c>replay:FILE</c>); this reader lets a host play the same samples on its
    /// own clock instead, through <see cref="World.SetHaptic(FrustaHandId, double, in FrustaPose, ReadOnlySpan{double})"/>,
    /// so that a world the host steps runs the recording deterministically (tests, a scene stepped
    /// with the game). Only SAMPLE frames are read (frames of other types are skipped); a frame with
    /// a bad checksum, an unknown type or a cut-off end is skipped as the native decoder skips it.
    /// Recordings of the OpenGloves text protocol are refused: their angles need a calibration.
    /// Format: <c>native/src/devices/recording.h</c> and <c>binary_profile.md</c>.
    /// </summary>
    public sealed class GloveRecording
    {
        const string Magic = "frusta-recording 1 ";
        const byte Sync = 0xF5, SampleType = 0x03;
        const int SampleSize = 47, PalmPoseSize = 20, MaxAngleCounts = 31416;
        const double AngleUnit = 1e-4, PositionUnit = 1e-5, QuaternionScale = 32767.0;

        readonly double[] times;
        readonly FrustaPose[] palms;
        readonly bool[] hasPalm;
        readonly double[] angles;  // HandJointCount per sample

        GloveRecording(List<double> t, List<FrustaPose> p, List<bool> h, List<double> a)
        {
            times = t.ToArray();
            palms = p.ToArray();
            hasPalm = h.ToArray();
            angles = a.ToArray();
        }

        /// <summary>Samples in the recording.</summary>
        public int SampleCount => times.Length;

        /// <summary>Seconds from the recording's start to its last sample.</summary>
        public double Duration => times.Length == 0 ? 0 : times[times.Length - 1];

        /// <summary>Read a recording file.</summary>
        /// <param name="path">A <c>.frrec</c> file.</param>
        /// <exception cref="FrustaException"><see cref="FrustaResult.Io"/> if it cannot be read; as
        /// <see cref="Parse"/> otherwise.</exception>
        public static GloveRecording Load(string path)
        {
            byte[] bytes;
            try
            {
                bytes = File.ReadAllBytes(path);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException || e is ArgumentException)
            {
                throw new FrustaException(FrustaResult.Io, $"{path}: {e.Message}", "GloveRecording.Load");
            }
            return Parse(bytes, path);
        }

        /// <summary>Read a recording from its bytes (an asset's, say).</summary>
        /// <param name="bytes">The file's bytes.</param>
        /// <param name="name">Names the recording in error messages.</param>
        /// <exception cref="FrustaException"><see cref="FrustaResult.FileFormat"/> for no recording
        /// header, or another protocol's; <see cref="FrustaResult.CorruptFile"/> for a record that runs
        /// past the end, times that go back, or no sample at all.</exception>
        public static GloveRecording Parse(ReadOnlySpan<byte> bytes, string name = "recording")
        {
            int eol = bytes.IndexOf((byte)'\n');
            string header = eol < 0 ? "" : Encoding.ASCII.GetString(bytes.Slice(0, eol).ToArray());
            if (!header.StartsWith(Magic, StringComparison.Ordinal))
                throw Fail(FrustaResult.FileFormat, $"{name}: not a Frusta glove recording (no \"{Magic.Trim()}\" header)");
            string protocol = header.Substring(Magic.Length);
            if (protocol != "frusta")
                throw Fail(FrustaResult.FileFormat, $"{name}: a recording of protocol \"{protocol}\"; only \"frusta\" (the binary profile) is read here");

            // records: int64 time (ns), uint32 byte count, the bytes; the glove's byte stream
            var stream = new List<byte>();
            var recordTimes = new List<(int end, long ns)>();
            int at = eol + 1;
            long last = long.MinValue;
            while (at < bytes.Length)
            {
                if (bytes.Length - at < 12)
                    throw Fail(FrustaResult.CorruptFile, $"{name}: a record header cut off at byte {at}");
                long ns = BitConverter.ToInt64(Le(bytes.Slice(at, 8)), 0);
                uint count = BitConverter.ToUInt32(Le(bytes.Slice(at + 8, 4)), 0);
                at += 12;
                if (count == 0 || count > 65536 || count > bytes.Length - at)
                    throw Fail(FrustaResult.CorruptFile, $"{name}: the record at byte {at - 12} holds {count} bytes, past the end or out of 1..65536");
                if (ns < last)
                    throw Fail(FrustaResult.CorruptFile, $"{name}: the record at byte {at - 12} goes back in time ({ns} ns after {last} ns)");
                last = ns;
                for (int i = 0; i < count; ++i) stream.Add(bytes[at + i]);
                at += (int)count;
                recordTimes.Add((stream.Count, ns));
            }

            // frames, each at the time of the record that completed it
            var t = new List<double>();
            var p = new List<FrustaPose>();
            var h = new List<bool>();
            var a = new List<double>();
            int record = 0;
            byte[] s = stream.ToArray();
            for (int i = 0; i + 5 <= s.Length;)
            {
                if (s[i] != Sync) { ++i; continue; }
                int length = s[i + 2];
                int end = i + 3 + length + 2;
                if (length > 120 || end > s.Length || Crc16(s, i + 1, length + 2) != (ushort)(s[end - 2] | s[end - 1] << 8))
                {
                    ++i;  // drop this sync byte only: a good frame may begin inside the bad one
                    continue;
                }
                if (s[i + 1] == SampleType && length >= SampleSize)
                {
                    while (recordTimes[record].end < end) ++record;
                    if (ReadSample(s, i + 3, length, a, out FrustaPose palm, out bool withPalm))
                    {
                        t.Add(recordTimes[record].ns * 1e-9);
                        p.Add(palm);
                        h.Add(withPalm);
                    }
                }
                i = end;
            }
            if (t.Count == 0) throw Fail(FrustaResult.CorruptFile, $"{name}: no glove sample in it");
            return new GloveRecording(t, p, h, a);
        }

        /// <summary>Seconds from the recording's start to a sample (when it was recorded).</summary>
        /// <param name="index">0..<see cref="SampleCount"/> - 1.</param>
        public double GetTime(int index) => times[index];

        /// <summary>One sample: the palm pose (Frusta's frame, metres; identity if the glove has no
        /// tracker) and the joint angles (radians, finger-major).</summary>
        /// <param name="index">0..<see cref="SampleCount"/> - 1.</param>
        /// <param name="palm">The palm pose.</param>
        /// <param name="jointAngles">At least <see cref="FrustaConstants.HandJointCount"/> values.</param>
        /// <returns>true if the sample carries a palm pose.</returns>
        public bool GetSample(int index, out FrustaPose palm, Span<double> jointAngles)
        {
            palm = palms[index];
            angles.AsSpan(index * FrustaConstants.HandJointCount, FrustaConstants.HandJointCount).CopyTo(jointAngles);
            return hasPalm[index];
        }

        // what native decode_sample accepts; a sample out of range is skipped, as the glove would drop it
        static bool ReadSample(byte[] s, int at, int length, List<double> angles, out FrustaPose palm, out bool withPalm)
        {
            palm = FrustaPose.Identity;
            withPalm = (s[at + 6] & 1) != 0;
            if (withPalm && length < SampleSize + PalmPoseSize) return false;
            var read = new double[FrustaConstants.HandJointCount];
            for (int j = 0; j < read.Length; ++j)
            {
                short counts = I16(s, at + 7 + 2 * j);
                if (Math.Abs((int)counts) > MaxAngleCounts) return false;
                read[j] = counts * AngleUnit;
            }
            if (withPalm)
            {
                int p = at + SampleSize;
                var position = new Vector3d(I32(s, p) * PositionUnit, I32(s, p + 4) * PositionUnit, I32(s, p + 8) * PositionUnit);
                var q = new Quaterniond(I16(s, p + 14) / QuaternionScale, I16(s, p + 16) / QuaternionScale,
                                        I16(s, p + 18) / QuaternionScale, I16(s, p + 12) / QuaternionScale);
                if (Math.Abs(q.Norm - 1.0) > 0.01) return false;
                palm = new FrustaPose(position, q.Normalized);
            }
            angles.AddRange(read);
            return true;
        }

        static short I16(byte[] s, int at) => (short)(s[at] | s[at + 1] << 8);

        static int I32(byte[] s, int at) => s[at] | s[at + 1] << 8 | s[at + 2] << 16 | s[at + 3] << 24;

        // CRC-16/CCITT-FALSE, as binary_profile.md specifies
        static ushort Crc16(byte[] data, int start, int count)
        {
            ushort crc = 0xFFFF;
            for (int i = start; i < start + count; ++i)
            {
                crc = (ushort)(crc ^ data[i] << 8);
                for (int bit = 0; bit < 8; ++bit)
                    crc = (ushort)((crc & 0x8000) != 0 ? crc << 1 ^ 0x1021 : crc << 1);
            }
            return crc;
        }

        // little-endian on any host
        static byte[] Le(ReadOnlySpan<byte> bytes)
        {
            byte[] copy = bytes.ToArray();
            if (!BitConverter.IsLittleEndian) Array.Reverse(copy);
            return copy;
        }

        static FrustaException Fail(FrustaResult result, string message) =>
            new FrustaException(result, message, "GloveRecording.Parse");
    }
}
