using System;
using System.Numerics;

namespace HeadGait
{
    /// <summary>
    /// BLSTM: one bidirectional LSTM layer over the window's time steps, the forward direction's last output and the
    /// backward direction's first joined, a fully connected layer and a softmax over the stride segments and Standing
    /// (dropout acts only in training). Gates in PyTorch's order (input, forget, cell, output); the two biases are stored
    /// summed. Runs in float32, as the file stores the weights and as the network was trained, in SIMD lanes
    /// (<see cref="Vector{T}"/>): each step's gates are one pass over the recurrent weights laid out by hidden unit, and the
    /// activations are <see cref="VectorMath.Tanh"/> and <see cref="VectorMath.Sigmoid"/> lane by lane. Allocation-free per window.
    /// </summary>
    public sealed class BlstmClassifier : LearnedClassifier
    {
        public const string Kind = "blstm";

        /// <summary>Gate vectors summed together in registers: 8 independent sums keep the adder busy.</summary>
        const int Block = 8;

        readonly int hidden, inputs, steps, classes;
        readonly int unitVectors;             // hidden units padded to whole lanes, in vectors
        readonly int gateVectors;             // 4 x unitVectors: the gates, each gate's units padded to whole lanes
        readonly Vector<float>[][] wIh, wHh;  // per direction: [input][gate vector], [hidden unit][gate vector]
        readonly Vector<float>[][] bias;      // per direction: [gate vector]
        readonly float[] fcW, fcB;            // [K x 2H], [K]
        readonly double[] logProbabilities;   // [K], LastOutputs
        readonly Vector<float>[] gates, cell;
        readonly float[] h, x, joined;
        // Without SIMD lanes (VectorMath.UseVectors): PyTorch's own layout, per direction, and scalar state.
        readonly float[][] plainIh, plainHh, plainBias;
        readonly float[] plainGates, plainCell;

        /// <summary>The BLSTM with the time filter (<see cref="PhaseSequenceFilter"/>, <see cref="DefaultFilter"/>).</summary>
        public BlstmClassifier(ModelFile model) : this(model, DefaultFilter()) { }

        /// <summary>
        /// The time filter the BLSTM runs with: the defaults, and THR's step clock keeping its walks going
        /// (<see cref="PhaseFilterSettings.WalkOnStepClock"/>) once THR's walk is 1 s old
        /// (<see cref="PhaseFilterSettings.StepClockWalkAge"/>) and while the BLSTM itself named walking for 0.3 of the last
        /// second (<see cref="PhaseFilterSettings.StepClockOwnWalkingShare"/>), through the gate's outright refusals too
        /// (<see cref="PhaseFilterSettings.StepClockThroughRefusals"/>). On the real glasses (in-sample, avatar): fragments per
        /// walking file 19 to 9, walking shown 90.8 to 93.9 %, standing, sitting and picking up shown as walking unchanged
        /// (1.0, 0.6, 1.8 %); with no age and no share (the SVM's carry before) 1.5 and 2.6 % (see the measurements log).
        /// A fresh walk is shown after 0.25 s rather than 0.15 (<see cref="PhaseFilterSettings.FreshWalkShownAfter"/>): the
        /// BLSTM's false walks in the glasses' standing files are mostly its short fresh ones (shown at once, standing 1.5 %).
        /// On the glasses (in-sample, avatar) standing 1.008 to 0.754 %, sitting 0.58 to 0.42, picking up 1.80 to 1.16 %,
        /// walking 93.94 to 93.90 %, fragments 9, TUG bouts' start delay median 0.48 to 0.52 s; 0.2 / 0.3: standing 0.86 / 0.58 %.
        /// A walk resumed within 3 s of a walk shown for 2.5 s shows through the gate's refusal by less than 0.75 log-odds
        /// (<see cref="PhaseFilterSettings.ResumeStart"/>, as the SVM's): glasses (avatar) walking 95.2 to 95.3 % (worst tenth
        /// 85.9 to 86.2), bouts shown within 0.3 s of their first step 79.3 to 80.8 %, still activities and put-ons to the
        /// sample as before (no style folds here for the BLSTM's style CV). Its still-start rule reads the bend in pitch and
        /// roll, as the SVM's (<see cref="PhaseFilterSettings.StillStartBendInRoll"/>): putting on 0.84 to 0.70 %, standing
        /// 0.75 to 0.61 %, sitting 0.42 to 0.39 %, picking up 1.16 to 1.04 %, walking 95.3 to 95.2 % (worst tenth 86.2 to 85.5).
        /// While THR's settled walk goes on, the tilt's start limit gives way to its walking one, as the SVM's
        /// (<see cref="PhaseFilterSettings.StartTiltOnSettledClock"/>): glasses walking 95.2 to 95.4 % (worst tenth 85.5 to
        /// 86.6), picking up 1.044 to 1.075 %, putting on 0.70 to 0.72 %, standing and sitting as before (style CV not judged).
        /// </summary>
        public static PhaseFilterSettings DefaultFilter() => new PhaseFilterSettings { WalkOnStepClock = true, FreshWalkShownAfter = 0.25,
            ResumeStart = FirstStepStartSettings.Shipped(resumeAfterShown: 2.5), StillStartBendInRoll = true, StartTiltOnSettledClock = true };

