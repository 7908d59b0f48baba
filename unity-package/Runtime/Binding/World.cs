// SPDX-License-Identifier: MIT
using System;
using System.Collections.Generic;

namespace Frusta.Binding
{
    /// <summary>
    /// A world: hands and objects stepped together. Each step turns every hand's haptic input
    /// (the glove) into a graphic hand that never sinks into an object, the contact forces, the
    /// device outputs and each object's reaction. Run it on its own 1 kHz thread
    /// (<see cref="Start"/>) or step it yourself (<see cref="Step()"/>); the host never waits for
    /// the stepping thread: object commands are queued for the next step and results are
    /// published as snapshots that <see cref="Read"/> latches.
    /// <para>Hands, like objects, come and go at any time: <see cref="CreateHand"/> and
    /// <see cref="DestroyHand"/> are queued for the next step, while the own thread runs.</para>
    /// <para>Threads: the creating thread is the host (Unity's main thread) for every member
    /// unless its documentation says otherwise; <see cref="SetHaptic(FrustaHandId, in FrustaPose, ReadOnlySpan{double})"/> may come from one input
    /// thread per hand; <see cref="ReadSnapshot"/> from any thread. Dispose is safe twice and
    /// from any thread; it waits for calls in flight, then stops the own thread, closes the
    /// world's gloves (<see cref="CreateDevice(string, in FrustaDeviceDef)"/>) and destroys the
    /// world with its hands and objects.</para>
    /// </summary>
    public sealed unsafe class World : IDisposable
    {
        readonly WorldHandle handle;
        // frusta_world_read latches one step per world: reads from several threads take turns,
        // and with the calls that add and remove hands and objects (a read frees what the
        // latched step no longer shows, on the native host's side)
        readonly object readGate = new object();
        readonly int maxContactsPerHand;
        volatile bool running;
        // the world's hands in creation order; replaced whole, so readers on other threads
        // see one list or the next
        volatile FrustaHandId[] hands = new FrustaHandId[0];

        /// <summary>A world with the library's default parameters (1 kHz, no gravity).</summary>
        public World() : this(FrustaWorldDef.Default) { }

        /// <summary>A world, without a thread yet (<c>frusta_create_world</c>).</summary>
        /// <param name="def">From <see cref="FrustaWorldDef.Default"/>, then edited.</param>
        /// <exception cref="FrustaException">A def value out of range (e.g. <see cref="FrustaResult.OutOfRange"/>
        /// naming "rate_hz"), or a def not from the defaults (<see cref="FrustaResult.DefNotDefaulted"/>).</exception>
        public World(in FrustaWorldDef def)
        {
            FrustaLibrary.EnsureCompatible();
            handle = new WorldHandle();
            handle.Create(def, Native.frusta_create_world, "frusta_create_world");
            maxContactsPerHand = def.MaxContactsPerHand;
            MaxHands = def.MaxHands;
            RateHz = def.RateHz;
        }

        internal WorldHandle Handle => handle;

        /// <summary>The native id (a value; stale once disposed).</summary>
        public FrustaWorldId Id => handle.Id;

        /// <summary>false once disposed (<c>frusta_world_is_valid</c>). Thread: any.</summary>
        public bool IsValid => !handle.IsClosed && Native.frusta_world_is_valid(handle.Id) == 1;

        /// <summary>true between <see cref="Start"/> and <see cref="Stop"/>.</summary>
        public bool IsRunning => running;

        /// <summary>The stepping rate from the def, Hz; a step advances time by 1/RateHz seconds.</summary>
        public double RateHz { get; }

        /// <summary>Hands created and not destroyed.</summary>
        public int HandCount => hands.Length;

        /// <summary>Hand slots, from the def: at most this many hands at once.</summary>
        public int MaxHands { get; }

        /// <summary>The world's hands, created and not destroyed, in creation order (the order of
        /// <see cref="WorldSnapshot"/>'s hands).</summary>
        public IReadOnlyList<FrustaHandId> Hands => hands;

        /// <summary>The most contacts a hand reports per step (the def's MaxContactsPerHand): a
        /// contact buffer this long is never too small.</summary>
        public int MaxContactsPerHand => maxContactsPerHand;

