using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;

namespace HeadGait
{
    /// <summary>
    /// A learned walking/standing gate for THR and COR (and the SVM's and BLSTM's): logistic regression on how much the
    /// head moves in the newest 0.5 s (log spread of SMV, of the vertical, lateral and forward acceleration, and of SMV's
    /// sample-to-sample change), how level it is (mean vertical specific force over g: bowing tips it far forward) and
    /// SMV's autocorrelation over the newest second at a lag of 0.25 s, half a step: walking swings to the opposite side
    /// of its bounce by then, while bowing and waving (slower) and hopping on the spot (about 4 Hz) are still on the same
    /// side. The regression reads these seven features and the pairwise products of three of them (<see cref="Multiplied"/>),
    /// so it can also refuse a head that swings too hard sideways or forwards: a child's wave swings the head sideways
    /// four times as hard as a walk, and a gate linear in the features took more movement for more walking. Gestures move
    /// the head sideways and forwards, walking bounces it up and down at step frequency with sharp heel strikes; a
    /// threshold on SMV alone (or a fixed correlation) confuses waving with calm walking. A gate may also pass what its
    /// regression refuses when the newest 2.5 s keep a walking rhythm (<see cref="UsesStepRhythm"/>, <see cref="StepRhythm"/>).
    /// </summary>
    public sealed class WalkingGate
    {
        /// <summary>Features measured per window (<see cref="Features"/>).</summary>
        public const int FeatureCount = 7;

        /// <summary>
        /// Features whose pairwise products the regression also weighs: the lateral and forward spreads (as spreads in
        /// m/s^2, not logs) and the autocorrelation. Products of spreads grow with a swing that is too large but vanish for
        /// a calm one (squares of log spreads also grew for a walker calmer than any in training, and refused the generated
        /// walker at half its amplitude); products with SMV's and the vertical spread let the calm hand-waving of the
        /// *active* style through with that style held out.
        /// </summary>
        static readonly int[] Multiplied = { 2, 3, 6 };
        static readonly int MultipliedCount = Multiplied.Length;

        /// <summary>The regression's inputs: the features, then each product of two <see cref="Multiplied"/> ones (i &lt;= j).</summary>
        public static readonly int InputCount = FeatureCount + MultipliedCount * (MultipliedCount + 1) / 2;

        /// <summary>Features that are log spreads (the first five); the products read them as spreads.</summary>
        const int LogSpreads = 5;

        /// <summary>Weights a gate has: one per input, then the bias.</summary>
        public static readonly int WeightCount = InputCount + 1;
        const int Samples = 50;

        /// <summary>History the gate reads (grid samples at 100 Hz): the autocorrelation's second.</summary>
        public const int HistorySamples = 100;

        /// <summary>The autocorrelation's lag (s).</summary>
        public const double HalfStepLag = 0.25;
        const double Epsilon = 0.01;

        readonly double[] weights; // InputCount weights, then the bias
        readonly double? levelTolerance;
        readonly bool usesStepRhythm;
        // Scratch per thread, not per gate: one gate is shared by every classifier made from the same model, and those
        // may run on several threads at once (parallel replays); per-gate buffers let their windows overwrite each other.
        [ThreadStatic] static double[] features, inputs;

        /// <param name="levelTolerance">Tilt (degrees) beyond which the spreads are read from a levelled window (<see cref="Features"/>); null: as the head frame gives them.</param>
        /// <param name="usesStepRhythm">Also pass a window that keeps a walking rhythm (<see cref="HeadGait.StepRhythm"/>) whatever its score.</param>
        public WalkingGate(double[] weights, double? levelTolerance = null, bool usesStepRhythm = false)
        {
            if (weights == null || weights.Length != WeightCount) throw new ArgumentException($"A walking gate has {WeightCount} weights.");
            foreach (var w in weights)
                if (!ImuSample.IsFiniteNumber(w) || Math.Abs(w) > 1e4) throw new ArgumentException("Walking gate weights must be finite and below 1e4.");
            if (levelTolerance.HasValue && !WindowLevel.IsTolerance(levelTolerance.Value)) throw new ArgumentException("A walking gate's levelling tolerance is 0..90 degrees.");
            this.weights = (double[])weights.Clone();
            this.levelTolerance = levelTolerance;
            this.usesStepRhythm = usesStepRhythm;
        }

        /// <summary>
        /// Whether a window the regression refuses still passes when the newest 2.5 s keep a walking rhythm
        /// (<see cref="HeadGait.StepRhythm"/>): a calm, slow walker moves the head as little as a gesture does.
        /// </summary>
        public bool UsesStepRhythm => usesStepRhythm;

