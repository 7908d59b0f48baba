// SPDX-License-Identifier: MIT
// Handles: small values, passed by value; default (all zero) is null.
using System;
using System.Runtime.InteropServices;

namespace Frusta.Binding
{
    /// <summary>
    /// A standalone hand (<see cref="Hand"/>) handle, the mirror of <c>frusta_hand_id</c> (8 bytes). Opaque; a value, not a pointer:
    /// copies name the same thing. <c>default</c> is null. A handle whose object was
    /// destroyed is stale: the native side refuses it, and the binding throws
    /// <see cref="FrustaException"/> with <see cref="FrustaResult.StaleId"/>.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct FrustaHandId : IEquatable<FrustaHandId>
    {
        /// <summary>Slot + 1; 0 is null.</summary>
        public int Index1;
        /// <summary>Owning world slot; 0 for a standalone hand.</summary>
        public ushort World0;
        /// <summary>Bumped when the slot is reused.</summary>
        public ushort Generation;

        /// <summary>The null handle (all zero).</summary>
        public static FrustaHandId Null => default;

        /// <summary>true for the null handle (<see cref="Index1"/> is 0).</summary>
        public bool IsNull => Index1 == 0;

        /// <summary>Field-wise equality.</summary>
        /// <param name="other">The handle to compare with.</param>
        /// <returns>true when both name the same slot, world and generation.</returns>
        public bool Equals(FrustaHandId other) =>
            Index1 == other.Index1 && World0 == other.World0 && Generation == other.Generation;

        /// <summary>Field-wise equality with a boxed handle.</summary>
        /// <param name="obj">The object to compare with.</param>
        /// <returns>true when obj is an equal handle.</returns>
        public override bool Equals(object obj) => obj is FrustaHandId o && Equals(o);

        /// <summary>A hash of the three fields.</summary>
        /// <returns>The hash code.</returns>
        public override int GetHashCode() => Index1 * 31 + (World0 << 16 | Generation);

        /// <summary>Field-wise equality.</summary>
        /// <param name="a">The first handle.</param>
        /// <param name="b">The second handle.</param>
        /// <returns>true when equal.</returns>
        public static bool operator ==(FrustaHandId a, FrustaHandId b) => a.Equals(b);

        /// <summary>Field-wise inequality.</summary>
        /// <param name="a">The first handle.</param>
        /// <param name="b">The second handle.</param>
        /// <returns>true when different.</returns>
        public static bool operator !=(FrustaHandId a, FrustaHandId b) => !a.Equals(b);

        /// <summary>"{index1, world0, generation}".</summary>
        /// <returns>The text.</returns>
        public override string ToString() => $"{{{Index1}, {World0}, {Generation}}}";
    }

    /// <summary>
    /// A sphere tree (<see cref="SphereTree"/>) handle, the mirror of <c>frusta_tree_id</c> (8 bytes). Opaque; a value, not a pointer:
    /// copies name the same thing. <c>default</c> is null. A handle whose object was
    /// destroyed is stale: the native side refuses it, and the binding throws
    /// <see cref="FrustaException"/> with <see cref="FrustaResult.StaleId"/>.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct FrustaTreeId : IEquatable<FrustaTreeId>
    {
        /// <summary>Slot + 1; 0 is null.</summary>
        public int Index1;
        /// <summary>Always 0: trees are standalone.</summary>
        public ushort World0;
        /// <summary>Bumped when the slot is reused.</summary>
        public ushort Generation;

        /// <summary>The null handle (all zero).</summary>
        public static FrustaTreeId Null => default;

        /// <summary>true for the null handle (<see cref="Index1"/> is 0).</summary>
        public bool IsNull => Index1 == 0;

        /// <summary>Field-wise equality.</summary>
        /// <param name="other">The handle to compare with.</param>
        /// <returns>true when both name the same slot, world and generation.</returns>
        public bool Equals(FrustaTreeId other) =>
            Index1 == other.Index1 && World0 == other.World0 && Generation == other.Generation;

        /// <summary>Field-wise equality with a boxed handle.</summary>
        /// <param name="obj">The object to compare with.</param>
        /// <returns>true when obj is an equal handle.</returns>
        public override bool Equals(object obj) => obj is FrustaTreeId o && Equals(o);

        /// <summary>A hash of the three fields.</summary>
        /// <returns>The hash code.</returns>
        public override int GetHashCode() => Index1 * 31 + (World0 << 16 | Generation);

        /// <summary>Field-wise equality.</summary>
        /// <param name="a">The first handle.</param>
        /// <param name="b">The second handle.</param>
        /// <returns>true when equal.</returns>
        public static bool operator ==(FrustaTreeId a, FrustaTreeId b) => a.Equals(b);

        /// <summary>Field-wise inequality.</summary>
        /// <param name="a">The first handle.</param>
        /// <param name="b">The second handle.</param>
        /// <returns>true when different.</returns>
        public static bool operator !=(FrustaTreeId a, FrustaTreeId b) => !a.Equals(b);

        /// <summary>"{index1, world0, generation}".</summary>
        /// <returns>The text.</returns>
        public override string ToString() => $"{{{Index1}, {World0}, {Generation}}}";
    }

