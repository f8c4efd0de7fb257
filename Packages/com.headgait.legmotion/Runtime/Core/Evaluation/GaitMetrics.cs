using System;
using System.Collections.Generic;

namespace HeadGait
{
    /// <summary>Accuracy and timing of predicted per-foot phases against ground truth.</summary>
    public sealed class GaitMetrics
    {
        /// <summary>Labelled (sample, foot) pairs compared.</summary>
        public int Comparisons { get; private set; }

        /// <summary>Share of (sample, foot) pairs whose predicted phase differs from the truth (Standing included).</summary>
        public double MisclassificationRate { get; private set; }

        public double MisclassificationLeft { get; private set; }
        public double MisclassificationRight { get; private set; }

        /// <summary>Share of samples whose walking/standing call is wrong.</summary>
        public double ActivityErrorRate { get; private set; }

        /// <summary>Errors in phase steps (<see cref="GaitPhases.Distance"/>): cyclic 0..4, Standing vs walking = 4.</summary>
        public double Mae { get; private set; }
        public double Mse { get; private set; }
        public double Rmse { get; private set; }

        /// <summary>CEP25/50/75/95: the absolute phase-step error that 25/50/75/95 % of comparisons stay within.</summary>
        public double Cep25 { get; private set; }
        public double Cep50 { get; private set; }
        public double Cep75 { get; private set; }
        public double Cep95 { get; private set; }

        /// <summary>
        /// Mean and median delay (ms) of predicted phase onsets after the true ones: each true walking-phase
        /// onset is matched to the nearest predicted onset of the same foot and phase within the window.
        /// Negative: the prediction came early.
        /// </summary>
        public double MeanDelayMs { get; private set; }
        public double MedianDelayMs { get; private set; }

        /// <summary>The same, for initial contacts only.</summary>
        public double MeanInitialContactDelayMs { get; private set; }

        public int TrueOnsets { get; private set; }
        public int MatchedOnsets { get; private set; }

        /// <summary>
        /// Compares aligned sequences. <paramref name="maxMatchSeconds"/> bounds the delay matching window
        /// (0.3 s: less than half a stride, so a phase cannot match its neighbour stride's copy).
        /// </summary>
        public static GaitMetrics Compute(IReadOnlyList<double> times,
            IReadOnlyList<GaitPhase> trueLeft, IReadOnlyList<GaitPhase> trueRight,
            IReadOnlyList<GaitPhase> predLeft, IReadOnlyList<GaitPhase> predRight,
            double maxMatchSeconds = 0.3)
        {
            int n = times.Count;
            if (trueLeft.Count != n || trueRight.Count != n || predLeft.Count != n || predRight.Count != n)
                throw new ArgumentException("All sequences must have the same length.");
            var m = new GaitMetrics();
            var errors = new List<double>(2 * n);
            int wrongL = 0, wrongR = 0, activityWrong = 0;
            double sum = 0, sumSq = 0;
            for (int i = 0; i < n; i++)
            {
                int dl = GaitPhases.Distance(trueLeft[i], predLeft[i]);
                int dr = GaitPhases.Distance(trueRight[i], predRight[i]);
                if (dl != 0) wrongL++;
                if (dr != 0) wrongR++;
                if ((trueLeft[i] == GaitPhase.Standing) != (predLeft[i] == GaitPhase.Standing)) activityWrong++;
                errors.Add(dl);
                errors.Add(dr);
                sum += dl + dr;
                sumSq += dl * dl + dr * dr;
            }
            m.Comparisons = 2 * n;
            if (n > 0)
            {
                m.MisclassificationLeft = (double)wrongL / n;
                m.MisclassificationRight = (double)wrongR / n;
                m.MisclassificationRate = (double)(wrongL + wrongR) / (2 * n);
                m.ActivityErrorRate = (double)activityWrong / n;
                m.Mae = sum / (2 * n);
                m.Mse = sumSq / (2 * n);
                m.Rmse = Math.Sqrt(m.Mse);
                errors.Sort();
                m.Cep25 = Percentile(errors, 0.25);
                m.Cep50 = Percentile(errors, 0.50);
                m.Cep75 = Percentile(errors, 0.75);
                m.Cep95 = Percentile(errors, 0.95);
            }

            var truth = PhaseEvents.Onsets(times, trueLeft, trueRight);
            var pred = PhaseEvents.Onsets(times, predLeft, predRight);
            var delays = new List<double>();
            double icSum = 0;
            int icCount = 0, total = 0;
            foreach (var t in truth)
            {
                if (t.Phase == GaitPhase.Standing) continue;
                total++;
                double best = double.PositiveInfinity;
                foreach (var p in pred)
                {
                    if (p.Foot != t.Foot || p.Phase != t.Phase) continue;
                    double d = p.Time - t.Time;
                    if (Math.Abs(d) <= maxMatchSeconds && Math.Abs(d) < Math.Abs(best)) best = d;
                    if (p.Time > t.Time + maxMatchSeconds) break;
                }
                if (double.IsInfinity(best)) continue;
                delays.Add(best * 1000.0);
                if (t.Phase == GaitPhase.InitialContact)
                {
                    icSum += best * 1000.0;
                    icCount++;
                }
            }
            m.TrueOnsets = total;
            m.MatchedOnsets = delays.Count;
            if (delays.Count > 0)
            {
                double ds = 0;
                foreach (var d in delays) ds += d;
                m.MeanDelayMs = ds / delays.Count;
                delays.Sort();
                m.MedianDelayMs = delays[delays.Count / 2];
            }
            else
            {
                m.MeanDelayMs = double.NaN;
                m.MedianDelayMs = double.NaN;
            }
            m.MeanInitialContactDelayMs = icCount > 0 ? icSum / icCount : double.NaN;
            return m;
        }

        /// <summary>Nearest-rank percentile of sorted values (NaN when there are none).</summary>
        public static double Percentile(IReadOnlyList<double> sorted, double q)
        {
            if (sorted.Count == 0) return double.NaN;
            int rank = (int)Math.Ceiling(q * sorted.Count);
            if (rank < 1) rank = 1;
            if (rank > sorted.Count) rank = sorted.Count;
            return sorted[rank - 1];
        }
    }
}
