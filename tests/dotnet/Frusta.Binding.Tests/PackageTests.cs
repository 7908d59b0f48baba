// SPDX-License-Identifier: MIT
// unity-package/ is a valid UPM package: manifest, assembly definitions, .meta files.
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;
using System.Text.RegularExpressions;
using Frusta.Binding;
using Xunit;

namespace Frusta.Binding.Tests
{
    public class PackageTests
    {
        // Unity's own assemblies a test assembly may reference
        static readonly HashSet<string> UnityAssemblies = new HashSet<string> { "UnityEngine.TestRunner", "UnityEditor.TestRunner" };

        static JsonElement Json(string path) => JsonDocument.Parse(File.ReadAllText(path)).RootElement;

        static Dictionary<string, (string Path, JsonElement Json)> Asmdefs() =>
            Directory.EnumerateFiles(TestEnv.Package, "*.asmdef", SearchOption.AllDirectories)
                .Where(p => !Path.GetRelativePath(TestEnv.Package, p).Split(Path.DirectorySeparatorChar).Any(d => d.EndsWith("~")))
                .Select(p => (p, Json(p)))
                .ToDictionary(x => x.Item2.GetProperty("name").GetString(), x => (x.p, x.Item2));

        static string[] Strings(JsonElement e, string property) =>
            e.TryGetProperty(property, out var a) ? a.EnumerateArray().Select(x => x.GetString()).ToArray() : Array.Empty<string>();

        [Fact]
        public void TheManifestNamesThePackageItsVersionUnityAndSamples()
        {
            JsonElement m = Json(Path.Combine(TestEnv.Package, "package.json"));
            string name = m.GetProperty("name").GetString();
            Assert.Matches(@"^com(\.[a-z0-9-]+){2,}$", name);
            Assert.Equal("com.frusta.engine", name);
            Assert.Equal(FrustaLibrary.VersionString, m.GetProperty("version").GetString());
            Assert.Equal("2022.3", m.GetProperty("unity").GetString());
            Assert.False(string.IsNullOrWhiteSpace(m.GetProperty("displayName").GetString()));
            Assert.False(string.IsNullOrWhiteSpace(m.GetProperty("description").GetString()));
            var samples = m.GetProperty("samples").EnumerateArray().ToArray();
            Assert.NotEmpty(samples);
            foreach (var s in samples)
            {
                string path = s.GetProperty("path").GetString();
                Assert.StartsWith("Samples~/", path);
                Assert.True(Directory.Exists(Path.Combine(TestEnv.Package, path)), $"{path} does not exist");
                Assert.NotEmpty(Directory.GetFiles(Path.Combine(TestEnv.Package, path), "*.cs"));
            }
            // the manifest's version is the library's and CMake's
            string cmake = File.ReadAllText(Path.Combine(TestEnv.Root, "CMakeLists.txt"));
            Assert.Matches($@"project\(frusta VERSION {Regex.Escape(FrustaLibrary.VersionString)}\b", cmake);
        }

