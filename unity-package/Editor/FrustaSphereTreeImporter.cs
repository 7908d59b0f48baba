// SPDX-License-Identifier: MIT
using System.IO;
using Frusta.Binding;
using Frusta.Unity;
using UnityEditor.AssetImporters;
using UnityEngine;

namespace Frusta.Editor
{
    /// <summary>Imports a baked <c>.frtree</c> file as a <see cref="FrustaSphereTreeAsset"/>, checked by
    /// the native loader. Bump the version whenever the file format changes.</summary>
    [ScriptedImporter(1, "frtree")]
    public sealed class FrustaSphereTreeImporter : ScriptedImporter
    {
        /// <summary>Load the file natively (which validates it), then store its bytes and figures.</summary>
        public override void OnImportAsset(AssetImportContext ctx)
        {
            var asset = ScriptableObject.CreateInstance<FrustaSphereTreeAsset>();
            byte[] bytes = File.ReadAllBytes(Path.GetFullPath(ctx.assetPath));
            try
            {
                // the bytes the asset keeps are the ones checked
                using (SphereTree tree = SphereTree.LoadFromMemory(bytes))
                    asset.Set(bytes, tree.Info);
            }
            catch (FrustaException e)
            {
                ctx.LogImportError($"{ctx.assetPath} is not a sphere tree this Frusta can read ({e.Result}): {e.NativeMessage}");
            }
            ctx.AddObjectToAsset("tree", asset);
            ctx.SetMainObject(asset);
        }
    }
}
