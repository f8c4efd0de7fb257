using System;
using System.Linq;
using System.Collections.Generic;
using System.IO;
using HeadGait.Synthetic;
using HeadGait.Training;
using NUnit.Framework;

namespace HeadGait.Tests
{
    public class WalkingGateTrainingTests
    {
        [Test]
        public void EveryGateAlsoLearnsFromCalmCopies()
        {
            var training = TestData.Training;
            var gates = GaitTraining.TrainGates(training);
            var withCalm = GaitTraining.WithCalmCopies(training);
            Assert.That(gates.Threshold.Weights, Is.EqualTo(WalkingGate.Train(withCalm, WalkingGate.DetectorPass, WindowLevel.ToleranceDegrees).Weights));
            Assert.That(gates.Correlation.Weights, Is.EqualTo(WalkingGate.Train(withCalm, WalkingGate.DetectorPass).Weights));
            Assert.That(gates.Learned.Weights, Is.EqualTo(WalkingGate.Train(withCalm, WalkingGate.LearnedPass, WindowLevel.ToleranceDegrees).Weights));
            // THR's and the learned classifiers' gates read a head looking down at its legs levelled; COR's, whose correlation
            // takes a bouncing bow for a step, does not.
            Assert.That(gates.Threshold.LevelTolerance, Is.EqualTo(WindowLevel.ToleranceDegrees));
            Assert.That(gates.Learned.LevelTolerance, Is.EqualTo(WindowLevel.ToleranceDegrees));
            Assert.That(gates.Correlation.LevelTolerance, Is.Null);
            Assert.That(gates.Correlation.Weights, Is.Not.EqualTo(WalkingGate.Train(training, WalkingGate.DetectorPass).Weights), "the calm copies change the fit");
        }

        [Test]
        public void ACorGateFittedOnCalmCopiesPassesMoreOfACalmWalkAndStillRefusesStanding()
        {
            // COR's gate as trained with and without the calm copies (no rhythm, so the score alone decides): a walk swaying
            // sideways and forwards a tenth as much, 30 % slower and bouncing less, passes more often with them (77 against 90 % of
            // its windows), and standing is still mostly refused (the generated start-stop recording's: 0.4 against 11 %;
            // on the real recordings COR showed 2.7 % of standing as walking either way).
            var training = TestData.Training;
            var plain = WalkingGate.Train(training, WalkingGate.DetectorPass);
            var withCalm = WalkingGate.Train(GaitTraining.WithCalmCopies(training), WalkingGate.DetectorPass);
            var walk = TestData.Eval("walk_straight");
            var calm = RecordingAugmentation.Transform(walk, 1.3, 0.1, 0.1, 0.4, new AugmentationSettings().SlowWindowSeconds, "calm");
            double PassShare(WalkingGate gate, Recording r, bool walking)
            {
                var rows = TestData.PerWindowTruth(r, WalkingGate.HistorySamples, gate.Passes);
                var kept = rows.FindAll(x => x.Walking == walking);
                return (double)kept.FindAll(x => x.Value).Count / kept.Count;
            }
            double before = PassShare(plain, calm, true), after = PassShare(withCalm, calm, true);
            Assert.That(after, Is.GreaterThan(before + 0.1), $"calm walk passed {before:P0} without the calm copies, {after:P0} with them");
            var standing = TestData.Eval("start_stop");
            Assert.That(PassShare(withCalm, standing, false), Is.LessThan(0.2), "the standing of the start-stop recording");
        }

        /// <summary>The gate's inputs on the newest window of a head-acceleration stream.</summary>
        static double[] LastFeatures(IEnumerable<ImuSample> samples)
        {
            var f = new double[WalkingGate.FeatureCount];
            var pre = new StreamPreprocessor(new PreprocessorSettings { History = WalkingGate.HistorySamples });
            foreach (var s in samples) pre.Push(s, w => WalkingGate.Features(w, f));
            return f;
        }

        static IEnumerable<ImuSample> Bouncing(double hertz, double amplitude, double seconds)
        {
            for (int i = 0; i < seconds * 100; i++)
                yield return new ImuSample(0.01 * i, 0, 0, 9.80665 + amplitude * Math.Sin(2 * Math.PI * hertz * 0.01 * i));
        }

        [Test]
        public void HalfAStepLaterWalkingHasSwungToTheOtherSideOfItsBounceAndHoppingHasNot()
        {
            var walker = GaitSubject.Random(11, "walker");
            var walk = WalkingStreamGenerator.Generate("walk", walker, new StreamScript().Walk(6, Foot.Left), 12);
            double walking = LastFeatures(walk.Samples.ConvertAll(r => r.Imu))[WalkingGate.FeatureCount - 1];
            Assert.That(walking, Is.LessThan(-0.3), "a step bounce (about 2 Hz) a quarter-second later");
            Assert.That(LastFeatures(Bouncing(4.1, 4, 3))[WalkingGate.FeatureCount - 1], Is.GreaterThan(0.5), "hopping on the spot at 4 Hz");
            Assert.That(LastFeatures(Bouncing(0.6, 2, 3))[WalkingGate.FeatureCount - 1], Is.GreaterThan(0.2), "a slow bow");
            Assert.That(LastFeatures(Bouncing(4.1, 0, 3))[WalkingGate.FeatureCount - 1], Is.EqualTo(0), "a head held still");
        }

        /// <summary>A gate's weights with the products weighing nothing: how a linear gate reads.</summary>
        static double[] LinearWeights(double[] features, double bias)
        {
            var w = new double[WalkingGate.WeightCount];
            Array.Copy(features, w, features.Length);
            w[WalkingGate.InputCount] = bias;
            return w;
        }

        [Test]
        public void OlderLinearGatesKeepTheirDecisions()
        {
            // Written before the autocorrelation input: six features and the bias.
            var old = WalkingGate.Parse("1.5,2,-0.5,0.25,-3,7,-12");
            Assert.That(old.Weights, Is.EqualTo(LinearWeights(new[] { 1.5, 2, -0.5, 0.25, -3, 7, 0 }, -12)));
            var kv = KeyValueText.Parse("# test\nwalking_gate=1.5,2,-0.5,0.25,-3,7,-12\nend\n", "# test", "thr.txt");
            Assert.That(kv.Gate("walking_gate").Weights, Is.EqualTo(old.Weights));
            // Written before the pairwise products: seven features and the bias.
            var linear = KeyValueText.Parse("# test\nwalking_gate=1.5,2,-0.5,0.25,-3,7,-0.8,-12\nend\n", "# test", "thr.txt").Gate("walking_gate");
            Assert.That(linear.Weights, Is.EqualTo(LinearWeights(new[] { 1.5, 2, -0.5, 0.25, -3, 7, -0.8 }, -12)));
            Assert.That(() => KeyValueText.Parse("# test\nwalking_gate=1,2,3\nend\n", "# test", "thr.txt").Gate("walking_gate"),
                Throws.TypeOf<FormatException>().With.Message.Contains("thr.txt").And.Message.Contains($"expected {WalkingGate.WeightCount}"));
        }

