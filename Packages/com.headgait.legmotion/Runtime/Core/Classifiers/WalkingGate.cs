using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;

namespace HeadGait
{
    /// <summary>
    /// A learned walking/standing gate for THR and COR: logistic regression on how much the head moves in the newest
    /// 0.5 s (log spread of SMV, of the vertical, lateral and forward acceleration, and of SMV's sample-to-sample change)
    /// and how level it is (mean vertical specific force over g: bowing tips it far forward). Gestures move the head
    /// sideways and forwards, walking bounces it up and down at step frequency with sharp heel strikes; a threshold on
    /// SMV alone (or a fixed correlation) confuses waving with calm walking. The last input is SMV's autocorrelation over
    /// the newest second at a lag of 0.25 s, half a step: walking swings to the opposite side of its bounce by then, while
    /// bowing and waving (slower) and hopping on the spot (about 4 Hz) are still on the same side. Leave-one-style-out
    /// (`headgait benchmark`): standing shown as walking THR 4.9 to 3.3 %, COR 7.7 to 5.9 %, SVM 5.0 to 4.5 %, BLSTM 2.9
    /// to 2.0 %; a fit on the real windows found no such gain over 0.5 s.
    /// </summary>
    public sealed class WalkingGate
    {
        public const int FeatureCount = 7;
        const int Samples = 50;

        /// <summary>History the gate reads (grid samples at 100 Hz): the autocorrelation's second.</summary>
        public const int HistorySamples = 100;

        /// <summary>The autocorrelation's lag (s).</summary>
        public const double HalfStepLag = 0.25;
        const double Epsilon = 0.01;

        readonly double[] weights; // FeatureCount weights, then the bias
        readonly double[] features = new double[FeatureCount];

        public WalkingGate(double[] weights)
        {
            if (weights == null || weights.Length != FeatureCount + 1) throw new ArgumentException($"A walking gate has {FeatureCount + 1} weights.");
            foreach (var w in weights)
                if (!ImuSample.IsFiniteNumber(w) || Math.Abs(w) > 1e4) throw new ArgumentException("Walking gate weights must be finite and below 1e4.");
            this.weights = (double[])weights.Clone();
        }

        /// <summary>Lets everything through (no gate).</summary>
        public static WalkingGate Open { get; } = new WalkingGate(new double[] { 0, 0, 0, 0, 0, 0, 0, 1 });

        public double[] Weights => (double[])weights.Clone();

        /// <summary>Log-odds that the window's newest 0.5 s is walking; positive passes.</summary>
        public double Score(SignalWindow window)
        {
            Features(window, features);
            double z = weights[FeatureCount];
            for (int i = 0; i < FeatureCount; i++) z += weights[i] * features[i];
            return z;
        }

        public bool Passes(SignalWindow window) => Score(window) > 0;

        /// <summary>The gate's inputs for the newest 50 samples (or fewer right after a restart).</summary>
        public static void Features(SignalWindow w, double[] f)
        {
            int n = Math.Min(Samples, Math.Min(w.Count, w.Length));
            int first = w.Length - n;
            f[0] = LogSpread(w.Smv, first, n);
            f[1] = LogSpread(w.Vertical, first, n);
            f[2] = LogSpread(w.Lateral, first, n);
            f[3] = LogSpread(w.Forward, first, n);
            double d = 0;
            for (int i = first + 1; i < first + n; i++) d += Math.Abs(w.Smv[i] - w.Smv[i - 1]);
            f[4] = Math.Log(d / Math.Max(1, n - 1) + Epsilon);
            double up = 0;
            for (int i = first; i < first + n; i++) up += w.Vertical[i];
            f[5] = n > 0 ? up / n / StandardGravity : 1;
            f[6] = Autocorrelation(w, (int)Math.Round(HalfStepLag * w.SampleRate));
        }

        /// <summary>SMV's autocorrelation (mean removed) at <paramref name="lag"/> over the newest second; 0 when it is flat or too short.</summary>
        static double Autocorrelation(SignalWindow w, int lag)
        {
            int n = Math.Min((int)Math.Round(HistorySamples * w.SampleRate / 100), Math.Min(w.Count, w.Length));
            if (lag < 1 || n < 2 * lag) return 0;
            int first = w.Length - n;
            double m = 0;
            for (int i = first; i < first + n; i++) m += w.Smv[i];
            m /= n;
            double ss = 0, lagged = 0;
            for (int i = first; i < first + n; i++)
            {
                double a = w.Smv[i] - m;
                ss += a * a;
                if (i + lag < first + n) lagged += a * (w.Smv[i + lag] - m);
            }
            return ss > 1e-9 ? lagged / ss : 0;
        }

