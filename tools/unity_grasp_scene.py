#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the Unity package's Grasp Scene sample (unity-package/Samples~/GraspScene/) from what
the repository builds, so that nothing in it is made by hand:

  Resources/FrustaGraspScene/<tree>.frtree   copies of OBJECTS_DIR's trees (the frusta_sample_objects
                                             target's output, build/samples/objects), the ones
                                             GraspScenario.cs names
  Resources/FrustaGraspScene/demo_glove.bytes  samples/data/demo_glove.frrec (.bytes: a TextAsset)
  GraspScene.unity                           a camera framing the table, a light, and one GameObject
                                             with the GraspScene component (which builds the rest)
  *.meta                                     for every file and folder of the sample: GUIDs are the
                                             md5 of the package path, as tests/dotnet/unity_meta.py's

Usage: tools/unity_grasp_scene.py [--check] OBJECTS_DIR
  --check   write nothing: fail, naming each file, unless the sample holds exactly what this
            would write; and check the scene (every fileID it references is defined in it, its
            anchors are unique, every script GUID it or an importer names is a .meta's of the
            package). ctest runs it as samples.unity_grasp_scene_is_current.

The scene holds only what is safe to write without a Unity editor: GameObject, Camera, Light,
AudioListener, MonoBehaviour and the settings documents as a Unity 2022.2 project saves them,
Transform (serializedVersion 2) with the root order in a SceneRoots document, as 2022.2 and
later write it (unity-package/README.md names the scenes read for this). It was never opened
in a Unity editor here."""
import math
import os
import re
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
PACKAGE = os.path.join(ROOT, "unity-package")
SAMPLE_REL = "Samples~/GraspScene"
SAMPLE = os.path.join(PACKAGE, SAMPLE_REL)
RESOURCES_REL = "Resources/FrustaGraspScene"
RECORDING = os.path.join(ROOT, "samples", "data", "demo_glove.frrec")
sys.path.insert(0, os.path.join(ROOT, "tests", "dotnet"))
import unity_meta  # noqa: E402  (the package's own .meta rule: GUIDs and importers)
from unity_meta import TAIL, guid_of  # noqa: E402


def meta_guid(path):
    with open(path + ".meta") as f:
        m = re.search(r"^guid: ([0-9a-f]{32})$", f.read(), re.M)
    if not m:
        sys.exit(f"unity_grasp_scene: {path}.meta has no guid")
    return m.group(1)


def trees():
    """The tree names GraspScenario.cs loads, in its order."""
    with open(os.path.join(SAMPLE, "GraspScenario.cs")) as f:
        names = re.findall(r'Tree = "(\w+)"', f.read())
    if not names:
        sys.exit("unity_grasp_scene: GraspScenario.cs names no tree")
    return list(dict.fromkeys(names))


def meta(rel, is_dir):
    """unity_meta's .meta, and those of the scene and the trees it does not write."""
    ext = os.path.splitext(rel)[1]
    head = f"fileFormatVersion: 2\nguid: {guid_of(rel)}\n"
    if ext == ".unity" and not is_dir:
        return head + "DefaultImporter:\n  externalObjects: {}\n" + TAIL
    if ext == ".frtree" and not is_dir:
        # the package's FrustaSphereTreeImporter imports it
        importer = meta_guid(os.path.join(PACKAGE, "Editor", "FrustaSphereTreeImporter.cs"))
        return head + ("ScriptedImporter:\n  internalIDToNameTable: []\n  externalObjects: {}\n  serializedVersion: 2\n"
                       + TAIL + f"  script: {{fileID: 11500000, guid: {importer}, type: 3}}\n")
    return unity_meta.meta(rel, is_dir)  # .md, .bytes: text


