using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using HeadGait.Calibration;
using HeadGait.Mocap;
using HeadGait.Synthetic;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>
    /// The wearer calibration's core: ankle trackers to foot labels, the fit's bounds, profiles on disk (versioned,
    /// validated, atomic, reset) and the self-supervised labels.
    /// </summary>
    public class CalibrationTests
    {
        static GaitModels shipped;
        static GaitModels Shipped => shipped ?? (shipped = TestData.ShippedModels());

        internal static Recording Unlabelled(Recording r) => new Recording(r.Name, r.Samples.Select(s => new RecordedSample(s.Imu)).ToList());

        /// <summary>The shipped THR, COR and SVM (no BLSTM: the learned refit's tests judge the SVM alone, and faster).</summary>
        static GaitModels ShippedWithSvmOnly => new GaitModels { Threshold = Shipped.Threshold, Correlation = Shipped.Correlation, Svm = Shipped.Svm };

        /// <summary>A calibration session of the generated walk: its head stream and two ankle trackers at 72 Hz.</summary>
        static CalibrationSession AnkleSession(Recording walk)
        {
            var (left, right) = SyntheticAnkles.From(walk, 72, 3);
            return new CalibrationSession(Unlabelled(walk), left, right);
        }

        internal static GaitSubject Wearer()
        {
            var s = GaitSubject.Random(12, "calm-wearer");
            s.StepFrequency = 1.5;
            s.VerticalAmplitude *= 0.6;
            return s;
        }

        internal static Recording Walk(GaitSubject wearer, ulong seed = 84)
            => WalkingStreamGenerator.Generate("calibration", wearer, new StreamScript().Stand(2).Walk(25, Foot.Left).Stand(1).Walk(25, Foot.Right, 40).Stand(3), seed);

        static double Agreement(Recording a, Recording truth) => FootContactLabeller.Agreement(a, truth);

        [Test]
        public void AnkleTrackersLabelAGeneratedWalkersFeet()
        {
            var walk = Walk(Wearer());
            var (left, right) = SyntheticAnkles.From(walk, 72, 3);
            var labelled = FootContactLabeller.Label(Unlabelled(walk), left, right);
            Assert.That(Agreement(labelled, walk), Is.GreaterThan(0.8));
            var truth = PhaseEvents.TruthContacts(walk);
            var offsets = PhaseEvents.TruthContacts(labelled).Select(c => Math.Abs(PhaseEvents.OffsetFromNearest(truth, c.Time))).ToList();
            // The made-up ankle slows as it lands, so it settles a little before the labels' contact.
            Assert.That(GaitMetrics.Median(offsets), Is.LessThan(0.04), "contacts where the walker's feet land");
            Assert.That(PhaseEvents.TruthContacts(labelled).Count, Is.EqualTo(truth.Count).Within(4));
            // Standing at the ends and in the middle stays standing.
            Assert.That(labelled.Samples.Take(100).All(s => s.Left == GaitPhase.Standing), Is.True);
        }

        [Test]
        public void AnkleTrackersFromMotionCaptureLabelLikeTheConverter()
        {
            string bvh = Path.Combine(TestData.SharedData("bvh/train"), "dataset-1_walk_feminine_001.bvh");
            if (!File.Exists(bvh)) Assert.Ignore($"{bvh} not found");
            var file = BvhFile.Load(bvh);
            var session = CalibrationSession.FromMotionCapture(file, 72);
            var converted = MocapConverter.Convert(file);
            Assert.That(session.LeftAnkle.Count, Is.EqualTo(72 * converted.Duration).Within(3));
            Assert.That(Agreement(session.Labelled(), converted), Is.GreaterThan(0.85));
        }

        [Test]
        public void WalksRecordedApartJoinIntoOneSessionOnOneClock()
        {
            // The calibration benchmark's minute is made of clips recorded apart: joined, they must read as one walk (one
            // clock, the ankles going on from where they stopped) that the ankle labeller labels like each clip alone.
            var wearer = Wearer();
            var parts = new List<CalibrationSession>();
            var truths = new List<CalibrationSession>();
            foreach (ulong seed in new[] { 84UL, 85UL, 86UL })
            {
                var walk = WalkingStreamGenerator.Generate("part" + seed, wearer, new StreamScript().Stand(1).Walk(8, Foot.Left).Stand(1), seed);
                var (left, right) = SyntheticAnkles.From(walk, 72, seed);
                parts.Add(new CalibrationSession(Unlabelled(walk), left, right));
                truths.Add(new CalibrationSession(walk));
            }
            var joined = CalibrationSession.Join(parts);
            var head = joined.Head.Samples;
            Assert.That(head.Count, Is.EqualTo(parts.Sum(p => p.Head.Samples.Count)));
            var steps = head.Zip(head.Skip(1), (a, b) => b.Imu.Time - a.Imu.Time).ToList();
            Assert.That(steps.Min(), Is.GreaterThan(0), "one clock, forward only");
            Assert.That(steps.Count(d => Math.Abs(d - CalibrationSession.JoinGapSeconds) < 1e-9), Is.EqualTo(parts.Count - 1), "the parts a join gap apart");
            foreach (var ankle in new[] { joined.LeftAnkle, joined.RightAnkle })
            {
                double fastest = ankle.Zip(ankle.Skip(1), (a, b) => Math.Sqrt(Math.Pow(b.Px - a.Px, 2) + Math.Pow(b.Pz - a.Pz, 2)) / (b.Time - a.Time)).Max();
                Assert.That(fastest, Is.LessThan(10), "the ankles go on from where the last part left them (m/s)");
            }
            var truth = CalibrationSession.Join(truths).Head;
            var labelled = joined.Labelled();
            Assert.That(Agreement(labelled, truth), Is.GreaterThan(0.8));
            Assert.That(PhaseEvents.TruthSteps(labelled).Count, Is.EqualTo(PhaseEvents.TruthSteps(truth).Count).Within(6));
            var mixed = Assert.Throws<ArgumentException>(() => CalibrationSession.Join(new[] { parts[0], truths[1] }));
            Assert.That(mixed.Message, Does.Contain("ankle streams"));
        }

        [Test]
        public void BrokenAnkleStreamsAreRefusedNamingTheStream()
        {
            var walk = Walk(Wearer());
            var (left, right) = SyntheticAnkles.From(walk, 72, 3);
            var gap = left.Where(p => p.Time < 10 || p.Time > 10.5).ToList();
            var e = Assert.Throws<ArgumentException>(() => FootContactLabeller.Label(Unlabelled(walk), gap, right));
            Assert.That(e.Message, Does.Contain("left ankle").And.Contain("loses tracking"));
            var late = right.Where(p => p.Time > 5).ToList();
            e = Assert.Throws<ArgumentException>(() => FootContactLabeller.Label(Unlabelled(walk), left, late));
            Assert.That(e.Message, Does.Contain("right ankle").And.Contain("recorded together"));
            Assert.Throws<ArgumentException>(() => FootContactLabeller.Label(Unlabelled(walk), left.Take(5).ToList(), right));
        }

        [Test]
        public void AShortWalkIsRefused()
        {
            var walk = CalibrationWalkRecorder(4);
            Assert.That(walk.End(), Is.Null);
            Assert.That(walk.State, Is.EqualTo(CalibrationWalk.Stage.Failed));
            Assert.That(walk.Prompt(0), Does.Contain("failed"));
            var shortWalk = WalkingStreamGenerator.Generate("short", Wearer(), new StreamScript().Stand(1).Walk(2, Foot.Left).Stand(1), 5);
            var e = Assert.Throws<InvalidOperationException>(() => WearerAdaptation.Fit(Shipped, new[] { shortWalk }, "w"));
            Assert.That(e.Message, Does.Contain("walk for longer"));
        }

        static CalibrationWalk CalibrationWalkRecorder(double seconds)
        {
            var walk = new CalibrationWalk(30);
            walk.Begin(0);
            for (int i = 0; i < seconds * 100; i++) walk.AddHead(new ImuSample(i * 0.01, 0, 0, 9.81));
            return walk;
        }

        [Test]
        public void TheCalibrationWalkPromptsTheWearerThroughIt()
        {
            var walk = new CalibrationWalk(60);
            Assert.That(walk.Prompt(0), Does.Contain("Start"));
            walk.Begin(100);
            Assert.That(walk.Prompt(101), Does.Contain("straight ahead"));
            Assert.That(walk.Prompt(130), Does.Contain("Turn around"));
            Assert.That(walk.Prompt(140), Does.Contain("back"));
            Assert.That(walk.Prompt(157), Does.Contain("stand still"));
            Assert.That(walk.IsDue(159), Is.False);
            Assert.That(walk.IsDue(160), Is.True);
            walk.AddHead(new ImuSample(double.NaN, 0, 0, 9.81));
            walk.AddAnkles(1, double.NaN, 0, 0, 0, 0, 0);
            Assert.That(walk.HeadSamples, Is.Zero);
            Assert.That(walk.AnklePoses, Is.Zero);
        }

        [Test]
        public void ALearnedGateOpensFurtherThanADetectorsForAWalkThatNeedsIt()
        {
            // The shipped learned gate set so that the generated wearer's walk needs it opened by 1.5 log-odds: more than a
            // detector's gate may open (1) but within the learned models' bound; a profile holding it reads back.
            var walk = new[] { Walk(Wearer()) };
            var gate = WalkingGate.Parse(Shipped.Svm.Values[WalkingGate.ModelKey]);
            double unbounded = WearerAdaptation.GateShift(gate, walk, WalkingGate.LearnedPass, 100);
            var closed = WearerProfile.OpenGate(gate, unbounded - 1.5);
            double needed = WearerAdaptation.GateShift(closed, walk, WalkingGate.LearnedPass, WearerProfile.MaxLearnedGateShift);
            Assert.That(needed, Is.GreaterThan(WearerProfile.MaxGateShift).And.LessThanOrEqualTo(WearerProfile.MaxLearnedGateShift));
            Assert.That(needed, Is.EqualTo(1.5).Within(1e-9));
            Assert.That(WearerAdaptation.GateShift(closed, walk, WalkingGate.DetectorPass, WearerProfile.MaxGateShift), Is.LessThanOrEqualTo(WearerProfile.MaxGateShift));

            var (left, right) = SyntheticAnkles.From(walk[0], 72, 3);
            var profile = new CalibrationSession(Unlabelled(walk[0]), left, right).Fit(Shipped, "calm-wearer");
            profile.LearnedGateShift = needed;
            var back = WearerProfile.Parse(profile.Serialize(), "wide.profile.txt");
            Assert.That(back.LearnedGateShift, Is.EqualTo(needed));
            var e = Assert.Throws<FormatException>(() => WearerProfile.Parse(profile.Serialize().Replace("learned_gate_shift=" + needed.ToString("R", System.Globalization.CultureInfo.InvariantCulture), "learned_gate_shift=2.5"), "wide.profile.txt"));
            Assert.That(e.Message, Does.Contain("wide.profile.txt").And.Contain("learned_gate_shift"));
        }

        [Test]
        public void AProfileRoundTripsAndDamageIsRefusedNamingTheFile()
        {
            var profile = AnkleSession(Walk(Wearer())).Fit(Shipped, "calm-wearer");
            string text = profile.Serialize();
            Assert.That(WearerProfile.Parse(text).Serialize(), Is.EqualTo(text));

            string folder = Path.Combine(Path.GetTempPath(), "headgait-profile-test-" + Guid.NewGuid().ToString("N"));
            try
            {
                var store = new WearerProfiles(folder);
                store.Save(profile);
                string path = store.PathOf("calm-wearer");
                Assert.That(File.ReadAllText(path), Is.EqualTo(text));
                Assert.That(Directory.GetFiles(folder), Has.Length.EqualTo(1), "no temporary file left behind");

                void Damaged(string from, string to, string expected)
                {
                    File.WriteAllText(path, text.Replace(from, to));
                    var e = Assert.Throws<FormatException>(() => WearerProfile.Load(path));
                    Assert.That(e.Message, Does.Contain(path).And.Contain(expected));
                    var models = store.ModelsFor("calm-wearer", Shipped, out var p, out string note);
                    Assert.That(p, Is.Null);
                    Assert.That(models, Is.SameAs(Shipped), "a damaged profile falls back to the shipped models");
                    Assert.That(note, Does.Contain(path));
                }
                Damaged(WearerProfile.Magic, "# headgait-wearer-profile v9", "first line");
                Damaged("learned_gain=", "learned_gain=9", "learned_gain");
                Damaged("cor.min_correlation=", "cor.min_correlation=x", "(cor.)");
                Damaged("thr.floor=", "thr.floor=-1", "(thr.)");
                Damaged("source=foot-references", "source=guess", "source");
                File.WriteAllText(path, text.Substring(0, text.Length / 3));
                Assert.Throws<FormatException>(() => WearerProfile.Load(path));

                // Fitted against other models: the shipped models apply, and the note says why.
                File.WriteAllText(path, text.Replace("base_models=" + profile.BaseModels, "base_models=0123456789abcdef"));
                var stale = store.ModelsFor("calm-wearer", Shipped, out var none, out string staleNote);
                Assert.That(none, Is.Null);
                Assert.That(staleNote, Does.Contain("other models"));

                store.Save(profile);
                var adapted = store.ModelsFor("calm-wearer", Shipped, out var loaded, out string ok);
                Assert.That(ok, Is.Null);
                Assert.That(loaded.Serialize(), Is.EqualTo(text));
                Assert.That(store.Wearers(), Is.EqualTo(new[] { "calm-wearer" }));
                Assert.That(store.ModelsFor("someone-else", Shipped, out _, out string missing), Is.SameAs(Shipped));
                Assert.That(missing, Does.Contain("no profile"));
                Assert.That(store.Reset("calm-wearer"), Is.True);
                Assert.That(store.ModelsFor("calm-wearer", Shipped, out _, out _), Is.SameAs(Shipped));
                Assert.Throws<ArgumentException>(() => store.PathOf("../escape"));
            }
            finally
            {
                if (Directory.Exists(folder)) Directory.Delete(folder, true);
            }
        }

        /// <summary>
        /// Wearer ids that differ only in case are one wearer (<see cref="WearerProfiles"/>). On a standalone headset the
        /// profiles lie in Android's shared storage, whose file names fold case: "anna" saved over "Anna"'s file there, and
        /// "Anna" then found a profile naming another wearer and got the shipped models. Where names keep case (here) the two
        /// were two files. Now both spellings find the one file, named as first saved, holding the last profile saved.
        /// </summary>
        [Test]
        public void WearerIdsThatDifferOnlyInCaseAreOneWearer()
        {
            var first = AnkleSession(Walk(Wearer())).Fit(Shipped, "Anna");
            string text = first.Serialize();
            Assert.That(text, Does.Contain("wearer=Anna\n"));
            var again = WearerProfile.Parse(text.Replace("wearer=Anna\n", "wearer=anna\n"));
            string folder = Path.Combine(Path.GetTempPath(), "headgait-profile-case-test-" + Guid.NewGuid().ToString("N"));
            try
            {
                var store = new WearerProfiles(folder);
                store.Save(first);
                store.Save(again);
                Assert.That(Directory.GetFiles(folder), Has.Length.EqualTo(1), "one wearer, one file");
                Assert.That(store.Wearers(), Is.EqualTo(new[] { "Anna" }), "named as first saved");
                foreach (var id in new[] { "Anna", "anna", "ANNA" })
                {
                    Assert.That(store.ModelsFor(id, Shipped, out var profile, out string note), Is.Not.SameAs(Shipped), id);
                    Assert.That(note, Is.Null, id);
                    Assert.That(profile.Wearer, Is.EqualTo("anna"), "the profile saved last");
                }
                Assert.That(store.Reset("ANNA"), Is.True);
                Assert.That(Directory.GetFiles(folder), Is.Empty);

                // Two files differing only in case, from before (or copied in): neither is guessed at, and the save is refused.
                File.WriteAllText(Path.Combine(folder, "Anna" + WearerProfile.Extension), text);
                File.WriteAllText(Path.Combine(folder, "anna" + WearerProfile.Extension), again.Serialize());
                if (Directory.GetFiles(folder).Length < 2) Assert.Pass("this file system folds case itself");
                Assert.That(store.ModelsFor("ANNA", Shipped, out var none, out string both), Is.SameAs(Shipped));
                Assert.That(none, Is.Null);
                Assert.That(both, Does.Contain("Anna" + WearerProfile.Extension).And.Contain("anna" + WearerProfile.Extension).And.Contain("differ only in case"));
                Assert.Throws<IOException>(() => store.Save(first));
                Assert.That(File.ReadAllText(Path.Combine(folder, "Anna" + WearerProfile.Extension)), Is.EqualTo(text), "nothing saved is changed");
            }
            finally
            {
                if (Directory.Exists(folder)) Directory.Delete(folder, true);
            }
        }

        [Test]
        public void TheLearnedModelsRefitToTheWearerAndKeepItThroughSaveAndLoad()
        {
            // A calm wearer's replayed calibration (head and two ankle streams): the SVM's channel gains and pair intercepts
            // refitted on the walk's labelled windows classify the same wearer's other walk better, and the profile read
            // back from disk predicts exactly as the one fitted.
            var wearer = Wearer();
            var walk = Walk(wearer);
            var models = ShippedWithSvmOnly;
            var profile = AnkleSession(walk).Fit(models, "calm-wearer");
            var svm = profile.AdjustmentFor(SvmClassifier.Kind);
            Assert.That(svm, Is.Not.Null, "the SVM's refit pays on a calm wearer's walk");
            Assert.That(svm.Changes, Is.True);
            Assert.That(svm.BiasShift, Has.All.InRange(-LearnedAdjustment.MaxBiasShift, LearnedAdjustment.MaxBiasShift));

            var other = WalkingStreamGenerator.Generate("other-walk", wearer, new StreamScript().Stand(2).Walk(20, Foot.Right).Stand(1).Walk(20, Foot.Left, -30).Stand(2), 911);
            double Misclassified(GaitModels m) => ReplayEvaluator.Run(other, m.Create("svm", out _)).ClassifierMetrics.MisclassificationRate;
            var withoutRefit = WearerProfile.Parse(profile.Serialize());
            withoutRefit.LearnedAdjustments.Clear();
            double refitted = Misclassified(profile.Apply(models)), scaledOnly = Misclassified(withoutRefit.Apply(models)), shippedOnly = Misclassified(models);
            Assert.That(refitted, Is.LessThan(scaledOnly), $"refitted {refitted:P1}, scaled only {scaledOnly:P1}, shipped {shippedOnly:P1}");

            string folder = Path.Combine(Path.GetTempPath(), "headgait-learned-profile-test-" + Guid.NewGuid().ToString("N"));
            try
            {
                var store = new WearerProfiles(folder);
                store.Save(profile);
                var loaded = store.ModelsFor("calm-wearer", models, out var back, out string note);
                Assert.That(note, Is.Null);
                Assert.That(back.AdjustmentFor(SvmClassifier.Kind).BiasShift, Is.EqualTo(svm.BiasShift));
                var a = ReplayEvaluator.Run(other, profile.Apply(models).Create("svm", out _));
                var b = ReplayEvaluator.Run(other, loaded.Create("svm", out _));
                Assert.That(b.ClassifierMetrics.MisclassificationRate, Is.EqualTo(a.ClassifierMetrics.MisclassificationRate));

                // A shift fitted against another SVM is left out, and the models say so.
                var changed = ModelFile.Parse(models.Svm.ToBytes(), "other-svm");
                var intercept = (double[])changed.Tensor("intercept", changed.ShapeOf("intercept")).Clone();
                intercept[0] += 0.5;
                changed.AddTensor("intercept", changed.ShapeOf("intercept"), intercept, true);
                var otherModels = new GaitModels { Threshold = models.Threshold, Correlation = models.Correlation, Svm = changed };
                var applied = back.Apply(otherModels);
                Assert.That(applied.Problems, Has.Some.Contains("svm adjustment was fitted against another model"));
                Assert.That(applied.Svm.HasTensor(SvmClassifier.WearerShiftTensor), Is.False, "the other model without the wearer's shifts");
                Assert.That(back.Apply(models).Svm.HasTensor(SvmClassifier.WearerShiftTensor), Is.True);
            }
            finally
            {
                if (Directory.Exists(folder)) Directory.Delete(folder, true);
            }
        }

        [Test]
        public void TheCalibrationJudgesTheSvmWithTheProductsStepClock()
        {
            // A fit scores its SVM candidates with GaitModels.SvmOf, the classifier Create("svm") gives the product: THR's
            // trained step clock beside it (PhaseFilterSettings.WalkOnStepClock). Built as the fit built it before, THR's
            // default clock decided 412 of a calm glasses wearer's 12,149 windows otherwise, so the fit judged another classifier.
            var models = Shipped;
            var fit = models.SvmOf(models.Svm);
            Assert.That(fit.WalkClockSettings, Is.SameAs(models.Threshold), "the fit's SVM keeps its walks on THR's trained clock");
            Assert.That(models.BlstmOf(models.Blstm).WalkClockSettings, Is.SameAs(models.Threshold));
            string file = Path.Combine(TestData.SharedData("glasses-train"), "cg1a_u09_e097_walking.csv");
            if (!File.Exists(file)) Assert.Ignore($"{file} not found");
            var rec = RecordingCsv.Load(file);
            var trained = ReplayEvaluator.Run(rec, fit, keepTrace: true).Predictions;
            var defaultClock = ReplayEvaluator.Run(rec, new SvmClassifier(models.Svm, SvmClassifier.DefaultFilter()), keepTrace: true).Predictions;
            Assert.That(Enumerable.Range(0, trained.Count).Count(i => trained[i].Left != defaultClock[i].Left), Is.GreaterThan(0), "the trained clock matters on a calm wearer");
        }

        [Test]
        public void TheSvmsShiftsSearchedOnTheWalkReplayedClassifyTheWearersOtherWalkBetter()
        {
            // A calm generated wearer whose stride segments the shipped SVM, with its time filter, shows at the wrong time:
            // the pair shifts fitted window by window (hinge) take part of it; searched further on the walk replayed through
            // the whole classifier (a lead of every pair, then pair by pair), they classify the wearer's other walk better.
            var wearer = Wearer();
            var walk = Walk(wearer);
            var models = ShippedWithSvmOnly;
            var session = AnkleSession(walk);
            var searched = session.Fit(models, "calm-wearer");
            var hinge = WearerAdaptation.Fit(models, new[] { session.Labelled() }, "calm-wearer", WearerProfile.FromFootReferences, new AdaptationSettings { LearnedShiftSearch = false });
            var other = WalkingStreamGenerator.Generate("other-walk", wearer, new StreamScript().Stand(2).Walk(20, Foot.Right).Stand(1).Walk(20, Foot.Left, -30).Stand(2), 911);
            double Misclassified(GaitModels m) => ReplayEvaluator.Run(other, m.Create("svm", out _)).ClassifierMetrics.MisclassificationRate;
            double withSearch = Misclassified(searched.Apply(models)), hingeOnly = Misclassified(hinge.Apply(models)), shippedOnly = Misclassified(models);
            Assert.That(withSearch, Is.LessThan(hingeOnly), $"searched {withSearch:P1}, hinge fit only {hingeOnly:P1}, shipped {shippedOnly:P1}");
        }

        [Test]
        public void TheSvmsChannelGainsFitAWearerWhoseSwayIsUnlikeTheTrainingWalkers()
        {
            // A calm generated wearer swaying sideways twice as far as the generator's walkers: with ankle trackers the SVM's
            // input channels' gains are searched (AdaptationSettings.SvmChannelGains; the BLSTM's stay off), and they classify
            // the wearer's other walk better than the profile fitted without them.
            var wearer = Wearer();
            wearer.LateralAmplitude *= 2;
            var walk = Walk(wearer);
            var models = ShippedWithSvmOnly;
            var session = AnkleSession(walk);
            var withGains = session.Fit(models, "swaying-wearer");
            var without = WearerAdaptation.Fit(models, new[] { session.Labelled() }, "swaying-wearer", WearerProfile.FromFootReferences, new AdaptationSettings { SvmChannelGains = false });
            Assert.That(withGains.AdjustmentFor(SvmClassifier.Kind).ChannelGain, Has.Some.Not.EqualTo(1.0), "a channel's gain is fitted");
            Assert.That(without.AdjustmentFor(SvmClassifier.Kind)?.ChannelGain ?? new[] { 1.0 }, Has.All.EqualTo(1.0));
            var other = WalkingStreamGenerator.Generate("other-walk", wearer, new StreamScript().Stand(2).Walk(20, Foot.Right).Stand(1).Walk(20, Foot.Left, -30).Stand(2), 911);
            double Misclassified(GaitModels m) => ReplayEvaluator.Run(other, m.Create("svm", out _)).ClassifierMetrics.MisclassificationRate;
            double gains = Misclassified(withGains.Apply(models)), noGains = Misclassified(without.Apply(models)), shippedOnly = Misclassified(models);
            string figures = $"with channel gains {gains:P1} ({string.Join("/", withGains.AdjustmentFor(SvmClassifier.Kind).ChannelGain)}), without {noGains:P1}, shipped {shippedOnly:P1}";
            TestContext.WriteLine(figures);
            Assert.That(gains, Is.LessThan(noGains), figures);
        }

        [Test]
        public void ADamagedLearnedAdjustmentIsRefusedNamingTheFile()
        {
            var walk = Walk(Wearer());
            var models = ShippedWithSvmOnly;
            string text = AnkleSession(walk).Fit(models, "calm-wearer").Serialize();
            Assert.That(text, Does.Contain("learned.svm.bias_shift="));
            string folder = Path.Combine(Path.GetTempPath(), "headgait-learned-damage-test-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(folder);
            string path = Path.Combine(folder, "calm-wearer" + WearerProfile.Extension);
            try
            {
                void Damaged(string from, string to, string expected)
                {
                    Assert.That(text, Does.Contain(from));
                    File.WriteAllText(path, text.Replace(from, to));
                    var e = Assert.Throws<FormatException>(() => WearerProfile.Load(path));
                    Assert.That(e.Message, Does.Contain(path).And.Contain(expected));
                }
                Damaged("learned.svm.bias_shift=", "learned.svm.bias_shift=7,", "bias_shift");
                Damaged("learned.svm.bias_shift=", "learned.svm.bias_shift=NaN,", "bias_shift");
                Damaged("learned.svm.channel_gain=", "learned.svm.channel_gain=40,", "channel_gain");
                Damaged("learned.svm.channel_gain=", "learned.svm.channel_gain=x,", "channel_gain");
                Damaged("learned.svm.model=", "learned.svm.model=zz", "learned.svm.model");
                Damaged("learned.svm.model=", "learned.svm.weights=1\nlearned.svm.model=", "learned.svm.weights");
                Damaged("learned.svm.", "learned.rnn.", "no learned model 'rnn'");
                Damaged(WearerProfile.Magic, WearerProfile.MagicV1, "v1 profile holds no learned adjustments");
                File.WriteAllText(path, string.Join("\n", text.Split('\n').Where(l => !l.StartsWith("learned.svm.channel_gain", StringComparison.Ordinal))));
                Assert.That(Assert.Throws<FormatException>(() => WearerProfile.Load(path)).Message, Does.Contain(path).And.Contain("lacks 'learned.svm.channel_gain'"));
                // A profile of the first version (no learned block, no time scale) still reads.
                string v1 = string.Join("\n", text.Split('\n').Where(l => !l.StartsWith("learned.", StringComparison.Ordinal) && !l.StartsWith("learned_time_scale=", StringComparison.Ordinal))).Replace(WearerProfile.Magic, WearerProfile.MagicV1);
                File.WriteAllText(path, v1);
                Assert.That(WearerProfile.Load(path).LearnedAdjustments, Is.Empty);
            }
            finally
            {
                Directory.Delete(folder, true);
            }
        }

        [Test]
        public void ThePartsOfAProfileStayWithinTheirBounds()
        {
            var walk = Walk(Wearer());
            var (left, right) = SyntheticAnkles.From(walk, 72, 3);
            var p = new CalibrationSession(Unlabelled(walk), left, right).Fit(Shipped, "calm-wearer");
            Assert.That(p.Correlation.MinCorrelation, Is.GreaterThanOrEqualTo(Shipped.Correlation.MinCorrelation - WearerAdaptation.MaxThresholdDrop));
            Assert.That(p.Threshold.Floor, Is.GreaterThanOrEqualTo(WearerAdaptation.MinFloorShare * Shipped.Threshold.Floor - 1e-9));
            Assert.That(p.LearnedGain, Is.InRange(WearerProfile.MinLearnedGain, WearerProfile.MaxLearnedGain));
            double corShift = p.Correlation.Gate.Weights[WalkingGate.InputCount] - Shipped.Correlation.Gate.Weights[WalkingGate.InputCount];
            Assert.That(corShift, Is.InRange(0, WearerProfile.MaxGateShift));
            Assert.That(p.Correlation.WalkingGateHoldShift, Is.InRange(0, WearerProfile.MaxCorGateShift));
        }

        [Test]
        public void CalibrationShowsNoMoreStandingWithHeadMovementAsWalking()
        {
            // The guard: a profile fitted on a calm, slow walker (whose gates open, whose templates and floor follow its
            // gentle steps) still keeps the same person's standing with head movement standing.
            var wearer = Wearer();
            var walk = Walk(wearer);
            var (left, right) = SyntheticAnkles.From(walk, 72, 3);
            var session = new CalibrationSession(Unlabelled(walk), left, right);
            var standing = new List<Recording>();
            for (int k = 0; k < 3; k++) standing.Add(WalkingStreamGenerator.Generate("stand" + k, wearer, new StreamScript().Stand(20, 0.5 + 0.5 * k), 500UL + (ulong)k));
            foreach (bool self in new[] { false, true })
            {
                var adapted = session.Fit(Shipped, "calm-wearer", self).Apply(Shipped);
                foreach (var clf in GaitModels.Names)
                {
                    double Shown(GaitModels m) => GaitMetrics.Pool(standing.Select(r => ReplayEvaluator.Run(r, m.Create(clf, out _)).ClassifierMetrics)).StandingAsWalking;
                    Assert.That(Shown(adapted), Is.LessThanOrEqualTo(Shown(Shipped)), $"{clf} ({(self ? "self-supervised" : "ankle trackers")})");
                }
            }
        }

        [Test]
        public void OneWalkingGateScoresAlikeOnParallelThreads()
        {
            // The calibration benchmark and the glasses check replay many recordings at once with classifiers made from one
            // set of models, so they share its walking gates; scratch buffers per gate let parallel windows overwrite each
            // other's features (the same recordings scored differently from run to run).
            var gate = Shipped.Threshold.Gate;
            var recordings = Enumerable.Range(0, 4).Select(k => WalkingStreamGenerator.Generate("r" + k, GaitSubject.Random(40UL + (ulong)k),
                new StreamScript().Stand(1).Walk(6, Foot.Left).Stand(2, 1.0), 90UL + (ulong)k)).ToList();
            List<double> Scores(Recording r)
            {
                var scores = new List<double>();
                var pre = new StreamPreprocessor(new PreprocessorSettings { History = gate.History });
                foreach (var x in r.Samples) pre.Push(x.Imu, w => scores.Add(gate.Score(w)));
                return scores;
            }
            var sequential = recordings.Select(Scores).ToList();
            int differing = 0;
            System.Threading.Tasks.Parallel.For(0, 32, new System.Threading.Tasks.ParallelOptions { MaxDegreeOfParallelism = 8 }, i =>
            {
                if (!Scores(recordings[i % recordings.Count]).SequenceEqual(sequential[i % recordings.Count])) System.Threading.Interlocked.Increment(ref differing);
            });
            Assert.That(differing, Is.Zero);
        }

        [Test]
        public void ACalmWearerWhoseStepsCorHalfMissesStillGivesSureSteps()
        {
            // A real glasses wearer (ClassyGlass dataset 2, user 5) walks slowly and gently: in the first minute COR, gate
            // open, finds about 60 contacts, a quarter of them two steps apart, so no stretch kept a steady rhythm and the
            // wearer could not be calibrated without foot references. With the missed steps filled in, the stretches run
            // on, at the step rhythm the signal itself shows.
            string file = Path.Combine(TestData.SharedData("glasses-train"), "cg2_u05_e028_walking.csv");
            if (!File.Exists(file)) Assert.Ignore($"{file} not found");
            var walk = RecordingCsv.Load(file);
            double end = walk.Samples[0].Imu.Time + 60;
            var first = new Recording("first-minute", walk.Samples.Where(s => s.Imu.Time < end).ToList());
            int Steps(List<Recording> sure) => sure.Sum(r => PhaseEvents.TruthSteps(r).Count);
            Assert.That(Steps(WearerAdaptation.SelfLabel(Shipped, first, fillMissed: false)), Is.LessThan(WearerAdaptation.MinSteps), "without filling in");
            var filled = WearerAdaptation.SelfLabel(Shipped, first);
            Assert.That(Steps(filled), Is.GreaterThanOrEqualTo(20));
            var durations = filled.SelectMany(r => PhaseEvents.TruthSteps(r)).Select(s => s.Duration).ToList();
            double signalStep = 60 / RhythmReference.Of(first).MedianCadence;
            Assert.That(GaitMetrics.Median(durations), Is.EqualTo(signalStep).Within(0.15 * signalStep), "the sure steps keep the signal's own rhythm");
        }

        [Test]
        public void SelfSupervisedLabelsComeFromStepsCorIsSureOf()
        {
            var walk = Walk(Wearer());
            var sure = WearerAdaptation.SelfLabel(Shipped, Unlabelled(walk));
            Assert.That(sure, Is.Not.Empty);
            var truth = PhaseEvents.TruthContacts(walk);
            var offsets = sure.SelectMany(r => PhaseEvents.TruthContacts(r)).Select(c => Math.Abs(PhaseEvents.OffsetFromNearest(truth, c.Time))).ToList();
            Assert.That(offsets.Count, Is.GreaterThan(20));
            Assert.That(GaitMetrics.Median(offsets), Is.LessThan(0.06), "the sure contacts are the walker's");
            // The sure stretches lie where the walker walks.
            var cursor = new LabelCursor(walk);
            int samples = 0, standing = 0;
            foreach (var r in sure)
                foreach (var s in r.Samples)
                {
                    Assert.That(s.Left, Is.Not.EqualTo(GaitPhase.Standing), "a sure stretch is labelled walking throughout");
                    samples++;
                    if (cursor.TryLabelsAt(s.Imu.Time, out var t) && t.Left == GaitPhase.Standing) standing++;
                }
            Assert.That((double)standing / samples, Is.LessThan(0.05));
        }

        [Test]
        public void ASelfSupervisedWalkOfFewSureStepsShowsNoGesturesAsWalkingMore()
        {
            // A recorded style (Bandai Namco dataset 1, *chimpira*): its one walking clip gives COR about six sure steps, and
            // the wearer's step averaged from them matched the same style's bows and waves, shown as walking more.
            string folder = TestData.SharedData("real-train");
            string walkFile = Path.Combine(folder, "bn1_walk_chimpira_001.csv");
            if (!File.Exists(walkFile)) Assert.Ignore($"{walkFile} not found");
            var sure = WearerAdaptation.SelfLabel(Shipped, Unlabelled(RecordingCsv.Load(walkFile)));
            int steps = sure.Sum(r => PhaseEvents.TruthSteps(r).Count);
            Assert.That(steps, Is.InRange(WearerAdaptation.MinSteps, AdaptationSettings.SelfSupervisedTemplateSteps - 1), "the walk gives a few sure steps");
            var adapted = WearerAdaptation.Fit(Shipped, sure, "chimpira", WearerProfile.SelfSupervised).Apply(Shipped);
            var gestures = new[] { "bow", "bye", "byebye", "guide" }.Select(g => RecordingCsv.Load(Path.Combine(folder, $"bn1_{g}_chimpira_001.csv"))).ToList();
            double Shown(GaitModels m) => GaitMetrics.Pool(gestures.Select(r => ReplayEvaluator.Run(r, m.Create("cor", out _)).ClassifierMetrics)).StandingAsWalking;
            Assert.That(Shown(adapted), Is.LessThanOrEqualTo(Shown(Shipped)));
        }

        [Test]
        public void ASelfSupervisedMinuteOnRealGlassesShowsNoStillTimeAsWalkingMore()
        {
            // Each glasses wearer calibrated on the first minute of their walking file: the wearer's own step, scored only on
            // the sure stretches of walking, matched five wearers' standing, head movement and picking up (COR's classifier
            // output on them 1.4 to 1.8 % of picking up), until a candidate had to show no more walking outside the walk's
            // own rhythm than the shipped COR (AdaptationSettings.StillCheck).
            var recordings = TestData.GlassesFiles().Select(f => RecordingCsv.Load(f)).ToList();
            double shippedFrames = 0, adaptedFrames = 0, stillFrames = 0;
            int ownSteps = 0;
            foreach (var person in recordings.GroupBy(RealActivity.PersonOf))
            {
                var walk = person.FirstOrDefault(r => RealActivity.Of(r) == RealActivity.Walking);
                if (walk == null || walk.Duration < 65) continue;
                double cut = walk.Samples[0].Imu.Time + 60;
                var first = new Recording(walk.Name + "_first", walk.Samples.Where(x => x.Imu.Time < cut).ToList());
                WearerProfile profile;
                try { profile = new CalibrationSession(first).Fit(Shipped, "wearer", selfSupervised: true); }
                catch (InvalidOperationException) { continue; }
                if (profile.Correlation.Templates.Count > Shipped.Correlation.Templates.Count) ownSteps++;
                var adapted = profile.Apply(Shipped);
                foreach (var still in person.Where(r => RealActivity.IsStill(RealActivity.Of(r))))
                {
                    double Walking(GaitModels m) => ReplayEvaluator.Run(still, m.Create("cor", out _), keepTrace: true).Predictions.Count(p => p.IsWalking);
                    stillFrames += ReplayEvaluator.Run(still, Shipped.Create("cor", out _), keepTrace: true).Predictions.Count;
                    shippedFrames += Walking(Shipped);
                    adaptedFrames += Walking(adapted);
                }
            }
            Assert.That(ownSteps, Is.GreaterThan(0), "some wearers keep their own step");
            // Half the figures' last decimal (0.1 % of still time): the still figures the glasses report stay as shipped
            // (all wearers: without the check 339 frames more than the shipped COR's 2245, with it 16).
            Assert.That((adaptedFrames - shippedFrames) / stillFrames, Is.LessThan(0.0005), "still time predicted walking, more than the shipped COR");
        }

        [Test]
        public void ASelfSupervisedMinuteOnRealGlassesShowsACalmWearersStillTimeAsWalkingNoMoreWithTheLearnedModels()
        {
            // A calm glasses wearer (ClassyGlass dataset 1, user 9): the first minute of their walking gives 16 sure steps
            // and the learned models' input gain its bound, 1.5, which scored the sure stretches better but showed the
            // wearer's standing as walking 3.1 s instead of 0.4 (SVM, avatar), until the gain too had to show no more
            // walking outside the walk's own rhythm than the shipped models (AdaptationSettings.StillCheck).
            string folder = TestData.SharedData("glasses-train");
            string walkFile = Path.Combine(folder, "cg1a_u09_e097_walking.csv");
            if (!File.Exists(walkFile)) Assert.Ignore($"{walkFile} not found");
            var walk = RecordingCsv.Load(walkFile);
            double cut = walk.Samples[0].Imu.Time + 60;
            var first = new Recording(walk.Name + "_first", walk.Samples.Where(x => x.Imu.Time < cut).ToList());
            var adapted = new CalibrationSession(first).Fit(Shipped, "calm", selfSupervised: true).Apply(Shipped);
            var still = new[] { "cg1a_u09_e096_standing.csv", "cg1a_u09_e093_sitting_head_movement.csv" }.Select(f => RecordingCsv.Load(Path.Combine(folder, f))).ToList();
            Assert.Multiple(() =>
            {
                foreach (var clf in new[] { "svm", "blstm" })
                    foreach (var rec in still)
                    {
                        int Walking(GaitModels m) => ReplayEvaluator.Run(rec, m.Create(clf, out _), keepTrace: true).Predictions.Count(p => p.IsWalking);
                        Assert.That(Walking(adapted), Is.LessThanOrEqualTo(Walking(Shipped)), $"{clf}, {rec.Name}: windows predicted walking");
                    }
            });
        }

        /// <summary>A generated wearer's walk of two straight walks of <paramref name="steps"/> steps each, labelled by ankle trackers.</summary>
        static Recording AnkleLabelledWalk(ulong seed, double stepFrequency, double bounce, int steps)
        {
            var wearer = GaitSubject.Random(seed, "wearer" + seed);
            wearer.StepFrequency = stepFrequency;
            wearer.VerticalAmplitude *= bounce;
            var walk = WalkingStreamGenerator.Generate("calibration", wearer, new StreamScript().Stand(2).Walk(steps, Foot.Left).Stand(1).Walk(steps, Foot.Right, 40).Stand(3), 84);
            var (left, right) = SyntheticAnkles.From(walk, 72, 3);
            return new CalibrationSession(Unlabelled(walk), left, right).Labelled();
        }

        static double Misclassified(Recording walk, CorrelationTemplate cor) => ReplayEvaluator.Run(walk, new CorrelationClassifier(cor)).ClassifierMetrics.MisclassificationRate;

        static AdaptationSettings CorOnly(double margin, int thresholdSteps = 60)
            => new AdaptationSettings { AcceptMargin = margin, CorThresholdSteps = thresholdSteps, CorGate = false, Threshold = false, LearnedGain = false, LearnedGate = false, LearnedRefit = false };

        [Test]
        public void AMinutesWalkKeepsCorsMostRefittedCandidateThatPays()
        {
            // A calm wearer's 84 steps: the wearer's step alone scores the walk better than the candidate whose threshold, lags
            // and lead were refitted too, and both beat the trained COR. Kept before: the better scoring one; held out (the
            // bn *feminine* style) that was the worse of the two on the wearer's other walks (19.9 against 15.9 %).
            var walk = AnkleLabelledWalk(8, 1.4, 0.6, 30);
            int steps = PhaseEvents.TruthSteps(walk).Count;
            Assert.That(steps, Is.GreaterThanOrEqualTo(new AdaptationSettings().CorThresholdSteps), "a minute's walk");
            var fuller = WearerAdaptation.Fit(Shipped, new[] { walk }, "calm", WearerProfile.FromFootReferences, CorOnly(double.NaN)).Correlation;
            var ownStepOnly = WearerAdaptation.Fit(Shipped, new[] { walk }, "calm", WearerProfile.FromFootReferences, CorOnly(double.NaN, int.MaxValue)).Correlation;
            double trained = Misclassified(walk, Shipped.Correlation), refitted = Misclassified(walk, fuller), own = Misclassified(walk, ownStepOnly);
            Assert.That(refitted, Is.LessThanOrEqualTo(trained - new AdaptationSettings().AcceptMargin), "the refitted candidate pays on the walk");
            Assert.That(own, Is.LessThan(refitted), "the wearer's step alone scores the walk better still");
            var kept = WearerAdaptation.Fit(Shipped, new[] { walk }, "calm").Correlation;
            Assert.That(kept.Serialize(), Is.EqualTo(fuller.Serialize()), $"trained {trained:P1}, own step {own:P1}, refitted {refitted:P1}");
        }

        [Test]
        public void AShortWalkKeepsTheWearersStepOnlyWhereItPaysByTheShortWalkMargin()
        {
            // 38 steps (one clip's worth): the wearer's own step scores the walk 1-2 points better than the trained COR, within
            // what a walk this short tells (held out, bn1 *feminine*'s clip: 2.6 points better on it, 0.6 worse on its other walks).
            var walk = AnkleLabelledWalk(3, 1.4, 0.5, 14);
            var settings = new AdaptationSettings();
            Assert.That(PhaseEvents.TruthSteps(walk).Count, Is.LessThan(settings.CorThresholdSteps));
            var own = WearerAdaptation.Fit(Shipped, new[] { walk }, "calm", WearerProfile.FromFootReferences, CorOnly(double.NaN)).Correlation;
            double trained = Misclassified(walk, Shipped.Correlation), gain = trained - Misclassified(walk, own);
            Assert.That(gain, Is.InRange(settings.AcceptMargin, settings.ShortWalkMargin), "the own step pays, by less than the short walk's margin");
            Assert.That(WearerAdaptation.Fit(Shipped, new[] { walk }, "calm").Correlation.Serialize(), Is.EqualTo(Shipped.Correlation.Serialize()), $"own step {gain:P1} better on the walk");
            var bigGain = WearerAdaptation.Fit(Shipped, new[] { walk }, "calm", WearerProfile.FromFootReferences, new AdaptationSettings { ShortWalkMargin = gain / 2, CorGate = false }).Correlation;
            Assert.That(bigGain.Serialize(), Is.EqualTo(own.Serialize()), "where the margin is met, the own step is kept");
        }

        [Test]
        public void AMinutesWalkKeepsTheTrainedCorWhereACandidateBeatsItByLessThanCorsMargin()
        {
            // A calm wearer's 84 steps: COR's refitted candidate beats the trained COR on the walk by more than half a point
            // (AcceptMargin) but less than CorAcceptMargin's point. Held out (bn *masculine*), such a candidate paid on its
            // minute's walk by a hair and scored its other walks 15.7 to 18.6 %; so it must not be kept, and is where COR's
            // own margin is taken away.
            var walk = AnkleLabelledWalk(33, 1.4, 0.65, 30);
            Assert.That(PhaseEvents.TruthSteps(walk).Count, Is.GreaterThanOrEqualTo(new AdaptationSettings().CorThresholdSteps), "a minute's walk");
            var settings = CorOnly(new AdaptationSettings().AcceptMargin);
            var kept = WearerAdaptation.Fit(Shipped, new[] { walk }, "calm", WearerProfile.FromFootReferences, settings).Correlation;
            settings.CorAcceptMargin = 0;
            var unguarded = WearerAdaptation.Fit(Shipped, new[] { walk }, "calm", WearerProfile.FromFootReferences, settings).Correlation;
            double gain = Misclassified(walk, Shipped.Correlation) - Misclassified(walk, unguarded);
            Assert.That(kept.Serialize(), Is.EqualTo(Shipped.Correlation.Serialize()), $"the candidate {gain:P2} better on the walk is refused");
            Assert.That(unguarded.Serialize(), Is.Not.EqualTo(Shipped.Correlation.Serialize()), "without COR's own margin it is kept");
            Assert.That(gain, Is.InRange(new AdaptationSettings().AcceptMargin, new AdaptationSettings().CorAcceptMargin - 1e-9), "it beats the trained COR by more than half a point, less than COR's margin");
        }

        [Test]
        public void AnAnkleWalkWhoseStepsCorsGateRefusesOpensItForWalksInProgressOnlyWhereThatPays()
        {
            // A slow, calm wearer's 22 steps (0.71 s a step): the shipped COR's gate breaks the walks off, and opened for walks
            // in progress as far as the walk needs it, COR scores the walk 11 points better, over the short walk's margin (held
            // out, bn1 *feminine*, a quarter of its one clip refused: 41.3 to 36.9 % on its other walks). Opened for starts too,
            // a calm wearer's standing with head movement was shown walking (CalibrationShowsNoMoreStandingWithHeadMovementAsWalking):
            // a start still needs the trained gate, and this wearer's standing with head movement is shown walking no more.
            // Another wearer's walk, which the opened gate scores only 3 points better, keeps the trained gate.
            var settings = new AdaptationSettings { Threshold = false, LearnedGain = false, LearnedGate = false, LearnedRefit = false };
            var wearer = GaitSubject.Random(1, "wearer1");
            wearer.StepFrequency = 1.4;
            wearer.VerticalAmplitude *= 0.35;
            var walk = AnkleLabelledWalk(1, 1.4, 0.35, 8);
            Assert.That(PhaseEvents.TruthSteps(walk).Count, Is.LessThan(settings.CorThresholdSteps), "a short walk");
            var openedProfile = WearerAdaptation.Fit(Shipped, new[] { walk }, "slow", WearerProfile.FromFootReferences, settings);
            var opened = openedProfile.Correlation;
            settings.CorGate = false;
            var closed = WearerAdaptation.Fit(Shipped, new[] { walk }, "slow", WearerProfile.FromFootReferences, settings).Correlation;
            Assert.That(opened.WalkingGateHoldShift, Is.GreaterThan(0).And.LessThanOrEqualTo(WearerProfile.MaxCorGateShift), "COR's gate opened for walks in progress, within its bound");
            Assert.That(opened.Gate.Serialize(), Is.EqualTo(Shipped.Correlation.Gate.Serialize()), "and as trained for a start");
            Assert.That(Misclassified(walk, opened), Is.LessThanOrEqualTo(Misclassified(walk, closed) - settings.ShortWalkMargin), "it pays on the walk by the short walk's margin");
            var standing = Enumerable.Range(0, 3).Select(k => WalkingStreamGenerator.Generate("stand" + k, wearer, new StreamScript().Stand(20, 0.5 + 0.5 * k), 500UL + (ulong)k)).ToList();
            double Shown(CorrelationTemplate c) => GaitMetrics.Pool(standing.Select(r => ReplayEvaluator.Run(r, new CorrelationClassifier(c)).ClassifierMetrics)).StandingAsWalking;
            Assert.That(Shown(opened), Is.LessThanOrEqualTo(Shown(Shipped.Correlation)), "standing with head movement shown as walking");
            Assert.That(WearerProfile.Parse(openedProfile.Serialize(), "slow.profile.txt").Correlation.WalkingGateHoldShift, Is.EqualTo(opened.WalkingGateHoldShift), "kept through the profile's save and load");
            openedProfile.Correlation = opened.With(walkingGateHoldShift: WearerProfile.MaxCorGateShift + 0.5);
            var e = Assert.Throws<FormatException>(() => WearerProfile.Parse(openedProfile.Serialize(), "slow.profile.txt"), "a profile opening COR's gate past its bound");
            Assert.That(e.Message, Does.Contain("slow.profile.txt").And.Contain("walking_gate_hold_shift"));

            var barely = AnkleLabelledWalk(3, 1.4, 0.45, 8);
            settings.CorGate = true;
            Assert.That(WearerAdaptation.Fit(Shipped, new[] { barely }, "calm", WearerProfile.FromFootReferences, settings).Correlation.WalkingGateHoldShift, Is.EqualTo(0), "the trained gate kept");
        }

        [Test]
        public void ASteadyWalkIsLabelledFromCorsOwnContactsAndACalmOneFilledIn()
        {
            // Self-supervised: a wearer whose steps COR finds steadily gives a minute's sure steps from its own contacts, and
            // the steps filled in midway between them (no side evidence, placed by the rhythm) only blurred the fit (held out,
            // bn *feminine*: 19.7 % filled, 16.6 % from COR's contacts alone); a calm wearer's half-missed steps still are.
            static Recording Walker(ulong seed, double frequency, double bounce)
            {
                var w = GaitSubject.Random(seed, "probe");
                w.StepFrequency = frequency;
                w.VerticalAmplitude *= bounce;
                return Unlabelled(WalkingStreamGenerator.Generate("calibration", w, new StreamScript().Stand(2).Walk(40, Foot.Left).Stand(1).Walk(40, Foot.Right, 40).Stand(3), 84));
            }
            static int Steps(List<Recording> r) => r.Sum(x => PhaseEvents.TruthSteps(x).Count);
            int below = AdaptationSettings.For(WearerProfile.SelfSupervised).FillMissedBelowSteps;

            var steady = Walker(6, 1.5, 0.7);
            int own = Steps(WearerAdaptation.SelfLabel(Shipped, steady, fillMissed: false)), filled = Steps(WearerAdaptation.SelfLabel(Shipped, steady));
            Assert.That(own, Is.GreaterThanOrEqualTo(below), "COR's own contacts give enough sure steps");
            Assert.That(filled, Is.GreaterThan(own), "filling in would add steps");
            Assert.That(new CalibrationSession(steady).Fit(Shipped, "steady", selfSupervised: true).Steps, Is.EqualTo(own));

            var calm = Walker(5, 1.45, 0.55);
            int calmOwn = Steps(WearerAdaptation.SelfLabel(Shipped, calm, fillMissed: false)), calmFilled = Steps(WearerAdaptation.SelfLabel(Shipped, calm));
            Assert.That(calmOwn, Is.LessThan(below));
            Assert.That(new CalibrationSession(calm).Fit(Shipped, "calm", selfSupervised: true).Steps, Is.EqualTo(calmFilled).And.GreaterThan(calmOwn));
        }

        [Test]
        public void AWalkWhoseFullGateOpeningOvershootsKeepsTheOpeningThatPaysBest()
        {
            // A calm wearer's 16 steps (0.69 s a step): COR's gate would need opening past the bound for the walk's walking
            // windows to pass, and opened that far for walks in progress (the bound, as before, 2) it scores the walk worse
            // (42 to 48 %), so the full opening would keep the trained gate; opened by 0.5 it scores it 9 points better. Held
            // out, bn1 *feminine* (a bound of 4): 41.3 to 34.5 % on its other walks (36.9 % at 2).
            var settings = new AdaptationSettings { Threshold = false, LearnedGain = false, LearnedGate = false, LearnedRefit = false };
            var walk = AnkleLabelledWalk(11, 1.45, 0.36, 8);
            Assert.That(PhaseEvents.TruthSteps(walk).Count, Is.LessThan(settings.CorThresholdSteps), "a short walk");
            var opened = WearerAdaptation.Fit(Shipped, new[] { walk }, "calm", WearerProfile.FromFootReferences, settings).Correlation;
            settings.CorGate = false;
            var closed = WearerAdaptation.Fit(Shipped, new[] { walk }, "calm", WearerProfile.FromFootReferences, settings).Correlation;
            Assert.That(WearerAdaptation.GateShift(closed.Gate, new[] { walk }, WalkingGate.DetectorPass, 2 * WearerProfile.MaxCorGateShift), Is.GreaterThan(WearerProfile.MaxCorGateShift), "the walk needs more than the bound");
            Assert.That(Misclassified(walk, closed.With(walkingGateHoldShift: 2)), Is.GreaterThan(Misclassified(walk, closed) - settings.ShortWalkMargin), "opened by 2 it does not pay");
            Assert.That(opened.WalkingGateHoldShift, Is.GreaterThan(0).And.LessThan(2), "a smaller opening kept");
            Assert.That(Misclassified(walk, opened), Is.LessThanOrEqualTo(Misclassified(walk, closed) - settings.ShortWalkMargin), "it pays by the short walk's margin");
            var wearer = GaitSubject.Random(11, "wearer11");
            wearer.StepFrequency = 1.45;
            wearer.VerticalAmplitude *= 0.36;
            var standing = Enumerable.Range(0, 3).Select(k => WalkingStreamGenerator.Generate("stand" + k, wearer, new StreamScript().Stand(20, 0.5 + 0.5 * k), 500UL + (ulong)k)).ToList();
            double Shown(CorrelationTemplate c) => GaitMetrics.Pool(standing.Select(r => ReplayEvaluator.Run(r, new CorrelationClassifier(c)).ClassifierMetrics)).StandingAsWalking;
            Assert.That(Shown(opened), Is.LessThanOrEqualTo(Shown(Shipped.Correlation)), "standing with head movement shown as walking");
        }
    }
}
