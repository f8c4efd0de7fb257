using System;
using System.Collections.Generic;
using System.IO;
using System.Text.RegularExpressions;

namespace HeadGait.Tooling
{
    /// <summary>
    /// The .meta files Unity needs beside every file and folder it imports (a package read from git or a registry is
    /// immutable: an asset without a committed .meta is ignored, and scenes and prefabs find scripts by the GUID in it).
    /// Lists what needs one, writes missing ones with a fresh GUID and the importer Unity uses for the file type, and
    /// checks a tree for missing, orphaned, malformed and duplicate-GUID .meta files.
    /// </summary>
    public static class UnityMeta
    {
        static readonly Regex GuidLine = new Regex(@"^guid: ([0-9a-f]{32})\s*$", RegexOptions.Multiline);

        /// <summary>A package's samples folder: not imported itself, but Unity copies each sample in it into Assets.</summary>
        public const string SamplesFolder = "Samples~";

        /// <summary>
        /// Files and folders under <paramref name="root"/> that Unity imports: everything except hidden entries (names
        /// starting with '.'), folders ending in '~' and what they hold, and .meta files themselves; plus what each sample in
        /// Samples~ holds (Unity copies Samples~/&lt;sample&gt;/ with its .meta files into Assets on import, so scenes and
        /// prefabs there keep their references). The sample folders themselves are not copied with a .meta.
        /// </summary>
        public static List<string> ImportedEntries(string root)
        {
            var list = new List<string>();
            Walk(root, list);
            string samples = Path.Combine(root, SamplesFolder);
            if (Directory.Exists(samples))
                foreach (var sample in Directory.GetDirectories(samples))
                    if (!Ignored(Path.GetFileName(sample))) Walk(sample, list);
            list.Sort(StringComparer.Ordinal);
            return list;
        }

        static void Walk(string dir, List<string> list)
        {
            foreach (var d in Directory.GetDirectories(dir))
            {
                string name = Path.GetFileName(d);
                if (Ignored(name) || name.EndsWith("~", StringComparison.Ordinal)) continue;
                list.Add(d);
                Walk(d, list);
            }
            foreach (var f in Directory.GetFiles(dir))
            {
                string name = Path.GetFileName(f);
                if (Ignored(name) || name.EndsWith(".meta", StringComparison.Ordinal)) continue;
                list.Add(f);
            }
        }

        static bool InHiddenFolder(string root, string path)
        {
            var parts = path.Substring(root.Length).Split(new[] { Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar }, StringSplitOptions.RemoveEmptyEntries);
            int first = 0;
            if (parts.Length > 0 && parts[0] == SamplesFolder)
            {
                if (parts.Length < 3) return true; // Samples~ and the sample folders themselves
                first = 2;
            }
            for (int i = first; i < parts.Length; i++)
                if (Ignored(parts[i]) || parts[i].EndsWith("~", StringComparison.Ordinal)) return true;
            return false;
        }

        static bool Ignored(string name) => name.StartsWith(".", StringComparison.Ordinal) || name == "bin" || name == "obj";

        /// <summary>The importer Unity assigns to an entry, by type.</summary>
        public static string ImporterFor(string path)
        {
            if (Directory.Exists(path)) return "DefaultImporter";
            string name = Path.GetFileName(path);
            switch (Path.GetExtension(name).ToLowerInvariant())
            {
                case ".cs": return "MonoImporter";
                case ".asmdef":
                case ".asmref": return "AssemblyDefinitionImporter";
                case ".json": return name == "package.json" ? "PackageManifestImporter" : "TextScriptImporter";
                case ".md":
                case ".txt":
                case ".bytes":
                case ".csv":
                case ".xml":
                case ".html":
                case ".yaml": return "TextScriptImporter";
                case ".png": return "TextureImporter";
                case ".shader": return "ShaderImporter";
                case ".prefab": return "PrefabImporter";
                case ".anim":
                case ".controller":
                case ".overridecontroller":
                case ".mat":
                case ".asset": return "NativeFormatImporter";
                // .onnx is claimed by Sentis' scripted importer when it is installed; without it Unity keeps the file as is.
                default: return "DefaultImporter";
            }
        }