        [Test]
        public void ALevellingGateSaysSoInItsText()
        {
            var w = new double[WalkingGate.WeightCount];
            w[0] = 1.5;
            w[WalkingGate.InputCount] = -2;
            var gate = new WalkingGate(w, 15);
            Assert.That(gate.Serialize(), Does.StartWith("level:15;"));
            var back = WalkingGate.Parse(gate.Serialize());
            Assert.That(back.LevelTolerance, Is.EqualTo(15));
            Assert.That(back.Weights, Is.EqualTo(w));
            Assert.That(WalkingGate.Parse(new WalkingGate(w).Serialize()).LevelTolerance, Is.Null);
            var kv = KeyValueText.Parse("# test\nwalking_gate=" + gate.Serialize() + "\nend\n", "# test", "thr.txt");
            Assert.That(kv.Gate("walking_gate").LevelTolerance, Is.EqualTo(15));
            Assert.That(() => WalkingGate.Parse("level:x;" + new WalkingGate(w).Serialize()), Throws.TypeOf<FormatException>().With.Message.Contains("levelling"));
            Assert.That(() => WalkingGate.Parse("level:15"), Throws.TypeOf<FormatException>().With.Message.Contains("levelling"));
            Assert.That(() => KeyValueText.Parse("# test\nwalking_gate=level:200;1,2\nend\n", "# test", "thr.txt").Gate("walking_gate"),
                Throws.TypeOf<FormatException>().With.Message.Contains("thr.txt"));
        }

        [Test]
        public void ALevellingGateReadsAWalkLookingDownAsUpright()
        {
            // The generated walk, and the same walk from a head pitched 35 degrees down and rolled 10: levelled, the
            // spreads agree; as the head frame gives them, the forward one swings with the bounce. The mean vertical
            // (a bow's tilt) is read as it is either way.
            var walk = TestData.Eval("walk_straight");
            var tilted = RecordingAugmentation.Tilted(walk);
            List<double[]> FeaturesOf(Recording r, double? tolerance) => TestData.PerWindow(r, WalkingGate.HistorySamples, window =>
            {
                var f = new double[WalkingGate.FeatureCount];
                WalkingGate.Features(window, f, tolerance);
                return f;
            });
            double MeanGap(List<double[]> a, List<double[]> b, int feature)
            {
                double sum = 0;
                for (int i = 0; i < a.Count; i++) sum += Math.Abs(a[i][feature] - b[i][feature]);
                return sum / a.Count;
            }
            var upright = FeaturesOf(walk, 0);
            var levelled = FeaturesOf(tilted, 0);
            var raw = FeaturesOf(tilted, null);
            for (int k = 1; k <= 3; k++)
                Assert.That(MeanGap(upright, levelled, k), Is.LessThan(0.1).And.LessThan(MeanGap(upright, raw, k) / 5), $"log spread {k}");
            Assert.That(MeanGap(upright, raw, 3), Is.GreaterThan(0.3), "forward log spread, not levelled");
            Assert.That(MeanGap(upright, levelled, 5), Is.GreaterThan(0.1), "the mean vertical keeps the tilt");
        }

        [Test]
        public void TheProductsScoreAsWritten()
        {
            // Only the first product weighs: the lateral log spread with itself, which the products read as the spread
            // (m/s^2): the score is that weight times the spread squared, plus the bias.
            var w = new double[WalkingGate.WeightCount];
            w[WalkingGate.FeatureCount] = -1;
            w[WalkingGate.InputCount] = 2;
            var gate = new WalkingGate(w);
            var f = new double[WalkingGate.FeatureCount];
            var pre = new StreamPreprocessor(new PreprocessorSettings { History = WalkingGate.HistorySamples });
            double score = double.NaN;
            for (int i = 0; i < 200; i++)
                pre.Push(new ImuSample(0.01 * i, 0, 1.5 * Math.Sin(2 * Math.PI * 0.01 * i), 9.80665 + Math.Sin(4 * Math.PI * 0.01 * i)), window =>
                {
                    WalkingGate.Features(window, f);
                    score = gate.Score(window);
                });
            Assert.That(Math.Exp(f[2]), Is.GreaterThan(0.2), "the head swings sideways");
            Assert.That(score, Is.EqualTo(2 - Math.Exp(2 * f[2])).Within(1e-9));
            Assert.That(WalkingGate.Parse(gate.Serialize()).Weights, Is.EqualTo(w));
        }

        [Test]
        public void TheLearnedGateRefusesASwingFarHarderSidewaysThanAWalk()
        {
            // A child's wave swings the head sideways far harder than walking does (a spread of 8.5 m/s^2 here, as in the
            // recorded one; people's walks 1-3.5), while the head bobs at walking cadence (2 Hz). A gate linear in the
            // features took more movement for more walking and let all of it through (the committed linear gate passed
            // every window); the committed gate, with the products, refuses most of it and still passes a generated walk.
            var gate = TestData.CommittedThreshold.Gate;
            var pre = new StreamPreprocessor(new PreprocessorSettings { History = WalkingGate.HistorySamples });
            var waveScores = new List<double>();
            for (int i = 0; i < 400; i++)
            {
                double t = 0.01 * i;
                pre.Push(new ImuSample(t, 3.6 * Math.Sin(2 * Math.PI * t + 0.5), 12 * Math.Sin(2 * Math.PI * t), 9.80665 + Math.Sin(2 * Math.PI * 2 * t + 1)),
                    w => { if (i >= 150) waveScores.Add(gate.Score(w)); });
            }
            Assert.That(waveScores.FindAll(z => z > 0).Count, Is.LessThan(waveScores.Count / 4), "the wave passes the gate");

            var walk = WalkingStreamGenerator.Generate("walk", GaitSubject.Random(11, "walker"), new StreamScript().Walk(8, Foot.Left), 12);
            pre = new StreamPreprocessor(new PreprocessorSettings { History = WalkingGate.HistorySamples });
            int passed = 0, windows = 0;
            foreach (var r in walk.Samples)
                pre.Push(r.Imu, w =>
                {
                    if (!r.HasTruth || r.Left == GaitPhase.Standing || w.Count < WalkingGate.HistorySamples) return;
                    windows++;
                    if (gate.Passes(w)) passed++;
                });
            Assert.That(passed, Is.GreaterThan(0.8 * windows), "the generated walk is refused");
        }
    }

