extern alias cli;

using System;
using System.IO;
using NUnit.Framework;
using BenchmarkCommand = cli::HeadGait.Cli.BenchmarkCommand;

namespace HeadGait.Tests.Cli
{
    /// <summary>
    /// The benchmarks' fold cache (`--fold-cache`) is read only where this build and the same options trained it: a cache
    /// another build trained gave other fold models (COR's clock lead) and, read as if current, other calibration figures.
    /// </summary>
    public class FoldCacheTests
    {
        string folder;

        [SetUp]
        public void SetUp() => folder = Path.Combine(Path.GetTempPath(), "headgait-foldcache-" + Guid.NewGuid().ToString("N"));

        [TearDown]
        public void TearDown()
        {
            if (Directory.Exists(folder)) Directory.Delete(folder, true);
        }

        [Test]
        public void AFoldCacheIsReadOnlyWhereThisBuildAndTheSameOptionsTrainedIt()
        {
            var shipped = GaitModels.Load(SamplePaths.FindModelsFolder(TestContext.CurrentContext.TestDirectory));
            int trainings = 0;
            (GaitModels, (WalkingGate, WalkingGate, WalkingGate), PhaseMap) Train()
            {
                trainings++;
                return (shipped, (shipped.Threshold.Gate, shipped.Correlation.Gate, null), PhaseMap.Perry);
            }

            var first = BenchmarkCommand.CachedFold(folder, "augment 2", Train);
            Assert.That(trainings, Is.EqualTo(1), "an empty cache trains");
            var again = BenchmarkCommand.CachedFold(folder, "augment 2", Train);
            Assert.That(trainings, Is.EqualTo(1), "the same build and options read it");
            Assert.That(again.Models.Correlation.Serialize(), Is.EqualTo(first.Models.Correlation.Serialize()));

            BenchmarkCommand.CachedFold(folder, "augment 3", Train);
            Assert.That(trainings, Is.EqualTo(2), "other options train again");

            string stampFile = Path.Combine(folder, BenchmarkCommand.FoldCacheStampFile);
            File.WriteAllText(stampFile, "core 00000000000000000000000000000000; augment 3");
            BenchmarkCommand.CachedFold(folder, "augment 3", Train);
            Assert.That(trainings, Is.EqualTo(3), "another build's cache trains again");
            Assert.That(File.ReadAllText(stampFile), Is.EqualTo(BenchmarkCommand.FoldCacheStamp("augment 3")));

            File.Delete(stampFile);
            BenchmarkCommand.CachedFold(folder, "augment 3", Train);
            Assert.That(trainings, Is.EqualTo(4), "a cache from before the stamp trains again");
        }
    }
}
