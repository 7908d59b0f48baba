// SPDX-License-Identifier: MIT
// The header's enums as int-backed C# enums (32-bit, as the ABI test freezes them) and
// its counts as constants.
using System;

namespace Frusta.Binding
{
    /// <summary>What a native call returned (<c>frusta_result</c>). Every failure also leaves
    /// a message naming the field and value at fault; <see cref="FrustaException"/> carries both.</summary>
    public enum FrustaResult
    {
        /// <summary>Success.</summary>
        Ok = 0,
        /// <summary>A required pointer argument was null (a binding bug if it reaches C#).</summary>
        NullPointer = 1,
        /// <summary>struct_size differs from the library's sizeof: a struct mirror has drifted.</summary>
        StructSize = 2,
        /// <summary>A def not obtained from the native defaults (its hidden cookie is missing).</summary>
        DefNotDefaulted = 3,
        /// <summary>A null id where an object is required.</summary>
        NullId = 4,
        /// <summary>The id's object was destroyed (or never existed).</summary>
        StaleId = 5,
        /// <summary>NaN or infinity in an input.</summary>
        NotFinite = 6,
        /// <summary>A finite value outside its documented range.</summary>
        OutOfRange = 7,
        /// <summary>A caller buffer or an internal pool is too small.</summary>
        Capacity = 8,
        /// <summary>The binding and the library were built for different ABIs.</summary>
        AbiMismatch = 9,
        /// <summary>The library ran out of memory.</summary>
        OutOfMemory = 10,
        /// <summary>A bug in the library: please report the message.</summary>
        Internal = 11,
        /// <summary>A file could not be opened, read or written.</summary>
        Io = 12,
        /// <summary>Not a Frusta file, or a format version this library cannot read.</summary>
        FileFormat = 13,
        /// <summary>A Frusta file whose contents fail validation.</summary>
        CorruptFile = 14,
        /// <summary>Not now: e.g. stepping a world that its own thread runs.</summary>
        WrongState = 15,
        /// <summary>A part this build of the library lacks: baking where the baker library
        /// (Embree) is not installed beside it. Bake with frusta-bake and load the file.</summary>
        Unavailable = 16,
    }

    /// <summary>Which hand (<c>frusta_hand_side</c>). A left hand is the mirror image of a
    /// right hand through its hand frame's x-z plane.</summary>
    public enum FrustaHandSide
    {
        /// <summary>A right hand (the default).</summary>
        Right = 0,
        /// <summary>A left hand.</summary>
        Left = 1,
    }

    /// <summary>A finger (<c>frusta_finger</c>), thumb first; indexes every per-finger array.</summary>
    public enum FrustaFinger
    {
        /// <summary>The thumb: its first segment is the metacarpal.</summary>
        Thumb = 0,
        /// <summary>The index finger.</summary>
        Index = 1,
        /// <summary>The middle finger.</summary>
        Middle = 2,
        /// <summary>The ring finger.</summary>
        Ring = 3,
        /// <summary>The little finger.</summary>
        Little = 4,
    }

    /// <summary>Which part of a segment solid is nearest to a sphere (<c>frusta_feature</c>).</summary>
    public enum FrustaFeature
    {
        /// <summary>The frustum's lateral surface (or an end cap face).</summary>
        Side = 0,
        /// <summary>The ball at the distal end E (the fingertip on a finger's last segment).</summary>
        Distal = 1,
        /// <summary>The ball at the proximal end D (a joint ball).</summary>
        Proximal = 2,
    }

    /// <summary>Constraint forms (<c>frusta_constraint_form</c>); both are zero when touching.</summary>
    public enum FrustaConstraintForm
    {
        /// <summary>Squared form, metres squared.</summary>
        Squared = 0,
        /// <summary>Signed gap along the surface normal, metres.</summary>
        Distance = 1,
    }

    /// <summary>What a glove's outputs are (<c>frusta_device_output</c>): bits of
    /// <see cref="FrustaDeviceStatus.Outputs"/>, which a glove announces.</summary>
    [Flags]
    public enum FrustaDeviceOutput
    {
        /// <summary>No outputs (a glove that only senses).</summary>
        None = 0,
        /// <summary>A brake per finger.</summary>
        FingerResistance = 1,
        /// <summary>A force vector per fingertip, palm frame.</summary>
        FingertipForce = 2,
        /// <summary>A torque per finger joint.</summary>
        JointTorque = 4,
    }