        /// <summary>Create a hand in this world built from <paramref name="def"/>, at any time, the own
        /// thread running or not (<c>frusta_create_world_hand</c>): it takes <see cref="SetHaptic(FrustaHandId, in FrustaPose, ReadOnlySpan{double})"/> at
        /// once and is in the steps from the next one on (<see cref="GetHand"/> refuses it until a
        /// <see cref="Read"/> latched such a step). Allocates (the hand's native memory, on this
        /// thread): not a per-frame call.</summary>
        /// <param name="def">From <see cref="FrustaHandDef.Default"/>, then edited.</param>
        /// <returns>The hand's id, which every call on the world's hands takes.</returns>
        /// <exception cref="FrustaException"><see cref="FrustaResult.Capacity"/> when <see cref="MaxHands"/>
        /// hands are present or still being let go of (see <see cref="DestroyHand"/>), or the command
        /// queue is full; a def value out of range.</exception>
        public FrustaHandId CreateHand(in FrustaHandDef def)
        {
            FrustaHandId hand;
            using (new HandleUse(handle))
            lock (readGate)
            {
                fixed (FrustaHandDef* d = &def)
                    Errors.Check(Native.frusta_create_world_hand(handle.Id, d, &hand), "frusta_create_world_hand");
                var grown = new FrustaHandId[hands.Length + 1];
                Array.Copy(hands, grown, hands.Length);
                grown[hands.Length] = hand;
                hands = grown;
            }
            return hand;
        }

        /// <summary>Destroy a hand of this world (queued; <c>frusta_destroy_world_hand</c>). Its id is
        /// refused at once by the calls that change the world (<see cref="SetHaptic(FrustaHandId, in FrustaPose, ReadOnlySpan{double})"/> from an input
        /// thread included); <see cref="GetHand"/> still reports it until a step has applied the
        /// removal. Its slot takes a new hand once a <see cref="Read"/> latched that step.</summary>
        /// <param name="hand">The id from <see cref="CreateHand"/>.</param>
        /// <exception cref="FrustaException"><see cref="FrustaResult.StaleId"/> for a hand already destroyed
        /// or of another world; <see cref="FrustaResult.WrongState"/> while a glove drives it (dispose the
        /// <see cref="Device"/> first).</exception>
        public void DestroyHand(FrustaHandId hand)
        {
            using (new HandleUse(handle))
            lock (readGate)
            {
                CheckBelongsHere(hand.World0, $"hand id {hand}", "frusta_destroy_world_hand");
                Errors.Check(Native.frusta_destroy_world_hand(hand), "frusta_destroy_world_hand");
                int at = Array.IndexOf(hands, hand);
                if (at < 0) return;
                var shrunk = new FrustaHandId[hands.Length - 1];
                Array.Copy(hands, shrunk, at);
                Array.Copy(hands, at + 1, shrunk, at, hands.Length - at - 1);
                hands = shrunk;
            }
        }

        /// <summary>
        /// Set a hand's haptic input: palm pose and 20 joint angles (radians, finger-major); the
        /// newest input wins and the next step uses it (<c>frusta_world_set_haptic</c>).
        /// Lock-free and allocation-free. Thread: one input thread per hand (or the host).
        /// </summary>
        /// <param name="hand">The id from <see cref="CreateHand"/>.</param>
        /// <param name="palm">Metres, world frame; quaternion norm in [0.5, 2].</param>
        /// <param name="angles">Exactly 20 radians, |angle| &lt;= 4 pi (FrustaConstants.MaxJointAngle; beyond the limits is clamped).</param>
        /// <exception cref="FrustaException"><see cref="FrustaResult.WrongState"/> on a hand a glove drives
        /// (<see cref="CreateDevice(string, in FrustaDeviceDef)"/>) until the glove is disposed;
        /// <see cref="FrustaResult.StaleId"/> for a hand of another world or a standalone hand.</exception>
        public void SetHaptic(FrustaHandId hand, in FrustaPose palm, ReadOnlySpan<double> angles)
        {
            using (new HandleUse(handle))
            fixed (FrustaPose* p = &palm)
            fixed (double* a = angles)
                Errors.Check(Native.frusta_world_set_haptic(handle.Id, hand, p, a, angles.Length), "frusta_world_set_haptic");
        }

