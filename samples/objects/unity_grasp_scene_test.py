#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""tools/unity_grasp_scene.py's scene checker finds what Unity would choke on: a fileID not
defined in the file, an anchor defined twice, a script GUID no .meta of the package has, a
component owned by another GameObject, a root missing from SceneRoots; and passes the scene
the generator writes."""
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
import unity_grasp_scene as g  # noqa: E402


class SceneChecker(unittest.TestCase):
    def setUp(self):
        self.guids = g.package_guids() | {g.guid_of(f"{g.SAMPLE_REL}/GraspScene.cs")}
        self.scene = g.scene()

    def problems(self, text):
        return g.check_scene(text, self.guids)

    def test_the_generated_scene_passes(self):
        self.assertEqual(self.problems(self.scene), [])

    def test_an_undefined_file_id_is_found(self):
        text = self.scene.replace("- component: {fileID: 100000013}", "- component: {fileID: 100000099}")
        self.assertTrue(any("100000099" in p for p in self.problems(text)))

    def test_a_repeated_anchor_is_found(self):
        text = self.scene.replace("--- !u!108 &100000013", "--- !u!108 &100000012")
        self.assertTrue(any("&100000012" in p for p in self.problems(text)))

    def test_an_unknown_script_guid_is_found(self):
        guid = g.guid_of(f"{g.SAMPLE_REL}/GraspScene.cs")
        text = self.scene.replace(guid, "0123456789abcdef0123456789abcdef")
        self.assertTrue(any("0123456789abcdef0123456789abcdef" in p for p in self.problems(text)))

    def test_a_component_of_another_owner_is_found(self):
        text = self.scene.replace("m_GameObject: {fileID: 100000011}", "m_GameObject: {fileID: 100000001}", 1)
        self.assertTrue(any("names another owner" in p for p in self.problems(text)))

    def test_a_root_missing_from_scene_roots_is_found(self):
        text = self.scene.replace("  - {fileID: 100000022}\n", "")
        self.assertTrue(any("SceneRoots" in p for p in self.problems(text)))

    def test_the_script_guid_is_the_component_scripts(self):
        with open(os.path.join(g.SAMPLE, "GraspScene.cs.meta")) as f:
            self.assertIn(f"guid: {g.guid_of(g.SAMPLE_REL + '/GraspScene.cs')}\n", f.read())
        self.assertIn(f"m_Script: {{fileID: 11500000, guid: {g.guid_of(g.SAMPLE_REL + '/GraspScene.cs')}, type: 3}}",
                      self.scene)

    def test_rotations_are_unit_and_look_where_asked(self):
        q = g.look_rotation((1.0, -1.0, 0.0))
        self.assertAlmostEqual(sum(c * c for c in q), 1.0, places=12)
        self.assertAlmostEqual(g.euler_hint(q)[0], 45.0, places=9)  # pitched down 45 degrees
        self.assertAlmostEqual(g.euler_hint(q)[1], 90.0, places=9)  # facing +x


if __name__ == "__main__":
    unittest.main()
