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
    /// <summary>A def-only creating call (<c>frusta_create_world</c>, <c>frusta_create_hand</c>).</summary>
    internal unsafe delegate FrustaResult CreateCall<TDef, TId>(TDef* def, TId* id)
        where TDef : unmanaged where TId : unmanaged;

    /// <summary>A call that copies one of an object's arrays under the C API's output-array rule
    /// (<c>frusta_hand_get_segments</c>, <c>frusta_sphere_tree_get_leaves</c>, ...).</summary>
    internal unsafe delegate FrustaResult ArrayCall<TId, T>(TId id, T* destination, int capacity, int* count)
        where TId : unmanaged where T : unmanaged;

    /// <summary>What the handles below share: the id they own once its creating call
    /// succeeded. They differ only in how they destroy it (<see cref="Destroy"/>).</summary>
    internal abstract class IdHandle<TId> : SafeHandle where TId : unmanaged
    {
        internal TId Id;
        protected IdHandle() : base(IntPtr.Zero, true) { }
        public override bool IsInvalid => handle == IntPtr.Zero;

        /// <summary>Destroy the object of <see cref="Id"/>; a stale id names nothing left to destroy.</summary>
        protected abstract void Destroy();

        // the id is released whatever the destroy said: a failure means it was already gone
        protected override bool ReleaseHandle()
        {
            Destroy();
            return true;
        }

        /// <summary>Own the id a creating call returned, or throw that call's error (the
        /// handle then owns nothing, so it releases nothing).</summary>
        internal void Own(FrustaResult created, TId id, string call)
        {
            Errors.Check(created, call);
            Id = id;
            SetHandle((IntPtr)1);
        }

        /// <summary>Create the object from a def and own it, as <see cref="Own"/>.</summary>
        internal unsafe void Create<TDef>(in TDef def, CreateCall<TDef, TId> create, string call)
            where TDef : unmanaged
        {
            TId id;
            FrustaResult r;
            fixed (TDef* d = &def) r = create(d, &id);
            Own(r, id, call);
        }

        /// <summary>Copy the first min(destination.Length, count) elements of one of the object's
        /// arrays, holding the handle for the call; returns the count. Allocation-free with a
        /// lambda that captures nothing (the compiler caches it).</summary>
        internal unsafe int CopyOut<T>(Span<T> destination, ArrayCall<TId, T> copy, string call)
            where T : unmanaged
        {
            int count;
            using (new HandleUse(this))
            fixed (T* p = destination)
                Errors.Check(copy(Id, p, destination.Length, &count), call);
            return count;
        }
    }

    internal sealed class WorldHandle : IdHandle<FrustaWorldId>
    {
        // stops the world's thread first (frusta_destroy_world does)
        protected override void Destroy() => Native.frusta_destroy_world(Id);
    }

    internal sealed class TreeHandle : IdHandle<FrustaTreeId>
    {
        // worlds that use the tree keep their own reference to it natively
        protected override void Destroy() => Native.frusta_destroy_sphere_tree(Id);
    }

    internal sealed class BakeJobHandle : IdHandle<FrustaBakeJobId>
    {
        // a job dropped unfinished: stopped, and its end (and any tree) thrown away
        protected override unsafe void Destroy()
        {
            Native.frusta_cancel_bake_job(Id);
            FrustaTreeId tree;
            if (Native.frusta_finish_bake_job(Id, &tree) == FrustaResult.Ok) Native.frusta_destroy_sphere_tree(tree);
        }
    }

    internal sealed class HandHandle : IdHandle<FrustaHandId>
    {
        protected override void Destroy() => Native.frusta_destroy_hand(Id);
    }

    internal sealed class FitterHandle : IdHandle<FrustaHandFitterId>
    {
        protected override void Destroy() => Native.frusta_destroy_hand_fitter(Id);
    }

    internal sealed class DeviceHandle : IdHandle<FrustaDeviceId>
    {
        // the owning world's handle: a glove closes only while its world is alive
        internal WorldHandle World;

        internal void Own(WorldHandle world, FrustaResult created, FrustaDeviceId id, string call)
        {
            World = world;
            Own(created, id, call);
        }

        // zeroes the glove's output and joins its thread. A disposed world closed its gloves
        // itself (frusta_destroy_world does), so there is nothing left to close; holding the
        // world's count keeps another thread from destroying it during the close
        protected override void Destroy()
        {
            bool added = false;
            try
            {
                World.DangerousAddRef(ref added);
            }
            catch (ObjectDisposedException)
            {
                return;
            }
            try
            {
                Native.frusta_destroy_device(Id);
            }
            finally
            {
                if (added) World.DangerousRelease();
            }
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