def look_rotation(forward, up=(0.0, 1.0, 0.0)):
    """Unity's Quaternion.LookRotation: +z along forward, +y towards up (x, y, z, w)."""
    def norm(v):
        n = math.sqrt(sum(c * c for c in v))
        return tuple(c / n for c in v)

    def cross(a, b):
        return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
    z = norm(forward)
    x = norm(cross(up, z))
    y = cross(z, x)
    m00, m01, m02 = x[0], y[0], z[0]
    m10, m11, m12 = x[1], y[1], z[1]
    m20, m21, m22 = x[2], y[2], z[2]
    trace = m00 + m11 + m22
    if trace > 0:
        s = 2.0 * math.sqrt(trace + 1.0)
        q = ((m21 - m12) / s, (m02 - m20) / s, (m10 - m01) / s, 0.25 * s)
    elif m00 > m11 and m00 > m22:
        s = 2.0 * math.sqrt(1.0 + m00 - m11 - m22)
        q = (0.25 * s, (m01 + m10) / s, (m02 + m20) / s, (m21 - m12) / s)
    elif m11 > m22:
        s = 2.0 * math.sqrt(1.0 + m11 - m00 - m22)
        q = ((m01 + m10) / s, 0.25 * s, (m12 + m21) / s, (m02 - m20) / s)
    else:
        s = 2.0 * math.sqrt(1.0 + m22 - m00 - m11)
        q = ((m02 + m20) / s, (m12 + m21) / s, 0.25 * s, (m10 - m01) / s)
    return q


def euler_hint(q):
    """Unity's inspector angles (ZXY order) of a rotation, degrees, for m_LocalEulerAnglesHint."""
    x, y, z, w = q
    sx = 2 * (w * x - y * z)
    ex = math.degrees(math.asin(max(-1.0, min(1.0, sx))))
    ey = math.degrees(math.atan2(2 * (w * y + x * z), 1 - 2 * (x * x + y * y)))
    ez = math.degrees(math.atan2(2 * (w * z + x * y), 1 - 2 * (x * x + z * z)))
    return ex, ey, ez


def num(v):
    """A float as Unity writes it: shortest form, no trailing .0."""
    r = round(v, 7)
    if r == 0:
        return "0"
    text = repr(r)
    return text[:-2] if text.endswith(".0") else text


def vec(v):
    return "{" + ", ".join(f"{k}: {num(c)}" for k, c in zip("xyzw", v)) + "}"