        /// <summary>
        /// Set a hand's haptic input stamped with the sample's time (<c>frusta_world_set_haptic_at</c>):
        /// each step plays the hand's samples <see cref="FrustaWorldDef.InputDelay"/> behind its own
        /// time, interpolated between the two around it, extrapolated at most
        /// <see cref="FrustaWorldDef.MaxExtrapolation"/> past the newest, then held. A host that
        /// stalls and then delivers its samples in a burst so moves the hand as its samples say.
        /// Lock-free and allocation-free. Thread: one input thread per hand (or the host).
        /// </summary>
        /// <param name="hand">The id from <see cref="CreateHand"/>.</param>
        /// <param name="time">Seconds on the world's clock: <see cref="Now"/>'s while the world runs on
        /// its own thread (<see cref="Start"/>); the step time while the host steps it (the step after n
        /// steps is at (n + 1) / rate). Later than the hand's previous timed sample, 0..1e9.</param>
        /// <param name="palm">Metres, world frame; quaternion norm in [0.5, 2].</param>
        /// <param name="angles">Exactly 20 radians, as <see cref="SetHaptic(FrustaHandId, in FrustaPose, ReadOnlySpan{double})"/> takes them.</param>
        /// <exception cref="FrustaException"><see cref="FrustaResult.OutOfRange"/> naming "time" for a time
        /// out of range or not after the previous one; otherwise as
        /// <see cref="SetHaptic(FrustaHandId, in FrustaPose, ReadOnlySpan{double})"/>.</exception>
        public void SetHaptic(FrustaHandId hand, double time, in FrustaPose palm, ReadOnlySpan<double> angles)
        {
            using (new HandleUse(handle))
            fixed (FrustaPose* p = &palm)
            fixed (double* a = angles)
                Errors.Check(Native.frusta_world_set_haptic_at(handle.Id, hand, time, p, a, angles.Length),
                             "frusta_world_set_haptic_at");
        }

        /// <summary>Seconds on Frusta's monotonic clock (<c>frusta_now</c>): the clock of
        /// <see cref="SetHaptic(FrustaHandId, double, in FrustaPose, ReadOnlySpan{double})"/>'s time
        /// while a world runs on its own thread. Thread: any.</summary>
        public static double Now => Native.frusta_now();

        /// <summary>Set a hand's haptic input from a fit of tracked joints: its palm and angles, as
        /// <see cref="SetHaptic(FrustaHandId, in FrustaPose, ReadOnlySpan{double})"/> takes them
        /// (<c>frusta_world_set_haptic</c>). Lock-free and allocation-free. Thread: one input thread per hand.</summary>
        /// <param name="hand">A hand of this world.</param>
        /// <param name="fit">From <see cref="HandFitter.Fit(ReadOnlySpan{FrustaTrackedJoint}, in FrustaPose, ref FrustaHandFit)"/>,
        /// in this world's frame (give the fit the joints' frame).</param>
        public void SetHaptic(FrustaHandId hand, in FrustaHandFit fit)
        {
            using (new HandleUse(handle))
            fixed (FrustaHandFit* f = &fit)
                Errors.Check(Native.frusta_world_set_haptic(handle.Id, hand, &f->Palm, f->angles, FrustaConstants.HandJointCount),
                             "frusta_world_set_haptic");
        }

        /// <summary>Create an object in this world with a tree's shape; queued, present from the next step
        /// (<c>frusta_create_object</c>). The world keeps the tree alive while it uses it.</summary>
        /// <param name="tree">The object's shape.</param>
        /// <param name="def">From <see cref="FrustaObjectDef.Default"/>, then edited.</param>
        /// <returns>The object's id in this world.</returns>
        /// <exception cref="FrustaException"><see cref="FrustaResult.Capacity"/> when MaxObjects are present or the
        /// command queue is full (step the world); a def value out of range.</exception>
        public FrustaObjectId CreateObject(SphereTree tree, in FrustaObjectDef def)
        {
            if (tree == null) throw new ArgumentNullException(nameof(tree));
            FrustaObjectId id;
            using (new HandleUse(handle))
            using (new HandleUse(tree.Handle))
            lock (readGate)
            fixed (FrustaObjectDef* d = &def)
                Errors.Check(Native.frusta_create_object(handle.Id, tree.Id, d, &id), "frusta_create_object");
            return id;
        }

        /// <summary>Destroy an object of this world (queued; <c>frusta_destroy_object</c>). Its id is
        /// refused at once by the calls that change the world; <see cref="GetObject"/> still reports it
        /// until a step has applied the removal.</summary>
        /// <param name="id">The object.</param>
        /// <exception cref="FrustaException"><see cref="FrustaResult.StaleId"/> for an object already destroyed
        /// or of another world.</exception>
        public void DestroyObject(FrustaObjectId id)
        {
            using (new HandleUse(handle))
            lock (readGate)
            {
                CheckBelongsHere(id.World0, $"object id {id}", "frusta_destroy_object");
                Errors.Check(Native.frusta_destroy_object(id), "frusta_destroy_object");
            }
        }

