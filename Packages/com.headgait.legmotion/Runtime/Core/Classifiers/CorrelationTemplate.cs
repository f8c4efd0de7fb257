using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace HeadGait
{
    /// <summary>
    /// What COR learns from labelled recordings: the mean step of SMV minus gravity (one step from a foot's initial
    /// contact to the other foot's, each step standardised before averaging so that bouncy and calm walkers weigh the
    /// same), the mean lateral acceleration over a left step (right steps mirrored in), the correlation a step must reach,
    /// the walking gate (<see cref="WalkingGate"/>), how late a contact is detected, and the phase map.
    /// </summary>
    public sealed class CorrelationTemplate
    {
        public const int StepPoints = 100;
        public const string Magic = "# headgait-cor-template v2";

        /// <summary>The paper's rule: a window is a step when Pearson's r with the mean template exceeds 0.9.</summary>
        public const double PaperMinCorrelation = 0.9;

        public CorrelationTemplate(double[] stepSmv, double[] stepLateral, PhaseMap phaseMap, double minCorrelation, WalkingGate gate,
            double contactLag, int stepsUsed = 0)
        {
            if (stepSmv == null || stepSmv.Length != StepPoints) throw new ArgumentException($"The step template needs {StepPoints} points.");
            if (stepLateral == null || stepLateral.Length != StepPoints) throw new ArgumentException($"The lateral template needs {StepPoints} points.");
            foreach (var v in stepSmv) if (!ImuSample.IsFiniteNumber(v)) throw new ArgumentException("The step template has a non-finite value.");
            foreach (var v in stepLateral) if (!ImuSample.IsFiniteNumber(v)) throw new ArgumentException("The lateral template has a non-finite value.");
            if (Spread(stepSmv) < 1e-9) throw new ArgumentException("The step template is constant: nothing to correlate with.");
            if (!(minCorrelation > -1 && minCorrelation < 1)) throw new ArgumentException("The minimum correlation must lie in (-1, 1).");
            if (!(Math.Abs(contactLag) < 0.5)) throw new ArgumentException("The contact lag must lie within 0.5 s.");
            StepSmv = (double[])stepSmv.Clone();
            StepLateral = (double[])stepLateral.Clone();
            PhaseMap = phaseMap ?? throw new ArgumentNullException(nameof(phaseMap));
            MinCorrelation = minCorrelation;
            Gate = gate ?? WalkingGate.Open;
            ContactLag = contactLag;
            StepsUsed = stepsUsed;
        }

        public double[] StepSmv { get; }
        public double[] StepLateral { get; }
        public PhaseMap PhaseMap { get; }
        public double MinCorrelation { get; }
        public WalkingGate Gate { get; }
        /// <summary>Mean time from a true initial contact to the correlation peak that detects it (s).</summary>
        public double ContactLag { get; }
        public int StepsUsed { get; }

        public CorrelationTemplate With(double? minCorrelation = null, WalkingGate gate = null, double? contactLag = null)
            => new CorrelationTemplate(StepSmv, StepLateral, PhaseMap, minCorrelation ?? MinCorrelation, gate ?? Gate,
                contactLag ?? ContactLag, StepsUsed);

        /// <summary>A template curve at step fraction u in [0, 1] (linear interpolation, clamped).</summary>
        public static double At(double[] curve, double u)
        {
            double p = Math.Min(Math.Max(u, 0), 1) * (curve.Length - 1);
            int i = Math.Min((int)p, curve.Length - 2);
            return curve[i] + (p - i) * (curve[i + 1] - curve[i]);
        }

        static double Spread(double[] v)
        {
            double m = 0, s = 0;
            foreach (var x in v) m += x;
            m /= v.Length;
            foreach (var x in v) s += (x - m) * (x - m);
            return Math.Sqrt(s / v.Length);
        }

        /// <summary>
        /// Learns the step and lateral templates from labelled recordings, with the given phase map and walking gate. The
        /// correlation threshold and contact lag are set by <see cref="CorrelationClassifier.Calibrate"/>. Throws
        /// <see cref="InvalidOperationException"/> when the recordings hold fewer than 8 usable steps.
        /// </summary>
        public static CorrelationTemplate Train(IEnumerable<Recording> recordings, PhaseMap map, WalkingGate gate)
        {
            var step = new double[StepPoints];
            var lateral = new double[StepPoints];
            int steps = 0;
            var curve = new double[StepPoints];
            foreach (var rec in recordings)
            {
                var raw = new RawSignal(rec);
                foreach (var st in PhaseEvents.TruthSteps(rec))
                {
                    for (int k = 0; k < StepPoints; k++) curve[k] = raw.Smv(st.Start + st.Duration * k / (StepPoints - 1));
                    double spread = Spread(curve);
                    if (spread < 1e-6) continue;
                    double mean = 0;
                    foreach (var v in curve) mean += v;
                    mean /= StepPoints;
                    for (int k = 0; k < StepPoints; k++) step[k] += (curve[k] - mean) / spread;
                    double lm = 0;
                    for (int k = 0; k < StepPoints; k++) lm += curve[k] = raw.Lateral(st.Start + st.Duration * k / (StepPoints - 1));
                    lm /= StepPoints;
                    double sign = st.Foot == Foot.Left ? 1 : -1;
                    for (int k = 0; k < StepPoints; k++) lateral[k] += sign * (curve[k] - lm);
                    steps++;
                }
            }
            if (steps < 8)
                throw new InvalidOperationException($"Training data too small: {steps} steps found (need 8); recordings need phase_left/phase_right labels with walking.");
            for (int k = 0; k < StepPoints; k++)
            {
                step[k] /= steps;
                lateral[k] /= steps;
            }
            return new CorrelationTemplate(step, lateral, map, 0.5, gate, 0, steps);
        }

        public string Serialize()
        {
            var ci = CultureInfo.InvariantCulture;
            string Join(double[] v)
            {
                var sb = new StringBuilder();
                for (int i = 0; i < v.Length; i++) sb.Append(i > 0 ? "," : "").Append(v[i].ToString("G9", ci));
                return sb.ToString();
            }
            return KeyValueText.Write(Magic, new[]
            {
                new KeyValuePair<string, string>("phase_map", PhaseMap.Serialize()),
                new KeyValuePair<string, string>("min_correlation", MinCorrelation.ToString("R", ci)),
                new KeyValuePair<string, string>("walking_gate", Gate.Serialize()),
                new KeyValuePair<string, string>("contact_lag", ContactLag.ToString("R", ci)),
                new KeyValuePair<string, string>("steps_used", StepsUsed.ToString(ci)),
                new KeyValuePair<string, string>("step_smv", Join(StepSmv)),
                new KeyValuePair<string, string>("step_lateral", Join(StepLateral)),
            });
        }

        public void Save(string path) => File.WriteAllText(path, Serialize(), new UTF8Encoding(false));

        public static CorrelationTemplate Load(string path) => Parse(File.ReadAllText(path, Encoding.UTF8), path);

        /// <summary>Reads a template written by <see cref="Serialize"/>; throws <see cref="FormatException"/> naming the source and the key.</summary>
        public static CorrelationTemplate Parse(string text, string source = "COR template")
        {
            var kv = KeyValueText.Parse(text, Magic, source);
            var map = kv.PhaseMap("phase_map");
            double minR = kv.Number("min_correlation", -0.999, 0.999);
            var gate = new WalkingGate(kv.Numbers("walking_gate", WalkingGate.FeatureCount + 1, -1e4, 1e4));
            double lag = kv.Number("contact_lag", -0.49, 0.49);
            int steps = (int)kv.Number("steps_used", 0, int.MaxValue, 0);
            var smv = kv.Numbers("step_smv", StepPoints, -1e6, 1e6);
            var lat = kv.Numbers("step_lateral", StepPoints, -1e6, 1e6);
            if (Spread(smv) < 1e-9) throw new FormatException($"{source}: 'step_smv' is constant: nothing to correlate with");
            return new CorrelationTemplate(smv, lat, map, minR, gate, lag, steps);
        }
    }
}
