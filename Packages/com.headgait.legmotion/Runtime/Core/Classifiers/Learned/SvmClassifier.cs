using System;

namespace HeadGait
{
    /// <summary>
    /// SVM: support vector machine with a polynomial kernel K(a, b) = (gamma a.b + coef0)^degree (the paper: cubic,
    /// C = 100), one-versus-one over the stride segments and Standing as LIBSVM trains it. Each pair's decision value
    /// votes for one of its two classes; the class with most votes wins, ties going to the lower class. Scores are the
    /// votes. Allocation-free per window.
    /// </summary>
    public sealed class SvmClassifier : LearnedClassifier
    {
        public const string Kind = "svm";

        readonly int classes, width, vectors, degree;
        /// <summary>Range of the kernel's gamma a model may hold (training on standardised features gives about 1 / features).</summary>
        public const double MinGamma = 1e-6, MaxGamma = 10;

        /// <summary>Largest |coef0| a model may hold.</summary>
        public const double MaxAbsCoef0 = 100;

        readonly double gamma, coef0;
        readonly double[] supportVectors; // [nSV x D]
        readonly double[] dualCoef;       // [(K-1) x nSV]
        readonly double[] intercept;      // [K(K-1)/2]
        readonly int[] start, count;      // each class's support vectors
        readonly double[] kernel;
        readonly double[] decision;
        readonly double[] share;          // [(K-1) x K]: each coefficient row over each class's vectors

        /// <summary>The SVM with the time filter (<see cref="PhaseSequenceFilter"/>, <see cref="DefaultFilter"/>).</summary>
        public SvmClassifier(ModelFile model) : this(model, DefaultFilter()) { }

        /// <summary>
        /// The time filter the SVM runs with: its evidence counts half (<see cref="PhaseFilterSettings.EvidenceWeight"/>
        /// 0.5), as votes made into probabilities are overconfident and at full weight a few windows voting otherwise broke
        /// walks apart. Style CV against full weight, same models: misclassification 21.5 to 20.7 %, standing shown as
        /// walking 1.9 to 1.6 %; calm walkers pay (ear-like step recall 95.6 to 94.7 %). The BLSTM keeps full weight.
        /// </summary>
        public static PhaseFilterSettings DefaultFilter() => new PhaseFilterSettings { EvidenceWeight = 0.5 };

        /// <summary>With the given time filter, or none (null): the SVM's own per-window votes decide, as the paper's classifier.</summary>
        public SvmClassifier(ModelFile model, PhaseFilterSettings filter) : base(model, Kind, filter)
        {
            classes = Segments.ClassCount;
            width = Features.Width;
            gamma = model.NeedDouble("gamma");
            coef0 = model.NeedDouble("coef0");
            degree = model.NeedInt("degree", 1, 5);
            // Ranges training can produce (standardised features: gamma about 1 / features, coef0 a small offset); beyond
            // them the kernel overflows or drowns every decision in one term.
            if (!(gamma >= MinGamma && gamma <= MaxGamma)) throw new ModelFormatException(model.Source, $"'gamma' is {gamma:G4}, outside {MinGamma}..{MaxGamma} (what training produces)");
            if (!(Math.Abs(coef0) <= MaxAbsCoef0)) throw new ModelFormatException(model.Source, $"'coef0' is {coef0:G4}, outside -{MaxAbsCoef0}..{MaxAbsCoef0} (what training produces)");
            var nSupport = model.Tensor("n_support", classes);
            start = new int[classes];
            count = new int[classes];
            for (int k = 0; k < classes; k++)
            {
                double v = nSupport[k];
                if (v < 0 || v != Math.Floor(v) || v > 10000000) throw new ModelFormatException(model.Source, $"n_support[{k}] = {v} is not a count");
                count[k] = (int)v;
                start[k] = k == 0 ? 0 : start[k - 1] + count[k - 1];
            }
            vectors = start[classes - 1] + count[classes - 1];
            if (vectors < 1) throw new ModelFormatException(model.Source, "has no support vectors");
            supportVectors = model.Tensor("support_vectors", vectors, width);
            dualCoef = model.Tensor("dual_coef", classes - 1, vectors);
            intercept = model.Tensor("intercept", classes * (classes - 1) / 2);
            kernel = new double[vectors];
            decision = new double[intercept.Length];
            share = new double[(classes - 1) * classes];
        }

        public SvmClassifier(string path) : this(ModelFile.Load(path)) { }

        /// <summary>
        /// Votes as probabilities for the time filter: each vote multiplies a class's odds by e (softmax of the votes). One-
        /// versus-one votes are not calibrated probabilities; this keeps their order and lets a clear winner dominate.
        /// </summary>
        protected override void ToProbabilities(double[] votes, double[] p)
        {
            double max = double.NegativeInfinity, sum = 0;
            foreach (var v in votes) max = Math.Max(max, v);
            for (int k = 0; k < votes.Length; k++) sum += p[k] = Math.Exp(votes[k] - max);
            for (int k = 0; k < votes.Length; k++) p[k] /= sum;
        }

        public override string Name => Filter == null ? "SVM-raw" : "SVM";
        public int SupportVectors => vectors;

        /// <summary>Pairwise decision values of the last window, in LIBSVM's order (0 vs 1, 0 vs 2, ..., K-2 vs K-1).</summary>
        public double[] LastDecision => decision;

        protected override void Score(double[] x, double[] votes)
        {
            VectorMath.MultiplyRows(supportVectors, vectors, x, width, kernel);
            for (int s = 0; s < vectors; s++)
            {
                double b = gamma * kernel[s] + coef0, p = b;
                for (int d = 1; d < degree; d++) p *= b;
                kernel[s] = p;
            }
            // Each class's share of each coefficient row, over contiguous support vectors (vectorised): pair (i, j) adds
            // class i's share of row j-1 and class j's share of row i, as LIBSVM lays the coefficients out.
            for (int r = 0; r < classes - 1; r++)
                for (int c = 0; c < classes; c++)
                    share[r * classes + c] = VectorMath.Dot(dualCoef, r * vectors + start[c], kernel, start[c], count[c]);
            Array.Clear(votes, 0, classes);
            int pair = 0;
            for (int i = 0; i < classes; i++)
            {
                for (int j = i + 1; j < classes; j++)
                {
                    double sum = intercept[pair] + share[(j - 1) * classes + i] + share[i * classes + j];
                    decision[pair] = sum;
                    if (sum > 0) votes[i]++;
                    else votes[j]++;
                    pair++;
                }
            }
        }
    }
}
