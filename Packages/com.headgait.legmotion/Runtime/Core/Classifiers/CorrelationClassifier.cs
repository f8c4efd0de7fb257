using System;
using System.Collections.Generic;

namespace HeadGait
{
    public sealed class CorrelationSettings
    {
        /// <summary>Shortest and longest step searched, in grid samples (30..90 = 0.3..0.9 s at 100 Hz).</summary>
        public int MinStepSamples = 30;
        public int MaxStepSamples = 90;

        /// <summary>While walking, only steps within this many samples of the current step period are tried.</summary>
        public int PeriodTolerance = 6;

        /// <summary>
        /// A correlation peak counts once no higher value came in this many samples after it: a step's correlation
        /// rises and falls over several samples, and waiting lets the true top win over an early bump.
        /// </summary>
        public int PeakConfirmSamples = 5;

        /// <summary>Overrides the template's correlation threshold when set (e.g. the paper's 0.9); NaN keeps the template's.</summary>
        public double MinCorrelationOverride = double.NaN;

        /// <summary>
        /// While standing, each window is also searched for a step at every phase (the paper's per-window rule); a match
        /// this much above the threshold starts walking at once instead of at the next contact. Negative turns it off.
        /// </summary>
        public double StartMargin = 0.05;

        /// <summary>Newest samples the standing search correlates (50 = the paper's 0.5 s window).</summary>
        public int StartWindow = 50;

        public StepClockSettings Clock = new StepClockSettings { ContactsToStart = 1 };
    }

    /// <summary>
    /// COR: at every window, Pearson's r between the newest P samples of SMV minus gravity and the mean step template
    /// stretched to P samples, for each step length P searched (around the current step period while walking). The
    /// template ends at an initial contact, so r peaks when a foot has just landed: a peak above the learned threshold is
    /// a contact (dated back by the learned detection lag). Which foot comes from the lateral acceleration of the step that
    /// just ended, correlated with the mean left step; a <see cref="StepClock"/> turns the contacts into a stride position.
    /// Each window costs one dot product per step length tried, about 4,000 multiply-adds when searching all of them.
    /// Allocation-free per window.
    /// </summary>
    public sealed class CorrelationClassifier : IGaitClassifier
    {
        readonly CorrelationTemplate template;
        readonly CorrelationSettings settings;
        readonly StepClock clock;
        readonly double[][] stepCurves;     // per step length P: the template at P samples, centred, unit norm
        readonly double[][] lateralCurves;  // the same for the lateral template
        readonly double[] prefix, prefixSq;
        readonly double[] recentR, recentEvidence, recentTime;
        readonly double minCorrelation;
        readonly double[][] startMean, startNorm; // per step length and phase: the periodic template's mean and spread over StartWindow samples
        readonly double[] centred;
        int recentCount;
        int stillWindows;

        public CorrelationClassifier(CorrelationTemplate template, CorrelationSettings settings = null)
        {
            this.template = template ?? throw new ArgumentNullException(nameof(template));
            this.settings = settings ?? new CorrelationSettings();
            var s = this.settings;
            if (s.MinStepSamples < 8 || s.MaxStepSamples < s.MinStepSamples || s.MaxStepSamples > 400)
                throw new ArgumentException("Step search range must satisfy 8 <= MinStepSamples <= MaxStepSamples <= 400.");
            if (s.PeakConfirmSamples < 1 || s.PeakConfirmSamples > 50) throw new ArgumentException("PeakConfirmSamples must be 1..50.");
            minCorrelation = double.IsNaN(s.MinCorrelationOverride) ? template.MinCorrelation : s.MinCorrelationOverride;
            clock = new StepClock(template.PhaseMap, s.Clock);
            int periods = s.MaxStepSamples - s.MinStepSamples + 1;
            stepCurves = new double[periods][];
            lateralCurves = new double[periods][];
            for (int i = 0; i < periods; i++)
            {
                int p = s.MinStepSamples + i;
                stepCurves[i] = Normalised(template.StepSmv, p);
                lateralCurves[i] = Normalised(template.StepLateral, p);
            }
            int L = s.StartWindow;
            startMean = new double[periods][];
            startNorm = new double[periods][];
            for (int i = 0; i < periods; i++)
            {
                int p = s.MinStepSamples + i;
                startMean[i] = new double[p];
                startNorm[i] = new double[p];
                for (int k = 0; k < p; k++)
                {
                    double m = 0, m2 = 0;
                    for (int j = 0; j < L; j++)
                    {
                        double v = stepCurves[i][Mod(k - (L - 1 - j), p)];
                        m += v;
                        m2 += v * v;
                    }
                    m /= L;
                    startMean[i][k] = m;
                    startNorm[i][k] = Math.Sqrt(Math.Max(0, m2 - L * m * m));
                }
            }
            centred = new double[L];
            prefix = new double[WindowLength + 1];
            prefixSq = new double[WindowLength + 1];
            int ring = 2 * s.PeakConfirmSamples + 1;
            recentR = new double[ring];
            recentEvidence = new double[ring];
            recentTime = new double[ring];
        }

