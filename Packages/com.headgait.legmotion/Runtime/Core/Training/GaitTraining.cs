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

        public const ulong DefaultSeed = 20261122;

        /// <summary>
        /// The recordings followed by <paramref name="copies"/> augmented copies of each labelled original (seeded by name;
        /// copies already in the list get none), drawn from <paramref name="settings"/> (the default ranges when null).
        /// </summary>
        public static List<Recording> WithAugmentation(IReadOnlyList<Recording> recordings, int copies, ulong seed = DefaultSeed, AugmentationSettings settings = null)
        {
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

        /// <summary>
        /// Each classifier's walking gate: THR's and COR's let <see cref="WalkingGate.DetectorPass"/> of the walking windows
        /// through, the SVM's and BLSTM's <see cref="WalkingGate.LearnedPass"/> (they have a standing class of their own);
        /// all are also fitted on <see cref="CalmGateCopies"/> calm copies of each original, and all but COR's read their
        /// spreads levelled beyond <see cref="WindowLevel.ToleranceDegrees"/> (a head looking down at its legs; COR's,
        /// levelled, let more bows through: standing shown as walking 2.6 to 2.7 %). Every gate also passes a window that keeps a walking
        /// rhythm (<see cref="StepRhythm"/>), so a calm, slow walker is not refused for moving as little as a gesture. Without standing to
        /// learn from, THR's and COR's gates are open and the learned classifiers' null (the models run ungated).
        /// </summary>
        public static (WalkingGate Threshold, WalkingGate Correlation, WalkingGate Learned) TrainGates(IReadOnlyList<Recording> training)
        {
            try
            {
                var withCalm = WithCalmCopies(training);
                var calm = WalkingGate.TrainEach(withCalm, new[] { WalkingGate.DetectorPass, WalkingGate.LearnedPass }, WindowLevel.ToleranceDegrees);
                var cor = WalkingGate.Train(withCalm, WalkingGate.DetectorPass);
                return (calm[0].WithStepRhythm(), cor.WithStepRhythm(), calm[1].WithStepRhythm());
            }
            catch (System.InvalidOperationException)
            {
                return (WalkingGate.Open, WalkingGate.Open, null);
            }
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
