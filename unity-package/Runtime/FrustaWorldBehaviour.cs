// SPDX-License-Identifier: MIT
using System;
using Frusta.Binding;
using UnityEngine;

namespace Frusta.Unity
{
    /// <summary>
    /// Owns a Frusta <see cref="World"/>. It is created in Awake (before any hand or object of the
    /// scene registers: this component runs early; hands and objects may also come and go later,
    /// while it runs), runs on its own 1 kHz thread while enabled
    /// (or is stepped from Update when <see cref="runOnOwnThread"/> is off, or by a script when
    /// <see cref="stepInUpdate"/> is off too), latches the newest
    /// step once per frame for the other components, and is disposed on destroy, on quit and
    /// before an editor domain reload.
    /// </summary>
    [DefaultExecutionOrder(-100)]
    [DisallowMultipleComponent]
    [AddComponentMenu("Frusta/Frusta World")]
    public sealed class FrustaWorldBehaviour : MonoBehaviour
    {
        [Tooltip("Steps per second (Hz); a step advances time by 1/rate.")]
        [SerializeField] double rateHz = 1000.0;
        [Tooltip("Run the world on its own thread; off: step it from Update, catching up with the frame time.")]
        [SerializeField] bool runOnOwnThread = true;
        [Tooltip("Its own thread and the threads of gloves driving its hands ask for real-time priority, so a " +
                 "glove is answered within a period whatever else the machine runs (State.Realtime says " +
                 "whether it was granted).")]
        [SerializeField] bool realtimePriority = true;
        [Tooltip("With Run On Own Thread off: step the world from Update; off: a script steps it (World.Step) " +
                 "before this component's Update, which then only latches the newest step.")]
        [SerializeField] bool stepInUpdate = true;
        [Tooltip("Object slots.")]
        [SerializeField] int maxObjects = 64;
        [Tooltip("Hand slots (1..64): hands at once, a user's two, another user's, rigs spawned at run time.")]
        [SerializeField] int maxHands = 8;
        [Tooltip("Object spheres near one hand that its buffers hold, made when the hand is added (about 400 " +
                 "bytes each; 1..262144). A hand meeting more grows them once on the stepping thread: raise " +
                 "it for objects denser than about 10^4 spheres.")]
        [SerializeField] int maxCandidatesPerHand = 1024;
        [Tooltip("Gravity on dynamic objects, m/s², Unity frame.")]
        [SerializeField] Vector3 gravity = Vector3.zero;

        World world;
        FrustaWorldState state;
        double pendingSteps;
        bool started;

        /// <summary>Steps per second (Hz). Set before the component wakes (add it to an inactive
        /// GameObject, set this, then activate it); later changes do not reach the world.</summary>
        public double RateHz { get => rateHz; set => rateHz = value; }

        /// <summary>Run the world on its own thread (else see <see cref="StepInUpdate"/>). Set before
        /// the component wakes.</summary>
        public bool RunOnOwnThread { get => runOnOwnThread; set => runOnOwnThread = value; }

        /// <summary>The world's thread and its gloves' threads ask for real-time priority
        /// (<see cref="FrustaWorldDef.RealtimePriority"/>). Set before the component wakes.</summary>
        public bool RealtimePriority { get => realtimePriority; set => realtimePriority = value; }

        /// <summary>Without its own thread: true, Update steps the world by the frame time; false, a
        /// script steps it (<see cref="Frusta.Binding.World.Step()"/>, before this component's Update:
        /// give it an earlier execution order) and Update only latches. Set before the component
        /// starts.</summary>
        public bool StepInUpdate { get => stepInUpdate; set => stepInUpdate = value; }

        /// <summary>Gravity on dynamic objects, m/s², Unity frame. Set before the component wakes.</summary>
        public Vector3 Gravity { get => gravity; set => gravity = value; }

        /// <summary>Object slots. Set before the component wakes.</summary>
        public int MaxObjects { get => maxObjects; set => maxObjects = value; }

        /// <summary>Object spheres near one hand that its buffers hold
        /// (<see cref="FrustaWorldDef.MaxCandidatesPerHand"/>). Set before the component wakes.</summary>
        public int MaxCandidatesPerHand { get => maxCandidatesPerHand; set => maxCandidatesPerHand = value; }

        /// <summary>The world; null before Awake and after destruction.</summary>
        public World World => world;

        /// <summary>The step latched this frame (by <see cref="Update"/>).</summary>
        public ref readonly FrustaWorldState State => ref state;

        /// <summary>Raised after each frame's latch; read hands and objects from here.</summary>
        public event Action<FrustaWorldBehaviour> Latched;

        void Awake()
        {
            FrustaWorldDef def = FrustaWorldDef.Default;
            def.RateHz = rateHz;
            def.RealtimePriority = realtimePriority;
            def.MaxObjects = maxObjects;
            def.MaxHands = maxHands;
            def.MaxCandidatesPerHand = maxCandidatesPerHand;
            def.Gravity = gravity.ToFrustaVector();
            world = new World(def);
#if UNITY_EDITOR
            // a domain reload would orphan the native thread: dispose first
            UnityEditor.AssemblyReloadEvents.beforeAssemblyReload += DisposeWorld;
#endif
            Application.quitting += DisposeWorld;
        }

        // every hand and object registered in its Awake/OnEnable: the world may step now
        void Start()
        {
            started = true;
            if (isActiveAndEnabled && runOnOwnThread) world.Start();
        }

        void OnEnable()
        {
            if (started && world != null && runOnOwnThread && !world.IsRunning) world.Start();
        }

        void OnDisable()
        {
            if (world != null && world.IsValid) world.Stop();
        }

        void Update()
        {
            if (world == null || !started) return;
            if (!runOnOwnThread && stepInUpdate)
            {
                pendingSteps += Time.deltaTime * rateHz;
                int steps = Math.Min((int)pendingSteps, (int)(0.1 * rateHz)); // at most 100 ms per frame
                pendingSteps -= (int)pendingSteps;
                world.Step(steps);
            }
            world.Read(ref state);
            Latched?.Invoke(this);
        }

        void OnDestroy() => DisposeWorld();

        void DisposeWorld()
        {
#if UNITY_EDITOR
            UnityEditor.AssemblyReloadEvents.beforeAssemblyReload -= DisposeWorld;
#endif
            Application.quitting -= DisposeWorld;
            world?.Dispose();
            world = null;
        }
    }
}
