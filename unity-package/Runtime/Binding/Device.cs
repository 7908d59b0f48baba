// SPDX-License-Identifier: MIT
using System;

namespace Frusta.Binding
{
    /// <summary>
    /// A force-feedback glove driving one hand of a <see cref="World"/>, from
    /// <see cref="World.CreateDevice(string, in FrustaDeviceDef)"/>. The glove runs on a native thread
    /// of its own: it feeds the glove's samples to the hand and sends the glove the world's outputs,
    /// cut to its limits and held at zero whenever a watchdog trips (no sample, no step, no
    /// <see cref="World.Read"/>, or a disconnect). No C# runs on that thread and no delegate is
    /// handed to native code: the host calls <see cref="Poll"/> once per frame, which reads the
    /// status and raises <see cref="StateChanged"/> and <see cref="WatchdogChanged"/> on the
    /// calling thread.
    /// <para>Threads: <see cref="Poll"/>, <see cref="GetStatus"/>, <see cref="Status"/> and
    /// <see cref="Dispose"/> on the host (the world's thread, Unity's main thread);
    /// <see cref="SetPalmPose"/> from any one thread per glove; <see cref="IsValid"/>,
    /// <see cref="Id"/>, <see cref="Uri"/>, <see cref="Hand"/> and <see cref="Enumerate()"/> from
    /// any thread. Disposing the world closes its gloves natively; the Device then reports
    /// <see cref="IsValid"/> false, <see cref="Poll"/> raises a change to
    /// <see cref="FrustaDeviceState.Closed"/> once, and its other calls throw
    /// <see cref="FrustaException"/> with <see cref="FrustaResult.StaleId"/>.</para>
    /// </summary>
    public sealed unsafe class Device : IDisposable
    {
        readonly DeviceHandle handle;
        // frusta_device_get_status has one reader: concurrent callers take turns
        readonly object statusGate = new object();
        FrustaDeviceStatus polled;
        FrustaDeviceState state = FrustaDeviceState.Connected;
        FrustaWatchdogReason watchdog = FrustaWatchdogReason.None;

        internal Device(World world, DeviceHandle handle, string uri, FrustaHandId hand)
        {
            World = world;
            this.handle = handle;
            Uri = uri;
            Hand = hand;
        }

        /// <summary>The native id (a value; stale once disposed or once the world is disposed).</summary>
        public FrustaDeviceId Id => handle.Id;

        /// <summary>The URI the glove was opened with.</summary>
        public string Uri { get; }

        /// <summary>The world's hand the glove drives (the def's <see cref="FrustaDeviceDef.Hand"/>).</summary>
        public FrustaHandId Hand { get; }

        /// <summary>The world the glove drives a hand of.</summary>
        public World World { get; }

        /// <summary>false once disposed, or once its world was disposed (<c>frusta_device_is_valid</c>).
        /// Thread: any.</summary>
        public bool IsValid => !handle.IsClosed && !handle.World.IsClosed && Native.frusta_device_is_valid(handle.Id) == 1;

        /// <summary>The state as of the last <see cref="Poll"/>: <see cref="FrustaDeviceState.Connected"/>
        /// at open (a glove absent at open is an error, not a retry).</summary>
        public FrustaDeviceState State => state;

        /// <summary>The watchdog reason as of the last <see cref="Poll"/>: <see cref="FrustaWatchdogReason.None"/>
        /// at open.</summary>
        public FrustaWatchdogReason Watchdog => watchdog;

        /// <summary>The status the last <see cref="Poll"/> read (all zero before the first). A reference
        /// into this object, valid until the next Poll; nothing is copied.</summary>
        public ref readonly FrustaDeviceStatus PolledStatus => ref polled;

        /// <summary>
        /// Raised by <see cref="Poll"/>, on its thread, when the glove's state differs from the previous
        /// Poll's (or from <see cref="FrustaDeviceState.Connected"/> for the first): a disconnect, a
        /// reconnect, or <see cref="FrustaDeviceState.Closed"/> once when its world was disposed. Changes
        /// that come and go between two polls are not seen here; <see cref="FrustaDeviceStatus.Disconnects"/>
        /// and <see cref="FrustaDeviceStatus.Reconnects"/> count every one. Disposing the Device raises nothing.
        /// </summary>
        public event EventHandler<DeviceStateChangedEventArgs> StateChanged;

        /// <summary>
        /// Raised by <see cref="Poll"/>, on its thread, after <see cref="StateChanged"/>, when the reason the
        /// output is held at zero differs from the previous Poll's (or from <see cref="FrustaWatchdogReason.None"/>
        /// for the first). <see cref="FrustaDeviceStatus.WatchdogTrips"/> counts every trip, seen or not.
        /// </summary>
        public event EventHandler<DeviceWatchdogChangedEventArgs> WatchdogChanged;