    public class StrideSegmentTests
    {
        [Test]
        public void AStanceLongerThanHalfTheStrideCutsItIntoSixteenPairsOfPhases()
        {
            var seg = new StrideSegments(PhaseMap.FromStanceFraction(0.574, 0.5));
            Assert.That(seg.Count, Is.EqualTo(16));
            Assert.That(seg.Names(), Is.EqualTo("IC/PSW,LR/PSW,LR/ISW,MST/ISW,MST/MSW,TST/MSW,TST/TSW,PSW/TSW,PSW/IC,PSW/LR,ISW/LR,ISW/MST,MSW/MST,MSW/TST,TSW/TST,TSW/PSW,STAND"));
            double total = 0;
            for (int k = 0; k < seg.Count; k++)
            {
                total += seg.Length(k);
                // A segment's phases are the map's anywhere inside it.
                Assert.That(seg.Map.PhaseAt(Foot.Left, seg.Center(k)), Is.EqualTo(seg.Left(k)));
                Assert.That(seg.Map.PhaseAt(Foot.Right, seg.Start(k) + 0.999 * seg.Length(k)), Is.EqualTo(seg.Right(k)));
                Assert.That(seg.ClassOf(seg.Left(k), seg.Right(k)), Is.EqualTo(k));
            }
            Assert.That(total, Is.EqualTo(1).Within(1e-9));
            Assert.That(seg.ClassOf(GaitPhase.Standing, GaitPhase.Standing), Is.EqualTo(seg.StandingClass));
            Assert.That(seg.ClassOf(GaitPhase.MidStance, GaitPhase.MidStance), Is.EqualTo(-1), "both feet in mid stance never happens in this map");
        }

        [Test]
        public void PerrysOwnMapSharesFourBoundariesBetweenTheFeetAndSoHasTwelve()
        {
            // Perry with the right foot half a stride later: 0/50, 12/62, 50/100 and 62/112 % coincide.
            Assert.That(new StrideSegments(PhaseMap.Perry).Count, Is.EqualTo(12));
        }
    }

    public class WindowFeatureTests
    {
        [Test]
        public void AveragesBlocksOfStepSamplesEndingAtTheNewestAndCentresAllButSmv()
        {
            var f = WindowFeatures.Parse("samples:50 step:2 channels:smv,lateral,forward");
            Assert.That(f.TimeSteps, Is.EqualTo(25));
            Assert.That(f.ToString(), Is.EqualTo("samples:50 step:2 channels:smv,lateral,forward"));
            var w = new SignalWindow(80, 100);
            for (int i = 0; i < 80; i++)
            {
                w.Smv[i] = i;
                w.Lateral[i] = 2 * i;
                w.Forward[i] = 5;
            }
            var x = new double[f.Width];
            f.Extract(w, x);
            // The newest 50 samples are 30..79: the last block is (78 + 79) / 2, the first (30 + 31) / 2. Lateral is centred on their mean.
            Assert.That(x[(f.TimeSteps - 1) * 3], Is.EqualTo(78.5));
            Assert.That(x[0], Is.EqualTo(30.5));
            Assert.That(x[(f.TimeSteps - 1) * 3 + 1], Is.EqualTo(2 * 78.5 - 2 * 54.5).Within(1e-9));
            Assert.That(x[2], Is.EqualTo(0));
        }

        [TestCase("samples:50 step:2")]
        [TestCase("samples:50 step:0 channels:smv")]
        [TestCase("samples:50 step:3 channels:smv")]
        [TestCase("samples:50 step:2 channels:smv,gyro")]
        [TestCase("samples:x step:2 channels:smv")]
        [TestCase("samples:50 step:2 channels:smv level:91")]
        [TestCase("samples:50 step:2 channels:smv level:x")]
        public void BadSpecsAreRefused(string spec) => Assert.That(() => WindowFeatures.Parse(spec), Throws.TypeOf<FormatException>());

        [Test]
        public void LevellingIsPartOfTheSpecAndOffInOldSpecs()
        {
            Assert.That(WindowFeatures.Parse("samples:50 step:2 channels:smv").LevelTolerance, Is.Null);
            var f = WindowFeatures.Parse("samples:50 step:2 channels:smv,forward level:15");
            Assert.That(f.LevelTolerance, Is.EqualTo(15));
            Assert.That(f.ToString(), Is.EqualTo("samples:50 step:2 channels:smv,forward level:15"));
            Assert.That(WindowFeatures.Parse("samples:50 step:2 channels:smv level:0").LevelTolerance, Is.EqualTo(0));
        }

        [Test]
        public void AWindowLevelTurnsTheMeanSpecificForceUpToTheTolerance()
        {
            // At rest with the head pitched 30 degrees down and rolled 15: gravity shows in all three head axes.
            const double g = 9.80665, pitch = 30 * Math.PI / 180, roll = -15 * Math.PI / 180;
            var w = new SignalWindow(100, 100);
            for (int i = 0; i < 100; i++)
            {
                w.Forward[i] = g * Math.Sin(pitch);
                w.Lateral[i] = g * Math.Cos(pitch) * Math.Sin(roll);
                w.Vertical[i] = g * Math.Cos(pitch) * Math.Cos(roll);
            }
            var level = WindowLevel.Of(w, 0);
            Assert.That(level.Forward(w, 50), Is.EqualTo(0).Within(1e-9));
            Assert.That(level.Lateral(w, 50), Is.EqualTo(0).Within(1e-9));
            Assert.That(level.Vertical(w, 50), Is.EqualTo(g).Within(1e-9));
            // With a tolerance it leans exactly that far afterwards, still forwards and to the right as it did.
            double lean = Math.Acos(Math.Cos(pitch) * Math.Cos(roll));
            var tolerant = WindowLevel.Of(w, 0, 15);
            Assert.That(tolerant.Vertical(w, 50), Is.EqualTo(g * Math.Cos(15 * Math.PI / 180)).Within(1e-9));
            Assert.That(tolerant.Forward(w, 50) / tolerant.Lateral(w, 50), Is.EqualTo(w.Forward[50] / w.Lateral[50]).Within(1e-9));
            // A lean within the tolerance is left as it is.
            var within = WindowLevel.Of(w, 0, lean * 180 / Math.PI + 1);
            Assert.That(within.Forward(w, 50), Is.EqualTo(w.Forward[50]));
            Assert.That(within.Vertical(w, 50), Is.EqualTo(w.Vertical[50]));
            // A window already upright is left as it is.
            var still = new SignalWindow(10, 100);
            for (int i = 0; i < 10; i++) still.Vertical[i] = g;
            var upright = WindowLevel.Of(still, 0);
            w.Forward[3] = 1.5;
            w.Lateral[3] = -0.5;
            w.Vertical[3] = 9;
            Assert.That(upright.Forward(w, 3), Is.EqualTo(1.5));
            Assert.That(upright.Vertical(w, 3), Is.EqualTo(9));
        }

