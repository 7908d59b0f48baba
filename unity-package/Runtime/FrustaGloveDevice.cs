// SPDX-License-Identifier: MIT
using System;
using Frusta.Binding;
using UnityEngine;
using UnityEngine.Events;

namespace Frusta.Unity
{
    /// <summary>
    /// A force-feedback glove driving a <see cref="FrustaHand"/>: opened by URI while enabled
    /// (<c>opengloves:/dev/ttyUSB0</c>, <c>serial:PATH</c>, <c>hid:VID:PID</c>,
    /// <c>replay:FILE?speed=1&amp;loop=1</c>, see <see cref="World.CreateDevice(string, in FrustaDeviceDef)"/>),
    /// closed when disabled or destroyed. The glove runs on a native thread of its own and feeds
    /// the hand directly; this component polls its status once per frame and raises
    /// <see cref="StateChanged"/> and <see cref="WatchdogChanged"/> on the main thread. For a glove
    /// without a tracker, the palm pose comes from <see cref="palmSource"/> each frame. The status
    /// and counters show in the inspector while playing.
    /// </summary>
    [AddComponentMenu("Frusta/Frusta Glove Device")]
    [DisallowMultipleComponent]
    public sealed class FrustaGloveDevice : MonoBehaviour
    {
        /// <summary>A change of the glove's state: (before, now).</summary>
        [Serializable]
        public sealed class StateEvent : UnityEvent<FrustaDeviceState, FrustaDeviceState> { }

        /// <summary>A change of the reason the glove's output is held at zero: (before, now).</summary>
        [Serializable]
        public sealed class WatchdogEvent : UnityEvent<FrustaWatchdogReason, FrustaWatchdogReason> { }

        [Tooltip("Where the glove is: opengloves:/dev/ttyUSB0, serial:/dev/ttyACM0, hid:1209:a7e1, " +
                 "replay:/path/glove.frrec?speed=1&loop=1. Relative paths start at the project folder (Editor) " +
                 "or the working directory (player).")]
        [SerializeField] string uri = "";
        [Tooltip("The hand the glove drives. Empty: the Frusta Hand on this GameObject.")]
        [SerializeField] FrustaHand hand;
        [Tooltip("The tracked wrist of a glove without a tracker: its pose goes with the glove's samples. " +
                 "Empty: the hand's haptic source. Ignored while the glove reports its own palm pose.")]
        [SerializeField] Transform palmSource;
        [Tooltip("Commands per second (Hz), 1..100000; below 1: the world's rate, never above what the glove takes.")]
        [SerializeField, Min(0f)] float outputRateHz;
        [Tooltip("Seconds without a valid sample before the output drops to zero.")]
        [SerializeField, Range(0.001f, 10f)] float watchdogSeconds = 0.05f;
        [Tooltip("Seconds without a frame reading the world before the output drops to zero; 0: not watched.")]
        [SerializeField, Range(0f, 60f)] float hostTimeoutSeconds = 0.25f;
        [Tooltip("Seconds between attempts to reopen a disconnected glove.")]
        [SerializeField, Range(0.001f, 60f)] float reconnectIntervalSeconds = 0.2f;
        [Tooltip("Newtons per finger the glove may resist with (its own limit if lower).")]
        [SerializeField, Min(0f)] float maxFingerResistance = 10f;
        [Tooltip("Newtons per fingertip.")]
        [SerializeField, Min(0f)] float maxFingertipForce = 10f;
        [Tooltip("Newton-metres per finger joint.")]
        [SerializeField, Min(0f)] float maxJointTorque = 0.5f;

        [Tooltip("(before, now): (Closed, Connected) when the glove opens, (Connected, Disconnected) and back " +
                 "as it goes and returns, (..., Closed) when it closes.")]
        [SerializeField] StateEvent stateChanged = new StateEvent();
        [Tooltip("(before, now) of the reason the glove's output is held at zero; None: it renders forces.")]
        [SerializeField] WatchdogEvent watchdogChanged = new WatchdogEvent();

        Device device;
        bool started;

        /// <summary>Raised on the main thread when the glove's state changes, with (before, now):
        /// (Closed, Connected) when it opens, (Connected, Disconnected) and back as it goes and
        /// returns, (..., Closed) when it closes (disabled, destroyed, or its world destroyed).</summary>
        public StateEvent StateChanged => stateChanged;

