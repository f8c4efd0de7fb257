using System;
using System.Collections.Generic;

namespace HeadGait
{
    /// <summary>
    /// Accuracy and timing of predicted per-foot phases against ground truth. Tallies are kept raw, so the
    /// metrics of several recordings pool exactly (<see cref="Pool"/>) instead of averaging averages.
    /// </summary>
    public sealed class GaitMetrics
    {
        /// <summary>Largest distance between a true and a predicted foot contact that still counts as the same step (s).</summary>
        public const double StepMatchSeconds = 0.25;

        long samples, wrongLeft, wrongRight, wrongBeyondAdjacent, activityWrong;
        readonly long[] errorHistogram = new long[GaitPhases.WalkingPhaseCount / 2 + 1];
        long walkingSamples, walkingShownStanding, standingSamples, standingShownWalking;
        int trueBouts, shownBouts;
        readonly List<double> onsetDelaysMs = new List<double>();
        readonly List<double> icOnsetDelaysMs = new List<double>();
        int trueOnsets;
        int trueSteps, predictedSteps, matchedSteps, matchedSameFoot;
        readonly List<double> stepTimingMs = new List<double>();
        readonly List<double> startDelays = new List<double>();
        readonly List<double> stopDelays = new List<double>();

        /// <summary>Labelled (sample, foot) pairs compared.</summary>
        public long Comparisons => 2 * samples;

        /// <summary>Share of (sample, foot) pairs whose predicted phase differs from the truth (Standing included).</summary>
        public double MisclassificationRate => Ratio(wrongLeft + wrongRight, Comparisons);

        /// <summary>The same, counting a prediction one phase off (cyclic neighbour) as correct.</summary>
        public double MisclassificationBeyondAdjacent => Ratio(wrongBeyondAdjacent, Comparisons);

        /// <summary>Share of samples whose walking/standing call is wrong.</summary>
        public double ActivityErrorRate => Ratio(activityWrong, samples);

        /// <summary>Share of truly walking samples predicted (or shown) as standing.</summary>
        public double WalkingAsStanding => Ratio(walkingShownStanding, walkingSamples);

        /// <summary>Share of truly standing samples predicted (or shown) as walking.</summary>
        public double StandingAsWalking => Ratio(standingShownWalking, standingSamples);

        /// <summary>
        /// Walking bouts shown per true walking bout: each run of samples predicted (or shown) as walking is one bout.
        /// 1 when every walk shows as one; a walk that breaks apart, or gesturing shown as walking, adds bouts.
        /// </summary>
        public double BoutsPerWalk => Ratio(shownBouts, trueBouts);

        public int TrueWalkingBouts => trueBouts;
        public int ShownWalkingBouts => shownBouts;

        public long WalkingSamples => walkingSamples;
        public long StandingSamples => standingSamples;

        /// <summary>Errors in phase steps (<see cref="GaitPhases.Distance"/>): cyclic 0..4, Standing vs walking = 4.</summary>
        public double Mae
        {
            get
            {
                double s = 0;
                for (int d = 0; d < errorHistogram.Length; d++) s += d * errorHistogram[d];
                return Ratio(s, Comparisons);
            }
        }

        public double Mse
        {
            get
            {
                double s = 0;
                for (int d = 0; d < errorHistogram.Length; d++) s += (double)d * d * errorHistogram[d];
                return Ratio(s, Comparisons);
            }
        }

        public double Rmse => Math.Sqrt(Mse);

        /// <summary>CEP25/50/75/95: the absolute phase-step error that 25/50/75/95 % of comparisons stay within.</summary>
        public double Cep25 => HistogramPercentile(0.25);
        public double Cep50 => HistogramPercentile(0.50);
        public double Cep75 => HistogramPercentile(0.75);
        public double Cep95 => HistogramPercentile(0.95);

