using System;

namespace HeadGait
{
    public sealed class CorrelationSettings
    {
        /// <summary>A window counts as walking only when its best Pearson r with the step template exceeds this.</summary>
        public double MinCorrelation = 0.9;

        /// <summary>Shortest and longest step period searched, in resampled samples (40..75 = 0.40..0.75 s at 100 Hz).</summary>
        public int MinStepSamples = 40;
        public int MaxStepSamples = 75;

        /// <summary>Overrides the template's SMV-spread gate when set (m/s^2); negative keeps the template's.</summary>
        public double MinWalkingStdOverride = -1;

        /// <summary>
        /// Memory of the side evidence per window (0 = decide every window alone). Steps alternate feet, so the
        /// lateral evidence of past windows carries over, flipped at each step boundary. 0.985 at 100 Hz keeps about 0.7 s.
        /// </summary>
        public double SideMemory = 0.985;

        /// <summary>
        /// Once walking, only step periods within this many samples of the running period estimate are considered,
        /// unless the full search beats them by more than <see cref="RelockMargin"/> in r. A 0.5 s window holds about
        /// one step, so period and phase can trade off; tracking the slowly-changing period removes that ambiguity.
        /// Negative disables tracking.
        /// </summary>
        public int PeriodTolerance = 3;

        public double RelockMargin = 0.03;
    }

    /// <summary>
    /// COR: the window's SMV is correlated (Pearson) with the periodic mean step template at every step
    /// period and phase offset; the best match gives the position inside the step at the window's end,
    /// and it must exceed |r| &gt; 0.9 to count as walking. Which foot's step it is comes from a second
    /// correlation of the lateral acceleration (acc_y) with the stride template, tried for both feet.
    /// </summary>
    public sealed class CorrelationClassifier : IGaitClassifier
    {
        readonly CorrelationTemplate template;
        readonly CorrelationSettings settings;
        readonly double[][] extended;   // per period P: template resampled at 1/P, extended periodically
        readonly double[][] segNorm;    // per period P and offset k: norm of the centred template segment
        readonly int windowLength;
        readonly double[] centred;
        readonly double[] latCentred;
        readonly double[] scores;

        public CorrelationClassifier(CorrelationTemplate template, CorrelationSettings settings = null, int windowLength = 50)
        {
            this.template = template ?? throw new ArgumentNullException(nameof(template));
            this.settings = settings ?? new CorrelationSettings();
            if (this.settings.MinStepSamples < 4 || this.settings.MaxStepSamples < this.settings.MinStepSamples)
                throw new ArgumentException("Step period search range is invalid.");
            this.windowLength = windowLength;
            int periods = this.settings.MaxStepSamples - this.settings.MinStepSamples + 1;
            extended = new double[periods][];
            segNorm = new double[periods][];
            for (int pi = 0; pi < periods; pi++)
            {
                int P = this.settings.MinStepSamples + pi;
                var ext = new double[P + windowLength];
                for (int j = 0; j < ext.Length; j++) ext[j] = template.StepAt((double)(j % P) / P);
                extended[pi] = ext;
                var norms = new double[P];
                for (int start = 0; start < P; start++)
                {
                    double m = 0;
                    for (int i = 0; i < windowLength; i++) m += ext[start + i];
                    m /= windowLength;
                    double ss = 0;
                    for (int i = 0; i < windowLength; i++)
                    {
                        double d = ext[start + i] - m;
                        ss += d * d;
                    }
                    norms[start] = Math.Sqrt(ss);
                }
                segNorm[pi] = norms;
            }
            centred = new double[windowLength];
            latCentred = new double[windowLength];
            scores = new double[this.settings.MaxStepSamples + 1];
            periodBestR = new double[periods];
            periodBestU = new double[periods];
        }

        int ArgMax(int from, int to)
        {
            int best = -1;
            for (int i = from; i <= to; i++)
                if (best < 0 || periodBestR[i] > periodBestR[best]) best = i;
            return best;
        }

        public string Name => "COR";
        public PhaseMap PhaseMap => template.PhaseMap;
        public CorrelationTemplate Template => template;

        /// <summary>Best Pearson r of the last classified window (diagnostics).</summary>
        public double LastCorrelation { get; private set; }

        /// <summary>Lateral correlation of the chosen side for the last walking window (diagnostics).</summary>
        public double LastSideCorrelation { get; private set; }

        readonly double[] periodBestR;
        readonly double[] periodBestU;
        double periodEstimate;      // running step period while walking (samples)
        double sideEvidence;        // > 0: the current step is the left foot's
        double lastStepFraction = -1;
        double lastWalkingTime = double.NegativeInfinity;

        public void Reset()
        {
            LastCorrelation = 0;
            LastSideCorrelation = 0;
            sideEvidence = 0;
            periodEstimate = 0;
            lastStepFraction = -1;
            lastWalkingTime = double.NegativeInfinity;
        }

