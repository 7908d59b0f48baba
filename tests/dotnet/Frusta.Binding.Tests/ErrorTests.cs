// SPDX-License-Identifier: MIT
// Native failures become FrustaException with the code and the library's own message,
// and change nothing.
using System;
using System.IO;
using Frusta.Binding;
using Xunit;
using static Frusta.Binding.Tests.Assertions;

namespace Frusta.Binding.Tests
{
    public class ErrorTests
    {
        [Theory]
        [InlineData(0.5, FrustaResult.OutOfRange, "0.5")]
        [InlineData(1e6, FrustaResult.OutOfRange, "1e+06")]
        [InlineData(double.NaN, FrustaResult.NotFinite, "nan")]
        public void ABadWorldDefValueNamesTheFieldAndValue(double rate, FrustaResult result, string value)
        {
            FrustaWorldDef def = FrustaWorldDef.Default;
            def.RateHz = rate;
            FrustaException e = Fails(result, () => new World(def), "rate_hz", value);
            Assert.Equal("frusta_create_world", e.Call);
            Assert.StartsWith("frusta_create_world failed: FRUSTA_ERROR_", e.Message);
        }

        [Fact]
        public void ADefNotFromTheDefaultsIsRefused()
        {
            var def = new FrustaWorldDef { struct_size = System.Runtime.InteropServices.Marshal.SizeOf<FrustaWorldDef>() }; // built by hand: no cookie
            Fails(FrustaResult.DefNotDefaulted, () => new World(def), "frusta_default_world_def");
            FrustaObjectDef objectDef = FrustaObjectDef.Default;
            objectDef.internal_value = 0;
            using var world = new World();
            using var tree = Box.Bake();
            Fails(FrustaResult.DefNotDefaulted, () => world.CreateObject(tree, objectDef), "internal_value");
            FrustaWorldDef drifted = FrustaWorldDef.Default;
            drifted.struct_size -= 8; // what a drifted mirror would send
            Fails(FrustaResult.StructSize, () => new World(drifted), "frusta_world_def");
        }

        [Fact]
        public void BadObjectAndHandValuesNameTheirFields()
        {
            using var world = new World();
            using var tree = Box.Bake();
            FrustaObjectDef def = FrustaObjectDef.Default;
            def.Friction = -0.1;
            Fails(FrustaResult.OutOfRange, () => world.CreateObject(tree, def), "friction", "-0.1");
            def = FrustaObjectDef.Default;
            def.Mass = 0;
            Fails(FrustaResult.OutOfRange, () => world.CreateObject(tree, def), "mass");
            def = FrustaObjectDef.Default;
            def.Pose.Rotation = new Quaterniond(0, 0, 0, 3);
            Fails(FrustaResult.OutOfRange, () => world.CreateObject(tree, def), "pose.rotation", "norm 3");

            FrustaHandDef hand = FrustaHandDef.Default;
            hand.SetJointRadius(FrustaFinger.Middle, 1, -0.01);
            Fails(FrustaResult.OutOfRange, () => world.CreateHand(hand), "joint_radius[2][1]", "-0.01");
            hand = FrustaHandDef.Default;
            hand.Side = (FrustaHandSide)7;
            Fails(FrustaResult.OutOfRange, () => world.CreateHand(hand), "side", "7");
            hand = FrustaHandDef.Default;
            Fails(FrustaResult.NotFinite, () => hand.SetSize(double.NaN, 0.085), "nan");
            Assert.Equal(0.19, hand.HandLength); // unchanged on error

            var state = new FrustaWorldState();
            world.Step();
            world.Read(ref state);
            Assert.Equal(0, state.HandCount);
            Assert.Equal(0, state.ObjectCount);
        }

        [Fact]
        public void BadHapticInputIsRefusedAndLeavesTheHandAlone()
        {
            using var world = new World();
            FrustaHandId hand = world.CreateHand(FrustaHandDef.Default);
            var angles = new double[20];
            var palm = FrustaPose.Identity;
            Fails(FrustaResult.OutOfRange, () => world.SetHaptic(hand, palm, new double[19]), "count", "19");
            var second = hand;
            second.Index1 = 2;
            Fails(FrustaResult.StaleId, () => world.SetHaptic(second, palm, angles), "no hand of this world");
            using (var standalone = new Hand())
                Fails(FrustaResult.StaleId, () => world.SetHaptic(standalone.Id, palm, angles), "standalone");
            angles[7] = double.PositiveInfinity;
            Fails(FrustaResult.NotFinite, () => world.SetHaptic(hand, palm, angles), "angles[7]", "inf");
            angles[7] = 0;
            palm.Position.Z = -2e6;
            Fails(FrustaResult.OutOfRange, () => world.SetHaptic(hand, palm, angles), "palm.position", "-2e+06");
        }

