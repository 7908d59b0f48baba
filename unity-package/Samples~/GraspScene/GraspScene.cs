// SPDX-License-Identifier: MIT
// Grasp Scene: open GraspScene.unity and press Play. A right hand, played from the bundled glove
// recording, pinches a marble off its stand, carries it 15 cm up and 11 cm along, and lets it
// fall onto the table, where it rests; then the hand slides a fingertip along a box and pinches
// a tile. The recording starts again after a pause.
//
// The scene file holds a camera, a light and this component; everything else is built here at
// Awake from what the sample ships: the objects' sphere trees (Resources/FrustaGraspScene/*.frtree,
// imported as FrustaSphereTreeAsset: baked by samples/objects, nothing is baked at run time) and
// the recording (Resources/FrustaGraspScene/demo_glove.bytes, samples/data/demo_glove.frrec).
// What happens in the world is GraspScenario's, in plain C#, which the dotnet tests run step
// for step as this component does: this component only steps it by the frame time and shows it.
using System;
using System.Collections.Generic;
using Frusta.Binding;
using Frusta.Unity;
using UnityEngine;

namespace Frusta.Samples
{
    /// <summary>Builds and runs the Grasp Scene (see the file's header).</summary>
    [DefaultExecutionOrder(-200)]  // steps the world before the Frusta World latches it (-100)
    public sealed class GraspScene : MonoBehaviour
    {
        [Tooltip("Start the recording again, marble back on its stand, after it ends.")]
        [SerializeField] bool loop = true;
        [Tooltip("Drive the hand from XR Hands (com.unity.xr.hands installed, a hand tracker running) instead of the recording.")]
        [SerializeField] bool trackedHand;
        [Tooltip("The objects' material. Empty: the default material Unity's primitives come with.")]
        [SerializeField] Material objectMaterial;

        const string Folder = "FrustaGraspScene/";

        FrustaWorldBehaviour world;
        FrustaHand hand;
        GraspScenario scenario;
        readonly List<(Transform view, FrustaObjectId id)> views = new List<(Transform, FrustaObjectId)>();
        FrustaObjectState state;

        void Awake()
        {
            // the world, stepped by the scenario (below) and latched by its component each frame
            var worldObject = new GameObject("Frusta World");
            worldObject.SetActive(false);  // configured before it wakes
            world = worldObject.AddComponent<FrustaWorldBehaviour>();
            world.RunOnOwnThread = false;
            world.StepInUpdate = false;
            world.Gravity = GraspScenario.Gravity.ToUnityVector();
            worldObject.SetActive(true);

            var recordingAsset = Resources.Load<TextAsset>(Folder + "demo_glove");
            if (recordingAsset == null)
            {
                Debug.LogError($"Grasp Scene: Resources/{Folder}demo_glove.bytes is missing.", this);
                enabled = false;
                return;
            }
            GloveRecording recording = GloveRecording.Parse(recordingAsset.bytes, "demo_glove.bytes");

            // the hand: a Frusta Hand of the default size, drawn by a Frusta Hand Mesh
            var handObject = new GameObject("Right Hand");
            handObject.SetActive(false);
            handObject.transform.SetParent(worldObject.transform, false);
            hand = handObject.AddComponent<FrustaHand>();
            handObject.AddComponent<FrustaHandMesh>();
            Type tracked = trackedHand ? Type.GetType("Frusta.Unity.FrustaXRHandsInput, Frusta.XRHands") : null;
            if (tracked != null) handObject.AddComponent(tracked);  // it takes the hand's input
            else hand.InputOwner = this;                            // the recording's, fed below
            if (trackedHand && tracked == null)
                Debug.LogWarning("Grasp Scene: Frusta XR Hands Input is not compiled (install com.unity.xr.hands 1.1 or " +
                                 "later): the recording drives the hand.", this);
            handObject.SetActive(true);  // joins the world

            try
            {
                scenario = new GraspScenario(world.World, hand.Id, LoadTree, recording) { Loop = loop };
            }
            catch (Exception e) when (e is FrustaException || e is ArgumentException)
            {
                Debug.LogError($"Grasp Scene: {e.Message}", this);
                enabled = false;
                return;
            }
            scenario.DriveHand = hand.InputOwner == (UnityEngine.Object)this;
            for (int i = 0; i < GraspScenario.Objects.Count; ++i) AddView(i);
        }

