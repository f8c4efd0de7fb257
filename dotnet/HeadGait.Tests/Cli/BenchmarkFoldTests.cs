extern alias cli;

using System.Collections.Generic;
using HeadGait.Synthetic;
using NUnit.Framework;
using BenchmarkCommand = cli::HeadGait.Cli.BenchmarkCommand;

namespace HeadGait.Tests.Cli
{
    /// <summary>
    /// A benchmark fold scores the SVM and the BLSTM as the product runs them: beside the THR of their fold, whose step clock
    /// keeps their walks going (<see cref="GaitModels.SvmOf"/>). A run of the learned classifiers alone trained no THR, so
    /// their step clock ran on THR's defaults and scored otherwise than beside THR.
    /// </summary>
    public class BenchmarkFoldTests
    {
        [Test]
        public void ALearnedClassifiersFoldTrainsTheThrItsStepClockRunsOn()
        {
            var train = new List<Recording>();
            for (ulong i = 0; i < 2; i++)
                train.Add(WalkingStreamGenerator.Generate($"fold walk {i}", GaitSubject.Random(20 + i), new StreamScript().Stand(2).Walk(12, Foot.Left).Stand(2), 20 + i));
            foreach (var names in new[] { new[] { "svm" }, new[] { "blstm" } })
            {
                var (models, _, _) = BenchmarkCommand.TrainFold(train, 0, BenchmarkCommand.FoldTrainsThreshold(names), false);
                Assert.That(models.Threshold, Is.Not.Null, $"{names[0]}: the fold's THR is trained for the step clock");
            }
            Assert.That(BenchmarkCommand.FoldTrainsThreshold(new[] { "cor" }), Is.False, "COR alone needs no THR");
        }
    }
}
