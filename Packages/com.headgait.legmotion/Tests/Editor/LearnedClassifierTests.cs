using System;
using System.Linq;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Text;
using HeadGait.Training;
using NUnit.Framework;

namespace HeadGait.Tests
{
    public class LearnedClassifierTests
    {
        static string Models => TestData.ModelsFolder;

        static string ModelPath(string file) => Path.Combine(Models, file);

        [TestCase(GaitModels.SvmFile)]
        [TestCase(GaitModels.BlstmFile)]
        public void ForwardPassEqualsTheTrainingFrameworksOutputs(string file)
        {
            var model = ModelFile.Load(ModelPath(file));
            var reference = ModelFile.Load(ReferenceCheck.ReferencePath(ModelPath(file)));
            Assert.That(reference.ShapeOf("inputs")[0], Is.GreaterThanOrEqualTo(32), "reference windows");
            Assert.That(ReferenceCheck.MaxDifference(model, reference), Is.LessThanOrEqualTo(1e-5));
        }

        /// <summary>
        /// The SVM sums its kernel products in float32, as its ONNX export does: its decision values stay within 1e-3 of
        /// LIBSVM's double ones per 5,828 support vectors (the bound set on the model that had 5,828; a float32 sum's rounding
        /// error grows with its number of terms; ONNX Runtime's own float32 export differs from the C# by up to about 6e-3)
        /// and every vote is cast alike (a differing vote makes the difference infinite).
        /// </summary>
        [Test]
        public void SvmDecisionValuesStayWithinFloatPrecisionOfTheFrameworks()
        {
            var model = ModelFile.Load(ModelPath(GaitModels.SvmFile));
            var reference = ModelFile.Load(ReferenceCheck.ReferencePath(ModelPath(GaitModels.SvmFile)));
            double diff = ReferenceCheck.MaxDecisionDifference(model, reference);
            int supportVectors = model.ShapeOf("support_vectors")[0];
            TestContext.WriteLine($"largest decision value difference {diff:G3} over {supportVectors} support vectors");
            Assert.That(diff, Is.LessThanOrEqualTo(1e-3 * supportVectors / 5828.0));
        }

        /// <summary>
        /// Confident scores for strides of segments, each as long as its share of a 1.1 s stride; in the middle of every
        /// segment <paramref name="length"/> windows name the class <paramref name="flicker"/> segments further on instead.
        /// </summary>
        static (List<bool> following, int landings) Flickering(BlstmClassifier blstm, int flicker, int strides = 2, int shiftAfter = -1, int shift = 0, int length = 2)
        {
            int n = blstm.Segments.Count, classes = blstm.Segments.ClassCount;
            var sequence = new List<int>();
            for (int stride = 0; stride < strides; stride++)
                for (int k = 0; k < n; k++)
                {
                    int windows = Math.Max(4, (int)Math.Round(blstm.Segments.Length(k) * 110));
                    for (int w = 0; w < windows; w++)
                    {
                        int c = w >= windows / 2 && w < windows / 2 + length ? (k + flicker + n) % n : k;
                        if (shiftAfter >= 0 && sequence.Count >= shiftAfter) c = (c + shift) % n;
                        sequence.Add(c);
                    }
                }
            var scores = new double[sequence.Count * classes];
            for (int i = 0; i < sequence.Count; i++)
                for (int c = 0; c < classes; c++) scores[i * classes + c] = c == sequence[i] ? 0.97 : 0.03 / (classes - 1);
            var following = new List<bool>();
            int landings = 0;
            GaitPhase previous = GaitPhase.Standing;
            for (int i = 0; i < sequence.Count; i++)
            {
                var p = blstm.ClassifyScored(scores, i, 0.01 * i, 100);
                if (GaitPhases.IsSwing(previous) && GaitPhases.IsStance(p.Left)) landings++;
                previous = p.Left;
                following.Add(p.Left == blstm.Segments.Left(sequence[i]) && p.Right == blstm.Segments.Right(sequence[i]));
            }
            return (following, landings);
        }

        static BlstmClassifier Blstm(string models) => new BlstmClassifier(GaitModels.Load(models).Blstm);

        [TestCase(-1, 2)]
        [TestCase(-2, 4)]
        [TestCase(8, 4)]
        public void AClassThatFlickersBackOrAcrossTheStrideIsHeldSoNoFootLandsTwice(int flicker, int length)
        {
            var (_, landings) = Flickering(Blstm(Models), flicker, length: length);
            Assert.That(landings, Is.EqualTo(2), "the left foot lands once per stride, however the scores flicker");
            var free = new BlstmClassifier(GaitModels.Load(Models).Blstm, new PhaseFilterSettings { HoldBackSegments = 0, SwapSegments = 99 });
            Assert.That(Flickering(free, flicker, length: length).landings, Is.GreaterThan(2), "without the holds the flicker lands the foot again");
        }

