using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;

namespace HeadGait.UnityCompileCheck
{
    /// <summary>One assembly definition file, read the way Unity's editor reads it (UnityCsReference
    /// Editor/Mono/Scripting/ScriptCompilation/CustomScriptAssemblyData.cs: the JSON field names; a missing field takes
    /// the default that file gives it, e.g. autoReferenced true).</summary>
    sealed class Asmdef
    {
        public string Name;
        public string Path;
        public string Directory;
        public List<string> References = new List<string>();
        public List<string> IncludePlatforms = new List<string>();
        public List<string> ExcludePlatforms = new List<string>();
        public bool AllowUnsafeCode;
        public bool OverrideReferences;
        public List<string> PrecompiledReferences = new List<string>();
        public bool AutoReferenced = true;
        public List<string> DefineConstraints = new List<string>();
        public List<VersionDefine> VersionDefines = new List<VersionDefine>();
        public bool NoEngineReferences;
        public string Guid;
        /// <summary>The .cs files Unity would put in this assembly: every script under its folder except in sub-folders
        /// that hold their own asmdef/asmref and in folders Unity does not import (ending in ~, starting with a dot).</summary>
        public List<string> Sources = new List<string>();

        /// <summary>An Editor-only assembly: includePlatforms is exactly ["Editor"].</summary>
        public bool EditorOnly => IncludePlatforms.Count == 1 && IncludePlatforms[0] == "Editor";

        public bool BuildsFor(string platform) =>
            IncludePlatforms.Count > 0 ? IncludePlatforms.Contains(platform) : !ExcludePlatforms.Contains(platform);

        public static Asmdef Read(string path)
        {
            JsonElement root;
            try
            {
                root = JsonDocument.Parse(File.ReadAllText(path),
                    new JsonDocumentOptions { AllowTrailingCommas = true, CommentHandling = JsonCommentHandling.Skip }).RootElement;
            }
            catch (JsonException e)
            {
                throw new InvalidDataException($"{path}: not valid JSON ({e.Message})");
            }
            var a = new Asmdef { Path = path, Directory = System.IO.Path.GetDirectoryName(path) };
            a.Name = Str(root, "name") ?? throw new InvalidDataException($"{path}: no \"name\"");
            a.References = Strings(root, "references");
            a.IncludePlatforms = Strings(root, "includePlatforms");
            a.ExcludePlatforms = Strings(root, "excludePlatforms");
            a.AllowUnsafeCode = Bool(root, "allowUnsafeCode", false);
            a.OverrideReferences = Bool(root, "overrideReferences", false);
            a.PrecompiledReferences = Strings(root, "precompiledReferences");
            a.AutoReferenced = Bool(root, "autoReferenced", true);
            a.DefineConstraints = Strings(root, "defineConstraints");
            a.NoEngineReferences = Bool(root, "noEngineReferences", false);
            if (root.TryGetProperty("versionDefines", out var vds))
                foreach (var vd in vds.EnumerateArray())
                    a.VersionDefines.Add(new VersionDefine(Str(vd, "name"), Str(vd, "expression") ?? "", Str(vd, "define")));
            var meta = path + ".meta";
            if (File.Exists(meta))
                a.Guid = File.ReadLines(meta).Select(l => l.Trim()).FirstOrDefault(l => l.StartsWith("guid:"))?.Substring(5).Trim();
            return a;
        }

        static string Str(JsonElement e, string name) =>
            e.TryGetProperty(name, out var v) && v.ValueKind == JsonValueKind.String ? v.GetString() : null;

        static bool Bool(JsonElement e, string name, bool fallback) =>
            e.TryGetProperty(name, out var v) && (v.ValueKind == JsonValueKind.True || v.ValueKind == JsonValueKind.False) ? v.GetBoolean() : fallback;

        static List<string> Strings(JsonElement e, string name) =>
            e.TryGetProperty(name, out var v) && v.ValueKind == JsonValueKind.Array
                ? v.EnumerateArray().Select(x => x.GetString()).Where(s => !string.IsNullOrEmpty(s)).ToList()
                : new List<string>();

        /// <summary>Unity skips folders whose names end in '~' or start with '.' (Manual: Special folder names).</summary>
        public static bool Hidden(string folderName) => folderName.EndsWith("~") || folderName.StartsWith(".");

