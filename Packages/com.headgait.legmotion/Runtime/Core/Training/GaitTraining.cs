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

        /// <summary>The recordings followed by <paramref name="copies"/> augmented copies of each labelled one (seeded by name).</summary>
        public static List<Recording> WithAugmentation(IReadOnlyList<Recording> recordings, int copies, ulong seed = DefaultSeed)
        {
            var list = new List<Recording>(recordings);
            foreach (var rec in recordings)
            {
                if (!rec.HasTruth) continue;
                var random = new DeterministicRandom(seed ^ DeterministicRandom.SeedFrom(rec.Name));
                for (int k = 0; k < copies; k++) list.Add(RecordingAugmentation.Augment(rec, random));
            }
            return list;
        }

        /// <summary>The walking gate THR and COR share; open when the recordings hold no standing to learn from.</summary>
        public static WalkingGate TrainGate(IReadOnlyList<Recording> training) => TrainGates(training).Detectors;

        /// <summary>
        /// From one fit, THR's and COR's walking gate (<see cref="WalkingGate.DetectorPass"/>; open when the recordings hold
        /// no standing to learn from) and the SVM's and BLSTM's (<see cref="WalkingGate.LearnedPass"/>; null then: the models
        /// run ungated).
        /// </summary>
        public static (WalkingGate Detectors, WalkingGate Learned) TrainGates(IReadOnlyList<Recording> training)
        {
            try
            {
                var gates = WalkingGate.TrainEach(training, new[] { WalkingGate.DetectorPass, WalkingGate.LearnedPass });
                return (gates[0], gates[1]);
            }
            catch (System.InvalidOperationException)
            {
                return (WalkingGate.Open, null);
            }
        }

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
        /// Mean time by which a step-clock classifier reports foot contacts late on the training recordings (s, clamped to
        /// 0.2): its clock's lead. Contacts are only detected after they happen, so between them the clock runs late.
        /// </summary>
        static double ContactTiming(System.Func<IGaitClassifier> make, IReadOnlyList<Recording> training)
        {
            var parts = new List<GaitMetrics>();
            foreach (var rec in training) parts.Add(ReplayEvaluator.Run(rec, make()).ClassifierMetrics);
            double ms = GaitMetrics.Pool(parts).StepTimingMeanMs;
            return double.IsNaN(ms) ? 0 : System.Math.Max(-0.2, System.Math.Min(0.2, ms / 1000));
        }
    }
}