        /// <summary>
        /// Mean and median delay (ms) of predicted phase onsets after the true ones: each true walking-phase
        /// onset is matched to the nearest predicted onset of the same foot and phase within 0.3 s.
        /// Negative: the prediction came early.
        /// </summary>
        public double MeanDelayMs => Mean(onsetDelaysMs);
        public double MedianDelayMs => Median(onsetDelaysMs);

        /// <summary>The same, for initial-contact onsets only.</summary>
        public double MeanInitialContactDelayMs => Mean(icOnsetDelaysMs);

        public int TrueOnsets => trueOnsets;
        public int MatchedOnsets => onsetDelaysMs.Count;

        /// <summary>
        /// Steps: a foot's contact (its phase entering stance from swing). True contacts are matched one to one
        /// with predicted contacts of either foot within <see cref="StepMatchSeconds"/>, nearest first.
        /// </summary>
        public int TrueSteps => trueSteps;
        public int PredictedSteps => predictedSteps;
        public int MatchedSteps => matchedSteps;
        public double StepRecall => Ratio(matchedSteps, trueSteps);
        public double StepPrecision => Ratio(matchedSteps, predictedSteps);

        /// <summary>Share of matched steps whose predicted contact is on the same foot as the true one.</summary>
        public double StepRightFoot => Ratio(matchedSameFoot, matchedSteps);

        /// <summary>Predicted minus true contact time of matched steps (ms): mean, median and standard deviation.</summary>
        public double StepTimingMeanMs => Mean(stepTimingMs);
        public double StepTimingMedianMs => Median(stepTimingMs);
        public double StepTimingSdMs
        {
            get
            {
                if (stepTimingMs.Count < 2) return double.NaN;
                double m = Mean(stepTimingMs), s = 0;
                foreach (var v in stepTimingMs) s += (v - m) * (v - m);
                return Math.Sqrt(s / (stepTimingMs.Count - 1));
            }
        }

        /// <summary>
        /// Walks that start inside a recording (standing labelled before them): seconds from the walk's first labelled
        /// sample to the first sample of the predicted walking that overlaps it (negative: shown early). A walk cut by the
        /// recording's start, or never shown, counts for neither this nor <see cref="MeanStopDelaySeconds"/>.
        /// </summary>
        public double MeanStartDelaySeconds => Mean(startDelays);
        public int Starts => startDelays.Count;

        /// <summary>
        /// Walks that end inside a recording: seconds from the first standing sample after the walk to the first standing
        /// sample after the predicted walking that overlaps its end (0 when it stops with the labels).
        /// </summary>
        public double MeanStopDelaySeconds => Mean(stopDelays);
        public int Stops => stopDelays.Count;

        /// <summary>Compares aligned sequences of one recording.</summary>
        public static GaitMetrics Compute(IReadOnlyList<double> times,
            IReadOnlyList<GaitPhase> trueLeft, IReadOnlyList<GaitPhase> trueRight,
            IReadOnlyList<GaitPhase> predLeft, IReadOnlyList<GaitPhase> predRight)
        {
            var m = new GaitMetrics();
            m.Add(times, trueLeft, trueRight, predLeft, predRight);
            return m;
        }

