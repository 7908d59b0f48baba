// SPDX-License-Identifier: MIT
// Hand Demo: a right hand closes over a ball resting on a box. Add this component to an
// empty GameObject in a new scene and press Play; a Frusta Hand Mesh draws the graphic
// hand, and the scene view shows its segments, joint balls and contacts (select the
// hand). The objects are Unity primitives baked into sphere trees at start.
//
// With "Replay Glove Recording" set, a Frusta Glove Device drives the hand instead: it
// replays demo_glove.frrec (next to this script; the demo hand of frusta_demo as a glove
// with a tracker would send it, Frusta's binary profile at 100 Hz) in a loop, through the
// same path a real glove takes. The hand slides a fingertip along a box and pinches a
// tile placed where the recording expects them.
using System.Collections.Generic;
using System.IO;
using Frusta.Binding;
using Frusta.Unity;
using UnityEngine;

namespace Frusta.Samples
{
    public sealed class HandDemo : MonoBehaviour
    {
        [Tooltip("Seconds for the hand to close, and again to open.")]
        [SerializeField] float cycleSeconds = 3f;
        [Tooltip("Drive the hand from the bundled glove recording (replayed in a loop) instead of the scripted grasp.")]
        [SerializeField] bool replayGloveRecording;
        [Tooltip("The recording to replay. Empty: demo_glove.frrec among the project's assets (Editor), " +
                 "or in StreamingAssets (player).")]
        [SerializeField] string recordingPath = "";

        FrustaWorldBehaviour world;
        FrustaHand hand;
        FrustaGloveDevice glove;
        readonly List<(Transform view, FrustaObjectId id)> objects = new List<(Transform, FrustaObjectId)>();
        readonly double[] angles = new double[FrustaConstants.HandJointCount];
        FrustaObjectState state;

        void Awake()
        {
            world = new GameObject("Frusta World").AddComponent<FrustaWorldBehaviour>();
            var handObject = new GameObject("Right Hand");
            // inactive while its components are set up: a glove opens only once told where
            handObject.SetActive(false);
            handObject.transform.SetParent(world.transform, false);
            hand = handObject.AddComponent<FrustaHand>();
            // the graphic hand drawn as its solids: no rig needed
            handObject.AddComponent<FrustaHandMesh>();

            if (replayGloveRecording)
            {
                glove = handObject.AddComponent<FrustaGloveDevice>();
                glove.Hand = hand;
                glove.Uri = $"replay:{Recording()}?speed=1&loop=1";
                glove.StateChanged.AddListener((before, now) => Debug.Log($"Frusta glove: {before} -> {now}", glove));
                handObject.SetActive(true);

                // the recording's objects, at the poses of samples/data/demo_glove.csv. Its world is
                // Frusta's z-up frame, which a glove's tracker shares: the camera looks at it with
                // Frusta's +z as up. (Its marble, carried and dropped by the host on a schedule, is
                // left out: here the fingers pinch the air there.)
                AddPrimitive(PrimitiveType.Cube, new FrustaPose(new Vector3d(0.175, 0.284, -0.045), Quaterniond.Identity),
                             new Vector3d(0.10, 0.06, 0.04));
                AddPrimitive(PrimitiveType.Cube, new FrustaPose(new Vector3d(0.123276, 0.529578, -0.050322),
                                                                new Quaterniond(-0.224914496, 0.881724078, 0.0, 0.414700035)),
                             new Vector3d(0.03, 0.03, 0.004));
                Camera view = Camera.main;
                if (view != null)
                {
                    Vector3 centre = new Vector3d(0.1, 0.26, 0.0).ToUnityVector();
                    view.transform.position = new Vector3d(0.55, 0.26, 0.35).ToUnityVector();
                    view.transform.LookAt(centre, new Vector3d(0, 0, 1).ToUnityVector());
                    view.nearClipPlane = 0.01f;
                }
                return;
            }

            // palm down, fingers along +z (Unity), above the objects
            handObject.transform.SetPositionAndRotation(new Vector3(0, 0.08f, -0.12f), Quaternion.Euler(90, -90, 0));
            handObject.SetActive(true);
            AddPrimitive(PrimitiveType.Cube, new Vector3(0, 0, 0), new Vector3(0.2f, 0.04f, 0.2f), dynamic: false);
            AddPrimitive(PrimitiveType.Sphere, new Vector3(0, 0.045f, 0.05f), new Vector3(0.05f, 0.05f, 0.05f), dynamic: false);
        }

        string Recording()
        {
            if (!string.IsNullOrEmpty(recordingPath)) return Path.GetFullPath(recordingPath);
#if UNITY_EDITOR
            // wherever the Package Manager copied the sample to
            foreach (string guid in UnityEditor.AssetDatabase.FindAssets("demo_glove"))
            {
                string path = UnityEditor.AssetDatabase.GUIDToAssetPath(guid);
                if (path.EndsWith(".frrec")) return Path.GetFullPath(path);
            }
#endif
            return Path.Combine(Application.streamingAssetsPath, "demo_glove.frrec");
        }

        // a kinematic object placed in Frusta's frame; size in metres along the object's axes
        void AddPrimitive(PrimitiveType type, in FrustaPose pose, Vector3d size)
        {
            GameObject view = GameObject.CreatePrimitive(type);
            Destroy(view.GetComponent<Collider>());
            view.transform.SetFrustaPose(pose);
            // the z flip turns lengths into lengths
            view.transform.localScale = new Vector3((float)size.X, (float)size.Y, (float)size.Z);
            Bake(view, view.transform.localScale, dynamic: false);
        }

        void AddPrimitive(PrimitiveType type, Vector3 position, Vector3 size, bool dynamic)
        {
            GameObject view = GameObject.CreatePrimitive(type);
            Destroy(view.GetComponent<Collider>());
            view.transform.SetPositionAndRotation(position, Quaternion.identity);
            view.transform.localScale = size;
            Bake(view, size, dynamic);
        }

        void Bake(GameObject view, Vector3 size, bool dynamic)
        {
            view.GetComponent<MeshFilter>().sharedMesh.ToFrustaMesh(size, out float[] vertices, out int[] indices);
            FrustaBakeDef bake = FrustaBakeDef.Default;
            bake.TargetError = 0.001;
            bake.ErrorSamples = 10000;
            using (SphereTree tree = SphereTree.Bake(vertices, indices, bake))
            {
                FrustaObjectDef def = FrustaObjectDef.Default;
                def.Pose = view.transform.ToFrustaPose();
                def.Dynamic = dynamic;
                objects.Add((view.transform, world.World.CreateObject(tree, def)));
            }
        }

        void Update()
        {
            if (glove != null) return; // the recording moves the fingers
            // a grasp: flex every finger joint by up to 1.2 rad and back
            float t = Mathf.PingPong(Time.time / cycleSeconds, 1f);
            for (int j = 0; j < angles.Length; ++j) angles[j] = j % 4 == 0 ? 0 : 1.2 * t;
            hand.SetJointAngles(angles);
        }

        void LateUpdate()
        {
            foreach (var (view, id) in objects)
            {
                try
                {
                    world.World.GetObject(id, ref state);
                    view.SetFrustaPose(state.Pose);
                }
                catch (FrustaException) { /* not in the latched step yet */ }
            }
        }
    }
}