        /// <summary>The learned features of every window after the first second of a recording.</summary>
        static List<double[]> FeaturesOf(Recording r, WindowFeatures f) => TestData.PerWindow(r, f.Samples, w =>
        {
            var x = new double[f.Width];
            f.Extract(w, x);
            return x;
        });

        static double RmsDifference(List<double[]> a, List<double[]> b)
        {
            double sum = 0;
            int n = 0;
            for (int i = 0; i < Math.Min(a.Count, b.Count); i++)
                for (int j = 0; j < a[i].Length; j++)
                {
                    sum += (a[i][j] - b[i][j]) * (a[i][j] - b[i][j]);
                    n++;
                }
            return Math.Sqrt(sum / n);
        }

        [Test]
        public void LevelledFeaturesOfAWalkLookingDownMatchTheUprightOnes()
        {
            // The same generated walk from a sensor pitched 35 degrees down and rolled 10: levelled, the learned
            // classifiers read what they read upright; unlevelled, the vertical bounce shows in the forward channel.
            var walk = TestData.Eval("walk_straight");
            var tilted = RecordingAugmentation.Tilted(walk);
            var level = WindowFeatures.Parse("samples:100 step:4 channels:smv,lateral,forward level:0");
            var raw = WindowFeatures.Parse("samples:100 step:4 channels:smv,lateral,forward");
            double levelled = RmsDifference(FeaturesOf(walk, level), FeaturesOf(tilted, level));
            double unlevelled = RmsDifference(FeaturesOf(walk, raw), FeaturesOf(tilted, raw));
            Assert.That(levelled, Is.LessThan(0.05), "m/s^2");
            Assert.That(unlevelled, Is.GreaterThan(10 * levelled));
        }
    }

    public class AugmentationTests
    {
        [Test]
        public void ATiltedCopyLooksDownWithTheSameLabelsAndMagnitudes()
        {
            var rec = TestData.Eval("walk_straight");
            var tilted = RecordingAugmentation.Tilted(rec);
            Assert.That(tilted.Samples.Count, Is.EqualTo(rec.Samples.Count));
            double pitch = RecordingAugmentation.TiltedPitchDegrees * Math.PI / 180, roll = RecordingAugmentation.TiltedRollDegrees * Math.PI / 180;
            double forward = 0, lateral = 0, up = 0, before = 0;
            for (int i = 0; i < rec.Samples.Count; i++)
            {
                ImuSample a = rec.Samples[i].Imu, b = tilted.Samples[i].Imu;
                Assert.That(b.Time, Is.EqualTo(a.Time));
                Assert.That(tilted.Samples[i].Left, Is.EqualTo(rec.Samples[i].Left));
                Assert.That(b.Magnitude, Is.EqualTo(a.Magnitude).Within(1e-9));
                forward += b.X;
                lateral += b.Y;
                up += b.Z;
                before += a.X;
            }
            int n = rec.Samples.Count;
            // Nose down: gravity now shows forwards (on top of the generated walker's own lean) and, rolled, sideways.
            Assert.That(forward / n - before / n, Is.EqualTo(9.81 * Math.Sin(pitch)).Within(1.0));
            Assert.That(lateral / n, Is.EqualTo(9.81 * Math.Cos(pitch) * Math.Sin(roll)).Within(0.5));
            Assert.That(up / n, Is.LessThan(9.81 * Math.Cos(pitch) + 0.5));
        }

        [TestCase(false)]
        [TestCase(true)]
        public void AWearerLikeCopyWalksAtADrawnCadenceWithDrawnSwayAndKeepsItsSteps(bool wide)
        {
            // The generated walk's walking part (a copy is made of walks only).
            var whole = TestData.Eval("walk_straight");
            var rec = new Recording(whole.Name, whole.Samples.Where(r => r.HasTruth && r.Left != GaitPhase.Standing && r.Right != GaitPhase.Standing).ToList());
            Assert.That(rec.Samples.Count, Is.GreaterThan(500));
            Assert.That(RecordingAugmentation.LikeWearer(whole, new DeterministicRandom(5)), Is.Null, "a recording that also stands keeps its own size");
            var settings = wide ? WearerSettings.Wide() : new WearerSettings();
            settings.MaxYawDegrees = 0;
            if (wide) Assert.That(settings.MinCadence < new WearerSettings().MinCadence && settings.MinVertical < new WearerSettings().MinVertical, Is.True);
            var random = new DeterministicRandom(5);
            for (int copy = 0; copy < 4; copy++)
            {
                var wearer = RecordingAugmentation.LikeWearer(rec, random, settings);
                Assert.That(RecordingAugmentation.IsCopy(wearer.Name) && RecordingAugmentation.OriginalName(wearer.Name) == rec.Name, Is.True, wearer.Name);
                double Cadence(Recording r)
                {
                    var rows = RecordingAugmentation.Uniform(r);
                    int contacts = 0, first = -1, last = -1;
                    for (int i = 1; i < rows.Count; i++)
                        if (GaitPhases.IsContact(rows[i - 1].Left, rows[i].Left) || GaitPhases.IsContact(rows[i - 1].Right, rows[i].Right))
                        {
                            contacts++;
                            if (first < 0) first = i;
                            last = i;
                        }
                    return 6000.0 * (contacts - 1) / (last - first);
                }
                double cadence = Cadence(wearer), own = Cadence(rec);
                Assert.That(cadence, Is.InRange(Math.Max(settings.MinCadence, own / settings.MaxStretch) - 1.5, Math.Min(settings.MaxCadence, own / settings.MinStretch) + 1.5));
                // The dynamic part (minus a 1 s moving average) of each axis has the drawn size, within the draw's range.
                var rows2 = RecordingAugmentation.Uniform(wearer);
                double[] min = { settings.MinForward, settings.MinLateral, settings.MinVertical }, max = { settings.MaxForward, settings.MaxLateral, settings.MaxVertical };
                for (int k = 0; k < 3; k++)
                {
                    var v = rows2.Select(r => k == 0 ? r.Imu.X : k == 1 ? r.Imu.Y : r.Imu.Z).ToArray();
                    double sum = 0;
                    int count = 0;
                    for (int i = 50; i < v.Length - 50; i++, count++)
                    {
                        double mean = 0;
                        for (int j = i - 50; j <= i + 50; j++) mean += v[j];
                        mean /= 101;
                        sum += (v[i] - mean) * (v[i] - mean);
                    }
                    Assert.That(Math.Sqrt(sum / count), Is.InRange(0.7 * min[k], 1.2 * max[k]), $"axis {k}");
                }
            }
            var standing = new Recording("still", Enumerable.Range(0, 300).Select(i => new RecordedSample(new ImuSample(i / 100.0, 0, 0, 9.81), GaitPhase.Standing, GaitPhase.Standing)).ToList());
            Assert.That(RecordingAugmentation.LikeWearer(standing, random), Is.Null, "standing keeps its own size");
        }