        /// <summary>Put an object at a pose, at rest (queued; <c>frusta_world_set_object_pose</c>).</summary>
        /// <param name="id">The object.</param>
        /// <param name="pose">Metres, world frame.</param>
        public void SetObjectPose(FrustaObjectId id, in FrustaPose pose)
        {
            using (new HandleUse(handle))
            fixed (FrustaPose* p = &pose)
                Errors.Check(Native.frusta_world_set_object_pose(handle.Id, id, p), "frusta_world_set_object_pose");
        }

        /// <summary>Hand an object to the world's dynamics (true) or take it back, at rest (false);
        /// queued (<c>frusta_world_set_object_dynamic</c>).</summary>
        /// <param name="id">The object.</param>
        /// <param name="dynamic">true: the world integrates it.</param>
        public void SetObjectDynamic(FrustaObjectId id, bool dynamic)
        {
            using (new HandleUse(handle))
                Errors.Check(Native.frusta_world_set_object_dynamic(handle.Id, id, dynamic ? 1 : 0),
                             "frusta_world_set_object_dynamic");
        }

        /// <summary>One step of 1/RateHz: apply queued commands, solve every hand, publish
        /// (<c>frusta_world_step</c>).</summary>
        /// <exception cref="FrustaException"><see cref="FrustaResult.WrongState"/> while the own thread runs.</exception>
        public void Step()
        {
            using (new HandleUse(handle))
                Errors.Check(Native.frusta_world_step(handle.Id), "frusta_world_step");
        }

        /// <summary>Several steps in a row.</summary>
        /// <param name="count">Steps, &gt;= 0.</param>
        public void Step(int count)
        {
            if (count < 0) throw new ArgumentOutOfRangeException(nameof(count));
            using (new HandleUse(handle))
                for (int i = 0; i < count; ++i)
                    Errors.Check(Native.frusta_world_step(handle.Id), "frusta_world_step");
        }

        /// <summary>Run the world on its own thread at RateHz on absolute deadlines until
        /// <see cref="Stop"/> (<c>frusta_world_start</c>). No C# runs on that thread.</summary>
        /// <exception cref="FrustaException"><see cref="FrustaResult.WrongState"/> when already running.</exception>
        public void Start()
        {
            using (new HandleUse(handle))
                Errors.Check(Native.frusta_world_start(handle.Id), "frusta_world_start");
            running = true;
        }

        /// <summary>Stop the own thread; returns once its current step is done; no effect if none
        /// runs (<c>frusta_world_stop</c>).</summary>
        public void Stop()
        {
            using (new HandleUse(handle))
                Errors.Check(Native.frusta_world_stop(handle.Id), "frusta_world_stop");
            running = false;
        }

        /// <summary>
        /// Latch the newest published step (never a torn one) and fill <paramref name="state"/>
        /// (<c>frusta_world_read</c>). <see cref="GetHand"/>, <see cref="GetContacts(FrustaHandId, Span{FrustaWorldContact})"/>
        /// and <see cref="GetObject"/> then read the latched step. Allocation-free: reuse one state.
        /// Thread: host; for one consistent step from any thread use <see cref="ReadSnapshot"/>.
        /// </summary>
        /// <param name="state">Filled; its previous contents do not matter.</param>
        public void Read(ref FrustaWorldState state)
        {
            state.struct_size = sizeof(FrustaWorldState);
            using (new HandleUse(handle))
            lock (readGate)
            fixed (FrustaWorldState* s = &state)
                Errors.Check(Native.frusta_world_read(handle.Id, s), "frusta_world_read");
        }

        /// <summary>One hand of the latched step (<c>frusta_world_get_hand</c>). Allocation-free.</summary>
        /// <param name="hand">The id from <see cref="CreateHand"/>.</param>
        /// <param name="output">Filled; reuse one per hand.</param>
        /// <exception cref="FrustaException"><see cref="FrustaResult.WrongState"/> before any <see cref="Read"/>;
        /// <see cref="FrustaResult.StaleId"/> for a hand this world does not have.</exception>
        public void GetHand(FrustaHandId hand, ref FrustaWorldHand output)
        {
            output.struct_size = sizeof(FrustaWorldHand);
            ReadLatched(hand, ref output, (world, h, o) => Native.frusta_world_get_hand(world, h, o), "frusta_world_get_hand");
        }

