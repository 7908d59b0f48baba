// SPDX-License-Identifier: MIT
using System;
using Frusta.Binding;
using UnityEngine;

namespace Frusta.Unity
{
    /// <summary>
    /// A baked sphere tree (a <c>.frtree</c> file) imported as an asset: its bytes and the figures
    /// the bake reported. <see cref="Load"/> hands the bytes to the native library in memory.
    /// </summary>
    public sealed class FrustaSphereTreeAsset : ScriptableObject
    {
        [SerializeField, HideInInspector] byte[] data = Array.Empty<byte>();
        [Tooltip("Leaf spheres of the tree.")]
        [SerializeField] int leafCount;
        [Tooltip("Levels below the root.")]
        [SerializeField] int depth;
        [Tooltip("Largest distance from the mesh surface to the leaves, millimetres (the bake's measure).")]
        [SerializeField] float uncoveredErrorMm;
        [Tooltip("Largest height of the leaves above the mesh surface, millimetres (the bake's measure).")]
        [SerializeField] float protrudingErrorMm;
        [Tooltip("Both error figures within the bake's target.")]
        [SerializeField] bool targetMet;

        /// <summary>The file's bytes.</summary>
        public byte[] Data => data;
        /// <summary>Leaf spheres.</summary>
        public int LeafCount => leafCount;
        /// <summary>Levels below the root.</summary>
        public int Depth => depth;
        /// <summary>Largest distance from the mesh surface to the leaves, millimetres.</summary>
        public float UncoveredErrorMm => uncoveredErrorMm;
        /// <summary>Largest height of the leaves above the mesh surface, millimetres.</summary>
        public float ProtrudingErrorMm => protrudingErrorMm;
        /// <summary>Both figures within the bake's target.</summary>
        public bool TargetMet => targetMet;

        /// <summary>Fill from a file's bytes and its tree's info (the importer calls this).</summary>
        public void Set(byte[] bytes, in FrustaSphereTreeInfo info)
        {
            data = bytes;
            leafCount = info.LeafCount;
            depth = info.Depth;
            uncoveredErrorMm = (float)(info.UncoveredError * 1000);
            protrudingErrorMm = (float)(info.ProtrudingError * 1000);
            targetMet = info.TargetMet;
        }

        /// <summary>Load the tree natively; dispose the result (a world keeps its own reference).</summary>
        public SphereTree Load() => SphereTree.LoadFromMemory(data);
    }
}
