// SPDX-License-Identifier: MIT
using System.IO;
using Frusta.Binding;
using UnityEngine;

namespace Frusta.Unity
{
    /// <summary>
    /// An object of a <see cref="FrustaWorldBehaviour"/> with a baked sphere tree as its shape. Its
    /// colliders stay as they are for everything else (PhysX, raycasts, triggers): Frusta's hands
    /// touch the tree, the rest of the scene the colliders. One owner moves the object:
    /// <list type="bullet">
    /// <item>Kinematic in Frusta (the default): Unity moves it (animation, scripts, or a
    /// non-kinematic Rigidbody, i.e. PhysX), Frusta follows; with a non-kinematic Rigidbody the
    /// hands' reaction wrench is applied to it each FixedUpdate, the force at its centre of mass and
    /// the torque moved there from the object's origin (Frusta's torque is about the origin).</item>
    /// <item>Dynamic in Frusta: Frusta moves it; a Rigidbody on it is made kinematic (PhysX must not
    /// move it too; the inspector warns) and is moved with MovePosition/MoveRotation, so what it
    /// pushes in PhysX is pushed.</item>
    /// </list>
    /// </summary>
    [AddComponentMenu("Frusta/Frusta Sphere Tree Object")]
    public sealed class FrustaSphereTreeObject : MonoBehaviour
    {
        [Tooltip("The world the object belongs to. Empty: the Frusta World above it, else the scene's.")]
        [SerializeField] FrustaWorldBehaviour world;
        [Tooltip("An imported .frtree asset.")]
        [SerializeField] FrustaSphereTreeAsset tree;
        [Tooltip("Or a .frtree path: absolute, or relative to StreamingAssets.")]
        [SerializeField] string treePath = "";
        [Tooltip("Frusta moves the object (its dynamics; a Rigidbody on it is made kinematic); off: Unity moves it.")]
        [SerializeField] bool dynamic;
        [Tooltip("Contact stiffness, N/m, per object axis.")]
        [SerializeField] Vector3 stiffness = new Vector3(400, 400, 400);
        [Tooltip("Coulomb friction coefficient of the hand on this object.")]
        [SerializeField, Range(0, 2)] float friction = 0.6f;
        [Tooltip("kg; a Rigidbody's mass wins.")]
        [SerializeField] float mass = 0.1f;
        [Tooltip("Draw the tree's leaf spheres when the object is selected.")]
        [SerializeField] bool drawLeaves;

        FrustaObjectId id;
        Rigidbody body;
        FrustaObjectState latest;
        Vector3 sentPosition;
        Quaternion sentRotation;
        FrustaSphere[] leaves;

        /// <summary>The object's id in the world (null before Awake).</summary>
        public FrustaObjectId Id => id;

        /// <summary>The latest state: pose, velocities and the hands' reaction wrench (Frusta frame).</summary>
        public ref readonly FrustaObjectState State => ref latest;

        void Awake()
        {
            if (world == null) world = GetComponentInParent<FrustaWorldBehaviour>();
            if (world == null) world = FindAnyObjectByType<FrustaWorldBehaviour>();
            body = GetComponent<Rigidbody>();
            if (dynamic && body != null && !body.isKinematic)
            {
                Debug.LogWarning($"{name}: Frusta moves this dynamic object, so its Rigidbody is made kinematic.", this);
                body.isKinematic = true;
            }
            if (world == null || world.World == null)
            {
                Debug.LogError("FrustaSphereTreeObject needs a FrustaWorldBehaviour in the scene.", this);
                enabled = false;
                return;
            }
            SphereTree shape;
            try
            {
                shape = tree != null ? tree.Load() : SphereTree.Load(ResolvePath(treePath));
            }
            catch (FrustaException e)
            {
                Debug.LogError($"Frusta could not load the sphere tree of {name}: {e.NativeMessage}", this);
                enabled = false;
                return;
            }
            using (shape)
            {
                FrustaObjectDef def = FrustaObjectDef.Default;
                def.Pose = transform.ToFrustaPose();
                def.Dynamic = dynamic;
                // the object frame's axes: z flips, so the stiffness' components keep their axes
                def.Stiffness = new Vector3d(stiffness.x, stiffness.y, stiffness.z);
                def.Friction = friction;
                def.Mass = body != null ? body.mass : mass;
                id = world.World.CreateObject(shape, def);
                if (drawLeaves)
                {
                    leaves = new FrustaSphere[shape.LeafCount];
                    shape.GetLeaves(leaves);
                }
            }
            sentPosition = transform.position;
            sentRotation = transform.rotation;
        }

        static string ResolvePath(string path) =>
            Path.IsPathRooted(path) ? path : Path.Combine(Application.streamingAssetsPath, path);

        void OnEnable()
        {
            if (world != null) world.Latched += OnLatched;
        }

        void OnDisable()
        {
            if (world != null) world.Latched -= OnLatched;
        }

        void OnLatched(FrustaWorldBehaviour source)
        {
            World w = source.World;
            try
            {
                w.GetObject(id, ref latest);
            }
            catch (FrustaException e) when (e.Result == FrustaResult.StaleId)
            {
                return; // added after the latched step: present from the next one
            }
            if (dynamic)
            {
                // a Rigidbody is moved in FixedUpdate, through PhysX
                if (body == null) transform.SetFrustaPose(latest.Pose);
            }
            else if (transform.position != sentPosition || transform.rotation != sentRotation)
            {
                // Unity moved it: tell Frusta (queued for the next step)
                w.SetObjectPose(id, transform.ToFrustaPose());
                sentPosition = transform.position;
                sentRotation = transform.rotation;
            }
        }

        void FixedUpdate()
        {
            if (body == null || id.IsNull) return;
            if (dynamic)
            {
                body.MovePosition(latest.Pose.Position.ToUnityVector());
                body.MoveRotation(latest.Pose.Rotation.ToUnityRotation());
                return;
            }
            if (body.isKinematic) return;
            // Frusta's torque is about the object's origin (its pose position); PhysX takes it about
            // the body's centre of mass
            Vector3d force = latest.ReactionForce;
            Vector3d torque = Wrench.TorqueAbout(latest.ReactionTorque, force, latest.Pose.Position,
                                                 body.worldCenterOfMass.ToFrustaVector());
            body.AddForce(force.ToUnityVector(), ForceMode.Force);
            body.AddTorque(torque.ToUnityAxial(), ForceMode.Force);
        }

        void OnDestroy()
        {
            World w = world != null ? world.World : null;
            if (w != null && w.IsValid && !id.IsNull)
            {
                try { w.DestroyObject(id); }
                catch (FrustaException) { /* already gone with its world */ }
            }
        }

        void OnDrawGizmosSelected()
        {
            if (leaves == null) return;
            Gizmos.color = new Color(0.3f, 0.7f, 1f, 0.5f);
            FrustaPose pose = transform.ToFrustaPose();
            foreach (FrustaSphere s in leaves)
                Gizmos.DrawWireSphere(pose.TransformPoint(s.Center).ToUnityVector(), (float)s.Radius);
        }
    }
}
