// SPDX-License-Identifier: MIT
using Frusta.Binding;
using Frusta.Unity;
using UnityEditor;
using UnityEngine;

namespace Frusta.Editor
{
    /// <summary>The glove's settings, then its live status and counters, read-only (repainted every
    /// frame in Play mode).</summary>
    [CustomEditor(typeof(FrustaGloveDevice))]
    public sealed class FrustaGloveDeviceEditor : UnityEditor.Editor
    {
        /// <summary>Repaint while playing: the status changes every frame.</summary>
        public override bool RequiresConstantRepaint() => Application.isPlaying;

        /// <summary>The serialized fields, then the status section.</summary>
        public override void OnInspectorGUI()
        {
            DrawDefaultInspector();
            var glove = (FrustaGloveDevice)target;
            EditorGUILayout.Space();
            EditorGUILayout.LabelField("Status", EditorStyles.boldLabel);
            if (!glove.IsOpen)
            {
                EditorGUILayout.LabelField("State", Application.isPlaying ? "Closed" : "Closed (opens in Play mode)");
                return;
            }
            FrustaDeviceStatus s = glove.Status;
            EditorGUILayout.LabelField("State", s.State.ToString());
            EditorGUILayout.LabelField("Output held by", s.Watchdog.ToString());
            EditorGUILayout.LabelField("Outputs", $"{s.Outputs}, {s.Fingers} fingers{(s.HasPalmPose ? ", tracked palm" : "")}");
            EditorGUILayout.LabelField("Protocol version", s.ProtocolVersion.ToString());
            EditorGUILayout.LabelField("Input rate", $"{s.InputRateHz:0.0} Hz, last sample " +
                                       (s.LastSampleAgeS < 0 ? "none yet" : $"{s.LastSampleAgeS * 1000:0.0} ms ago"));
            EditorGUILayout.LabelField("Output rate", $"{s.OutputRateHz:0.0} Hz");
            EditorGUILayout.LabelField("Frames", $"{s.FramesOk} ok, {s.FramesCorrupt} corrupt, {s.FramesTruncated} truncated, " +
                                       $"{s.FramesOutOfRange} out of range, {s.SamplesRejected} rejected");
            EditorGUILayout.LabelField("Commands", $"{s.CommandsSent} sent, {s.CommandsDropped} dropped");
            EditorGUILayout.LabelField("Connection", $"{s.Disconnects} disconnects, {s.Reconnects} reconnects, " +
                                       $"{s.WatchdogTrips} watchdog trips");
            EditorGUILayout.LabelField("Limits", $"{s.MaxFingerResistance:0.##} N resistance, {s.MaxFingertipForce:0.##} N " +
                                       $"fingertip, {s.MaxJointTorque:0.###} N m joint");
            for (int f = 0; f < FrustaConstants.FingerCount; ++f)
            {
                var finger = (FrustaFinger)f;
                Vector3d force = s.GetFingertipForce(finger);
                EditorGUILayout.LabelField(finger.ToString(), $"{s.GetFingerResistance(finger):0.00} N resistance, " +
                                           $"fingertip ({force.X:0.00}, {force.Y:0.00}, {force.Z:0.00}) N");
            }
            if (s.RecordingFailed) EditorGUILayout.HelpBox("The disk refused the recording; the glove runs on.", MessageType.Warning);
        }
    }
}
