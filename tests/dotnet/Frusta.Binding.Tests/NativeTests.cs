// SPDX-License-Identifier: MIT
// The P/Invoke layer against frusta.h: every function bound, by its C name, with the
// C parameter count, and exported by the library the tests load.
using System;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Runtime.InteropServices;
using System.Text.RegularExpressions;
using Frusta.Binding;
using Xunit;

namespace Frusta.Binding.Tests
{
    public class NativeTests
    {
        static (string Name, int Parameters)[] HeaderFunctions()
        {
            string text = File.ReadAllText(Path.Combine(TestEnv.Root, "native", "include", "frusta", "frusta.h"));
            return Regex.Matches(text, @"FRUSTA_API\s+[^;(]*?\b(frusta_[a-z_0-9]+)\s*\(([^)]*)\)")
                .Select(m =>
                {
                    string args = m.Groups[2].Value.Trim();
                    int count = args == "void" || args.Length == 0 ? 0 : args.Split(',').Length;
                    return (m.Groups[1].Value, count);
                })
                .ToArray();
        }

        static MethodInfo[] Imports() =>
            Type.GetType("Frusta.Binding.Native, Frusta.Binding", true)
                .GetMethods(BindingFlags.Static | BindingFlags.NonPublic | BindingFlags.Public)
                .Where(m => m.GetCustomAttribute<DllImportAttribute>() != null).ToArray();

        [Fact]
        public void EveryHeaderFunctionIsImportedOnceWithItsParameterCount()
        {
            var header = HeaderFunctions();
            Assert.True(header.Length >= 53, $"{header.Length} functions parsed from frusta.h");
            var imports = Imports();
            foreach (var (name, parameters) in header)
            {
                var bound = imports.Where(m => m.Name == name).ToArray();
                Assert.True(bound.Length == 1, $"{name} is imported {bound.Length} times");
                Assert.True(bound[0].GetParameters().Length == parameters,
                    $"{name}: {parameters} parameters in C, {bound[0].GetParameters().Length} in C#");
            }
            var names = header.Select(h => h.Name).ToHashSet();
            foreach (var m in imports) Assert.True(names.Contains(m.Name), $"{m.Name} is not in frusta.h");
        }

        [Fact]
        public void ImportsAreCdeclExactSpellingAndBlittable()
        {
            foreach (var m in Imports())
            {
                var a = m.GetCustomAttribute<DllImportAttribute>();
                Assert.Equal("frusta", a.Value);
                Assert.Equal(CallingConvention.Cdecl, a.CallingConvention);
                Assert.True(a.ExactSpelling, m.Name);
                Assert.False(m.IsGenericMethod, m.Name);
                foreach (var t in m.GetParameters().Select(p => p.ParameterType).Append(m.ReturnType))
                {
                    // pointers, primitives, int-backed enums and the blittable mirrors: nothing to marshal
                    Type e = t.IsPointer ? t.GetElementType() : t;
                    bool ok = e == typeof(void) || e.IsPrimitive || e.IsEnum || FrustaLibrary.Mirrors.Any(x => x.Type == e);
                    Assert.True(ok && !t.IsByRef, $"{m.Name}: {t} crosses the boundary");
                }
            }
        }

        [Fact]
        public void TheLoadedLibraryExportsEveryImport()
        {
            string path = Path.Combine(AppContext.BaseDirectory, "libfrusta.so");
            IntPtr lib = NativeLibrary.Load(path);
            try
            {
                foreach (var m in Imports())
                    Assert.True(NativeLibrary.TryGetExport(lib, m.Name, out _), $"{path} does not export {m.Name}");
            }
            finally
            {
                NativeLibrary.Free(lib);
            }
        }
    }
}
