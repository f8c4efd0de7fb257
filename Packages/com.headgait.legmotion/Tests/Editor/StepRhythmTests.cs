using System;
using System.Collections.Generic;
using HeadGait.Synthetic;
using HeadGait.Training;
using NUnit.Framework;

namespace HeadGait.Tests
{
    public class StepRhythmTests
    {
        /// <summary>Each full 2.5-s window's rhythm, with the time of its newest sample.</summary>
        static List<(double Time, StepRhythm Rhythm)> Rhythms(Recording r, double? levelTolerance = null)
            => TestData.PerWindow(r, StepRhythm.HistorySamples, w => (w.EndTime, StepRhythm.Of(w, levelTolerance)));

        /// <summary>Windows whose newest <paramref name="span"/> seconds (default: all 2.5 s) carry the given label kind (walking or standing) on both feet.</summary>
        static List<StepRhythm> Where(Recording r, List<(double Time, StepRhythm Rhythm)> rhythms, bool walking, double span = StepRhythm.HistorySamples / 100.0)
        {
            var kept = new List<StepRhythm>();
            var rows = r.Samples;
            int row = 0;
            foreach (var (time, rhythm) in rhythms)
            {
                bool all = true;
                while (row < rows.Count && rows[row].Imu.Time < time - span) row++;
                for (int i = row; i < rows.Count && rows[i].Imu.Time <= time; i++)
                    if ((rows[i].Left != GaitPhase.Standing) != walking || (rows[i].Right != GaitPhase.Standing) != walking) all = false;
                if (all) kept.Add(rhythm);
            }
            return kept;
        }

        static double ShareWalking(List<StepRhythm> rhythms)
        {
            int n = 0;
            foreach (var r in rhythms) if (r.IsWalking) n++;
            return rhythms.Count == 0 ? double.NaN : (double)n / rhythms.Count;
        }

        static double MedianPeriod(List<StepRhythm> rhythms)
        {
            var p = new List<double>();
            foreach (var r in rhythms) p.Add(r.Period);
            p.Sort();
            return p[p.Count / 2];
        }

        [Test]
        public void AWalkKeepsItsRhythmHoweverCalm()
        {
            // The generated straight walk, and the same walk 30 % slower with every movement a fifth as large: the rhythm
            // reads the shape, not the size, and finds the slower step period.
            var walk = TestData.Eval("walk_straight");
            var calm = RecordingAugmentation.Transform(walk, 1.3, 0.2, 0.2, 0.2, new AugmentationSettings().SlowWindowSeconds, "calm");
            var brisk = Where(walk, Rhythms(walk), true);
            var slow = Where(calm, Rhythms(calm), true);
            Assert.That(brisk.Count, Is.GreaterThan(1000));
            Assert.That(ShareWalking(brisk), Is.GreaterThan(0.9));
            Assert.That(ShareWalking(slow), Is.GreaterThan(0.8));
            double period = MedianPeriod(brisk);
            Assert.That(period, Is.InRange(StepRhythm.ShortestStep, StepRhythm.LongestStep));
            Assert.That(MedianPeriod(slow), Is.EqualTo(1.3 * period).Within(0.05));
        }

        [Test]
        public void StandingWithNodsHasNoWalkingRhythm()
        {
            // The generated start-stop walk stands 4 s between walks, nodding: no window inside a stand keeps the rhythm,
            // nor one whose newest second is standing after a walk, though its older samples still hold the walk's rhythm.
            var rec = TestData.Eval("start_stop");
            var rhythms = Rhythms(rec);
            var standing = Where(rec, rhythms, false);
            Assert.That(standing.Count, Is.GreaterThan(100));
            Assert.That(ShareWalking(standing), Is.EqualTo(0));
            var justStopped = Where(rec, rhythms, false, 1.0);
            Assert.That(justStopped.Count, Is.GreaterThan(standing.Count + 300));
            Assert.That(ShareWalking(justStopped), Is.EqualTo(0));
            Assert.That(justStopped.FindAll(r => r.Bounce > StepRhythm.MinBounce && r.Sway < StepRhythm.MaxSway).Count, Is.GreaterThan(50),
                "windows that still hold the walk's rhythm in their older samples");
        }

