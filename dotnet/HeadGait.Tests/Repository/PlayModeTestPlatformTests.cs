using System.IO;
using System.Linq;
using NUnit.Framework;
using NUnit.Framework.Interfaces;
using NUnit.Framework.Internal;
using UnityEngine;

namespace HeadGait.Tests
{
    /// <summary>
    /// The Play Mode test assembly targets every platform, so Test Runner's "Run on player" (a headset) runs it there, where
    /// the package folder does not exist: its fixtures that read the package's files are marked
    /// <see cref="NeedsPackageFilesAttribute"/> and skipped on a player instead of failing.
    /// </summary>
    public class PlayModeTestPlatformTests
    {
        static string Package => RepositoryPaths.Package;

        [Test]
        public void EveryPlayModeFixtureThatReadsPackageFilesRunsInTheEditorOnly()
        {
            var unmarked = Directory.EnumerateFiles(Path.Combine(Package, "Tests", "Runtime"), "*.cs")
                .Where(f =>
                {
                    var code = File.ReadLines(f).Where(line => !line.TrimStart().StartsWith("//")).ToList();
                    bool reads = code.Any(line => line.Contains("SamplePaths.") || line.Contains("TestData."));
                    return reads && !code.Any(line => line.Trim() == "[NeedsPackageFiles]");
                })
                .Select(Path.GetFileName)
                .ToList();
            Assert.That(unmarked, Is.Empty, "fixtures reading the package's files without [NeedsPackageFiles]");
        }

        sealed class Fixture
        {
            public void Reads() { }
        }

        [Test]
        public void AFixtureThatNeedsPackageFilesIsSkippedOnAPlayerAndRunsInTheEditor()
        {
            RunState On(RuntimePlatform platform)
            {
                var test = new TestMethod(new MethodWrapper(typeof(Fixture), nameof(Fixture.Reads)));
                using (new StandInPlatform(platform)) new NeedsPackageFilesAttribute().ApplyToTest(test);
                return test.RunState;
            }
            Assert.That(On(RuntimePlatform.LinuxEditor), Is.EqualTo(RunState.Runnable));
            Assert.That(On(RuntimePlatform.WindowsEditor), Is.EqualTo(RunState.Runnable));
            Assert.That(On(RuntimePlatform.Android), Is.EqualTo(RunState.Skipped));
        }
    }
}