        /// <summary>One hand of the latched step, as <see cref="GetHand"/>, or false when the step does
        /// not show it: created after the latched step, destroyed before it, or another world's. What a component
        /// reading a hand created at run time calls each frame: no exception, no allocation.</summary>
        /// <param name="hand">The id from <see cref="CreateHand"/>.</param>
        /// <param name="output">Filled when the step shows the hand.</param>
        /// <returns>true when filled.</returns>
        /// <exception cref="FrustaException">As <see cref="GetHand"/>, but for a hand the step does not show.</exception>
        public bool TryGetHand(FrustaHandId hand, ref FrustaWorldHand output)
        {
            output.struct_size = sizeof(FrustaWorldHand);
            FrustaResult r;
            using (new HandleUse(handle))
            lock (readGate)
            fixed (FrustaWorldHand* o = &output)
                r = Native.frusta_world_get_hand(handle.Id, hand, o);
            if (r == FrustaResult.StaleId) return false;
            Errors.Check(r, "frusta_world_get_hand");
            return true;
        }

        /// <summary>How many contacts one hand has in the latched step (at most <see cref="MaxContactsPerHand"/>).</summary>
        /// <param name="hand">The id from <see cref="CreateHand"/>.</param>
        /// <returns>The count.</returns>
        public int GetContactCount(FrustaHandId hand) => GetContacts(hand, default);

        /// <summary>Copy one hand's contacts of the latched step (<c>frusta_world_get_contacts</c>): the first
        /// min(destination.Length, count) of them. Allocation-free: reuse a buffer of
        /// <see cref="MaxContactsPerHand"/>, which is never short.</summary>
        /// <param name="hand">The id from <see cref="CreateHand"/>.</param>
        /// <param name="destination">Receives the contacts.</param>
        /// <returns>How many contacts the hand has, which exceeds destination.Length when it was short.</returns>
        public int GetContacts(FrustaHandId hand, Span<FrustaWorldContact> destination)
        {
            int count;
            using (new HandleUse(handle))
            lock (readGate)
            {
                fixed (FrustaWorldContact* c = destination)
                    Errors.Check(Native.frusta_world_get_contacts(handle.Id, hand, c, destination.Length, &count),
                                 "frusta_world_get_contacts");
            }
            return count;
        }

        /// <summary>Copy one hand's contacts of the latched step into an array (see
        /// <see cref="GetContacts(FrustaHandId, Span{FrustaWorldContact})"/>).</summary>
        /// <param name="hand">The id from <see cref="CreateHand"/>.</param>
        /// <param name="destination">Receives the contacts.</param>
        /// <param name="count">How many contacts the hand has (more than copied when destination was short).</param>
        public void GetContacts(FrustaHandId hand, FrustaWorldContact[] destination, out int count)
        {
            if (destination == null) throw new ArgumentNullException(nameof(destination));
            count = GetContacts(hand, destination.AsSpan());
        }

        /// <summary>One object of the latched step (<c>frusta_world_get_object</c>). Allocation-free.</summary>
        /// <param name="id">The object.</param>
        /// <param name="output">Filled.</param>
        /// <exception cref="FrustaException"><see cref="FrustaResult.StaleId"/> for an object destroyed, or created
        /// after the latched step.</exception>
        public void GetObject(FrustaObjectId id, ref FrustaObjectState output)
        {
            output.struct_size = sizeof(FrustaObjectState);
            ReadLatched(id, ref output, (world, i, o) => Native.frusta_world_get_object(world, i, o), "frusta_world_get_object");
        }

        /// <summary>Whether, in the latched step, <paramref name="hand"/> ignores <paramref name="id"/>: the
        /// object was created or moved into the hand and they have not parted since; the hand passes
        /// through it and pushes it with no force until then
        /// (<c>frusta_world_get_object_ignored_by</c>). Allocation-free.</summary>
        /// <param name="id">The object.</param>
        /// <param name="hand">The hand.</param>
        /// <returns>true while the hand ignores the object.</returns>
        /// <exception cref="FrustaException"><see cref="FrustaResult.StaleId"/> for an object or hand not in the
        /// latched step.</exception>
        public bool IsObjectIgnoredBy(FrustaObjectId id, FrustaHandId hand)
        {
            int ignored;
            using (new HandleUse(handle))
            lock (readGate)
                Errors.Check(Native.frusta_world_get_object_ignored_by(handle.Id, id, hand, &ignored),
                             "frusta_world_get_object_ignored_by");
            return ignored != 0;
        }