        public GaitPrediction Classify(SignalWindow window)
        {
            if (window.Length != windowLength) throw new ArgumentException($"COR was built for {windowLength}-sample windows, got {window.Length}.");
            int n = windowLength;
            double now = window.EndTime;
            double mean = 0;
            for (int i = 0; i < n; i++) mean += window.Smv[i];
            mean /= n;
            double ss = 0;
            for (int i = 0; i < n; i++)
            {
                double d = window.Smv[i] - mean;
                centred[i] = d;
                ss += d * d;
            }
            double wNorm = Math.Sqrt(ss);
            double gate = settings.MinWalkingStdOverride >= 0 ? settings.MinWalkingStdOverride : template.MinWalkingStd;
            if (wNorm / Math.Sqrt(n) < gate || wNorm <= 0)
            {
                LastCorrelation = 0;
                return GaitPrediction.Standing(now);
            }

            for (int pi = 0; pi < extended.Length; pi++)
            {
                int P = settings.MinStepSamples + pi;
                var ext = extended[pi];
                var norms = segNorm[pi];
                double localBest = double.NegativeInfinity;
                int localK = 0;
                // The sample at window index i sits at step phase (k - (n-1) + i)/P; start = (k - n + 1) mod P.
                for (int start = 0; start < P; start++)
                {
                    double dot = 0;
                    for (int i = 0; i < n; i++) dot += centred[i] * ext[start + i];
                    double r = norms[start] > 0 ? dot / (wNorm * norms[start]) : 0;
                    scores[start] = r;
                    if (r > localBest)
                    {
                        localBest = r;
                        localK = start;
                    }
                }
                // Sub-sample refinement of the offset by a parabola through the neighbours.
                double rm = scores[(localK - 1 + P) % P], rp = scores[(localK + 1) % P];
                double denom = rm - 2 * localBest + rp;
                double frac = denom < 0 ? 0.5 * (rm - rp) / denom : 0;
                if (frac > 0.5) frac = 0.5;
                if (frac < -0.5) frac = -0.5;
                periodBestR[pi] = localBest;
                periodBestU[pi] = PhaseMap.Wrap((localK + frac + n - 1) / P);
            }

            int chosen = ArgMax(0, extended.Length - 1);
            bool tracking = settings.PeriodTolerance >= 0 && now - lastWalkingTime <= 0.2 && periodEstimate > 0;
            if (tracking)
            {
                int centre = (int)Math.Round(periodEstimate) - settings.MinStepSamples;
                int near = ArgMax(Math.Max(0, centre - settings.PeriodTolerance), Math.Min(extended.Length - 1, centre + settings.PeriodTolerance));
                if (near >= 0 && periodBestR[chosen] - periodBestR[near] <= settings.RelockMargin) chosen = near;
            }
            double best = periodBestR[chosen];
            int bestP = settings.MinStepSamples + chosen;
            double bestU = periodBestU[chosen];
            LastCorrelation = best;
            if (best < settings.MinCorrelation) return GaitPrediction.Standing(now, Math.Max(0, best));

            // Side: which foot's step is this? Correlate lateral acc with the stride template for both.
            double lm = 0;
            for (int i = 0; i < n; i++) lm += window.Lateral[i];
            lm /= n;
            for (int i = 0; i < n; i++) latCentred[i] = window.Lateral[i] - lm;
            double offset = template.PhaseMap.RightOffset;
            double sLeft = bestU * offset;                       // left step spans stride [0, offset)
            double sRight = offset + bestU * (1 - offset);       // right step spans [offset, 1)
            double rLeft = LateralCorrelation(sLeft, offset, bestP);
            double rRight = LateralCorrelation(sRight, 1 - offset, bestP);
            // Carry the side evidence across windows: when the step fraction wraps, a new step (of the other foot) began.
            if (now - lastWalkingTime > 0.2) sideEvidence = 0;
            else if (lastStepFraction >= 0 && Math.Abs(bestU - lastStepFraction) > 0.5) sideEvidence = -sideEvidence;
            sideEvidence = settings.SideMemory * sideEvidence + (rLeft - rRight);
            lastStepFraction = bestU;
            lastWalkingTime = now;
            periodEstimate = tracking ? 0.9 * periodEstimate + 0.1 * bestP : bestP;
            double s = sideEvidence >= 0 ? sLeft : sRight;
            LastSideCorrelation = sideEvidence >= 0 ? rLeft : rRight;
            return GaitPrediction.Walking(now, s, bestP / window.SampleRate, best, template.PhaseMap);
        }

        double LateralCorrelation(double sEnd, double stepFraction, int stepSamples)
        {
            int n = windowLength;
            double perSample = stepFraction / stepSamples;
            double tm = 0;
            double dot = 0, tt = 0;
            for (int i = 0; i < n; i++) tm += template.LateralAt(sEnd - (n - 1 - i) * perSample);
            tm /= n;
            double ll = 0;
            for (int i = 0; i < n; i++)
            {
                double v = template.LateralAt(sEnd - (n - 1 - i) * perSample) - tm;
                dot += latCentred[i] * v;
                tt += v * v;
                ll += latCentred[i] * latCentred[i];
            }
            return tt > 0 && ll > 0 ? dot / Math.Sqrt(tt * ll) : 0;
        }
    }
}
