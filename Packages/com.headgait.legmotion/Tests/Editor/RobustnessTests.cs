using System;
using System.Collections.Generic;
using HeadGait.Synthetic;
using NUnit.Framework;

namespace HeadGait.Tests
{
    public class RobustnessTests
    {
        [Test]
        public void GarbageStreamNeverThrowsAndNeverEmitsNonFiniteOutput()
        {
            var rnd = new DeterministicRandom(99);
            var classifiers = new IGaitClassifier[] { new CorrelationClassifier(TestData.Template), new ThresholdClassifier() };
            foreach (var c in classifiers)
            {
                var pipeline = new GaitPipeline(c);
                int frames = 0;
                pipeline.FrameProduced += (p, f) =>
                {
                    frames++;
                    Assert.That(double.IsNaN(f.StridePosition) || double.IsInfinity(f.StridePosition), Is.False);
                    Assert.That(f.WalkWeight, Is.InRange(0.0, 1.0));
                };
                double t = 100;
                for (int i = 0; i < 20000; i++)
                {
                    double u = rnd.NextDouble();
                    t += u < 0.01 ? -0.5 : u < 0.02 ? 2.0 : u < 0.05 ? 0 : 0.002 + 0.02 * rnd.NextDouble();
                    double x = u > 0.97 ? double.NaN : u > 0.96 ? double.PositiveInfinity : u > 0.95 ? 1e9 : 30 * rnd.NextGaussian();
                    pipeline.Push(new ImuSample(u > 0.99 ? double.NaN : t, x, 5 * rnd.NextGaussian(), 9.8 + 20 * rnd.NextGaussian()));
                }
                Assert.That(frames, Is.GreaterThan(1000), c.Name);
                Assert.That(pipeline.Preprocessor.Skipped, Is.GreaterThan(500), c.Name);
                // Jumps of +2 s and -0.5 s move the clock for good: the stream re-bases on them once the next samples agree.
                Assert.That(pipeline.Preprocessor.Rebases, Is.GreaterThan(50), c.Name);
            }
        }

        [Test]
        public void GlitchyRecordingReplaysWithItsBadRowsSkipped()
        {
            var rec = TestData.Eval("glitchy");
            var r = ReplayEvaluator.Run(rec, new CorrelationClassifier(TestData.Template));
            Assert.That(r.FileWarnings, Is.EqualTo(5));
            Assert.That(r.SkippedSamples, Is.GreaterThan(10));
            Assert.That(r.Gaps, Is.EqualTo(1));
            // The glitches cost little: within 5 points of the same walk recorded cleanly.
            var clean = ReplayEvaluator.Run(SampleLibrary.GlitchyBeforeCorruption(), new CorrelationClassifier(TestData.Template));
            Assert.That(r.ClassifierMetrics.MisclassificationRate, Is.LessThan(clean.ClassifierMetrics.MisclassificationRate + 0.05));
            TestContext.WriteLine($"glitchy {r.ClassifierMetrics.MisclassificationRate:P1}, clean {clean.ClassifierMetrics.MisclassificationRate:P1}");
        }

        [Test]
        public void EmptyAndUnlabelledRecordingsReplayWithoutMetrics()
        {
            var empty = RecordingCsv.Parse("timestamp_s,acc_x,acc_y,acc_z\n");
            var r = ReplayEvaluator.Run(empty, new ThresholdClassifier());
            Assert.That(r.Windows, Is.EqualTo(0));
            Assert.That(r.ClassifierMetrics, Is.Null);

            var rows = new System.Text.StringBuilder("timestamp_s,acc_x,acc_y,acc_z\n");
            for (int i = 0; i < 300; i++) rows.Append(i * 0.01).Append(",0,0,9.81\n");
            var unlabelled = RecordingCsv.Parse(rows.ToString());
            r = ReplayEvaluator.Run(unlabelled, new CorrelationClassifier(TestData.Template));
            Assert.That(r.Windows, Is.EqualTo(251));
            Assert.That(r.AnimatorMetrics, Is.Null);
        }

        [Test]
        public void ReplayIsRepeatable()
        {
            var rec = TestData.Eval("start_stop");
            var a = ReplayEvaluator.Run(rec, new CorrelationClassifier(TestData.Template));
            var b = ReplayEvaluator.Run(rec, new CorrelationClassifier(TestData.Template));
            Assert.That(b.ClassifierMetrics.MisclassificationRate, Is.EqualTo(a.ClassifierMetrics.MisclassificationRate));
            Assert.That(b.AnimatorMetrics.MisclassificationRate, Is.EqualTo(a.AnimatorMetrics.MisclassificationRate));
        }
    }
}