        /// <summary>Raised on the main thread when the reason the output is held at zero changes,
        /// with (before, now); now is None when the glove renders forces again.</summary>
        public WatchdogEvent WatchdogChanged => watchdogChanged;

        /// <summary>The open glove; null while closed.</summary>
        public Device Device => device;

        /// <summary>true while the glove is open (it may still be disconnected: see <see cref="State"/>).</summary>
        public bool IsOpen => device != null;

        /// <summary>The state as of this frame's poll; Closed while closed.</summary>
        public FrustaDeviceState State => device != null ? device.State : FrustaDeviceState.Closed;

        /// <summary>The status this frame's poll read (all zero while closed).</summary>
        public FrustaDeviceStatus Status => device != null ? device.PolledStatus : default;

        /// <summary>The URI; setting it reopens an open glove at the new one.</summary>
        public string Uri
        {
            get => uri;
            set
            {
                uri = value;
                if (device == null) return;
                Close();
                Open();
            }
        }

        /// <summary>The hand the glove drives; set it before the glove opens (in Start).</summary>
        public FrustaHand Hand
        {
            get => hand;
            set => hand = value;
        }

        void Awake()
        {
            if (hand == null) hand = GetComponent<FrustaHand>();
        }

        // every hand of the scene has joined its world in its OnEnable: the glove may open now
        void Start()
        {
            started = true;
            Open();
        }

        void OnEnable()
        {
            // a hand that leaves its world closes the glove first; back, it may open it again
            if (hand != null) hand.Registered += Open;
            if (started) Open();
        }

        void OnDisable()
        {
            if (hand != null) hand.Registered -= Open;
            Close();
        }

        void OnDestroy() => Close();

        void Update()
        {
            if (device == null) return;
            if (!device.PolledStatus.HasPalmPose)
            {
                Transform source = palmSource != null ? palmSource : (hand != null ? hand.HapticSource : transform);
                device.SetPalmPose(source.ToFrustaPose());
            }
            // false once the world was destroyed, which closed the glove (StateChanged said so)
            if (!device.Poll()) Close();
        }

        void Open()
        {
            if (device != null || !isActiveAndEnabled || string.IsNullOrEmpty(uri)) return;
            World world = hand != null && hand.WorldBehaviour != null ? hand.WorldBehaviour.World : null;
            if (world == null || hand.Id.IsNull)
            {
                Debug.LogError("FrustaGloveDevice needs a registered Frusta Hand (set one, or put this on the hand).", this);
                return;
            }
            FrustaDeviceDef def = FrustaDeviceDef.Default;
            def.Hand = hand.Id;
            def.OutputRateHz = outputRateHz < 1f ? 0.0 : outputRateHz;  // 0 or 1..100000 natively
            def.WatchdogS = watchdogSeconds;
            def.HostTimeoutS = hostTimeoutSeconds;
            def.ReconnectIntervalS = reconnectIntervalSeconds;
            def.MaxFingerResistance = maxFingerResistance;
            def.MaxFingertipForce = maxFingertipForce;
            def.MaxJointTorque = maxJointTorque;
            try
            {
                device = world.CreateDevice(uri, def);
            }
            catch (FrustaException e)
            {
                Debug.LogError($"Frusta glove \"{uri}\" did not open ({e.Result}): {e.NativeMessage}", this);
                return;
            }
            device.StateChanged += OnStateChanged;
            device.WatchdogChanged += OnWatchdogChanged;
            hand.DrivenByDevice = true;
            hand.Releasing += Close;
            stateChanged.Invoke(FrustaDeviceState.Closed, FrustaDeviceState.Connected);
        }

        void Close()
        {
            if (device == null) return;
            FrustaDeviceState last = device.State;
            device.StateChanged -= OnStateChanged;
            device.WatchdogChanged -= OnWatchdogChanged;
            device.Dispose(); // zeroes the glove's output; stale (and fine) if the world went first
            device = null;
            if (hand != null)
            {
                hand.DrivenByDevice = false;
                hand.Releasing -= Close;
            }
            if (last != FrustaDeviceState.Closed) stateChanged.Invoke(last, FrustaDeviceState.Closed);
        }

        void OnStateChanged(object sender, DeviceStateChangedEventArgs e) => stateChanged.Invoke(e.OldState, e.NewState);

        void OnWatchdogChanged(object sender, DeviceWatchdogChangedEventArgs e) => watchdogChanged.Invoke(e.OldReason, e.NewReason);
    }
}