        [Test]
        public void WhenTheFeetReallySwapTheShownClassFollowsWithinAFewSegments()
        {
            var blstm = Blstm(Models);
            int n = blstm.Segments.Count;
            // From window 150 on the model names the class half a stride on, for good.
            var (following, landings) = Flickering(blstm, 0, strides: 3, shiftAfter: 150, shift: n / 2);
            Assert.That(following.GetRange(following.Count - 100, 100), Is.All.True, "a stride later the legs show what the model says");
            int firstFollowing = following.FindIndex(150, f => f);
            // Carried on for a step (SwapCarrySteps at the default 0.55 s step) before the swap is taken, and a few windows more.
            Assert.That(firstFollowing - 150, Is.LessThan(new PhaseFilterSettings().SwapCarrySteps * 55 + 10), "held for at most about a step");
        }

        /// <summary>
        /// Left-foot landings and the last 100 windows' agreement with the walk when confident scores follow the segments
        /// in order at a 1.1 s stride for three strides, except that windows 120-159 name the class half a stride on (the
        /// model's feet swapped for 0.4 s, then back).
        /// </summary>
        static (int landings, bool followsAtTheEnd) SwappedForAWhile(BlstmClassifier blstm)
        {
            int n = blstm.Segments.Count, classes = blstm.Segments.ClassCount;
            var sequence = new List<int>();
            for (int stride = 0; stride < 3; stride++)
                for (int k = 0; k < n; k++)
                    for (int w = Math.Max(4, (int)Math.Round(blstm.Segments.Length(k) * 110)); w > 0; w--) sequence.Add(k);
            var scores = new double[sequence.Count * classes];
            for (int i = 0; i < sequence.Count; i++)
            {
                int named = i >= 120 && i < 160 ? (sequence[i] + n / 2) % n : sequence[i];
                for (int c = 0; c < classes; c++) scores[i * classes + c] = c == named ? 0.97 : 0.03 / (classes - 1);
            }
            int landings = 0;
            bool follows = true;
            GaitPhase previous = GaitPhase.Standing;
            for (int i = 0; i < sequence.Count; i++)
            {
                var p = blstm.ClassifyScored(scores, i, 0.01 * i, 100);
                if (GaitPhases.IsSwing(previous) && GaitPhases.IsStance(p.Left)) landings++;
                previous = p.Left;
                if (i >= sequence.Count - 100) follows &= p.Left == blstm.Segments.Left(sequence[i]) && p.Right == blstm.Segments.Right(sequence[i]);
            }
            return (landings, follows);
        }

        [Test]
        public void WhileTheFeetAreHeldAcrossTheStrideTheShownPositionGoesOn()
        {
            // Three strides from the left foot's contact: it lands again at the start of the second and the third.
            var (landings, follows) = SwappedForAWhile(Blstm(Models));
            Assert.That(landings, Is.EqualTo(2), "no step lost while the model's feet were swapped");
            Assert.That(follows, Is.True, "and the legs show what the model says once it is back");
            var waiting = new BlstmClassifier(GaitModels.Load(Models).Blstm, new PhaseFilterSettings { SwapCarrySteps = 0 });
            Assert.That(SwappedForAWhile(waiting).landings, Is.Not.EqualTo(2), "a held class that stands still, then takes the model's class back, lands the foot out of turn");
        }

        /// <summary>
        /// What the BLSTM shows over 2 s of confident walking scores (the segments in order at a 1.1 s stride) and then 1 s
        /// of standing at <paramref name="standing"/> (the walk's next segment second, as a network's runner-up), the gate
        /// saying <paramref name="gate"/> throughout.
        /// </summary>
        static List<GaitPrediction> WalkThenStanding(BlstmClassifier blstm, GateVerdict gate, double standing)
        {
            int n = blstm.Segments.Count, classes = blstm.Segments.ClassCount;
            var scores = new double[300 * classes];
            for (int i = 0; i < 300; i++)
            {
                int walking = (int)(i / 110.0 * n) % n;
                for (int c = 0; c < classes; c++) scores[i * classes + c] = 0.001 / (classes - 2);
                if (i < 200) scores[i * classes + walking] = 0.999;
                else
                {
                    scores[i * classes + blstm.Segments.StandingClass] = standing;
                    scores[i * classes + walking] = 0.999 - standing;
                }
            }
            var shown = new List<GaitPrediction>();
            for (int i = 0; i < 300; i++)
                shown.Add(blstm.ClassifyScored(scores, i, 0.01 * i, 100, i < 200 ? GateVerdict.Passes : gate));
            return shown;
        }