        /// <summary>Copy every segment of one hand of the latched step, world coordinates, finger-major
        /// (thumb first), proximal to distal (<c>frusta_world_get_hand_segments</c>): the first
        /// min(destination.Length, 15) of them. Allocation-free: reuse a buffer of
        /// <see cref="FrustaConstants.HandSegmentCount"/>.</summary>
        /// <param name="hand">The hand.</param>
        /// <param name="which">The graphic (displayed) hand or the haptic (input) one.</param>
        /// <param name="destination">Receives the segments, Frusta's frame.</param>
        /// <returns>How many segments the hand has (15).</returns>
        /// <exception cref="FrustaException"><see cref="FrustaResult.WrongState"/> while the hand has had no
        /// input (<see cref="FrustaWorldHand.Solved"/> false); <see cref="FrustaResult.StaleId"/> for a hand
        /// not in the latched step.</exception>
        public int GetHandSegments(FrustaHandId hand, FrustaHandKind which, Span<FrustaSegment> destination)
        {
            int count;
            using (new HandleUse(handle))
            lock (readGate)
            fixed (FrustaSegment* s = destination)
                Errors.Check(Native.frusta_world_get_hand_segments(handle.Id, hand, (int)which, s, destination.Length, &count),
                             "frusta_world_get_hand_segments");
            return count;
        }

        /// <summary>Copy the palm spheres of one hand of the latched step, world coordinates
        /// (<c>frusta_world_get_hand_palm_spheres</c>): the first min(destination.Length, count) of
        /// them. An empty destination asks for the count alone. Allocation-free.</summary>
        /// <param name="hand">The hand.</param>
        /// <param name="which">The graphic (displayed) hand or the haptic (input) one.</param>
        /// <param name="destination">Receives the spheres, Frusta's frame.</param>
        /// <returns>How many palm spheres the hand has (more than copied when destination was short).</returns>
        /// <exception cref="FrustaException">As <see cref="GetHandSegments"/>.</exception>
        public int GetHandPalmSpheres(FrustaHandId hand, FrustaHandKind which, Span<FrustaSphere> destination)
        {
            int count;
            using (new HandleUse(handle))
            lock (readGate)
            fixed (FrustaSphere* s = destination)
                Errors.Check(Native.frusta_world_get_hand_palm_spheres(handle.Id, hand, (int)which, s, destination.Length, &count),
                             "frusta_world_get_hand_palm_spheres");
            return count;
        }

        /// <summary>A snapshot buffer sized for this world's hands and contacts, for
        /// <see cref="ReadSnapshot"/>. Allocates: make one per reader and reuse it.</summary>
        /// <returns>An empty snapshot.</returns>
        public WorldSnapshot CreateSnapshot() => new WorldSnapshot(hands.Length, maxContactsPerHand);

        /// <summary>
        /// Latch the newest step and copy its state, every hand and every hand's contacts into
        /// <paramref name="snapshot"/>, all from that one step. Thread: any; readers on several
        /// threads take turns on the world's read lock. Allocation-free once the snapshot has
        /// room for the world's hands.
        /// </summary>
        /// <param name="snapshot">From <see cref="CreateSnapshot"/>; reused.</param>
        public void ReadSnapshot(WorldSnapshot snapshot)
        {
            if (snapshot == null) throw new ArgumentNullException(nameof(snapshot));
            using (new HandleUse(handle))
            lock (readGate)
            {
                FrustaWorldId id = handle.Id;
                snapshot.state.struct_size = sizeof(FrustaWorldState);
                fixed (FrustaWorldState* s = &snapshot.state)
                    Errors.Check(Native.frusta_world_read(id, s), "frusta_world_read");
                // the world's hands the step shows: one created since is not in it yet
                FrustaHandId[] ids = hands;
                snapshot.EnsureHands(ids.Length);
                int count = 0;
                foreach (FrustaHandId hand in ids)
                {
                    snapshot.hands[count].struct_size = sizeof(FrustaWorldHand);
                    FrustaResult r;
                    fixed (FrustaWorldHand* p = &snapshot.hands[count])
                        r = Native.frusta_world_get_hand(id, hand, p);
                    if (r == FrustaResult.StaleId) continue;
                    Errors.Check(r, "frusta_world_get_hand");
                    int contacts;
                    Errors.Check(Native.frusta_world_get_contacts(id, hand, null, 0, &contacts), "frusta_world_get_contacts");
                    snapshot.EnsureContacts(count, contacts);
                    fixed (FrustaWorldContact* c = snapshot.contacts[count])
                        Errors.Check(Native.frusta_world_get_contacts(id, hand, c, snapshot.contacts[count].Length, &contacts),
                                     "frusta_world_get_contacts");
                    snapshot.contactCounts[count] = contacts;
                    snapshot.ids[count] = hand;
                    ++count;
                }
                snapshot.handCount = count;
            }
        }

