// The faithful compile check: every asmdef of the package (Runtime, Editor, Tests, each sample) compiled as its own
// assembly the way Unity compiles it, so what fails in Unity fails here. Per asmdef: C# 9 against .NET Standard 2.1
// (Unity 6's default API compatibility level), only the assemblies it references by name or GUID plus Unity's implicit
// ones (UnityEngine unless noEngineReferences; UnityEditor too inside the editor), with overrideReferences only its
// precompiledReferences, and compiled only where its includePlatforms/excludePlatforms and defineConstraints (with its
// versionDefines) allow. Unity's own assemblies and the packages' are the stand-ins in dotnet/UnityStubs, each compiled
// under the assembly name Unity gives it (StandIns.cs). Run in two contexts (the editor, with UNITY_INCLUDE_TESTS for
// the manifest's testables; an Android player, e.g. Quest) and with every optional package present, then each absent.
// Usage: unity-compile-check [PROJECT_DIR] (default: the repository root). Exit code 1 when anything fails to compile.
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Text.Json;
using System.Text.RegularExpressions;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;

namespace HeadGait.UnityCompileCheck
{
    static class Program
    {
        static int Main(string[] args)
        {
            string project = Path.GetFullPath(args.Length > 0 ? args[0] : FindRepositoryRoot());
            try
            {
                return new Check(project, Console.Out).Run() ? 0 : 1;
            }
            catch (Exception e) when (e is IOException || e is InvalidDataException || e is FormatException || e is JsonException)
            {
                Console.Error.WriteLine($"unity-compile-check: {e.Message}");
                return 2;
            }
        }