        [Test]
        public void AWindowTheGateIsSureIsWalkingDoesNotEndAWalkButStartsNone()
        {
            var settings = new PhaseFilterSettings();
            Assert.That(settings.SureWalkingLogOdds, Is.EqualTo(5), "over 99 % sure");
            var passed = WalkThenStanding(Blstm(Models), GateVerdict.Passes, 0.95);
            var sure = WalkThenStanding(Blstm(Models), GateVerdict.SurelyWalking, 0.95);
            Assert.That(passed[199].IsWalking && sure[199].IsWalking, Is.True, "walking before the model's scores turn");
            Assert.That(passed.GetRange(250, 50).TrueForAll(p => !p.IsWalking), Is.True, "where the gate only passes, the model ends the walk");
            Assert.That(sure.GetRange(200, 100).TrueForAll(p => p.IsWalking), Is.True, "where the gate is sure, a 95 % standing does not");
            var certain = WalkThenStanding(Blstm(Models), GateVerdict.SurelyWalking, 0.998);
            Assert.That(certain.GetRange(250, 50).TrueForAll(p => !p.IsWalking), Is.True, "a model all but certain of standing still ends it");
            var standing = new BlstmClassifier(GaitModels.Load(Models).Blstm);
            int classes = standing.Segments.ClassCount;
            var still = new double[classes];
            still[standing.Segments.StandingClass] = 0.99;
            for (int i = 0; i < 100; i++)
                Assert.That(standing.ClassifyScored(still, 0, 0.01 * i, 100, GateVerdict.SurelyWalking).IsWalking, Is.False, "the gate alone starts no walk");
        }

        [Test]
        public void AShortRefusalOfTheGateInsideAWalkDoesNotEndIt()
        {
            // Confident walking scores throughout; the gate refuses 4 windows (40 ms) in the middle, as it does inside
            // slow real walks. With the refusal as standing outright the walk broke there.
            List<GaitPrediction> Shown(PhaseFilterSettings settings)
            {
                var blstm = new BlstmClassifier(GaitModels.Load(Models).Blstm, settings);
                int n = blstm.Segments.Count, classes = blstm.Segments.ClassCount;
                var scores = new double[300 * classes];
                for (int i = 0; i < 300; i++)
                {
                    for (int c = 0; c < classes; c++) scores[i * classes + c] = 0.001 / (classes - 1);
                    scores[i * classes + (int)(i / 110.0 * n) % n] = 0.999;
                }
                var shown = new List<GaitPrediction>();
                for (int i = 0; i < 300; i++)
                    shown.Add(blstm.ClassifyScored(scores, i, 0.01 * i, 100, i >= 200 && i < 204 ? GateVerdict.Refuses : GateVerdict.Passes));
                return shown;
            }
            Assert.That(new PhaseFilterSettings().RefusedWalkingShare, Is.GreaterThan(0));
            var ridden = Shown(new PhaseFilterSettings());
            var broken = Shown(new PhaseFilterSettings { RefusedWalkingShare = 0 });
            Assert.That(ridden.FindIndex(100, p => !p.IsWalking), Is.EqualTo(-1), "the walk rides out the refusal");
            Assert.That(broken.GetRange(200, 4).Exists(p => !p.IsWalking), Is.True, "a refusal as standing outright ends it");
            // A refusal that lasts still ends the walk, and no refusal starts one.
            var blstm2 = new BlstmClassifier(GaitModels.Load(Models).Blstm);
            int k = blstm2.Segments.ClassCount;
            var walkingScores = new double[k];
            walkingScores[0] = 1;
            GaitPrediction last = default;
            for (int i = 0; i < 200; i++) last = blstm2.ClassifyScored(walkingScores, 0, 0.01 * i, 100, GateVerdict.Passes);
            Assert.That(last.IsWalking, Is.True);
            for (int i = 200; i < 300; i++) last = blstm2.ClassifyScored(walkingScores, 0, 0.01 * i, 100, GateVerdict.Refuses);
            Assert.That(last.IsWalking, Is.False, "a second of refusals ends the walk");
            for (int i = 300; i < 400; i++) Assert.That(blstm2.ClassifyScored(walkingScores, 0, 0.01 * i, 100, GateVerdict.Refuses).IsWalking, Is.False, "refused while standing: standing");
        }