        /// <summary>Open a glove with the library's defaults (<see cref="FrustaDeviceDef.Default"/>) to drive
        /// one hand; see <see cref="CreateDevice(string, in FrustaDeviceDef)"/>.</summary>
        /// <param name="uri">Where the glove is, e.g. <c>opengloves:/dev/ttyUSB0</c> or <c>replay:FILE</c>.</param>
        /// <param name="hand">The id from <see cref="CreateHand"/>.</param>
        /// <returns>The open glove; dispose it to close it.</returns>
        public Device CreateDevice(string uri, FrustaHandId hand)
        {
            FrustaDeviceDef def = FrustaDeviceDef.Default;
            def.Hand = hand;
            return CreateDevice(uri, def);
        }

        /// <summary>
        /// Open the glove at <paramref name="uri"/> to drive the hand <paramref name="def"/>.Hand of this
        /// world, and start the glove's own native thread (<c>frusta_create_device</c>). The URI is
        /// one of <c>opengloves:PATH?baud=N</c> (OpenGloves alpha encoding over serial),
        /// <c>serial:PATH?baud=N</c> and <c>hid:VID:PID[:SERIAL]</c> (Frusta's binary profile), or
        /// <c>replay:FILE?speed=1|max&amp;loop=0|1</c> (a recording); any takes <c>&amp;record=FILE</c>.
        /// While the glove is open it feeds the hand (<see cref="SetHaptic(FrustaHandId, in FrustaPose, ReadOnlySpan{double})"/> on that hand is refused
        /// with <see cref="FrustaResult.WrongState"/>), and its palm comes from
        /// <see cref="Device.SetPalmPose"/> unless the glove reports one. Thread: host.
        /// </summary>
        /// <param name="uri">Where the glove is (UTF-8 on the native side).</param>
        /// <param name="def">From <see cref="FrustaDeviceDef.Default"/>, then edited: its Hand set to an id from
        /// <see cref="CreateHand"/>.</param>
        /// <returns>The open glove; dispose it to close it (disposing the world closes it too).</returns>
        /// <exception cref="FrustaException"><see cref="FrustaResult.OutOfRange"/> for a malformed URI or a def
        /// value out of range; <see cref="FrustaResult.NullId"/> or <see cref="FrustaResult.StaleId"/> for a
        /// def whose Hand is not one of this world's; <see cref="FrustaResult.Io"/> for a glove absent at open
        /// (not a retry); <see cref="FrustaResult.WrongState"/> when the hand already has a glove; the native
        /// message names the problem.</exception>
        public Device CreateDevice(string uri, in FrustaDeviceDef def)
        {
            if (uri == null) throw new ArgumentNullException(nameof(uri));
            int max = Utf8.MaxBytes(uri);
            Span<byte> text = max <= Utf8.StackLimit ? stackalloc byte[max] : new byte[max];
            Utf8.Encode(uri, text, nameof(uri));
            var device = new DeviceHandle();
            FrustaDeviceId id;
            using (new HandleUse(handle))
            {
                FrustaResult r;
                fixed (byte* u = text)
                fixed (FrustaDeviceDef* d = &def)
                    r = Native.frusta_create_device(handle.Id, u, d, &id);
                device.Own(handle, r, id, "frusta_create_device");
            }
            return new Device(this, device, uri, def.Hand);
        }

        unsafe delegate FrustaResult LatchedRead<TKey, T>(FrustaWorldId world, TKey key, T* output)
            where TKey : unmanaged where T : unmanaged;

        // one part of the latched step into output, under the handle and the read gate as every
        // read of it; allocation-free with a lambda that captures nothing (the compiler caches it)
        void ReadLatched<TKey, T>(TKey key, ref T output, LatchedRead<TKey, T> read, string call)
            where TKey : unmanaged where T : unmanaged
        {
            using (new HandleUse(handle))
            lock (readGate)
            fixed (T* o = &output)
                Errors.Check(read(handle.Id, key, o), call);
        }

