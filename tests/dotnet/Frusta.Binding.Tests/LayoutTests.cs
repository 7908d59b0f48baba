// SPDX-License-Identifier: MIT
// The C# mirrors against the frozen table of tests/abi/abi_layout_test.cpp and against
// the loaded library's frusta_struct_size.
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using System.Text.RegularExpressions;
using Frusta.Binding;
using Xunit;

namespace Frusta.Binding.Tests
{
    public class LayoutTests
    {
        record Member(string Struct, string Name, int Offset, int Size);

        static readonly Lazy<string> TableText = new Lazy<string>(() =>
            File.ReadAllText(Path.Combine(TestEnv.Root, "tests", "abi", "abi_layout_test.cpp")));

        static List<Member> Members() =>
            Regex.Matches(TableText.Value, @"X\((frusta_[a-z_0-9]+), ([a-z_0-9]+), (\d+), (\d+)\)")
                 .Select(m => new Member(m.Groups[1].Value, m.Groups[2].Value, int.Parse(m.Groups[3].Value), int.Parse(m.Groups[4].Value)))
                 .ToList();

        static Dictionary<string, int> Sizes() =>
            Regex.Matches(TableText.Value, @"X\((frusta_[a-z_0-9]+), (\d+), (\d+)\)")
                 .ToDictionary(m => m.Groups[1].Value, m => int.Parse(m.Groups[2].Value));

        static Type MirrorOf(string cName) => FrustaLibrary.Mirrors.Single(m => m.CName == cName).Type;

        static string Normal(string name) => name.Replace("_", "").ToLowerInvariant();

        static FieldInfo[] Fields(Type t) =>
            t.GetFields(BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic).OrderBy(f => Marshal.OffsetOf(t, f.Name).ToInt32()).ToArray();

        static int FieldSize(FieldInfo f)
        {
            var fixedBuffer = f.GetCustomAttribute<FixedBufferAttribute>();
            if (fixedBuffer != null) return fixedBuffer.Length * Marshal.SizeOf(fixedBuffer.ElementType);
            return Marshal.SizeOf(f.FieldType.IsEnum ? Enum.GetUnderlyingType(f.FieldType) : f.FieldType);
        }

        [Fact]
        public void TheTableWasParsed()
        {
            Assert.True(Sizes().Count >= 23, $"{Sizes().Count} structs in the table");
            Assert.True(Members().Count >= 200, $"{Members().Count} members in the table");
        }

        [Fact]
        public void EveryStructOfTheTableIsMirroredAndNoOther()
        {
            var tabled = Sizes().Keys.OrderBy(n => n).ToArray();
            var mirrored = FrustaLibrary.Mirrors.Select(m => m.CName).OrderBy(n => n).ToArray();
            Assert.Equal(tabled, mirrored);
        }

        [Fact]
        public void EveryMirrorHasTheTablesSizeAndTheLibrarysSize()
        {
            foreach (var (name, size) in Sizes())
            {
                Type t = MirrorOf(name);
                Assert.True(size == Marshal.SizeOf(t), $"{name}: table {size}, Marshal.SizeOf({t.Name}) {Marshal.SizeOf(t)}");
                Assert.True(size == FrustaLibrary.Mirrors.Single(m => m.CName == name).Sizeof, $"{name}: sizeof({t.Name})");
                Assert.True(size == FrustaLibrary.GetNativeStructSize(name), $"{name}: frusta_struct_size {FrustaLibrary.GetNativeStructSize(name)}");
            }
        }