        [Test]
        public void AWalkTheGateRefusesForAStretchWhileItsRhythmGoesOnStaysOneWalk([Values("svm", "blstm")] string kind)
        {
            // The generated straight walk, its gate swapped for one that refuses every window for 1.5 s in the middle, as
            // the gate refuses slow, calm glasses wearers' heads: the head's rhythm goes on, so the walk goes on (THR and
            // COR's step clock rides such refusals out: StepClock.HeldByRhythm). Without the hold it ended after 10 refusals.
            var rec = TestData.Eval("walk_straight");
            var models = GaitModels.Load(Models);
            double from = rec.Samples[rec.Samples.Count / 2].Imu.Time, to = from + 1.5;
            List<(double time, bool walking)> Shown(PhaseFilterSettings settings)
            {
                LearnedClassifier c = kind == "svm" ? new SvmClassifier(models.Svm, settings) : new BlstmClassifier(models.Blstm, settings);
                return ShownWithGateSwapped(c, rec, ScoringEveryWindow(-100, c.Gate), from, to);
            }
            PhaseFilterSettings Settings(bool hold)
            {
                var settings = kind == "svm" ? SvmClassifier.DefaultFilter() : new PhaseFilterSettings();
                settings.HoldOnRhythm = hold;
                return settings;
            }
            Assert.That(new PhaseFilterSettings().HoldOnRhythm, Is.True);
            var held = Shown(Settings(true));
            var refused = held.FindAll(p => p.time >= from && p.time < to);
            Assert.That(refused.Count, Is.GreaterThan(100));
            Assert.That(held.Exists(p => p.time > from - 1 && p.time < from && p.walking), Is.True, "walking before the refusals");
            Assert.That(held.FindAll(p => p.time >= from - 0.5 && p.time < to + 0.5).TrueForAll(p => p.walking), Is.True, "one walk through the refusals");
            var unheld = Shown(Settings(false));
            Assert.That(unheld.FindAll(p => p.time >= from && p.time < to).Exists(p => !p.walking), Is.True, "without the hold the refusals end the walk");
        }

        /// <summary>
        /// Each window of <paramref name="rec"/> as <paramref name="c"/> shows it (walking or not), its gate swapped for
        /// <paramref name="swapped"/> for windows ending in [<paramref name="from"/>, <paramref name="to"/>).
        /// </summary>
        static List<(double time, bool walking)> ShownWithGateSwapped(LearnedClassifier c, Recording rec, WalkingGate swapped, double from, double to)
        {
            var gate = c.Gate;
            var pre = new StreamPreprocessor(new PreprocessorSettings { History = c.WindowLength });
            var shown = new List<(double, bool)>();
            foreach (var s in rec.Samples)
                pre.Push(s.Imu, w =>
                {
                    c.Gate = w.EndTime >= from && w.EndTime < to ? swapped : gate;
                    shown.Add((w.EndTime, c.Classify(w).IsWalking));
                });
            return shown;
        }

        /// <summary>A gate that gives every window <paramref name="logOdds"/> (levelled as <paramref name="like"/>, no rhythm of its own).</summary>
        static WalkingGate ScoringEveryWindow(double logOdds, WalkingGate like)
        {
            var weights = new double[WalkingGate.LinearWeightCount];
            weights[weights.Length - 1] = logOdds;
            return WalkingGate.FromWeights(weights, like.LevelTolerance);
        }

        [Test]
        public void ASettledWalkRidesOutTheGatesNearMissesButNoneStartsOne()
        {
            // The generated straight walk, its gate swapped for one that refuses every window by 1 log-odds for 1.5 s in the
            // middle, as the gate refuses slow, calm walkers, the head's rhythm not holding (HoldOnRhythm off): the SVM's walk
            // goes on through them. Before NarrowRefusalLogOdds the refusals ended it.
            var rec = TestData.Eval("walk_straight");
            var models = GaitModels.Load(Models);
            double from = rec.Samples[rec.Samples.Count / 2].Imu.Time, to = from + 1.5;
            List<(double time, bool walking)> Shown(double narrow, double gateFrom, double refusal)
            {
                var settings = SvmClassifier.DefaultFilter();
                settings.HoldOnRhythm = false;
                settings.NarrowRefusalLogOdds = narrow;
                var c = new SvmClassifier(models.Svm, settings);
                return ShownWithGateSwapped(c, rec, ScoringEveryWindow(refusal, c.Gate), gateFrom, to);
            }
            Assert.That(SvmClassifier.DefaultFilter().NarrowRefusalLogOdds, Is.EqualTo(2));
            var held = Shown(2, from, -1);
            Assert.That(held.Exists(p => p.time > from - 1 && p.time < from && p.walking), Is.True, "walking before the near misses");
            Assert.That(held.FindAll(p => p.time >= from - 0.5 && p.time < to + 0.5).TrueForAll(p => p.walking), Is.True, "one walk through the near misses");
            Assert.That(Shown(0, from, -1).FindAll(p => p.time >= from && p.time < to).Exists(p => !p.walking), Is.True, "without the hold they end the walk");
            Assert.That(Shown(2, from, -3).FindAll(p => p.time >= from && p.time < to).Exists(p => !p.walking), Is.True, "a refusal by more ends it");
            Assert.That(Shown(2, double.NegativeInfinity, -1).FindAll(p => p.time < to).TrueForAll(p => !p.walking), Is.True, "near misses from the start start no walk");
        }

