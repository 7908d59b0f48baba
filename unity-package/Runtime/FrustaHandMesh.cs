// SPDX-License-Identifier: MIT
using System;
using System.Runtime.InteropServices;
using Frusta.Binding;
using UnityEngine;
using UnityEngine.Rendering;

namespace Frusta.Unity
{
    /// <summary>
    /// Shows a <see cref="FrustaHand"/>'s graphic hand (the one that never sinks into objects) as a
    /// smooth mesh of its exact solids, with no rig: each finger segment's frustum with its joint
    /// balls and hemispherical fingertip, and the palm's spheres. The mesh is rebuilt in place each
    /// frame from the world's latched step (<see cref="HandMesh"/> in the binding does the geometry,
    /// already in Unity's frame), without allocating, and drawn in world space with
    /// <c>Graphics.DrawMesh</c>, so this object's transform does not move it.
    /// <para>Material: the one set in the inspector, or else a default made at run time in
    /// the inspector's colour from the first shader found of: the active render pipeline's lit shader
    /// ("Universal Render Pipeline/Lit", "HDRP/Lit"), the built-in pipeline's "Standard", then
    /// "Unlit/Color". <c>Shader.Find</c> only finds shaders a player build includes: in a build
    /// without a material that uses the shader, set a material here or add the shader to Project
    /// Settings &gt; Graphics &gt; Always Included Shaders.</para>
    /// </summary>
    [AddComponentMenu("Frusta/Frusta Hand Mesh")]
    [DisallowMultipleComponent]
    public sealed class FrustaHandMesh : MonoBehaviour
    {
        [Tooltip("The hand to show. Empty: the FrustaHand on this object or its parents.")]
        [SerializeField] FrustaHand hand;
        [Tooltip("Empty: a default lit material of the active render pipeline in the colour below.")]
        [SerializeField] Material material;
        [Tooltip("The default material's colour (unused when a material is set).")]
        [SerializeField] Color color = new Color(0.9f, 0.75f, 0.6f);
        [Tooltip("Show the palm's spheres too.")]
        [SerializeField] bool palm = true;
        [Tooltip("Vertices around each ring.")]
        [SerializeField, Range(3, 64)] int slices = HandMesh.DefaultSlices;
        [Tooltip("Rings per ball arc, poles excluded.")]
        [SerializeField, Range(1, 16)] int arcRings = HandMesh.DefaultArcRings;
        [Tooltip("Whether the hand casts shadows.")]
        [SerializeField] ShadowCastingMode castShadows = ShadowCastingMode.On;
        [Tooltip("Whether shadows fall on the hand.")]
        [SerializeField] bool receiveShadows = true;

        HandMesh layout;                    // null until the hand is first shown, or after a change
        FrustaHandId builtFor;              // the hand id the layout was sized for
        Mesh mesh;
        Material defaultMaterial;
        bool noShader;
        readonly FrustaSegment[] segments = new FrustaSegment[FrustaConstants.HandSegmentCount];
        FrustaSphere[] spheres = Array.Empty<FrustaSphere>();
        Vector3[] positions = Array.Empty<Vector3>(), normals = Array.Empty<Vector3>();

        /// <summary>The hand shown (null if none was set or found).</summary>
        public FrustaHand Hand => hand;

        /// <summary>The mesh, world space, Unity's frame (null until the hand is first shown).</summary>
        public Mesh Mesh => mesh;

        /// <summary>The material drawn with: the inspector's, or the default one.</summary>
        public Material Material => material != null ? material : defaultMaterial;

        void OnEnable()
        {
            if (hand == null) hand = GetComponentInParent<FrustaHand>();
        }

        // a tessellation or palm change takes effect at the next frame
        void OnValidate() => layout = null;

