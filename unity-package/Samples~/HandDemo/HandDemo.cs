// SPDX-License-Identifier: MIT
// Hand Demo: a right hand closes over a ball resting on a box. Add this component to an
// empty GameObject in a new scene and press Play; the scene view shows the hand's
// segments, joint balls and contacts (select the hand). The objects are Unity primitives
// baked into sphere trees at start, so the sample needs no asset files.
using System.Collections.Generic;
using Frusta.Binding;
using Frusta.Unity;
using UnityEngine;

namespace Frusta.Samples
{
    public sealed class HandDemo : MonoBehaviour
    {
        [Tooltip("Seconds for the hand to close, and again to open.")]
        [SerializeField] float cycleSeconds = 3f;

        FrustaWorldBehaviour world;
        FrustaHand hand;
        readonly List<(Transform view, FrustaObjectId id)> objects = new List<(Transform, FrustaObjectId)>();
        readonly double[] angles = new double[FrustaConstants.HandJointCount];
        FrustaObjectState state;

        void Awake()
        {
            world = new GameObject("Frusta World").AddComponent<FrustaWorldBehaviour>();
            var handObject = new GameObject("Right Hand");
            handObject.transform.SetParent(world.transform, false);
            // palm down, fingers along +z (Unity), above the objects
            handObject.transform.SetPositionAndRotation(new Vector3(0, 0.08f, -0.12f), Quaternion.Euler(90, -90, 0));
            hand = handObject.AddComponent<FrustaHand>();

            AddPrimitive(PrimitiveType.Cube, new Vector3(0, 0, 0), new Vector3(0.2f, 0.04f, 0.2f), dynamic: false);
            AddPrimitive(PrimitiveType.Sphere, new Vector3(0, 0.045f, 0.05f), new Vector3(0.05f, 0.05f, 0.05f), dynamic: false);
        }

        void AddPrimitive(PrimitiveType type, Vector3 position, Vector3 size, bool dynamic)
        {
            GameObject view = GameObject.CreatePrimitive(type);
            Destroy(view.GetComponent<Collider>());
            view.transform.SetPositionAndRotation(position, Quaternion.identity);
            view.transform.localScale = size;
            Mesh mesh = view.GetComponent<MeshFilter>().sharedMesh;
            var vertices = new float[mesh.vertexCount * 3];
            Vector3[] v = mesh.vertices;
            for (int i = 0; i < v.Length; ++i)
            {
                Vector3d p = Vector3.Scale(v[i], size).ToFrustaVector();
                vertices[3 * i] = (float)p.X;
                vertices[3 * i + 1] = (float)p.Y;
                vertices[3 * i + 2] = (float)p.Z;
            }
            int[] indices = mesh.triangles;
            CoordinateConversion.FlipWinding(indices);
            FrustaBakeDef bake = FrustaBakeDef.Default;
            bake.TargetError = 0.001;
            bake.ErrorSamples = 10000;
            using (SphereTree tree = SphereTree.Bake(vertices, indices, bake))
            {
                FrustaObjectDef def = FrustaObjectDef.Default;
                def.Pose = view.transform.ToFrustaPose();
                def.Dynamic = dynamic;
                objects.Add((view.transform, world.World.AddObject(tree, def)));
            }
        }

        void Update()
        {
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