        [Fact]
        public void EveryMemberHasTheTablesOffsetAndSizeInOrder()
        {
            foreach (var group in Members().GroupBy(m => m.Struct))
            {
                Type t = MirrorOf(group.Key);
                FieldInfo[] fields = Fields(t);
                Member[] members = group.ToArray();
                Assert.True(members.Length == fields.Length,
                    $"{group.Key} has {members.Length} members, {t.Name} {fields.Length} fields: {string.Join(", ", fields.Select(f => f.Name))}");
                for (int i = 0; i < members.Length; ++i)
                {
                    Member m = members[i];
                    FieldInfo f = fields[i];
                    Assert.True(Normal(m.Name) == Normal(f.Name), $"{group.Key} member {i} is {m.Name}, {t.Name} has {f.Name}");
                    int offset = Marshal.OffsetOf(t, f.Name).ToInt32();
                    Assert.True(m.Offset == offset, $"{group.Key}.{m.Name} at {m.Offset}, {t.Name}.{f.Name} at {offset}");
                    Assert.True(m.Size == FieldSize(f), $"{group.Key}.{m.Name} is {m.Size} bytes, {t.Name}.{f.Name} {FieldSize(f)}");
                }
            }
        }

        [Fact]
        public void EveryInternalFieldTheBindingDoesNotFillHasAPublicFace()
        {
            // the generator makes flags and fixed buffers internal under their C names; a new one
            // in the header stays out of users' reach until Structs.cs wraps it
            foreach (var m in FrustaLibrary.Mirrors)
                foreach (FieldInfo f in Fields(m.Type).Where(f => !f.IsPublic))
                {
                    if (Regex.IsMatch(f.Name, @"^(struct_size|internal_value|reserved\d*)$")) continue;
                    string pascal = string.Concat(f.Name.Split('_').Select(w => char.ToUpperInvariant(w[0]) + w.Substring(1)));
                    var faces = new[] { pascal, "Get" + pascal, "Copy" + pascal };
                    Assert.True(m.Type.GetMembers(BindingFlags.Public | BindingFlags.Instance).Any(x => faces.Contains(x.Name)),
                        $"{m.Type.Name}.{f.Name} has no public {string.Join(", ", faces)}");
                }
        }

        [Fact]
        public void MirrorsAreBlittable()
        {
            foreach (var m in FrustaLibrary.Mirrors)
            {
                // a non-blittable struct cannot be pinned
                object boxed = Activator.CreateInstance(m.Type);
                GCHandle h = GCHandle.Alloc(boxed, GCHandleType.Pinned);
                h.Free();
                bool references = (bool)typeof(RuntimeHelpers).GetMethod(nameof(RuntimeHelpers.IsReferenceOrContainsReferences))
                    .MakeGenericMethod(m.Type).Invoke(null, null);
                Assert.False(references, m.Type.Name);
            }
        }

        [Fact]
        public void DefaultsCarryTheirSizeAndCookie()
        {
            Assert.Equal(896, FrustaHandDef.Default.struct_size);
            Assert.Equal(56, FrustaBakeDef.Default.struct_size);
            Assert.Equal(152, FrustaWorldDef.Default.struct_size);
            Assert.Equal(224, FrustaObjectDef.Default.struct_size);
            Assert.Equal(728, FrustaDeviceDef.Default.struct_size);
            Assert.Equal(56, FrustaHandFitDef.Default.struct_size);
            Assert.NotEqual(0, FrustaHandFitDef.Default.internal_value);
            Assert.NotEqual(0, FrustaWorldDef.Default.internal_value);
            Assert.NotEqual(0, FrustaObjectDef.Default.internal_value);
            Assert.NotEqual(0, FrustaDeviceDef.Default.internal_value);
        }