HEADER = """%YAML 1.1
%TAG !u! tag:unity3d.com,2011:
--- !u!29 &1
OcclusionCullingSettings:
  m_ObjectHideFlags: 0
  serializedVersion: 2
  m_OcclusionBakeSettings:
    smallestOccluder: 5
    smallestHole: 0.25
    backfaceThreshold: 100
  m_SceneGUID: 00000000000000000000000000000000
  m_OcclusionCullingData: {fileID: 0}
--- !u!104 &2
RenderSettings:
  m_ObjectHideFlags: 0
  serializedVersion: 9
  m_Fog: 0
  m_FogColor: {r: 0.5, g: 0.5, b: 0.5, a: 1}
  m_FogMode: 3
  m_FogDensity: 0.01
  m_LinearFogStart: 0
  m_LinearFogEnd: 300
  m_AmbientSkyColor: {r: 0.212, g: 0.227, b: 0.259, a: 1}
  m_AmbientEquatorColor: {r: 0.114, g: 0.125, b: 0.133, a: 1}
  m_AmbientGroundColor: {r: 0.047, g: 0.043, b: 0.035, a: 1}
  m_AmbientIntensity: 1
  m_AmbientMode: 0
  m_SubtractiveShadowColor: {r: 0.42, g: 0.478, b: 0.627, a: 1}
  m_SkyboxMaterial: {fileID: 10304, guid: 0000000000000000f000000000000000, type: 0}
  m_HaloStrength: 0.5
  m_FlareStrength: 1
  m_FlareFadeSpeed: 3
  m_HaloTexture: {fileID: 0}
  m_SpotCookie: {fileID: 10001, guid: 0000000000000000e000000000000000, type: 0}
  m_DefaultReflectionMode: 0
  m_DefaultReflectionResolution: 128
  m_ReflectionBounces: 1
  m_ReflectionIntensity: 1
  m_CustomReflection: {fileID: 0}
  m_Sun: {fileID: 0}
  m_IndirectSpecularColor: {r: 0, g: 0, b: 0, a: 1}
  m_UseRadianceAmbientProbe: 0
--- !u!157 &3
LightmapSettings:
  m_ObjectHideFlags: 0
  serializedVersion: 12
  m_GIWorkflowMode: 1
  m_GISettings:
    serializedVersion: 2
    m_BounceScale: 1
    m_IndirectOutputScale: 1
    m_AlbedoBoost: 1
    m_EnvironmentLightingMode: 0
    m_EnableBakedLightmaps: 0
    m_EnableRealtimeLightmaps: 0
  m_LightmapEditorSettings:
    serializedVersion: 12
    m_Resolution: 2
    m_BakeResolution: 40
    m_AtlasSize: 1024
    m_AO: 0
    m_AOMaxDistance: 1
    m_CompAOExponent: 1
    m_CompAOExponentDirect: 0
    m_ExtractAmbientOcclusion: 0
    m_Padding: 2
    m_LightmapParameters: {fileID: 0}
    m_LightmapsBakeMode: 1
    m_TextureCompression: 1
    m_FinalGather: 0
    m_FinalGatherFiltering: 1
    m_FinalGatherRayCount: 256
    m_ReflectionCompression: 2
    m_MixedBakeMode: 2
    m_BakeBackend: 1
    m_PVRSampling: 1
    m_PVRDirectSampleCount: 32
    m_PVRSampleCount: 512
    m_PVRBounces: 2
    m_PVREnvironmentSampleCount: 256
    m_PVREnvironmentReferencePointCount: 2048
    m_PVRFilteringMode: 1
    m_PVRDenoiserTypeDirect: 1
    m_PVRDenoiserTypeIndirect: 1
    m_PVRDenoiserTypeAO: 1
    m_PVRFilterTypeDirect: 0
    m_PVRFilterTypeIndirect: 0
    m_PVRFilterTypeAO: 0
    m_PVREnvironmentMIS: 1
    m_PVRCulling: 1
    m_PVRFilteringGaussRadiusDirect: 1
    m_PVRFilteringGaussRadiusIndirect: 5
    m_PVRFilteringGaussRadiusAO: 2
    m_PVRFilteringAtrousPositionSigmaDirect: 0.5
    m_PVRFilteringAtrousPositionSigmaIndirect: 2
    m_PVRFilteringAtrousPositionSigmaAO: 1
    m_ExportTrainingData: 0
    m_TrainingDataDestination: TrainingData
    m_LightProbeSampleCountMultiplier: 4
  m_LightingDataAsset: {fileID: 0}
  m_LightingSettings: {fileID: 0}
--- !u!196 &4
NavMeshSettings:
  serializedVersion: 2
  m_ObjectHideFlags: 0
  m_BuildSettings:
    serializedVersion: 3
    agentTypeID: 0
    agentRadius: 0.5
    agentHeight: 2
    agentSlope: 45
    agentClimb: 0.4
    ledgeDropHeight: 0
    maxJumpAcrossDistance: 0
    minRegionArea: 2
    manualCellSize: 0
    cellSize: 0.16666667
    manualTileSize: 0
    tileSize: 256
    buildHeightMesh: 0
    maxJobWorkers: 0
    preserveTilesOutsideBounds: 0
    debug:
      m_Flags: 0
  m_NavMeshData: {fileID: 0}
"""

OBJECT_HEAD = """  m_ObjectHideFlags: 0
  m_CorrespondingSourceObject: {fileID: 0}
  m_PrefabInstance: {fileID: 0}
  m_PrefabAsset: {fileID: 0}
"""


def game_object(anchor, name, components, tag="Untagged"):
    listed = "".join(f"  - component: {{fileID: {c}}}\n" for c in components)
    return (f"--- !u!1 &{anchor}\nGameObject:\n" + OBJECT_HEAD + "  serializedVersion: 6\n  m_Component:\n" + listed +
            f"  m_Layer: 0\n  m_Name: {name}\n  m_TagString: {tag}\n  m_Icon: {{fileID: 0}}\n  m_NavMeshLayer: 0\n"
            "  m_StaticEditorFlags: 0\n  m_IsActive: 1\n")


def transform(anchor, owner, position, rotation):
    return (f"--- !u!4 &{anchor}\nTransform:\n" + OBJECT_HEAD + f"  m_GameObject: {{fileID: {owner}}}\n"
            "  serializedVersion: 2\n"
            f"  m_LocalRotation: {vec(rotation)}\n  m_LocalPosition: {vec(position)}\n"
            "  m_LocalScale: {x: 1, y: 1, z: 1}\n  m_ConstrainProportionsScale: 0\n  m_Children: []\n"
            f"  m_Father: {{fileID: 0}}\n  m_LocalEulerAnglesHint: {vec(euler_hint(rotation))}\n")