        [Test]
        public void TheGateVerdictFollowsItsLogOdds()
        {
            var rec = TestData.Eval("walk_straight");
            var blstm = Blstm(Models);
            var pre = new StreamPreprocessor(new PreprocessorSettings { History = blstm.WindowLength });
            var verdicts = new List<(GateVerdict verdict, double logOdds)>();
            foreach (var s in rec.Samples) pre.Push(s.Imu, w => verdicts.Add((blstm.JudgeGate(w), blstm.Gate.Score(w))));
            Assert.That(verdicts.Exists(v => v.verdict == GateVerdict.SurelyWalking), Is.True, "the generated walk has windows the gate is sure of");
            foreach (var (verdict, logOdds) in verdicts)
                if (logOdds >= 5) Assert.That(verdict, Is.EqualTo(GateVerdict.SurelyWalking));
            // Below that, a window is sure exactly when its step rhythm says walking (the rhythm alone may pass it).
            var rhythmOff = new BlstmClassifier(GaitModels.Load(Models).Blstm, new PhaseFilterSettings { SureOnStepRhythm = false });
            pre.Reset();
            int sureByRhythm = 0;
            foreach (var s in rec.Samples)
                pre.Push(s.Imu, w =>
                {
                    double logOdds = blstm.Gate.Score(w);
                    if (logOdds >= 5) return;
                    bool rhythm = StepRhythm.Of(w, blstm.Gate.LevelTolerance).IsWalking;
                    var verdict = blstm.JudgeGate(w);
                    if (rhythm && verdict == GateVerdict.SurelyWalking) sureByRhythm++;
                    Assert.That(verdict, Is.EqualTo(rhythm ? GateVerdict.SurelyWalking : logOdds > 0 ? GateVerdict.Passes : GateVerdict.Refuses));
                    Assert.That(rhythmOff.JudgeGate(w), Is.EqualTo(logOdds > 0 ? GateVerdict.Passes : rhythm ? GateVerdict.Passes : GateVerdict.Refuses), "without the rhythm as sure");
                });
            Assert.That(sureByRhythm, Is.GreaterThan(0), "the generated walk has windows only its rhythm makes sure");
            var off = new BlstmClassifier(GaitModels.Load(Models).Blstm, new PhaseFilterSettings { SureWalkingLogOdds = double.PositiveInfinity, SureOnStepRhythm = false });
            pre.Reset();
            foreach (var s in rec.Samples) pre.Push(s.Imu, w => Assert.That(off.JudgeGate(w), Is.Not.EqualTo(GateVerdict.SurelyWalking), "turned off"));
            blstm.Gate = null;
            pre.Reset();
            foreach (var s in rec.Samples) pre.Push(s.Imu, w => Assert.That(blstm.JudgeGate(w), Is.EqualTo(GateVerdict.Passes), "no gate: the model decides"));
        }

        [Test]
        public void TheSvmsHalfWeightEvidenceBreaksGeneratedWalksApartLessOften()
        {
            // Votes made into probabilities are overconfident: at full weight a few windows voting otherwise end a walk.
            var model = GaitModels.Load(Models).Svm;
            GaitMetrics Pooled(Func<SvmClassifier> make) => GaitMetrics.Pool(TestData.EvalSet().Select(r => ReplayEvaluator.Run(r, make()).ClassifierMetrics));
            var half = Pooled(() => new SvmClassifier(model));
            var full = Pooled(() => new SvmClassifier(model, new PhaseFilterSettings()));
            Assert.That(new SvmClassifier(model).Filter.Settings.EvidenceWeight, Is.EqualTo(0.5));
            Assert.That(half.ShownWalkingBouts, Is.LessThan(full.ShownWalkingBouts));
            Assert.That(half.StepRecall, Is.GreaterThanOrEqualTo(full.StepRecall - 0.01), "without losing steps");
        }

        [Test]
        public void ACorruptedWeightChangesTheOutputsBeyondTheLimit()
        {
            // The check above can fail: perturb one LSTM weight and it must notice.
            var model = ModelFile.Load(ModelPath(GaitModels.BlstmFile));
            var weights = model.Tensor("lstm_w_hh", model.ShapeOf("lstm_w_hh"));
            weights[7] += 0.5;
            var reference = ModelFile.Load(ReferenceCheck.ReferencePath(ModelPath(GaitModels.BlstmFile)));
            Assert.That(ReferenceCheck.MaxDifference(model, reference), Is.GreaterThan(1e-5));
        }