        void LateUpdate()
        {
            // the world latched its step in its Update; LateUpdate sees that step
            World world = hand != null && hand.WorldBehaviour != null ? hand.WorldBehaviour.World : null;
            if (world == null || !hand.Shown) return;
            // a rebuilt hand (FrustaHand.Rebuild: a new id, maybe another palm) is sized again
            if (layout == null || !builtFor.Equals(hand.Id)) Build(world);
            Material drawn = Material;
            if (drawn == null) return;

            world.GetHandSegments(hand.Id, FrustaHandKind.Graphic, segments);
            if (spheres.Length > 0) world.GetHandPalmSpheres(hand.Id, FrustaHandKind.Graphic, spheres);
            layout.Update(segments, spheres, MemoryMarshal.Cast<Vector3, float>(positions.AsSpan()),
                          MemoryMarshal.Cast<Vector3, float>(normals.AsSpan()), out Vector3d min, out Vector3d max);
            // the triangles never change and the box comes with the update
            const MeshUpdateFlags flags = MeshUpdateFlags.DontValidateIndices | MeshUpdateFlags.DontRecalculateBounds;
            mesh.SetVertices(positions, 0, positions.Length, flags);
            mesh.SetNormals(normals, 0, normals.Length, flags);
            var lo = new Vector3((float)min.X, (float)min.Y, (float)min.Z);
            var hi = new Vector3((float)max.X, (float)max.Y, (float)max.Z);
            mesh.bounds = new Bounds(0.5f * (lo + hi), hi - lo);
            Graphics.DrawMesh(mesh, Matrix4x4.identity, drawn, gameObject.layer, null, 0, null, castShadows, receiveShadows);
        }

        // size everything once for the hand's parts and the tessellation
        void Build(World world)
        {
            int palmCount = palm ? world.GetHandPalmSpheres(hand.Id, FrustaHandKind.Graphic, Span<FrustaSphere>.Empty) : 0;
            spheres = palmCount > 0 ? new FrustaSphere[palmCount] : Array.Empty<FrustaSphere>();
            layout = new HandMesh(segments.Length, palmCount, slices, arcRings, HandMeshFrame.Unity);
            builtFor = hand.Id;
            positions = new Vector3[layout.VertexCount];
            normals = new Vector3[layout.VertexCount];
            var indices = new int[layout.IndexCount];
            layout.WriteTriangles(indices);
            if (mesh == null)
            {
                mesh = new Mesh { name = "Frusta hand", hideFlags = HideFlags.DontSave };
                mesh.MarkDynamic();
            }
            mesh.Clear();
            mesh.indexFormat = layout.VertexCount > ushort.MaxValue ? IndexFormat.UInt32 : IndexFormat.UInt16;
            mesh.SetVertices(positions);
            mesh.SetNormals(normals);
            mesh.SetIndices(indices, MeshTopology.Triangles, 0, false);
            if (material == null && defaultMaterial == null && !noShader)
            {
                defaultMaterial = CreateDefaultMaterial(color);
                noShader = defaultMaterial == null;
                if (noShader)
                    Debug.LogError("FrustaHandMesh found no shader for its default material: set a material.", this);
            }
        }

        // the first shader found, as the class summary lists them
        static Material CreateDefaultMaterial(Color color)
        {
            Shader shader = null;
            if (GraphicsSettings.currentRenderPipeline != null)
            {
                shader = Shader.Find("Universal Render Pipeline/Lit");
                if (shader == null) shader = Shader.Find("HDRP/Lit");
            }
            else
            {
                shader = Shader.Find("Standard");
            }
            if (shader == null) shader = Shader.Find("Unlit/Color");
            if (shader == null) return null;
            // Material.color sets the shader's main colour (_Color, or _BaseColor marked [MainColor])
            return new Material(shader) { name = "Frusta hand (default)", color = color, hideFlags = HideFlags.DontSave };
        }

        void OnDestroy()
        {
            if (mesh != null) Destroy(mesh);
            if (defaultMaterial != null) Destroy(defaultMaterial);
        }
    }
}