        [Test]
        public void AWalkWithoutTheSidewaysSwayIsNoRhythm()
        {
            // The bounce alone is not a walk (a nod or a bob on the spot repeats too): the same walk with its sideways
            // acceleration replaced by noise as large as the sway keeps no rhythm.
            var walk = TestData.Eval("walk_straight");
            var random = new DeterministicRandom(5);
            var rows = new List<RecordedSample>();
            foreach (var s in walk.Samples)
                rows.Add(new RecordedSample(new ImuSample(s.Imu.Time, s.Imu.X, 0.3 * random.NextGaussian(), s.Imu.Z), s.Left, s.Right));
            var noSway = new Recording("no sway", rows);
            Assert.That(ShareWalking(Where(noSway, Rhythms(noSway), true)), Is.LessThan(0.01));
            Assert.That(ShareWalking(Where(walk, Rhythms(walk), true)), Is.GreaterThan(0.9));
        }

        [Test]
        public void ATiltedWalkKeepsItsRhythmLevelled()
        {
            var tilted = RecordingAugmentation.Tilted(TestData.Eval("walk_straight"));
            Assert.That(ShareWalking(Where(tilted, Rhythms(tilted, WindowLevel.ToleranceDegrees), true)), Is.GreaterThan(0.9));
        }

        [Test]
        public void TheRhythmKeptInTheStreamedWindowIsThatWindowsOwnAtEachTolerance()
        {
            // The hold, the step clock and the gate ask the preprocessor's window in turn, at the gate's tolerance or none;
            // each must get what a fresh copy of that fill measures, never a reading of the fill before or of the other tolerance.
            var tilted = RecordingAugmentation.Tilted(TestData.Eval("walk_straight"));
            double? level = WindowLevel.ToleranceDegrees;
            int differing = 0;
            var readings = TestData.PerWindow(tilted, StepRhythm.HistorySamples, w =>
            {
                var copy = w.Clone();
                var asked = new[] { StepRhythm.Of(w, level), StepRhythm.Of(w, null), StepRhythm.Of(w, null), StepRhythm.Of(w, level) };
                var fresh = new[] { StepRhythm.Of(copy, level), StepRhythm.Of(copy, null), StepRhythm.Of(copy, null), StepRhythm.Of(copy, level) };
                if (!fresh[0].Equals(fresh[1])) differing++;
                return (asked, fresh);
            });
            Assert.That(readings.Count, Is.GreaterThan(100));
            foreach (var (asked, fresh) in readings) Assert.That(asked, Is.EqualTo(fresh));
            Assert.That(differing, Is.GreaterThan(readings.Count / 2), "levelling changes the tilted walk's rhythm, so a reading of the other tolerance would show");
        }

        [Test]
        public void TooShortAHistoryHasNoRhythm()
        {
            var walk = TestData.Eval("walk_straight");
            var pre = new StreamPreprocessor(new PreprocessorSettings { History = StepRhythm.HistorySamples });
            int seen = 0;
            foreach (var s in walk.Samples)
            {
                pre.Push(s.Imu, w =>
                {
                    if (w.Count >= w.Length) return;
                    seen++;
                    Assert.That(StepRhythm.Of(w).Period, Is.EqualTo(0));
                    Assert.That(StepRhythm.Of(w).IsWalking, Is.False);
                });
            }
            Assert.That(seen, Is.GreaterThan(100));
        }

        [Test]
        public void AGateThatListensForTheRhythmPassesACalmWalkItsScoreRefuses()
        {
            // A gate whose regression refuses everything: with the rhythm it passes the walk once 2.5 s of it are in the
            // window, without it never; its text says so, and every classifier reading it keeps 2.5 s of history.
            var w = new double[WalkingGate.WeightCount];
            w[WalkingGate.InputCount] = -1;
            var deaf = new WalkingGate(w, WindowLevel.ToleranceDegrees);
            var listening = deaf.WithStepRhythm();
            var calm = RecordingAugmentation.Transform(TestData.Eval("walk_straight"), 1.3, 0.2, 0.2, 0.2, new AugmentationSettings().SlowWindowSeconds, "calm");
            var decisions = TestData.PerWindow(calm, listening.History, win => (Listening: listening.Passes(win), Deaf: deaf.Passes(win)));
            Assert.That(decisions.FindAll(d => d.Deaf).Count, Is.EqualTo(0));
            Assert.That(decisions.FindAll(d => d.Listening).Count, Is.GreaterThan(decisions.Count / 2));

            var text = listening.Serialize();
            Assert.That(text, Does.StartWith("level:15;rhythm;"));
            var read = WalkingGate.Parse(text);
            Assert.That(read.UsesStepRhythm, Is.True);
            Assert.That(read.LevelTolerance, Is.EqualTo(15));
            Assert.That(read.Weights, Is.EqualTo(w));
            Assert.That(WalkingGate.Parse(deaf.Serialize()).UsesStepRhythm, Is.False);
            Assert.That(WalkingGate.Parse("rhythm;" + string.Join(",", w)).UsesStepRhythm, Is.True);

            Assert.That(listening.History, Is.EqualTo(StepRhythm.HistorySamples));
            Assert.That(deaf.History, Is.EqualTo(WalkingGate.HistorySamples));
            var thr = new ThresholdClassifier(new ThresholdSettings { Gate = listening });
            Assert.That(thr.WindowLength, Is.EqualTo(StepRhythm.HistorySamples));
        }

