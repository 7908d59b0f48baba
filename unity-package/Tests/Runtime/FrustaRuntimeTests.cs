// SPDX-License-Identifier: MIT
using System.Collections;
using System.Collections.Generic;
using System.Text.RegularExpressions;
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

        [UnityTest]
        public IEnumerator AHandSpawnedWhileTheWorldRunsJoinsItAndLeavesItWhenDestroyed()
        {
            var go = new GameObject("world");
            var behaviour = go.AddComponent<FrustaWorldBehaviour>();
            yield return null; // Start: the own thread runs
            var handObject = new GameObject("spawned hand");
            handObject.transform.SetParent(go.transform, false);
            var hand = handObject.AddComponent<FrustaHand>();
            FrustaHandId id = hand.Id;
            Assert.IsFalse(id.IsNull);
            CollectionAssert.AreEqual(new[] { id }, behaviour.World.Hands);
            float until = Time.realtimeSinceStartup + 5f;
            while (!hand.State.Solved && Time.realtimeSinceStartup < until) yield return null;
            Assert.IsTrue(hand.State.Solved);
            Object.Destroy(handObject);
            yield return null;
            CollectionAssert.IsEmpty(behaviour.World.Hands);
            var stale = Assert.Throws<FrustaException>(
                () => behaviour.World.SetHaptic(id, FrustaPose.Identity, new double[FrustaConstants.HandJointCount]));
            Assert.AreEqual(FrustaResult.StaleId, stale.Result);
            Object.Destroy(go);
            yield return null;
        }

        [UnityTest]
        public IEnumerator AGloveThatDoesNotOpenLeavesTheHandToTheHost()
        {
            var go = new GameObject("world");
            go.AddComponent<FrustaWorldBehaviour>();
            var handObject = new GameObject("hand");
            handObject.SetActive(false); // its components are set up first
            handObject.transform.SetParent(go.transform, false);
            var hand = handObject.AddComponent<FrustaHand>();
            var glove = handObject.AddComponent<FrustaGloveDevice>();
            glove.Uri = "serial:/nonexistent/tty";
            handObject.SetActive(true);
            LogAssert.Expect(LogType.Error, new Regex(@"did not open \(Io\): /nonexistent/tty"));
            yield return null; // Start: the glove tries to open
            Assert.IsFalse(glove.IsOpen);
            Assert.AreEqual(FrustaDeviceState.Closed, glove.State);
            Assert.IsFalse(hand.DrivenByDevice);
            Object.Destroy(go);
            yield return null;
        }

#if UNITY_EDITOR
        [UnityTest]
        public IEnumerator TheSamplesRecordingDrivesTheHandThroughAGloveComponent()
        {
            var package = UnityEditor.PackageManager.PackageInfo.FindForAssembly(typeof(FrustaGloveDevice).Assembly);
            Assert.IsNotNull(package);
            string recording = System.IO.Path.Combine(package.resolvedPath, "Samples~", "HandDemo", "demo_glove.frrec");
            var go = new GameObject("world");
            go.AddComponent<FrustaWorldBehaviour>();
            var handObject = new GameObject("hand");
            handObject.SetActive(false);
            handObject.transform.SetParent(go.transform, false);
            var hand = handObject.AddComponent<FrustaHand>();
            var glove = handObject.AddComponent<FrustaGloveDevice>();
            glove.Uri = $"replay:{recording}?speed=max";
            var states = new List<(FrustaDeviceState, FrustaDeviceState)>();
            glove.StateChanged.AddListener((before, now) => states.Add((before, now)));
            handObject.SetActive(true);
            yield return null; // Start: the glove opens
            Assert.IsTrue(glove.IsOpen);
            Assert.IsTrue(hand.DrivenByDevice);
            float until = Time.realtimeSinceStartup + 5f;
            while (glove.State != FrustaDeviceState.Disconnected && Time.realtimeSinceStartup < until) yield return null;
            Assert.AreEqual(FrustaDeviceState.Disconnected, glove.State);
            Assert.AreEqual(1211L, glove.Status.FramesOk); // every sample of the recording
            Assert.AreEqual(0L, glove.Status.FramesCorrupt);

            glove.enabled = false; // closes it: the hand is the host's again
            Assert.IsFalse(glove.IsOpen);
            Assert.IsFalse(hand.DrivenByDevice);
            CollectionAssert.AreEqual(new[]
            {
                (FrustaDeviceState.Closed, FrustaDeviceState.Connected),
                (FrustaDeviceState.Connected, FrustaDeviceState.Disconnected),
                (FrustaDeviceState.Disconnected, FrustaDeviceState.Closed),
            }, states);
            Object.Destroy(go);
            yield return null;
        }
#endif
    }
}