        [Test]
        public void ATurnedCopyMixesForwardIntoSidewaysAndKeepsTheVertical()
        {
            var rec = TestData.Eval("walk_straight");
            var turned = RecordingAugmentation.Turned(rec);
            Assert.That(turned.Name, Is.EqualTo(rec.Name));
            Assert.That(turned.Samples.Count, Is.EqualTo(rec.Samples.Count));
            double yaw = RecordingAugmentation.TurnedYawDegrees * Math.PI / 180;
            for (int i = 0; i < rec.Samples.Count; i++)
            {
                ImuSample a = rec.Samples[i].Imu, b = turned.Samples[i].Imu;
                Assert.That(turned.Samples[i].Right, Is.EqualTo(rec.Samples[i].Right));
                Assert.That(b.Z, Is.EqualTo(a.Z));
                Assert.That(b.X * b.X + b.Y * b.Y, Is.EqualTo(a.X * a.X + a.Y * a.Y).Within(1e-9));
            }
            // A head turned left sees the walk's forward push partly on its right (negative y): a pure forward
            // acceleration of 1 shows as cos(yaw) forward and -sin(yaw) sideways.
            var push = new Recording("push", new[] { new RecordedSample(new ImuSample(0, 1, 0, 9.81)) });
            var seen = RecordingAugmentation.Turned(push).Samples[0].Imu;
            Assert.That(seen.X, Is.EqualTo(Math.Cos(yaw)).Within(1e-12));
            Assert.That(seen.Y, Is.EqualTo(-Math.Sin(yaw)).Within(1e-12));
        }

        [Test]
        public void AJoltedCopyRingsAtEachContactOverSensorNoise()
        {
            // A still head on an exact 100 Hz grid whose left foot lands at sample 300: swing before, stance after.
            const int contact = 300;
            var rows = new List<RecordedSample>();
            for (int i = 0; i < 600; i++)
                rows.Add(new RecordedSample(new ImuSample(i / 100.0, 0, 0, 9.81),
                    i < contact ? GaitPhase.MidSwing : GaitPhase.InitialContact, GaitPhase.MidStance));
            var still = new Recording("still", rows);
            var jolted = RecordingAugmentation.Jolted(still);
            Assert.That(jolted.Name, Is.EqualTo("still"));
            Assert.That(jolted.Samples.Count, Is.EqualTo(rows.Count));
            double Rise(int i) => jolted.Samples[i].Imu.Z - 9.81;
            // The jolt peaks at the contact, vertical and half as much forward, and has rung out 0.1 s later.
            Assert.That(Rise(contact), Is.EqualTo(RecordingAugmentation.JoltPeak).Within(5 * RecordingAugmentation.JoltNoise));
            Assert.That(jolted.Samples[contact].Imu.X, Is.EqualTo(RecordingAugmentation.JoltForwardShare * RecordingAugmentation.JoltPeak).Within(5 * RecordingAugmentation.JoltNoise));
            // Before the contact only noise, of the stated SD on every axis.
            double sum = 0;
            int count = 0;
            for (int i = 0; i < contact; i++, count += 3)
            {
                var a = jolted.Samples[i].Imu;
                sum += a.X * a.X + a.Y * a.Y + Rise(i) * Rise(i);
            }
            Assert.That(Math.Sqrt(sum / count), Is.EqualTo(RecordingAugmentation.JoltNoise).Within(0.01));
            Assert.That(Math.Abs(Rise(contact + 10)), Is.LessThan(5 * RecordingAugmentation.JoltNoise));
            Assert.That(jolted.Samples[contact].Left, Is.EqualTo(GaitPhase.InitialContact));
            // Seeded by the name: the same clip is jolted the same way in every fold.
            Assert.That(RecordingAugmentation.Jolted(still).Samples[5].Imu.Y, Is.EqualTo(jolted.Samples[5].Imu.Y));
        }

        [Test]
        public void ACopyAtAnotherSensorRateKeepsTheSignalTheLabelsAndWhatThePipelineShows()
        {
            var walk = TestData.Eval("walk_straight");
            var at50 = RecordingAugmentation.AtRate(walk, 50);
            Assert.That(at50.Name, Is.EqualTo(walk.Name));
            Assert.That(at50.Samples.Count, Is.EqualTo(walk.Duration * 50).Within(2));
            for (int i = 1; i < at50.Samples.Count; i++)
                Assert.That(at50.Samples[i].Imu.Time - at50.Samples[i - 1].Imu.Time, Is.EqualTo(0.02).Within(1e-9));
            // Each kept row lies on the line between the two source rows around it, with the earlier row's labels.
            var uniform = RecordingAugmentation.Uniform(walk);
            for (int i = 0; i < at50.Samples.Count; i++)
            {
                Assert.That(at50.Samples[i].Imu.Z, Is.EqualTo(uniform[2 * i].Imu.Z).Within(1e-9));
                Assert.That(at50.Samples[i].Left, Is.EqualTo(uniform[2 * i].Left));
            }
            // The preprocessor brings it back to 100 Hz: the same classifier shows the walk about as well.
            double Miscl(Recording r) => ReplayEvaluator.Run(r, new CorrelationClassifier(TestData.Template)).ClassifierMetrics.MisclassificationRate;
            double at100 = Miscl(walk), atFifty = Miscl(at50);
            TestContext.WriteLine($"COR misclassification at 100 Hz {at100:P1}, at 50 Hz {atFifty:P1}");
            Assert.That(atFifty, Is.EqualTo(at100).Within(0.05));
            Assert.Throws<ArgumentOutOfRangeException>(() => RecordingAugmentation.AtRate(walk, 0));
        }

