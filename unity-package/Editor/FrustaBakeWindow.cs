// SPDX-License-Identifier: MIT
using System;
using System.Diagnostics;
using System.IO;
using System.Threading.Tasks;
using Frusta.Binding;
using Frusta.Unity;
using UnityEditor;
using UnityEngine;

namespace Frusta.Editor
{
    /// <summary>
    /// Window > Frusta > Bake Sphere Tree: bakes a mesh asset into a <c>.frtree</c> asset through the
    /// native bake (frusta_create_sphere_tree_from_mesh) on a worker thread, with a progress bar, and shows the
    /// tree's error figures.
    /// </summary>
    public sealed class FrustaBakeWindow : EditorWindow
    {
        Mesh mesh;
        float unitsToMetres = 1f;
        float targetErrorMm = 1f;
        int maxLeaves = 200000;
        int branching = 4;
        Task<SphereTree> bake;
        Stopwatch clock;
        string outputPath;
        string message = "";
        MessageType messageType = MessageType.None;
        FrustaSphereTreeInfo info;
        bool haveInfo;

        [MenuItem("Window/Frusta/Bake Sphere Tree")]
        static void Open() => GetWindow<FrustaBakeWindow>("Frusta Bake");

        void OnGUI()
        {
            using (new EditorGUI.DisabledScope(bake != null))
            {
                mesh = (Mesh)EditorGUILayout.ObjectField("Mesh", mesh, typeof(Mesh), false);
                unitsToMetres = EditorGUILayout.FloatField(new GUIContent("Metres per unit", "The mesh's scale to metres."), unitsToMetres);
                targetErrorMm = EditorGUILayout.FloatField(new GUIContent("Target error (mm)", "Bound on both error figures."), targetErrorMm);
                maxLeaves = EditorGUILayout.IntField("Leaf budget", maxLeaves);
                branching = EditorGUILayout.IntSlider("Branching", branching, 2, 16);
                if (GUILayout.Button("Bake") && mesh != null) StartBake();
            }
            if (message.Length > 0) EditorGUILayout.HelpBox(message, messageType);
            if (haveInfo)
            {
                EditorGUILayout.LabelField("Leaves", info.LeafCount.ToString());
                EditorGUILayout.LabelField("Depth", info.Depth.ToString());
                EditorGUILayout.LabelField("Uncovered error", $"{info.UncoveredError * 1000:0.###} mm");
                EditorGUILayout.LabelField("Protruding error", $"{info.ProtrudingError * 1000:0.###} mm");
                EditorGUILayout.LabelField("Bake time", $"{info.BakeSeconds:0.##} s");
            }
        }

        void StartBake()
        {
            if (!mesh.isReadable)
            {
                Show(MessageType.Error, $"{mesh.name} is not readable: tick Read/Write in its model's import settings.");
                return;
            }
            string path = EditorUtility.SaveFilePanelInProject("Save sphere tree", mesh.name, "frtree", "Where the baked tree goes");
            if (string.IsNullOrEmpty(path)) return;

            // Unity's left-handed mesh to Frusta's right-handed metres; the winding turns with it
            mesh.ToFrustaMesh(Vector3.one * unitsToMetres, out float[] vertices, out int[] indices);
            FrustaBakeDef def = FrustaBakeDef.Default;
            def.TargetError = targetErrorMm / 1000.0;
            def.MaxLeaves = maxLeaves;
            def.Branching = branching;

            outputPath = path;
            haveInfo = false;
            clock = Stopwatch.StartNew();
            bake = Task.Run(() => SphereTree.Bake(vertices, indices, def));
            EditorApplication.update += Poll;
        }

        void Poll()
        {
            if (!bake.IsCompleted)
            {
                // the native bake reports no progress: show the time it has taken so far
                EditorUtility.DisplayProgressBar("Frusta", $"Baking {mesh.name} ({clock.Elapsed.TotalSeconds:0} s)",
                                                 (float)(1 - Math.Exp(-clock.Elapsed.TotalSeconds / 10)));
                return;
            }
            EditorApplication.update -= Poll;
            EditorUtility.ClearProgressBar();
            try
            {
                using (SphereTree tree = bake.Result)
                {
                    tree.Save(Path.GetFullPath(outputPath));
                    info = tree.Info;
                    haveInfo = true;
                }
                AssetDatabase.ImportAsset(outputPath);
                if (info.TargetMet)
                    Show(MessageType.Info, $"Baked {outputPath}: both errors within {targetErrorMm} mm.");
                else
                    Show(MessageType.Warning, $"Baked {outputPath}, but the leaf budget ran out before the target: raise it or the target error.");
            }
            catch (AggregateException e) when (e.InnerException is FrustaException f)
            {
                Show(MessageType.Error, $"The bake failed ({f.Result}): {f.NativeMessage}");
            }
            catch (FrustaException f)
            {
                Show(MessageType.Error, $"Saving failed ({f.Result}): {f.NativeMessage}");
            }
            finally
            {
                bake = null;
                Repaint();
            }
        }

        void Show(MessageType type, string text)
        {
            messageType = type;
            message = text;
            Repaint();
        }

        void OnDisable()
        {
            if (bake != null) EditorApplication.update -= Poll;
            EditorUtility.ClearProgressBar();
        }
    }
}
