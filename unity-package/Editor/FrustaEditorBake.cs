// SPDX-License-Identifier: MIT
using System;
using Frusta.Binding;
using Frusta.Unity;
using UnityEditor;
using UnityEngine;

namespace Frusta.Editor
{
    /// <summary>A bake in the editor: asks where the <c>.frtree</c> asset goes, runs a native bake job
    /// (<see cref="BakeJob"/>) shown in Unity's background tasks (<c>UnityEditor.Progress</c>) with its real
    /// progress and a cancel button, polled each editor update, and imports the tree when done. The
    /// editor never blocks.</summary>
    static class FrustaEditorBake
    {
        /// <summary>How a bake ended: the imported asset (null when there is none), and what to tell
        /// the user, how loudly.</summary>
        internal delegate void Finished(FrustaSphereTreeAsset asset, MessageType type, string message);

        /// <summary>Bake a Unity mesh (scaled to metres per axis) into a <c>.frtree</c> asset whose path the
        /// user picks (suggested: <paramref name="name"/>); <paramref name="finished"/> is called once,
        /// on the main thread, unless the user closes the save dialog.</summary>
        /// <returns>true when a bake started; false when the user closed the dialog or the mesh cannot
        /// be read (then <paramref name="finished"/> has said why).</returns>
        internal static bool Start(Mesh mesh, Vector3 metresPerUnit, in FrustaBakeDef def, string name, Finished finished)
        {
            if (!mesh.isReadable)
            {
                finished(null, MessageType.Error, $"{mesh.name} is not readable: tick Read/Write in its model's import settings.");
                return false;
            }
            string path = EditorUtility.SaveFilePanelInProject("Save sphere tree", name, "frtree", "Where the baked tree goes");
            if (string.IsNullOrEmpty(path)) return false;
            // Unity's left-handed mesh to Frusta's right-handed metres; the winding turns with it
            mesh.ToFrustaMesh(metresPerUnit, out float[] vertices, out int[] indices);
            BakeJob job;
            try
            {
                job = BakeJob.Start(vertices, indices, def);
            }
            catch (FrustaException e)
            {
                finished(null, MessageType.Error, $"The bake was refused ({e.Result}): {e.NativeMessage}");
                return false;
            }
            double target = def.TargetError * 1000;
            int progress = Progress.Start($"Frusta: baking {mesh.name}", path);
            Progress.RegisterCancelCallback(progress, () =>
            {
                job.Cancel();
                return true;
            });
            EditorApplication.CallbackFunction poll = null;
            poll = () =>
            {
                if (!job.IsDone)
                {
                    Progress.Report(progress, (float)job.Progress);
                    return;
                }
                EditorApplication.update -= poll;
                try
                {
                    using (SphereTree tree = job.Finish())
                        tree.Save(System.IO.Path.GetFullPath(path));
                    AssetDatabase.ImportAsset(path);
                    Progress.Finish(progress, Progress.Status.Succeeded);
                    var asset = AssetDatabase.LoadAssetAtPath<FrustaSphereTreeAsset>(path);
                    if (asset == null) finished(null, MessageType.Error, $"Baked {path}, but it did not import.");
                    else if (asset.TargetMet) finished(asset, MessageType.Info, $"Baked {path}: both errors within {target:0.###} mm.");
                    else finished(asset, MessageType.Warning, $"Baked {path} within the leaf budget at a coarser error than the target (see its error figures): raise the budget or the target error.");
                }
                catch (FrustaException e)
                {
                    bool cancelled = e.Result == FrustaResult.Cancelled;
                    Progress.Finish(progress, cancelled ? Progress.Status.Canceled : Progress.Status.Failed);
                    finished(null, cancelled ? MessageType.Info : MessageType.Error,
                             cancelled ? "The bake was cancelled." : $"The bake failed ({e.Result}): {e.NativeMessage}");
                }
                finally
                {
                    job.Dispose();
                }
            };
            EditorApplication.update += poll;
            return true;
        }
    }
}