        [Fact]
        public void AssemblyDefinitionsAreTheOnesTheLayoutNeedsAndTheirReferencesResolve()
        {
            var asmdefs = Asmdefs();
            Assert.Equal(new[] { "Frusta.Binding", "Frusta.Editor", "Frusta.Editor.Tests", "Frusta.Runtime", "Frusta.Runtime.Tests",
                                 "Frusta.XRHands" },
                         asmdefs.Keys.OrderBy(k => k, StringComparer.Ordinal).ToArray());
            var all = asmdefs.Keys.ToHashSet();
            all.Add("Frusta.Samples.HandDemo");
            foreach (var (name, (path, json)) in asmdefs)
            {
                Assert.Equal(name, Path.GetFileNameWithoutExtension(path));
                foreach (string r in Strings(json, "references"))
                    Assert.True(asmdefs.ContainsKey(r) || UnityAssemblies.Contains(r) || (name, r) == ("Frusta.XRHands", "Unity.XR.Hands"),
                                $"{name} references {r}, which is not in the package");
            }

            JsonElement binding = asmdefs["Frusta.Binding"].Json;
            Assert.True(binding.GetProperty("noEngineReferences").GetBoolean());
            Assert.True(binding.GetProperty("allowUnsafeCode").GetBoolean());
            Assert.Empty(Strings(binding, "references"));
            Assert.Equal(Path.Combine(TestEnv.Package, "Runtime", "Binding", "Frusta.Binding.asmdef"), asmdefs["Frusta.Binding"].Path);

            Assert.Equal(new[] { "Frusta.Binding" }, Strings(asmdefs["Frusta.Runtime"].Json, "references"));
            Assert.Equal(new[] { "Editor" }, Strings(asmdefs["Frusta.Editor"].Json, "includePlatforms"));

            foreach (string test in new[] { "Frusta.Editor.Tests", "Frusta.Runtime.Tests" })
            {
                JsonElement t = asmdefs[test].Json;
                Assert.Equal(new[] { "UNITY_INCLUDE_TESTS" }, Strings(t, "defineConstraints"));
                Assert.False(t.GetProperty("autoReferenced").GetBoolean(), test);
                Assert.Contains("nunit.framework.dll", Strings(t, "precompiledReferences"));
                Assert.Contains("UnityEngine.TestRunner", Strings(t, "references"));
            }
            Assert.Equal(new[] { "Editor" }, Strings(asmdefs["Frusta.Editor.Tests"].Json, "includePlatforms"));

            // the XR Hands input compiles only where com.unity.xr.hands (1.1 on: XRHand.isTracked) is
            // installed: its define comes from that package's version, and constrains the assembly
            JsonElement xrHands = asmdefs["Frusta.XRHands"].Json;
            Assert.Equal(new[] { "FRUSTA_XR_HANDS" }, Strings(xrHands, "defineConstraints"));
            var defines = xrHands.GetProperty("versionDefines").EnumerateArray()
                .ToDictionary(d => d.GetProperty("define").GetString(),
                              d => (d.GetProperty("name").GetString(), d.GetProperty("expression").GetString()));
            Assert.Equal(("com.unity.xr.hands", "1.1.0"), defines["FRUSTA_XR_HANDS"]);
            Assert.Equal(("com.unity.xr.hands", "1.5.0"), defines["FRUSTA_XR_HANDS_1_5"]);
            Assert.Contains("Unity.XR.Hands", Strings(xrHands, "references"));
        }

        // the package's Unity scripts (not compiled here: read as text)
        static IEnumerable<string> UnityScripts() =>
            Directory.EnumerateFiles(TestEnv.Package, "*.cs", SearchOption.AllDirectories)
                .Where(p => !p.Contains(Path.Combine("Runtime", "Binding")));

        [Fact]
        public void EveryInspectorFieldHasATooltip()
        {
            var missing = new List<string>();
            foreach (string file in UnityScripts())
            {
                string[] lines = File.ReadAllLines(file);
                for (int i = 0; i < lines.Length; ++i)
                {
                    string line = lines[i].Trim();
                    // Unity shows [SerializeField] fields and public fields (of components and of
                    // [Serializable] types)
                    bool field = line.Contains("[SerializeField") ||
                                 Regex.IsMatch(line, @"^(\[[^\]]*\]\s*)*public [\w<>\[\]]+ \w+( = [^;]+)?;$");
                    if (!field || line.Contains("HideInInspector") || line.Contains("NonSerialized")) continue;
                    // the attributes on this line and the lines just above it
                    bool tip = line.Contains("Tooltip(");
                    for (int k = i - 1; k >= 0 && !tip; --k)
                    {
                        string above = lines[k].Trim();
                        if (above.StartsWith("[Tooltip(") || (above.EndsWith("\")]") && above.StartsWith("\""))) { tip = true; break; }
                        // stop at anything but attributes, their strings and doc comments (another field, say)
                        if (above.EndsWith(";") || !(above.StartsWith("[") || above.StartsWith("\"") || above.StartsWith("///"))) break;
                    }
                    if (!tip) missing.Add($"{Path.GetRelativePath(TestEnv.Package, file)}:{i + 1}: {line}");
                }
            }
            Assert.True(missing.Count == 0, "no tooltip:\n" + string.Join("\n", missing));
        }