def camera(anchor, owner):
    return (f"--- !u!20 &{anchor}\nCamera:\n" + OBJECT_HEAD + f"  m_GameObject: {{fileID: {owner}}}\n" + """  m_Enabled: 1
  serializedVersion: 2
  m_ClearFlags: 1
  m_BackGroundColor: {r: 0.19215687, g: 0.3019608, b: 0.4745098, a: 0}
  m_projectionMatrixMode: 1
  m_GateFitMode: 2
  m_FOVAxisMode: 0
  m_Iso: 200
  m_ShutterSpeed: 0.005
  m_Aperture: 16
  m_FocusDistance: 10
  m_FocalLength: 50
  m_BladeCount: 5
  m_Curvature: {x: 2, y: 11}
  m_BarrelClipping: 0.25
  m_Anamorphism: 0
  m_SensorSize: {x: 36, y: 24}
  m_LensShift: {x: 0, y: 0}
  m_NormalizedViewPortRect:
    serializedVersion: 2
    x: 0
    y: 0
    width: 1
    height: 1
  near clip plane: 0.01
  far clip plane: 100
  field of view: 50
  orthographic: 0
  orthographic size: 5
  m_Depth: -1
  m_CullingMask:
    serializedVersion: 2
    m_Bits: 4294967295
  m_RenderingPath: -1
  m_TargetTexture: {fileID: 0}
  m_TargetDisplay: 0
  m_TargetEye: 3
  m_HDR: 1
  m_AllowMSAA: 1
  m_AllowDynamicResolution: 0
  m_ForceIntoRT: 0
  m_OcclusionCulling: 1
  m_StereoConvergence: 10
  m_StereoSeparation: 0.022
""")


def audio_listener(anchor, owner):
    return f"--- !u!81 &{anchor}\nAudioListener:\n" + OBJECT_HEAD + f"  m_GameObject: {{fileID: {owner}}}\n  m_Enabled: 1\n"


def light(anchor, owner):
    return (f"--- !u!108 &{anchor}\nLight:\n" + OBJECT_HEAD + f"  m_GameObject: {{fileID: {owner}}}\n" + """  m_Enabled: 1
  serializedVersion: 10
  m_Type: 1
  m_Shape: 0
  m_Color: {r: 1, g: 0.95686275, b: 0.8392157, a: 1}
  m_Intensity: 1
  m_Range: 10
  m_SpotAngle: 30
  m_InnerSpotAngle: 21.80208
  m_CookieSize: 10
  m_Shadows:
    m_Type: 2
    m_Resolution: -1
    m_CustomResolution: -1
    m_Strength: 1
    m_Bias: 0.05
    m_NormalBias: 0.4
    m_NearPlane: 0.2
    m_CullingMatrixOverride:
      e00: 1
      e01: 0
      e02: 0
      e03: 0
      e10: 0
      e11: 1
      e12: 0
      e13: 0
      e20: 0
      e21: 0
      e22: 1
      e23: 0
      e30: 0
      e31: 0
      e32: 0
      e33: 1
    m_UseCullingMatrixOverride: 0
  m_Cookie: {fileID: 0}
  m_DrawHalo: 0
  m_Flare: {fileID: 0}
  m_RenderMode: 0
  m_CullingMask:
    serializedVersion: 2
    m_Bits: 4294967295
  m_RenderingLayerMask: 1
  m_Lightmapping: 4
  m_LightShadowCasterMode: 0
  m_AreaSize: {x: 1, y: 1}
  m_BounceIntensity: 1
  m_ColorTemperature: 6570
  m_UseColorTemperature: 0
  m_BoundingSphereOverride: {x: 0, y: 0, z: 0, w: 0}
  m_UseBoundingSphereOverride: 0
  m_UseViewFrustumForShadowCasterCull: 1
  m_ShadowRadius: 0
  m_ShadowAngle: 0
""")


def mono_behaviour(anchor, owner, script_guid, fields):
    return (f"--- !u!114 &{anchor}\nMonoBehaviour:\n" + OBJECT_HEAD + f"  m_GameObject: {{fileID: {owner}}}\n"
            "  m_Enabled: 1\n  m_EditorHideFlags: 0\n"
            f"  m_Script: {{fileID: 11500000, guid: {script_guid}, type: 3}}\n"
            "  m_Name: \n  m_EditorClassIdentifier: \n" + fields)


