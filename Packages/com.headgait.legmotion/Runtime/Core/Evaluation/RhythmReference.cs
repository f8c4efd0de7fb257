using System;
using System.Collections.Generic;

namespace HeadGait
{
    /// <summary>
    /// Where an unlabelled recording shows walking, and at what step rate, read from the signal itself (looking ahead and
    /// back, as no live classifier can): the measuring stick for real recordings that have an activity but no phase
    /// labels. Every <see cref="Hop"/> the 4 s around a moment (SMV and lateral averaged over 0.2 s) are searched for a step period of 0.3-1.1 s; the moment is
    /// walking when SMV repeats at that period and at twice it (<see cref="MinBounce"/>), the lateral acceleration swings
    /// to the other side one step later and back one stride later (<see cref="MaxSway"/>, <see cref="MinStride"/>: a step
    /// goes to one foot, the next to the other) and the head moves at all (<see cref="MinSpread"/>). Runs of such moments
    /// (gaps under 1 s filled, and gaps under 3 s through which the head keeps moving as in the walk, such as
    /// the steps of a turn; runs under 2 s dropped) are walking bouts; each bout's edges are moved to where the head's
    /// movement rises to half the bout's level (the first step's rise) and falls below it (the last step). The step
    /// period is the lag where SMV repeats best while the lateral swings back most (SMV alone often repeats best a stride later).
    /// Steps taken while turning count as walking where they keep the rhythm; turning on the spot or shuffling without a
    /// rhythm does not. This is a definition, not ground truth: it is checked on generated walks of known cadence (tests)
    /// and on the real files' activities (walking files mostly walking, standing, sitting and picking up nearly never).
    /// </summary>
    public sealed class RhythmReference
    {
        /// <summary>Analysis rate (Hz) of the resampled SMV and lateral channels.</summary>
        public const double Rate = 50;

        /// <summary>Spacing of the moments judged (s).</summary>
        public const double Hop = 0.2;

        /// <summary>Half the span judged around each moment (s).</summary>
        public const double HalfSpan = 2.0;

        /// <summary>Step periods searched (s).</summary>
        public const double ShortestStep = 0.3, LongestStep = 1.1;

        /// <summary>Least SMV autocorrelation one step and one stride apart; most lateral one step apart, least one stride apart.</summary>
        public const double MinBounce = 0.25, MaxSway = -0.1, MinStride = 0.1;

        /// <summary>Least spread of SMV over the span (m/s^2): a still head has no steps, whatever its noise repeats.</summary>
        public const double MinSpread = 0.2;

        /// <summary>Gaps shorter than this inside walking are walking (s); bouts shorter than <see cref="ShortestBout"/> are dropped.</summary>
        public const double LongestGap = 1.0, ShortestBout = 2.0;

        /// <summary>Span of the moving average the rhythm is judged on (s).</summary>
        public const double Smoothing = 0.2;

        /// <summary>Gaps up to this long (s) are also walking when the head keeps moving at the bouts' edge level throughout (steps in a turn).</summary>
        public const double LongestMovingGap = 3.0;

        /// <summary>Share of a bout's typical movement (0.5 s spread of SMV) that marks its first and last step.</summary>
        public const double EdgeShare = 0.5;

        readonly double start;
        readonly double[] periods; // per moment, 0 when not walking
        readonly List<(double Start, double End)> bouts = new List<(double, double)>();

        RhythmReference(double start, double[] periods)
        {
            this.start = start;
            this.periods = periods;
        }

        /// <summary>The walking bouts, in order, with their edges at the first and last step (s, recording time).</summary>
        public IReadOnlyList<(double Start, double End)> Bouts => bouts;

        /// <summary>Total walking time (s).</summary>
        public double WalkingSeconds
        {
            get
            {
                double s = 0;
                foreach (var b in bouts) s += b.End - b.Start;
                return s;
            }
        }

        /// <summary>Whether <paramref name="time"/> lies inside a walking bout.</summary>
        public bool IsWalking(double time)
        {
            foreach (var b in bouts)
                if (time >= b.Start && time < b.End) return true;
            return false;
        }

