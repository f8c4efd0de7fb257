using System.IO;
using System.Linq;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>
    /// Head samples and what is recorded beside them share one clock (`HeadClock`). The legacy reader stamped the frame's
    /// unscaled time while the calibration walk stamped the ankle trackers with real time since start-up; real time counts a
    /// headset's sleep, so where the clocks part the ankle poses fall outside the head stream and the walk is fitted without them. The
    /// legacy-only configuration compiles in the Unity compile check but never runs here, so the rule is read in the source:
    /// outside `HeadClock` only the component's own frame clock (`GaitLegAnimator`, the runner's "no samples lately" rule)
    /// reads one of Unity's clocks.
    /// </summary>
    public class HeadClockTests
    {
        static string Package => RepositoryPaths.Package;

        [Test]
        public void OnlyTheHeadClockReadsTheClockHeadSamplesAreStampedOn()
        {
            var readers = Directory.EnumerateFiles(Path.Combine(Package, "Runtime"), "*.cs", SearchOption.AllDirectories)
                .Concat(Directory.EnumerateFiles(Path.Combine(Package, "Samples~"), "*.cs", SearchOption.AllDirectories))
                .Where(f => File.ReadLines(f).Any(line => !line.TrimStart().StartsWith("//")
                    && (line.Contains("Time.realtimeSinceStartup") || line.Contains("Time.unscaledTime"))))
                .Select(Path.GetFileName)
                .OrderBy(n => n)
                .ToList();
            Assert.That(readers, Is.EqualTo(new[] { "GaitLegAnimator.cs", "HeadClock.cs" }));
        }
    }
}