        [Test]
        public void TrainedGatesListenForTheRhythm()
        {
            var gates = TestData.Gates;
            Assert.That(gates.Threshold.UsesStepRhythm && gates.Correlation.UsesStepRhythm && gates.Learned.UsesStepRhythm, Is.True);
        }

        /// <summary>
        /// A head that bumps twice per step of <paramref name="step"/> s (SMV's strongest line at twice the step rate, as
        /// in slow glasses wearers; one foot's steps bump harder, so SMV repeats better half a step later than a step later),
        /// sways sideways once per stride and surges forwards once per step.
        /// </summary>
        static Recording DoubleBumpWalk(double step, double seconds)
        {
            var rows = new List<RecordedSample>();
            for (int i = 0; i < seconds * 100; i++)
            {
                double t = i * 0.01;
                double bump = (int)Math.Floor(t / step) % 2 == 0 ? 2.0 : 1.4; // left steps bump harder than right ones
                double up = 9.80665 + bump * Math.Cos(2 * Math.PI * 2 * t / step);
                rows.Add(new RecordedSample(new ImuSample(t, 0.6 * Math.Cos(2 * Math.PI * t / step), 0.8 * Math.Sin(Math.PI * t / step), up)));
            }
            return new Recording("double bump", rows);
        }

        [Test]
        public void TheStepPeriodIsWhereTheHeadSwaysBackNotTheSecondBump()
        {
            // SMV repeats best 0.4 s later; only at 0.8 s has the head swayed to the other side.
            var rhythms = TestData.PerWindow(DoubleBumpWalk(0.8, 10), StepRhythm.HistorySamples, w => StepRhythm.Of(w));
            var full = rhythms.FindAll(r => r.Period > 0);
            Assert.That(full.Count, Is.GreaterThan(500));
            Assert.That(MedianPeriod(full), Is.EqualTo(0.8).Within(0.03));
            Assert.That(ShareWalking(full), Is.GreaterThan(0.9));
            Assert.That(full.TrueForAll(r => r.ShowsStepPeriod), Is.True);
        }

        [Test]
        public void ADetectorCountsOneStepPerStepOfTheRhythmNotEachBump()
        {
            // THR crosses its threshold at every bump, 0.4 s apart: without the rhythm its clock measures a 0.4-s period
            // from the first interval and counts every bump as a step.
            const double step = 0.8, seconds = 20;
            var settings = new ThresholdSettings { Gate = WalkingGate.Open.WithStepRhythm() };
            var thr = new ThresholdClassifier(settings);
            int contacts = 0;
            thr.ContactDetected += (t, e) => contacts++;
            var pre = new StreamPreprocessor(new PreprocessorSettings { History = thr.WindowLength });
            foreach (var s in DoubleBumpWalk(step, seconds).Samples) pre.Push(s.Imu, w => thr.Classify(w));
            Assert.That(contacts, Is.InRange(seconds / step - 4, seconds / step + 2));
        }

        /// <summary>
        /// A slow walk of <paramref name="step"/>-s steps whose every third step lands too softly for THR's threshold (a calm
        /// walker: the head's rhythm still shows the step, SMV repeating per step and the head swaying to the other side).
        /// </summary>
        static Recording SlowWalkWithSoftSteps(double step, double seconds)
        {
            var rows = new List<RecordedSample>();
            for (int i = 0; i < seconds * 100; i++)
            {
                double t = i * 0.01;
                int k = (int)Math.Floor(t / step);
                double since = t - k * step;
                double heel = (k % 3 == 2 ? 0.3 : 2.5) * Math.Exp(-since * since / (2 * 0.04 * 0.04));
                double up = 9.80665 + heel + 0.5 * Math.Cos(2 * Math.PI * t / step);
                rows.Add(new RecordedSample(new ImuSample(t, 0.5 * Math.Cos(2 * Math.PI * t / step), 0.8 * Math.Sin(Math.PI * t / step), up)));
            }
            return new Recording("slow walk, soft steps", rows);
        }

