// SPDX-License-Identifier: MIT
using Frusta.Binding;
using Frusta.Unity;
using NUnit.Framework;
using UnityEngine;

namespace Frusta.Editor.Tests
{
    public class FrustaEditorTests
    {
        [Test]
        public void TheEditorLoadsTheNativeLibraryOfTheBindingsAbi()
        {
            FrustaLibrary.EnsureCompatible();
            Assert.AreEqual(FrustaConstants.AbiVersion, FrustaLibrary.AbiVersion);
        }

        [Test]
        public void UnityVectorsAndRotationsRoundTrip()
        {
            var p = new Vector3(0.1f, -0.2f, 0.3f);
            Assert.AreEqual(p, p.ToFrustaVector().ToUnityVector());
            Assert.AreEqual(-0.3, p.ToFrustaVector().Z, 1e-7);
            Quaternion q = Quaternion.Euler(10, 20, 30);
            Assert.Less(Quaternion.Angle(q, q.ToFrustaRotation().ToUnityRotation()), 1e-3f);
        }
    }
}
