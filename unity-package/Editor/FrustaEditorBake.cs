// SPDX-License-Identifier: MIT
using System;
using Frusta.Binding;
using Frusta.Unity;
using UnityEditor;
using UnityEngine;

namespace Frusta.Editor
{
    /// <summary>A bake in the editor: a native bake job (<see cref="BakeJob"/>) shown in Unity's
    /// background tasks (<c>UnityEditor.Progress</c>) with its real progress and a cancel button, polled
    /// each editor update, saved as a <c>.frtree</c> asset when done. The editor never blocks.</summary>
    static class FrustaEditorBake
    {
        /// <summary>Bake a Unity mesh (scaled to metres per axis) into the <c>.frtree</c> at
        /// <paramref name="assetPath"/>, then call <paramref name="done"/> with the imported asset, or
        /// <paramref name="failed"/> with why not (cancelled included).</summary>
        internal static void Start(Mesh mesh, Vector3 metresPerUnit, in FrustaBakeDef def, string assetPath,
                                   Action<FrustaSphereTreeAsset> done, Action<string> failed)
        {
            // Unity's left-handed mesh to Frusta's right-handed metres; the winding turns with it
            mesh.ToFrustaMesh(metresPerUnit, out float[] vertices, out int[] indices);
            BakeJob job;
            try
            {
                job = BakeJob.Start(vertices, indices, def);
            }
            catch (FrustaException e)
            {
                failed($"The bake was refused ({e.Result}): {e.NativeMessage}");
                return;
            }
            int progress = Progress.Start($"Frusta: baking {mesh.name}", assetPath);
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
                        tree.Save(System.IO.Path.GetFullPath(assetPath));
                    AssetDatabase.ImportAsset(assetPath);
                    Progress.Finish(progress, Progress.Status.Succeeded);
                    done(AssetDatabase.LoadAssetAtPath<FrustaSphereTreeAsset>(assetPath));
                }
                catch (FrustaException e)
                {
                    bool cancelled = e.Result == FrustaResult.Cancelled;
                    Progress.Finish(progress, cancelled ? Progress.Status.Canceled : Progress.Status.Failed);
                    failed(cancelled ? "The bake was cancelled." : $"The bake failed ({e.Result}): {e.NativeMessage}");
                }
                finally
                {
                    job.Dispose();
                }
            };
            EditorApplication.update += poll;
        }
    }
}