    /// <summary>
    /// A world (<see cref="World"/>) handle, the mirror of <c>frusta_world_id</c> (8 bytes). Opaque; a value, not a pointer:
    /// copies name the same thing. <c>default</c> is null. A handle whose object was
    /// destroyed is stale: the native side refuses it, and the binding throws
    /// <see cref="FrustaException"/> with <see cref="FrustaResult.StaleId"/>.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct FrustaWorldId : IEquatable<FrustaWorldId>
    {
        /// <summary>Slot + 1; 0 is null.</summary>
        public int Index1;
        /// <summary>Always 0.</summary>
        public ushort World0;
        /// <summary>Bumped when the slot is reused.</summary>
        public ushort Generation;

        /// <summary>The null handle (all zero).</summary>
        public static FrustaWorldId Null => default;

        /// <summary>true for the null handle (<see cref="Index1"/> is 0).</summary>
        public bool IsNull => Index1 == 0;

        /// <summary>Field-wise equality.</summary>
        /// <param name="other">The handle to compare with.</param>
        /// <returns>true when both name the same slot, world and generation.</returns>
        public bool Equals(FrustaWorldId other) =>
            Index1 == other.Index1 && World0 == other.World0 && Generation == other.Generation;

        /// <summary>Field-wise equality with a boxed handle.</summary>
        /// <param name="obj">The object to compare with.</param>
        /// <returns>true when obj is an equal handle.</returns>
        public override bool Equals(object obj) => obj is FrustaWorldId o && Equals(o);

        /// <summary>A hash of the three fields.</summary>
        /// <returns>The hash code.</returns>
        public override int GetHashCode() => Index1 * 31 + (World0 << 16 | Generation);

        /// <summary>Field-wise equality.</summary>
        /// <param name="a">The first handle.</param>
        /// <param name="b">The second handle.</param>
        /// <returns>true when equal.</returns>
        public static bool operator ==(FrustaWorldId a, FrustaWorldId b) => a.Equals(b);

        /// <summary>Field-wise inequality.</summary>
        /// <param name="a">The first handle.</param>
        /// <param name="b">The second handle.</param>
        /// <returns>true when different.</returns>
        public static bool operator !=(FrustaWorldId a, FrustaWorldId b) => !a.Equals(b);

        /// <summary>"{index1, world0, generation}".</summary>
        /// <returns>The text.</returns>
        public override string ToString() => $"{{{Index1}, {World0}, {Generation}}}";
    }

