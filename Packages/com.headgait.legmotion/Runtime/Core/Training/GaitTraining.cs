using System;
using System.Collections.Generic;
using HeadGait.Synthetic;

namespace HeadGait.Training
{
    /// <summary>The training steps `headgait train` and the cross-validation benchmark share, so both train the same way.</summary>
    public static class GaitTraining
    {
        /// <summary>Augmented copies of each labelled recording (see <see cref="RecordingAugmentation"/>) made per original.</summary>
        public const int DefaultAugmentedCopies = 2;

        /// <summary>Most augmented copies per original: each is a whole recording held in memory, so the count bounds the memory training takes.</summary>
        public const int MaxAugmentedCopies = 20;

        public const ulong DefaultSeed = 20261122;

        /// <summary>
        /// The recordings followed by <paramref name="copies"/> augmented copies of each labelled original (seeded by name;
        /// copies already in the list get none), drawn from <paramref name="settings"/> (the default ranges when null).
        /// </summary>
        public static List<Recording> WithAugmentation(IReadOnlyList<Recording> recordings, int copies, ulong seed = DefaultSeed, AugmentationSettings settings = null)
        {
            if (copies < 0 || copies > MaxAugmentedCopies) throw new ArgumentOutOfRangeException(nameof(copies), copies, $"augmented copies must be 0 to {MaxAugmentedCopies}");
            var list = new List<Recording>(recordings);
            foreach (var rec in recordings)
            {
                if (!rec.HasTruth || RecordingAugmentation.IsCopy(rec.Name)) continue;
                var random = new DeterministicRandom(seed ^ DeterministicRandom.SeedFrom(rec.Name));
                for (int k = 0; k < copies; k++) list.Add(RecordingAugmentation.Augment(rec, random, settings));
            }
            return list;
        }

        /// <summary>
        /// Copies of each original recording that every walking gate also learns from, swaying sideways and forwards as
        /// little as a real ear-worn sensor (see <see cref="CalmSway"/>): a gate that had not seen calm sway shut on calm
        /// walks and broke them apart. Leave-one-style-out on held-out clips made ear-like
        /// (<see cref="RecordingAugmentation.EarLike"/>): step recall THR 93.6 to 95.1 %, SVM 93.8 to 95.1 %, BLSTM 94.4 to
        /// 95.2 %; walking shown as standing THR 8.8 to 6.7 %; walking bouts shown per walk (avatar) SVM 2.02 to 1.91,
        /// BLSTM 1.61 to 1.48. The clips as recorded scored the same. COR's gate learns from them too since its contacts
        /// need a step's span of SMV and the rhythm keeps calm walks going: as recorded 23.5 to 23.4 %, walking shown as
        /// standing 1.7 to 1.2 %, standing 2.7 % either way (gestures 0.5 to 0.3 %); ear-like 27.7 to 26.3 %, bouts per
        /// walk (classifier) 1.46 to 1.25, but its standing shown as walking 2.9 to 4.4 % (gestures 0.9 to 1.8 %).
        /// </summary>
        public const int CalmGateCopies = 2;

        /// <summary>
        /// The calm copies' ranges: sideways and forward swing scaled by 0.2 to 0.6 (a real ear-worn sensor measured about
        /// half of the mocap-derived swing), time stretched by up to 1.6 instead of 1.3 (a calm walker is often a slow
        /// one: the actors rarely walk slower than 100 steps a minute); overall gain as for every copy. Stretching to 1.6,
        /// leave-one-style-out on held-out clips 40 % slower (<see cref="RecordingAugmentation.Slow"/>): walking shown as
        /// standing THR 15.0 to 10.1 %, SVM 11.4 to 9.8 %, BLSTM 6.0 to 4.5 %, misclassification 44.3 / 31.4 / 27.9 to
        /// 41.8 / 30.6 / 27.3 %; ear-like 0.2-0.7 point better; as recorded the same but standing shown as walking THR 1.7
        /// to 1.9 %, SVM 1.6 to 1.5 %, BLSTM 1.1 to 1.2 % (1.5: 42.5 / 30.9 / 27.5 %, THR 1.8 %).
        /// </summary>
        public static AugmentationSettings CalmSway => new AugmentationSettings { MinLateralScale = 0.2, MaxLateralScale = 0.6, MinForwardScale = 0.2, MaxForwardScale = 0.6, MaxStretch = 1.6 };

