// SPDX-License-Identifier: MIT
using System.Collections;
using Frusta.Binding;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.TestTools;

namespace Frusta.Unity.Tests
{
    public class FrustaRuntimeTests
    {
        [UnityTest]
        public IEnumerator AWorldComponentRunsAndIsDisposedWithItsObject()
        {
            var go = new GameObject("world");
            var behaviour = go.AddComponent<FrustaWorldBehaviour>();
            World world = behaviour.World;
            Assert.IsTrue(world.IsValid);
            yield return null; // Start: the own thread runs
            yield return new WaitForSeconds(0.1f);
            Assert.Greater(behaviour.State.Step, 0UL);
            Object.Destroy(go);
            yield return null;
            Assert.IsFalse(world.IsValid);
        }
    }
}
