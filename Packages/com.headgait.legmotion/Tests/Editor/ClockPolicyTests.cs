using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>The live pipeline's clock policy: no timestamp, however wrong, freezes the avatar.</summary>
    public class ClockPolicyTests
    {
        static Recording Edited(string name, Func<int, RecordedSample, RecordedSample?> edit, Func<int, RecordedSample?> insertAfter = null)
        {
            var source = TestData.Eval("walk_straight");
            var rows = new List<RecordedSample>();
            for (int i = 0; i < source.Samples.Count; i++)
            {
                var e = edit(i, source.Samples[i]);
                if (e.HasValue) rows.Add(e.Value);
                var extra = insertAfter?.Invoke(i);
                if (extra.HasValue) rows.Add(extra.Value);
            }
            return new Recording(name, rows);
        }

        static RecordedSample At(RecordedSample s, double time)
            => new RecordedSample(new ImuSample(time, s.Imu.X, s.Imu.Y, s.Imu.Z), s.Left, s.Right, s.Line);

        static IGaitClassifier Cor() => new CorrelationClassifier(TestData.Template);

        [Test]
        public void OneFutureTimestampIsHeldAndDroppedNotTakenAsTheClock()
        {
            // Regression: a single sample stamped +1e6 s used to become the reference time; every later sample was then
            // "out of order" and the avatar froze in Walking.
            var source = TestData.Eval("walk_straight");
            int glitch = source.Samples.Count / 2;
            var rec = Edited("future", (i, s) => s, i => i == glitch ? At(source.Samples[i], source.Samples[i].Imu.Time + 1e6) : (RecordedSample?)null);
            var clean = ReplayEvaluator.Run(source, Cor());
            var r = ReplayEvaluator.Run(rec, Cor());
            Assert.That(r.SkippedSamples, Is.EqualTo(1));
            Assert.That(r.Windows, Is.EqualTo(clean.Windows).Within(2));
            Assert.That(r.ClassifierMetrics.MisclassificationRate, Is.EqualTo(clean.ClassifierMetrics.MisclassificationRate).Within(0.01));
        }

        [TestCase(-30.0)]
        [TestCase(+1000.0)]
        [TestCase(-1e5)]
        public void AClockThatJumpsForGoodIsFollowedAfterAFewSamples(double jump)
        {
            var source = TestData.Eval("walk_straight");
            double cut = source.Samples[source.Samples.Count / 2].Imu.Time;
            var rec = Edited("jump", (i, s) => s.Imu.Time >= cut ? At(s, s.Imu.Time + jump) : s);
            var pipeline = new GaitPipeline(Cor());
            double firstWalkingAfter = double.NaN;
            int rebasedAt = -1;
            for (int i = 0; i < rec.Samples.Count; i++)
            {
                var outcome = pipeline.Push(rec.Samples[i].Imu);
                if (outcome == SampleOutcome.AcceptedAfterRebase)
                {
                    rebasedAt = i;
                    Assert.That(pipeline.Latest.State, Is.EqualTo(LocomotionState.Standing), "the avatar settles instead of freezing mid-stride");
                }
                if (rebasedAt >= 0 && double.IsNaN(firstWalkingAfter) && pipeline.LatestPrediction.IsWalking && pipeline.LatestPrediction.Time >= cut + jump)
                    firstWalkingAfter = rec.Samples[i].Imu.Time - (cut + jump);
            }
            Assert.That(pipeline.Preprocessor.Rebases, Is.EqualTo(1));
            Assert.That(pipeline.Preprocessor.SkippedSuspectTime, Is.EqualTo(0), "the held samples were used once the clock was confirmed");
            Assert.That(firstWalkingAfter, Is.LessThan(1.0), "walking is recognised again within a second of the new clock");
        }

        [Test]
        public void LateSamplesAreSkippedAndAHoleRestartsTheWindow()
        {
            var pre = new StreamPreprocessor();
            Assert.That(pre.Push(new ImuSample(10.00, 0, 0, 9.8), null), Is.EqualTo(SampleOutcome.Accepted));
            Assert.That(pre.Push(new ImuSample(10.01, 0, 0, 9.8), null), Is.EqualTo(SampleOutcome.Accepted));
            Assert.That(pre.Push(new ImuSample(9.95, 0, 0, 9.8), null), Is.EqualTo(SampleOutcome.SkippedOutOfOrder));
            Assert.That(pre.Push(new ImuSample(10.01, 0, 0, 9.8), null), Is.EqualTo(SampleOutcome.SkippedDuplicateTime));
            Assert.That(pre.Push(new ImuSample(10.50, 0, 0, 9.8), null), Is.EqualTo(SampleOutcome.AcceptedAfterGap));
            Assert.That(pre.Push(new ImuSample(20.00, 0, 0, 9.8), null), Is.EqualTo(SampleOutcome.SkippedSuspectTime));
            Assert.That(pre.Push(new ImuSample(10.51, 0, 0, 9.8), null), Is.EqualTo(SampleOutcome.Accepted), "the old clock goes on");
            Assert.That(pre.SkippedSuspectTime, Is.EqualTo(1));
            Assert.That(pre.Rebases, Is.EqualTo(0));
        }

        [Test]
        public void WhatThePolicySkippedIsDescribedByReason()
        {
            var pre = new StreamPreprocessor();
            Assert.That(pre.DescribeSkips(), Is.Empty, "a fresh stream has skipped nothing");
            pre.Push(new ImuSample(10.00, 0, 0, 9.8), null);
            pre.Push(new ImuSample(10.01, 0, 0, 9.8), null);
            pre.Push(new ImuSample(9.95, 0, 0, 9.8), null);
            pre.Push(new ImuSample(9.96, 0, 0, 9.8), null);
            pre.Push(new ImuSample(10.01, 0, 0, 9.8), null);
            pre.Push(new ImuSample(10.02, double.NaN, 0, 9.8), null);
            pre.Push(new ImuSample(10.50, 0, 0, 9.8), null);
            Assert.That(pre.DescribeSkips(),
                Is.EqualTo("skipped 4 sample(s): 2 out of time order, 1 with a repeated time, 1 not finite; 1 hole(s), 0 clock re-base(s)"));
        }
    
        /// <summary>A generated walk: <paramref name="seconds"/> of walking from a standing start, as plain samples.</summary>
        static List<ImuSample> Walk(double seconds, ulong seed = 5)
        {
            var rec = HeadGait.Synthetic.WalkingStreamGenerator.Generate("walk", new HeadGait.Synthetic.GaitSubject(),
                new HeadGait.Synthetic.StreamScript { StartTime = 0 }.Walk(seconds, Foot.Left), seed);
            var list = new List<ImuSample>();
            foreach (var r in rec.Samples) list.Add(r.Imu);
            return list;
        }

        static ImuSample Shifted(ImuSample s, double origin, double scale = 1) => new ImuSample(origin + scale * s.Time, s.X, s.Y, s.Z);

        /// <summary>
        /// Pushes the stream, collecting every warning the pipeline's preprocessor gives, and returns how long after
        /// <paramref name="cleanFrom"/> (a sample index) the first window came and walking was first recognised (NaN: never).
        /// </summary>
        static (double window, double walking) Replay(GaitPipeline pipeline, List<ImuSample> samples, int cleanFrom, List<string> warnings)
        {
            double window = double.NaN, walking = double.NaN;
            long windowsBefore = 0;
            for (int i = 0; i < samples.Count; i++)
            {
                if (i == cleanFrom) windowsBefore = pipeline.Windows;
                pipeline.Push(samples[i]);
                string w = pipeline.Preprocessor.TakeWarning();
                if (w != null) warnings.Add(w);
                if (i < cleanFrom) continue;
                double since = samples[i].Time - samples[cleanFrom].Time;
                if (double.IsNaN(window) && pipeline.Windows > windowsBefore) window = since;
                if (double.IsNaN(walking) && pipeline.LatestPrediction.IsWalking) walking = since;
            }
            return (window, walking);
        }

        [Test]
        public void EpochMicrosecondsReadAsSecondsAreRefusedOnceAndTheAvatarStands()
        {
            // Regression: 60 s of walking stamped 1.7e15 + t (a double there resolves 0.25 s) froze the stream: every sample was
            // a repeated time or a hole, no window ever came and nothing said why.
            var walk = Walk(60);
            var samples = new List<ImuSample>();
            foreach (var s in walk) samples.Add(Shifted(s, 1.7e15));
            int clean = samples.Count;
            foreach (var s in Walk(10, 6)) samples.Add(s); // the app notices and stamps seconds since start-up
            var pipeline = new GaitPipeline(Cor());
            var warnings = new List<string>();
            long windowsInEpoch = -1;
            for (int i = 0; i < clean; i++)
            {
                pipeline.Push(samples[i]);
                string w = pipeline.Preprocessor.TakeWarning();
                if (w != null) warnings.Add(w);
                Assert.That(pipeline.Latest.State, Is.EqualTo(LocomotionState.Standing), "the avatar stands while the clock is refused");
            }
            windowsInEpoch = pipeline.Windows;
            var (window, walking) = Replay(pipeline, samples.GetRange(clean, samples.Count - clean), 0, warnings);
            TestContext.WriteLine(string.Join("\n", warnings));
            Assert.That(windowsInEpoch, Is.EqualTo(0));
            Assert.That(pipeline.Preprocessor.SkippedCoarseClock, Is.EqualTo(clean));
            Assert.That(warnings, Has.Count.EqualTo(1), "refused once, with one warning");
            Assert.That(warnings[0], Does.Contain("1.7E+15").And.Contain("seconds"));
            Assert.That(pipeline.Preprocessor.DescribeSkips(), Does.Contain("too large to resolve"));
            Assert.That(window, Is.LessThan(1.0), "windows resume within a second of a usable clock");
            Assert.That(walking, Is.LessThan(1.0), "and walking is recognised within a second");
        }

        [Test]
        public void AClockThatTurnsCoarseMidWalkLeavesTheAvatarStanding()
        {
            var walk = Walk(10);
            var pipeline = new GaitPipeline(Cor());
            int half = walk.Count / 2;
            for (int i = 0; i < half; i++) pipeline.Push(walk[i]);
            Assert.That(pipeline.Latest.State, Is.Not.EqualTo(LocomotionState.Standing), "walking before the clock goes wrong");
            pipeline.Push(Shifted(walk[half], 1.7e15));
            Assert.That(pipeline.Latest.State, Is.EqualTo(LocomotionState.Standing), "a refused clock settles the avatar at once");
        }

        [TestCase(1.7e9)]   // an epoch in seconds
        [TestCase(-3e5)]
        [TestCase(1e11)]
        public void LargeButResolvableClocksWorkAsAnyOther(double origin)
        {
            var walk = Walk(20);
            var plain = new GaitPipeline(Cor());
            foreach (var s in walk) plain.Push(s);
            var shifted = new GaitPipeline(Cor());
            var warnings = new List<string>();
            var samples = walk.ConvertAll(s => Shifted(s, origin));
            var (_, walking) = Replay(shifted, samples, 0, warnings);
            Assert.That(warnings, Is.Empty);
            Assert.That(shifted.Windows, Is.EqualTo(plain.Windows).Within(2));
            Assert.That(walking, Is.LessThan(2.0));
        }

        /// <summary>
        /// Every rate from 1 Hz to 2 kHz: 20 s of walking at that rate, then walking at 100 Hz on the same clock. At or above the
        /// lowest rate windows come; below it the avatar stands with one warning; either way no exception, and after the slow
        /// part windows resume within a second.
        /// </summary>
        [TestCase(1.0)]
        [TestCase(2.0)]
        [TestCase(5.0)]
        [TestCase(8.0)]
        [TestCase(9.5)]
        [TestCase(10.0)]
        [TestCase(12.0)]
        [TestCase(20.0)]
        [TestCase(50.0)]
        [TestCase(200.0)]
        [TestCase(1000.0)]
        [TestCase(2000.0)]
        public void EveryRateFromOneHertzToTwoKilohertzWorksOrStandsWithOneWarning(double rate)
        {
            var settings = new PreprocessorSettings();
            var walk = Walk(20);
            var samples = new List<ImuSample>();
            int n = (int)(20 * rate);
            // Sampled from the 100 Hz walk at the nearest sample (the rate is what matters here, not the interpolation).
            for (int i = 0; i < n; i++)
            {
                double t = i / rate;
                var s = walk[Math.Min(walk.Count - 1, (int)Math.Round(t * 100))];
                samples.Add(new ImuSample(t, s.X, s.Y, s.Z));
            }
            int clean = samples.Count;
            double resume = samples[clean - 1].Time + 0.01;
            foreach (var s in Walk(10, 6)) samples.Add(Shifted(s, resume));
            var pipeline = new GaitPipeline(Cor());
            var warnings = new List<string>();
            long slowWindows = 0;
            pipeline.FrameProduced += (p, f) => { if (p.Time < resume) slowWindows++; };
            var (window, walking) = Replay(pipeline, samples, clean, warnings);
            TestContext.WriteLine($"{rate} Hz: {slowWindows} windows, {string.Join("; ", warnings)}; window after {window:F2} s, walking after {walking:F2} s");
            if (rate >= settings.LowestRate)
            {
                Assert.That(slowWindows, Is.GreaterThan(0), "at or above the lowest rate windows come");
                Assert.That(warnings, Is.Empty);
            }
            else
            {
                Assert.That(slowWindows, Is.EqualTo(0));
                Assert.That(warnings, Has.Count.EqualTo(1), "below the lowest rate: one warning");
                Assert.That(warnings[0], Does.Contain("lowest rate of 10 Hz"));
            }
            Assert.That(window, Is.LessThan(1.0), "windows resume within a second of the clean stream");
            Assert.That(walking, Is.LessThan(1.5), "walking is recognised again");
        }

        /// <summary>
        /// Every classifier through the extreme rates and an epoch clock, each followed by clean walking at 100 Hz: no
        /// exception, windows again within a second, walking recognised within the hostile-stream bounds (FuzzTests).
        /// </summary>
        [TestCase("thr", 1.2)]
        [TestCase("svm", 1.6)]
        [TestCase("blstm", 1.6)]
        public void EveryClassifierComesBackFromExtremeRatesAndEpochClocks(string name, double within)
        {
            var models = TestData.ShippedModels();
            var walk = Walk(8);
            foreach (double rate in new[] { 1.0, 9.5, 10.0, 2000.0, -1 })
            {
                var samples = new List<ImuSample>();
                if (rate < 0) foreach (var s in walk) samples.Add(Shifted(s, 1.7e15)); // epoch microseconds read as seconds
                else
                    for (int i = 0; i < (int)(8 * rate); i++)
                    {
                        var s = walk[Math.Min(walk.Count - 1, (int)Math.Round(i / rate * 100))];
                        samples.Add(new ImuSample(i / rate, s.X, s.Y, s.Z));
                    }
                int clean = samples.Count;
                double resume = rate < 0 ? 50 : samples[clean - 1].Time + 0.01;
                foreach (var s in Walk(8, 6)) samples.Add(Shifted(s, resume));
                var pipeline = new GaitPipeline(models.Create(name, out _));
                var (window, walking) = Replay(pipeline, samples, clean, new List<string>());
                string what = rate < 0 ? "epoch 1.7e15" : $"{rate} Hz";
                Assert.That(window, Is.LessThan(1.0), $"{name} after {what}: windows again");
                Assert.That(walking, Is.LessThan(within), $"{name} after {what}: walking recognised");
            }
        }

        [Test]
        public void TheLowestRateIsStatedOnceAndMillisecondClocksAreNamed()
        {
            Assert.That(new PreprocessorSettings().LowestRate, Is.EqualTo(10).Within(1e-9));
            // Epoch milliseconds read as seconds: 10 "seconds" between 100 Hz samples.
            var pipeline = new GaitPipeline(Cor());
            var warnings = new List<string>();
            var walk = Walk(5);
            Replay(pipeline, walk.ConvertAll(s => Shifted(s, 1.7e9, 1000)), 0, warnings);
            Assert.That(pipeline.Windows, Is.EqualTo(0));
            Assert.That(warnings, Has.Count.EqualTo(1));
            Assert.That(warnings[0], Does.Contain("milliseconds"));
        }

        [TestCase(25.0, false)]
        [TestCase(20.0, false)]
        [TestCase(8.0, false)]
        [TestCase(30.0, true)]
        [TestCase(72.0, true)]
        public void ThePosePathStatesItsLowestRateAndWarnsOnceBelowIt(double rate, bool gives)
        {
            var estimator = new PoseAccelerationEstimator();
            int samples = 0, warnings = 0;
            for (int i = 0; i < (int)(10 * rate); i++)
            {
                double t = i / rate;
                if (estimator.Push(t, 0, 1.7 + 0.02 * Math.Sin(2 * Math.PI * 2 * t), 1.2 * t, 0, 0, 0, 1, out _)) samples++;
                if (estimator.TakeWarning() != null) warnings++;
            }
            Assert.That(rate >= estimator.LowestRate, Is.EqualTo(gives), $"lowest pose rate {estimator.LowestRate:F1} Hz");
            if (gives)
            {
                Assert.That(samples, Is.GreaterThan(0));
                Assert.That(warnings, Is.EqualTo(0));
            }
            else
            {
                Assert.That(samples, Is.EqualTo(0));
                Assert.That(warnings, Is.EqualTo(1));
            }
        }
}
}
