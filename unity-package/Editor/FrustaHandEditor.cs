// SPDX-License-Identifier: MIT
using System;
using Frusta.Binding;
using Frusta.Unity;
using UnityEditor;
using UnityEngine;

namespace Frusta.Editor
{
    /// <summary>The hand's settings, buttons that map a skinned rig (a humanoid avatar's bones, or bones
    /// named after XR Hands' joints) with the axes computed, and a warning for every mapped bone that
    /// could not turn.</summary>
    [CustomEditor(typeof(FrustaHand))]
    public sealed class FrustaHandEditor : UnityEditor.Editor
    {
        string problem;

        /// <summary>The serialized fields, the mapping buttons, then the warnings.</summary>
        public override void OnInspectorGUI()
        {
            DrawDefaultInspector();
            var hand = (FrustaHand)target;
            EditorGUILayout.Space();
            EditorGUILayout.LabelField("Rig (map it in its rest pose: fingers straight)", EditorStyles.boldLabel);
            using (new EditorGUI.DisabledScope(Application.isPlaying))
            {
                if (GUILayout.Button(new GUIContent("Map From Humanoid Animator",
                        "The bones of the humanoid Animator above or below this hand, for its side.")))
                    problem = Map(hand, HumanoidBones(hand));
                if (GUILayout.Button(new GUIContent("Map From XR Hands Joint Names",
                        "Bones under this hand's root named after XR Hands' joints (R_IndexProximal, ...).")))
                    problem = Map(hand, XrHandsBones(hand));
            }
            if (problem != null) EditorGUILayout.HelpBox(problem, MessageType.Error);
            foreach (FrustaHand.BoneMapping b in hand.Bones)
            {
                if (b.bone == null)
                    EditorGUILayout.HelpBox($"A mapping of the {b.finger} finger's segment {b.segment} has no bone.", MessageType.Warning);
                else if (b.flexionAxis == Vector3.zero || (b.segment == 0 && b.abductionAxis == Vector3.zero))
                    EditorGUILayout.HelpBox($"{b.bone.name} has no {(b.flexionAxis == Vector3.zero ? "flexion" : "abduction")} axis: " +
                                            "it would never turn that way. Map the rig, or set the axis.", MessageType.Warning);
            }
        }

        static string Map(FrustaHand hand, (Transform wrist, Transform[] bones, string missing) rig)
        {
            if (rig.missing != null) return rig.missing;
            Undo.RecordObject(hand, "Map Frusta Hand Rig");
            string problem = hand.MapRig(rig.wrist, rig.bones);
            EditorUtility.SetDirty(hand);
            return problem;
        }

        static (Transform, Transform[], string) HumanoidBones(FrustaHand hand)
        {
            Animator animator = hand.GetComponentInParent<Animator>();
            if (animator == null) animator = hand.GetComponentInChildren<Animator>();
            if (animator == null || !animator.isHuman) return (null, null, "No humanoid Animator above or below this hand.");
            FrustaHandSide side = hand.BuildDef().Side;
            var bones = new Transform[FrustaConstants.HandSegmentCount];
            for (int k = 0; k < bones.Length; ++k)
            {
                var id = (HumanBodyBones)Enum.Parse(typeof(HumanBodyBones),
                    HandRig.HumanoidBoneName(side, (FrustaFinger)(k / 3), k % 3));
                bones[k] = animator.GetBoneTransform(id);
            }
            Transform wrist = animator.GetBoneTransform(side == FrustaHandSide.Right ? HumanBodyBones.RightHand : HumanBodyBones.LeftHand);
            return (wrist, bones, wrist == null ? "The avatar has no hand bone for this side." : null);
        }

        static (Transform, Transform[], string) XrHandsBones(FrustaHand hand)
        {
            FrustaHandSide side = hand.BuildDef().Side;
            Transform[] all = hand.transform.root.GetComponentsInChildren<Transform>(true);
            Transform Find(string joint)
            {
                foreach (Transform t in all)
                    if (HandRig.NamesXrHandsJoint(t.name, joint, side)) return t;
                return null;
            }
            var bones = new Transform[FrustaConstants.HandSegmentCount];
            for (int k = 0; k < bones.Length; ++k) bones[k] = Find(HandRig.XrHandsJointName((FrustaFinger)(k / 3), k % 3));
            Transform wrist = Find("Wrist");
            return (wrist, bones, wrist == null ? $"No bone named after XR Hands' Wrist for the {side} hand under {hand.transform.root.name}." : null);
        }
    }
}
