// SPDX-License-Identifier: MIT
using Frusta.Binding;
using Frusta.Unity;
using UnityEditor;
using UnityEngine;

namespace Frusta.Editor
{
    /// <summary>
    /// Window > Frusta > Bake Sphere Tree: bakes a mesh asset into a <c>.frtree</c> asset through a
    /// native bake job (<see cref="FrustaEditorBake"/>: Unity's progress bar with the bake's real
    /// progress and a cancel button), and shows the tree's error figures.
    /// </summary>
    public sealed class FrustaBakeWindow : EditorWindow
    {
        Mesh mesh;
        float unitsToMetres = 1f;
        float targetErrorMm = 1f;
        int maxLeaves = 200000;
        int branching = 4;
        bool baking;
        string message = "";
        MessageType messageType = MessageType.None;
        FrustaSphereTreeAsset baked;

        [MenuItem("Window/Frusta/Bake Sphere Tree")]
        static void Open() => GetWindow<FrustaBakeWindow>("Frusta Bake");

        void OnGUI()
        {
            using (new EditorGUI.DisabledScope(baking))
            {
                mesh = (Mesh)EditorGUILayout.ObjectField("Mesh", mesh, typeof(Mesh), false);
                unitsToMetres = EditorGUILayout.FloatField(new GUIContent("Metres per unit", "The mesh's scale to metres."), unitsToMetres);
                targetErrorMm = EditorGUILayout.FloatField(new GUIContent("Target error (mm)", "Bound on both error figures."), targetErrorMm);
                maxLeaves = EditorGUILayout.IntField(new GUIContent("Leaf budget", "The most leaf spheres the tree may have."), maxLeaves);
                branching = EditorGUILayout.IntSlider(new GUIContent("Branching", "Children per node."), branching, 2, 16);
                if (GUILayout.Button("Bake") && mesh != null) StartBake();
            }
            if (message.Length > 0) EditorGUILayout.HelpBox(message, messageType);
            if (baked != null)
            {
                EditorGUILayout.LabelField("Leaves", baked.LeafCount.ToString());
                EditorGUILayout.LabelField("Depth", baked.Depth.ToString());
                EditorGUILayout.LabelField("Uncovered error", $"{baked.UncoveredErrorMm:0.###} mm");
                EditorGUILayout.LabelField("Protruding error", $"{baked.ProtrudingErrorMm:0.###} mm");
            }
        }

        void StartBake()
        {
            FrustaBakeDef def = FrustaBakeDef.Default;
            def.TargetError = targetErrorMm / 1000.0;
            def.MaxLeaves = maxLeaves;
            def.Branching = branching;
            baked = null;
            baking = FrustaEditorBake.Start(mesh, Vector3.one * unitsToMetres, def, mesh.name, (asset, type, text) =>
            {
                baking = false;
                baked = asset;
                Show(type, text);
            });
            if (baking) Show(MessageType.Info, $"Baking {mesh.name} (Unity's progress bar shows how far, and cancels)...");
        }

        void Show(MessageType type, string text)
        {
            messageType = type;
            message = text;
            Repaint();
        }
    }
}
