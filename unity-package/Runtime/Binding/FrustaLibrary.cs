// SPDX-License-Identifier: MIT
using System;
using System.Runtime.InteropServices;
using System.Text;
using System.Threading;

namespace Frusta.Binding
{
    /// <summary>
    /// The loaded native library: its version, and the load-time check that it is the ABI
    /// this binding mirrors. Every constructor and default of the binding runs
    /// <see cref="EnsureCompatible"/> first, so a mismatched library fails loudly at the first
    /// call instead of corrupting memory.
    /// </summary>
    public static unsafe partial class FrustaLibrary
    {
        /// <summary>One mirrored struct: its C name, its C# type and its C# size.</summary>
        internal readonly struct Mirror
        {
            internal readonly string CName;
            internal readonly Type Type;
            internal readonly int Sizeof;

            internal Mirror(string cName, Type type, int size)
            {
                CName = cName;
                Type = type;
                Sizeof = size;
            }
        }

        static readonly object Gate = new object();
        static int checkedOk;
        static Exception failure;

        /// <summary>The library's version, major*1000000 + minor*1000 + patch (<c>frusta_version</c>). Thread: any.</summary>
        public static int Version
        {
            get
            {
                EnsureCompatible();
                return Native.frusta_version();
            }
        }

        /// <summary>The library's version as "major.minor.patch", e.g. "0.4.0". Thread: any.</summary>
        public static string VersionString
        {
            get
            {
                int v = Version;
                return $"{v / 1000000}.{v / 1000 % 1000}.{v % 1000}";
            }
        }

        /// <summary>The library's ABI version (<c>frusta_abi_version</c>); equals
        /// <see cref="FrustaConstants.AbiVersion"/> once <see cref="EnsureCompatible"/> passed. Thread: any.</summary>
        public static int AbiVersion => Native.frusta_abi_version();

        /// <summary>A native call made only once <see cref="EnsureCompatible"/> passed, as a call
        /// that returns a mirrored struct by value must be (before, its layout may not be the
        /// library's). Allocation-free with a lambda that captures nothing.</summary>
        internal static T Compatible<T>(Func<T> call)
        {
            EnsureCompatible();
            return call();
        }

        /// <summary>
        /// Check once per process that the native library has this binding's ABI
        /// (<c>frusta_check_abi</c>) and that every mirrored struct has the native size
        /// (<c>frusta_struct_size</c>). Cheap after the first call. Thread: any.
        /// </summary>
        /// <exception cref="FrustaException">With <see cref="FrustaResult.AbiMismatch"/> naming
        /// every disagreement; thrown again by every later call.</exception>
        /// <exception cref="DllNotFoundException">The native library is not where the runtime looks
        /// (in Unity: Runtime/Plugins/&lt;platform&gt;; in dotnet test: next to the test assembly).</exception>
        public static void EnsureCompatible()
        {
            if (Volatile.Read(ref checkedOk) == 1) return;
            lock (Gate)
            {
                if (checkedOk == 1) return;
                if (failure != null) throw failure;
                try
                {
                    Check();
                    Volatile.Write(ref checkedOk, 1);
                }
                catch (FrustaException e)
                {
                    failure = e;
                    throw;
                }
            }
        }

        /// <summary>The native name of a result code, e.g. "FRUSTA_ERROR_STALE_ID"
        /// (<c>frusta_result_name</c>). Thread: any.</summary>
        /// <param name="result">A result code.</param>
        /// <returns>The header's name of the code.</returns>
        public static string GetResultName(FrustaResult result) => Utf8.Decode(Native.frusta_result_name((int)result));

        /// <summary>sizeof the public struct named <paramref name="cName"/> in the loaded library, or 0
        /// for a name it does not have (<c>frusta_struct_size</c>). Thread: any.</summary>
        /// <param name="cName">A C struct name, e.g. "frusta_world_def".</param>
        /// <returns>Bytes, or 0.</returns>
        public static int GetNativeStructSize(string cName)
        {
            if (cName == null) throw new ArgumentNullException(nameof(cName));
            Span<byte> name = stackalloc byte[Utf8.MaxBytes(cName)];
            Utf8.Encode(cName, name, nameof(cName));
            fixed (byte* p = name) return Native.frusta_struct_size(p);
        }

        static void Check()
        {
            var problems = new StringBuilder();
            FrustaResult abi = Native.frusta_check_abi(FrustaConstants.AbiVersion);
            if (abi != FrustaResult.Ok)
                problems.Append(Utf8.Decode(Native.frusta_last_error())).Append("; ");
            try
            {
                foreach (Mirror m in Mirrors)
                {
                    int native = GetNativeStructSize(m.CName);
                    int marshal = Marshal.SizeOf(m.Type);
                    if (native != m.Sizeof || marshal != m.Sizeof)
                        problems.Append($"{m.CName} is {native} bytes in the library, {m.Sizeof} in C# {m.Type.Name} " +
                                        $"(Marshal.SizeOf {marshal}); ");
                }
            }
            catch (EntryPointNotFoundException e)
            {
                problems.Append($"the library has no frusta_struct_size, so it predates ABI {FrustaConstants.AbiVersion} ({e.Message}); ");
            }
            if (problems.Length > 0)
                throw new FrustaException(FrustaResult.AbiMismatch,
                    "the native library does not match the C# binding (ABI " + FrustaConstants.AbiVersion +
                    "): " + problems.ToString().TrimEnd(' ', ';') +
                    ". Rebuild the native library from the same commit as the package.",
                    "FrustaLibrary.EnsureCompatible");
        }
    }
}