        /// <summary>The template curve resampled to p samples (the last one at the step's end), centred, unit norm.</summary>
        static double[] Normalised(double[] curve, int p)
        {
            var v = new double[p];
            double mean = 0;
            for (int j = 0; j < p; j++) mean += v[j] = CorrelationTemplate.At(curve, (j + 1.0) / p);
            mean /= p;
            double ss = 0;
            for (int j = 0; j < p; j++)
            {
                v[j] -= mean;
                ss += v[j] * v[j];
            }
            double norm = Math.Sqrt(ss);
            for (int j = 0; j < p; j++) v[j] = norm > 0 ? v[j] / norm : 0;
            return v;
        }

        public string Name => "COR";
        public int WindowLength => settings.MaxStepSamples;
        public PhaseMap PhaseMap => template.PhaseMap;
        public CorrelationTemplate Template => template;
        public StepClock Clock => clock;

        /// <summary>Best Pearson r of the last window (diagnostics).</summary>
        public double LastCorrelation { get; private set; }

        /// <summary>Raised for every contact the clock takes: its time (lag-corrected), the evidence that it is the left foot's, and its r.</summary>
        public event Action<double, double, double> ContactDetected;

        public void Reset()
        {
            clock.Reset();
            recentCount = 0;
            stillWindows = 0;
            LastCorrelation = 0;
        }

        public GaitPrediction Classify(SignalWindow window)
        {
            int n = window.Length;
            if (n < WindowLength) throw new ArgumentException($"COR needs {WindowLength}-sample windows, got {n}.");
            double now = window.EndTime;
            var x = window.Smv;
            int o = n - WindowLength;
            prefix[0] = prefixSq[0] = 0;
            for (int i = 0; i < WindowLength; i++)
            {
                double v = x[o + i];
                prefix[i + 1] = prefix[i] + v;
                prefixSq[i + 1] = prefixSq[i] + v * v;
            }

            // The head does not move like walking in the newest 0.5 s: standing, whatever the shape.
            int valid = Math.Min(window.Count, WindowLength);
            double best = -1;
            int bestIndex = -1;
            bool moving = template.Gate.Passes(window);
            stillWindows = moving ? 0 : stillWindows + 1;
            if (stillWindows == settings.Clock.StopAfterStillWindows) clock.Stop();
            if (moving)
            {
                int from = 0, to = Math.Min(stepCurves.Length - 1, valid - settings.MinStepSamples);
                if (clock.IsWalking(now) && to >= 0)
                {
                    int centre = (int)Math.Round(clock.StepPeriod * window.SampleRate) - settings.MinStepSamples;
                    from = Math.Max(0, Math.Min(to, centre - settings.PeriodTolerance));
                    to = Math.Max(from, Math.Min(to, centre + settings.PeriodTolerance));
                }
                for (int i = from; i <= to; i++)
                {
                    double r = Correlation(x, o, stepCurves[i], WindowLength);
                    if (r > best)
                    {
                        best = r;
                        bestIndex = i;
                    }
                }
            }
            LastCorrelation = best;
            double evidence = bestIndex >= 0 && best >= minCorrelation ? -Correlation(window.Lateral, n - lateralCurves[bestIndex].Length, lateralCurves[bestIndex], lateralCurves[bestIndex].Length, true) : 0;
            // The step that just ended was a left step when the lateral matches the left-step template: the foot landing now is the right one.
            Remember(now, best, evidence);
            if (recentCount == recentR.Length)
            {
                int centre = settings.PeakConfirmSamples;
                double r = recentR[centre];
                bool peak = r >= minCorrelation;
                for (int i = 0; peak && i < recentR.Length; i++)
                    if (i != centre && (recentR[i] > r || (recentR[i] == r && i < centre))) peak = false;
                if (peak && clock.Contact(recentTime[centre] - template.ContactLag, recentEvidence[centre]))
                    ContactDetected?.Invoke(recentTime[centre] - template.ContactLag, recentEvidence[centre], r);
            }
            if (!clock.IsWalking(now) && settings.StartMargin >= 0 && moving) TryStart(window, now, valid);
            return clock.Predict(now, Math.Max(0, best));
        }