        /// <summary>This gate, also passing windows that keep a walking rhythm.</summary>
        public WalkingGate WithStepRhythm() => new WalkingGate(weights, levelTolerance, true);

        /// <summary>Samples of history (at 100 Hz) the gate reads: a second, or the rhythm's 2.5 s.</summary>
        public int History => usesStepRhythm ? Math.Max(HistorySamples, StepRhythm.HistorySamples) : HistorySamples;

        /// <summary>Tilt (degrees) beyond which the gate reads its spreads from a levelled window; null: never levelled.</summary>
        public double? LevelTolerance => levelTolerance;

        /// <summary>Lets everything through (no gate).</summary>
        public static WalkingGate Open { get; } = Linear(new double[FeatureCount], 1);

        public double[] Weights => (double[])weights.Clone();

        /// <summary>Log-odds that the window's newest 0.5 s is walking; positive passes.</summary>
        public double Score(SignalWindow window)
        {
            var features = WalkingGate.features ?? (WalkingGate.features = new double[FeatureCount]);
            var inputs = WalkingGate.inputs ?? (WalkingGate.inputs = new double[InputCount]);
            Features(window, features, levelTolerance);
            FillInputs(features, inputs);
            return LogOdds(weights, inputs);
        }

        /// <summary>The log-odds weights <paramref name="w"/> give inputs <paramref name="x"/> (<see cref="InputCount"/> of them).</summary>
        static double LogOdds(double[] w, double[] x)
        {
            double z = w[InputCount];
            for (int i = 0; i < InputCount; i++) z += w[i] * x[i];
            return z;
        }

        /// <summary>Feature <paramref name="i"/> as the products read it: a spread for the log spreads, else as measured.</summary>
        static double ProductInput(double[] f, int i) => i < LogSpreads ? Math.Exp(f[i]) : f[i];

        /// <summary>The regression's inputs for features <paramref name="f"/>, into <paramref name="x"/>: the features, then the products.</summary>
        static void FillInputs(double[] f, double[] x)
        {
            Array.Copy(f, x, FeatureCount);
            Span<double> g = stackalloc double[MultipliedCount];
            for (int i = 0; i < MultipliedCount; i++) g[i] = ProductInput(f, Multiplied[i]);
            int k = FeatureCount;
            for (int i = 0; i < MultipliedCount; i++)
                for (int j = i; j < MultipliedCount; j++) x[k++] = g[i] * g[j];
        }

        /// <summary>Whether the window counts as walking: a positive score, or a walking rhythm where the gate listens for one.</summary>
        public bool Passes(SignalWindow window) => Passes(window, out _);

        /// <summary><see cref="Passes(SignalWindow)"/>, also giving the regression's log-odds (<see cref="Score"/>).</summary>
        public bool Passes(SignalWindow window, out double logOdds)
        {
            logOdds = Score(window);
            return ScorePasses(logOdds) || (usesStepRhythm && StepRhythm.Of(window, levelTolerance).IsWalking);
        }

        /// <summary>Whether a window of log-odds <paramref name="logOdds"/> (<see cref="Score"/>, plus any opening a wearer's profile adds) passes on its score.</summary>
        public static bool ScorePasses(double logOdds) => logOdds > 0;

