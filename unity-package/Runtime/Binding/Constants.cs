// SPDX-License-Identifier: MIT
// Counts the binding uses that frusta.h states only in words; the header's own constants
// are in Generated/Enums.g.cs.
namespace Frusta.Binding
{
    public static partial class FrustaConstants
    {
        /// <summary>The body index of the palm in <see cref="FrustaWorldContact.Body"/> (15).</summary>
        public const int PalmBody = HandSegmentCount;
        /// <summary>Flexion joints per finger a glove calibration maps (3): first, second, third.</summary>
        public const int FlexionJointsPerFinger = 3;
        /// <summary>Bytes of <see cref="FrustaDeviceInfo.Uri"/> in UTF-8, its NUL included (256).</summary>
        public const int DeviceUriCapacity = 256;
    }
}