        [Test]
        public void StretchesTimeWithTheLabelsAndScalesOnlyTheDynamicPart()
        {
            var rec = TestData.Eval("walk_straight");
            var slow = RecordingAugmentation.Transform(rec, 1.25, 0.5, 0.5, 0.5, 1.0, "slow");
            Assert.That(slow.Duration, Is.EqualTo(rec.Duration * 1.25).Within(0.02));
            var steps = PhaseEvents.TruthSteps(rec);
            var slowSteps = PhaseEvents.TruthSteps(slow);
            Assert.That(slowSteps.Count, Is.EqualTo(steps.Count).Within(1));
            double mean(List<PhaseEvents.Step> s) { double t = 0; foreach (var x in s) t += x.Duration; return t / s.Count; }
            Assert.That(mean(slowSteps), Is.EqualTo(1.25 * mean(steps)).Within(0.01));
            // Gravity stays: a standing head still reads about g up; the bounce halves.
            Assert.That(slow.Samples[20].Imu.Z, Is.EqualTo(rec.Samples[16].Imu.Z).Within(0.5));
            double Spread(Recording r)
            {
                double m = 0, m2 = 0;
                int n = 0;
                foreach (var s in r.Samples)
                {
                    if (s.Left == GaitPhase.Standing) continue;
                    m += s.Imu.Z;
                    m2 += s.Imu.Z * s.Imu.Z;
                    n++;
                }
                m /= n;
                return Math.Sqrt(m2 / n - m * m);
            }
            Assert.That(Spread(slow), Is.EqualTo(0.5 * Spread(rec)).Within(0.1 * Spread(rec)));
        }

        /// <summary>Spread of what moves within a second (gravity and head tilt are left as they are), while walking.</summary>
        static double Spread(Recording r, Func<ImuSample, double> axis)
        {
            var v = r.Samples.ConvertAll(x => axis(x.Imu));
            double m = 0, m2 = 0;
            int n = 0;
            for (int i = 50; i < v.Count - 50; i++)
            {
                if (r.Samples[i].Left == GaitPhase.Standing) continue;
                double local = 0;
                for (int k = i - 50; k < i + 50; k++) local += v[k];
                double d = v[i] - local / 100;
                m += d;
                m2 += d * d;
                n++;
            }
            m /= n;
            return Math.Sqrt(m2 / n - m * m);
        }

        [Test]
        public void CalmCopiesAreMadeOfEachOriginalOnlyAndSwayLessSidewaysAndForwards()
        {
            var originals = TestData.Training.GetRange(0, 2);
            var training = GaitTraining.WithAugmentation(originals, 1);
            var withCalm = GaitTraining.WithCalmCopies(training);
            Assert.That(withCalm.Count, Is.EqualTo(training.Count + GaitTraining.CalmGateCopies * originals.Count));
            var sway = GaitTraining.CalmSway;
            foreach (var copy in withCalm.GetRange(training.Count, withCalm.Count - training.Count))
            {
                Assert.That(RecordingAugmentation.IsCopy(copy.Name), copy.Name);
                var original = originals.Find(r => r.Name == RecordingAugmentation.OriginalName(copy.Name));
                Assert.That(original, Is.Not.Null, copy.Name + " is a copy of an original, not of a copy");
                // Relative to the vertical bounce, as time stretch and overall gain scale all three alike.
                double lateral = Spread(copy, a => a.Y) / Spread(copy, a => a.Z) / (Spread(original, a => a.Y) / Spread(original, a => a.Z));
                double forward = Spread(copy, a => a.X) / Spread(copy, a => a.Z) / (Spread(original, a => a.X) / Spread(original, a => a.Z));
                Assert.That(lateral, Is.InRange(sway.MinLateralScale - 0.05, sway.MaxLateralScale + 0.05), copy.Name);
                Assert.That(forward, Is.InRange(sway.MinForwardScale - 0.05, sway.MaxForwardScale + 0.05), copy.Name);
            }
        }

        [TestCase("ear-like", RecordingAugmentation.EarLikeStretch, RecordingAugmentation.EarLikeSidewaysGain)]
        [TestCase("slow", RecordingAugmentation.SlowStretch, RecordingAugmentation.SlowSidewaysGain)]
        public void AnEarLikeOrSlowCopyIsSlowerAndSwaysLess(string variant, double stretch, double sidewaysGain)
        {
            var rec = TestData.Eval("walk_straight");
            var copy = variant == "slow" ? RecordingAugmentation.Slow(rec) : RecordingAugmentation.EarLike(rec);
            Assert.That(copy.Name, Is.EqualTo(rec.Name), "scored as the same clip");
            Assert.That(copy.Duration, Is.EqualTo(rec.Duration * stretch).Within(0.02));
            double slower = 1 / (stretch * stretch);
            Assert.That(Spread(copy, a => a.Z) / Spread(rec, a => a.Z), Is.EqualTo(slower).Within(0.1));
            Assert.That(Spread(copy, a => a.Y) / Spread(rec, a => a.Y), Is.EqualTo(slower * sidewaysGain).Within(0.1));
            var steps = PhaseEvents.TruthContacts(rec);
            var slowSteps = PhaseEvents.TruthContacts(copy);
            Assert.That(slowSteps.Count, Is.EqualTo(steps.Count), "the same steps");
            Assert.That(slowSteps[slowSteps.Count - 1].Time - slowSteps[0].Time, Is.EqualTo(stretch * (steps[steps.Count - 1].Time - steps[0].Time)).Within(0.05), "each taking longer");
        }

