using System;
using System.IO;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>The package's folders are found however a Unity project installed it.</summary>
    public class SamplePathsTests
    {
        string root;

        [SetUp]
        public void MakeRoot() => root = Path.Combine(Path.GetTempPath(), "headgait-paths-" + Guid.NewGuid().ToString("N"));

        [TearDown]
        public void RemoveRoot()
        {
            if (Directory.Exists(root)) Directory.Delete(root, true);
        }

        string MakePackage(string folder, string name = SamplePaths.PackageName)
        {
            Directory.CreateDirectory(Path.Combine(folder, "Samples~", "Recordings", "eval"));
            Directory.CreateDirectory(Path.Combine(folder, "Models"));
            File.WriteAllText(Path.Combine(folder, "package.json"), "{\n  \"name\": \"" + name + "\",\n  \"version\": \"0.1.0\"\n}\n");
            return folder;
        }

        string Scripts()
        {
            string assets = Path.Combine(root, "Project", "Assets", "Scripts");
            Directory.CreateDirectory(assets);
            return assets;
        }

        static string Full(string p) => Path.GetFullPath(p).TrimEnd(Path.DirectorySeparatorChar);

        [Test]
        public void InstalledFromGitTheCachedPackageIsFound()
        {
            // Unity puts a git or registry install under Library/PackageCache/<name>@<hash>.
            string pkg = MakePackage(Path.Combine(root, "Project", "Library", "PackageCache", SamplePaths.PackageName + "@1a2b3c4d5e"));
            MakePackage(Path.Combine(root, "Project", "Library", "PackageCache", "com.other.package@99"), "com.other.package");
            string start = Scripts();
            Assert.That(Full(SamplePaths.FindRecordingsFolder(start)), Is.EqualTo(Full(Path.Combine(pkg, "Samples~", "Recordings"))));
            Assert.That(Full(SamplePaths.FindModelsFolder(start)), Is.EqualTo(Full(Path.Combine(pkg, "Models"))));
        }

        [Test]
        public void EmbeddedPackageIsFound()
        {
            string pkg = MakePackage(Path.Combine(root, "Project", "Packages", SamplePaths.PackageName));
            Assert.That(Full(SamplePaths.FindModelsFolder(Scripts())), Is.EqualTo(Full(Path.Combine(pkg, "Models"))));
        }

        [Test]
        public void LocalFileDependencyIsFoundThroughTheManifest()
        {
            string pkg = MakePackage(Path.Combine(root, "checkout", "Packages", "headgait"));
            string packages = Path.Combine(root, "Project", "Packages");
            Directory.CreateDirectory(packages);
            File.WriteAllText(Path.Combine(packages, "manifest.json"),
                "{\n  \"dependencies\": {\n    \"" + SamplePaths.PackageName + "\": \"file:../../checkout/Packages/headgait\"\n  }\n}\n");
            Assert.That(Full(SamplePaths.FindRecordingsFolder(Scripts())), Is.EqualTo(Full(Path.Combine(pkg, "Samples~", "Recordings"))));
        }

        [Test]
        public void AStartInsideThePackageFindsItsOwnFolders()
        {
            string pkg = MakePackage(Path.Combine(root, "anywhere", "headgait-copy"));
            string inside = Path.Combine(pkg, "Tests", "Editor");
            Directory.CreateDirectory(inside);
            Assert.That(Full(SamplePaths.FindModelsFolder(inside)), Is.EqualTo(Full(Path.Combine(pkg, "Models"))));
        }

        [Test]
        public void AFolderWithTheRightNameButAnotherPackageIsNotTakenForIt()
        {
            string fake = MakePackage(Path.Combine(root, "Project", "Packages", SamplePaths.PackageName), "com.someone.else");
            foreach (var candidate in SamplePaths.CandidateRoots(Scripts()))
                Assert.That(Full(candidate), Is.Not.EqualTo(Full(fake)));
        }
    }
}