    /// <summary>Whether a glove is connected (<c>frusta_device_state</c>).</summary>
    public enum FrustaDeviceState
    {
        /// <summary>The glove is open and its stream is up.</summary>
        Connected = 1,
        /// <summary>The stream went away; the library reopens it every
        /// <see cref="FrustaDeviceDef.ReconnectIntervalS"/> (a replay that ended stays here).</summary>
        Disconnected = 2,
        /// <summary>The glove was closed.</summary>
        Closed = 3,
    }

    /// <summary>Why a glove's output is held at zero now (<c>frusta_watchdog_reason</c>).</summary>
    public enum FrustaWatchdogReason
    {
        /// <summary>Not held: the glove renders the world's outputs.</summary>
        None = 0,
        /// <summary>No valid sample for <see cref="FrustaDeviceDef.WatchdogS"/> (or none yet).</summary>
        InputStalled = 1,
        /// <summary>The glove is disconnected.</summary>
        Disconnected = 2,
        /// <summary>The world has not stepped for <see cref="FrustaDeviceDef.EngineTimeoutS"/>.</summary>
        EngineStalled = 3,
        /// <summary>The host has not read the world (<see cref="World.Read"/>) for
        /// <see cref="FrustaDeviceDef.HostTimeoutS"/>.</summary>
        HostStalled = 4,
    }

    /// <summary>What kind of device <see cref="Device.Enumerate()"/> found (<c>frusta_device_kind</c>).</summary>
    public enum FrustaDeviceKind
    {
        /// <summary>A serial port: open it as <c>opengloves:PATH</c> or <c>serial:PATH</c>.</summary>
        Serial = 1,
        /// <summary>A vendor-defined HID device: <c>hid:VID:PID</c>.</summary>
        Hid = 2,
        /// <summary>Any USB device (for its ids; not opened directly).</summary>
        Usb = 3,
    }

    /// <summary>The header's counts (<c>FRUSTA_*_COUNT</c> and friends).</summary>
    public static class FrustaConstants
    {
        /// <summary>The ABI this binding mirrors (<c>FRUSTA_ABI_VERSION</c>).</summary>
        public const int AbiVersion = 2;
        /// <summary>The library version this binding was written for (<c>FRUSTA_VERSION</c>,
        /// major*1000000 + minor*1000 + patch).</summary>
        public const int Version = 3000;
        /// <summary>Fingers per hand (5).</summary>
        public const int FingerCount = 5;
        /// <summary>Segments per finger (3).</summary>
        public const int SegmentsPerFinger = 3;
        /// <summary>Joint angles per finger (4): abduction, then flexion of the first, second, third joint.</summary>
        public const int JointsPerFinger = 4;
        /// <summary>Segments per hand (15), finger-major.</summary>
        public const int HandSegmentCount = FingerCount * SegmentsPerFinger;
        /// <summary>Joint angles per hand (20), finger-major.</summary>
        public const int HandJointCount = FingerCount * JointsPerFinger;
        /// <summary>The largest |joint angle| any input may carry, radians (4 pi, <c>FRUSTA_MAX_JOINT_ANGLE</c>):
        /// beyond it a reading is refused as corrupt; within it, angles beyond the hand's limits are clamped.</summary>
        public const double MaxJointAngle = 12.566370614359172;
        /// <summary>Palm degrees of freedom in a Jacobian (6): translation x y z, then rotation x y z.</summary>
        public const int PalmDof = 6;
        /// <summary>The body index of the palm in <see cref="FrustaWorldContact.Body"/> (15).</summary>
        public const int PalmBody = HandSegmentCount;
        /// <summary>Doubles in one point Jacobian: 3 rows x (4 joints + 6 palm DOF) = 30.</summary>
        public const int PointJacobianLength = 3 * (JointsPerFinger + PalmDof);
        /// <summary>Flexion joints per finger a glove calibration maps (3): first, second, third.</summary>
        public const int FlexionJointsPerFinger = 3;
        /// <summary>Bytes of <see cref="FrustaDeviceInfo.Uri"/> in UTF-8, its NUL included (256).</summary>
        public const int DeviceUriCapacity = 256;
    }
}
