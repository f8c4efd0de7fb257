using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace HeadGait
{
    /// <summary>
    /// Templates for the COR classifier, learned from labelled recordings:
    /// the mean SMV-minus-gravity curve over one step (initial contact to the other foot's initial
    /// contact, on a grid of <see cref="StepPoints"/>), the mean lateral acceleration over one stride
    /// (left IC to left IC, <see cref="StridePoints"/>), the phase map (where each phase starts in the
    /// stride) and the smallest SMV spread that still counts as walking.
    /// </summary>
    public sealed class CorrelationTemplate
    {
        public const int StepPoints = 100;
        public const int StridePoints = 200;
        const string Magic = "# headgait-cor-template v1";

        public CorrelationTemplate(double[] stepSmv, double[] strideLateral, PhaseMap phaseMap, double minWalkingStd, int stepsUsed = 0, int stridesUsed = 0)
        {
            if (stepSmv == null || stepSmv.Length != StepPoints) throw new ArgumentException($"Step template needs {StepPoints} points.");
            if (strideLateral == null || strideLateral.Length != StridePoints) throw new ArgumentException($"Stride template needs {StridePoints} points.");
            foreach (var v in stepSmv) if (!ImuSample.IsFiniteNumber(v)) throw new ArgumentException("Step template has a non-finite value.");
            foreach (var v in strideLateral) if (!ImuSample.IsFiniteNumber(v)) throw new ArgumentException("Stride template has a non-finite value.");
            StepSmv = (double[])stepSmv.Clone();
            StrideLateral = (double[])strideLateral.Clone();
            PhaseMap = phaseMap ?? throw new ArgumentNullException(nameof(phaseMap));
            MinWalkingStd = minWalkingStd;
            StepsUsed = stepsUsed;
            StridesUsed = stridesUsed;
        }

        public double[] StepSmv { get; }
        public double[] StrideLateral { get; }
        public PhaseMap PhaseMap { get; }
        public double MinWalkingStd { get; }
        public int StepsUsed { get; }
        public int StridesUsed { get; }

        /// <summary>Step template at step fraction u (periodic, linear interpolation).</summary>
        public double StepAt(double u) => Periodic(StepSmv, u);

        /// <summary>Lateral template at stride position s (periodic, linear interpolation).</summary>
        public double LateralAt(double s) => Periodic(StrideLateral, s);

        static double Periodic(double[] v, double x)
        {
            double p = PhaseMap.Wrap(x) * v.Length;
            int i = (int)p;
            if (i >= v.Length) i = v.Length - 1;
            double a = p - i;
            int j = i + 1 == v.Length ? 0 : i + 1;
            return v[i] + a * (v[j] - v[i]);
        }

        /// <summary>
        /// Learns templates from recordings with ground truth. Throws <see cref="InvalidOperationException"/>
        /// when they hold fewer than 4 usable steps or 2 usable strides.
        /// </summary>
        public static CorrelationTemplate Train(IEnumerable<Recording> recordings)
        {
            var step = new double[StepPoints];
            var stride = new double[StridePoints];
            var onsetSums = new double[GaitPhases.WalkingPhaseCount];
            var onsetCounts = new int[GaitPhases.WalkingPhaseCount];
            double offsetSum = 0;
            int offsetCount = 0;
            int steps = 0, strides = 0;
            var walkingStd = new List<double>();

            foreach (var rec in recordings)
            {
                var raw = new RawSignal(rec);
                var stepList = PhaseEvents.TruthSteps(rec);
                foreach (var st in stepList)
                {
                    for (int k = 0; k < StepPoints; k++) step[k] += raw.Smv(st.Start + st.Duration * k / StepPoints);
                    steps++;
                    // Spread of a 0.5 s window ending at the step's end: what the gate will see.
                    double m = 0, m2 = 0;
                    for (int k = 0; k < 50; k++)
                    {
                        double v = raw.Smv(st.End - k * 0.01);
                        m += v;
                        m2 += v * v;
                    }
                    m /= 50;
                    walkingStd.Add(Math.Sqrt(Math.Max(0, m2 / 50 - m * m)));
                }

                // Strides: a left step followed directly by a right step.
                var onsets = PhaseEvents.TruthOnsets(rec);
                for (int i = 0; i + 1 < stepList.Count; i++)
                {
                    var a = stepList[i];
                    var b = stepList[i + 1];
                    if (a.Foot != Foot.Left || b.Foot != Foot.Right || Math.Abs(b.Start - a.End) > 1e-9) continue;
                    double t0 = a.Start, dur = b.End - a.Start;
                    var lat = new double[StridePoints];
                    double mean = 0;
                    for (int k = 0; k < StridePoints; k++)
                    {
                        lat[k] = raw.Lateral(t0 + dur * k / StridePoints);
                        mean += lat[k];
                    }
                    mean /= StridePoints;
                    for (int k = 0; k < StridePoints; k++) stride[k] += lat[k] - mean;
                    strides++;
                    offsetSum += (a.End - t0) / dur;
                    offsetCount++;
                    // Where each of the left foot's phases starts inside this stride.
                    var seen = new bool[GaitPhases.WalkingPhaseCount];
                    foreach (var o in onsets)
                    {
                        if (o.Foot != Foot.Left || o.Time <= t0 || o.Time >= t0 + dur || o.Phase == GaitPhase.Standing) continue;
                        int p = (int)o.Phase;
                        if (seen[p]) continue;
                        seen[p] = true;
                        onsetSums[p] += (o.Time - t0) / dur;
                        onsetCounts[p]++;
                    }
                }
            }
            if (steps < 4 || strides < 2)
                throw new InvalidOperationException($"Training data too small: {steps} steps and {strides} strides found (need 4 and 2); recordings need phase_left/phase_right labels with walking.");
            for (int k = 0; k < StepPoints; k++) step[k] /= steps;
            for (int k = 0; k < StridePoints; k++) stride[k] /= strides;

            PhaseMap map = PhaseMap.Perry;
            var learned = new double[GaitPhases.WalkingPhaseCount];
            bool complete = true;
            for (int p = 1; p < learned.Length; p++)
            {
                if (onsetCounts[p] == 0) complete = false;
                else learned[p] = onsetSums[p] / onsetCounts[p];
            }
            if (complete)
            {
                try
                {
                    map = new PhaseMap(learned, offsetCount > 0 ? offsetSum / offsetCount : 0.5);
                }
                catch (ArgumentException)
                {
                    map = PhaseMap.Perry;
                }
            }
            walkingStd.Sort();
            double p05 = walkingStd[(int)(0.05 * (walkingStd.Count - 1))];
            return new CorrelationTemplate(step, stride, map, 0.4 * p05, steps, strides);
        }

        public string Serialize()
        {
            var ci = CultureInfo.InvariantCulture;
            var sb = new StringBuilder();
            sb.Append(Magic).Append('\n');
            sb.Append("# steps_used=").Append(StepsUsed).Append(" strides_used=").Append(StridesUsed).Append('\n');
            sb.Append("phase_map=").Append(PhaseMap.Serialize()).Append('\n');
            sb.Append("min_walking_std=").Append(MinWalkingStd.ToString("R", ci)).Append('\n');
            sb.Append("step_smv=");
            for (int i = 0; i < StepSmv.Length; i++) sb.Append(i > 0 ? "," : "").Append(StepSmv[i].ToString("G9", ci));
            sb.Append('\n').Append("stride_lateral=");
            for (int i = 0; i < StrideLateral.Length; i++) sb.Append(i > 0 ? "," : "").Append(StrideLateral[i].ToString("G9", ci));
            sb.Append('\n');
            return sb.ToString();
        }

        public void Save(string path) => File.WriteAllText(path, Serialize(), new UTF8Encoding(false));

        public static CorrelationTemplate Load(string path) => Parse(File.ReadAllText(path));

        /// <summary>Reads a template written by <see cref="Serialize"/>; throws <see cref="FormatException"/> naming what is wrong.</summary>
        public static CorrelationTemplate Parse(string text)
        {
            if (text == null) throw new FormatException("Template text is missing.");
            var values = new Dictionary<string, string>();
            bool magic = false;
            foreach (var rawLine in text.Split('\n'))
            {
                string line = rawLine.Trim();
                if (line.Length == 0) continue;
                if (line == Magic) { magic = true; continue; }
                if (line.StartsWith("#", StringComparison.Ordinal)) continue;
                int eq = line.IndexOf('=');
                if (eq <= 0) throw new FormatException($"Template line without key=value: '{Shorten(line)}'");
                values[line.Substring(0, eq)] = line.Substring(eq + 1);
            }
            if (!magic) throw new FormatException($"Not a COR template (first line must be '{Magic}').");
            string Need(string key) => values.TryGetValue(key, out var v) ? v : throw new FormatException($"Template lacks '{key}'.");
            var ci = CultureInfo.InvariantCulture;
            double[] Numbers(string key, int count)
            {
                string[] parts = Need(key).Split(',');
                if (parts.Length != count) throw new FormatException($"Template '{key}' has {parts.Length} values, expected {count}.");
                var r = new double[count];
                for (int i = 0; i < count; i++)
                {
                    if (!double.TryParse(parts[i], NumberStyles.Float, ci, out r[i]) || !ImuSample.IsFiniteNumber(r[i]))
                        throw new FormatException($"Template '{key}' value {i} ('{parts[i]}') is not a finite number.");
                }
                return r;
            }
            var map = PhaseMap.Parse(Need("phase_map"));
            if (!double.TryParse(Need("min_walking_std"), NumberStyles.Float, ci, out double gate) || !(gate >= 0))
                throw new FormatException("Template 'min_walking_std' is not a non-negative number.");
            return new CorrelationTemplate(Numbers("step_smv", StepPoints), Numbers("stride_lateral", StridePoints), map, gate);
        }

        static string Shorten(string s) => s.Length > 40 ? s.Substring(0, 40) + "..." : s;
    }
}