        /// <summary>Whether <paramref name="time"/> lies within <paramref name="edge"/> seconds of a walking bout (inside one included).</summary>
        public bool IsNear(double time, double edge)
        {
            foreach (var b in bouts)
                if (time >= b.Start - edge && time <= b.End + edge) return true;
            return false;
        }

        /// <summary>The step period (s) the signal shows nearest <paramref name="time"/> inside its bout; 0 outside walking.</summary>
        public double StepPeriod(double time)
        {
            if (!IsWalking(time) || periods.Length == 0) return 0;
            int k = (int)Math.Round((time - start) / Hop);
            k = Math.Max(0, Math.Min(periods.Length - 1, k));
            for (int d = 0; d < periods.Length; d++)
            {
                if (k - d >= 0 && periods[k - d] > 0) return periods[k - d];
                if (k + d < periods.Length && periods[k + d] > 0) return periods[k + d];
            }
            return 0;
        }

        /// <summary>Median step rate over the walking moments (steps per minute); NaN without walking.</summary>
        public double MedianCadence
        {
            get
            {
                var rates = new List<double>();
                for (int k = 0; k < periods.Length; k++)
                    if (periods[k] > 0 && IsWalking(start + k * Hop)) rates.Add(60 / periods[k]);
                return GaitMetrics.Median(rates);
            }
        }

        /// <summary>Measures a recording (acceleration in the head frame, z up, y left).</summary>
        public static RhythmReference Of(Recording recording)
        {
            if (recording == null) throw new ArgumentNullException(nameof(recording));
            var raw = new RawSignal(recording);
            if (raw.Count < 2) return new RhythmReference(0, Array.Empty<double>());
            double t0 = raw.StartTime, t1 = raw.EndTime;
            int n = (int)Math.Floor((t1 - t0) * Rate) + 1;
            var smv = new double[n];
            var lat = new double[n];
            for (int i = 0; i < n; i++)
            {
                double t = t0 + i / Rate;
                smv[i] = raw.Smv(t);
                lat[i] = raw.Lateral(t);
            }
            // The rhythm is judged on the channels averaged over 0.2 s: heel strikes and SMV's second harmonic (two bumps per
            // step in some walkers) otherwise blur the step's repeat. The edges are found on the unsmoothed SMV.
            var smvSmooth = MovingAverage(smv, (int)Math.Round(Smoothing * Rate));
            lat = MovingAverage(lat, (int)Math.Round(Smoothing * Rate));
            int half = (int)Math.Round(HalfSpan * Rate), hop = (int)Math.Round(Hop * Rate);
            int shortest = (int)Math.Ceiling(ShortestStep * Rate), longest = (int)Math.Floor(LongestStep * Rate);
            int moments = n / hop + 1;
            var periods = new double[moments];
            for (int k = 0; k < moments; k++)
            {
                int c = k * hop, a = Math.Max(0, c - half), b = Math.Min(n, c + half);
                if (b - a < 2 * longest + 4) continue;
                var s = new ReadOnlySpan<double>(smvSmooth, a, b - a);
                if (StepRhythm.Spread(s) < MinSpread) continue;
                // The step: SMV repeats while the lateral swings to the other side. (SMV alone repeats best a stride later
                // when the steps differ; the lateral repeats there instead of swinging back.)
                var l = new ReadOnlySpan<double>(lat, a, b - a);
                int best = shortest;
                double bestScore = double.NegativeInfinity;
                for (int lag = shortest; lag <= longest; lag++)
                {
                    double r = StepRhythm.Autocorrelation(s, lag) - StepRhythm.Autocorrelation(l, lag);
                    if (r > bestScore)
                    {
                        bestScore = r;
                        best = lag;
                    }
                }
                if (StepRhythm.Autocorrelation(s, best) < MinBounce || 2 * best < s.Length - 2 && StepRhythm.Autocorrelation(s, 2 * best) < MinBounce) continue;
                if (StepRhythm.Autocorrelation(l, best) > MaxSway || StepRhythm.Autocorrelation(l, 2 * best) < MinStride) continue;
                periods[k] = best / Rate;
            }
            var reference = new RhythmReference(t0, periods);
            reference.FindBouts(smv, t0, hop);
            return reference;
        }