        static int Mod(int a, int p) => ((a % p) + p) % p;

        /// <summary>
        /// The standing search: the newest StartWindow samples against the template repeated at every step length and
        /// phase (coarse grid, then its neighbours). A clear match starts the clock at the phase found, with the side from
        /// the lateral acceleration of the step in progress and the one before it (mirrored).
        /// </summary>
        void TryStart(SignalWindow window, double now, int valid)
        {
            int L = settings.StartWindow;
            if (valid < L) return;
            var x = window.Smv;
            int first = window.Length - L;
            double mean = 0;
            for (int j = 0; j < L; j++) mean += x[first + j];
            mean /= L;
            double ss = 0;
            for (int j = 0; j < L; j++)
            {
                centred[j] = x[first + j] - mean;
                ss += centred[j] * centred[j];
            }
            if (ss <= 1e-12) return;
            double norm = Math.Sqrt(ss), bestR = -1;
            int bestI = -1, bestK = 0;
            for (int pass = 0; pass < 2; pass++)
            {
                int iFrom = pass == 0 ? 0 : Math.Max(0, bestI - 1), iTo = pass == 0 ? stepCurves.Length - 1 : Math.Min(stepCurves.Length - 1, bestI + 1);
                int stride = pass == 0 ? 2 : 1;
                int ci = bestI, ck = bestK;
                for (int i = iFrom; i <= iTo; i += stride)
                {
                    var curve = stepCurves[i];
                    int p = curve.Length;
                    int kFrom = pass == 0 ? 0 : ck * p / stepCurves[ci].Length - 2, kTo = pass == 0 ? p - 1 : kFrom + 4;
                    for (int k = kFrom; k <= kTo; k += stride)
                    {
                        int km = Mod(k, p);
                        if (startNorm[i][km] <= 1e-12) continue;
                        double dot = 0;
                        for (int j = 0; j < L; j++) dot += centred[j] * curve[Mod(km - (L - 1 - j), p)];
                        double r = dot / (norm * startNorm[i][km]);
                        if (r > bestR)
                        {
                            bestR = r;
                            bestI = i;
                            bestK = km;
                        }
                    }
                }
                if (bestI < 0) return;
            }
            if (bestR < minCorrelation + settings.StartMargin) return;
            var lateral = lateralCurves[bestI];
            int period = lateral.Length;
            int sinceContact = (bestK + 1) % period; // samples since the step's initial contact (index P-1 is the contact)
            // Hypothesis: the last contact was the left foot's, so the step in progress is a left step and the one before a right step.
            double lm = 0;
            for (int j = 0; j < L; j++) lm += window.Lateral[first + j];
            lm /= L;
            double dotL = 0, nl = 0, nt = 0;
            for (int j = 0; j < L; j++)
            {
                int back = L - 1 - j;
                double t = lateral[Mod(bestK - back, period)] * (back < sinceContact ? 1 : -1);
                double v = window.Lateral[first + j] - lm;
                dotL += v * t;
                nl += v * v;
                nt += t * t;
            }
            double leftEvidence = nl > 0 && nt > 0 ? dotL / Math.Sqrt(nl * nt) : 0;
            clock.Start(now - sinceContact / window.SampleRate, leftEvidence, period / window.SampleRate);
        }

        void Remember(double time, double r, double evidence)
        {
            if (recentCount == recentR.Length)
            {
                Array.Copy(recentR, 1, recentR, 0, recentR.Length - 1);
                Array.Copy(recentEvidence, 1, recentEvidence, 0, recentR.Length - 1);
                Array.Copy(recentTime, 1, recentTime, 0, recentR.Length - 1);
                recentCount--;
            }
            recentR[recentCount] = r;
            recentEvidence[recentCount] = evidence;
            recentTime[recentCount] = time;
            recentCount++;
        }