        /// <summary>
        /// Read the newest status (<c>frusta_device_get_status</c>, lock-free on the native side) into
        /// <paramref name="status"/>. Allocation-free: reuse one status. Thread: host.
        /// </summary>
        /// <param name="status">Filled; its previous contents do not matter.</param>
        /// <exception cref="FrustaException"><see cref="FrustaResult.StaleId"/> once the world was disposed.</exception>
        /// <exception cref="ObjectDisposedException">After <see cref="Dispose"/>.</exception>
        public void GetStatus(ref FrustaDeviceStatus status)
        {
            FrustaResult r = ReadStatus(ref status, out bool worldGone);
            if (worldGone) ThrowWorldGone("frusta_device_get_status");
            Errors.Check(r, "frusta_device_get_status");
        }

        /// <summary>The newest status (see <see cref="GetStatus"/>): a 320-byte copy, no garbage. Thread: host.</summary>
        public FrustaDeviceStatus Status
        {
            get
            {
                FrustaDeviceStatus status = default;
                GetStatus(ref status);
                return status;
            }
        }

        /// <summary>
        /// The palm pose for a glove without a tracker (<c>frusta_device_set_palm_pose</c>): the glove's
        /// next samples carry it to the hand. Ignored while the glove reports its own
        /// (<see cref="FrustaDeviceStatus.HasPalmPose"/>). Lock-free and allocation-free.
        /// Thread: any one thread per glove.
        /// </summary>
        /// <param name="palm">Metres, Frusta's right-handed world frame (convert Unity poses with
        /// <see cref="CoordinateConversion.PoseFromUnity"/>); quaternion norm in [0.5, 2].</param>
        /// <exception cref="FrustaException"><see cref="FrustaResult.NotFinite"/> or
        /// <see cref="FrustaResult.OutOfRange"/> for a bad pose; <see cref="FrustaResult.StaleId"/> once the
        /// world was disposed.</exception>
        /// <exception cref="ObjectDisposedException">After <see cref="Dispose"/>.</exception>
        public void SetPalmPose(in FrustaPose palm)
        {
            using (var use = new DeviceUse(handle))
            {
                if (!use.WorldAlive) ThrowWorldGone("frusta_device_set_palm_pose");
                fixed (FrustaPose* p = &palm)
                    Errors.Check(Native.frusta_device_set_palm_pose(handle.Id, p), "frusta_device_set_palm_pose");
            }
        }

        /// <summary>
        /// Read the status and raise <see cref="StateChanged"/>, then <see cref="WatchdogChanged"/>, for
        /// what changed since the previous Poll. Call it once per frame on the host; it allocates only
        /// when it raises an event. Handlers run synchronously on this thread; an exception from one
        /// propagates out of Poll (the status is taken all the same).
        /// </summary>
        /// <returns>true while the glove is open; false once the Device was disposed or its world was
        /// disposed (then <see cref="StateChanged"/> reports <see cref="FrustaDeviceState.Closed"/> once).</returns>
        public bool Poll()
        {
            if (state == FrustaDeviceState.Closed || handle.IsClosed) return false;
            FrustaResult r = ReadStatus(ref polled, out bool worldGone);
            if (worldGone || r == FrustaResult.StaleId)
            {
                // the world closed its gloves
                polled.MarkClosed();
                FrustaDeviceState old = state;
                state = FrustaDeviceState.Closed;
                StateChanged?.Invoke(this, new DeviceStateChangedEventArgs(old, state, polled));
                return false;
            }
            Errors.Check(r, "frusta_device_get_status");

            FrustaDeviceState oldState = state;
            FrustaWatchdogReason oldWatchdog = watchdog;
            state = polled.State;
            watchdog = polled.Watchdog;
            if (state != oldState) StateChanged?.Invoke(this, new DeviceStateChangedEventArgs(oldState, state, polled));
            if (watchdog != oldWatchdog)
                WatchdogChanged?.Invoke(this, new DeviceWatchdogChangedEventArgs(oldWatchdog, watchdog, polled));
            return true;
        }

        /// <summary>
        /// Every serial port, HID device and USB device present now (<c>frusta_enumerate_devices</c>).
        /// Slow (it reads /dev, hidapi and the system's USB device list) and allocates: not for a frame loop. Thread: any.
        /// </summary>
        /// <returns>The devices found; empty when none.</returns>
        public static FrustaDeviceInfo[] Enumerate()
        {
            int count = Enumerate(Span<FrustaDeviceInfo>.Empty);
            while (true)
            {
                var found = new FrustaDeviceInfo[count];
                int total = Enumerate(found);
                // a device plugged in between the two calls: ask again with room for it
                if (total > found.Length)
                {
                    count = total;
                    continue;
                }
                if (total < found.Length) Array.Resize(ref found, total);
                return found;
            }
        }

