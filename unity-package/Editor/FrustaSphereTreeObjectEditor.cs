// SPDX-License-Identifier: MIT
using Frusta.Unity;
using UnityEditor;
using UnityEngine;

namespace Frusta.Editor
{
    /// <summary>The object's settings, with a warning where two engines would move it or nothing
    /// gives it a shape.</summary>
    [CustomEditor(typeof(FrustaSphereTreeObject)), CanEditMultipleObjects]
    public sealed class FrustaSphereTreeObjectEditor : UnityEditor.Editor
    {
        /// <summary>The serialized fields, then the warnings.</summary>
        public override void OnInspectorGUI()
        {
            DrawDefaultInspector();
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
    }
}