        /// <summary>Seeds the calm copies (with each recording's name), apart from the training copies' seed.</summary>
        const ulong CalmSeed = 7;

        /// <summary>Seeds the start-and-stop copies (with each recording's name).</summary>
        const ulong StartStopSeed = 11;

        /// <summary>
        /// One copy of each original walking recording as a walk that starts and stops (an augmented variant made into
        /// one by <see cref="RecordingAugmentation.StartingAndStopping"/>), for the learned classifiers' training windows:
        /// the real recordings are cut from continuous walking, so without them the networks never see a walk begin or end.
        /// </summary>
        public static List<Recording> StartStopCopies(IReadOnlyList<Recording> recordings)
        {
            var list = new List<Recording>();
            foreach (var rec in recordings)
            {
                if (!rec.HasTruth || RecordingAugmentation.IsCopy(rec.Name)) continue;
                var random = new DeterministicRandom(StartStopSeed ^ DeterministicRandom.SeedFrom(rec.Name));
                var copy = RecordingAugmentation.StartingAndStopping(RecordingAugmentation.Augment(rec, random), random);
                if (copy != null) list.Add(copy);
            }
            return list;
        }

        /// <summary>Seeds the wearer-like copies (with each recording's name).</summary>
        const ulong WearerSeed = 13;

        /// <summary>Copies of each walking recording made wearer-like (<see cref="WearerCopies"/>) for the learned classifiers' training windows.</summary>
        public const int DefaultWearerCopies = 2;

        /// <summary>
        /// <paramref name="copies"/> copies of each original walking recording as a slow, calm wearer of a real head-worn
        /// sensor might give it (<see cref="RecordingAugmentation.LikeWearer"/>), for the learned classifiers' training windows
        /// only: the actors walk faster and sway twice as much as people in a headset, and the networks otherwise take such
        /// people for standing.
        /// </summary>
        public static List<Recording> WearerCopies(IReadOnlyList<Recording> recordings, int copies = DefaultWearerCopies, WearerSettings settings = null)
        {
            var list = new List<Recording>();
            foreach (var rec in recordings)
            {
                if (!rec.HasTruth || RecordingAugmentation.IsCopy(rec.Name)) continue;
                var random = new DeterministicRandom(WearerSeed ^ DeterministicRandom.SeedFrom(rec.Name));
                for (int k = 0; k < copies; k++)
                {
                    var copy = RecordingAugmentation.LikeWearer(rec, random, settings);
                    if (copy == null) break;
                    list.Add(copy);
                }
            }
            return list;
        }

        /// <summary>
        /// Each classifier's walking gate: THR's and COR's let <see cref="WalkingGate.DetectorPass"/> of the walking windows
        /// through, the SVM's and BLSTM's <see cref="WalkingGate.LearnedPass"/> (they have a standing class of their own);
        /// all are also fitted on <see cref="CalmGateCopies"/> calm copies of each original, and all but COR's read their
        /// spreads levelled beyond <see cref="WindowLevel.ToleranceDegrees"/> (a head looking down at its legs; COR's,
        /// levelled, let more bows through: standing shown as walking 2.6 to 2.7 %). Every gate also passes a window that keeps a walking
        /// rhythm (<see cref="StepRhythm"/>), so a calm, slow walker is not refused for moving as little as a gesture. Without standing to
        /// learn from, THR's and COR's gates are open and the learned classifiers' null (the models run ungated).
        /// </summary>
        public static (WalkingGate Threshold, WalkingGate Correlation, WalkingGate Learned) TrainGates(IReadOnlyList<Recording> training, IReadOnlyList<Recording> real = null)
            => GatesFrom(GateWindows.Of(WithCalmCopies(training)), real == null ? null : GateWindows.Of(RealGateRecordings(real)));

