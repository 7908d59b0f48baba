// SPDX-License-Identifier: MIT
// Ownership of native objects. Frusta hands out ids (8-byte values), not pointers, so
// SafeHandle's IntPtr only marks "owned" (1) or "released" (0) and the id lives beside it.
// Why SafeHandle rather than a plain IDisposable with a finalizer: its reference count
// (DangerousAddRef/Release around every native call) keeps Dispose on one thread from
// destroying a world while another thread is inside frusta_world_read or
// frusta_world_set_haptic with its id; the destroy then runs when the last call
// returns. Its critical finalizer also runs on an AppDomain unload (Unity's domain
// reload), after ordinary finalizers, and Dispose is idempotent.
using System;
using System.Runtime.InteropServices;

namespace Frusta.Binding
{
    internal sealed class WorldHandle : SafeHandle
    {
        internal FrustaWorldId Id;
        internal WorldHandle() : base(IntPtr.Zero, true) { }
        public override bool IsInvalid => handle == IntPtr.Zero;
        internal void Own(FrustaWorldId id)
        {
            Id = id;
            SetHandle((IntPtr)1);
        }
        // stops the world's thread first (frusta_destroy_world does); a stale id is already gone
        protected override bool ReleaseHandle()
        {
            Native.frusta_destroy_world(Id);
            return true;
        }
    }

    internal sealed class TreeHandle : SafeHandle
    {
        internal FrustaTreeId Id;
        internal TreeHandle() : base(IntPtr.Zero, true) { }
        public override bool IsInvalid => handle == IntPtr.Zero;
        internal void Own(FrustaTreeId id)
        {
            Id = id;
            SetHandle((IntPtr)1);
        }
        // worlds that use the tree keep their own reference to it natively
        protected override bool ReleaseHandle()
        {
            Native.frusta_destroy_sphere_tree(Id);
            return true;
        }
    }

    internal sealed class HandHandle : SafeHandle
    {
        internal FrustaHandId Id;
        internal HandHandle() : base(IntPtr.Zero, true) { }
        public override bool IsInvalid => handle == IntPtr.Zero;
        internal void Own(FrustaHandId id)
        {
            Id = id;
            SetHandle((IntPtr)1);
        }
        protected override bool ReleaseHandle()
        {
            Native.frusta_destroy_hand(Id);
            return true;
        }
    }

    internal sealed class DeviceHandle : SafeHandle
    {
        internal FrustaDeviceId Id;
        // the owning world's handle: a glove closes only while its world is alive
        internal WorldHandle World;
        internal DeviceHandle() : base(IntPtr.Zero, true) { }
        public override bool IsInvalid => handle == IntPtr.Zero;
        internal void Own(WorldHandle world, FrustaDeviceId id)
        {
            World = world;
            Id = id;
            SetHandle((IntPtr)1);
        }
        // zeroes the glove's output and joins its thread. A disposed world closed its gloves
        // itself (frusta_destroy_world does), so there is nothing left to close; holding the
        // world's count keeps another thread from destroying it during the close
        protected override bool ReleaseHandle()
        {
            bool added = false;
            try
            {
                World.DangerousAddRef(ref added);
            }
            catch (ObjectDisposedException)
            {
                return true;
            }
            try
            {
                Native.frusta_destroy_device(Id);
            }
            finally
            {
                if (added) World.DangerousRelease();
            }
            return true;
        }
    }

    /// <summary>Holds a handle's reference count for one native call (a struct: no garbage).</summary>
    internal struct HandleUse : IDisposable
    {
        readonly SafeHandle handle;
        bool added;

        /// <summary>Throws ObjectDisposedException once the owner was disposed.</summary>
        internal HandleUse(SafeHandle handle)
        {
            this.handle = handle;
            added = false;
            handle.DangerousAddRef(ref added);
        }

        public void Dispose()
        {
            if (!added) return;
            added = false;
            handle.DangerousRelease();
        }
    }

    /// <summary>Holds a glove's and its world's reference counts for one native call (a struct: no
    /// garbage). The world's count keeps another thread from destroying the world, and with it the
    /// glove, during the call.</summary>
    internal struct DeviceUse : IDisposable
    {
        readonly DeviceHandle device;
        bool deviceAdded, worldAdded;

        /// <summary>Throws ObjectDisposedException once the Device was disposed.</summary>
        internal DeviceUse(DeviceHandle device)
        {
            this.device = device;
            deviceAdded = false;
            worldAdded = false;
            device.DangerousAddRef(ref deviceAdded);
            try
            {
                device.World.DangerousAddRef(ref worldAdded);
            }
            catch (ObjectDisposedException)
            {
                // the world was disposed: it closed its gloves, the id is stale
            }
        }

        /// <summary>false once the glove's world was disposed: do not call native then.</summary>
        internal bool WorldAlive => worldAdded;

        public void Dispose()
        {
            if (worldAdded)
            {
                worldAdded = false;
                device.World.DangerousRelease();
            }
            if (deviceAdded)
            {
                deviceAdded = false;
                device.DangerousRelease();
            }
        }
    }
}