        void FindBouts(double[] smv, double t0, int hop)
        {
            // The 0.5 s spread of SMV starting at each analysis sample (the movement that follows it).
            int w = (int)Math.Round(0.5 * Rate);
            var moving = new double[smv.Length];
            for (int i = 0; i < smv.Length; i++)
                moving[i] = StepRhythm.Spread(new ReadOnlySpan<double>(smv, i, Math.Min(w, smv.Length - i)));
            // Runs of walking moments; short gaps filled, and longer ones where the head keeps moving as in the walk.
            var walkingMoving = new List<double>();
            for (int k = 0; k < periods.Length; k++)
                if (periods[k] > 0) walkingMoving.Add(moving[Math.Min(smv.Length - 1, k * hop)]);
            double keepsMoving = EdgeShare * GaitMetrics.Median(walkingMoving);
            var runs = new List<(int First, int Last)>();
            int gap = (int)Math.Round(LongestGap / Hop), movingGap = (int)Math.Round(LongestMovingGap / Hop);
            for (int k = 0; k < periods.Length; k++)
            {
                if (periods[k] <= 0) continue;
                if (runs.Count > 0)
                {
                    int last = runs[runs.Count - 1].Last;
                    bool fill = k - last <= gap;
                    if (!fill && k - last <= movingGap)
                    {
                        fill = true;
                        for (int i = last * hop; i < k * hop && fill; i++) fill = moving[Math.Min(smv.Length - 1, i)] >= keepsMoving;
                    }
                    if (fill)
                    {
                        runs[runs.Count - 1] = (runs[runs.Count - 1].First, k);
                        continue;
                    }
                }
                runs.Add((k, k));
            }
            int half = (int)Math.Round(HalfSpan * Rate);
            foreach (var (first, last) in runs)
            {
                int a = first * hop, b = Math.Min(smv.Length - 1, last * hop);
                var inside = new List<double>();
                for (int i = a; i <= b; i++) inside.Add(moving[i]);
                double level = EdgeShare * GaitMetrics.Median(inside);
                // The first step: the earliest sample from which the head moves at half the bout's level, within the span
                // the first walking moment judged; the last step: the latest such sample within the last moment's span.
                int lo = Math.Max(0, a - half), hi = Math.Min(smv.Length - 1, b + half);
                int onset = a;
                for (int i = a; i >= lo && moving[i] >= level; i--) onset = i;
                if (onset == a) for (int i = a; i <= b && moving[i] < level; i++) onset = i + 1;
                int end = b;
                for (int i = b; i <= hi && i - w >= 0 && moving[i - w] >= level; i++) end = i - w / 2; // the middle of the last moving half second
                double s = t0 + onset / Rate, e = t0 + end / Rate;
                if (e - s < ShortestBout) continue;
                if (bouts.Count > 0 && s <= bouts[bouts.Count - 1].End) bouts[bouts.Count - 1] = (bouts[bouts.Count - 1].Start, Math.Max(e, bouts[bouts.Count - 1].End));
                else bouts.Add((s, e));
            }
        }

        /// <summary>Centred moving average over <paramref name="width"/> samples (fewer at the ends).</summary>
        static double[] MovingAverage(double[] x, int width)
        {
            var y = new double[x.Length];
            if (width < 2)
            {
                Array.Copy(x, y, x.Length);
                return y;
            }
            int h = width / 2;
            double sum = 0;
            int lo = 0, hi = 0; // the sum covers x[lo..hi)
            for (int c = 0; c < x.Length; c++)
            {
                int a = Math.Max(0, c - h), b = Math.Min(x.Length, c - h + width);
                while (hi < b) sum += x[hi++];
                while (lo < a) sum -= x[lo++];
                y[c] = sum / (hi - lo);
            }
            return y;
        }
    }
}