        /// <summary>
        /// The gates from windows already read: <paramref name="labelled"/> (the labelled recordings with their calm copies)
        /// and <paramref name="real"/> (unlabelled real recordings, <see cref="RealGateRecordings"/>; null: none), so that
        /// cross-validation folds read each recording once.
        /// </summary>
        public static (WalkingGate Threshold, WalkingGate Correlation, WalkingGate Learned) GatesFrom(GateWindows labelled, GateWindows real = null)
        {
            var all = real == null ? labelled : GateWindows.Union(new[] { labelled, real });
            try
            {
                double standingPass = real == null ? 1 : RealStandingPass;
                var levelled = WalkingGate.FitEach(all.Levelled, new[] { WalkingGate.DetectorPass, WalkingGate.LearnedPass }, WindowLevel.ToleranceDegrees, standingPass);
                var cor = WalkingGate.FitEach(all.Plain, new[] { WalkingGate.DetectorPass }, null, standingPass)[0];
                return (levelled[0].WithStepRhythm(), cor.WithStepRhythm(), levelled[1].WithStepRhythm());
            }
            catch (System.InvalidOperationException)
            {
                return (WalkingGate.Open, WalkingGate.Open, null);
            }
        }

        /// <summary>
        /// With real recordings to learn from, at most this share of all standing windows (the labelled recordings' and the
        /// real still activities') may pass a gate: the real walkers are calmer than the actors, and passing
        /// <see cref="WalkingGate.DetectorPass"/> of their walking as well let the real standing and picking up through.
        /// </summary>
        public const double RealStandingPass = 0.03;

        /// <summary>The gates' training windows, read levelled (THR's and the learned classifiers' gates) and as they are (COR's).</summary>
        public sealed class GateWindows
        {
            public WalkingGate.TrainingWindows Levelled, Plain;

            public static GateWindows Of(IEnumerable<Recording> recordings)
            {
                var list = new List<Recording>(recordings);
                return new GateWindows
                {
                    Levelled = WalkingGate.TrainingWindows.Of(list, WindowLevel.ToleranceDegrees),
                    Plain = WalkingGate.TrainingWindows.Of(list),
                };
            }

            public static GateWindows Union(IEnumerable<GateWindows> parts)
            {
                var list = new List<GateWindows>(parts);
                return new GateWindows
                {
                    Levelled = WalkingGate.TrainingWindows.Union(list.ConvertAll(p => p.Levelled)),
                    Plain = WalkingGate.TrainingWindows.Union(list.ConvertAll(p => p.Plain)),
                };
            }
        }

        /// <summary>
        /// Unlabelled real recordings with an activity (<see cref="RealActivity"/>) as the walking gates can learn from them:
        /// a walking file is labelled walking where the signal shows a walking rhythm (<see cref="RhythmReference"/>) and
        /// left unlabelled elsewhere (turns, pauses: neither class is sure); standing, sitting with head movement and
        /// picking things up are standing throughout; other activities (timed up-and-go) are left out. Only the walking /
        /// standing distinction is labelled: the phases are placeholders, not to be trained on as phases.
        /// </summary>
        public static List<Recording> RealGateRecordings(IEnumerable<Recording> real)
        {
            var list = new List<Recording>();
            foreach (var rec in real)
            {
                string activity = RealActivity.Of(rec);
                bool still = RealActivity.IsStill(activity);
                if (!still && activity != RealActivity.Walking) continue;
                var reference = still ? null : RhythmReference.Of(rec);
                var samples = new List<RecordedSample>(rec.Samples.Count);
                foreach (var s in rec.Samples)
                {
                    if (still) samples.Add(new RecordedSample(s.Imu, GaitPhase.Standing, GaitPhase.Standing, s.Line));
                    else if (reference.IsWalking(s.Imu.Time)) samples.Add(new RecordedSample(s.Imu, GaitPhase.MidStance, GaitPhase.MidSwing, s.Line));
                    else samples.Add(new RecordedSample(s.Imu, s.Line));
                }
                list.Add(new Recording(rec.Name, samples));
            }
            return list;
        }