        [Test]
        public void CommittedModelsAgreeOnClassesFeaturesAndPhaseMap()
        {
            var models = GaitModels.Load(Models);
            Assert.That(models.Problems, Is.Empty);
            var svm = new SvmClassifier(models.Svm);
            var blstm = new BlstmClassifier(models.Blstm);
            Assert.That(svm.Segments.Names(), Is.EqualTo(blstm.Segments.Names()));
            Assert.That(svm.PhaseMap.Serialize(), Is.EqualTo(models.Correlation.PhaseMap.Serialize()), "one phase map for all four classifiers");
            Assert.That(models.Threshold.PhaseMap.Serialize(), Is.EqualTo(models.Correlation.PhaseMap.Serialize()));
            Assert.That(svm.Segments.Count, Is.EqualTo(16));
            Assert.That(svm.Features.ToString(), Is.EqualTo(blstm.Features.ToString()));
        }

        [TestCase("blstm")]
        [TestCase("svm")]
        public void RecognisesGeneratedWalkingAndStanding(string name)
        {
            var models = GaitModels.Load(Models);
            var rec = TestData.Eval("walk_straight");
            var r = ReplayEvaluator.Run(rec, models.Create(name, out string warning));
            Assert.That(warning, Is.Null);
            // Trained on people, tried on the package's generated walker: it must at least tell walking from standing.
            Assert.That(r.ClassifierMetrics.WalkingAsStanding, Is.LessThan(0.15));
            Assert.That(r.ClassifierMetrics.StandingAsWalking, Is.LessThan(0.15));
            Assert.That(r.AnimatorMetrics.StepRecall, Is.GreaterThan(0.8));
        }

        [Test]
        public void OnnxExportsRunInOnnxRuntimeLikeTheTrainingFramework()
        {
            // ONNX Runtime is not on NuGet here; its npm package is (training/package.json, installed by .ci/run).
            string script = Path.GetFullPath(Path.Combine(Models, "..", "..", "..", "training", "check_onnx.mjs"));
            string modules = Path.Combine(Path.GetDirectoryName(script) ?? ".", "node_modules", "onnxruntime-node");
            if (!File.Exists(script) || !Directory.Exists(modules))
                Assert.Ignore($"ONNX Runtime for Node not installed (cd training && npm ci --ignore-scripts); looked for {modules}");
            var info = new ProcessStartInfo("node", $"\"{script}\" \"{Models}\"") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
            Process p;
            try
            {
                p = Process.Start(info);
            }
            catch (System.ComponentModel.Win32Exception)
            {
                Assert.Ignore("node is not installed");
                return;
            }
            string output = p.StandardOutput.ReadToEnd() + p.StandardError.ReadToEnd();
            p.WaitForExit();
            TestContext.WriteLine(output);
            Assert.That(p.ExitCode, Is.EqualTo(0), output);
            Assert.That(output, Does.Contain("blstm.onnx"));
            Assert.That(output, Does.Contain("svm.onnx"));
        }
    }

    public class ModelFileTests
    {
        static byte[] Blstm() => File.ReadAllBytes(Path.Combine(TestData.ModelsFolder, GaitModels.BlstmFile));

        static ModelFormatException Refused(byte[] bytes)
            => Assert.Throws<ModelFormatException>(() => new BlstmClassifier(ModelFile.Parse(bytes, "broken.bytes")));

        static int HeaderEnd(byte[] b)
        {
            string text = Encoding.UTF8.GetString(b, 0, Math.Min(b.Length, 20000));
            return Encoding.UTF8.GetByteCount(text.Substring(0, text.IndexOf("\nend\n", StringComparison.Ordinal) + 5));
        }

        [Test]
        public void RoundTripsThroughBytes()
        {
            var m = ModelFile.Parse(Blstm(), "blstm.bytes");
            var again = ModelFile.Parse(m.ToBytes(), "again");
            Assert.That(again.Kind, Is.EqualTo("blstm"));
            Assert.That(again.Tensor("fc_b", again.ShapeOf("fc_b")), Is.EqualTo(m.Tensor("fc_b", m.ShapeOf("fc_b"))));
        }