        /// <summary>
        /// Fill <paramref name="destination"/> with the devices present now, without allocating (see
        /// <see cref="Enumerate()"/>). Pass an empty span to learn the count. Thread: any.
        /// </summary>
        /// <param name="destination">Receives at most its length of devices.</param>
        /// <returns>How many devices there are, which may exceed destination's length.</returns>
        public static int Enumerate(Span<FrustaDeviceInfo> destination)
        {
            FrustaLibrary.EnsureCompatible();
            int count;
            fixed (FrustaDeviceInfo* p = destination)
                Errors.Check(Native.frusta_enumerate_devices(p, destination.Length, &count), "frusta_enumerate_devices");
            return count;
        }

        /// <summary>Send the glove a zero command, stop its thread and close it (<c>frusta_destroy_device</c>);
        /// the hand takes <see cref="World.SetHaptic(FrustaHandId, in FrustaPose, ReadOnlySpan{double})"/> again. Raises no event. Safe to call twice, and
        /// after the world was disposed (which closed the glove already). Thread: host.</summary>
        public void Dispose() => handle.Dispose();

        // worldGone: the world was disposed (it closed the glove), so native was not called
        FrustaResult ReadStatus(ref FrustaDeviceStatus status, out bool worldGone)
        {
            status.struct_size = sizeof(FrustaDeviceStatus);
            using (var use = new DeviceUse(handle))
            {
                worldGone = !use.WorldAlive;
                if (worldGone) return FrustaResult.StaleId;
                lock (statusGate)
                fixed (FrustaDeviceStatus* s = &status)
                    return Native.frusta_device_get_status(handle.Id, s);
            }
        }

        // the native side would say the same of the stale id, were it asked
        void ThrowWorldGone(string call) =>
            throw new FrustaException(FrustaResult.StaleId,
                $"device id {handle.Id} names no open glove: its world was disposed, which closed it", call);
    }

    /// <summary>What <see cref="Device"/>'s events share: a value as of the previous
    /// <see cref="Device.Poll"/>, the value now, and the status that showed the change.</summary>
    /// <typeparam name="T">The value that changed.</typeparam>
    public abstract class DeviceChangeEventArgs<T> : EventArgs
    {
        readonly FrustaDeviceStatus status;

        private protected DeviceChangeEventArgs(T before, T now, in FrustaDeviceStatus status)
        {
            Before = before;
            Now = now;
            this.status = status;
        }

        private protected T Before { get; }

        private protected T Now { get; }

        /// <summary>The status that showed the change (its counters and rates at that poll).</summary>
        public ref readonly FrustaDeviceStatus Status => ref status;
    }

    /// <summary>What <see cref="Device.StateChanged"/> reports.</summary>
    public sealed class DeviceStateChangedEventArgs : DeviceChangeEventArgs<FrustaDeviceState>
    {
        /// <summary>A change of a glove's state.</summary>
        /// <param name="oldState">The state before.</param>
        /// <param name="newState">The state now.</param>
        /// <param name="status">The status that showed the change.</param>
        public DeviceStateChangedEventArgs(FrustaDeviceState oldState, FrustaDeviceState newState, in FrustaDeviceStatus status)
            : base(oldState, newState, status) { }

        /// <summary>The state as of the previous <see cref="Device.Poll"/>.</summary>
        public FrustaDeviceState OldState => Before;

        /// <summary>The state now.</summary>
        public FrustaDeviceState NewState => Now;
    }

    /// <summary>What <see cref="Device.WatchdogChanged"/> reports.</summary>
    public sealed class DeviceWatchdogChangedEventArgs : DeviceChangeEventArgs<FrustaWatchdogReason>
    {
        /// <summary>A change of the reason a glove's output is held at zero.</summary>
        /// <param name="oldReason">The reason before.</param>
        /// <param name="newReason">The reason now (<see cref="FrustaWatchdogReason.None"/>: released).</param>
        /// <param name="status">The status that showed the change.</param>
        public DeviceWatchdogChangedEventArgs(FrustaWatchdogReason oldReason, FrustaWatchdogReason newReason, in FrustaDeviceStatus status)
            : base(oldReason, newReason, status) { }

        /// <summary>The reason as of the previous <see cref="Device.Poll"/>.</summary>
        public FrustaWatchdogReason OldReason => Before;

        /// <summary>The reason now; <see cref="FrustaWatchdogReason.None"/> when the output is released.</summary>
        public FrustaWatchdogReason NewReason => Now;
    }
}