        [Test]
        public void AStartStopCopyStandsThenWalksFromAToeOffToAContactAndStandsAgain()
        {
            var rec = TestData.Eval("walk_straight");
            Assert.That(RecordingAugmentation.StartingAndStopping(rec, new DeterministicRandom(1)), Is.Null, "it stands in places: not one walk");
            int from = rec.Samples.FindIndex(x => x.Left != GaitPhase.Standing);
            int count = rec.Samples.FindIndex(from, x => x.Left == GaitPhase.Standing) - from;
            var walk = new Recording("walk", rec.Samples.GetRange(from, count));
            for (ulong seed = 1; seed <= 5; seed++)
            {
                var copy = RecordingAugmentation.StartingAndStopping(walk, new DeterministicRandom(seed));
                Assert.That(RecordingAugmentation.OriginalName(copy.Name), Is.EqualTo("walk"));
                var rows = copy.Samples;
                int start = rows.FindIndex(x => x.Left != GaitPhase.Standing);
                int stop = rows.FindLastIndex(x => x.Left != GaitPhase.Standing);
                var settings = new RecordingAugmentation.StartStopSettings();
                Assert.That(start / 100.0, Is.InRange(settings.MinStanding - 0.01, settings.MaxStanding + 0.01));
                Assert.That((rows.Count - 1 - stop) / 100.0, Is.InRange(settings.MinStanding - 0.01, settings.MaxStanding + 0.01));
                for (int i = start; i <= stop; i++)
                    Assert.That(rows[i].Left != GaitPhase.Standing && rows[i].Right != GaitPhase.Standing, $"one walk, no standing inside (row {i})");
                Assert.That(GaitPhases.IsSwing(rows[start].Left) ^ GaitPhases.IsSwing(rows[start].Right), "the walk begins as one foot leaves the ground");
                Assert.That(rows[stop].Left == GaitPhase.InitialContact || rows[stop].Right == GaitPhase.InitialContact, "and ends as one lands");
                for (int i = 1; i < rows.Count; i++) Assert.That(rows[i].Imu.Time - rows[i - 1].Imu.Time, Is.EqualTo(0.01).Within(1e-9));

                // Standing barely moves; the walk's bounce grows from nothing, so the splice does not jump.
                double Range(int a, int b)
                {
                    double lo = double.MaxValue, hi = double.MinValue;
                    for (int i = a; i < b; i++)
                    {
                        lo = Math.Min(lo, rows[i].Imu.Z);
                        hi = Math.Max(hi, rows[i].Imu.Z);
                    }
                    return hi - lo;
                }
                double walking = Range(start + 150, stop - 150);
                Assert.That(Range(0, start), Is.LessThan(0.1 * walking));
                Assert.That(Range(stop + 1, rows.Count), Is.LessThan(0.1 * walking));
                Assert.That(Range(start - 5, start + 5), Is.LessThan(0.1 * walking));
                Assert.That(Range(stop - 5, stop + 5), Is.LessThan(0.1 * walking));
                // Speeding up pushes the head forwards, slowing down backwards.
                double Forward(int a, int b)
                {
                    double sum = 0;
                    for (int i = a; i < b; i++) sum += rows[i].Imu.X;
                    return sum / (b - a);
                }
                Assert.That(Forward(start, start + 60) - Forward(0, start), Is.GreaterThan(0.3));
                Assert.That(Forward(stop - 40, stop) - Forward(stop + 1, rows.Count), Is.LessThan(-0.3));
            }
        }

        [Test]
        public void CopiesAreSeededByNameAndKeepTheirOriginalsName()
        {
            var a = GaitTraining.WithAugmentation(new[] { TestData.Eval("walk_straight") }, 3);
            var b = GaitTraining.WithAugmentation(new[] { TestData.Eval("walk_straight") }, 3);
            Assert.That(a.Count, Is.EqualTo(4));
            for (int i = 1; i < 4; i++)
            {
                Assert.That(a[i].Name, Does.StartWith("walk_straight~"));
                Assert.That(a[i].Name, Is.EqualTo(b[i].Name));
                Assert.That(a[i].Samples[500].Imu.Z, Is.EqualTo(b[i].Samples[500].Imu.Z));
            }
            Assert.That(a[1].Name, Is.Not.EqualTo(a[2].Name));
        }
    }

    public class CrossValidationTests
    {
        [Test]
        public void StylesComeFromTheCorpusNamingAndOtherNamesAreTheirOwnGroup()
        {
            Assert.That(CrossValidation.StyleOf("bn_wk_act_001"), Is.EqualTo("bn/act"));
            Assert.That(CrossValidation.StyleOf("bn_neg_wl_fem_002"), Is.EqualTo("bn/fem"));
            Assert.That(CrossValidation.StyleOf("bn1_walk-back_giant_001"), Is.EqualTo("bn1/giant"));
            Assert.That(CrossValidation.StyleOf("my_walk"), Is.EqualTo("my_walk"));
        }

        [Test]
        public void EveryRecordingIsTestedExactlyOnceAndNeverTrainedOnInItsFold()
        {
            var names = new List<string>();
            foreach (var s in new[] { "act", "fem", "mas" })
                for (int i = 1; i <= 7; i++) names.Add($"bn_wk_{s}_{i:000}");
            names.Add("bn_neg_wb_fem_001");
            foreach (var scheme in new[] { CrossValidation.ByStyle, CrossValidation.ByFile })
            {
                var folds = CrossValidation.Make(scheme, names);
                var seen = new Dictionary<string, int>();
                foreach (var f in folds)
                    foreach (var n in f.Test) seen[n] = seen.TryGetValue(n, out int c) ? c + 1 : 1;
                Assert.That(seen.Count, Is.EqualTo(names.Count), scheme);
                Assert.That(seen.Values, Has.All.EqualTo(1), scheme);
            }
            var style = CrossValidation.LeaveOneStyleOut(names);
            Assert.That(style.Count, Is.EqualTo(3));
            Assert.That(style.Find(f => f.Name == "bn/fem").Test, Does.Contain("bn_neg_wb_fem_001"));
            Assert.That(CrossValidation.FileFolds(names)[0].Test, Is.EquivalentTo(CrossValidation.FileFolds(names)[0].Test), "seeded");
        }
    }

    public class PhaseMapTrainingTests
    {
        [Test]
        public void LearnsTheStanceShareAndTheRightFootsOffsetFromTheLabels()
        {
            // The generated subjects walk with their own stance share (0.60-0.64); the learned map must sit inside that range.
            var map = PhaseMapTraining.Learn(TestData.Training);
            Assert.That(map.Onset(GaitPhase.InitialSwing), Is.InRange(0.59, 0.65));
            Assert.That(map.RightOffset, Is.EqualTo(0.5).Within(0.02));
            // Perry's proportions inside stance: loading response ends at 12/62 of it.
            Assert.That(map.Onset(GaitPhase.MidStance) / map.Onset(GaitPhase.InitialSwing), Is.EqualTo(12.0 / 62).Within(1e-9));
        }

        [Test]
        public void StanceFollowsTheStridePeriodOfTheTrainingWalkers()
        {
            // Two walkers: a slow one with a long stance and a fast one with a short stance. The learned share must rise
            // with the period by their difference over the period difference, and sit between them at the mean period.
            var slow = GaitSubject.Random(3, "slow");
            slow.StepFrequency = 1.6;
            slow.StanceFraction = 0.64;
            var fast = GaitSubject.Random(4, "fast");
            fast.StepFrequency = 2.1;
            fast.StanceFraction = 0.58;
            var recordings = new[]
            {
                WalkingStreamGenerator.Generate("slow", slow, new StreamScript().Stand(1).Walk(40, Foot.Left).Stand(1), 5),
                WalkingStreamGenerator.Generate("fast", fast, new StreamScript().Stand(1).Walk(40, Foot.Left).Stand(1), 6),
            };
            var map = PhaseMapTraining.Learn(recordings);
            double expected = (0.64 - 0.58) / (2 / 1.6 - 2 / 2.1);
            Assert.That(map.StanceSlope, Is.EqualTo(expected).Within(0.25 * expected));
            Assert.That(map.StanceShare(1 / 1.6), Is.EqualTo(0.64).Within(0.015));
            Assert.That(map.StanceShare(1 / 2.1), Is.EqualTo(0.58).Within(0.015));
        }