        /// <summary>With the given time filter, or none (null): the network's own per-window answers, as the paper's classifier.</summary>
        public BlstmClassifier(ModelFile model, PhaseFilterSettings filter) : base(model, Kind, filter)
        {
            var shape = model.ShapeOf("lstm_w_hh");
            if (shape.Length != 3 || shape[0] != 2 || shape[1] != 4 * shape[2] || shape[2] < 1 || shape[2] > 1024)
                throw new ModelFormatException(model.Source, "tensor 'lstm_w_hh' must be 2 x 4H x H");
            hidden = shape[2];
            inputs = Features.Channels.Length;
            steps = Features.TimeSteps;
            classes = Segments.ClassCount;
            int lanes = Vector<float>.Count;
            unitVectors = (hidden + lanes - 1) / lanes;
            gateVectors = 4 * unitVectors;
            var ih = model.Tensor("lstm_w_ih", 2, 4 * hidden, inputs);
            var hh = model.Tensor("lstm_w_hh", 2, 4 * hidden, hidden);
            var b = model.Tensor("lstm_b", 2, 4 * hidden);
            wIh = new Vector<float>[2][];
            wHh = new Vector<float>[2][];
            bias = new Vector<float>[2][];
            for (int d = 0; d < 2; d++)
            {
                wIh[d] = ByUnit(ih, d * 4 * hidden * inputs, inputs);
                wHh[d] = ByUnit(hh, d * 4 * hidden * hidden, hidden);
                bias[d] = ByUnit(b, d * 4 * hidden, 1);
            }
            plainIh = new float[2][];
            plainHh = new float[2][];
            plainBias = new float[2][];
            for (int d = 0; d < 2; d++)
            {
                plainIh[d] = ToFloat(ih, d * 4 * hidden * inputs, 4 * hidden * inputs);
                plainHh[d] = ToFloat(hh, d * 4 * hidden * hidden, 4 * hidden * hidden);
                plainBias[d] = ToFloat(b, d * 4 * hidden, 4 * hidden);
            }
            plainGates = new float[4 * hidden];
            plainCell = new float[hidden];
            fcW = ToFloat(model.Tensor("fc_w", classes, 2 * hidden));
            fcB = ToFloat(model.Tensor("fc_b", classes));
            logProbabilities = new double[classes];
            gates = new Vector<float>[gateVectors];
            cell = new Vector<float>[unitVectors];
            h = new float[unitVectors * lanes];
            x = new float[Features.Width];
            joined = new float[2 * hidden];
        }

