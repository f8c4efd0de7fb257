using System;

namespace HeadGait
{
    /// <summary>
    /// BLSTM: one bidirectional LSTM layer over the window's time steps, the forward direction's last output and the
    /// backward direction's first joined, a fully connected layer and a softmax over the stride segments and Standing
    /// (dropout acts only in training). Gates in PyTorch's order (input, forget, cell, output); the two biases are stored
    /// summed. Allocation-free per window.
    /// </summary>
    public sealed class BlstmClassifier : LearnedClassifier
    {
        public const string Kind = "blstm";

        readonly int hidden, inputs, steps, classes;
        readonly double[][] wIh, wHh, bias;   // per direction: [4H x C], [4H x H], [4H]
        readonly double[] fcW, fcB;           // [K x 2H], [K]
        readonly double[] h, c, gates, joined;

        /// <summary>The BLSTM with the time filter (<see cref="PhaseSequenceFilter"/>).</summary>
        public BlstmClassifier(ModelFile model) : this(model, new PhaseFilterSettings()) { }

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
            var ih = model.Tensor("lstm_w_ih", 2, 4 * hidden, inputs);
            var hh = model.Tensor("lstm_w_hh", 2, 4 * hidden, hidden);
            var b = model.Tensor("lstm_b", 2, 4 * hidden);
            wIh = new double[2][];
            wHh = new double[2][];
            bias = new double[2][];
            for (int d = 0; d < 2; d++)
            {
                wIh[d] = Slice(ih, d, 4 * hidden * inputs);
                wHh[d] = Slice(hh, d, 4 * hidden * hidden);
                bias[d] = Slice(b, d, 4 * hidden);
            }
            fcW = model.Tensor("fc_w", classes, 2 * hidden);
            fcB = model.Tensor("fc_b", classes);
            h = new double[hidden];
            c = new double[hidden];
            gates = new double[4 * hidden];
            joined = new double[2 * hidden];
        }

        public BlstmClassifier(string path) : this(ModelFile.Load(path)) { }

        public override string Name => Filter == null ? "BLSTM-raw" : "BLSTM";
        public int Hidden => hidden;

        static double[] Slice(double[] all, int index, int length)
        {
            var r = new double[length];
            Array.Copy(all, index * length, r, 0, length);
            return r;
        }

        protected override void Score(double[] x, double[] probabilities)
        {
            Run(0, x, 0);
            Run(1, x, hidden);
            double max = double.NegativeInfinity;
            for (int k = 0; k < classes; k++)
            {
                double z = fcB[k];
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

        /// <summary>One direction over the window; its final hidden state goes to joined[offset..].</summary>
        void Run(int direction, double[] x, int offset)
        {
            var wi = wIh[direction];
            var wh = wHh[direction];
            var b = bias[direction];
            Array.Clear(h, 0, hidden);
            Array.Clear(c, 0, hidden);
            for (int n = 0; n < steps; n++)
            {
                int t = direction == 0 ? n : steps - 1 - n;
                int xo = t * inputs;
                // The recurrent product dominates the cost.
                VectorMath.MultiplyRows(wh, 4 * hidden, h, hidden, gates);
                for (int g = 0; g < 4 * hidden; g++)
                {
                    double z = b[g];
                    int ri = g * inputs;
                    for (int i = 0; i < inputs; i++) z += wi[ri + i] * x[xo + i];
                    gates[g] += z;
                }
                for (int j = 0; j < hidden; j++)
                {
                    double ig = Sigmoid(gates[j]);
                    double fg = Sigmoid(gates[hidden + j]);
                    double cg = Math.Tanh(gates[2 * hidden + j]);
                    double og = Sigmoid(gates[3 * hidden + j]);
                    c[j] = fg * c[j] + ig * cg;
                    h[j] = og * Math.Tanh(c[j]);
                }
            }
            Array.Copy(h, 0, joined, offset, hidden);
        }

        static double Sigmoid(double z) => 1.0 / (1.0 + Math.Exp(-z));
    }
}