        [Fact]
        public void StaleAndNullIdsAreRefused()
        {
            using var tree = Box.Bake();
            FrustaObjectId removed;
            using (var world = new World())
            {
                removed = world.CreateObject(tree, FrustaObjectDef.Default);
                world.DestroyObject(removed);
                Fails(FrustaResult.StaleId, () => world.DestroyObject(removed), "names no object");
                using (var other = new World())
                {
                    // the id names its world: another World refuses to destroy it
                    FrustaObjectId kept = world.CreateObject(tree, FrustaObjectDef.Default);
                    Fails(FrustaResult.StaleId, () => other.DestroyObject(kept), "another world");
                    world.DestroyObject(kept);
                }
                Fails(FrustaResult.NullId, () => world.SetObjectDynamic(FrustaObjectId.Null, true), "null");
                var forged = removed;
                forged.World0 = 0;
                Fails(FrustaResult.StaleId, () => world.SetObjectDynamic(forged, true), "another world");
            }
            using (var other = new World())
            {
                // an object id of a destroyed world in the world that took its slot
                Fails(FrustaResult.StaleId, () => other.SetObjectPose(removed, FrustaPose.Identity));
            }
        }

        [Fact]
        public void ReadsBeforeAnyReadAreWrongState()
        {
            using var world = new World();
            FrustaHandId hand = world.CreateHand(FrustaHandDef.Default);
            world.Step();
            var h = new FrustaWorldHand();
            Fails(FrustaResult.WrongState, () => world.GetHand(hand, ref h), "frusta_world_read");
            var state = new FrustaWorldState();
            world.Read(ref state);
            var fourth = hand;
            fourth.Index1 = 4;
            Fails(FrustaResult.StaleId, () => world.GetHand(fourth, ref h), "hand id", "no hand of this world");
            Fails(FrustaResult.NullId, () => world.GetHand(FrustaHandId.Null, ref h), "null");
            world.GetHand(hand, ref h);
            Assert.False(h.Solved);
            Assert.Equal(0, world.GetContactCount(hand));
            Assert.Equal(0, world.GetContacts(hand, Span<FrustaWorldContact>.Empty));
        }

        [Fact]
        public void AMissingTreeFileIsAnIoErrorNamingThePath()
        {
            string path = TestEnv.TempPath("missing.frtree");
            Fails(FrustaResult.Io, () => SphereTree.Load(path), Path.GetFileName(path));
        }

        [Fact]
        public void ACorruptTreeFileIsRefusedWithTheReason()
        {
            string good = TestEnv.TempPath("good.frtree");
            string bad = TestEnv.TempPath("bad.frtree");
            string truncated = TestEnv.TempPath("truncated.frtree");
            string notATree = TestEnv.TempPath("text.frtree");
            try
            {
                using (var tree = Box.Bake()) tree.Save(good);
                byte[] bytes = File.ReadAllBytes(good);
                Assert.True(bytes.Length > 256, $"{bytes.Length} bytes");

                // a leaf's radius (in the body, past the header) made negative
                byte[] corrupt = (byte[])bytes.Clone();
                for (int i = bytes.Length / 2; i < bytes.Length / 2 + 64; ++i) corrupt[i] = 0xFF;
                File.WriteAllBytes(bad, corrupt);
                var e = Assert.Throws<FrustaException>(() => SphereTree.Load(bad));
                Assert.True(e.Result == FrustaResult.CorruptFile || e.Result == FrustaResult.FileFormat, e.Message);
                Assert.False(string.IsNullOrEmpty(e.NativeMessage));

                File.WriteAllBytes(truncated, bytes.AsSpan(0, bytes.Length - 100).ToArray());
                e = Assert.Throws<FrustaException>(() => SphereTree.Load(truncated));
                Assert.True(e.Result == FrustaResult.CorruptFile || e.Result == FrustaResult.FileFormat, e.Message);

                File.WriteAllText(notATree, "this is not a sphere tree, but it is long enough to hold a header of one");
                Fails(FrustaResult.FileFormat, () => SphereTree.Load(notATree));
            }
            finally
            {
                foreach (var p in new[] { good, bad, truncated, notATree }) File.Delete(p);
            }
        }

        [Fact]
        public void ManagedArgumentChecksComeBeforeNativeCalls()
        {
            Assert.Throws<ArgumentNullException>(() => SphereTree.Load(null));
            Assert.Throws<ArgumentException>(() => SphereTree.Load("a\0b"));
            Assert.Throws<ArgumentException>(() => SphereTree.Bake(new float[4], Box.Triangles));
            using var world = new World();
            Assert.Throws<ArgumentNullException>(() => world.CreateObject(null, FrustaObjectDef.Default));
            Assert.Throws<ArgumentOutOfRangeException>(() => FrustaHandDef.Default.GetJointRadius(FrustaFinger.Index, 4));
        }

        [Fact]
        public void TheMessageIsThreadLocalAndTheExceptionKeepsIt()
        {
            FrustaWorldDef def = FrustaWorldDef.Default;
            def.MaxObjects = 0;
            FrustaException mine = Assert.Throws<FrustaException>(() => new World(def));
            FrustaException theirs = null;
            var t = new System.Threading.Thread(() =>
            {
                FrustaWorldDef d = FrustaWorldDef.Default;
                d.SpinUs = -1;
                theirs = Assert.Throws<FrustaException>(() => new World(d));
            });
            t.Start();
            t.Join();
            Assert.Contains("max_objects", mine.NativeMessage);
            Assert.Contains("spin_us", theirs.NativeMessage);
        }
    }
}
