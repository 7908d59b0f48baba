// SPDX-License-Identifier: MIT
using System;
using System.IO;
using Frusta.Binding;
using Xunit;
using static Frusta.Binding.Tests.Assertions;

namespace Frusta.Binding.Tests
{
    public class SphereTreeTests
    {
        [Fact]
        public void ABakedBoxHasLeavesInsideItsBoundsAndSavesAndLoadsTheSame()
        {
            using var tree = Box.Bake();
            FrustaSphereTreeInfo info = tree.Info;
            Assert.Equal(12, info.TriangleCount);
            Assert.Equal(4, info.Branching);
            Assert.True(info.LeafCount > 0 && info.NodeCount > info.LeafCount && info.Depth >= 1);
            Assert.Equal(0.001, info.TargetError);
            Assert.True(info.TargetMet, $"uncovered {info.UncoveredError}, protruding {info.ProtrudingError}");
            Assert.True(info.UncoveredError <= 0.001 && info.ProtrudingError <= 0.001);
            Assert.Equal(100000, info.ErrorSamples);
            Assert.True(info.BakeSeconds > 0);
            Near(new Vector3d(0.01, 0.01, 0.01), info.BoundsMax, 0.0011, "bounds max");
            Near(new Vector3d(-0.01, -0.01, -0.01), info.BoundsMin, 0.0011, "bounds min");

            var leaves = new FrustaSphere[tree.LeafCount];
            Assert.Equal(info.LeafCount, tree.GetLeaves(leaves));
            foreach (var s in leaves)
            {
                Assert.True(s.Radius > 0);
                // within the reported bounds, and those within the box grown by the target error
                Vector3d lo = s.Center - new Vector3d(s.Radius, s.Radius, s.Radius), hi = s.Center + new Vector3d(s.Radius, s.Radius, s.Radius);
                Assert.True(lo.X >= info.BoundsMin.X - 1e-9 && lo.Y >= info.BoundsMin.Y - 1e-9 && lo.Z >= info.BoundsMin.Z - 1e-9 &&
                            hi.X <= info.BoundsMax.X + 1e-9 && hi.Y <= info.BoundsMax.Y + 1e-9 && hi.Z <= info.BoundsMax.Z + 1e-9,
                            $"leaf {s.Center} r {s.Radius} outside the bounds");
                foreach (double c in new[] { s.Center.X, s.Center.Y, s.Center.Z })
                    Assert.True(Math.Abs(c) + s.Radius <= 0.01 + info.TargetError, $"leaf {s.Center} r {s.Radius} sticks out");
            }
            // a short buffer gets what fits, and the count of all
            var shorter = new FrustaSphere[leaves.Length - 1];
            Assert.Equal(leaves.Length, tree.GetLeaves(shorter));
            Assert.Equal(leaves[^2].Center, shorter[^1].Center);

            string path = TestEnv.TempPath("box.frtree");
            try
            {
                tree.Save(path);
                using var loaded = SphereTree.Load(path);
                Assert.Equal(info.LeafCount, loaded.Info.LeafCount);
                var again = new FrustaSphere[leaves.Length];
                loaded.GetLeaves(again);
                for (int i = 0; i < leaves.Length; ++i)
                {
                    Assert.Equal(leaves[i].Center, again[i].Center);
                    Assert.Equal(leaves[i].Radius, again[i].Radius);
                }
            }
            finally
            {
                File.Delete(path);
            }
        }

        [Fact]
        public void ASegmentQueryFindsTheLeavesNearIt()
        {
            using var tree = Box.Bake();
            var pose = new FrustaPose(new Vector3d(1, 0, 0), Quaterniond.Identity);
            // a segment lying on the box's top face (z = 0.01 in the object frame)
            var segment = new FrustaSegment
            {
                Proximal = new Vector3d(0.99, 0, 0.012),
                Distal = new Vector3d(1.01, 0, 0.012),
                ProximalRadius = 0.001,
                DistalRadius = 0.001,
            };
            var hits = new FrustaTreeHit[256];
            int found = tree.QuerySegment(pose, segment, 0.002, -1, hits);
            Assert.True(found > 0 && found <= hits.Length, $"{found} hits");
            for (int i = 0; i < found; ++i)
            {
                Assert.True(hits[i].Leaf >= 0);
                Assert.True(hits[i].Sphere.Center.X > 0.98, "in the world frame through the pose");
            }
            var far = segment;
            far.Proximal.Z = far.Distal.Z = 0.5;
            Assert.Equal(0, tree.QuerySegment(pose, far, 0.002, -1, hits));
        }

        [Fact]
        public void GeometryQueriesGiveTheDistance()
        {
            var segment = new FrustaSegment
            {
                Proximal = new Vector3d(0, 0, 0),
                Distal = new Vector3d(0.05, 0, 0),
                ProximalRadius = 0.01,
                DistalRadius = 0.008,
            };
            var sphere = new FrustaSphere(new Vector3d(0.1, 0, 0), 0.02);
            FrustaContactQuery q = Geometry.QueryContact(segment, sphere);
            Near(0.1 - 0.05 - 0.008 - 0.02, q.Distance, 1e-12, "gap beyond the distal ball");
            Assert.Equal(FrustaFeature.Distal, q.Feature);
            Assert.False(q.Contact);
            Near(new Vector3d(-1, 0, 0), q.Normal, 1e-12, "normal");
            FrustaConstraint c = Geometry.EvaluateConstraint(segment, sphere, FrustaConstraintForm.Distance);
            Near(q.Distance, c.Value, 1e-12, "constraint");
            Near(new Vector3d(1, 0, 0), c.GradCenter, 1e-9, "dg/dO");
            sphere.Radius = -1;
            Fails(FrustaResult.OutOfRange, () => Geometry.QueryContact(segment, sphere), "radius");
        }

        [Fact]
        public void AStandaloneHandReportsItsGeometryAndJacobian()
        {
            using var hand = new Hand();
            Assert.True(hand.IsValid);
            var angles = new double[20];
            angles[5] = 0.5; // index, first flexion
            hand.SetJointAngles(angles);
            var back = new double[20];
            Assert.Equal(20, hand.GetJointAngles(back));
            Assert.Equal(0.5, back[5]);
            var firstSix = new double[6];
            Assert.Equal(20, hand.GetJointAngles(firstSix));
            Assert.Equal(0.5, firstSix[5]);
            var jacobian = new double[FrustaConstants.PointJacobianLength];
            Vector3d point = hand.GetPointJacobian(FrustaFinger.Index, 2, new Vector3d(0.01, 0, 0), jacobian);
            var segments = new FrustaSegment[15];
            hand.GetSegments(segments);
            Assert.True((point - segments[5].Proximal).Length > 0.009);
            // the palm's translation columns are the identity
            for (int row = 0; row < 3; ++row)
                for (int col = 0; col < 3; ++col)
                    Assert.Equal(row == col ? 1.0 : 0.0, jacobian[row * 10 + 4 + col], 12);
            Assert.True(hand.PalmSphereCount > 0);
            Fails(FrustaResult.OutOfRange, () => hand.SetJointAngles(new double[3]), "count");
        }
    }
}