        public BlstmClassifier(string path) : this(ModelFile.Load(path)) { }

        public override string Name => Filter == null ? "BLSTM-raw" : "BLSTM";
        public int Hidden => hidden;

        /// <summary>
        /// A [4H x n] gate matrix (PyTorch's rows) as n rows of gate vectors: element (gate s, unit j) of column i goes to
        /// row i, lane s * padded H + j; the padding lanes stay zero, so padded units keep a zero state.
        /// </summary>
        Vector<float>[] ByUnit(double[] all, int offset, int n)
        {
            int lanes = Vector<float>.Count;
            var row = new float[gateVectors * lanes];
            var r = new Vector<float>[n * gateVectors];
            for (int i = 0; i < n; i++)
            {
                for (int s = 0; s < 4; s++)
                    for (int j = 0; j < hidden; j++)
                        row[s * unitVectors * lanes + j] = (float)all[offset + (s * hidden + j) * n + i];
                for (int v = 0; v < gateVectors; v++) r[i * gateVectors + v] = new Vector<float>(row, v * lanes);
            }
            return r;
        }

        static float[] ToFloat(double[] v) => ToFloat(v, 0, v.Length);

        static float[] ToFloat(double[] v, int offset, int length)
        {
            var r = new float[length];
            for (int i = 0; i < length; i++) r[i] = (float)v[offset + i];
            return r;
        }

        public override string OutputBiasName => "fc_b";
        public override bool PairwiseOutputs => false;

        public override double[] LastOutputs
        {
            get
            {
                var p = LastScores;
                for (int k = 0; k < p.Length; k++) logProbabilities[k] = Math.Log(Math.Max(p[k], 1e-12));
                return logProbabilities;
            }
        }

        protected override void Score(double[] standardised, double[] probabilities)
        {
            for (int i = 0; i < x.Length; i++) x[i] = (float)standardised[i];
            if (VectorMath.UseVectors)
            {
                Run(0, 0);
                Run(1, hidden);
            }
            else
            {
                RunPlain(0, 0);
                RunPlain(1, hidden);
            }
            double max = double.NegativeInfinity;
            for (int k = 0; k < classes; k++)
            {
                float z = fcB[k];
                int row = k * 2 * hidden;
                for (int j = 0; j < 2 * hidden; j++) z += fcW[row + j] * joined[j];
                probabilities[k] = z;
                if (z > max) max = z;
            }
            double sum = 0;
            for (int k = 0; k < classes; k++)
            {
                probabilities[k] = Math.Exp(probabilities[k] - max);
                sum += probabilities[k];
            }
            for (int k = 0; k < classes; k++) probabilities[k] /= sum;
        }

        /// <summary>The shifted logits' softmax: the probabilities (the outputs, from any evaluator) times e^shift, normalised.</summary>
        protected override bool WearerProbabilities(double[] probabilities, double[] p)
        {
            var shift = WearerShift;
            if (shift == null) return false;
            double sum = 0;
            for (int k = 0; k < classes; k++) sum += p[k] = probabilities[k] * Math.Exp(shift[k]);
            if (!(sum > 0)) return false;
            for (int k = 0; k < classes; k++) p[k] /= sum;
            return true;
        }