        /// <summary>
        /// The still real recordings (standing, sitting with head movement, picking things up; <see cref="RealActivity.IsStill"/>)
        /// labelled standing throughout, for the learned classifiers' standing class: nobody walks in them, whatever the
        /// head does. Walking and other activities are left out (their phases are unknown).
        /// </summary>
        public static List<Recording> RealStillRecordings(IEnumerable<Recording> real)
        {
            var list = new List<Recording>();
            foreach (var rec in real)
            {
                if (!RealActivity.IsStill(RealActivity.Of(rec))) continue;
                var samples = new List<RecordedSample>(rec.Samples.Count);
                foreach (var s in rec.Samples) samples.Add(new RecordedSample(s.Imu, GaitPhase.Standing, GaitPhase.Standing, s.Line));
                list.Add(new Recording(rec.Name, samples));
            }
            return list;
        }

        /// <summary>The recordings followed by <see cref="CalmGateCopies"/> calm copies of each labelled original (not of augmented copies).</summary>
        public static List<Recording> WithCalmCopies(IReadOnlyList<Recording> training)
            => WithAugmentation(training, CalmGateCopies, CalmSeed, CalmSway);

        /// <summary>
        /// Writes what C# learns for the learned classifiers into a trained SVM or BLSTM model file: the walking gate (or
        /// removes a stale one when <paramref name="gate"/> is null) and the phase map's stance slope, when given (its onsets
        /// must be the model's own, which define its classes). The network's tensors are left as they are.
        /// </summary>
        public static void WriteGateAndStance(string modelPath, WalkingGate gate, PhaseMap stance = null)
        {
            var model = ModelFile.Load(modelPath);
            if (gate == null) model.Values.Remove(WalkingGate.ModelKey);
            else model.Set(WalkingGate.ModelKey, gate.Serialize());
            if (stance != null)
            {
                PhaseMap own;
                try
                {
                    own = PhaseMap.Parse(model.Need("phase_map"));
                }
                catch (FormatException e)
                {
                    throw new ModelFormatException(model.Source, e.Message);
                }
                try
                {
                    model.Set("phase_map", own.WithStanceOf(stance).Serialize());
                }
                catch (ArgumentException e)
                {
                    throw new ModelFormatException(model.Source, $"was trained with other phase onsets; retrain it ({e.Message})");
                }
            }
            model.Save(modelPath);
        }

        public static ThresholdSettings TrainThreshold(IReadOnlyList<Recording> training, PhaseMap map, WalkingGate gate)
        {
            var s = ThresholdClassifier.Calibrate(training, map, gate);
            s.Clock.Lead = ContactTiming(() => new ThresholdClassifier(s), training);
            return s;
        }

        public static CorrelationTemplate TrainCorrelation(IReadOnlyList<Recording> training, PhaseMap map, WalkingGate gate, CorrelationSettings settings = null)
        {
            var t = CorrelationClassifier.Calibrate(CorrelationTemplate.Train(training, map, gate), training, settings);
            return t.With(clockLead: ContactTiming(() => new CorrelationClassifier(t, settings), training));
        }

        /// <summary>
        /// Median time by which a step-clock classifier reports foot contacts late on the training recordings (s, clamped
        /// to 0.2): its clock's lead. Contacts are only detected after they happen, so between them the clock runs late.
        /// The median, not the mean: the few steps matched far off at the starts of walks moved the mean by up to 12 ms
        /// between otherwise equal COR settings, and 10 ms of clock lead is worth several points of misclassification.
        /// </summary>
        internal static double ContactTiming(System.Func<IGaitClassifier> make, IReadOnlyList<Recording> training)
        {
            var parts = new List<GaitMetrics>();
            foreach (var rec in training) parts.Add(ReplayEvaluator.Run(rec, make()).ClassifierMetrics);
            double ms = GaitMetrics.Pool(parts).StepTimingMedianMs;
            return double.IsNaN(ms) ? 0 : System.Math.Max(-0.2, System.Math.Min(0.2, ms / 1000));
        }
    }
}