        [Test]
        public void WithoutWalkingItKeepsPerrysMap()
        {
            var standing = WalkingStreamGenerator.Generate("s", GaitSubject.Random(1), new StreamScript().Stand(10), 1);
            Assert.That(PhaseMapTraining.Learn(new[] { standing }).Serialize(), Is.EqualTo(PhaseMap.Perry.Serialize()));
        }
    }

    public class WindowDatasetTests
    {
        [Test]
        public void ExportsTheLiveWindowsWithTheLabelsAtTheirNewestSample()
        {
            string dir = Path.Combine(Path.GetTempPath(), "headgait-export-" + Guid.NewGuid().ToString("N"));
            try
            {
                var rec = TestData.Eval("start_stop");
                var features = WindowFeatures.Parse("samples:50 step:2 channels:smv,lateral");
                var segments = new StrideSegments(TestData.Map);
                var summary = WindowDataset.Export(new[] { new WindowDataset.Item { Recording = rec, FileIndex = 0 } }, new[] { rec.Name },
                    features, segments, 4, dir);
                long windows = 0;
                var pre = new StreamPreprocessor();
                foreach (var s in rec.Samples) pre.Push(s.Imu, w => windows++);
                Assert.That(summary.Windows, Is.EqualTo((windows + 3) / 4));
                Assert.That(summary.PerClass[segments.StandingClass], Is.GreaterThan(100));
                var x = File.ReadAllBytes(Path.Combine(dir, "X.npy"));
                Assert.That(x.Length, Is.EqualTo(128 + summary.Windows * features.Width * 4), "npy header + float32 data");
                string header = System.Text.Encoding.ASCII.GetString(x, 10, 118);
                Assert.That(header, Does.Contain($"'shape': ({summary.Windows}, 25, 2)"));
                Assert.That(File.ReadAllText(Path.Combine(dir, "dataset.txt")), Does.Contain("classes=" + segments.Names()));
            }
            finally
            {
                if (Directory.Exists(dir)) Directory.Delete(dir, true);
            }
        }

        [Test]
        public void StillRealRecordingsAreExportedAsStandingAtTheirOwnStrideAndNearTheGateOnly()
        {
            string dir = Path.Combine(Path.GetTempPath(), "headgait-export-" + Guid.NewGuid().ToString("N"));
            try
            {
                // The generated start-stop walk under a still and a walking activity's name: only the still one is kept,
                // standing throughout although it walks (nobody walks in a still activity, whatever the signal does).
                var walk = TestData.Eval("start_stop");
                var still = GaitTraining.RealStillRecordings(new[] { new Recording("p1_e001_standing_pickup", walk.Samples), new Recording("p1_e002_walking", walk.Samples) });
                Assert.That(still.Select(r => r.Name), Is.EqualTo(new[] { "p1_e001_standing_pickup" }));
                Assert.That(still[0].Samples.All(r => r.HasTruth && r.Left == GaitPhase.Standing && r.Right == GaitPhase.Standing), Is.True);
                var segments = new StrideSegments(TestData.Map);
                var items = new[]
                {
                    new WindowDataset.Item { Recording = walk, FileIndex = 0 },
                    new WindowDataset.Item { Recording = still[0], FileIndex = 1, Stride = 12 },
                };
                var summary = WindowDataset.Export(items, new[] { walk.Name, still[0].Name }, WindowFeatures.Parse("samples:50 step:2 channels:smv"), segments, 4, dir);
                long windows = 0;
                var pre = new StreamPreprocessor();
                foreach (var s in walk.Samples) pre.Push(s.Imu, w => windows++);
                long own = (windows + 3) / 4, fromStill = (windows + 11) / 12;
                Assert.That(summary.Windows, Is.EqualTo(own + fromStill));
                var y = File.ReadAllBytes(Path.Combine(dir, "y.npy"));
                for (long i = own; i < own + fromStill; i++)
                    Assert.That(BitConverter.ToInt32(y, (int)(128 + 4 * i)), Is.EqualTo(segments.StandingClass), $"window {i}");
                Assert.That(File.ReadAllText(Path.Combine(dir, "files.tsv")), Does.Contain("1\tp1_e001_standing_pickup"));

                // Near a gate only: one that scores every window -0.5 keeps them all within 1 log-odds, one at -2 none.
                long Near(double bias)
                {
                    var w = new double[WalkingGate.WeightCount];
                    w[WalkingGate.InputCount] = bias;
                    var item = new WindowDataset.Item { Recording = still[0], Stride = 12, NearGate = new WalkingGate(w), NearLogOdds = 1 };
                    return WindowDataset.Export(new[] { item }, new[] { still[0].Name }, WindowFeatures.Parse("samples:50 step:2 channels:smv"), segments, 4, Path.Combine(dir, "near")).Windows;
                }
                Assert.That(Near(-0.5), Is.EqualTo(fromStill));
                Assert.That(Near(-2), Is.Zero);
            }
            finally
            {
                if (Directory.Exists(dir)) Directory.Delete(dir, true);
            }
        }

        [Test]
        public void MarksAugmentedCopiesOneAndWalksMadeToStartAndStopTwo()
        {
            string dir = Path.Combine(Path.GetTempPath(), "headgait-export-" + Guid.NewGuid().ToString("N"));
            try
            {
                var rec = TestData.Eval("start_stop");
                var items = new[]
                {
                    new WindowDataset.Item { Recording = rec },
                    new WindowDataset.Item { Recording = rec, Augmented = true },
                    new WindowDataset.Item { Recording = rec, Augmented = true, StartsAndStops = true },
                };
                var summary = WindowDataset.Export(items, new[] { rec.Name }, WindowFeatures.Parse("samples:50 step:2 channels:smv"),
                    new StrideSegments(TestData.Map), 10, dir);
                var bytes = File.ReadAllBytes(Path.Combine(dir, "augmented.npy"));
                long each = summary.Windows / 3;
                Assert.That(bytes.Length, Is.EqualTo(128 + 4 * 3 * each));
                for (long i = 0; i < 3 * each; i++)
                    Assert.That(BitConverter.ToInt32(bytes, (int)(128 + 4 * i)), Is.EqualTo(i / each), $"window {i}");
            }
            finally
            {
                if (Directory.Exists(dir)) Directory.Delete(dir, true);
            }
        }
    }
}
