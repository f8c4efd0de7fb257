using System.Collections.Generic;
using NUnit.Framework;

namespace HeadGait.Tests
{
    public class MetricsTests
    {
        /// <summary>Labels of 10 s of walking at 100 Hz, stride 1.1 s, shifted in time by shiftSeconds.</summary>
        static void Labels(double shiftSeconds, List<double> times, List<GaitPhase> left, List<GaitPhase> right)
        {
            for (int i = 0; i < 1000; i++)
            {
                double t = i * 0.01;
                times?.Add(t);
                double s = (t - shiftSeconds) / 1.1;
                bool walking = t - shiftSeconds >= 1.0;
                left.Add(walking ? PhaseMap.Perry.PhaseAt(Foot.Left, s) : GaitPhase.Standing);
                right.Add(walking ? PhaseMap.Perry.PhaseAt(Foot.Right, s) : GaitPhase.Standing);
            }
        }

        [Test]
        public void PerfectPredictionScoresZero()
        {
            var t = new List<double>(); var l = new List<GaitPhase>(); var r = new List<GaitPhase>();
            Labels(0, t, l, r);
            var m = GaitMetrics.Compute(t, l, r, l, r);
            Assert.That(m.MisclassificationRate, Is.EqualTo(0));
            Assert.That(m.Rmse, Is.EqualTo(0));
            Assert.That(m.MeanDelayMs, Is.EqualTo(0));
            Assert.That(m.MatchedOnsets, Is.EqualTo(m.TrueOnsets));
            Assert.That(m.Comparisons, Is.EqualTo(2000));
        }

        [Test]
        public void AWalkBrokenIntoFragmentsCountsEachAsABout()
        {
            var t = new List<double>(); var l = new List<GaitPhase>(); var r = new List<GaitPhase>();
            Labels(0, t, l, r);
            var pl = new List<GaitPhase>(l); var pr = new List<GaitPhase>(r);
            Assert.That(GaitMetrics.Compute(t, l, r, pl, pr).BoutsPerWalk, Is.EqualTo(1), "one walk shown as one");
            // Standing shown for 0.2 s twice in the middle of the walk: three bouts where there was one.
            foreach (int from in new[] { 400, 700 })
                for (int i = from; i < from + 20; i++) pl[i] = pr[i] = GaitPhase.Standing;
            var m = GaitMetrics.Compute(t, l, r, pl, pr);
            Assert.That(m.TrueWalkingBouts, Is.EqualTo(1));
            Assert.That(m.ShownWalkingBouts, Is.EqualTo(3));
            Assert.That(GaitMetrics.Pool(new[] { m, m }).BoutsPerWalk, Is.EqualTo(3));
        }

        /// <summary>Per-sample walking (true) or standing (false) at 100 Hz from the given runs of seconds, as phases.</summary>
        static List<GaitPhase> Activity(params (bool walking, double seconds)[] runs)
        {
            var phases = new List<GaitPhase>();
            foreach (var (walking, seconds) in runs)
                for (int i = 0; i < (int)System.Math.Round(seconds * 100); i++)
                    phases.Add(walking ? GaitPhase.MidStance : GaitPhase.Standing);
            return phases;
        }

        static GaitMetrics CompareActivity(List<GaitPhase> truth, List<GaitPhase> predicted)
        {
            var t = new List<double>();
            for (int i = 0; i < truth.Count; i++) t.Add(i * 0.01);
            return GaitMetrics.Compute(t, truth, truth, predicted, predicted);
        }

        [Test]
        public void StartAndStopDelaysMeasureEachWalkInsideTheRecording()
        {
            var truth = Activity((false, 1), (true, 3), (false, 1), (true, 2), (false, 1));
            // The first walk shown 0.4 s late and 0.3 s too long; the second from 0.2 s early to 0.1 s short.
            var shown = Activity((false, 1.4), (true, 2.9), (false, 0.5), (true, 2.1), (false, 1.1));
            var m = CompareActivity(truth, shown);
            Assert.That(m.Starts, Is.EqualTo(2));
            Assert.That(m.Stops, Is.EqualTo(2));
            Assert.That(m.MeanStartDelaySeconds, Is.EqualTo((0.4 - 0.2) / 2).Within(1e-9));
            Assert.That(m.MeanStopDelaySeconds, Is.EqualTo((0.3 - 0.1) / 2).Within(1e-9));
            var pooled = GaitMetrics.Pool(new[] { m, CompareActivity(truth, truth) });
            Assert.That(pooled.Starts, Is.EqualTo(4));
            Assert.That(pooled.MeanStartDelaySeconds, Is.EqualTo(0.2 / 4).Within(1e-9));
        }

