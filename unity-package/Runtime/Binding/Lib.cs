// SPDX-License-Identifier: MIT
using System.Runtime.CompilerServices;

// the tests and the Unity assemblies reach the raw P/Invoke layer; users go through
// the managed API (World, SphereTree, Hand)
[assembly: InternalsVisibleTo("Frusta.Binding.Tests")]
[assembly: InternalsVisibleTo("Frusta.Runtime")]
[assembly: InternalsVisibleTo("Frusta.Editor")]

namespace Frusta.Binding
{
    /// <summary>The one place that names the native library.</summary>
    internal static class Lib
    {
#if UNITY_IOS && !UNITY_EDITOR
        // static linking on iOS
        internal const string Name = "__Internal";
#else
        // frusta.dll, libfrusta.so, libfrusta.dylib; dotnet test loads it from the test's folder
        internal const string Name = "frusta";
#endif
    }
}