        static string FindRepositoryRoot()
        {
            for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir != null; dir = dir.Parent)
                if (File.Exists(Path.Combine(dir.FullName, "Packages", "manifest.json"))) return dir.FullName;
            return Directory.GetCurrentDirectory();
        }

    }

    /// <summary>The check itself, on a Unity project folder; writes its log to <c>log</c>.</summary>
    public sealed class Check
    {
        const string PackageName = "com.headgait.legmotion";
        const string TestFramework = "com.unity.test-framework";
        const int MaxErrorsShown = 8;

        readonly TextWriter log;
        readonly string project, packageDir, stubsDir, nugetRoot;
        readonly string editorVersion;
        readonly string packageMinimumUnity; // package.json "unity" (+ "unityRelease")
        readonly Dictionary<string, string> manifest;      // package -> version, as the project's manifest lists them
        readonly Dictionary<string, string> packageDeps;   // this package's own dependencies
        readonly HashSet<string> testables;
        readonly int activeInputHandler;
        readonly List<Asmdef> asmdefs = new List<Asmdef>();
        readonly List<string> looseAssetScripts = new List<string>();
        readonly List<MetadataReference> framework;
        int failures;

        public Check(string project, TextWriter log)
        {
            this.log = log;
            this.project = project;
            packageDir = Path.Combine(project, "Packages", PackageName);
            stubsDir = Path.Combine(project, "dotnet", "UnityStubs");
            nugetRoot = typeof(Check).Assembly.GetCustomAttributes<AssemblyMetadataAttribute>()
                .First(a => a.Key == "NuGetPackageRoot").Value;

            var versionFile = Path.Combine(project, "ProjectSettings", "ProjectVersion.txt");
            editorVersion = Regex.Match(File.ReadAllText(versionFile), @"m_EditorVersion:\s*(\S+)").Groups[1].Value;
            if (editorVersion.Length == 0) throw new InvalidDataException($"{versionFile}: no m_EditorVersion");

            // Active Input Handling (ProjectSettings.asset activeInputHandler): 0 Input Manager, 1 Input System, 2 both;
            // Unity defines ENABLE_LEGACY_INPUT_MANAGER / ENABLE_INPUT_SYSTEM from it. Absent means Unity's default, 0.
            var settings = Path.Combine(project, "ProjectSettings", "ProjectSettings.asset");
            var handler = File.Exists(settings) ? Regex.Match(File.ReadAllText(settings), @"\n\s*activeInputHandler:\s*(\d)") : Match.Empty;
            activeInputHandler = handler.Success ? int.Parse(handler.Groups[1].Value) : 0;

            var manifestPath = Path.Combine(project, "Packages", "manifest.json");
            var manifestJson = JsonDocument.Parse(File.ReadAllText(manifestPath)).RootElement;
            manifest = Versions(manifestJson, "dependencies");
            testables = manifestJson.TryGetProperty("testables", out var t)
                ? t.EnumerateArray().Select(x => x.GetString()).ToHashSet() : new HashSet<string>();
            var packageJson = JsonDocument.Parse(File.ReadAllText(Path.Combine(packageDir, "package.json"))).RootElement;
            packageDeps = Versions(packageJson, "dependencies");
            manifest[PackageName] = packageJson.GetProperty("version").GetString();
            packageMinimumUnity = packageJson.TryGetProperty("unity", out var u)
                ? OldestEditor(u.GetString(), packageJson.TryGetProperty("unityRelease", out var ur) ? ur.GetString() : null) : null;

            foreach (var path in Directory.GetFiles(packageDir, "*.asmdef", SearchOption.AllDirectories).OrderBy(p => p, StringComparer.Ordinal))
            {
                var rel = Path.GetRelativePath(packageDir, path).Replace('\\', '/');
                // Unity skips the package's ~ folders; a sample (Samples~/NAME) is compiled once imported into Assets.
                var parts = rel.Split('/');
                bool inSample = parts[0] == "Samples~";
                if (parts.Take(parts.Length - 1).Skip(inSample ? 2 : 0).Any(Asmdef.Hidden)) continue;
                asmdefs.Add(Asmdef.Read(path));
            }
            foreach (var dup in asmdefs.GroupBy(a => a.Name).Where(g => g.Count() > 1))
                throw new InvalidDataException($"two asmdefs are named {dup.Key}: {string.Join(", ", dup.Select(a => a.Path))}");

            var looseInPackage = Asmdef.AssignSources(packageDir, asmdefs);
            if (looseInPackage.Count > 0)
            {
                failures++;
                log.WriteLine($"error: scripts in the package outside any asmdef (Unity does not compile them): {string.Join(", ", looseInPackage.Select(Rel))}");
            }
            var samples = Path.Combine(packageDir, "Samples~");
            if (Directory.Exists(samples))
                foreach (var sample in Directory.GetDirectories(samples))
                    looseAssetScripts.AddRange(Asmdef.AssignSources(sample, asmdefs));
            var assets = Path.Combine(project, "Assets");
            if (Directory.Exists(assets)) looseAssetScripts.AddRange(Asmdef.AssignSources(assets, asmdefs));

            var refDir = Path.Combine(nugetRoot, "netstandard.library.ref", "2.1.0", "ref", "netstandard2.1");
            framework = Directory.GetFiles(refDir, "*.dll").Select(f => (MetadataReference)MetadataReference.CreateFromFile(f)).ToList();
        }

        /// <summary>The oldest editor a package.json admits: its "unity" (YEAR.MINOR) with its "unityRelease", or the
        /// series' first release (0f1) without one. Both package.json minimums compared here (this package's, and a
        /// stand-in package's) go through it, so "6000.0" is not taken for a release after 6000.0.0f1.</summary>
        static string OldestEditor(string unity, string unityRelease = null) => unity + "." + (unityRelease ?? "0f1");

        static Dictionary<string, string> Versions(JsonElement root, string name) =>
            root.TryGetProperty(name, out var deps)
                ? deps.EnumerateObject().ToDictionary(p => p.Name, p => p.Value.GetString())
                : new Dictionary<string, string>();

        string Rel(string path) => Path.GetRelativePath(project, path).Replace('\\', '/');

        public bool Run()
        {
            log.WriteLine($"Unity {editorVersion}, activeInputHandler {activeInputHandler}, {asmdefs.Count} asmdefs, NUnit 3.6.0 for nunit.framework.dll, C# 9, .NET Standard 2.1");
            // Optional: every package a stand-in stands for that this package does not depend on (the test framework
            // comes with the project's testables).
            var optional = StandIn.All.Select(s => s.Package).Where(p => p != null && p != TestFramework && !packageDeps.ContainsKey(p))
                .Distinct().OrderBy(p => p, StringComparer.Ordinal).ToList();
            var missing = optional.Where(p => !manifest.ContainsKey(p)).ToList();
            if (missing.Count > 0)
            {
                failures++;
                log.WriteLine($"error: Packages/manifest.json lacks {string.Join(", ", missing)}: the all-packages configuration cannot be built");
            }
            var configurations = new List<(string name, HashSet<string> absent)> { ("every optional package", new HashSet<string>()) };
            foreach (var p in optional)
            {
                var absent = new HashSet<string> { p };
                foreach (var (dependent, needs) in StandIn.PackageDependencies)
                    if (needs.Contains(p)) absent.Add(dependent);
                configurations.Add(("without " + string.Join(" and ", absent.OrderBy(x => x == p ? 0 : 1)), absent));
            }
            foreach (var (name, absent) in configurations)
                foreach (var editor in new[] { true, false })
                    Build($"{name}, {(editor ? "editor" : "Android player")}", absent, editor, editorVersion);
            // The oldest editor package.json admits, with the optional packages that editor can install: its own defines
            // (UNITY_20XX_Y_OR_NEWER) and versionDefines on "Unity" select the code that editor compiles.
            if (packageMinimumUnity != null && Semver.Parse(packageMinimumUnity).CompareTo(Semver.Parse(editorVersion)) < 0)
            {
                var tooNew = StandIn.PackageMinimumUnity.Where(m => Semver.Parse(OldestEditor(m.Value)).CompareTo(Semver.Parse(packageMinimumUnity)) > 0)
                    .Select(m => m.Key).ToHashSet();
                string without = tooNew.Count > 0 ? $", without {string.Join(" and ", tooNew.OrderBy(x => x, StringComparer.Ordinal))} (needs a newer editor)" : "";
                Build($"package.json minimum, Unity {packageMinimumUnity}{without}, editor", tooNew, true, packageMinimumUnity);
            }
            log.WriteLine(failures == 0 ? "unity-compile-check: every assembly compiled in every configuration"
                                            : $"unity-compile-check: {failures} failure(s)");
            return failures == 0;
        }

        void Build(string configuration, HashSet<string> absent, bool editor, string unity)
        {
            log.WriteLine($"== {configuration}");
            var packages = new Dictionary<string, string>(manifest);
            foreach (var dep in packageDeps)
                if (!packages.TryGetValue(dep.Key, out var v) || Semver.Parse(v).CompareTo(Semver.Parse(dep.Value)) < 0)
                    packages[dep.Key] = dep.Value; // the package manager resolves to the higher version
            foreach (var p in absent) packages.Remove(p);
            string platform = editor ? "Editor" : "Android";

            var defines = GlobalDefines(editor, unity);
            bool testsIncluded = editor && packages.ContainsKey(TestFramework);
            var built = new Dictionary<string, (MetadataReference image, bool autoReferenced)>();

            var nunit = MetadataReference.CreateFromFile(Path.Combine(nugetRoot, "nunit", "3.6.0", "lib", "net40", "nunit.framework.dll"));
            // Unity's and the packages' assemblies present in this configuration.
            var sources = StandIn.Partition(stubsDir);
            foreach (var standIn in StandIn.InDependencyOrder())
            {
                if (standIn.EditorOnly && !editor) continue;
                if (standIn.Package != null && !packages.ContainsKey(standIn.Package)) continue;
                if (standIn.Package == TestFramework && !testsIncluded) continue;
                var refs = standIn.References.Where(built.ContainsKey).Select(r => built[r].image).ToList();
                // The test framework's assemblies are built on NUnit's extension interfaces (UnityTestAttribute).
                if (standIn.Package == TestFramework) refs.Add(nunit);
                var image = Compile(standIn.Name, sources[standIn], defines, refs, LanguageVersion.Latest, allowUnsafe: true, out var errors);
                if (image == null)
                {
                    failures++;
                    log.WriteLine($"  stand-in {standIn.Name}: FAILED");
                    foreach (var e in errors) log.WriteLine("    " + e);
                    continue;
                }
                built[standIn.Name] = (image, true);
            }
            log.WriteLine($"  stand-ins: {string.Join(", ", StandIn.All.Select(s => s.Name).Where(built.ContainsKey))}");

            foreach (var a in Order(asmdefs))
            {
                if (!a.BuildsFor(platform)) { log.WriteLine($"  {a.Name}: not built (platforms)"); continue; }
                var symbols = new HashSet<string>(defines);
                // Test assemblies compile in the editor for the manifest's testables and for Assets (an imported sample).
                if (testsIncluded && (IsSample(a) || testables.Contains(PackageName))) symbols.Add("UNITY_INCLUDE_TESTS");
                foreach (var vd in a.VersionDefines)
                {
                    var version = vd.Name == "Unity" ? unity : packages.TryGetValue(vd.Name, out var v) ? v : null;
                    if (version != null && vd.Define != null && vd.Admits(version)) symbols.Add(vd.Define);
                }
                var unmet = a.DefineConstraints.Where(c => !ConstraintMet(c, symbols)).ToList();
                if (unmet.Count > 0) { log.WriteLine($"  {a.Name}: not built (defineConstraints {string.Join(", ", unmet)} unmet)"); continue; }

                var refs = new List<MetadataReference>();
                var refNames = new List<string>();
                void Add(string name)
                {
                    if (built.TryGetValue(name, out var r) && !refNames.Contains(name)) { refs.Add(r.image); refNames.Add(name); }
                }
                var dropped = new List<string>();
                foreach (var reference in a.References)
                {
                    var name = reference.StartsWith("GUID:") ? asmdefs.FirstOrDefault(x => x.Guid == reference.Substring(5))?.Name ?? reference : reference;
                    if (built.ContainsKey(name)) Add(name);
                    else dropped.Add(name); // Unity drops a reference to an assembly that is absent or not compiled here
                }
                if (!a.NoEngineReferences)
                {
                    Add("UnityEngine");
                    if (editor) Add("UnityEditor");
                }
                if (a.OverrideReferences)
                    foreach (var dll in a.PrecompiledReferences)
                    {
                        if (dll == "nunit.framework.dll" && packages.ContainsKey(TestFramework)) { refs.Add(nunit); refNames.Add(dll); }
                        else dropped.Add(dll);
                    }
                var image = Compile(a.Name, a.Sources, symbols, refs, LanguageVersion.CSharp9, a.AllowUnsafeCode, out var errors);
                var note = dropped.Count > 0 ? $"; absent here: {string.Join(", ", dropped)}" : "";
                if (image == null)
                {
                    failures++;
                    log.WriteLine($"  {a.Name}: FAILED ({a.Sources.Count} files; references {string.Join(", ", refNames)}{note})");
                    foreach (var e in errors) log.WriteLine("    " + e);
                    continue;
                }
                built[a.Name] = (image, a.AutoReferenced);
                log.WriteLine($"  {a.Name}: built ({a.Sources.Count} files; references {string.Join(", ", refNames)}{note})");
            }

            // Scripts in Assets (and in samples without an asmdef, once imported) go to Assembly-CSharp, which sees every
            // auto-referenced assembly.
            if (looseAssetScripts.Count > 0)
            {
                var refs = built.Where(b => b.Value.autoReferenced && (editor || b.Key != "UnityEditor")).Select(b => b.Value.image).ToList();
                var image = Compile("Assembly-CSharp", looseAssetScripts, defines, refs, LanguageVersion.CSharp9, false, out var errors);
                log.WriteLine($"  Assembly-CSharp: {(image == null ? "FAILED" : "built")} ({looseAssetScripts.Count} files)");
                if (image == null) { failures++; foreach (var e in errors) log.WriteLine("    " + e); }
            }
            else log.WriteLine("  Assembly-CSharp: no scripts outside asmdefs");
        }

        static bool IsSample(Asmdef a) => a.Path.Replace('\\', '/').Contains("/Samples~/");

        /// <summary>One defineConstraints entry: "A", "!A", or alternatives "A || !B" (Manual: Define constraints).</summary>
        static bool ConstraintMet(string constraint, HashSet<string> symbols) =>
            constraint.Split("||").Select(s => s.Trim()).Any(term =>
                term.StartsWith("!") ? !symbols.Contains(term.Substring(1).Trim()) : symbols.Contains(term));

        /// <summary>The symbols Unity defines for every script: the editor-version series (UNITY_6000_0_OR_NEWER and each
        /// earlier series), the input handling, the API compatibility level and the editor or target platform.</summary>
        HashSet<string> GlobalDefines(bool editor, string unity)
        {
            var s = new HashSet<string> { "NET_STANDARD_2_1", "NET_STANDARD", "NETSTANDARD2_1", "NETSTANDARD", "CSHARP_7_3_OR_NEWER", "UNITY_5_3_OR_NEWER" };
            var v = Semver.Parse(unity);
            var parts = unity.Split('.');
            int major = int.Parse(parts[0]), minor = int.Parse(parts[1]);
            s.Add($"UNITY_{major}"); s.Add($"UNITY_{major}_{minor}");
            var series = new List<(int, int)>();
            for (int y = 2017; y <= 2023; y++) for (int m = 1; m <= 4; m++) series.Add((y, m));
            for (int m = 0; m <= 9; m++) series.Add((6000, m));
            foreach (var (y, m) in series)
                if (v.CompareTo(Semver.Parse($"{y}.{m}.0a1")) >= 0) s.Add($"UNITY_{y}_{m}_OR_NEWER");
            if (activeInputHandler != 1) s.Add("ENABLE_LEGACY_INPUT_MANAGER");
            if (activeInputHandler != 0) s.Add("ENABLE_INPUT_SYSTEM");
            if (editor) { s.Add("UNITY_EDITOR"); s.Add("UNITY_EDITOR_LINUX"); }
            else { s.Add("UNITY_ANDROID"); s.Add("ENABLE_IL2CPP"); }
            return s;
        }

        /// <summary>Asmdefs in dependency order (references first), as Unity compiles them.</summary>
        List<Asmdef> Order(List<Asmdef> all)
        {
            var byName = all.ToDictionary(a => a.Name);
            var result = new List<Asmdef>();
            var state = new Dictionary<string, int>();
            void Visit(Asmdef a)
            {
                if (state.TryGetValue(a.Name, out var st))
                {
                    if (st == 1) throw new InvalidDataException($"{a.Path}: references form a cycle through {a.Name}");
                    return;
                }
                state[a.Name] = 1;
                foreach (var r in a.References)
                {
                    var name = r.StartsWith("GUID:") ? all.FirstOrDefault(x => x.Guid == r.Substring(5))?.Name : r;
                    if (name != null && byName.TryGetValue(name, out var dep)) Visit(dep);
                }
                state[a.Name] = 2;
                result.Add(a);
            }
            foreach (var a in all) Visit(a);
            return result;
        }

        MetadataReference Compile(string name, IEnumerable<string> files, IEnumerable<string> defines,
            List<MetadataReference> references, LanguageVersion language, bool allowUnsafe, out List<string> errors)
        {
            var parse = new CSharpParseOptions(language, preprocessorSymbols: defines);
            var trees = files.Select(f => CSharpSyntaxTree.ParseText(File.ReadAllText(f), parse, f)).ToList();
            var options = new CSharpCompilationOptions(OutputKind.DynamicallyLinkedLibrary, allowUnsafe: allowUnsafe,
                optimizationLevel: OptimizationLevel.Release, nullableContextOptions: NullableContextOptions.Disable);
            var compilation = CSharpCompilation.Create(name, trees, framework.Concat(references), options);
            using var stream = new MemoryStream();
            var result = compilation.Emit(stream);
            var all = result.Diagnostics.Where(d => d.Severity == DiagnosticSeverity.Error).Select(Format).Distinct().ToList();
            errors = all.Take(MaxErrorsShown).ToList();
            if (all.Count > MaxErrorsShown) errors.Add($"... and {all.Count - MaxErrorsShown} more errors");
            if (!result.Success) return null;
            return MetadataReference.CreateFromImage(stream.ToArray());
        }

        string Format(Diagnostic d)
        {
            var span = d.Location.GetLineSpan();
            var where = span.Path is { Length: > 0 } ? $"{Rel(span.Path)}({span.StartLinePosition.Line + 1},{span.StartLinePosition.Character + 1}): " : "";
            return $"{where}error {d.Id}: {d.GetMessage()}";
        }
    }
}
