using System;
using System.Globalization;
using System.IO;
using System.Linq;
using HeadGait.Synthetic;
using HeadGait.Calibration;
using HeadGait.Training;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>
    /// A wearer's time scale for the learned models (<see cref="LearnedClassifier.TimeScale"/>, <see cref="WearerProfile.LearnedTimeScale"/>):
    /// what the model reads at a scale, that 1 reads as ever, and the profile's field versioned and validated.
    /// </summary>
    public class LearnedTimeScaleTests
    {
        static GaitModels shipped;
        static GaitModels Shipped => shipped ?? (shipped = TestData.ShippedModels());

        /// <summary>A window of <paramref name="length"/> samples at 100 Hz of a bounce of period <paramref name="period"/> (s).</summary>
        static SignalWindow Bounce(int length, double period)
        {
            var w = new SignalWindow(length, 100); // every sample valid
            for (int i = 0; i < length; i++)
            {
                double t = -(length - 1 - i) / 100.0; // before the newest sample
                w.Smv[i] = 2 * Math.Cos(2 * Math.PI * t / period);
                w.Vertical[i] = 9.81 + 1.5 * Math.Cos(2 * Math.PI * t / period + 0.3);
                w.Lateral[i] = 0.8 * Math.Sin(Math.PI * t / period);
                w.Forward[i] = 0.5 * Math.Sin(2 * Math.PI * t / period + 1);
            }
            return w;
        }

        static ModelFile WithTimeScale(ModelFile model, string scale)
        {
            var copy = ModelFile.Parse(model.ToBytes(), "scaled.bytes");
            copy.Set(LearnedClassifier.WearerTimeScaleKey, scale);
            return copy;
        }

        [Test]
        public void ASlowBounceReadAtItsTimeScaleLooksLikeTheQuickOne()
        {
            // A walker stepping every 0.7 s read at 0.7 / 0.5 = 1.4 gives the model the features a walker stepping every
            // 0.5 s gives it unscaled (up to the linear interpolation between grid samples).
            var svm = Shipped.Svm;
            var plain = new SvmClassifier(svm, null);
            var scaled = new SvmClassifier(WithTimeScale(svm, "1.4"), null);
            Assert.That(plain.TimeScale, Is.EqualTo(1));
            Assert.That(scaled.TimeScale, Is.EqualTo(1.4));
            Assert.That(scaled.ModelSpan, Is.EqualTo((int)Math.Ceiling(99 * 1.4) + 1));
            Assert.That(scaled.WindowLength, Is.GreaterThanOrEqualTo(scaled.ModelSpan));
            var quick = new double[plain.Features.Width];
            var slow = new double[plain.Features.Width];
            var slowUnscaled = new double[plain.Features.Width];
            plain.ReadFeatures(Bounce(250, 0.5), quick);
            scaled.ReadFeatures(Bounce(250, 0.7), slow);
            plain.ReadFeatures(Bounce(250, 0.7), slowUnscaled);
            double Distance(double[] a, double[] b)
            {
                double d = 0;
                for (int i = 0; i < a.Length; i++) d = Math.Max(d, Math.Abs(a[i] - b[i]));
                return d;
            }
            Assert.That(Distance(slow, quick), Is.LessThan(0.02), "read at its scale the slow bounce is the quick one");
            Assert.That(Distance(slowUnscaled, quick), Is.GreaterThan(1), "unscaled it is not");
        }

        [Test]
        public void AScaleOfOneReadsTheWindowAsEver()
        {
            // Without the key, or a profile's scale of 1, nothing of the model or the window read changes.
            var models = new GaitModels { Threshold = Shipped.Threshold, Correlation = Shipped.Correlation, Svm = Shipped.Svm };
            var profile = new WearerProfile { Wearer = "w" };
            var applied = profile.Apply(models).Svm;
            Assert.That(applied.Values.ContainsKey(LearnedClassifier.WearerTimeScaleKey), Is.False);
            var a = new SvmClassifier(models.Svm, SvmClassifier.DefaultFilter());
            var b = new SvmClassifier(applied, SvmClassifier.DefaultFilter());
            Assert.That(b.WindowLength, Is.EqualTo(a.WindowLength));
            var window = Bounce(a.WindowLength, 0.62);
            Assert.That(b.Standardise(window), Is.EqualTo(a.Standardise(window)));
            profile.LearnedTimeScale = 1.25;
            Assert.That(profile.Apply(models).Svm.Values[LearnedClassifier.WearerTimeScaleKey], Is.EqualTo("1.25"));
        }

        [TestCase("3")]
        [TestCase("0.1")]
        [TestCase("NaN")]
        [TestCase("fast")]
        public void AModelsTimeScaleOutsideItsRangeIsRefusedNamingTheFile(string value)
        {
            var e = Assert.Throws<ModelFormatException>(() => new SvmClassifier(WithTimeScale(Shipped.Svm, value), null));
            Assert.That(e.Message, Does.Contain("scaled.bytes").And.Contain(LearnedClassifier.WearerTimeScaleKey));
        }

        [Test]
        public void AProfilesTimeScaleRoundTripsAndIsValidatedOnLoad()
        {
            var profile = new WearerProfile { Wearer = "slow-wearer", Steps = 40, LearnedTimeScale = 1.3 };
            string text = profile.Serialize();
            Assert.That(text, Does.StartWith(WearerProfile.Magic).And.Contain("learned_time_scale=1.3\n"));
            var back = WearerProfile.Parse(text, "slow.profile.txt");
            Assert.That(back.LearnedTimeScale, Is.EqualTo(1.3));
            Assert.That(back.Serialize(), Is.EqualTo(text));

            void Refused(string from, string to, string expected)
            {
                Assert.That(text, Does.Contain(from));
                var e = Assert.Throws<FormatException>(() => WearerProfile.Parse(text.Replace(from, to), "slow.profile.txt"));
                Assert.That(e.Message, Does.Contain("slow.profile.txt").And.Contain(expected));
            }
            Refused("learned_time_scale=1.3", "learned_time_scale=2.5", "learned_time_scale");
            Refused("learned_time_scale=1.3", "learned_time_scale=0.2", "learned_time_scale");
            Refused("learned_time_scale=1.3", "learned_time_scale=x", "learned_time_scale");
            Refused("learned_time_scale=1.3\n", "", "lacks 'learned_time_scale'");
            // A v2 profile (before the scale) reads with the window as it is; one that claims a scale is refused.
            string v2 = text.Replace(WearerProfile.Magic, WearerProfile.MagicV2).Replace("learned_time_scale=1.3\n", "");
            var old = WearerProfile.Parse(v2, "old.profile.txt");
            Assert.That(old.LearnedTimeScale, Is.EqualTo(1));
            Refused(WearerProfile.Magic, WearerProfile.MagicV2, "v2 profile holds no learned time scale");
            // The bounds a profile may hold lie within what a model may.
            Assert.That(WearerProfile.MinLearnedTimeScale, Is.GreaterThanOrEqualTo(LearnedClassifier.MinTimeScale));
            Assert.That(WearerProfile.MaxLearnedTimeScale, Is.LessThanOrEqualTo(LearnedClassifier.MaxTimeScale));
            Assert.That(profile.LearnedTimeScale.ToString(CultureInfo.InvariantCulture), Is.EqualTo("1.3"));
        }

        static (Recording walk, Recording other, GaitSubject wearer) QuickAndSlow(double stepFrequency, ulong seed)
        {
            var wearer = GaitSubject.Random(seed, "wearer" + seed);
            wearer.StepFrequency = stepFrequency;
            var walk = WalkingStreamGenerator.Generate("calibration", wearer, new StreamScript().Stand(2).Walk(30, Foot.Left).Stand(1).Walk(30, Foot.Right, 40).Stand(3), 84);
            var other = WalkingStreamGenerator.Generate("other-walk", wearer, new StreamScript().Stand(2).Walk(25, Foot.Right).Stand(1).Walk(25, Foot.Left, -30).Stand(2), 911);
            return (walk, other, wearer);
        }

        static WearerProfile Fitted(Recording walk, GaitModels models, AdaptationSettings settings)
        {
            var (left, right) = SyntheticAnkles.From(walk, 72, 3);
            var session = new CalibrationSession(CalibrationTests.Unlabelled(walk), left, right);
            return WearerAdaptation.Fit(models, new[] { session.Labelled() }, "wearer", WearerProfile.FromFootReferences, settings);
        }

        [Test]
        public void AQuickWalkersModelsReadTheirWalkAtTheTrainingWalkersStepAndClassifyTheirOtherWalkBetter()
        {
            // A generated wearer stepping 2.4 times a second (0.42 s a step; the training walkers take about 0.54 s): the
            // calibration reads the SVM's window at the ratio of the two, and the wearer's other walk is classified better
            // than by the same profile reading the window as it is (the live scale off too, or it would read the walk at the
            // wearer's step without the profile); their standing with head movement is shown as walking no more than by the
            // shipped models.
            var models = new GaitModels { Threshold = Shipped.Threshold, Correlation = Shipped.Correlation, Svm = Shipped.Svm };
            var (walk, other, wearer) = QuickAndSlow(2.4, 31);
            var profile = Fitted(walk, models, new AdaptationSettings());
            Assert.That(AdaptationSettings.For(WearerProfile.SelfSupervised).LearnedTimeScale, Is.False, "self-supervised profiles read the window as it is");
            double trainedStep = models.SvmOf(models.Svm).TrainedStepPeriod;
            Assert.That(profile.LearnedTimeScale, Is.LessThan(1).And.EqualTo(WearerAdaptation.StepPeriod(new[] { walk }) / trainedStep).Within(0.01));
            var unscaled = WearerProfile.Parse(profile.Serialize());
            unscaled.LearnedTimeScale = 1;
            double scaled = ReplayEvaluator.Run(other, profile.Apply(models).Create("svm", out _)).ClassifierMetrics.MisclassificationRate;
            double plain = ReplayEvaluator.Run(other, Svm(unscaled.Apply(models), liveScale: false)).ClassifierMetrics.MisclassificationRate;
            double shipped = ReplayEvaluator.Run(other, models.Create("svm", out _)).ClassifierMetrics.MisclassificationRate;
            TestContext.WriteLine($"time scale {profile.LearnedTimeScale:F3}: other walk {scaled:P1} scaled, {plain:P1} unscaled, {shipped:P1} shipped");
            Assert.That(scaled, Is.LessThan(plain - 0.01), $"scaled {scaled:P1}, unscaled {plain:P1}, shipped {shipped:P1}");

            var standing = Enumerable.Range(0, 3).Select(k => WalkingStreamGenerator.Generate("stand" + k, wearer, new StreamScript().Stand(20, 0.5 + 0.5 * k), 500UL + (ulong)k)).ToList();
            double Shown(GaitModels m) => GaitMetrics.Pool(standing.Select(r => ReplayEvaluator.Run(r, m.Create("svm", out _)).ClassifierMetrics)).StandingAsWalking;
            TestContext.WriteLine($"standing shown walking: scaled {Shown(profile.Apply(models)):P2}, unscaled {Shown(unscaled.Apply(models)):P2}, shipped {Shown(models):P2}");
            Assert.That(Shown(profile.Apply(models)), Is.LessThanOrEqualTo(Shown(models)));
        }

        /// <summary>The SVM of <paramref name="models"/> as <see cref="GaitModels.Create"/> makes it, with the live time scale on or off.</summary>
        static LearnedClassifier Svm(GaitModels models, bool liveScale)
        {
            var settings = SvmClassifier.DefaultFilter();
            settings.LiveTimeScale = liveScale;
            return new SvmClassifier(models.Svm, settings) { WalkClockSettings = models.Threshold };
        }

        static LearnedClassifier ShippedSvm(bool liveScale) => Svm(Shipped, liveScale);

        [Test]
        public void AQuickWearerWithoutAProfileIsReadAtTheirOwnStepAndClassifiedBetter()
        {
            // The same generated quick wearer as above (0.42 s a step), no calibration: the head's rhythm (or THR's settled
            // step clock beside the model) shows their step, the SVM also reads the window at its ratio to the training
            // walkers' and that reading picks the walking class. Their walk is classified better than with the window read as
            // it is, and their standing with head movement is shown as walking no more.
            Assert.That(SvmClassifier.DefaultFilter().LiveTimeScale, Is.True, "the shipped SVM reads a quick wearer at their step");
            var (_, other, wearer) = QuickAndSlow(2.4, 31);
            var live = ShippedSvm(true);
            double scaled = ReplayEvaluator.Run(other, live).ClassifierMetrics.MisclassificationRate;
            double plain = ReplayEvaluator.Run(other, ShippedSvm(false)).ClassifierMetrics.MisclassificationRate;
            double trainedStep = live.TrainedStepPeriod;
            TestContext.WriteLine($"live scale {live.LiveTimeScale:F2} (step over the training walkers' {WearerAdaptation.StepPeriod(new[] { other }) / trainedStep:F2}): other walk {scaled:P1} live, {plain:P1} as it is");
            Assert.That(live.LiveTimeScale, Is.EqualTo(WearerAdaptation.StepPeriod(new[] { other }) / trainedStep).Within(0.06));
            Assert.That(scaled, Is.LessThan(plain - 0.01), $"live {scaled:P1}, as it is {plain:P1}");

            var standing = Enumerable.Range(0, 3).Select(k => WalkingStreamGenerator.Generate("stand" + k, wearer, new StreamScript().Stand(20, 0.5 + 0.5 * k), 500UL + (ulong)k)).ToList();
            double Shown(bool liveScale) => GaitMetrics.Pool(standing.Select(r => ReplayEvaluator.Run(r, ShippedSvm(liveScale)).ClassifierMetrics)).StandingAsWalking;
            Assert.That(Shown(true), Is.LessThanOrEqualTo(Shown(false)));
        }

        [Test]
        public void AQuickWearerIsReadAtTheirStepFromTheFirstStepTheClockTimes()
        {
            // A stream that starts in the quick wearer's walk, as the motion-capture clips do. THR's step clock beside the
            // SVM times their step between its first two contacts; the live scale follows it from there, not only once the
            // clock's walk has settled (a second later: the quick *active* walkers' 3-4 s clips were read as they are for
            // most of their length).
            var wearer = GaitSubject.Random(31, "wearer31");
            wearer.StepFrequency = 2.4;
            var walk = WalkingStreamGenerator.Generate("walk", wearer, new StreamScript().Walk(12, Foot.Left).Stand(2), 912);
            var live = ShippedSvm(true);
            var pipeline = new GaitPipeline(live);
            double firstScaled = double.NaN;
            foreach (var s in walk.Samples)
            {
                pipeline.Push(s.Imu);
                if (double.IsNaN(firstScaled) && live.LiveTimeScale < 1) firstScaled = s.Imu.Time - walk.Samples[0].Imu.Time;
            }
            TestContext.WriteLine($"read at a scale from {firstScaled:F2} s ({live.LiveTimeScale:F2} at the end)");
            Assert.That(live.LiveTimeScale, Is.LessThan(0.85));
            Assert.That(firstScaled, Is.LessThan(1.5), "the settled clock alone: 1.76 s");
        }

        [Test]
        public void ASlowWalkersHalfStepsAreNotReadAsAQuickWalkersSteps()
        {
            // The real bn *fem* walks made slow (0.78 s a step, slower than the training walkers, so never read quicker):
            // THR's step clock beside the SVM first times some of them from two bumps of one step, 0.31-0.36 s apart. Such
            // an interval is under what a live scale reaches (0.7 of the trained step) and is not taken; taken, it read
            // 3.5 % of these clips' samples at the scale's floor, against 1.6 % (the settled clock's and rhythm's misreadings).
            var files = Directory.GetFiles(TestData.SharedData("real-train"), "bn_*_fem_*.csv")
                .Where(f => !Path.GetFileName(f).StartsWith("bn_neg_", StringComparison.Ordinal)).OrderBy(f => f, StringComparer.Ordinal).ToList();
            Assert.That(files, Has.Count.GreaterThan(50));
            int samples = 0, atFloor = 0;
            foreach (var file in files)
            {
                var live = ShippedSvm(true);
                var pipeline = new GaitPipeline(live);
                foreach (var s in RecordingAugmentation.Slow(TestData.Load(file)).Samples)
                {
                    pipeline.Push(s.Imu);
                    samples++;
                    if (live.LiveTimeScale <= WearerProfile.MinLearnedTimeScale + 0.02) atFloor++;
                }
            }
            double share = (double)atFloor / samples;
            TestContext.WriteLine($"{files.Count} clips made slow: {share:P2} of {samples} samples read at the live scale's floor");
            Assert.That(share, Is.LessThan(0.025));
        }

        [Test]
        public void ASlowWearerWithoutAProfileIsReadAsEver()
        {
            // Slower than the training walkers (0.71 s a step): no live scale, and every prediction as with it off.
            var (_, other, _) = QuickAndSlow(1.4, 32);
            var live = ShippedSvm(true);
            var a = ReplayEvaluator.Run(other, live).ClassifierMetrics;
            var b = ReplayEvaluator.Run(other, ShippedSvm(false)).ClassifierMetrics;
            Assert.That(live.LiveTimeScale, Is.EqualTo(1));
            Assert.That(live.RowsPerWindow, Is.EqualTo(2));
            Assert.That(a.MisclassificationRate, Is.EqualTo(b.MisclassificationRate));
            Assert.That(a.StandingAsWalking, Is.EqualTo(b.StandingAsWalking));
        }

        [Test]
        public void ASlowWalkersModelsReadTheirWindowAsItIs()
        {
            // Slower than the training walkers (0.71 s a step): training stretched its walks that far already, and reading
            // such wearers quicker cost every slow style held out, so the profile keeps the window as it is; with
            // AdaptationSettings.LearnedTimeScaleUpward it would read it slower.
            var models = new GaitModels { Threshold = Shipped.Threshold, Correlation = Shipped.Correlation, Svm = Shipped.Svm };
            var (walk, _, _) = QuickAndSlow(1.4, 32);
            var settings = new AdaptationSettings { LearnedRefit = false };
            Assert.That(Fitted(walk, models, settings).LearnedTimeScale, Is.EqualTo(1));
            settings.LearnedTimeScaleUpward = true;
            Assert.That(Fitted(walk, models, settings).LearnedTimeScale, Is.GreaterThan(1.2));
        }

        [Test]
        public void AProfileThatLeftTheScaleAtOneFollowsTheLiveScale()
        {
            // A wearer's calibration walk no quicker than the training walkers' leaves the profile's scale at 1; their other
            // walks may be quicker, and the models then follow the live scale as the shipped ones do. Kept at 1 instead (the
            // walk's measured step), bn1 *childish*'s held-out walks scored 32.3 % with ankle trackers against 25.3 % uncalibrated.
            var models = new GaitModels { Threshold = Shipped.Threshold, Correlation = Shipped.Correlation, Svm = Shipped.Svm };
            var (walk, _, _) = QuickAndSlow(1.4, 32);
            var (_, quick, _) = QuickAndSlow(2.4, 31);
            var profile = Fitted(walk, models, new AdaptationSettings { LearnedRefit = false });
            Assert.That(profile.Source, Is.EqualTo(WearerProfile.FromFootReferences));
            Assert.That(profile.LearnedTimeScale, Is.EqualTo(1));
            Assert.That(profile.ScaledModel(models.Svm).Values.ContainsKey(LearnedClassifier.WearerTimeScaleKey), Is.False);
            var svm = (LearnedClassifier)profile.Apply(models).Create("svm", out _);
            Assert.That(svm.LiveTimeScale, Is.EqualTo(1));
            ReplayEvaluator.Run(quick, svm);
            Assert.That(svm.LiveTimeScale, Is.LessThan(0.85));
            Assert.That(svm.TimeScale, Is.EqualTo(1));
        }
    }
}