    /// <summary>
    /// An object within a world (<see cref="World.AddObject"/>) handle, the mirror of <c>frusta_object_id</c> (8 bytes). Opaque; a value, not a pointer:
    /// copies name the same thing. <c>default</c> is null. A handle whose object was
    /// destroyed is stale: the native side refuses it, and the binding throws
    /// <see cref="FrustaException"/> with <see cref="FrustaResult.StaleId"/>.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct FrustaObjectId : IEquatable<FrustaObjectId>
    {
        /// <summary>Slot + 1; 0 is null.</summary>
        public int Index1;
        /// <summary>The owning world: slot + 1 in the low byte, its generation's low byte above.</summary>
        public ushort World0;
        /// <summary>Bumped when the slot is reused.</summary>
        public ushort Generation;

        /// <summary>The null handle (all zero).</summary>
        public static FrustaObjectId Null => default;

        /// <summary>true for the null handle (<see cref="Index1"/> is 0).</summary>
        public bool IsNull => Index1 == 0;

        /// <summary>Field-wise equality.</summary>
        /// <param name="other">The handle to compare with.</param>
        /// <returns>true when both name the same slot, world and generation.</returns>
        public bool Equals(FrustaObjectId other) =>
            Index1 == other.Index1 && World0 == other.World0 && Generation == other.Generation;

        /// <summary>Field-wise equality with a boxed handle.</summary>
        /// <param name="obj">The object to compare with.</param>
        /// <returns>true when obj is an equal handle.</returns>
        public override bool Equals(object obj) => obj is FrustaObjectId o && Equals(o);

        /// <summary>A hash of the three fields.</summary>
        /// <returns>The hash code.</returns>
        public override int GetHashCode() => Index1 * 31 + (World0 << 16 | Generation);

        /// <summary>Field-wise equality.</summary>
        /// <param name="a">The first handle.</param>
        /// <param name="b">The second handle.</param>
        /// <returns>true when equal.</returns>
        public static bool operator ==(FrustaObjectId a, FrustaObjectId b) => a.Equals(b);

        /// <summary>Field-wise inequality.</summary>
        /// <param name="a">The first handle.</param>
        /// <param name="b">The second handle.</param>
        /// <returns>true when different.</returns>
        public static bool operator !=(FrustaObjectId a, FrustaObjectId b) => !a.Equals(b);

        /// <summary>"{index1, world0, generation}".</summary>
        /// <returns>The text.</returns>
        public override string ToString() => $"{{{Index1}, {World0}, {Generation}}}";
    }

    /// <summary>
    /// A force-feedback glove (<see cref="Device"/>) handle, the mirror of <c>frusta_device_id</c> (8 bytes). Opaque; a value, not a pointer:
    /// copies name the same thing. <c>default</c> is null. A handle whose glove was closed (or
    /// whose world was destroyed) is stale: the native side refuses it, and the binding throws
    /// <see cref="FrustaException"/> with <see cref="FrustaResult.StaleId"/>.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct FrustaDeviceId : IEquatable<FrustaDeviceId>
    {
        /// <summary>The hand it drives + 1; 0 is null.</summary>
        public int Index1;
        /// <summary>The owning world: slot + 1 in the low byte, its generation's low byte above.</summary>
        public ushort World0;
        /// <summary>Bumped at each open on that hand.</summary>
        public ushort Generation;

        /// <summary>The null handle (all zero).</summary>
        public static FrustaDeviceId Null => default;

        /// <summary>true for the null handle (<see cref="Index1"/> is 0).</summary>
        public bool IsNull => Index1 == 0;

        /// <summary>Field-wise equality.</summary>
        /// <param name="other">The handle to compare with.</param>
        /// <returns>true when both name the same hand, world and generation.</returns>
        public bool Equals(FrustaDeviceId other) =>
            Index1 == other.Index1 && World0 == other.World0 && Generation == other.Generation;

        /// <summary>Field-wise equality with a boxed handle.</summary>
        /// <param name="obj">The object to compare with.</param>
        /// <returns>true when obj is an equal handle.</returns>
        public override bool Equals(object obj) => obj is FrustaDeviceId o && Equals(o);

        /// <summary>A hash of the three fields.</summary>
        /// <returns>The hash code.</returns>
        public override int GetHashCode() => Index1 * 31 + (World0 << 16 | Generation);

        /// <summary>Field-wise equality.</summary>
        /// <param name="a">The first handle.</param>
        /// <param name="b">The second handle.</param>
        /// <returns>true when equal.</returns>
        public static bool operator ==(FrustaDeviceId a, FrustaDeviceId b) => a.Equals(b);

        /// <summary>Field-wise inequality.</summary>
        /// <param name="a">The first handle.</param>
        /// <param name="b">The second handle.</param>
        /// <returns>true when different.</returns>
        public static bool operator !=(FrustaDeviceId a, FrustaDeviceId b) => !a.Equals(b);

        /// <summary>"{index1, world0, generation}".</summary>
        /// <returns>The text.</returns>
        public override string ToString() => $"{{{Index1}, {World0}, {Generation}}}";
    }
}