        [Fact]
        public void DefaultValuesReadBackThroughTheMirror()
        {
            // the values world_c_test.c checks: a shifted field would read something else
            FrustaWorldDef w = FrustaWorldDef.Default;
            Assert.Equal(64, w.MaxObjects);
            Assert.Equal(1000.0, w.RateHz);
            Assert.Equal(200.0, w.SpinUs);
            Assert.Equal(Vector3d.Zero, w.Gravity);
            Assert.Equal(0.002, w.PredictionMargin);
            Assert.Equal(0.0, w.LodError);
            Assert.Equal(2, w.MaxIterations);
            Assert.Equal(64, w.MaxSubsteps);
            Assert.Equal(256, w.MaxContactsPerHand);
            Assert.Equal(256, w.CommandCapacity);
            Assert.Equal(8, w.MaxHands);
            Assert.True(w.RealtimePriority);
            Assert.Equal((10.0, 10.0, 0.5, 20.0, 1.0),
                (w.MaxFingertipForce, w.MaxFingerResistance, w.MaxJointTorque, w.MaxPalmForce, w.MaxPalmTorque));
            Assert.Equal((0.010, 0.040), (w.InputDelay, w.MaxExtrapolation));
            Assert.Equal(1024, w.MaxCandidatesPerHand);

            FrustaObjectDef o = FrustaObjectDef.Default;
            Assert.False(o.Dynamic);
            Assert.Equal(Vector3d.Zero, o.Pose.Position);
            Assert.Equal(Quaterniond.Identity, o.Pose.Rotation);
            Assert.Equal(new Vector3d(400, 400, 400), o.Stiffness);
            Assert.Equal((0.6, 1e4, 0.0, 0.0, 0.1), (o.Friction, o.TangentialStiffness, o.NormalDamping, o.TangentialDamping, o.Mass));
            Assert.Equal(new Vector3d(4e-5, 4e-5, 4e-5), o.Inertia);
            Assert.Equal((0.0, 0.0), (o.LinearDamping, o.AngularDamping));

            FrustaHandDef h = FrustaHandDef.Default;
            Assert.Equal(FrustaHandSide.Right, h.Side);
            Assert.Equal(0.19, h.HandLength);
            Assert.Equal(0.085, h.HandBreadth);
            Assert.True(h.PalmLength > 0 && h.PalmBreadth > 0 && h.PalmThickness > 0);
            // the index finger's first joint lies ahead of the wrist, the thumb's towards +y
            Assert.True(h.GetBasePosition(FrustaFinger.Index).X > 0.05);
            Assert.True(h.GetBasePosition(FrustaFinger.Thumb).Y > h.GetBasePosition(FrustaFinger.Little).Y);
            for (int f = 0; f < 5; ++f)
                for (int s = 0; s < 3; ++s)
                    Assert.True(h.GetSegmentLength((FrustaFinger)f, s) > 0.005, $"segment {f}/{s}");

            FrustaHandFitDef fit = FrustaHandFitDef.Default;
            Assert.Equal((FrustaJointLayout.Xr, false, 10, 0.0), (fit.Layout, fit.RequireTracked, fit.MaxIterations, fit.OrientationWeight));

            FrustaBakeDef b = FrustaBakeDef.Default;
            Assert.Equal((4, 0.001, 200000L, 40, 100000L, 1UL), (b.Branching, b.TargetError, b.MaxLeaves, b.MaxDepth, b.ErrorSamples, b.Seed));
        }

        [Fact]
        public void VersionAndAbiMatchTheBinding()
        {
            FrustaLibrary.EnsureCompatible();
            Assert.Equal(FrustaConstants.AbiVersion, FrustaLibrary.AbiVersion);
            Assert.Equal(FrustaConstants.Version, FrustaLibrary.Version);
            Assert.Equal("0.5.0", FrustaLibrary.VersionString);
            Assert.Equal("FRUSTA_ERROR_STALE_ID", FrustaLibrary.GetResultName(FrustaResult.StaleId));
            Assert.Equal(0, FrustaLibrary.GetNativeStructSize("frusta_no_such_struct"));
        }

        [Fact]
        public void EveryResultCodeHasTheHeadersName()
        {
            foreach (FrustaResult r in Enum.GetValues(typeof(FrustaResult)))
            {
                string native = FrustaLibrary.GetResultName(r);
                string expected = r == FrustaResult.Ok ? "FRUSTA_OK"
                    : "FRUSTA_ERROR_" + Regex.Replace(r.ToString(), "(?<!^)([A-Z])", "_$1").ToUpperInvariant();
                Assert.Equal(expected, native);
            }
        }
    }
}
