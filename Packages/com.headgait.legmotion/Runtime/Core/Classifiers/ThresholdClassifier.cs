using System;
using System.Collections.Generic;

namespace HeadGait
{
    public sealed class ThresholdSettings
    {
        /// <summary>SMV-minus-gravity level (m/s^2) whose upward crossing is taken as an initial contact.</summary>
        public double Threshold = 1.2;

        /// <summary>The detector re-arms once SMV falls below Threshold * RearmFraction.</summary>
        public double RearmFraction = 0.3;

        /// <summary>Crossings closer than this to the previous step are ignored (seconds).</summary>
        public double MinStepInterval = 0.3;

        /// <summary>Steps further apart than this are not used to update the step period (seconds).</summary>
        public double MaxStepInterval = 1.0;

        /// <summary>Step period assumed before two steps have been seen (seconds).</summary>
        public double InitialStepPeriod = 0.55;

        /// <summary>Standing is reported once no step was detected for this many step periods.</summary>
        public double StandingAfterPeriods = 1.6;

        /// <summary>Samples of lateral acceleration before the crossing that decide the side.</summary>
        public int SideSamples = 25;

        /// <summary>+1: positive mean lateral acceleration before the crossing means a left initial contact; -1: the opposite.</summary>
        public int LeftLateralSign = +1;
    }

    /// <summary>
    /// THR: an initial contact is detected when SMV minus gravity rises above a threshold; the side comes
    /// from the sign of the lateral (acc_y) acceleration just before it. Between detections the stride
    /// position advances at the measured step rate; no step for a while means standing.
    /// </summary>
    public sealed class ThresholdClassifier : IGaitClassifier
    {
        readonly ThresholdSettings settings;
        bool armed = true;
        bool walking;
        double lastStepTime = double.NegativeInfinity;
        Foot lastFoot;
        double stepPeriod;
        double lastSmv;

        public ThresholdClassifier(ThresholdSettings settings = null, PhaseMap phaseMap = null)
        {
            this.settings = settings ?? new ThresholdSettings();
            PhaseMap = phaseMap ?? PhaseMap.Perry;
            Reset();
        }

        public string Name => "THR";
        public PhaseMap PhaseMap { get; }
        public ThresholdSettings Settings => settings;

        public void Reset()
        {
            armed = true;
            walking = false;
            lastStepTime = double.NegativeInfinity;
            stepPeriod = settings.InitialStepPeriod;
            lastSmv = 0;
        }

        public GaitPrediction Classify(SignalWindow window)
        {
            int n = window.Length;
            double now = window.EndTime;
            double smv = window.Smv[n - 1];
            if (!armed && smv < settings.Threshold * settings.RearmFraction) armed = true;

            bool crossed = armed && smv >= settings.Threshold && lastSmv < settings.Threshold;
            lastSmv = smv;
            if (crossed && now - lastStepTime >= settings.MinStepInterval)
            {
                armed = false;
                int m = Math.Min(settings.SideSamples, n);
                double mean = 0;
                for (int i = n - m; i < n; i++) mean += window.Lateral[i];
                mean /= m;
                // Remove the window's lateral offset (head tilt leaks gravity into acc_y).
                double offset = 0;
                for (int i = 0; i < n; i++) offset += window.Lateral[i];
                offset /= n;
                Foot foot = (mean - offset) * settings.LeftLateralSign >= 0 ? Foot.Left : Foot.Right;
                double interval = now - lastStepTime;
                if (walking && interval <= settings.MaxStepInterval)
                {
                    stepPeriod = 0.7 * stepPeriod + 0.3 * interval;
                }
                walking = true;
                lastStepTime = now;
                lastFoot = foot;
            }

            if (walking && now - lastStepTime > settings.StandingAfterPeriods * stepPeriod) walking = false;
            if (!walking) return GaitPrediction.Standing(now);

            double since = now - lastStepTime;
            double s = PhaseMap.StridePositionOfOnset(lastFoot, GaitPhase.InitialContact) + since / (2 * stepPeriod);
            double confidence = Math.Max(0, 1 - since / (settings.StandingAfterPeriods * stepPeriod));
            return GaitPrediction.Walking(now, s, stepPeriod, confidence, PhaseMap);
        }

        /// <summary>
        /// Sets the threshold to a fraction of the median per-step SMV peak in labelled recordings and
        /// picks the lateral sign that names the feet right most often. Returns the settings it chose.
        /// </summary>
        public static ThresholdSettings Calibrate(IEnumerable<Recording> training, double peakFraction = 0.6)
        {
            var peaks = new List<double>();
            int agree = 0, disagree = 0;
            var s = new ThresholdSettings();
            foreach (var rec in training)
            {
                var raw = new RawSignal(rec);
                foreach (var step in PhaseEvents.TruthSteps(rec))
                {
                    double peak = double.NegativeInfinity;
                    for (int k = 0; k < 50; k++) peak = Math.Max(peak, raw.Smv(step.Start + step.Duration * k / 50.0));
                    peaks.Add(peak);
                    double before = 0, around = 0;
                    for (int k = 0; k < s.SideSamples; k++) before += raw.Lateral(step.Start + 0.05 - k * 0.01);
                    for (int k = 0; k < 50; k++) around += raw.Lateral(step.Start + 0.05 - k * 0.01);
                    double sign = before / s.SideSamples - around / 50;
                    if ((sign >= 0) == (step.Foot == Foot.Left)) agree++; else disagree++;
                }
            }
            if (peaks.Count == 0) return s;
            peaks.Sort();
            s.Threshold = peakFraction * peaks[peaks.Count / 2];
            s.LeftLateralSign = agree >= disagree ? +1 : -1;
            return s;
        }
    }
}
