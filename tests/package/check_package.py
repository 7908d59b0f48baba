#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Checks a release tarball of the Unity package (tools/package) as Unity would meet it:
unpacked into an empty folder, it must be npm pack's layout (one top folder, package/),
with a complete package.json, LICENSE.md and the third-party notices; every imported
file and folder with a .meta of a unique GUID and no .meta without its asset
(tests/dotnet/unity_meta.py's rule); the plugins' import settings within Unity's
one-plugin-per-(platform, CPU, file name) rule (unity_plugins.py); each library of the
architecture its folder names; and the libraries needing nothing outside the package
but the operating system (objdump -p, ldd), with the newest glibc symbol version they
ask for at most GLIBC_FLOOR.
Usage: check_package.py TARBALL UNPACK_DIR [--release] [--windows-baker]   (UNPACK_DIR is
emptied, then kept for the tests that load the libraries from it; --release: the
manifest's links are required; --windows-baker: so is the Windows editor's baker,
tools/package --windows-baker)"""
import json
import os
import re
import shutil
import subprocess
import sys
import tarfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "dotnet"))
sys.path.insert(0, HERE)
import unity_meta  # noqa: E402
import unity_plugins  # noqa: E402

# the newest glibc the Linux libraries may ask for (README: Ubuntu 22.04, Debian 12)
GLIBC_FLOOR = (2, 35)
# what every Linux desktop with that glibc has: the C and C++ runtimes and libudev (systemd)
LINUX_SYSTEM = {"libc.so.6", "libm.so.6", "libdl.so.2", "libpthread.so.0", "librt.so.1",
                "ld-linux-x86-64.so.2", "ld-linux-aarch64.so.1", "libgcc_s.so.1", "libstdc++.so.6",
                "libudev.so.1"}
# what every Windows since 7 has (tests/abi/exports.cmake's list)
WINDOWS_SYSTEM = {"kernel32.dll", "user32.dll", "advapi32.dll", "setupapi.dll", "hid.dll", "ws2_32.dll",
                  "msvcrt.dll", "bcrypt.dll", "shell32.dll", "ole32.dll", "cfgmgr32.dll", "winmm.dll"}
# each plugin folder's architecture: ELF e_machine or PE machine
ARCH = {"Linux/x86_64": ("elf", 62), "Linux/arm64": ("elf", 183), "Windows/x86_64": ("pe", 0x8664)}

failures = []
RELEASE = "--release" in sys.argv[3:]
WINDOWS_BAKER = "--windows-baker" in sys.argv[3:]
# the bakers and what they load: the editors' alone, never a player's
EDITOR_ONLY = ("libfrusta_bake.so", "libembree3.so.3", "libtbb.so.12", "frusta_bake.dll")


def fail(message):
    failures.append(message)
    print("FAIL", message)


def unpack(tarball, into):
    shutil.rmtree(into, ignore_errors=True)
    os.makedirs(into)
    with tarfile.open(tarball, "r:gz") as tar:
        for m in tar.getmembers():
            parts = m.name.split("/")
            if parts[0] != "package" or ".." in parts or m.name.startswith("/"):
                fail(f"{m.name}: outside package/")
            if not (m.isfile() or m.isdir()):
                fail(f"{m.name}: neither a file nor a folder")
        tar.extractall(into, filter="data")
    return os.path.join(into, "package")


def check_manifest(package, tarball):
    with open(os.path.join(package, "package.json"), encoding="utf-8") as f:
        m = json.load(f)
    if os.path.basename(tarball) != f"{m['name']}-{m['version']}.tgz":
        fail(f"{os.path.basename(tarball)} is not named {m['name']}-{m['version']}.tgz")
    for key in ("name", "version", "displayName", "description", "unity", "license"):
        if not isinstance(m.get(key), str) or not m[key].strip():
            fail(f"package.json: {key} is missing")
    # the links: all three (a release: --release), or none where the repository's address
    # is not known (tools/package says so)
    links = [k for k in ("documentationUrl", "changelogUrl", "licensesUrl") if k in m]
    if links or RELEASE:
        for key in ("documentationUrl", "changelogUrl", "licensesUrl"):
            if not re.match(r"^https://\S+$", str(m.get(key, ""))):
                fail(f"package.json: {key} is not an https URL: {m.get(key)}")
    else:
        print("package.json: no documentationUrl, changelogUrl, licensesUrl (no repository address)")
    if not m.get("author", {}).get("name"):
        fail("package.json: author.name is missing")
    if not m.get("keywords"):
        fail("package.json: keywords are missing")
    for s in m.get("samples", []):
        if not os.path.isdir(os.path.join(package, s["path"])):
            fail(f"package.json: sample {s['path']} is not in the tarball")
    if not m.get("samples"):
        fail("package.json: no samples")
    for name in ("README.md", "CHANGELOG.md", "LICENSE.md", "Third Party Notices.md"):
        if not os.path.isfile(os.path.join(package, name)):
            fail(f"{name} is missing")


def check_metas(package):
    guids = {}
    count = 0
    for rel, is_dir in unity_meta.assets(package):
        meta = os.path.join(package, rel + ".meta")
        count += 1
        if not os.path.isfile(meta):
            fail(f"{rel} has no .meta")
            continue
        with open(meta, encoding="utf-8") as f:
            text = f.read()
        g = re.search(r"^guid: ([0-9a-f]{32})$", text, re.M)
        if not g:
            fail(f"{rel}.meta has no guid")
            continue
        if g.group(1) in guids:
            fail(f"{rel}.meta repeats the guid of {guids[g.group(1)]}")
        guids[g.group(1)] = rel
        if is_dir != ("folderAsset: yes" in text):
            fail(f"{rel}.meta: folderAsset does not say it is {'a folder' if is_dir else 'a file'}")
    imported = {rel for rel, _ in unity_meta.assets(package)}
    for base, dirs, files in os.walk(package):
        dirs[:] = [d for d in dirs if not d.endswith("~") and not d.startswith(".")]
        for name in files:
            if name.endswith(".meta"):
                rel = os.path.relpath(os.path.join(base, name[:-5]), package).replace(os.sep, "/")
                if rel not in imported:
                    fail(f"{rel}.meta has no asset")
    print(f"{count} imported files and folders, each with a .meta of its own GUID")


def machine(path):
    with open(path, "rb") as f:
        head = f.read(4096)
    if head[:4] == b"\x7fELF":
        return "elf", int.from_bytes(head[18:20], "little")
    if head[:2] == b"MZ":
        pe = int.from_bytes(head[0x3C:0x40], "little")
        if head[pe:pe + 4] == b"PE\0\0":
            return "pe", int.from_bytes(head[pe + 4:pe + 6], "little")
    return None, None


def objdump(*args):
    return subprocess.run(["objdump", *args], check=True, capture_output=True, text=True).stdout


def check_libraries(package):
    floor = (0, 0)
    floor_cxx = (0, 0, 0)
    plugins = os.path.join(package, "Runtime", "Plugins")
    for base, _, files in sorted(os.walk(plugins)):
        folder = os.path.relpath(base, plugins).replace(os.sep, "/")
        for name in sorted(f for f in files if not f.endswith(".meta")):
            path = os.path.join(base, name)
            rel = f"{folder}/{name}"
            kind, arch = machine(path)
            if (kind, arch) != ARCH.get(folder):
                fail(f"{rel}: {kind} machine {arch}, not the {folder} its folder says")
                continue
            siblings = set(files)
            dump = objdump("-p", path)
            if kind == "elf":
                needed = re.findall(r"^\s*NEEDED\s+(\S+)$", dump, re.M)
                outside = [n for n in needed if n not in LINUX_SYSTEM and n not in siblings]
                if outside:
                    fail(f"{rel} needs {', '.join(outside)}, neither the system's nor in the package")
                # Frusta's own find theirs by an RPATH of $ORIGIN (the old kind, which also
                # serves Embree's need of TBB: ldd below checks that chain)
                ours = [n for n in needed if n in siblings]
                if ours and name.startswith("libfrusta") and not re.search(r"^\s*RPATH\s+\$ORIGIN$", dump, re.M):
                    fail(f"{rel} needs {', '.join(ours)} beside it without an RPATH of $ORIGIN")
                symbols = objdump("-T", path)
                for v in re.findall(r"\(GLIBC_(\d+)\.(\d+)(?:\.\d+)?\)", symbols):
                    floor = max(floor, tuple(map(int, v)))
                for v in re.findall(r"\(GLIBCXX_(\d+)\.(\d+)(?:\.(\d+))?\)", symbols):
                    floor_cxx = max(floor_cxx, tuple(int(x or 0) for x in v))
                print(f"{rel}: needs {', '.join(needed)}")
            else:
                imports = re.findall(r"^\s*DLL Name: (\S+)$", dump, re.M)
                outside = [d for d in imports if d.lower() not in WINDOWS_SYSTEM and not d.lower().startswith("api-ms-win-")]
                if outside:
                    fail(f"{rel} imports {', '.join(outside)}, which Windows does not have")
                print(f"{rel}: imports {', '.join(imports)}")
    # what the dynamic linker finds for the Linux x86_64 libraries (this machine's
    # architecture): the package's own copies first
    linux = os.path.join(plugins, "Linux", "x86_64")
    for name in ("libfrusta.so", "libfrusta_bake.so"):
        out = subprocess.run(["ldd", os.path.join(linux, name)], check=True, capture_output=True, text=True).stdout
        for lib, where in re.findall(r"^\s*(\S+) => (\S+)", out, re.M):
            if where == "not":
                fail(f"{name}: {lib} not found")
            elif lib not in LINUX_SYSTEM and os.path.dirname(os.path.realpath(where)) != os.path.realpath(linux):
                fail(f"{name}: {lib} resolves to {where}, outside the package")
    print(f"glibc needed: {floor[0]}.{floor[1]} (floor {GLIBC_FLOOR[0]}.{GLIBC_FLOOR[1]}); "
          f"libstdc++ needed: GLIBCXX_{'.'.join(map(str, floor_cxx))}")
    if floor > GLIBC_FLOOR:
        fail(f"the Linux libraries need glibc {floor[0]}.{floor[1]}, newer than the {GLIBC_FLOOR[0]}.{GLIBC_FLOOR[1]} the README states")


def main():
    tarball, into = sys.argv[1], sys.argv[2]
    package = unpack(tarball, into)
    check_manifest(package, tarball)
    check_metas(package)
    rows, errors = unity_plugins.check(package)
    for r in rows:
        print(r)
    for e in errors:
        fail(e)
    # and the runtime is there for every editor and player the tarball serves, the
    # baker for the editors that can bake
    for version in ("2022.3", "2023.1", "6000.3"):
        wants = [f"Unity {version} Linux64: Plugins/{'x86_64/' if version == '6000.3' else ''}libfrusta.so <- ",
                 f"Unity {version} Win64: Plugins/x86_64/frusta.dll <- ",
                 f"Unity {version} Editor Linux x86_64: libfrusta.so <- ",
                 f"Unity {version} Editor Linux x86_64: libfrusta_bake.so <- ",
                 f"Unity {version} Editor Windows x86_64: frusta.dll <- "]
        if WINDOWS_BAKER:
            wants.append(f"Unity {version} Editor Windows x86_64: frusta_bake.dll <- ")
        for want in wants:
            if not any(r.startswith(want) for r in rows):
                fail(f"no plugin for {want[:-4]}")
    for r in rows:
        where = r.split(" <- ")[0]
        if " Editor " not in where and where.endswith(EDITOR_ONLY):
            fail(f"{r}: the baker and its libraries are for the editor only")
    check_libraries(package)
    size = os.path.getsize(tarball)
    print(f"{os.path.basename(tarball)}: {size / 1e6:.1f} MB; {len(failures)} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