        [Test]
        public void WalksCutByTheRecordingOrNeverShownHaveNoStartOrStop()
        {
            // Walking at both edges: no start and no stop inside the recording.
            var edges = CompareActivity(Activity((true, 2), (false, 1), (true, 2)), Activity((true, 5)));
            Assert.That(edges.Starts, Is.EqualTo(1), "the second walk starts inside");
            Assert.That(edges.Stops, Is.EqualTo(1), "the first walk stops inside");
            Assert.That(edges.MeanStartDelaySeconds, Is.EqualTo(-3).Within(1e-9), "shown since the recording began");
            Assert.That(edges.MeanStopDelaySeconds, Is.EqualTo(2.99).Within(1e-9), "still shown at the last sample");
            var missed = CompareActivity(Activity((false, 1), (true, 1), (false, 1)), Activity((false, 3)));
            Assert.That(missed.Starts + missed.Stops, Is.EqualTo(0));
            Assert.That(double.IsNaN(missed.MeanStartDelaySeconds));
        }

        [Test]
        public void LatePredictionHasPositiveDelay()
        {
            var t = new List<double>(); var l = new List<GaitPhase>(); var r = new List<GaitPhase>();
            var pl = new List<GaitPhase>(); var pr = new List<GaitPhase>();
            Labels(0, t, l, r);
            Labels(0.04, null, pl, pr);
            var m = GaitMetrics.Compute(t, l, r, pl, pr);
            Assert.That(m.MeanDelayMs, Is.EqualTo(40).Within(1));
            Assert.That(m.MedianDelayMs, Is.EqualTo(40).Within(1));
            Assert.That(m.MeanInitialContactDelayMs, Is.EqualTo(40).Within(1));
            // Each foot changes phase 8 times per 1.1 s stride over 9 s of walking; 40 ms late is wrong 4 samples per change.
            Assert.That(m.MisclassificationRate, Is.EqualTo(0.9 * 8 * 0.04 / 1.1).Within(0.015));
            Assert.That(m.Cep50, Is.EqualTo(0));
            Assert.That(m.Cep95, Is.GreaterThanOrEqualTo(1));
        }

        [Test]
        public void EarlyPredictionHasNegativeDelay()
        {
            var t = new List<double>(); var l = new List<GaitPhase>(); var r = new List<GaitPhase>();
            var pl = new List<GaitPhase>(); var pr = new List<GaitPhase>();
            Labels(0.1, t, l, r);
            Labels(0.03, null, pl, pr);
            var m = GaitMetrics.Compute(t, l, r, pl, pr);
            Assert.That(m.MeanDelayMs, Is.EqualTo(-70).Within(1));
        }

        [Test]
        public void StandingAgainstWalkingIsTheLargestError()
        {
            var t = new List<double> { 0, 0.01, 0.02, 0.03 };
            var truth = new List<GaitPhase> { GaitPhase.Standing, GaitPhase.Standing, GaitPhase.MidStance, GaitPhase.MidStance };
            var pred = new List<GaitPhase> { GaitPhase.Standing, GaitPhase.MidSwing, GaitPhase.Standing, GaitPhase.TerminalStance };
            var m = GaitMetrics.Compute(t, truth, truth, pred, pred);
            Assert.That(m.MisclassificationRate, Is.EqualTo(0.75));
            Assert.That(m.ActivityErrorRate, Is.EqualTo(0.5));
            Assert.That(m.Mae, Is.EqualTo((0 + 4 + 4 + 1) / 4.0));
            Assert.That(m.Rmse, Is.EqualTo(System.Math.Sqrt((16 + 16 + 1) / 4.0)).Within(1e-12));
            Assert.That(m.Cep25, Is.EqualTo(0));
            Assert.That(m.Cep75, Is.EqualTo(4));
        }

