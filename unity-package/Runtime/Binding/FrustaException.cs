// SPDX-License-Identifier: MIT
using System;

namespace Frusta.Binding
{
    /// <summary>
    /// A native call failed. <see cref="Result"/> is the code the library returned and
    /// <see cref="NativeMessage"/> the message it left in <c>frusta_last_error()</c> on the
    /// calling thread, naming the field and value at fault. Nothing the failed call would
    /// have changed has changed (the library's guarantee). Thrown on the thread that made the call.
    /// </summary>
    public sealed class FrustaException : Exception
    {
        /// <summary>A failure with its code, the native message and the call that failed.</summary>
        /// <param name="result">The native result code (never <see cref="FrustaResult.Ok"/>).</param>
        /// <param name="nativeMessage">The library's message (may be empty).</param>
        /// <param name="call">The native function or managed operation that failed.</param>
        public FrustaException(FrustaResult result, string nativeMessage, string call)
            : base(Compose(result, nativeMessage, call))
        {
            Result = result;
            NativeMessage = nativeMessage ?? string.Empty;
            Call = call ?? string.Empty;
        }

        /// <summary>The code the library returned.</summary>
        public FrustaResult Result { get; }

        /// <summary>The library's own message from <c>frusta_last_error()</c>, e.g.
        /// "rate_hz is 0.5, must be 1..100000".</summary>
        public string NativeMessage { get; }

        /// <summary>The native function that failed, e.g. "frusta_create_world".</summary>
        public string Call { get; }

        static string Compose(FrustaResult result, string message, string call) =>
            string.IsNullOrEmpty(message)
                ? $"{call} failed: {ResultName(result)}"
                : $"{call} failed: {ResultName(result)}: {message}";

        static string ResultName(FrustaResult result) =>
            Enum.IsDefined(typeof(FrustaResult), result) ? "FRUSTA_" + NameOf(result) : $"result {(int)result}";

        static string NameOf(FrustaResult result)
        {
            // the header's spelling: FRUSTA_ERROR_STALE_ID for StaleId
            if (result == FrustaResult.Ok) return "OK";
            var name = result.ToString();
            var text = new System.Text.StringBuilder("ERROR");
            foreach (char c in name)
            {
                if (char.IsUpper(c)) text.Append('_');
                text.Append(char.ToUpperInvariant(c));
            }
            return text.ToString();
        }
    }
}
