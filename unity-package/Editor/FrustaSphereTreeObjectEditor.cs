// SPDX-License-Identifier: MIT
using Frusta.Unity;
using UnityEditor;
using UnityEngine;

namespace Frusta.Editor
{
    /// <summary>The object's settings, its tree's error figures, a Bake button that bakes the object's
    /// own mesh (its MeshFilter's, else its MeshCollider's) at its transform's scale, and a warning where
    /// two engines would move it or nothing gives it a shape.</summary>
    [CustomEditor(typeof(FrustaSphereTreeObject)), CanEditMultipleObjects]
    public sealed class FrustaSphereTreeObjectEditor : UnityEditor.Editor
    {
        string message;
        MessageType messageType;
        bool baking;

        /// <summary>The serialized fields, the tree's figures and Bake, then the warnings.</summary>
        public override void OnInspectorGUI()
        {
            DrawDefaultInspector();
            if (targets.Length == 1) TreeSection((FrustaSphereTreeObject)target);
            foreach (Object t in targets)
            {
                var o = (FrustaSphereTreeObject)t;
                var so = new SerializedObject(o);
                var body = o.GetComponent<Rigidbody>();
                if (so.FindProperty("dynamic").boolValue && body != null && !body.isKinematic)
                    EditorGUILayout.HelpBox(
                        $"{o.name}: Frusta (Dynamic) and PhysX (a non-kinematic Rigidbody) would both move this object. " +
                        "In Play mode the Rigidbody is made kinematic and Frusta moves it. Untick Dynamic to let PhysX " +
                        "move it and receive the hands' forces instead.", MessageType.Warning);
                if (so.FindProperty("tree").objectReferenceValue == null &&
                    string.IsNullOrEmpty(so.FindProperty("treePath").stringValue))
                    EditorGUILayout.HelpBox($"{o.name}: no sphere tree (an asset or a path): the hands will not touch it.",
                                            MessageType.Warning);
            }
        }

        void TreeSection(FrustaSphereTreeObject o)
        {
            var so = new SerializedObject(o);
            var asset = so.FindProperty("tree").objectReferenceValue as FrustaSphereTreeAsset;
            if (asset != null)
            {
                EditorGUILayout.LabelField("Leaves", asset.LeafCount.ToString());
                EditorGUILayout.LabelField(new GUIContent("Uncovered error", "Largest distance from the mesh surface to the leaves: how far a finger may sink."),
                                           new GUIContent($"{asset.UncoveredErrorMm:0.###} mm"));
                EditorGUILayout.LabelField(new GUIContent("Protruding error", "Largest height of the leaves above the mesh surface: how far off a finger may stop."),
                                           new GUIContent($"{asset.ProtrudingErrorMm:0.###} mm"));
            }
            Mesh mesh = o.TryGetComponent(out MeshFilter filter) && filter.sharedMesh != null ? filter.sharedMesh
                      : o.TryGetComponent(out MeshCollider collider) ? collider.sharedMesh : null;
            using (new EditorGUI.DisabledScope(mesh == null || baking || Application.isPlaying))
            {
                var label = new GUIContent(baking ? "Baking..." : "Bake This Object's Mesh",
                    "Bake the MeshFilter's (else the MeshCollider's) mesh at this transform's scale into a .frtree asset, " +
                    "in the background (Unity's progress bar; cancel there), and use it.");
                if (GUILayout.Button(label)) Bake(o, mesh);
            }
            if (message != null) EditorGUILayout.HelpBox(message, messageType);
        }

        void Bake(FrustaSphereTreeObject o, Mesh mesh)
        {
            baking = FrustaEditorBake.Start(mesh, o.transform.lossyScale, FrustaBakeDef.Default, o.name, (asset, type, text) =>
            {
                baking = false;
                Show(type, text);
                if (o == null || asset == null) return;
                // through the serialized object: undoable, and the scene is marked changed
                var so = new SerializedObject(o);
                so.FindProperty("tree").objectReferenceValue = asset;
                so.ApplyModifiedProperties();
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