def scene():
    """GraspScene.unity. The table (GraspScenario: the recording's frame turned z up -> Unity's y
    up, Unity = (x, z + 0.815, y) of the recording's, table top at y 0.75) spans x -0.15..0.45,
    z -0.17..0.73; the hand works over x 0.02..0.28, z -0.04..0.59, y 0.75..0.95. The camera looks
    at that from behind the hand (its wrist side), above, as its owner would."""
    script = guid_of(f"{SAMPLE_REL}/GraspScene.cs")  # its .meta is written below
    eye, target = (-0.32, 1.12, 0.28), (0.17, 0.80, 0.28)
    cam_rot = look_rotation(tuple(t - e for t, e in zip(target, eye)))
    light_rot = look_rotation((0.35, -0.8, 0.48))  # from above, behind the camera's left
    roots = []
    docs = [HEADER]
    # anchors: fixed, distinct, as an editor would have numbered them
    cam_go, cam_tr, cam_cam, cam_audio = 100000001, 100000002, 100000003, 100000004
    docs.append(game_object(cam_go, "Main Camera", [cam_tr, cam_cam, cam_audio], tag="MainCamera"))
    docs.append(transform(cam_tr, cam_go, eye, cam_rot))
    docs.append(camera(cam_cam, cam_go))
    docs.append(audio_listener(cam_audio, cam_go))
    roots.append(cam_tr)
    light_go, light_tr, light_light = 100000011, 100000012, 100000013
    docs.append(game_object(light_go, "Directional Light", [light_tr, light_light]))
    docs.append(transform(light_tr, light_go, (0, 3, 0), light_rot))
    docs.append(light(light_light, light_go))
    roots.append(light_tr)
    demo_go, demo_tr, demo_mb = 100000021, 100000022, 100000023
    docs.append(game_object(demo_go, "Grasp Scene", [demo_tr, demo_mb]))
    docs.append(transform(demo_tr, demo_go, (0, 0, 0), (0, 0, 0, 1)))
    docs.append(mono_behaviour(demo_mb, demo_go, script,
                               "  loop: 1\n  trackedHand: 0\n  objectMaterial: {fileID: 0}\n"))
    roots.append(demo_tr)
    docs.append("--- !u!1660057539 &9223372036854775807\nSceneRoots:\n  m_ObjectHideFlags: 0\n  m_Roots:\n" +
                "".join(f"  - {{fileID: {r}}}\n" for r in roots))
    return "".join(docs)


def check_scene(text, package_guids):
    """Problems of a scene file: its documents' anchors unique, every local fileID defined,
    every script GUID a .meta's of the package, each component owned by the GameObject that
    lists it, the roots listed once."""
    problems = []
    if not text.startswith("%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n"):
        problems.append("does not start with Unity's YAML header")
    docs = re.split(r"^--- ", text, flags=re.M)[1:]
    anchors, classes, bodies = [], {}, {}
    for d in docs:
        m = re.match(r"!u!(\d+) &(-?\d+)( stripped)?\n([A-Za-z]+):\n", d)
        if not m:
            problems.append(f"a document with no !u!CLASS &ANCHOR header: {d[:40]!r}")
            continue
        anchors.append(m.group(2))
        classes[m.group(2)] = m.group(4)
        bodies[m.group(2)] = d
    for a in sorted({a for a in anchors if anchors.count(a) > 1}):
        problems.append(f"anchor &{a} is defined {anchors.count(a)} times")
    for m in re.finditer(r"\{fileID: (-?\d+)(, guid: ([0-9a-f]{32}), type: (\d+))?\}", text):
        file_id, guid, kind = m.group(1), m.group(3), m.group(4)
        if guid is None:
            if file_id != "0" and file_id not in classes:
                problems.append(f"fileID {file_id} is referenced but not defined in the file")
        elif kind == "3" and guid not in package_guids:
            problems.append(f"script guid {guid} is no .meta's of the package")
    for anchor, body in bodies.items():
        if classes[anchor] != "GameObject":
            continue
        for c in re.findall(r"- component: \{fileID: (\d+)\}", body):
            if c in bodies and f"m_GameObject: {{fileID: {anchor}}}" not in bodies[c]:
                problems.append(f"component &{c} of GameObject &{anchor} names another owner")
    root_transforms = {a for a, b in bodies.items() if classes[a] == "Transform" and "m_Father: {fileID: 0}" in b}
    listed = [r for a, b in bodies.items() if classes[a] == "SceneRoots" for r in re.findall(r"- \{fileID: (\d+)\}", b)]
    if sorted(listed) != sorted(root_transforms):
        problems.append(f"SceneRoots lists {sorted(listed)}, the root transforms are {sorted(root_transforms)}")
    return problems