        [Test]
        public void ASlowWalkerWhoseSoftStepsGoUndetectedKeepsWalkingWhileTheRhythmShowsTheSteps()
        {
            // Every third step is missed: 1.8 s between contacts, more than the 1.5 step periods after which the clock alone
            // reports standing. The head's rhythm still shows the steps, so the walk goes on and the missed step is walked.
            const double step = 0.9, seconds = 30;
            var thr = new ThresholdClassifier(new ThresholdSettings { Gate = WalkingGate.Open.WithStepRhythm() });
            var contacts = new List<(double Time, Foot Foot)>();
            thr.ContactDetected += (t, e) => contacts.Add((t, thr.Clock.LastFoot));
            int windows = 0, walking = 0;
            var pre = new StreamPreprocessor(new PreprocessorSettings { History = thr.WindowLength });
            foreach (var s in SlowWalkWithSoftSteps(step, seconds).Samples)
                pre.Push(s.Imu, w =>
                {
                    var p = thr.Classify(w);
                    if (w.EndTime < 4) return;
                    windows++;
                    if (p.IsWalking) walking++;
                });
            Assert.That(contacts.Count, Is.InRange(seconds / step * 2 / 3 - 3, seconds / step * 2 / 3 + 1), "the soft steps are not detected");
            Assert.That((double)walking / windows, Is.GreaterThan(0.98), "walking throughout");
            // Across a missed step the same foot lands again: steps one period apart alternate, two periods apart do not.
            int right = 0, judged = 0;
            for (int i = 1; i < contacts.Count; i++)
            {
                if (contacts[i].Time < 4) continue;
                bool twoSteps = contacts[i].Time - contacts[i - 1].Time > 1.5 * step;
                judged++;
                if ((contacts[i].Foot == contacts[i - 1].Foot) == twoSteps) right++;
            }
            Assert.That(right, Is.EqualTo(judged), "the feet follow the steps");
        }

        /// <summary>
        /// Standing, then bending down to the floor and straightening again <paramref name="times"/> times: the head pitches
        /// forward by <paramref name="degrees"/> over 0.8 s, stays down a second and comes up over 0.6 s, landing with a jolt of 3 m/s^2 that
        /// bumps SMV like a heel strike.
        /// </summary>
        static Recording PickingThingsUp(int times, double degrees = 70)
        {
            var rows = new List<RecordedSample>();
            const double g = 9.80665, cycle = 6;
            for (int i = 0; i < (2 + times * cycle) * 100; i++)
            {
                double t = i * 0.01, c = (t - 2) % cycle;
                double pitch = 0;
                if (t >= 2)
                {
                    if (c < 0.8) pitch = c / 0.8;
                    else if (c < 1.8) pitch = 1;
                    else if (c < 2.4) pitch = 1 - (c - 1.8) / 0.6;
                }
                double angle = pitch * degrees * Math.PI / 180;
                double jolt = t >= 2 && c >= 2.4 ? 3 * Math.Exp(-(c - 2.45) * (c - 2.45) / (2 * 0.04 * 0.04)) : 0;
                double a = g + jolt;
                rows.Add(new RecordedSample(new ImuSample(t, a * Math.Sin(angle), 0.05 * Math.Sin(7 * t), a * Math.Cos(angle))));
            }
            return new Recording("picking things up", rows);
        }

        [Test]
        public void BendingDownToPickSomethingUpDoesNotStartAWalk()
        {
            // With a gate that passes everything, THR takes the jolt of straightening up for a first step and walks.
            var thr = new ThresholdClassifier(new ThresholdSettings { Gate = WalkingGate.Open });
            int walking = 0;
            var pre = new StreamPreprocessor(new PreprocessorSettings { History = thr.WindowLength });
            foreach (var s in PickingThingsUp(5).Samples) pre.Push(s.Imu, w => { if (thr.Classify(w).IsWalking) walking++; });
            Assert.That(walking, Is.EqualTo(0));
        }