        const double StandardGravity = 9.80665;

        static double LogSpread(double[] v, int first, int n)
        {
            if (n < 2) return Math.Log(Epsilon);
            double m = 0, m2 = 0;
            for (int i = first; i < first + n; i++)
            {
                m += v[i];
                m2 += v[i] * v[i];
            }
            m /= n;
            return Math.Log(Math.Sqrt(Math.Max(0, m2 / n - m * m)) + Epsilon);
        }

        /// <summary>Reads weights as <see cref="Serialize"/> writes them; a <see cref="FormatException"/> says what is wrong.</summary>
        public static WalkingGate Parse(string text)
        {
            var parts = (text ?? "").Split(',');
            if (parts.Length != FeatureCount + 1 && parts.Length != FeatureCount)
                throw new FormatException($"a walking gate has {FeatureCount + 1} comma-separated weights, found {parts.Length}");
            var w = new double[parts.Length];
            for (int i = 0; i < parts.Length; i++)
                if (!double.TryParse(parts[i].Trim(), NumberStyles.Float, CultureInfo.InvariantCulture, out w[i]) || !ImuSample.IsFiniteNumber(w[i]) || Math.Abs(w[i]) > 1e4)
                    throw new FormatException($"walking gate weight {i + 1} is '{parts[i].Trim()}', not a finite number below 1e4");
            return FromWeights(w);
        }

        /// <summary>
        /// A gate from its weights as written: <see cref="FeatureCount"/> and the bias, or one fewer from a model written
        /// before the autocorrelation input, which then weighs nothing and the gate decides as it did.
        /// </summary>
        public static WalkingGate FromWeights(double[] w)
        {
            if (w == null || w.Length != FeatureCount) return new WalkingGate(w);
            var full = new double[FeatureCount + 1];
            Array.Copy(w, full, FeatureCount - 1);
            full[FeatureCount] = w[FeatureCount - 1];
            return new WalkingGate(full);
        }

        public string Serialize()
        {
            var sb = new StringBuilder();
            for (int i = 0; i < weights.Length; i++) sb.Append(i > 0 ? "," : "").Append(weights[i].ToString("R", CultureInfo.InvariantCulture));
            return sb.ToString();
        }

        /// <summary>
        /// Share of walking windows THR's and COR's gate lets through. From leave-one-style-out cross-validation of COR: 0.99
        /// let 14 % of gesturing show as walking, 0.97 7.6 % (misclassification 28.0 to 27.5 %), 0.94 5.6 % but step recall
        /// fell under 95 %.
        /// </summary>
        public const double DetectorPass = 0.97;

        /// <summary>
        /// Share of walking windows the SVM's and BLSTM's gate lets through: they have a standing class of their own, so
        /// their gate only keeps out the gesturing they mistake for walking. From leave-one-style-out cross-validation:
        /// without a gate 14.8 % (SVM) and 5.8 % (BLSTM) of standing showed as walking; 0.97 cut that to 3.9 and 2.2 % but
        /// step recall fell to 95.8 and 94.5 %; 0.985 gives 5.0 and 2.9 % (gestures of the first corpus 1.5 and 1.1 %)
        /// with recall 97.3 and 96.0 % and lower misclassification (23.5 to 22.0 %, 18.2 to 17.8 %).
        /// </summary>
        public const double LearnedPass = 0.985;

        /// <summary>The model-file key that holds a learned classifier's gate (<see cref="Serialize"/>).</summary>
        public const string ModelKey = "walking_gate";

        /// <summary>
        /// Fits the gate on windows of labelled recordings (every 5th window; walking = the newest sample is labelled
        /// walking), both classes weighted equally, then sets the bias so that <paramref name="walkingPass"/> of the walking
        /// windows pass: the gate only has to keep out what clearly is not walking; the classifiers decide the rest.
        /// Throws <see cref="InvalidOperationException"/> without both classes.
        /// </summary>
        public static WalkingGate Train(IEnumerable<Recording> recordings, double walkingPass = DetectorPass)
            => TrainEach(recordings, new[] { walkingPass })[0];

