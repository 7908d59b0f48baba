#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Write the .meta file Unity needs beside every file and folder of unity-package/ that
lacks one (folders ending in ~ and their contents are not imported, so they get none).
GUIDs are the md5 of the package-relative path: stable across machines and unique.
Existing .meta files are kept (Unity keeps them too). Run it after adding a file;
PackageTests checks that none is missing. Usage: python3 tests/dotnet/unity_meta.py"""
import hashlib
import os
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "unity-package")
TAIL = "  userData: \n  assetBundleName: \n  assetBundleVariant: \n"
# built binaries are ignored by git; only their hand-written .meta is committed
SKIP = {".so", ".dll", ".dylib", ".bundle", ".meta"}


def guid_of(rel):
    """The GUID of a package-relative path."""
    return hashlib.md5(("com.frusta.engine/" + rel).encode()).hexdigest()


def meta(rel, is_dir):
    head = f"fileFormatVersion: 2\nguid: {guid_of(rel)}\n"
    if is_dir:
        return head + "folderAsset: yes\nDefaultImporter:\n  externalObjects: {}\n" + TAIL
    ext = os.path.splitext(rel)[1]
    if ext == ".cs":
        return head + ("MonoImporter:\n  externalObjects: {}\n  serializedVersion: 2\n  defaultReferences: []\n"
                       "  executionOrder: 0\n  icon: {instanceID: 0}\n") + TAIL
    if ext == ".asmdef":
        return head + "AssemblyDefinitionImporter:\n  externalObjects: {}\n" + TAIL
    if rel == "package.json":
        return head + "PackageManifestImporter:\n  externalObjects: {}\n" + TAIL
    return head + "TextScriptImporter:\n  externalObjects: {}\n" + TAIL


def assets(root):
    """(package-relative path, is folder) of everything Unity imports under root, .meta
    files aside: not hidden, not in a folder ending in ~ (tests/package checks a tarball
    with this same rule)."""
    for base, dirs, files in os.walk(root):
        dirs[:] = sorted(d for d in dirs if not d.endswith("~") and not d.startswith("."))
        for name in dirs + sorted(files):
            if name.startswith(".") or name.endswith(".meta"):
                continue
            path = os.path.join(base, name)
            yield os.path.relpath(path, root).replace(os.sep, "/"), os.path.isdir(path)


def main():
    written = 0
    for rel, is_dir in assets(ROOT):
        # built libraries (libembree3.so.3 too) are ignored by git: only their .meta is committed
        if os.path.splitext(rel)[1] in SKIP or ".so." in os.path.basename(rel):
            continue
        target = os.path.join(ROOT, rel) + ".meta"
        if os.path.exists(target):
            continue
        with open(target, "w") as f:
            f.write(meta(rel, is_dir))
        written += 1
        print("wrote", os.path.relpath(target, ROOT))
    print(f"{written} .meta files written", file=sys.stderr)


if __name__ == "__main__":
    main()