        /// <summary>
        /// A model the bend fools: from <c>from</c> to <c>to</c> seconds into each pick-up (by default from the moment the head
        /// starts coming up until a second after the jolt of straightening), it names the stride's segments in order at a 1.1-s stride, as if walking; standing
        /// otherwise. <see cref="Time"/> is the newest sample's time of the window it scores next.
        /// </summary>
        sealed class FooledByTheBend : ILearnedEvaluator
        {
            readonly LearnedClassifier classifier;
            readonly double from, to;
            public double Time;

            public FooledByTheBend(LearnedClassifier classifier, double from = 1.8, double to = 3.4)
            {
                this.classifier = classifier;
                this.from = from;
                this.to = to;
            }

            public void Evaluate(double[] features, int windows, double[] outputs)
            {
                var segments = classifier.Segments;
                double c = (Time - 2) % 6;
                int shown = Time >= 2 && c >= from && c < to ? (int)((c - from) / 1.1 * segments.Count) % segments.Count : segments.StandingClass;
                SureOutputs.Write(classifier, shown, outputs);
            }
        }

        [TestCase(false)]
        [TestCase(true)]
        public void BendingDownToPickSomethingUpStartsNoWalkOfTheLearnedClassifiers(bool svm)
        {
            // Without the walking gate the model's word alone would walk through each straightening up.
            var models = TestData.ShippedModels();
            LearnedClassifier learned = svm ? new SvmClassifier(models.Svm) : new BlstmClassifier(models.Blstm);
            learned.Gate = null;
            var fooled = new FooledByTheBend(learned);
            learned.Evaluator = fooled;
            int walking = 0, windows = 0;
            var pre = new StreamPreprocessor(new PreprocessorSettings { History = Math.Max(learned.WindowLength, StepRhythm.HistorySamples) });
            foreach (var s in PickingThingsUp(5).Samples)
                pre.Push(s.Imu, w =>
                {
                    fooled.Time = w.EndTime;
                    windows++;
                    if (learned.Classify(w).IsWalking) walking++;
                });
            Assert.That(windows, Is.GreaterThan(2500));
            Assert.That(walking, Is.EqualTo(0));
            // The same model, the head upright: its fooled second walks.
            var upright = new FooledByTheBend(learned);
            learned.Reset();
            learned.Evaluator = upright;
            walking = 0;
            pre = new StreamPreprocessor(new PreprocessorSettings { History = Math.Max(learned.WindowLength, StepRhythm.HistorySamples) });
            for (int i = 0; i < 1400; i++)
                pre.Push(new ImuSample(i * 0.01, 0, 0, 9.80665), w =>
                {
                    upright.Time = w.EndTime;
                    if (learned.Classify(w).IsWalking) walking++;
                });
            Assert.That(walking, Is.GreaterThan(100), "the model's word walks where the head does not bend");
        }

        [TestCase(false)]
        [TestCase(true)]
        public void AWalkTheBendStartedIsWithdrawnOnceTheTiltMoves(bool svm)
        {
            // The model takes bending down (35 degrees: under the limit that ends any walk) for steps from halfway down. The
            // tilt's half-second means pass the start limit only at the bottom, after the walk began; the walk, not half a
            // second old, is withdrawn then instead of lasting as long as the model's mistake (1.2 s). The rule for walks from
            // a still head, which refuses this walk outright (PhaseFilterSettings.StillStartMaxBend), is off here.
            var models = TestData.ShippedModels();
            var filter = svm ? SvmClassifier.DefaultFilter() : new PhaseFilterSettings();
            filter.StillStartMaxBend = 0;
            LearnedClassifier learned = svm ? new SvmClassifier(models.Svm, filter) : new BlstmClassifier(models.Blstm, filter);
            learned.Gate = null;
            var fooled = new FooledByTheBend(learned, from: 0.4, to: 1.6);
            learned.Evaluator = fooled;
            int run = 0, longest = 0, walks = 0;
            var pre = new StreamPreprocessor(new PreprocessorSettings { History = Math.Max(learned.WindowLength, StepRhythm.HistorySamples) });
            foreach (var s in PickingThingsUp(5, degrees: 35).Samples)
                pre.Push(s.Imu, w =>
                {
                    fooled.Time = w.EndTime;
                    if (learned.Classify(w).IsWalking)
                    {
                        if (run++ == 0) walks++;
                        longest = Math.Max(longest, run);
                    }
                    else run = 0;
                });
            Assert.That(walks, Is.GreaterThanOrEqualTo(1), "the bend's onset fools the model into a walk");
            Assert.That(longest, Is.LessThan(70), "withdrawn within 0.7 s");
        }
    }
}