        static byte[] LoadTree(string name)
        {
            FrustaSphereTreeAsset asset = Resources.Load<FrustaSphereTreeAsset>(Folder + name);
            return asset != null ? asset.Data : null;
        }

        // a primitive (or a generated octahedron) where the object is, the size of its tree's mesh
        void AddView(int index)
        {
            GraspSceneObject o = GraspScenario.Objects[index];
            GameObject view;
            if (o.Shape == GraspShape.Octahedron)
            {
                view = new GameObject(o.Name, typeof(MeshFilter), typeof(MeshRenderer));
                view.GetComponent<MeshFilter>().sharedMesh = Octahedron((float)o.Size.X);
                view.GetComponent<MeshRenderer>().sharedMaterial = objectMaterial != null ? objectMaterial : DefaultMaterial();
            }
            else
            {
                view = GameObject.CreatePrimitive(o.Shape == GraspShape.Box ? PrimitiveType.Cube : PrimitiveType.Sphere);
                view.name = o.Name;
                Destroy(view.GetComponent<Collider>());  // Frusta's trees are what the hand touches
                // the z flip keeps lengths: the object's axes keep their extents
                view.transform.localScale = o.Shape == GraspShape.Box
                    ? new Vector3((float)o.Size.X, (float)o.Size.Y, (float)o.Size.Z)
                    : Vector3.one * (float)o.Size.X;
                if (objectMaterial != null) view.GetComponent<MeshRenderer>().sharedMaterial = objectMaterial;
            }
            view.transform.SetFrustaPose(GraspScenario.ToWorld(o.Pose));
            views.Add((view.transform, scenario.GetObjectId(index)));
        }

        Material defaultMaterial;

        // the material a primitive comes with, for the generated mesh too
        Material DefaultMaterial()
        {
            if (defaultMaterial != null) return defaultMaterial;
            GameObject probe = GameObject.CreatePrimitive(PrimitiveType.Cube);
            defaultMaterial = probe.GetComponent<MeshRenderer>().sharedMaterial;
            Destroy(probe);
            return defaultMaterial;
        }

        // six vertices on the axes at `radius` (as samples/objects' octahedron), flat-shaded
        static Mesh Octahedron(float radius)
        {
            Vector3[] v = { Vector3.right, Vector3.left, Vector3.up, Vector3.down, Vector3.forward, Vector3.back };
            int[][] faces = { new[] { 0, 2, 4 }, new[] { 2, 1, 4 }, new[] { 1, 3, 4 }, new[] { 3, 0, 4 },
                              new[] { 2, 0, 5 }, new[] { 1, 2, 5 }, new[] { 3, 1, 5 }, new[] { 0, 3, 5 } };
            var vertices = new List<Vector3>();
            var triangles = new List<int>();
            foreach (int[] f in faces)
            {
                // Unity's winding is clockwise seen from outside
                Vector3 a = v[f[0]] * radius, b = v[f[1]] * radius, c = v[f[2]] * radius;
                if (Vector3.Dot(Vector3.Cross(b - a, c - a), a + b + c) < 0) (b, c) = (c, b);
                triangles.Add(vertices.Count); vertices.Add(a);
                triangles.Add(vertices.Count); vertices.Add(b);
                triangles.Add(vertices.Count); vertices.Add(c);
            }
            var mesh = new Mesh { name = "Octahedron" };
            mesh.SetVertices(vertices);
            mesh.SetTriangles(triangles, 0);
            mesh.RecalculateNormals();
            mesh.RecalculateBounds();
            return mesh;
        }

        void Update()
        {
            if (scenario == null) return;
            // the recording's clock is the world's: catch up with the game's time, at most 100 ms
            // of world time a frame (a hitch slows the scene down rather than jumping it)
            scenario.DriveHand = hand.InputOwner == (UnityEngine.Object)this;
            scenario.AdvanceTo(scenario.Time + Time.deltaTime, (int)(0.1 * world.World.RateHz));
        }

        void LateUpdate()
        {
            if (scenario == null) return;
            foreach (var (view, id) in views)
            {
                try
                {
                    world.World.GetObject(id, ref state);
                    view.SetFrustaPose(state.Pose);
                }
                catch (FrustaException) { /* not in the latched step yet (no step this frame) */ }
            }
        }
    }
}
