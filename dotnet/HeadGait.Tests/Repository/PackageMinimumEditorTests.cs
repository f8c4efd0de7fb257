using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>
    /// package.json's minimum editor ("unity") is at least the editor that writes what the package's serialized assets
    /// hold: no editor reads an object saved at a serialized version newer than its own, or fields its type does not
    /// have, as that object was meant. The editors are read off the type trees Unity editors report for each class,
    /// dumped per editor in AssetRipper/TypeTreeDumps (StructsDump/editor/VERSION.dump, "CLASS Base // ..., Version{N}"
    /// with N in hex, then one line per field); only the dumps named below were read.
    /// </summary>
    public class PackageMinimumEditorTests
    {
        /// <summary>Class and top-level serializedVersion: the oldest editor seen writing it (an upper bound on the
        /// first editor that did; the series before it was read and writes an older version where one is named).</summary>
        static readonly (string type, int version, string editor)[] VersionWrittenBy =
        {
            // 2021.3.36f1.dump: "GameObject Base ... Version{6}".
            ("GameObject", 6, "2021.3"),
            // 2021.3.36f1.dump: "OcclusionCullingSettings Base ... Version{2}".
            ("OcclusionCullingSettings", 2, "2021.3"),
            // 2021.3.36f1.dump: "Material Base ... Version{8}" (2022.3.40f1 and 6000.0.23f1 write 8 too: the number
            // alone does not need Unity 6; the fields below do).
            ("Material", 8, "2021.3"),
            // 2021.3.36f1.dump: "AnimationClip Base ... Version{6}"; 2022.3.40f1.dump and 6000.0.23f1.dump: Version{7}.
            ("AnimationClip", 7, "2022.3"),
            // 2022.3.40f1.dump: "LightmapSettings Base ... Version{c}" (12, with m_GIWorkflowMode); 6000.0.23f1.dump:
            // Version{d} (13, with m_BakeOnSceneLoad). The 2023.x dumps were not read.
            ("LightmapSettings", 13, "6000.0"),
        };

        /// <summary>Class and top-level field: the oldest editor seen whose type tree has the field.</summary>
        static readonly (string type, string field, string editor)[] FieldWrittenBy =
        {
            // Material variants: absent from 2021.3.36f1.dump's Material, present in 2022.3.40f1.dump's.
            ("Material", "m_Parent", "2022.3"),
            ("Material", "m_LockedProperties", "2022.3"),
            // Absent from 2022.3.40f1.dump's Material (which ends at m_BuildTextureStacks), present in 6000.0.23f1.dump's.
            ("Material", "m_AllowLocking", "6000.0"),
            // Absent from 2022.3.40f1.dump's LightmapSettings, present in 6000.0.23f1.dump's.
            ("LightmapSettings", "m_BakeOnSceneLoad", "6000.0"),
        };

        static readonly string[] SerializedAssetExtensions = { ".mat", ".anim", ".controller", ".prefab", ".unity", ".asset" };

        [Test]
        public void DeclaredMinimumEditorWritesWhatTheSerializedAssetsHold()
        {
            string package = RepositoryPaths.Package;
            using var json = JsonDocument.Parse(File.ReadAllText(Path.Combine(package, "package.json")));
            string declared = json.RootElement.GetProperty("unity").GetString();

            var problems = new List<string>();
            int checkedObjects = 0;
            foreach (var file in Directory.GetFiles(package, "*.*", SearchOption.AllDirectories)
                         .Where(f => SerializedAssetExtensions.Contains(Path.GetExtension(f))).OrderBy(f => f, StringComparer.Ordinal))
            {
                string rel = Path.GetRelativePath(package, file).Replace('\\', '/');
                foreach (var (type, version, fields) in Documents(File.ReadAllText(file)))
                {
                    var versions = VersionWrittenBy.Where(v => v.type == type).ToList();
                    if (version is int v && versions.Count > 0)
                    {
                        checkedObjects++;
                        var entry = versions.Where(e => e.version == v).Select(e => e.editor).FirstOrDefault();
                        if (entry == null && v > versions.Max(e => e.version))
                            problems.Add($"{rel}: {type} serializedVersion {v} is newer than any in the table: add which editor writes it");
                        else if (entry != null && Compare(declared, entry) < 0)
                            problems.Add($"{rel}: {type} serializedVersion {v} is written from Unity {entry}, package.json says {declared}");
                    }
                    foreach (var (_, field, editor) in FieldWrittenBy.Where(f => f.type == type && fields.Contains(f.field)))
                        if (Compare(declared, editor) < 0)
                            problems.Add($"{rel}: {type}.{field} exists from Unity {editor}, package.json says {declared}");
                }
            }
            Assert.That(checkedObjects, Is.GreaterThan(0), "no serialized object of a type in the table was found");
            Assert.That(problems, Is.Empty, string.Join("\n", problems.Distinct().Take(20)));
        }

        [TestCase("6000.0", "2022.3", 1)]
        [TestCase("2021.3", "6000.0", -1)]
        [TestCase("2022.3", "2022.3", 0)]
        [TestCase("2022.10", "2022.3", 1)]
        public void EditorVersionsCompareByNumber(string a, string b, int sign)
            => Assert.That(Math.Sign(Compare(a, b)), Is.EqualTo(sign));

        /// <summary>Each YAML document of a Unity text asset: its class (the line after "--- !u!ID &amp;FILEID"), its
        /// top-level serializedVersion (none where the class writes none) and its top-level field names.</summary>
        static IEnumerable<(string type, int? version, HashSet<string> fields)> Documents(string text)
        {
            var parts = Regex.Split(text, @"^--- !u!\d+ &\S+.*$", RegexOptions.Multiline);
            foreach (var body in parts.Skip(1))
            {
                var type = Regex.Match(body, @"^(\w+):\s*$", RegexOptions.Multiline);
                if (!type.Success) continue;
                var version = Regex.Match(body, @"^  serializedVersion: (\d+)", RegexOptions.Multiline);
                var fields = Regex.Matches(body, @"^  (\w+):", RegexOptions.Multiline).Select(m => m.Groups[1].Value).ToHashSet();
                yield return (type.Groups[1].Value, version.Success ? int.Parse(version.Groups[1].Value) : null, fields);
            }
        }

        /// <summary>Compares editor versions "YEAR.MINOR" (package.json's "unity") number by number.</summary>
        static int Compare(string a, string b)
        {
            int[] Parse(string s) => s.Split('.').Select(int.Parse).ToArray();
            var (x, y) = (Parse(a), Parse(b));
            for (int i = 0; i < Math.Max(x.Length, y.Length); i++)
            {
                int c = (i < x.Length ? x[i] : 0).CompareTo(i < y.Length ? y[i] : 0);
                if (c != 0) return c;
            }
            return 0;
        }
    }
}