        /// <summary>
        /// <see cref="Run"/> without SIMD lanes: one gate at a time, in float32 with the same activations (the sums in
        /// another order, so within float precision of the lanes' answers).
        /// </summary>
        void RunPlain(int direction, int offset)
        {
            var wi = plainIh[direction];
            var wh = plainHh[direction];
            var b = plainBias[direction];
            Array.Clear(h, 0, h.Length);
            Array.Clear(plainCell, 0, hidden);
            for (int n = 0; n < steps; n++)
            {
                int xo = (direction == 0 ? n : steps - 1 - n) * inputs;
                for (int g = 0; g < 4 * hidden; g++)
                {
                    float z = b[g];
                    for (int i = 0; i < inputs; i++) z += wi[g * inputs + i] * x[xo + i];
                    for (int j = 0; j < hidden; j++) z += wh[g * hidden + j] * h[j];
                    plainGates[g] = z;
                }
                for (int j = 0; j < hidden; j++)
                {
                    float c = VectorMath.Sigmoid(plainGates[hidden + j]) * plainCell[j]
                        + VectorMath.Sigmoid(plainGates[j]) * VectorMath.Tanh(plainGates[2 * hidden + j]);
                    plainCell[j] = c;
                    h[j] = VectorMath.Sigmoid(plainGates[3 * hidden + j]) * VectorMath.Tanh(c);
                }
            }
            Array.Copy(h, 0, joined, offset, hidden);
        }

        /// <summary>One direction over the window; its final hidden state goes to joined[offset..].</summary>
        void Run(int direction, int offset)
        {
            var wi = wIh[direction];
            var wh = wHh[direction];
            var b = bias[direction];
            int lanes = Vector<float>.Count, nv = gateVectors, uv = unitVectors;
            Array.Clear(h, 0, h.Length);
            Array.Clear(cell, 0, cell.Length);
            for (int n = 0; n < steps; n++)
            {
                int xo = (direction == 0 ? n : steps - 1 - n) * inputs;
                int units = n == 0 ? 0 : hidden; // the state starts at zero: no recurrent product on the first step
                int g = 0;
                for (; g + Block <= nv; g += Block)
                {
                    Vector<float> a0 = b[g], a1 = b[g + 1], a2 = b[g + 2], a3 = b[g + 3];
                    Vector<float> a4 = b[g + 4], a5 = b[g + 5], a6 = b[g + 6], a7 = b[g + 7];
                    for (int i = 0; i < inputs; i++)
                    {
                        var xi = new Vector<float>(x[xo + i]);
                        int r = i * nv + g;
                        a0 += xi * wi[r]; a1 += xi * wi[r + 1]; a2 += xi * wi[r + 2]; a3 += xi * wi[r + 3];
                        a4 += xi * wi[r + 4]; a5 += xi * wi[r + 5]; a6 += xi * wi[r + 6]; a7 += xi * wi[r + 7];
                    }
                    for (int j = 0; j < units; j++)
                    {
                        var hj = new Vector<float>(h[j]);
                        int r = j * nv + g;
                        a0 += hj * wh[r]; a1 += hj * wh[r + 1]; a2 += hj * wh[r + 2]; a3 += hj * wh[r + 3];
                        a4 += hj * wh[r + 4]; a5 += hj * wh[r + 5]; a6 += hj * wh[r + 6]; a7 += hj * wh[r + 7];
                    }
                    gates[g] = a0; gates[g + 1] = a1; gates[g + 2] = a2; gates[g + 3] = a3;
                    gates[g + 4] = a4; gates[g + 5] = a5; gates[g + 6] = a6; gates[g + 7] = a7;
                }
                for (; g < nv; g++)
                {
                    var a = b[g];
                    for (int i = 0; i < inputs; i++) a += new Vector<float>(x[xo + i]) * wi[i * nv + g];
                    for (int j = 0; j < units; j++) a += new Vector<float>(h[j]) * wh[j * nv + g];
                    gates[g] = a;
                }
                for (int k = 0; k < uv; k++)
                {
                    var ig = VectorMath.Sigmoid(gates[k]);
                    var fg = VectorMath.Sigmoid(gates[uv + k]);
                    var cg = VectorMath.Tanh(gates[2 * uv + k]);
                    var og = VectorMath.Sigmoid(gates[3 * uv + k]);
                    var c = fg * cell[k] + ig * cg;
                    cell[k] = c;
                    (og * VectorMath.Tanh(c)).CopyTo(h, k * lanes);
                }
            }
            Array.Copy(h, 0, joined, offset, hidden);
        }
    }
}
