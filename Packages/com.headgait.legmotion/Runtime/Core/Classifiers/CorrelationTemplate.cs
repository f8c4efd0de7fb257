using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace HeadGait
{
    /// <summary>One mean step of COR: SMV minus gravity over a step and the lateral acceleration of a left step.</summary>
    public sealed class StepTemplate
    {
        public StepTemplate(double[] smv, double[] lateral, double contactLag, int steps)
        {
            if (smv == null || smv.Length != CorrelationTemplate.StepPoints) throw new ArgumentException($"A step template needs {CorrelationTemplate.StepPoints} points.");
            if (lateral == null || lateral.Length != CorrelationTemplate.StepPoints) throw new ArgumentException($"A lateral template needs {CorrelationTemplate.StepPoints} points.");
            foreach (var v in smv) if (!ImuSample.IsFiniteNumber(v)) throw new ArgumentException("The step template has a non-finite value.");
            foreach (var v in lateral) if (!ImuSample.IsFiniteNumber(v)) throw new ArgumentException("The lateral template has a non-finite value.");
            if (CorrelationTemplate.Spread(smv) < 1e-9) throw new ArgumentException("The step template is constant: nothing to correlate with.");
            if (!(Math.Abs(contactLag) < 0.5)) throw new ArgumentException("The contact lag must lie within 0.5 s.");
            Smv = (double[])smv.Clone();
            Lateral = (double[])lateral.Clone();
            ContactLag = contactLag;
            Steps = steps;
        }

        /// <summary>SMV minus gravity from one foot's initial contact to the other's, each step standardised before averaging.</summary>
        public double[] Smv { get; }

        /// <summary>Lateral acceleration over a left step (left contact to right contact), right steps mirrored in.</summary>
        public double[] Lateral { get; }

        /// <summary>Mean time from a true initial contact to the correlation peak that detects it with this template (s).</summary>
        public double ContactLag { get; }

        /// <summary>Training steps this template averages.</summary>
        public int Steps { get; }

        public StepTemplate WithLag(double lag) => new StepTemplate(Smv, Lateral, lag, Steps);
    }

    /// <summary>
    /// What COR learns from labelled recordings: a few mean steps (people step differently: a bouncy and a calm walker's
    /// head traces differ more than one mean can cover, so steps are clustered and each cluster averaged), the correlation
    /// a step must reach, the walking gate (<see cref="WalkingGate"/>), how far the stride clock must run ahead, and the
    /// phase map. Saved as text (<c># headgait-cor-template v2</c>).
    /// </summary>
    public sealed class CorrelationTemplate
    {
        public const int StepPoints = 100;
        public const string Magic = "# headgait-cor-template v2";

        /// <summary>The paper's rule: a window is a step when Pearson's r with the mean template exceeds 0.9.</summary>
        public const double PaperMinCorrelation = 0.9;

        /// <summary>Mean steps learned by default.</summary>
        public const int DefaultTemplateCount = 3;

        public CorrelationTemplate(IReadOnlyList<StepTemplate> templates, PhaseMap phaseMap, double minCorrelation, WalkingGate gate, double clockLead = 0,
            double leadPerLogBounce = 0, double leadReferenceBounce = StepClockSettings.DefaultLeadReferenceBounce, double walkingGateHoldShift = 0)
        {
            if (!(walkingGateHoldShift >= 0 && walkingGateHoldShift <= MaxWalkingGateHoldShift)) throw new ArgumentException($"The walking gate's hold shift must lie in 0..{MaxWalkingGateHoldShift} log-odds.");
            WalkingGateHoldShift = walkingGateHoldShift;
            if (templates == null || templates.Count < 1 || templates.Count > 16) throw new ArgumentException("COR needs 1 to 16 step templates.");
            if (!(minCorrelation > -1 && minCorrelation < 1)) throw new ArgumentException("The minimum correlation must lie in (-1, 1).");
            if (!(Math.Abs(clockLead) < 0.5)) throw new ArgumentException("The clock lead must lie within 0.5 s.");
            if (!(Math.Abs(leadPerLogBounce) <= StepClockSettings.MaxLeadPerLogBounce)) throw new ArgumentException($"The clock lead per log bounce must lie within {StepClockSettings.MaxLeadPerLogBounce} s.");
            if (!(leadReferenceBounce > 0 && leadReferenceBounce < 1000)) throw new ArgumentException("The clock lead's reference bounce must lie in (0, 1000) m/s^2.");
            Templates = new List<StepTemplate>(templates).AsReadOnly();
            PhaseMap = phaseMap ?? throw new ArgumentNullException(nameof(phaseMap));
            MinCorrelation = minCorrelation;
            Gate = gate ?? WalkingGate.Open;
            ClockLead = clockLead;
            LeadPerLogBounce = leadPerLogBounce;
            LeadReferenceBounce = leadReferenceBounce;
        }


        public IReadOnlyList<StepTemplate> Templates { get; }
        public PhaseMap PhaseMap { get; }
        public double MinCorrelation { get; }
        public WalkingGate Gate { get; }
        /// <summary>How far the stride clock reports ahead of itself (s; see <see cref="StepClockSettings.Lead"/>).</summary>
        public double ClockLead { get; }

        /// <summary>
        /// Seconds of clock lead added per unit of the natural log of the walker's bounce (SMV's peak over its matched
        /// steps, <see cref="CorrelationClassifier.WalkBounce"/>) above <see cref="LeadReferenceBounce"/>: a bouncier
        /// walker's contacts come out later. Learned by <see cref="CorrelationClassifier.Calibrate"/>; 0 keeps the lead fixed.
        /// </summary>
        public double LeadPerLogBounce { get; }

        /// <summary>The bounce (m/s^2) at which the lead is <see cref="ClockLead"/>: the training contacts' median.</summary>
        public double LeadReferenceBounce { get; }

        /// <summary>
        /// Log-odds by which the walking gate opens for a walk in progress only (it keeps a walk going, never starts one): a
        /// wearer's profile sets it where the ankle trackers showed the gate refusing their walking
        /// (<see cref="HeadGait.Calibration.AdaptationSettings.CorGate"/>); trained models 0.
        /// </summary>
        public double WalkingGateHoldShift { get; }

        /// <summary>Most <see cref="WalkingGateHoldShift"/> may be.</summary>
        public const double MaxWalkingGateHoldShift = 5;

        public int StepsUsed
        {
            get
            {
                int n = 0;
                foreach (var t in Templates) n += t.Steps;
                return n;
            }
        }

        public CorrelationTemplate With(double? minCorrelation = null, WalkingGate gate = null, double? clockLead = null, IReadOnlyList<StepTemplate> templates = null,
            double? leadPerLogBounce = null, double? leadReferenceBounce = null, double? walkingGateHoldShift = null)
            => new CorrelationTemplate(templates ?? Templates, PhaseMap, minCorrelation ?? MinCorrelation, gate ?? Gate, clockLead ?? ClockLead,
                leadPerLogBounce ?? LeadPerLogBounce, leadReferenceBounce ?? LeadReferenceBounce, walkingGateHoldShift ?? WalkingGateHoldShift);

        /// <summary>The same templates with every contact lag set to <paramref name="lag"/>.</summary>
        public CorrelationTemplate WithLag(double lag)
        {
            var t = new List<StepTemplate>();
            foreach (var s in Templates) t.Add(s.WithLag(lag));
            return With(templates: t);
        }

        /// <summary>A template curve at step fraction u in [0, 1] (linear interpolation, clamped).</summary>
        public static double At(double[] curve, double u)
        {
            double p = Math.Min(Math.Max(u, 0), 1) * (curve.Length - 1);
            int i = Math.Min((int)p, curve.Length - 2);
            return curve[i] + (p - i) * (curve[i + 1] - curve[i]);
        }

        internal static double Spread(double[] v)
        {
            double m = 0, s = 0;
            foreach (var x in v) m += x;
            m /= v.Length;
            foreach (var x in v) s += (x - m) * (x - m);
            return Math.Sqrt(s / v.Length);
        }

        /// <summary>
        /// Learns up to <paramref name="count"/> mean steps from labelled recordings by k-means over the standardised steps
        /// (deterministic: seeded with the steps furthest apart), with the given phase map and walking gate. The correlation
        /// threshold, lags and clock lead are set by calibration. Throws <see cref="InvalidOperationException"/> with fewer
        /// than 8 usable steps.
        /// </summary>
        public static CorrelationTemplate Train(IEnumerable<Recording> recordings, PhaseMap map, WalkingGate gate, int count = DefaultTemplateCount)
        {
            var smv = new List<double[]>();
            var lateral = new List<double[]>();
            foreach (var rec in recordings)
            {
                var raw = new RawSignal(rec);
                foreach (var st in PhaseEvents.TruthSteps(rec))
                {
                    var curve = new double[StepPoints];
                    for (int k = 0; k < StepPoints; k++) curve[k] = raw.Smv(st.Start + st.Duration * k / (StepPoints - 1));
                    if (!Standardise(curve)) continue;
                    var lat = new double[StepPoints];
                    double lm = 0;
                    for (int k = 0; k < StepPoints; k++) lm += lat[k] = raw.Lateral(st.Start + st.Duration * k / (StepPoints - 1));
                    lm /= StepPoints;
                    double sign = st.Foot == Foot.Left ? 1 : -1;
                    for (int k = 0; k < StepPoints; k++) lat[k] = sign * (lat[k] - lm);
                    smv.Add(curve);
                    lateral.Add(lat);
                }
            }
            if (smv.Count < 8)
                throw new InvalidOperationException($"Training data too small: {smv.Count} steps found (need 8); recordings need phase_left/phase_right labels with walking.");
            var assignment = Cluster(smv, Math.Max(1, Math.Min(count, smv.Count / 50 + 1)));
            var templates = new List<StepTemplate>();
            for (int c = 0; c <= Max(assignment); c++)
            {
                var s = new double[StepPoints];
                var l = new double[StepPoints];
                int n = 0;
                for (int i = 0; i < smv.Count; i++)
                {
                    if (assignment[i] != c) continue;
                    for (int k = 0; k < StepPoints; k++)
                    {
                        s[k] += smv[i][k];
                        l[k] += lateral[i][k];
                    }
                    n++;
                }
                if (n == 0) continue;
                for (int k = 0; k < StepPoints; k++)
                {
                    s[k] /= n;
                    l[k] /= n;
                }
                templates.Add(new StepTemplate(s, l, 0, n));
            }
            templates.Sort((a, b) => b.Steps.CompareTo(a.Steps));
            return new CorrelationTemplate(templates, map, 0.5, gate);
        }

        static bool Standardise(double[] v)
        {
            double spread = Spread(v);
            if (spread < 1e-6) return false;
            double mean = 0;
            foreach (var x in v) mean += x;
            mean /= v.Length;
            for (int i = 0; i < v.Length; i++) v[i] = (v[i] - mean) / spread;
            return true;
        }

        static int Max(int[] v)
        {
            int m = 0;
            foreach (var x in v) m = Math.Max(m, x);
            return m;
        }

        /// <summary>k-means on standardised curves, seeded with the mean's furthest curve and then the furthest from those chosen.</summary>
        static int[] Cluster(List<double[]> curves, int k)
        {
            int n = curves.Count, d = StepPoints;
            var centres = new List<double[]>();
            var mean = new double[d];
            foreach (var c in curves) for (int j = 0; j < d; j++) mean[j] += c[j] / n;
            var nearest = new double[n];
            for (int i = 0; i < n; i++) nearest[i] = Distance(curves[i], mean);
            while (centres.Count < k)
            {
                int far = 0;
                for (int i = 1; i < n; i++) if (nearest[i] > nearest[far]) far = i;
                var centre = (double[])curves[far].Clone();
                centres.Add(centre);
                for (int i = 0; i < n; i++) nearest[i] = centres.Count == 1 ? Distance(curves[i], centre) : Math.Min(nearest[i], Distance(curves[i], centre));
            }
            var assignment = new int[n];
            for (int iter = 0; iter < 30; iter++)
            {
                bool changed = false;
                for (int i = 0; i < n; i++)
                {
                    int best = 0;
                    for (int c = 1; c < k; c++) if (Distance(curves[i], centres[c]) < Distance(curves[i], centres[best])) best = c;
                    changed |= best != assignment[i];
                    assignment[i] = best;
                }
                for (int c = 0; c < k; c++)
                {
                    var sum = new double[d];
                    int m = 0;
                    for (int i = 0; i < n; i++)
                    {
                        if (assignment[i] != c) continue;
                        for (int j = 0; j < d; j++) sum[j] += curves[i][j];
                        m++;
                    }
                    if (m == 0) continue;
                    for (int j = 0; j < d; j++) centres[c][j] = sum[j] / m;
                }
                if (!changed && iter > 0) break;
            }
            // Clusters of under 5 % of the steps join their nearest neighbour: too few steps for a stable mean.
            var sizes = new int[k];
            foreach (var a in assignment) sizes[a]++;
            var map = new int[k];
            int next = 0;
            for (int c = 0; c < k; c++) map[c] = sizes[c] >= 0.05 * n ? next++ : -1;
            for (int i = 0; i < n; i++)
            {
                if (map[assignment[i]] >= 0) continue;
                int best = -1;
                for (int c = 0; c < k; c++)
                    if (map[c] >= 0 && (best < 0 || Distance(curves[i], centres[c]) < Distance(curves[i], centres[best]))) best = c;
                assignment[i] = best < 0 ? 0 : best;
            }
            for (int i = 0; i < n; i++) assignment[i] = map[assignment[i]] >= 0 ? map[assignment[i]] : 0;
            return assignment;
        }

        static double Distance(double[] a, double[] b)
        {
            double s = 0;
            for (int j = 0; j < a.Length; j++) s += (a[j] - b[j]) * (a[j] - b[j]);
            return s;
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
            var pairs = new List<KeyValuePair<string, string>>
            {
                new KeyValuePair<string, string>("phase_map", PhaseMap.Serialize()),
                new KeyValuePair<string, string>("min_correlation", MinCorrelation.ToString("R", ci)),
                new KeyValuePair<string, string>("walking_gate", Gate.Serialize()),
                new KeyValuePair<string, string>("clock_lead", ClockLead.ToString("R", ci)),
                new KeyValuePair<string, string>("clock_lead_per_log_bounce", LeadPerLogBounce.ToString("R", ci)),
                new KeyValuePair<string, string>("clock_lead_reference_bounce", LeadReferenceBounce.ToString("R", ci)),
                new KeyValuePair<string, string>("templates", Templates.Count.ToString(ci)),
            };
            // Written only when set (a wearer's profile), so that trained templates read as before.
            if (WalkingGateHoldShift != 0) pairs.Insert(pairs.Count - 1, new KeyValuePair<string, string>("walking_gate_hold_shift", WalkingGateHoldShift.ToString("R", ci)));
            for (int k = 0; k < Templates.Count; k++)
            {
                var t = Templates[k];
                pairs.Add(new KeyValuePair<string, string>($"steps.{k}", t.Steps.ToString(ci)));
                pairs.Add(new KeyValuePair<string, string>($"contact_lag.{k}", t.ContactLag.ToString("R", ci)));
                pairs.Add(new KeyValuePair<string, string>($"step_smv.{k}", Join(t.Smv)));
                pairs.Add(new KeyValuePair<string, string>($"step_lateral.{k}", Join(t.Lateral)));
            }
            return KeyValueText.Write(Magic, pairs);
        }

        public void Save(string path) => AtomicFile.WriteAllText(path, Serialize());

        public static CorrelationTemplate Load(string path) => Parse(InputLimits.ReadAllText(path, InputLimits.MaxTextModelBytes, "a text model file"), path);

        /// <summary>Reads a template written by <see cref="Serialize"/>; throws <see cref="FormatException"/> naming the source and the key.</summary>
        public static CorrelationTemplate Parse(string text, string source = "COR template")
        {
            var kv = KeyValueText.Parse(text, Magic, source);
            var map = kv.PhaseMap("phase_map");
            double minR = kv.Number("min_correlation", -0.999, 0.999);
            var gate = kv.Gate("walking_gate");
            double lead = kv.Number("clock_lead", -0.49, 0.49, 0);
            double leadPerLogBounce = kv.Number("clock_lead_per_log_bounce", -StepClockSettings.MaxLeadPerLogBounce, StepClockSettings.MaxLeadPerLogBounce, 0);
            double leadReferenceBounce = kv.Number("clock_lead_reference_bounce", 1e-6, 999, StepClockSettings.DefaultLeadReferenceBounce);
            double holdShift = kv.Number("walking_gate_hold_shift", 0, MaxWalkingGateHoldShift, 0);
            int count = (int)kv.Number("templates", 1, 16);
            var templates = new List<StepTemplate>();
            for (int k = 0; k < count; k++)
            {
                var smv = kv.Numbers($"step_smv.{k}", StepPoints, -1e6, 1e6);
                if (Spread(smv) < 1e-9) throw new FormatException($"{source}: 'step_smv.{k}' is constant: nothing to correlate with");
                templates.Add(new StepTemplate(smv, kv.Numbers($"step_lateral.{k}", StepPoints, -1e6, 1e6),
                    kv.Number($"contact_lag.{k}", -0.49, 0.49), (int)kv.Number($"steps.{k}", 0, int.MaxValue, 0)));
            }
            return new CorrelationTemplate(templates, map, minR, gate, lead, leadPerLogBounce, leadReferenceBounce, holdShift);
        }
    }
}
