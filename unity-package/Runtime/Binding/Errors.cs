// SPDX-License-Identifier: MIT
using System.Runtime.CompilerServices;

namespace Frusta.Binding
{
    /// <summary>Native results to exceptions, with the calling thread's native message.</summary>
    internal static unsafe class Errors
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static void Check(FrustaResult result, string call)
        {
            if (result != FrustaResult.Ok) Throw(result, call);
        }

        // kept out of line: the happy path stays small and allocation-free
        [MethodImpl(MethodImplOptions.NoInlining)]
        internal static void Throw(FrustaResult result, string call) =>
            throw new FrustaException(result, Utf8.Decode(Native.frusta_last_error()), call);
    }
}