        /// <summary>
        /// The fileID of a native asset's main object: class ID * 100000 (AnimationClip 74, AnimatorController 91,
        /// AnimatorOverrideController 221, Material 21; https://docs.unity3d.com/Manual/ClassIDReference.html).
        /// </summary>
        public static long MainObjectFileId(string path)
        {
            switch (Path.GetExtension(path).ToLowerInvariant())
            {
                case ".anim": return 7400000;
                case ".controller": return 9100000;
                case ".overridecontroller": return 22100000;
                case ".mat": return 2100000;
                default: return 11400000; // a ScriptableObject .asset
            }
        }

        /// <summary>A new .meta's text for the entry, with the given GUID (32 lower-case hex digits).</summary>
        public static string Text(string path, string guid)
        {
            string importer = ImporterFor(path);
            var lines = new List<string> { "fileFormatVersion: 2", "guid: " + guid };
            if (Directory.Exists(path)) lines.Add("folderAsset: yes");
            lines.Add(importer + ":");
            lines.Add("  externalObjects: {}");
            if (importer == "NativeFormatImporter") lines.Add("  mainObjectFileID: " + MainObjectFileId(path));
            if (importer == "MonoImporter")
            {
                lines.Add("  serializedVersion: 2");
                lines.Add("  defaultReferences: []");
                lines.Add("  executionOrder: 0");
                lines.Add("  icon: {instanceID: 0}");
            }
            lines.Add("  userData: ");
            lines.Add("  assetBundleName: ");
            lines.Add("  assetBundleVariant: ");
            return string.Join("\n", lines) + "\n";
        }

        /// <summary>Writes a .meta for every imported entry that lacks one; returns the paths written.</summary>
        public static List<string> WriteMissing(string root)
        {
            var written = new List<string>();
            foreach (var entry in ImportedEntries(root))
            {
                string meta = entry + ".meta";
                if (File.Exists(meta)) continue;
                File.WriteAllText(meta, Text(entry, Guid.NewGuid().ToString("N")));
                written.Add(meta);
            }
            return written;
        }

        /// <summary>The GUID a .meta file declares, or null when it has none.</summary>
        public static string GuidOf(string metaPath)
        {
            var m = GuidLine.Match(File.ReadAllText(metaPath).Replace("\r\n", "\n"));
            return m.Success ? m.Groups[1].Value : null;
        }

        /// <summary>Every problem with the .meta files under the roots (one line each), or none.</summary>
        public static List<string> Problems(params string[] roots)
        {
            var problems = new List<string>();
            var guids = new Dictionary<string, string>();
            foreach (var root in roots)
            {
                var entries = new HashSet<string>(ImportedEntries(root));
                foreach (var entry in entries)
                {
                    string meta = entry + ".meta";
                    if (!File.Exists(meta))
                    {
                        problems.Add($"{entry}: no .meta");
                        continue;
                    }
                    string text = File.ReadAllText(meta).Replace("\r\n", "\n");
                    string guid = GuidOf(meta);
                    if (!text.StartsWith("fileFormatVersion: 2\n", StringComparison.Ordinal) || guid == null)
                    {
                        problems.Add($"{meta}: not a Unity .meta (needs 'fileFormatVersion: 2' and a 32-digit guid)");
                        continue;
                    }
                    if (guids.TryGetValue(guid, out var other)) problems.Add($"{meta}: guid {guid} repeats {other}");
                    else guids[guid] = meta;
                    string importer = ImporterFor(entry);
                    if (!Regex.IsMatch(text, "^" + importer + ":", RegexOptions.Multiline)) problems.Add($"{meta}: expected the {importer}");
                    if (Directory.Exists(entry) != text.Contains("\nfolderAsset: yes\n")) problems.Add($"{meta}: folderAsset does not match what {Path.GetFileName(entry)} is");
                }
                // Folders ending in '~' are not imported, but samples keep their .meta files there so that references survive
                // the copy into Assets: only the imported part of the tree is checked for orphans.
                foreach (var meta in Directory.GetFiles(root, "*.meta", SearchOption.AllDirectories))
                {
                    string entry = meta.Substring(0, meta.Length - ".meta".Length);
                    if (InHiddenFolder(root, entry)) continue;
                    if (!entries.Contains(entry)) problems.Add($"{meta}: orphaned (no {Path.GetFileName(entry)} beside it)");
                }
            }
            return problems;
        }
    }
}