def package_guids():
    guids = set()
    for base, dirs, files in os.walk(PACKAGE):
        dirs[:] = [d for d in dirs if not d.startswith(".")]
        for name in files:
            if name.endswith(".meta"):
                with open(os.path.join(base, name)) as f:
                    m = re.search(r"^guid: ([0-9a-f]{32})$", f.read(), re.M)
                if m:
                    guids.add(m.group(1))
    return guids


def wanted(objects_dir):
    """{sample-relative path: bytes} of everything this writes."""
    out = {}
    for name in trees():
        src = os.path.join(objects_dir, name + ".frtree")
        if not os.path.isfile(src):
            sys.exit(f"unity_grasp_scene: {src} is missing: build the frusta_sample_objects target")
        with open(src, "rb") as f:
            out[f"{RESOURCES_REL}/{name}.frtree"] = f.read()
    with open(RECORDING, "rb") as f:
        out[f"{RESOURCES_REL}/demo_glove.bytes"] = f.read()
    out["GraspScene.unity"] = scene().encode()
    # a .meta for every file and folder: the ones written here, and the hand-written ones
    files = set(out)
    for base, dirs, names in os.walk(SAMPLE):
        dirs[:] = [d for d in dirs if not d.startswith(".")]
        for n in names:
            if not n.endswith(".meta") and not n.startswith("."):
                files.add(os.path.relpath(os.path.join(base, n), SAMPLE).replace(os.sep, "/"))
    folders = {"/".join(f.split("/")[:i]) for f in files for i in range(1, f.count("/") + 1)}
    for rel in sorted(files | folders):
        out[rel + ".meta"] = meta(f"{SAMPLE_REL}/{rel}", rel in folders).encode()
    return out


def main():
    args = sys.argv[1:]
    check = "--check" in args
    args = [a for a in args if a != "--check"]
    if len(args) != 1:
        sys.exit(__doc__)
    out = wanted(args[0])
    stale = []
    for rel, data in sorted(out.items()):
        path = os.path.join(SAMPLE, rel)
        current = open(path, "rb").read() if os.path.isfile(path) else None
        if current == data:
            continue
        if check:
            stale.append(rel)
            continue
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "wb") as f:
            f.write(data)
        print("wrote", os.path.join(SAMPLE_REL, rel))
    # nothing left over from an earlier scene (a tree no longer named)
    resources = os.path.join(SAMPLE, RESOURCES_REL)
    for n in sorted(os.listdir(resources)) if os.path.isdir(resources) else []:
        rel = f"{RESOURCES_REL}/{n}"
        if rel not in out:
            if check:
                stale.append(rel + " (not written by this script)")
            else:
                os.remove(os.path.join(resources, n))
                print("removed", os.path.join(SAMPLE_REL, rel))
    problems = check_scene(out["GraspScene.unity"].decode(), package_guids() | {guid_of(f"{SAMPLE_REL}/GraspScene.cs")})
    for rel, data in out.items():
        for guid in re.findall(r"script: \{fileID: 11500000, guid: ([0-9a-f]{32}), type: 3\}", data.decode(errors="replace")):
            if rel.endswith(".meta") and guid not in package_guids():
                problems.append(f"{rel} names importer script {guid}, no .meta's of the package")
    for p in problems:
        print(f"unity_grasp_scene: GraspScene.unity: {p}", file=sys.stderr)
    if stale:
        print("unity_grasp_scene: not what tools/unity_grasp_scene.py writes (run it with the objects of a fresh "
              "build and commit the result): " + ", ".join(stale), file=sys.stderr)
    return 1 if stale or problems else 0


if __name__ == "__main__":
    sys.exit(main())