        /// <summary>Assigns each script under <paramref name="root"/> to the nearest asmdef above it; returns the scripts
        /// that have none (Unity compiles those in Assets into Assembly-CSharp, and ignores them in a package).</summary>
        public static List<string> AssignSources(string root, IReadOnlyList<Asmdef> asmdefs)
        {
            var byDir = asmdefs.ToDictionary(a => System.IO.Path.GetFullPath(a.Directory));
            var loose = new List<string>();
            void Walk(string dir, Asmdef owner)
            {
                if (byDir.TryGetValue(System.IO.Path.GetFullPath(dir), out var own)) owner = own;
                foreach (var f in System.IO.Directory.GetFiles(dir, "*.cs").OrderBy(f => f, StringComparer.Ordinal))
                    (owner?.Sources ?? loose).Add(f);
                foreach (var d in System.IO.Directory.GetDirectories(dir).OrderBy(d => d, StringComparer.Ordinal))
                    if (!Hidden(System.IO.Path.GetFileName(d))) Walk(d, owner);
            }
            Walk(root, null);
            return loose;
        }
    }

    /// <summary>A versionDefines entry: <see cref="Define"/> is set when the resource <see cref="Name"/> (a package, a
    /// built-in module or "Unity" for the editor) is present at a version the expression admits.</summary>
    public sealed class VersionDefine
    {
        public readonly string Name, Expression, Define;
        public VersionDefine(string name, string expression, string define) { Name = name; Expression = expression; Define = define; }

        /// <summary>Unity's expression syntax (Manual: "Assembly definition properties", Version Defines): "1.2.3" means
        /// x ≥ 1.2.3; "[1.2,3.4]", "(1.2,3.4)", "[1.2,3.4)", "(1.2,3.4]" are ranges with inclusive [ ] and exclusive ( );
        /// "[1.2.3]" is exactly 1.2.3; an empty expression admits every version.</summary>
        public bool Admits(string version)
        {
            var e = Expression.Trim();
            if (e.Length == 0) return true;
            var v = Semver.Parse(version);
            if (e[0] != '[' && e[0] != '(') return v.CompareTo(Semver.Parse(e)) >= 0;
            var inner = e.Substring(1, e.Length - 2);
            var parts = inner.Split(',');
            if (parts.Length == 1) return v.CompareTo(Semver.Parse(parts[0])) == 0;
            bool lowOk = parts[0].Trim().Length == 0 || (e[0] == '[' ? v.CompareTo(Semver.Parse(parts[0])) >= 0 : v.CompareTo(Semver.Parse(parts[0])) > 0);
            char close = e[e.Length - 1];
            bool highOk = parts[1].Trim().Length == 0 || (close == ']' ? v.CompareTo(Semver.Parse(parts[1])) <= 0 : v.CompareTo(Semver.Parse(parts[1])) < 0);
            return lowOk && highOk;
        }
    }

    /// <summary>Versions as Unity writes them: 1.2.3, 1.2.3-pre.1, and editor versions such as 6000.0.58f2 (the letter
    /// and what follows it are a pre-release tag for ordering: a &lt; b &lt; f &lt; p).</summary>
    readonly struct Semver : IComparable<Semver>
    {
        readonly int[] numbers;
        readonly string tag;
        Semver(int[] numbers, string tag) { this.numbers = numbers; this.tag = tag; }

        public static Semver Parse(string text)
        {
            text = text.Trim();
            int dash = text.IndexOf('-');
            string tag = dash >= 0 ? text.Substring(dash + 1) : "";
            string core = dash >= 0 ? text.Substring(0, dash) : text;
            var nums = new List<int>();
            foreach (var part in core.Split('.'))
            {
                int i = 0;
                while (i < part.Length && char.IsDigit(part[i])) i++;
                if (i == 0) throw new FormatException($"not a version: '{text}'");
                nums.Add(int.Parse(part.Substring(0, i)));
                if (i < part.Length) { tag = part.Substring(i); break; } // 58f2: the editor's release letter
            }
            while (nums.Count < 3) nums.Add(0);
            return new Semver(nums.ToArray(), tag);
        }

        public int CompareTo(Semver other)
        {
            for (int i = 0; i < 3; i++)
                if (numbers[i] != other.numbers[i]) return numbers[i].CompareTo(other.numbers[i]);
            if (tag == other.tag) return 0;
            if (tag.Length == 0) return 1; // a release sorts after its pre-releases
            if (other.tag.Length == 0) return -1;
            return string.CompareOrdinal(tag, other.tag);
        }
    }
}