        /// <summary>
        /// One gate per share in <paramref name="walkingPasses"/>, from one fit: the gates differ only in their bias, so the
        /// classifiers that pass different shares of walking (<see cref="DetectorPass"/>, <see cref="LearnedPass"/>) need the
        /// windows read and the regression solved once.
        /// </summary>
        public static WalkingGate[] TrainEach(IEnumerable<Recording> recordings, IReadOnlyList<double> walkingPasses)
        {
            var walking = new List<double[]>();
            var standing = new List<double[]>();
            foreach (var rec in recordings)
            {
                if (!rec.HasTruth) continue;
                var pre = new StreamPreprocessor(new PreprocessorSettings { History = HistorySamples });
                int row = -1;
                long count = 0;
                var rows = rec.Samples;
                foreach (var s in rows)
                {
                    pre.Push(s.Imu, w =>
                    {
                        if (count++ % 5 != 0) return;
                        while (row + 1 < rows.Count && rows[row + 1].Imu.Time <= w.EndTime + 1e-9) row++;
                        if (row < 0 || !rows[row].HasTruth) return;
                        var f = new double[FeatureCount];
                        Features(w, f);
                        (rows[row].Left == GaitPhase.Standing ? standing : walking).Add(f);
                    });
                }
            }
            if (walking.Count < 20 || standing.Count < 20)
                throw new InvalidOperationException($"The walking gate needs walking and standing windows: found {walking.Count} and {standing.Count}.");
            var w8 = Fit(walking, standing);
            var scores = new List<double>();
            foreach (var f in walking)
            {
                double z = 0;
                for (int i = 0; i < FeatureCount; i++) z += w8[i] * f[i];
                scores.Add(z);
            }
            scores.Sort();
            var gates = new WalkingGate[walkingPasses.Count];
            for (int g = 0; g < gates.Length; g++)
            {
                w8[FeatureCount] = -scores[(int)Math.Floor((1 - walkingPasses[g]) * (scores.Count - 1))] + 1e-9;
                gates[g] = new WalkingGate(w8); // copies the weights
            }
            return gates;
        }

        /// <summary>Balanced logistic regression by Newton's method (a 6x6 system), with a small ridge for stability.</summary>
        static double[] Fit(List<double[]> positive, List<double[]> negative)
        {
            int d = FeatureCount + 1;
            var w = new double[d];
            double wp = 0.5 / positive.Count, wn = 0.5 / negative.Count;
            for (int iter = 0; iter < 30; iter++)
            {
                var g = new double[d];
                var h = new double[d, d];
                void Add(double[] f, double y, double weight)
                {
                    double z = w[d - 1];
                    for (int i = 0; i < d - 1; i++) z += w[i] * f[i];
                    double p = 1 / (1 + Math.Exp(-z));
                    double r = weight * (p - y), s = weight * p * (1 - p);
                    for (int i = 0; i < d; i++)
                    {
                        double fi = i < d - 1 ? f[i] : 1;
                        g[i] += r * fi;
                        for (int j = 0; j < d; j++) h[i, j] += s * fi * (j < d - 1 ? f[j] : 1);
                    }
                }
                foreach (var f in positive) Add(f, 1, wp);
                foreach (var f in negative) Add(f, 0, wn);
                for (int i = 0; i < d; i++)
                {
                    g[i] += 1e-4 * w[i];
                    h[i, i] += 1e-4;
                }
                var step = Solve(h, g);
                double change = 0;
                for (int i = 0; i < d; i++)
                {
                    w[i] -= step[i];
                    change += Math.Abs(step[i]);
                }
                if (change < 1e-8) break;
            }
            return w;
        }

        static double[] Solve(double[,] a, double[] b)
        {
            int n = b.Length;
            var m = (double[,])a.Clone();
            var x = (double[])b.Clone();
            for (int c = 0; c < n; c++)
            {
                int pivot = c;
                for (int r = c + 1; r < n; r++) if (Math.Abs(m[r, c]) > Math.Abs(m[pivot, c])) pivot = r;
                for (int k = 0; k < n; k++) (m[c, k], m[pivot, k]) = (m[pivot, k], m[c, k]);
                (x[c], x[pivot]) = (x[pivot], x[c]);
                double diag = m[c, c];
                if (Math.Abs(diag) < 1e-12) continue;
                for (int r = 0; r < n; r++)
                {
                    if (r == c) continue;
                    double f = m[r, c] / diag;
                    for (int k = c; k < n; k++) m[r, k] -= f * m[c, k];
                    x[r] -= f * x[c];
                }
            }
            for (int i = 0; i < n; i++) x[i] = Math.Abs(m[i, i]) < 1e-12 ? 0 : x[i] / m[i, i];
            return x;
        }
    }
}