        /// <summary>
        /// The gate's inputs for the newest 50 samples (or fewer right after a restart). With <paramref name="levelTolerance"/>
        /// the vertical, lateral and forward spreads come from the window levelled over its second (<see cref="WindowLevel"/>):
        /// a head looking down at its legs otherwise swings its forward channel with the bounce, as a bow does. The mean
        /// vertical stays as the head frame gives it, since a bow's tilt is what tells it from a walk.
        /// </summary>
        public static void Features(SignalWindow w, double[] f, double? levelTolerance = null)
        {
            int n = Math.Min(Samples, Math.Min(w.Count, w.Length));
            int first = w.Length - n;
            var level = levelTolerance.HasValue ? WindowLevel.Of(w, w.Length - HistoryCount(w), levelTolerance.Value) : WindowLevel.None;
            f[0] = LogSpread(w, level, WindowChannel.Smv, first, n);
            f[1] = LogSpread(w, level, WindowChannel.Vertical, first, n);
            f[2] = LogSpread(w, level, WindowChannel.Lateral, first, n);
            f[3] = LogSpread(w, level, WindowChannel.Forward, first, n);
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
            int n = HistoryCount(w);
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

        /// <summary>Valid samples of the second the gate reads (its autocorrelation and levelling), at the window's rate.</summary>
        static int HistoryCount(SignalWindow w) => Math.Min((int)Math.Round(HistorySamples * w.SampleRate / 100), Math.Min(w.Count, w.Length));

        static double LogSpread(SignalWindow w, in WindowLevel level, WindowChannel channel, int first, int n)
        {
            if (n < 2) return Math.Log(Epsilon);
            double m = 0, m2 = 0;
            for (int i = first; i < first + n; i++)
            {
                double v = level.Read(w, channel, i);
                m += v;
                m2 += v * v;
            }
            m /= n;
            return Math.Log(Math.Sqrt(Math.Max(0, m2 / n - m * m)) + Epsilon);
        }

        /// <summary>What a levelling gate's text starts with: <c>level:15;</c> then the weights.</summary>
        const string LevelPrefix = "level:";

        /// <summary>What a gate that listens for the step rhythm has before its weights.</summary>
        const string RhythmOption = "rhythm;";

        /// <summary>Reads a gate as <see cref="Serialize"/> writes it; a <see cref="FormatException"/> says what is wrong.</summary>
        public static WalkingGate Parse(string text)
        {
            text = text ?? "";
            double? level = null;
            bool rhythm = false;
            if (text.StartsWith(LevelPrefix, StringComparison.Ordinal))
            {
                int end = text.IndexOf(';');
                string value = end < 0 ? text.Substring(LevelPrefix.Length) : text.Substring(LevelPrefix.Length, end - LevelPrefix.Length);
                if (end < 0 || !WindowLevel.TryParseTolerance(value, out double tolerance))
                    throw new FormatException($"walking gate levelling '{value}' is not a tilt of 0..90 degrees followed by ';' and the weights");
                level = tolerance;
                text = text.Substring(end + 1);
            }
            if (text.StartsWith(RhythmOption, StringComparison.Ordinal))
            {
                rhythm = true;
                text = text.Substring(RhythmOption.Length);
            }
            var parts = text.Split(',');
            if (parts.Length != WeightCount && Array.IndexOf(OlderLengths(), parts.Length) < 0)
                throw new FormatException($"a walking gate has {WeightCount} comma-separated weights (expected {WeightCount}, or {LinearWeightCount} or {LinearWeightCount - 1} from an older model), found {parts.Length}");
            var w = new double[parts.Length];
            for (int i = 0; i < parts.Length; i++)
                if (!double.TryParse(parts[i].Trim(), NumberStyles.Float, CultureInfo.InvariantCulture, out w[i]) || !ImuSample.IsFiniteNumber(w[i]) || Math.Abs(w[i]) > 1e4)
                    throw new FormatException($"walking gate weight {i + 1} is '{parts[i].Trim()}', not a finite number below 1e4");
            return FromWeights(w, level, rhythm);
        }

        /// <summary>Weights of a gate written before the pairwise products: the seven features and the bias.</summary>
        public const int LinearWeightCount = FeatureCount + 1;

        /// <summary>Shorter weight lists older models hold: the linear gate's, and the linear gate's before the autocorrelation input.</summary>
        public static int[] OlderLengths() => new[] { LinearWeightCount, LinearWeightCount - 1 };

        /// <summary>
        /// A gate from its weights as written (<see cref="WeightCount"/> or one of <see cref="OlderLengths"/>). An older linear gate weighs no products, and
        /// one written before the autocorrelation input weighs that at nothing: either decides as it did.
        /// </summary>
        public static WalkingGate FromWeights(double[] w, double? levelTolerance = null, bool usesStepRhythm = false)
        {
            if (w == null || w.Length == WeightCount) return new WalkingGate(w, levelTolerance, usesStepRhythm);
            if (w.Length != LinearWeightCount && w.Length != LinearWeightCount - 1) return new WalkingGate(w); // refused, naming the count
            var linear = new double[FeatureCount];
            Array.Copy(w, linear, w.Length - 1);
            return Linear(linear, w[w.Length - 1], levelTolerance, usesStepRhythm);
        }

        static WalkingGate Linear(double[] featureWeights, double bias, double? levelTolerance = null, bool usesStepRhythm = false)
        {
            var full = new double[WeightCount];
            Array.Copy(featureWeights, full, FeatureCount);
            full[InputCount] = bias;
            return new WalkingGate(full, levelTolerance, usesStepRhythm);
        }

        public string Serialize()
        {
            var sb = new StringBuilder();
            if (levelTolerance.HasValue) sb.Append(LevelPrefix).Append(levelTolerance.Value.ToString("R", CultureInfo.InvariantCulture)).Append(';');
            if (usesStepRhythm) sb.Append(RhythmOption);
            for (int i = 0; i < weights.Length; i++) sb.Append(i > 0 ? "," : "").Append(weights[i].ToString("R", CultureInfo.InvariantCulture));
            return sb.ToString();
        }

        /// <summary>
        /// Share of walking windows THR's and COR's gates let through. From leave-one-style-out cross-validation of COR: 0.99
        /// let 14 % of gesturing show as walking, 0.97 7.6 % (misclassification 28.0 to 27.5 %), 0.94 5.6 % but step recall
        /// fell under 95 %.
        /// </summary>
        public const double DetectorPass = 0.97;

        /// <summary>
        /// Share of walking windows the SVM's and BLSTM's gate lets through: they have a standing class of their own, so
        /// their gate only keeps out the gesturing they mistake for walking. From leave-one-style-out cross-validation:
        /// without a gate 14.8 % (SVM) and 5.8 % (BLSTM) of standing showed as walking. With the linear gate, 0.97 cut that
        /// to 3.9 and 2.2 % but step recall fell to 95.8 and 94.5 %, so 0.985 was used. With the products, 0.98 instead of
        /// 0.985 shows 1.9 instead of 2.2 % (SVM) and 1.0 instead of 1.1 % (BLSTM) of standing as walking, at step recall
        /// 96.5 instead of 96.6 % and 96.1 instead of 96.2 %, with the same misclassification.
        /// </summary>
        public const double LearnedPass = 0.98;

        /// <summary>The model-file key that holds a learned classifier's gate (<see cref="Serialize"/>).</summary>
        public const string ModelKey = "walking_gate";

        /// <summary>
        /// Fits the gate on windows of labelled recordings (every 5th window; walking = the newest sample is labelled
        /// walking), both classes weighted equally, then sets the bias so that <paramref name="walkingPass"/> of the walking
        /// windows pass: the gate only has to keep out what clearly is not walking; the classifiers decide the rest.
        /// Throws <see cref="InvalidOperationException"/> without both classes.
        /// </summary>
        public static WalkingGate Train(IEnumerable<Recording> recordings, double walkingPass = DetectorPass, double? levelTolerance = null)
            => TrainEach(recordings, new[] { walkingPass }, levelTolerance)[0];

        /// <summary>
        /// One gate per share in <paramref name="walkingPasses"/>, from one fit: the gates differ only in their bias, so
        /// classifiers that pass different shares of walking (<see cref="DetectorPass"/>, <see cref="LearnedPass"/>) from
        /// the same recordings need the windows read and the regression solved once.
        /// </summary>
        public static WalkingGate[] TrainEach(IEnumerable<Recording> recordings, IReadOnlyList<double> walkingPasses, double? levelTolerance = null)
            => FitEach(TrainingWindows.Of(recordings, levelTolerance), walkingPasses, levelTolerance);

        /// <summary>
        /// The regression's inputs of labelled windows (every 5th; walking = the newest sample is labelled walking; samples
        /// without labels are left out), read once so that gates for several sets of recordings (cross-validation folds)
        /// can be fitted from their union.
        /// </summary>
        public sealed class TrainingWindows
        {
            public readonly List<double[]> Walking = new List<double[]>();
            public readonly List<double[]> Standing = new List<double[]>();

            public static TrainingWindows Of(IEnumerable<Recording> recordings, double? levelTolerance = null)
            {
                var windows = new TrainingWindows();
                foreach (var rec in recordings)
                {
                    if (!rec.HasTruth) continue;
                    var pre = new StreamPreprocessor(new PreprocessorSettings { History = HistorySamples });
                    var labels = new LabelCursor(rec);
                    long count = 0;
                    foreach (var s in rec.Samples)
                    {
                        pre.Push(s.Imu, w =>
                        {
                            if (count++ % 5 != 0) return;
                            if (!labels.TryLabelsAt(w.EndTime, out var truth)) return;
                            var f = new double[FeatureCount];
                            Features(w, f, levelTolerance);
                            var x = new double[InputCount];
                            FillInputs(f, x);
                            (truth.Left == GaitPhase.Standing ? windows.Standing : windows.Walking).Add(x);
                        });
                    }
                }
                return windows;
            }

            /// <summary>The windows of all <paramref name="parts"/> (the arrays are shared, not copied).</summary>
            public static TrainingWindows Union(IEnumerable<TrainingWindows> parts)
            {
                var all = new TrainingWindows();
                foreach (var p in parts)
                {
                    all.Walking.AddRange(p.Walking);
                    all.Standing.AddRange(p.Standing);
                }
                return all;
            }
        }

        /// <summary>
        /// One gate per share in <paramref name="walkingPasses"/> from windows already read (<see cref="TrainingWindows"/>,
        /// read with the same <paramref name="levelTolerance"/>).
        /// </summary>
        /// <param name="standingPass">At most this share of the standing windows may pass: where it is the stricter bound, it sets the bias.</param>
        public static WalkingGate[] FitEach(TrainingWindows windows, IReadOnlyList<double> walkingPasses, double? levelTolerance = null, double standingPass = 1)
        {
            var walking = windows.Walking;
            var standing = windows.Standing;
            if (walking.Count < 20 || standing.Count < 20)
                throw new InvalidOperationException($"The walking gate needs walking and standing windows: found {walking.Count} and {standing.Count}.");
            var weights = Fit(walking, standing);
            weights[InputCount] = 0; // the bias comes from the walking windows' scores below
            var scores = new List<double>();
            foreach (var x in walking) scores.Add(LogOdds(weights, x));
            scores.Sort();
            var standingScores = new List<double>();
            foreach (var x in standing) standingScores.Add(LogOdds(weights, x));
            standingScores.Sort();
            double standingBias = standingPass >= 1 ? double.PositiveInfinity
                : -standingScores[(int)Math.Ceiling((1 - Math.Max(0, standingPass)) * (standingScores.Count - 1))];
            var gates = new WalkingGate[walkingPasses.Count];
            for (int g = 0; g < gates.Length; g++)
            {
                weights[InputCount] = Math.Min(-scores[(int)Math.Floor((1 - walkingPasses[g]) * (scores.Count - 1))] + 1e-9, standingBias);
                gates[g] = new WalkingGate(weights, levelTolerance); // copies the weights
            }
            return gates;
        }

        /// <summary>
        /// Balanced logistic regression by Newton's method on standardized inputs, with a small ridge (the products span
        /// very different scales), returned as weights on the raw inputs; the bias is set by the caller.
        /// </summary>
        static double[] Fit(List<double[]> positive, List<double[]> negative)
        {
            int n = InputCount, d = n + 1;
            var mean = new double[n];
            var sd = new double[n];
            int total = positive.Count + negative.Count;
            var both = new[] { positive, negative };
            foreach (var set in both) foreach (var x in set) for (int i = 0; i < n; i++) mean[i] += x[i] / total;
            foreach (var set in both) foreach (var x in set) for (int i = 0; i < n; i++) sd[i] += (x[i] - mean[i]) * (x[i] - mean[i]) / total;
            for (int i = 0; i < n; i++) sd[i] = sd[i] > 1e-12 ? Math.Sqrt(sd[i]) : 1;

            var w = new double[d]; // standardized inputs, then the bias
            var u = new double[d];
            double wp = 0.5 / positive.Count, wn = 0.5 / negative.Count;
            for (int iter = 0; iter < 30; iter++)
            {
                var g = new double[d];
                var h = new double[d, d];
                void Add(double[] x, double y, double weight)
                {
                    for (int i = 0; i < n; i++) u[i] = (x[i] - mean[i]) / sd[i];
                    u[n] = 1;
                    double z = 0;
                    for (int i = 0; i < d; i++) z += w[i] * u[i];
                    double p = 1 / (1 + Math.Exp(-z));
                    double r = weight * (p - y), s = weight * p * (1 - p);
                    for (int i = 0; i < d; i++)
                    {
                        g[i] += r * u[i];
                        double su = s * u[i];
                        for (int j = i; j < d; j++) h[i, j] += su * u[j];
                    }
                }
                foreach (var x in positive) Add(x, 1, wp);
                foreach (var x in negative) Add(x, 0, wn);
                for (int i = 0; i < d; i++)
                    for (int j = 0; j < i; j++) h[i, j] = h[j, i];
                for (int i = 0; i < n; i++)
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
            var raw = new double[d];
            raw[n] = w[n];
            for (int i = 0; i < n; i++)
            {
                raw[i] = w[i] / sd[i];
                raw[n] -= raw[i] * mean[i];
            }
            return raw;
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
