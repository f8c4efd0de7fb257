using System;
using System.IO;
using HeadGait.Tooling;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>Every file and folder Unity imports from the package and the project's Assets has a valid, unique .meta.</summary>
    public class MetaFileTests
    {
        static string Package => RepositoryPaths.Package;

        [Test]
        public void EveryImportedEntryHasItsOwnValidMeta()
        {
            string assets = Path.GetFullPath(Path.Combine(Package, "..", "..", "Assets"));
            var problems = UnityMeta.Problems(Path.GetFullPath(Package), assets);
            Assert.That(problems, Is.Empty, "run `dotnet run --project dotnet/HeadGait.Cli -- unity-meta` to add missing ones");
        }

        [Test]
        public void TheCheckCatchesMissingOrphanedDuplicateAndWrongMetas()
        {
            string root = Path.Combine(Path.GetTempPath(), "headgait-meta-" + Guid.NewGuid().ToString("N"));
            try
            {
                Directory.CreateDirectory(Path.Combine(root, "Runtime"));
                Directory.CreateDirectory(Path.Combine(root, "Samples~", "Demo"));
                File.WriteAllText(Path.Combine(root, "Runtime", "A.cs"), "class A {}");
                File.WriteAllText(Path.Combine(root, "Runtime", "B.cs"), "class B {}");
                File.WriteAllText(Path.Combine(root, "package.json"), "{}");
                File.WriteAllText(Path.Combine(root, "Samples~", "Demo", "S.cs"), "class S {}");
                Directory.CreateDirectory(Path.Combine(root, "Documentation~"));
                File.WriteAllText(Path.Combine(root, "Documentation~", "index.md"), "# doc");
                var written = UnityMeta.WriteMissing(root);
                Assert.That(written.Count, Is.EqualTo(5), "Runtime, A.cs, B.cs, package.json and the sample's S.cs; not Samples~, the sample folder or Documentation~");
                Assert.That(File.Exists(Path.Combine(root, "Samples~", "Demo", "S.cs.meta")));
                Assert.That(UnityMeta.Problems(root), Is.Empty);
                Assert.That(File.ReadAllText(Path.Combine(root, "package.json.meta")), Does.Contain("PackageManifestImporter:"));
                Assert.That(File.ReadAllText(Path.Combine(root, "Runtime.meta")), Does.Contain("folderAsset: yes"));

                File.Delete(Path.Combine(root, "Runtime", "B.cs.meta"));
                File.WriteAllText(Path.Combine(root, "Gone.cs.meta"), UnityMeta.Text(Path.Combine(root, "Runtime", "A.cs"), Guid.NewGuid().ToString("N")));
                File.Copy(Path.Combine(root, "Runtime", "A.cs.meta"), Path.Combine(root, "Runtime", "C.cs.meta"));
                File.WriteAllText(Path.Combine(root, "Runtime", "C.cs"), "class C {}");
                File.WriteAllText(Path.Combine(root, "package.json.meta"), File.ReadAllText(Path.Combine(root, "package.json.meta")).Replace("PackageManifestImporter", "TextScriptImporter"));
                File.Delete(Path.Combine(root, "Samples~", "Demo", "S.cs.meta"));
                File.WriteAllText(Path.Combine(root, "Samples~", "Demo", "Old.cs.meta"), UnityMeta.Text(Path.Combine(root, "Runtime", "A.cs"), Guid.NewGuid().ToString("N")));
                var problems = string.Join("\n", UnityMeta.Problems(root));
                Assert.That(problems, Does.Contain("B.cs: no .meta"));
                Assert.That(problems, Does.Contain("Gone.cs.meta: orphaned"));
                Assert.That(problems, Does.Contain("repeats"));
                Assert.That(problems, Does.Contain("expected the PackageManifestImporter"));
                Assert.That(problems, Does.Contain("S.cs: no .meta"));
                Assert.That(problems, Does.Contain("Old.cs.meta: orphaned"));
                Assert.That(problems, Does.Not.Contain("index.md"));
            }
            finally
            {
                Directory.Delete(root, true);
            }
        }
    }
}