        [Fact]
        public void TheEditorWorkflowInstallsTheTarballWhereItsTestProjectLooks()
        {
            // .github/workflows/unity.yml cannot run here (no Unity editor or licence): its paths can
            string root = Path.GetDirectoryName(TestEnv.Package);
            string workflow = File.ReadAllText(Path.Combine(root, ".github", "workflows", "unity.yml"));
            foreach (string part in new[] { "game-ci/unity-test-runner@v4", "editmode", "playmode", "packageMode:",
                                            "run: tar -xzf build/package/com.frusta.engine-*.tgz -C build/package",
                                            "path: build/package/com.frusta.engine-*.tgz", "tools/package" })
                Assert.Contains(part, workflow);
            // tools/package writes the tarball there; npm-pack layout unpacks to package/
            Assert.Contains("out=\"build/package\"", File.ReadAllText(Path.Combine(root, "tools", "package")));
            string project = Path.Combine(root, "tests", "unity", "XRHandsProject");
            Assert.Contains($"'tests/unity/XRHandsProject'", workflow);
            JsonElement manifest = Json(Path.Combine(project, "Packages", "manifest.json"));
            JsonElement dependencies = manifest.GetProperty("dependencies");
            string source = dependencies.GetProperty("com.frusta.engine").GetString();
            Assert.StartsWith("file:", source);
            Assert.Equal(Path.Combine(root, "build", "package", "package"),
                         Path.GetFullPath(Path.Combine(project, "Packages", source.Substring(5))));
            Assert.Equal(new[] { "com.frusta.engine" }, Strings(manifest, "testables"));
            // the XR Hands version Frusta.XRHands needs (its versionDefines)
            Assert.True(Version.Parse(dependencies.GetProperty("com.unity.xr.hands").GetString()) >= new Version(1, 5, 0));
        }

        [Fact]
        public void NoScriptUsesObsoleteUnityApi()
        {
            // obsolete from Unity 2023.1 (FindAnyObjectByType / FindObjectsByType replace them)
            foreach (string file in UnityScripts())
                Assert.DoesNotMatch(@"\bFind(Objects?)OfType\b", File.ReadAllText(file));
        }

        [Fact]
        public void TheBindingFolderHoldsNoUnityEngineCode()
        {
            foreach (string file in Directory.EnumerateFiles(Path.Combine(TestEnv.Package, "Runtime", "Binding"), "*.cs", SearchOption.AllDirectories))
                Assert.DoesNotMatch(@"using\s+UnityEngine|UnityEngine\.[A-Z]\w*\s*[.(]", File.ReadAllText(file));
        }