        [Test]
        public void EmptyTruncatedOrForeignFilesNameTheFileAndTheProblem()
        {
            var good = Blstm();
            Assert.That(Refused(new byte[0]).Message, Does.StartWith("broken.bytes:").And.Contain("empty"));
            Assert.That(Refused(Encoding.UTF8.GetBytes("PK\u0003\u0004 zip")).Message, Does.Contain("not a HeadGait model"));
            var truncated = new byte[good.Length - 100];
            Array.Copy(good, truncated, truncated.Length);
            Assert.That(Refused(truncated).Message, Does.Contain("truncated"));
            var headerOnly = new byte[HeaderEnd(good) - 10];
            Array.Copy(good, headerOnly, headerOnly.Length);
            Assert.That(Refused(headerOnly).Message, Does.Contain("truncated or not a model file"));
            var longer = new byte[good.Length + 8];
            Array.Copy(good, longer, good.Length);
            Assert.That(Refused(longer).Message, Does.Contain("after the last tensor"));
        }

        [Test]
        public void NaNWeightsAndWrongShapesAreRefused()
        {
            var good = Blstm();
            var nan = (byte[])good.Clone();
            var bits = BitConverter.GetBytes(float.NaN);
            Array.Copy(bits, 0, nan, good.Length - 4, 4); // the last fc_b value
            Assert.That(Refused(nan).Message, Does.Contain("fc_b").And.Contain("not finite"));

            var m = ModelFile.Parse(good, "x");
            var shape = m.ShapeOf("fc_w");
            var fewer = new double[(shape[0] - 1) * shape[1]];
            m.AddTensor("fc_w", new[] { shape[0] - 1, shape[1] }, fewer, false);
            Assert.That(Refused(m.ToBytes()).Message, Does.Contain("fc_w"));

            var wrongKind = ModelFile.Parse(good, "x");
            wrongKind.Set("kind", "svm");
            Assert.That(Refused(wrongKind.ToBytes()).Message, Does.Contain("'svm' model"));

            var wrongClasses = ModelFile.Parse(good, "x");
            wrongClasses.Set("classes", "IC/PSW,STAND");
            Assert.That(Refused(wrongClasses.ToBytes()).Message, Does.Contain("classes"));
        }