        // a destroy call takes the id alone, which names its world: refuse another world's here, as
        // every other call of this world does (world0: slot + 1 and the generation's low byte)
        void CheckBelongsHere(ushort world0, string what, string call)
        {
            if (world0 != 0 && world0 != (ushort)((handle.Id.Index1 & 0xff) | ((handle.Id.Generation & 0xff) << 8)))
                throw new FrustaException(FrustaResult.StaleId, $"{what} belongs to another world, or to a destroyed one", call);
        }

        /// <summary>Stop the own thread and destroy the world with its objects
        /// (<c>frusta_destroy_world</c>); waits for calls in flight on other threads. Safe to call twice.</summary>
        public void Dispose()
        {
            handle.Dispose();
            running = false;
        }
    }

    /// <summary>
    /// One step of a world copied out by <see cref="World.ReadSnapshot"/>: its state, every hand
    /// of the world it shows and every such hand's contacts. Caller-owned and reused; not
    /// thread-safe itself (one per reader).
    /// </summary>
    public sealed class WorldSnapshot
    {
        internal FrustaWorldState state;
        internal FrustaWorldHand[] hands;
        internal FrustaHandId[] ids;
        internal FrustaWorldContact[][] contacts;
        internal int[] contactCounts;
        internal int handCount;

        /// <summary>An empty snapshot with room for <paramref name="handCapacity"/> hands of
        /// <paramref name="contactCapacity"/> contacts each; it grows if a step needs more.</summary>
        /// <param name="handCapacity">Hands, &gt;= 0.</param>
        /// <param name="contactCapacity">Contacts per hand, &gt;= 0.</param>
        public WorldSnapshot(int handCapacity, int contactCapacity)
        {
            if (handCapacity < 0) throw new ArgumentOutOfRangeException(nameof(handCapacity));
            if (contactCapacity < 0) throw new ArgumentOutOfRangeException(nameof(contactCapacity));
            hands = new FrustaWorldHand[handCapacity];
            ids = new FrustaHandId[handCapacity];
            contacts = new FrustaWorldContact[handCapacity][];
            contactCounts = new int[handCapacity];
            for (int h = 0; h < handCapacity; ++h) contacts[h] = new FrustaWorldContact[contactCapacity];
        }

        /// <summary>The step's state (step count, time, timings).</summary>
        public ref readonly FrustaWorldState State => ref state;

        /// <summary>The world's hands the step shows (<see cref="World.Hands"/> at the read, but a hand
        /// created after the step).</summary>
        public int HandCount => handCount;

        /// <summary>The id of one hand of the step.</summary>
        /// <param name="hand">0..HandCount-1, in the world's creation order.</param>
        /// <returns>The hand's id.</returns>
        public FrustaHandId GetHandId(int hand)
        {
            if ((uint)hand >= (uint)handCount) throw new ArgumentOutOfRangeException(nameof(hand));
            return ids[hand];
        }

        /// <summary>One hand of the step.</summary>
        /// <param name="hand">0..HandCount-1, in the world's creation order (<see cref="GetHandId"/>).</param>
        /// <returns>A read-only reference into the snapshot, valid until the next ReadSnapshot into it.</returns>
        public ref readonly FrustaWorldHand GetHand(int hand)
        {
            if ((uint)hand >= (uint)handCount) throw new ArgumentOutOfRangeException(nameof(hand));
            return ref hands[hand];
        }

        /// <summary>One hand's contacts in the step.</summary>
        /// <param name="hand">0..HandCount-1, in the world's creation order (<see cref="GetHandId"/>).</param>
        /// <returns>A read-only view into the snapshot, valid until the next ReadSnapshot into it.</returns>
        public ReadOnlySpan<FrustaWorldContact> GetContacts(int hand)
        {
            if ((uint)hand >= (uint)handCount) throw new ArgumentOutOfRangeException(nameof(hand));
            return new ReadOnlySpan<FrustaWorldContact>(contacts[hand], 0, contactCounts[hand]);
        }

        internal void EnsureHands(int count)
        {
            if (count <= hands.Length) return;
            int old = hands.Length;
            int capacity = old > 0 ? contacts[0].Length : 0;
            Array.Resize(ref hands, count);
            Array.Resize(ref ids, count);
            Array.Resize(ref contacts, count);
            Array.Resize(ref contactCounts, count);
            for (int h = old; h < count; ++h) contacts[h] = new FrustaWorldContact[capacity];
        }

        internal void EnsureContacts(int hand, int count)
        {
            if (count > contacts[hand].Length) contacts[hand] = new FrustaWorldContact[count];
        }
    }
}