        [Test]
        public void PercentileIsNearestRank()
        {
            var v = new List<double> { 1, 2, 3, 4, 5, 6, 7, 8, 9, 10 };
            Assert.That(GaitMetrics.Percentile(v, 0.25), Is.EqualTo(3));
            Assert.That(GaitMetrics.Percentile(v, 0.95), Is.EqualTo(10));
            Assert.That(GaitMetrics.Percentile(new List<double>(), 0.5), Is.NaN);
        }

        [Test]
        public void MismatchedLengthsAreRefused()
        {
            var a = new List<GaitPhase> { GaitPhase.Standing };
            Assert.That(() => GaitMetrics.Compute(new List<double> { 0, 1 }, a, a, a, a), Throws.ArgumentException);
        }

        [Test]
        public void PerRecordingScoresCarryEachReplaysMetricsOneRowPerOutput()
        {
            var walk = TestData.Eval("start_stop");
            var odd = new Recording("walk, \"quoted\"", walk.Samples);
            var results = new List<ReplayResult>
            {
                ReplayEvaluator.Run(walk, new ThresholdClassifier(TestData.Threshold)),
                ReplayEvaluator.Run(odd, new CorrelationClassifier(TestData.Template)),
            };
            var writer = new System.IO.StringWriter();
            var rows = results.ConvertAll(r => new RecordingScoresCsv.Row { Scheme = "style", Fold = "bn/act", Result = r });
            rows[1] = new RecordingScoresCsv.Row { Scheme = "style", Fold = "bn/act", Variant = "slow", Result = results[1] };
            RecordingScoresCsv.Write(writer, rows);
            var lines = writer.ToString().TrimEnd('\n', '\r').Split('\n');
            Assert.That(lines[0].TrimEnd('\r'), Is.EqualTo(RecordingScoresCsv.Header));
            Assert.That(lines.Length, Is.EqualTo(5), "header, then classifier and avatar rows per replay");

            var header = new List<string>(RecordingScoresCsv.Header.Split(','));
            var thrAvatar = lines[2].TrimEnd('\r').Split(',');
            var m = results[0].AnimatorMetrics;
            Assert.That(thrAvatar[header.IndexOf("recording")], Is.EqualTo("start_stop"));
            Assert.That(thrAvatar[header.IndexOf("variant")], Is.EqualTo(RecordingScoresCsv.AsRecorded), "a row without a variant is the clip as recorded");
            Assert.That(thrAvatar[header.IndexOf("classifier")], Is.EqualTo("THR"));
            Assert.That(thrAvatar[header.IndexOf("output")], Is.EqualTo("avatar"));
            Assert.That(double.Parse(thrAvatar[header.IndexOf("miscl")], System.Globalization.CultureInfo.InvariantCulture), Is.EqualTo(m.MisclassificationRate).Within(1e-6));
            Assert.That(double.Parse(thrAvatar[header.IndexOf("standing_as_walking")], System.Globalization.CultureInfo.InvariantCulture), Is.EqualTo(m.StandingAsWalking).Within(1e-6));
            Assert.That(int.Parse(thrAvatar[header.IndexOf("true_steps")]), Is.EqualTo(m.TrueSteps).And.GreaterThan(5));
            Assert.That(int.Parse(thrAvatar[header.IndexOf("predicted_steps")]), Is.EqualTo(m.PredictedSteps));
            Assert.That(double.Parse(thrAvatar[header.IndexOf("step_timing_ms")], System.Globalization.CultureInfo.InvariantCulture),
                Is.EqualTo(m.StepTimingMeanMs).Within(0.05).And.Not.EqualTo(0), "the matched contacts' mean timing, to 0.1 ms");
            Assert.That(lines[3], Does.StartWith("style,bn/act,slow,\"walk, \"\"quoted\"\"\",COR,clf,"), "a name with a comma or quote is quoted");
        }
    }
}
