// SPDX-License-Identifier: MIT
using System;
using System.Text;

namespace Frusta.Binding
{
    /// <summary>UTF-8 for C strings. Encoding writes into a caller buffer (stackalloc for
    /// short strings): no garbage for the calls that can happen often.</summary>
    internal static unsafe class Utf8
    {
        // strings up to this many bytes (NUL included) go through a stack buffer
        internal const int StackLimit = 512;

        /// <summary>Bytes needed for s with its NUL, at most.</summary>
        internal static int MaxBytes(string s) => Encoding.UTF8.GetMaxByteCount(s.Length) + 1;

        /// <summary>Write s and a NUL into destination (at least MaxBytes(s) long). A string with
        /// a NUL inside would be cut short by C, so it is refused.</summary>
        internal static void Encode(string s, Span<byte> destination, string parameter)
        {
            if (s.IndexOf('\0') >= 0) throw new ArgumentException("contains a NUL character", parameter);
            int n;
            fixed (char* chars = s)
            fixed (byte* bytes = destination)
                n = Encoding.UTF8.GetBytes(chars, s.Length, bytes, destination.Length - 1);
            destination[n] = 0;
        }

        /// <summary>A NUL-terminated UTF-8 C string as a string ("" for null).</summary>
        internal static string Decode(byte* p)
        {
            if (p == null) return string.Empty;
            int n = 0;
            while (p[n] != 0) ++n;
            return Encoding.UTF8.GetString(p, n);
        }
    }
}