        /// <summary>Adds one recording's aligned sequences to the tallies.</summary>
        public void Add(IReadOnlyList<double> times,
            IReadOnlyList<GaitPhase> trueLeft, IReadOnlyList<GaitPhase> trueRight,
            IReadOnlyList<GaitPhase> predLeft, IReadOnlyList<GaitPhase> predRight)
        {
            int n = times.Count;
            if (trueLeft.Count != n || trueRight.Count != n || predLeft.Count != n || predRight.Count != n)
                throw new ArgumentException("All sequences must have the same length.");
            for (int i = 0; i < n; i++)
            {
                int dl = GaitPhases.Distance(trueLeft[i], predLeft[i]);
                int dr = GaitPhases.Distance(trueRight[i], predRight[i]);
                if (dl != 0) wrongLeft++;
                if (dr != 0) wrongRight++;
                if (dl > 1) wrongBeyondAdjacent++;
                if (dr > 1) wrongBeyondAdjacent++;
                errorHistogram[dl]++;
                errorHistogram[dr]++;
                bool trueStanding = trueLeft[i] == GaitPhase.Standing;
                bool predStanding = predLeft[i] == GaitPhase.Standing;
                if (trueStanding != predStanding) activityWrong++;
                if (trueStanding)
                {
                    standingSamples++;
                    if (!predStanding) standingShownWalking++;
                }
                else
                {
                    walkingSamples++;
                    if (predStanding) walkingShownStanding++;
                }
            }
            samples += n;
            trueBouts += Bouts(trueLeft);
            shownBouts += Bouts(predLeft);
            AddOnsetDelays(times, trueLeft, trueRight, predLeft, predRight);
            AddSteps(times, trueLeft, trueRight, predLeft, predRight);
            AddStartsAndStops(times, trueLeft, predLeft);
        }

        /// <summary>The tallies of several recordings together.</summary>
        public static GaitMetrics Pool(IEnumerable<GaitMetrics> parts)
        {
            var m = new GaitMetrics();
            foreach (var p in parts)
            {
                if (p == null) continue;
                m.samples += p.samples;
                m.wrongLeft += p.wrongLeft;
                m.wrongRight += p.wrongRight;
                m.wrongBeyondAdjacent += p.wrongBeyondAdjacent;
                m.activityWrong += p.activityWrong;
                for (int d = 0; d < m.errorHistogram.Length; d++) m.errorHistogram[d] += p.errorHistogram[d];
                m.walkingSamples += p.walkingSamples;
                m.walkingShownStanding += p.walkingShownStanding;
                m.standingSamples += p.standingSamples;
                m.standingShownWalking += p.standingShownWalking;
                m.trueBouts += p.trueBouts;
                m.shownBouts += p.shownBouts;
                m.onsetDelaysMs.AddRange(p.onsetDelaysMs);
                m.icOnsetDelaysMs.AddRange(p.icOnsetDelaysMs);
                m.trueOnsets += p.trueOnsets;
                m.trueSteps += p.trueSteps;
                m.predictedSteps += p.predictedSteps;
                m.matchedSteps += p.matchedSteps;
                m.matchedSameFoot += p.matchedSameFoot;
                m.stepTimingMs.AddRange(p.stepTimingMs);
                m.startDelays.AddRange(p.startDelays);
                m.stopDelays.AddRange(p.stopDelays);
            }
            return m;
        }

        /// <summary>Runs of walking (any phase but standing) in one foot's sequence.</summary>
        static int Bouts(IReadOnlyList<GaitPhase> phases)
        {
            int bouts = 0;
            bool walking = false;
            foreach (var p in phases)
            {
                bool now = p != GaitPhase.Standing;
                if (now && !walking) bouts++;
                walking = now;
            }
            return bouts;
        }

        /// <summary>Start and stop delays of the walks inside the recording (standing is both feet's, so one foot tells).</summary>
        void AddStartsAndStops(IReadOnlyList<double> times, IReadOnlyList<GaitPhase> truth, IReadOnlyList<GaitPhase> predicted)
        {
            int n = times.Count, i = 0;
            while (i < n)
            {
                if (truth[i] == GaitPhase.Standing)
                {
                    i++;
                    continue;
                }
                int from = i;
                while (i < n && truth[i] != GaitPhase.Standing) i++;
                int first = from;
                while (first < i && predicted[first] == GaitPhase.Standing) first++;
                if (first == i) continue; // never shown: recall and walking shown as standing count it
                if (from > 0)
                {
                    // Shown from the walk's first sample: the predicted walking may have begun before it.
                    if (first == from)
                        while (first > 0 && predicted[first - 1] != GaitPhase.Standing) first--;
                    startDelays.Add(times[first] - times[from]);
                }
                if (i < n)
                {
                    int end = i;
                    while (end > from && predicted[end - 1] == GaitPhase.Standing) end--;
                    if (end == i)
                        while (end < n && predicted[end] != GaitPhase.Standing) end++;
                    // A prediction still walking at the recording's end stops no earlier than its last sample.
                    stopDelays.Add(times[Math.Min(end, n - 1)] - times[i]);
                }
            }
        }