        /// <summary>Pearson r of the newest curve.Length samples ending at window index start + length - 1 with a centred unit-norm curve.</summary>
        double Correlation(double[] signal, int start, double[] curve, int length, bool ownSums = false)
        {
            int p = curve.Length;
            int first = start + length - p;
            double dot = 0, sum, sumSq;
            for (int j = 0; j < p; j++) dot += signal[first + j] * curve[j];
            if (ownSums)
            {
                sum = sumSq = 0;
                for (int j = 0; j < p; j++)
                {
                    sum += signal[first + j];
                    sumSq += signal[first + j] * signal[first + j];
                }
            }
            else
            {
                int a = length - p; // prefix sums are over the COR window
                sum = prefix[length] - prefix[a];
                sumSq = prefixSq[length] - prefixSq[a];
            }
            double ss = sumSq - sum * sum / p;
            return ss > 1e-12 ? dot / Math.Sqrt(ss) : 0;
        }

        /// <summary>
        /// Sets the correlation threshold and the contact lag on labelled recordings. First a replay with no threshold:
        /// the r of correlation peaks that match a true contact (within 0.15 s) and of those that do not give the threshold
        /// that best separates them. Then a replay with that threshold: the lag is the median time from a true contact to
        /// the peak the clock takes for it (measured with the threshold in force, since weaker early peaks would bias it).
        /// </summary>
        public static CorrelationTemplate Calibrate(CorrelationTemplate template, IReadOnlyList<Recording> recordings, CorrelationSettings settings = null)
        {
            var trueR = new List<double>();
            var falseR = new List<double>();
            Match(template.With(minCorrelation: -0.99, contactLag: 0), recordings, settings, (offset, r) =>
            {
                if (Math.Abs(offset) <= 0.15) trueR.Add(r);
                else falseR.Add(r);
            });
            if (trueR.Count < 8) return template;
            // Threshold: minimise missed true peaks plus accepted false ones (both per true contact).
            double bestThreshold = template.MinCorrelation, bestCost = double.PositiveInfinity;
            for (double th = 0.2; th <= 0.95; th += 0.01)
            {
                double missed = 0, accepted = 0;
                foreach (var r in trueR) if (r < th) missed++;
                foreach (var r in falseR) if (r >= th) accepted++;
                double cost = (missed + accepted) / trueR.Count;
                if (cost < bestCost)
                {
                    bestCost = cost;
                    bestThreshold = th;
                }
            }
            var thresholded = template.With(minCorrelation: Math.Round(bestThreshold, 2), contactLag: 0);
            var lags = new List<double>();
            Match(thresholded, recordings, settings, (offset, r) =>
            {
                if (Math.Abs(offset) <= 0.15) lags.Add(offset);
            });
            if (lags.Count < 8) return thresholded;
            lags.Sort();
            return thresholded.With(contactLag: Math.Max(-0.45, Math.Min(0.45, lags[lags.Count / 2])));
        }

        /// <summary>Replays each recording and reports, for every contact the clock takes, its offset from the nearest true contact and its r.</summary>
        static void Match(CorrelationTemplate probe, IReadOnlyList<Recording> recordings, CorrelationSettings settings, Action<double, double> onContact)
        {
            foreach (var rec in recordings)
            {
                var cor = new CorrelationClassifier(probe, settings);
                var detections = new List<(double time, double r)>();
                var pre = new StreamPreprocessor(new PreprocessorSettings { History = cor.WindowLength });
                cor.ContactDetected += (t, e, r) => detections.Add((t, r));
                foreach (var s in rec.Samples) pre.Push(s.Imu, w => cor.Classify(w));
                PhaseEvents.ExtractTruth(rec, out var times, out var left, out var right);
                var contacts = PhaseEvents.Contacts(times, left, right);
                foreach (var d in detections)
                {
                    double nearest = double.PositiveInfinity;
                    foreach (var c in contacts)
                        if (Math.Abs(d.time - c.Time) < Math.Abs(nearest)) nearest = d.time - c.Time;
                    onContact(nearest, d.r);
                }
            }
        }
    }
}
