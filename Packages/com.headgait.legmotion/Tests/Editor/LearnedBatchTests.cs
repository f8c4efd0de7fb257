using System;
using System.Collections.Generic;
using System.Globalization;
using HeadGait.Synthetic;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>
    /// Scoring the windows a batch of samples completes in one evaluator call (GaitPipeline.PushBatch, the job path and
    /// Sentis) must give exactly the predictions and animator frames of classifying one window at a time.
    /// </summary>
    public class LearnedBatchTests
    {
        static GaitModels Models => TestData.ShippedModels();

        static LearnedClassifier Create(GaitModels models, string kind)
            => kind == SvmClassifier.Kind ? new SvmClassifier(models.Svm) : (LearnedClassifier)new BlstmClassifier(models.Blstm);

        /// <summary>A generated walk with standing before and after, and a 0.5 s dropout mid-walk (a restart).</summary>
        static List<ImuSample> GeneratedWalkWithGap()
        {
            var rec = WalkingStreamGenerator.Generate("walk", GaitSubject.Random(11),
                new StreamScript().Stand(2).Walk(8, Foot.Left).Stand(2).Walk(6, Foot.Right, 0.3), 11);
            var samples = new List<ImuSample>();
            foreach (var s in rec.Samples)
                if (s.Imu.Time < 6.0 || s.Imu.Time > 6.5) samples.Add(s.Imu);
            return samples;
        }

        static List<ImuSample> Recording(string name)
        {
            var samples = new List<ImuSample>();
            foreach (var s in TestData.Eval(name).Samples) samples.Add(s.Imu);
            return samples;
        }

        /// <summary>Every prediction and frame the pipeline produces, written with round-trip precision.</summary>
        static List<string> Frames(GaitPipeline pipeline)
        {
            var frames = new List<string>();
            pipeline.FrameProduced += (p, f) => frames.Add(string.Format(CultureInfo.InvariantCulture,
                "{0:R} {1} {2:R} {3:R} {4:R} {5}/{6} | {7} {8:R} {9:R} {10:R} {11}/{12}",
                p.Time, p.IsWalking, p.StridePosition, p.StepPeriod, p.Confidence, p.Left, p.Right,
                f.State, f.StridePosition, f.WalkWeight, f.StepPeriod, f.Left, f.Right));
            return frames;
        }

        static List<string> OneAtATime(LearnedClassifier classifier, List<ImuSample> samples)
        {
            var pipeline = new GaitPipeline(classifier);
            var frames = Frames(pipeline);
            foreach (var s in samples) pipeline.Push(s);
            return frames;
        }

        /// <summary>Pushes the samples in batches of 1 to 40 samples (as frames of varying length hand them over).</summary>
        static List<string> Batched(LearnedClassifier classifier, List<ImuSample> samples, out GaitPipeline pipeline)
        {
            pipeline = new GaitPipeline(classifier);
            var frames = Frames(pipeline);
            var rng = new Random(5);
            var buffer = new ImuSample[64];
            for (int i = 0; i < samples.Count;)
            {
                int n = Math.Min(samples.Count - i, 1 + rng.Next(40));
                samples.CopyTo(i, buffer, 0, n);
                pipeline.PushBatch(buffer, n);
                i += n;
            }
            return frames;
        }

        /// <summary>Counts calls and windows, scoring with the C# network.</summary>
        sealed class CountingEvaluator : ILearnedEvaluator
        {
            readonly ILearnedEvaluator inner;
            public int Calls, Windows, Largest;
            public CountingEvaluator(ILearnedEvaluator inner) => this.inner = inner;

            public void Evaluate(double[] features, int windows, double[] outputs)
            {
                Calls++;
                Windows += windows;
                Largest = Math.Max(Largest, windows);
                inner.Evaluate(features, windows, outputs);
            }
        }

        static void AssertBatchedEqualsOneAtATime(string kind, List<ImuSample> samples, bool expectRestart, bool expectLiveScale = false)
        {
            var models = Models;
            var single = Create(models, kind);
            var singleCounter = new CountingEvaluator(single.Network);
            single.Evaluator = singleCounter;
            var expected = OneAtATime(single, samples);

            var batchedClassifier = Create(models, kind);
            var counter = new CountingEvaluator(batchedClassifier.Network);
            batchedClassifier.Evaluator = counter;
            var actual = Batched(batchedClassifier, samples, out var pipeline);

            Assert.That(expected.Count, Is.GreaterThan(500), "windows classified");
            Assert.That(expected.Exists(f => f.Contains(" True ")), Is.True, "some windows are predicted walking");
            Assert.That(actual, Is.EqualTo(expected), "batched predictions and frames equal one-at-a-time ones, bit for bit");
            // A window read at a live time scale is scored twice (as it is, and at the scale), every other window once.
            Assert.That(counter.Windows, Is.EqualTo(singleCounter.Windows), "every window scored as often as one at a time");
            Assert.That(counter.Windows, Is.GreaterThanOrEqualTo(expected.Count));
            if (expectLiveScale)
            {
                Assert.That(batchedClassifier.LiveTimeScale, Is.LessThan(1), "the stream moved the live scale");
                Assert.That(counter.Windows, Is.GreaterThan(expected.Count + 100), "windows read at the scale were scored twice");
            }
            else if (kind == BlstmClassifier.Kind) Assert.That(counter.Windows, Is.EqualTo(expected.Count), "every window scored exactly once");
            Assert.That(counter.Calls, Is.LessThan(counter.Windows / 5), "windows are scored in batches, not one per call");
            Assert.That(counter.Largest, Is.GreaterThan(20));
            if (expectRestart) Assert.That(pipeline.Preprocessor.Gaps, Is.GreaterThan(0), "the stream restarted inside a batch");
        }

        [TestCase("svm")]
        [TestCase("blstm")]
        public void BatchedEvaluationEqualsPerWindowOnAGeneratedWalkWithADropout(string kind)
            => AssertBatchedEqualsOneAtATime(kind, GeneratedWalkWithGap(), expectRestart: true);

        [Test]
        public void BatchedEvaluationEqualsPerWindowForAQuickWalkerReadAtALiveScale()
        {
            // A walker quicker than the training walkers (2.4 steps a second): the SVM reads part of the stream at a live
            // time scale, so a batch holds windows scored once and windows scored twice.
            var wearer = GaitSubject.Random(31, "quick");
            wearer.StepFrequency = 2.4;
            var rec = WalkingStreamGenerator.Generate("quick", wearer, new StreamScript().Stand(2).Walk(25, Foot.Right).Stand(1).Walk(25, Foot.Left, -30).Stand(2), 911);
            var samples = new List<ImuSample>();
            foreach (var s in rec.Samples) samples.Add(s.Imu);
            AssertBatchedEqualsOneAtATime("svm", samples, expectRestart: false, expectLiveScale: true);
        }

        [TestCase("svm", "walk_turns")]
        [TestCase("svm", "irregular_rate")]
        [TestCase("blstm", "start_stop")]
        [TestCase("blstm", "glitchy")]
        public void BatchedEvaluationEqualsPerWindowOnTheSampleRecordings(string kind, string recording)
            => AssertBatchedEqualsOneAtATime(kind, Recording(recording), expectRestart: false);

        /// <summary>An evaluator that hands each window the next one's outputs: the comparison above must notice.</summary>
        sealed class ShiftedRowsEvaluator : ILearnedEvaluator
        {
            readonly ILearnedEvaluator inner;
            readonly int outputCount;
            public ShiftedRowsEvaluator(ILearnedEvaluator inner, int outputCount)
            {
                this.inner = inner;
                this.outputCount = outputCount;
            }

            public void Evaluate(double[] features, int windows, double[] outputs)
            {
                inner.Evaluate(features, windows, outputs);
                Array.Copy(outputs, outputCount, outputs, 0, (windows - 1) * outputCount);
            }
        }

        [Test]
        public void AnEvaluatorThatMixesUpWindowsChangesThePredictions()
        {
            var models = Models;
            var samples = GeneratedWalkWithGap();
            var expected = OneAtATime(Create(models, "blstm"), samples);
            var shifted = Create(models, "blstm");
            shifted.Evaluator = new ShiftedRowsEvaluator(shifted.Network, shifted.OutputCount);
            var actual = Batched(shifted, samples, out _);
            Assert.That(actual.Count, Is.EqualTo(expected.Count));
            Assert.That(actual, Is.Not.EqualTo(expected));
        }

        /// <summary>The SVM scores four windows per pass and the rest one by one: every batch size gives each window's own outputs.</summary>
        [TestCase("blstm")]
        [TestCase("svm")]
        public void TheNetworkScoresABatchAsItScoresEachWindow(string kind)
        {
            var blstm = Create(Models, kind);
            var samples = GeneratedWalkWithGap();
            var pre = new StreamPreprocessor(new PreprocessorSettings { History = blstm.WindowLength });
            var rows = new List<double[]>();
            var single = new List<double[]>();
            foreach (var s in samples)
                pre.Push(s, w =>
                {
                    if (rows.Count >= 64 || w.EndTime < 3) return;
                    rows.Add((double[])blstm.Standardise(w).Clone());
                    var alone = new double[blstm.OutputCount];
                    blstm.Network.Evaluate(blstm.Standardise(w), 1, alone);
                    single.Add(alone);
                });
            int width = blstm.Features.Width, k = blstm.OutputCount;
            var features = new double[rows.Count * width];
            for (int i = 0; i < rows.Count; i++) Array.Copy(rows[i], 0, features, i * width, width);
            var scores = new double[rows.Count * k];
            blstm.Network.Evaluate(features, rows.Count, scores);
            for (int i = 0; i < rows.Count; i++)
                Assert.That(new ArraySegment<double>(scores, i * k, k), Is.EqualTo(single[i]), $"window {i}");
            for (int size = 1; size <= 9; size++)
            {
                var part = new double[size * k];
                blstm.Network.Evaluate(new ArraySegment<double>(features, 20 * width, size * width).ToArray(), size, part);
                for (int i = 0; i < size; i++)
                    Assert.That(new ArraySegment<double>(part, i * k, k), Is.EqualTo(single[20 + i]), $"window {i} of a batch of {size}");
            }
            Assert.That(single[0], Is.Not.EqualTo(single[40]), "the windows differ");
            Assert.Throws<ArgumentException>(() => blstm.Network.Evaluate(features, rows.Count + 1, scores));
        }

        [Test]
        public void OtherClassifiersPushTheirBatchOneSampleAtATime()
        {
            var samples = Recording("walk_straight");
            var cor = Models.Create("cor", out _);
            var a = new GaitPipeline(cor);
            var expected = Frames(a);
            foreach (var s in samples) a.Push(s);
            var b = new GaitPipeline(Models.Create("cor", out _));
            var actual = Frames(b);
            b.PushBatch(samples.ToArray(), samples.Count);
            Assert.That(actual, Is.EqualTo(expected));
            Assert.That(actual.Count, Is.GreaterThan(500));
        }
    }
}