        void AddOnsetDelays(IReadOnlyList<double> times,
            IReadOnlyList<GaitPhase> trueLeft, IReadOnlyList<GaitPhase> trueRight,
            IReadOnlyList<GaitPhase> predLeft, IReadOnlyList<GaitPhase> predRight)
        {
            // 0.3 s: less than half a stride, so a phase cannot match its neighbour stride's copy.
            const double maxMatchSeconds = 0.3;
            var truth = PhaseEvents.Onsets(times, trueLeft, trueRight);
            var pred = PhaseEvents.Onsets(times, predLeft, predRight);
            foreach (var t in truth)
            {
                if (t.Phase == GaitPhase.Standing) continue;
                trueOnsets++;
                double best = double.PositiveInfinity;
                foreach (var p in pred)
                {
                    if (p.Foot != t.Foot || p.Phase != t.Phase) continue;
                    double d = p.Time - t.Time;
                    if (Math.Abs(d) <= maxMatchSeconds && Math.Abs(d) < Math.Abs(best)) best = d;
                    if (p.Time > t.Time + maxMatchSeconds) break;
                }
                if (double.IsInfinity(best)) continue;
                onsetDelaysMs.Add(best * 1000.0);
                if (t.Phase == GaitPhase.InitialContact) icOnsetDelaysMs.Add(best * 1000.0);
            }
        }

        void AddSteps(IReadOnlyList<double> times,
            IReadOnlyList<GaitPhase> trueLeft, IReadOnlyList<GaitPhase> trueRight,
            IReadOnlyList<GaitPhase> predLeft, IReadOnlyList<GaitPhase> predRight)
        {
            var truth = PhaseEvents.Contacts(times, trueLeft, trueRight);
            var pred = PhaseEvents.Contacts(times, predLeft, predRight);
            trueSteps += truth.Count;
            predictedSteps += pred.Count;
            var used = new bool[pred.Count];
            int first = 0;
            foreach (var t in truth)
            {
                while (first < pred.Count && pred[first].Time < t.Time - StepMatchSeconds) first++;
                int best = -1;
                for (int j = first; j < pred.Count && pred[j].Time <= t.Time + StepMatchSeconds; j++)
                {
                    if (used[j]) continue;
                    if (best < 0 || Math.Abs(pred[j].Time - t.Time) < Math.Abs(pred[best].Time - t.Time)) best = j;
                }
                if (best < 0) continue;
                used[best] = true;
                matchedSteps++;
                if (pred[best].Foot == t.Foot) matchedSameFoot++;
                stepTimingMs.Add((pred[best].Time - t.Time) * 1000.0);
            }
        }

        double HistogramPercentile(double q)
        {
            long total = Comparisons;
            if (total == 0) return double.NaN;
            long rank = Math.Max(1, (long)Math.Ceiling(q * total));
            long seen = 0;
            for (int d = 0; d < errorHistogram.Length; d++)
            {
                seen += errorHistogram[d];
                if (seen >= rank) return d;
            }
            return errorHistogram.Length - 1;
        }

        static double Ratio(double a, double b) => b > 0 ? a / b : double.NaN;

        static double Mean(List<double> v)
        {
            if (v.Count == 0) return double.NaN;
            double s = 0;
            foreach (var x in v) s += x;
            return s / v.Count;
        }

        /// <summary>The upper median (the middle value, the higher of two); NaN when there are none. Leaves the list as it is.</summary>
        public static double Median(List<double> v)
        {
            if (v.Count == 0) return double.NaN;
            var sorted = new List<double>(v);
            sorted.Sort();
            return sorted[sorted.Count / 2];
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
