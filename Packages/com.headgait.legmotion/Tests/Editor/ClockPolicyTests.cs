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
    }
}
