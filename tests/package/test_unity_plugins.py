#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""unity_plugins.py finds what Unity would refuse: packages of .meta files written the
way Unity writes them, with the collisions Unity's own code reports and without.
Usage: python3 tests/package/test_unity_plugins.py"""
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import unity_plugins  # noqa: E402


def meta(editor=None, players=None, defines=()):
    """A PluginImporter .meta: editor (OS, CPU) or None; players {target: CPU}."""
    players = players or {}
    text = ("fileFormatVersion: 2\nguid: 00000000000000000000000000000000\nPluginImporter:\n"
            "  externalObjects: {}\n  serializedVersion: 2\n  iconMap: {}\n  executionOrder: {}\n")
    text += "  defineConstraints:" + ("".join(f"\n  - {d}" for d in defines) if defines else " []") + "\n"
    text += "  isPreloaded: 0\n  isOverridable: 1\n  platformData:\n"
    text += "  - first:\n      : Any\n    second:\n      enabled: 0\n      settings: {}\n"
    if editor:
        text += (f"  - first:\n      Editor: Editor\n    second:\n      enabled: 1\n      settings:\n"
                 f"        CPU: {editor[1]}\n        DefaultValueInitialized: true\n        OS: {editor[0]}\n")
    else:
        text += "  - first:\n      Editor: Editor\n    second:\n      enabled: 0\n      settings:\n        CPU: AnyCPU\n"
    for target in ("Linux64", "Win64", "OSXUniversal"):
        cpu = players.get(target)
        text += (f"  - first:\n      Standalone: {target}\n    second:\n      enabled: {1 if cpu else 0}\n"
                 f"      settings:\n        CPU: {cpu or 'None'}\n")
    return text + "  userData: \n  assetBundleName: \n  assetBundleVariant: \n"


class UnityPluginRule(unittest.TestCase):
    def package(self, plugins):
        root = tempfile.mkdtemp(prefix="frusta_plugins_")
        self.addCleanup(lambda: __import__("shutil").rmtree(root))
        for path, text in plugins.items():
            os.makedirs(os.path.dirname(os.path.join(root, path)), exist_ok=True)
            open(os.path.join(root, path), "wb").close()
            with open(os.path.join(root, path + ".meta"), "w") as f:
                f.write(text)
        return unity_plugins.check(root)

    def test_two_linux_libraries_of_one_name_collide_before_6000_3(self):
        rows, errors = self.package({
            "Linux/x86_64/libfrusta.so": meta(("Linux", "x86_64"), {"Linux64": "x86_64"}),
            "Linux/arm64/libfrusta.so": meta(None, {"Linux64": "ARM64"}),
        })
        self.assertTrue(any("Unity 2022.3 Linux64: Plugin 'libfrusta.so' is used from several locations" in e for e in errors), errors)
        self.assertTrue(any(e.startswith("Unity 2023.1 Linux64") for e in errors), errors)
        self.assertFalse(any(e.startswith("Unity 6000.3") for e in errors), errors)
        self.assertIn("Unity 6000.3 Linux64: Plugins/ARM64/libfrusta.so <- Linux/arm64/libfrusta.so", rows)

    def test_a_version_define_keeps_arm64_out_of_older_versions(self):
        rows, errors = self.package({
            "Linux/x86_64/libfrusta.so": meta(("Linux", "x86_64"), {"Linux64": "x86_64"}),
            "Linux/arm64/libfrusta.so": meta(None, {"Linux64": "ARM64"}, ["UNITY_6000_3_OR_NEWER"]),
        })
        self.assertEqual(errors, [])
        self.assertIn("Unity 2022.3 Linux64: Plugins/libfrusta.so <- Linux/x86_64/libfrusta.so", rows)

    def test_windows_arm64_goes_into_its_own_folder_from_2023_1_and_nowhere_before(self):
        rows, errors = self.package({
            "Windows/x86_64/frusta.dll": meta(("Windows", "x86_64"), {"Win64": "x86_64"}),
            "Windows/arm64/frusta.dll": meta(("Windows", "ARM64"), {"Win64": "ARM64"}),
        })
        self.assertEqual(errors, [])
        self.assertFalse(any(r.startswith("Unity 2022.3 Win64: Plugins/ARM64/") for r in rows), rows)
        self.assertIn("Unity 2023.1 Win64: Plugins/ARM64/frusta.dll <- Windows/arm64/frusta.dll", rows)

    def test_two_windows_libraries_for_x86_64_collide(self):
        _, errors = self.package({
            "A/frusta.dll": meta(None, {"Win64": "x86_64"}),
            "B/frusta.dll": meta(None, {"Win64": "AnyCPU"}),
        })
        self.assertTrue(any("Win64: Plugin 'frusta.dll' is used from several locations" in e for e in errors), errors)

    def test_two_editor_libraries_for_one_os_and_cpu_collide(self):
        _, errors = self.package({
            "A/libfrusta.so": meta(("Linux", "x86_64")),
            "B/libfrusta.so": meta(("AnyOS", "AnyCPU")),
        })
        self.assertTrue(any("Editor Linux x86_64: 'libfrusta.so' is loaded from several locations" in e for e in errors), errors)

    def test_a_plugin_for_any_platform_is_refused(self):
        text = meta(("Linux", "x86_64")).replace("      : Any\n    second:\n      enabled: 0", "      : Any\n    second:\n      enabled: 1")
        _, errors = self.package({"A/libfrusta.so": text})
        self.assertTrue(any("enabled for Any platform" in e for e in errors), errors)


if __name__ == "__main__":
    unittest.main(verbosity=1)