        [Test]
        public void AnUnusableModelFallsBackToCorWithAWarningAndNeverThrowsPerSample()
        {
            string dir = Path.Combine(Path.GetTempPath(), "headgait-fallback-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(dir);
            try
            {
                string models = TestData.ModelsFolder;
                File.Copy(Path.Combine(models, GaitModels.ThresholdFile), Path.Combine(dir, GaitModels.ThresholdFile));
                File.Copy(Path.Combine(models, GaitModels.CorrelationFile), Path.Combine(dir, GaitModels.CorrelationFile));
                var half = Blstm();
                Array.Resize(ref half, half.Length / 2);
                File.WriteAllBytes(Path.Combine(dir, GaitModels.BlstmFile), half);
                var loaded = GaitModels.Load(dir);
                Assert.That(loaded.Problems, Has.Some.Contains(GaitModels.BlstmFile).And.Some.Contains("truncated"));
                Assert.That(loaded.Problems, Has.Some.Contains(GaitModels.SvmFile).And.Some.Contains("not found"));
                var c = loaded.Create("blstm", out string warning);
                Assert.That(c.Name, Is.EqualTo("COR"));
                Assert.That(warning, Does.Contain("BLSTM").And.Contain("truncated"));
                var pipeline = new GaitPipeline(c);
                var rnd = new Synthetic.DeterministicRandom(5);
                for (int i = 0; i < 3000; i++) pipeline.Push(i * 0.01, double.NaN, rnd.NextGaussian(), i % 7 == 0 ? double.PositiveInfinity : 9.8);
                Assert.That(pipeline.Preprocessor.Skipped, Is.GreaterThan(0));
            }
            finally
            {
                Directory.Delete(dir, true);
            }
        }

        static List<GaitPrediction> Predictions(LearnedClassifier classifier, Recording recording)
            => ReplayEvaluator.Run(recording, classifier, keepTrace: true).Predictions;

        [TestCase("svm")]
        [TestCase("blstm")]
        public void AWindowTheWalkingGateRefusesIsStandingWhateverTheModelScores(string name)
        {
            var models = TestData.ShippedModels();
            var rec = TestData.Eval("start_stop");
            var gated = (LearnedClassifier)models.Create(name, out _);
            Assert.That(gated.Gate, Is.Not.Null, "headgait train writes the walking gate into the committed model file");

            var ungated = (LearnedClassifier)models.Create(name, out _);
            ungated.Gate = null;
            var refusing = (LearnedClassifier)models.Create(name, out _);
            refusing.Gate = WalkingGate.FromWeights(new double[] { 0, 0, 0, 0, 0, 0, 0, -1 });

            var open = ReplayEvaluator.Run(rec, ungated);
            var withGate = ReplayEvaluator.Run(rec, gated);
            Assert.That(Predictions(ungated, rec).FindAll(p => p.IsWalking).Count, Is.GreaterThan(300), "the model alone sees walking");
            Assert.That(Predictions(refusing, rec).TrueForAll(p => !p.IsWalking), Is.True, "a gate that refuses every window leaves only standing");
            // The committed gate only keeps out what is clearly not walking: the generated walking still shows.
            Assert.That(withGate.ClassifierMetrics.WalkingAsStanding, Is.LessThan(open.ClassifierMetrics.WalkingAsStanding + 0.05));
            Assert.That(withGate.ClassifierMetrics.StandingAsWalking, Is.LessThanOrEqualTo(open.ClassifierMetrics.StandingAsWalking));
        }

        [Test]
        public void TrainingWritesTheGateIntoTheModelFileWithoutTouchingItsNetwork()
        {
            string path = Path.Combine(Path.GetTempPath(), "headgait-gate-" + Guid.NewGuid().ToString("N") + ".bytes");
            try
            {
                File.WriteAllBytes(path, Blstm());
                var features = new double[new BlstmClassifier(ModelFile.Load(path)).Features.Width];
                for (int i = 0; i < features.Length; i++) features[i] = Math.Sin(0.37 * i);
                double[] Scores() => (double[])new BlstmClassifier(ModelFile.Load(path)).ScoreFeatures(features).Clone();
                var before = Scores();

                var weights = new double[WalkingGate.WeightCount];
                for (int i = 0; i < weights.Length; i++) weights[i] = 0.5 * i - 7;
                var gate = new WalkingGate(weights);
                GaitTraining.WriteGateAndStance(path, gate);
                var written = new BlstmClassifier(ModelFile.Load(path));
                Assert.That(written.Gate.Weights, Is.EqualTo(gate.Weights));
                Assert.That(Scores(), Is.EqualTo(before), "the network's tensors are unchanged");

                GaitTraining.WriteGateAndStance(path, null);
                Assert.That(new BlstmClassifier(ModelFile.Load(path)).Gate, Is.Null, "no standing to learn from: the stale gate goes");

                // The stance slope learned in C# joins the model's own onsets; a map with other onsets is refused by file name.
                var own = written.PhaseMap;
                var sloped = PhaseMap.FromStanceFraction(own.Onset(GaitPhase.InitialSwing), own.RightOffset, 0.11, 1.07);
                GaitTraining.WriteGateAndStance(path, gate, sloped);
                var withStance = new BlstmClassifier(ModelFile.Load(path));
                Assert.That(withStance.PhaseMap.StanceSlope, Is.EqualTo(0.11));
                Assert.That(withStance.Segments.Names(), Is.EqualTo(written.Segments.Names()));
                Assert.That(Scores(), Is.EqualTo(before));
                var other = PhaseMap.FromStanceFraction(own.Onset(GaitPhase.InitialSwing) + 0.02, own.RightOffset, 0.11, 1.07);
                var e = Assert.Throws<ModelFormatException>(() => GaitTraining.WriteGateAndStance(path, gate, other));
                Assert.That(e.Message, Does.Contain(Path.GetFileName(path)).And.Contain("other phase onsets"));
                // A cross-validation fold's map lends its slope; the model keeps its own onsets, which define its classes.
                withStance.AdoptStance(PhaseMap.FromStanceFraction(own.Onset(GaitPhase.InitialSwing) + 0.02, own.RightOffset, 0.07, 1.2));
                Assert.That(withStance.PhaseMap.StanceSlope, Is.EqualTo(0.07));
                Assert.That(withStance.PhaseMap.ReferenceStridePeriod, Is.EqualTo(1.2));
                Assert.That(withStance.PhaseMap.Onset(GaitPhase.InitialSwing), Is.EqualTo(own.Onset(GaitPhase.InitialSwing)));
            }
            finally
            {
                File.Delete(path);
            }
        }

        [TestCase("1,2,3", "14 comma-separated weights")]
        [TestCase("1,2,3,4,5,6,NaN", "weight 7")]
        [TestCase("1,2,x,4,5,6,7", "weight 3")]
        [TestCase("1,2,3,4,5,6,1e9", "weight 7")]
        public void ABrokenGateNamesTheFileAndTheProblem(string weights, string problem)
        {
            var m = ModelFile.Parse(Blstm(), "broken.bytes");
            m.Set(WalkingGate.ModelKey, weights);
            var e = Refused(m.ToBytes());
            Assert.That(e.Message, Does.StartWith("broken.bytes: ").And.Contain("walking gate").And.Contain(problem));
        }
    }
}
