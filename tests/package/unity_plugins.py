#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Unity's rule for native plugins, read from their .meta files (PluginImporter): in a
player build, every plugin the build target takes is copied to a path computed from
its file name and CPU, and two plugins with the same path fail the build ("Plugin
'X' is used from several locations"); in the editor, two plugins for the same OS, CPU
and file name make the load ambiguous. This module applies that rule as the editor's
C# does (UnityCsReference: Editor/Mono/ImportSettings/DesktopPluginImporterExtension.cs
CalculateFinalPluginPath, Editor/Mono/Modules/DefaultPluginImporterExtension.cs
CheckFileCollisions), for each Unity version whose rule differs:
  2022.3          Linux64 takes x86_64 only and copies by file name; Win64 x86_64 only
  2023.1-6000.2   Win64 takes ARM64 too (into ARM64/)
  6000.3 on       Linux64 takes ARM64 too, and copies into <CPU>/<file name>
A plugin's defineConstraints are honoured for the version defines
(UNITY_<X>_<Y>_OR_NEWER); any other constraint is taken as met (the worst case).
Usage: unity_plugins.py PACKAGE_FOLDER [--without-binaries]   (prints the table, exits 1
on a violation; --without-binaries: the .meta files alone, as git holds them)"""
import os
import re
import sys

# (version, Linux64 CPUs, Win64 CPUs, Linux64 copies into a CPU folder)
VERSIONS = [
    ((2022, 3), {"x86_64"}, {"x86_64"}, False),
    ((2023, 1), {"x86_64"}, {"x86_64", "ARM64"}, False),
    ((6000, 3), {"x86_64", "ARM64"}, {"x86_64", "ARM64"}, True),
]
EDITOR_OS = {"Windows", "Linux", "OSX", "AnyOS"}
EDITOR_CPU = {"x86_64", "ARM64", "AnyCPU"}


def parse_meta(text):
    """The PluginImporter part of a .meta: {"platforms": {(group, name): (enabled,
    settings)}, "defines": [...]}, or None for another importer."""
    if "\nPluginImporter:" not in "\n" + text:
        return None
    defines = []
    m = re.search(r"^  defineConstraints:(.*)$((?:\n  - .*)*)", text, re.M)
    if m:
        inline = m.group(1).strip()
        if inline not in ("", "[]"):
            defines += [d.strip() for d in inline.strip("[]").split(",") if d.strip()]
        defines += [line.strip()[2:].strip() for line in m.group(2).splitlines() if line.strip()]
    platforms = {}
    # "  - first:\n      GROUP: NAME\n    second:\n      enabled: N\n      settings: ..."
    entries = re.split(r"^  - first:\n", text.split("  platformData:", 1)[1], flags=re.M)[1:]
    for entry in entries:
        head = re.match(r"      ([^:\n]*): ?([^\n]*)\n", entry)
        enabled = re.search(r"^      enabled: (\d)", entry, re.M)
        settings = dict(re.findall(r"^        ([^:\n]+): ?([^\n]*)$", entry, re.M))
        key = (head.group(1).strip(), head.group(2).strip())
        platforms[key] = (enabled is not None and enabled.group(1) == "1", settings)
    return {"platforms": platforms, "defines": defines}


def plugins(package):
    """{package path: parsed PluginImporter} for every native plugin's .meta."""
    found = {}
    for base, dirs, files in os.walk(package):
        dirs[:] = [d for d in dirs if not d.endswith("~") and not d.startswith(".")]
        for name in files:
            if name.endswith(".meta"):
                with open(os.path.join(base, name), encoding="utf-8") as f:
                    parsed = parse_meta(f.read())
                if parsed is not None:
                    found[os.path.relpath(os.path.join(base, name[:-5]), package).replace(os.sep, "/")] = parsed
    return found