        [Fact]
        public void EveryImportedFileAndFolderHasAMetaWithAUniqueGuid()
        {
            var guids = new Dictionary<string, string>();
            void Check(string path)
            {
                string meta = path + ".meta";
                Assert.True(File.Exists(meta), $"{Path.GetRelativePath(TestEnv.Package, path)} has no .meta (run tests/dotnet/unity_meta.py)");
                Match m = Regex.Match(File.ReadAllText(meta), @"^guid: ([0-9a-f]{32})$", RegexOptions.Multiline);
                Assert.True(m.Success, $"{meta} has no guid");
                Assert.False(guids.TryGetValue(m.Groups[1].Value, out string other), $"{meta} repeats the guid of {other}");
                guids[m.Groups[1].Value] = meta;
                if (Directory.Exists(path)) Assert.Contains("folderAsset: yes", File.ReadAllText(meta));
            }
            void Walk(string dir)
            {
                foreach (string d in Directory.GetDirectories(dir).Where(d => !Path.GetFileName(d).EndsWith("~") && !Path.GetFileName(d).StartsWith(".")))
                {
                    Check(d);
                    Walk(d);
                }
                foreach (string f in Directory.GetFiles(dir).Where(f => !f.EndsWith(".meta") && !Path.GetFileName(f).StartsWith(".")))
                    Check(f);
                // and no .meta without its asset (a deleted file's leftover); the plugins' binaries
                // (libembree3.so.3 too) are built or copied by tools/package
                foreach (string meta in Directory.GetFiles(dir, "*.meta"))
                {
                    string asset = meta.Substring(0, meta.Length - 5);
                    Assert.True(File.Exists(asset) || Directory.Exists(asset) || Regex.IsMatch(asset, @"\.(so(\.\d+)*|dll)$"), $"{meta} has no asset");
                }
            }
            Walk(TestEnv.Package);
            // each runtime library loads in its own editor and player only
            void Plugin(string folder, string file, string editorOs, string player, string cpu)
            {
                string text = File.ReadAllText(Path.Combine(TestEnv.Package, "Runtime", "Plugins", folder, file + ".meta"));
                Assert.Contains("PluginImporter:", text);
                Assert.Matches(editorOs is null
                    ? @"Editor: Editor\n    second:\n      enabled: 0"
                    : $@"Editor: Editor\n    second:\n      enabled: 1\n      settings:\n        CPU: x86_64\n        DefaultValueInitialized: true\n        OS: {editorOs}", text);
                foreach (string standalone in new[] { "Linux64", "Win64", "OSXUniversal" })
                    Assert.Matches(standalone == player
                        ? $@"Standalone: {standalone}\n    second:\n      enabled: 1\n      settings:\n        CPU: {cpu}"
                        : $@"Standalone: {standalone}\n    second:\n      enabled: 0", text);
            }
            Plugin(Path.Combine("Linux", "x86_64"), "libfrusta.so", "Linux", "Linux64", "x86_64");
            Plugin(Path.Combine("Linux", "arm64"), "libfrusta.so", null, "Linux64", "ARM64");
            Plugin(Path.Combine("Windows", "x86_64"), "frusta.dll", "Windows", "Win64", "x86_64");
            // the bakers serve their editors only
            Plugin(Path.Combine("Linux", "x86_64"), "libfrusta_bake.so", "Linux", null, null);
            Plugin(Path.Combine("Windows", "x86_64"), "frusta_bake.dll", "Windows", null, null);
        }

        [Fact]
        public void TheSampleShipsTheBundledGloveRecordingUnchanged()
        {
            // the Hand Demo replays its own copy: the package is installed without the repository
            string bundled = Path.Combine(TestEnv.Root, "samples", "data", "demo_glove.frrec");
            string copy = Path.Combine(TestEnv.Package, "Samples~", "HandDemo", "demo_glove.frrec");
            Assert.True(File.Exists(copy), $"{copy} is missing");
            Assert.True(File.ReadAllBytes(bundled).AsSpan().SequenceEqual(File.ReadAllBytes(copy)),
                $"{copy} differs from {bundled}: copy it again (cp samples/data/demo_glove.frrec unity-package/Samples~/HandDemo/)");
            Assert.Contains("demo_glove.frrec", File.ReadAllText(Path.Combine(TestEnv.Package, "Samples~", "HandDemo", "HandDemo.cs")));
        }

        [Fact]
        public void TheChangelogHasAnEntryForTheManifestsVersion()
        {
            // UPM's convention (Keep a Changelog): "## [x.y.z] - yyyy-mm-dd", newest first
            string text = File.ReadAllText(Path.Combine(TestEnv.Package, "CHANGELOG.md"));
            string version = Json(Path.Combine(TestEnv.Package, "package.json")).GetProperty("version").GetString();
            var entries = Regex.Matches(text, @"^## \[(\d+\.\d+\.\d+)\] - \d{4}-\d{2}-\d{2}$", RegexOptions.Multiline)
                               .Select(m => Version.Parse(m.Groups[1].Value)).ToArray();
            Assert.NotEmpty(entries);
            Assert.Equal(Version.Parse(version), entries[0]);
            Assert.Equal(entries.OrderByDescending(v => v).ToArray(), entries);
        }

        [Fact]
        public void NoBuildOutputLivesInThePackage()
        {
            foreach (string d in Directory.EnumerateDirectories(TestEnv.Package, "*", SearchOption.AllDirectories))
                Assert.False(Path.GetFileName(d) is "bin" or "obj", $"{d} is build output inside the package");
        }
    }
}