def defines_met(defines, version):
    for d in defines:
        m = re.fullmatch(r"UNITY_(\d+)_(\d+)_OR_NEWER", d)
        if m and version < (int(m.group(1)), int(m.group(2))):
            return False
        m = re.fullmatch(r"!UNITY_(\d+)_(\d+)_OR_NEWER", d)
        if m and version >= (int(m.group(1)), int(m.group(2))):
            return False
    return True


def player_path(path, target, cpu, linux_cpu_folder):
    """Where a player build copies the plugin (CalculateFinalPluginPath), "" if not at all."""
    name = os.path.basename(path)
    if cpu in ("", "None"):
        return ""
    if target == "Win64":
        return ("ARM64/" if cpu == "ARM64" else "x86_64/") + name
    if target == "Linux64":
        return (cpu + "/" + name) if linux_cpu_folder else name
    return name


def check(package, with_binaries=True):
    """(rows of "where: what", errors); with_binaries: each .meta's plugin must be there"""
    rows, errors = [], []
    found = plugins(package)
    for path, p in sorted(found.items()):
        if with_binaries and not os.path.exists(os.path.join(package, path)):
            errors.append(f"{path}.meta: its plugin is missing")
        anyp = p["platforms"].get(("", "Any"), (False, {}))
        if anyp[0]:
            errors.append(f"{path}: enabled for Any platform (each platform must be chosen)")
    for version, linux_cpus, win_cpus, linux_cpu_folder in VERSIONS:
        v = f"{version[0]}.{version[1]}"
        allowed = {"Linux64": linux_cpus, "Win64": win_cpus, "Win": {"x86"}, "OSXUniversal": {"x86_64", "ARM64", "AnyCPU"}}
        for target in ("Linux64", "Win64", "Win", "OSXUniversal"):
            copied = {}
            for path, p in sorted(found.items()):
                enabled, settings = p["platforms"].get(("Standalone", target), (False, {}))
                if not enabled or not defines_met(p["defines"], version):
                    continue
                cpu = settings.get("CPU", "AnyCPU")
                # a CPU the version cannot build is dropped, but for Linux64 before
                # 6000.3, which copies by file name whatever the CPU says
                by_name = target == "Linux64" and not linux_cpu_folder
                if cpu not in allowed[target] and cpu != "AnyCPU" and not by_name:
                    continue
                dest = player_path(path, target, cpu, linux_cpu_folder)
                if dest:
                    copied.setdefault(dest, []).append(path)
            for dest, paths in sorted(copied.items()):
                rows.append(f"Unity {v} {target}: Plugins/{dest} <- {', '.join(paths)}")
                if len(paths) > 1:
                    errors.append(f"Unity {v} {target}: Plugin '{os.path.basename(dest)}' is used from several locations: {', '.join(paths)}")
        editor = {}
        for path, p in sorted(found.items()):
            enabled, settings = p["platforms"].get(("Editor", "Editor"), (False, {}))
            if not enabled or not defines_met(p["defines"], version):
                continue
            os_name, cpu = settings.get("OS", "AnyOS"), settings.get("CPU", "AnyCPU")
            if os_name not in EDITOR_OS or cpu not in EDITOR_CPU:
                errors.append(f"{path}: editor OS {os_name} / CPU {cpu} is not one Unity knows")
            for o in ([os_name] if os_name != "AnyOS" else ["Windows", "Linux", "OSX"]):
                for c in ([cpu] if cpu != "AnyCPU" else ["x86_64", "ARM64"]):
                    editor.setdefault((o, c, os.path.basename(path)), []).append(path)
        for (o, c, name), paths in sorted(editor.items()):
            rows.append(f"Unity {v} Editor {o} {c}: {name} <- {', '.join(paths)}")
            if len(paths) > 1:
                errors.append(f"Unity {v} Editor {o} {c}: '{name}' is loaded from several locations: {', '.join(paths)}")
    return rows, errors


def main():
    rows, errors = check(sys.argv[1], "--without-binaries" not in sys.argv[2:])
    for r in rows:
        print(r)
    for e in errors:
        print("FAIL", e)
    sys.exit(1 if errors else 0)


if __name__ == "__main__":
    main()
