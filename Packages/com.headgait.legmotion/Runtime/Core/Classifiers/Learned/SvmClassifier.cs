using System;
using System.Numerics;
using System.Runtime.CompilerServices;

namespace HeadGait
{
    /// <summary>
    /// SVM: support vector machine with a polynomial kernel K(a, b) = (gamma a.b + coef0)^degree (the paper: cubic,
    /// C = 100), one-versus-one over the stride segments and Standing as LIBSVM trains it. Each pair's decision value
    /// votes for one of its two classes; the class with most votes wins, ties going to the lower class. Its outputs (what
    /// an evaluator gives) are the pairs' decision values, its scores the votes they cast. Computed in float32 SIMD lanes,
    /// several windows per pass over the support vectors, with pairs too close to call decided again in double
    /// (<see cref="RecheckMargin"/>); scalar and double without lanes. Allocation-free per window.
    /// </summary>
    public sealed class SvmClassifier : LearnedClassifier
    {
        public const string Kind = "svm";

        /// <summary>Windows scored together in one pass over the support vectors (<see cref="ScoreBatch"/>).</summary>
        public const int WindowsPerPass = 4;

        readonly int classes, width, vectors, degree;
        /// <summary>Range of the kernel's gamma a model may hold (training on standardised features gives about 1 / features).</summary>
        public const double MinGamma = 1e-6, MaxGamma = 10;

        /// <summary>Largest |coef0| a model may hold.</summary>
        public const double MaxAbsCoef0 = 100;

        readonly double gamma, coef0;
        readonly double[] intercept;       // [K(K-1)/2]
        readonly double[] supportVectors;  // [nSV x D], the model's own double values: for pairs too close to call in float32
        readonly double[] dualCoef;        // [(K-1) x nSV]
        readonly int[] start, count;       // each class's support vectors
        // The support vectors in blocks of one lane width, each class's padded with zero vectors to whole blocks, stored
        // feature by feature ([block][feature] of lanes) so that a block's kernel values come out lane by lane with no
        // horizontal sums; float32 (decision values within about 1e-3 of double arithmetic).
        readonly Vector<float>[] blocks;
        readonly int[] firstBlock;         // [K + 1]: each class's blocks
        readonly Vector<float>[] dual;     // [coefficient row][block], zero in the padding
        readonly float[] x;                // [WindowsPerPass x D]
        readonly Vector<float>[] kernel;   // [WindowsPerPass x blocks]
        double[] kernelInDouble;           // [nSV], the scalar path's, made on its first use
        readonly double[] share;           // [WindowsPerPass x (K-1) x K]: each coefficient row over each class's vectors

        /// <summary>The SVM with the time filter (<see cref="PhaseSequenceFilter"/>, <see cref="DefaultFilter"/>).</summary>
        public SvmClassifier(ModelFile model) : this(model, DefaultFilter()) { }

        /// <summary>
        /// The time filter the SVM runs with: its evidence counts half (<see cref="PhaseFilterSettings.EvidenceWeight"/>
        /// 0.5), as votes made into probabilities are overconfident and at full weight a few windows voting otherwise broke
        /// walks apart. Style CV against full weight, same models: misclassification 21.5 to 20.7 %, standing shown as
        /// walking 1.9 to 1.6 %; calm walkers pay (ear-like step recall 95.6 to 94.7 %). The BLSTM keeps full weight.
        /// A young walk's standing weighs 0.1 (<see cref="PhaseFilterSettings.YoungWalkStandingWeight"/>; the BLSTM's 0.3): on
        /// the real glasses (in-sample; before a sure pass showed a fresh walk at once) the SVM at 0.3 kept its 21 fragments per
        /// walking file, at 0.1 19 (standing shown as walking 0.5 to 0.7 %), at 0.03 19 (0.8 %).
        /// THR's step clock keeps its walks going (<see cref="PhaseFilterSettings.WalkOnStepClock"/>): on the glasses
        /// (in-sample, avatar) fragments 19 to 12, walking shown 91.7 to 94.1 %, standing 0.7 to 1.0 %, picking up 1.5 to
        /// 2.0 % with the carry at once wherever the gate did not refuse; with THR's walk settled and the SVM's own walking
        /// share asked, as the BLSTM's, fragments 10, walking 94.5 %, standing 0.9 %, picking up 1.5 % (style CV the same;
        /// held-out clips made slow 27.0 to 27.3 %, as a clip's first second is no longer carried).
        /// A walk at least half a second old rides out the gate's near misses (<see cref="PhaseFilterSettings.NarrowRefusalLogOdds"/>
        /// 2 log-odds): held-out clips made slow 27.2 to 26.3 %, as recorded 21.0 % either; glasses (in-sample, avatar) walking
        /// 94.5 to 94.6 %, standing and sitting unchanged, picking up 1.53 to 1.54 %.
        /// A walk shown for under half a second gives the next no credit (<see cref="PhaseFilterSettings.ShortWalkGivesNoCredit"/>):
        /// standing with gestures shown as walking (style CV, avatar) 1.2 to 0.9 %, as recorded 21.0 / 19.4 to 21.0 / 19.3 %,
        /// held-out clips made slow 26.3 / 24.3 to 26.9 / 24.7 %; glasses (in-sample, avatar) walking 94.6 to 94.4 %.
        /// A walk resumed within 3 s of a walk shown for 2.5 s shows through the gate's refusal by less than 0.75 log-odds
        /// (<see cref="PhaseFilterSettings.ResumeStart"/>, as COR's first-step start): glasses (avatar) walking 95.5 to 95.6 %,
        /// bouts shown within 0.3 s of their first step 75.6 to 77.5 %, still activities and put-ons to the sample as before;
        /// style CV 21.0 / 19.3 % and gestures and bows either way, the clips made slow 26.9 to 26.8 %.
        /// The still-start rule reads the head's bend from the still head in pitch and roll
        /// (<see cref="PhaseFilterSettings.StillStartBendInRoll"/>): glasses (avatar; put-ons five draws per file) putting on
        /// 1.10 to 0.97 %, standing 0.83 to 0.71 %, sitting 0.25 to 0.23 %, picking up 1.37 to 1.21 %, walking 95.6 to 95.5 %
        /// (worst tenth 90.1 either way); style CV every per-recording score the same.
        /// A wearer quicker than the training walkers is read at their own step without a calibration
        /// (<see cref="PhaseFilterSettings.LiveTimeScale"/>): style CV 21.0 / 19.3 to 18.8 / 17.6 % (the quick *active* walkers
        /// 27.5 to 19.9 %, bn1 *childish* 33.1 to 26.3 %, no style worse by more than 0.4 point), the clips made slow 26.8 to
        /// 26.9 %, gestures and bows as before; glasses (avatar) walking 95.5 % either way, alternation 97.55 to 97.51 %,
        /// picking up 1.21 to 1.22 %, putting on 0.965 to 0.971 %. Cost: windows read at a scale are scored twice. With the
        /// step clock's first timed step as well as its settled one: style CV 18.8 / 17.6 to 18.4 / 16.9 %, slow 26.9 to 27.1 %.
        /// While THR's settled walk goes on, the tilt's start limit gives way to its walking one
        /// (<see cref="PhaseFilterSettings.StartTiltOnSettledClock"/>): style CV 18.4 / 16.9 to 18.2 / 16.8 % (bn1 *childish*
        /// 25.2 to 20.1 %), slow and gestures and bows as before; glasses (avatar) walking 95.5 to 95.6 % (worst tenth 90.1 to
        /// 91.1), picking up 1.22 to 1.24 %, putting on 0.971 to 0.983 %, standing and sitting as before.
        /// </summary>
        public static PhaseFilterSettings DefaultFilter() => new PhaseFilterSettings { EvidenceWeight = 0.5, YoungWalkStandingWeight = 0.1, WalkOnStepClock = true, NarrowRefusalLogOdds = 2,
            ShortWalkGivesNoCredit = true, ResumeStart = FirstStepStartSettings.Shipped(resumeAfterShown: 2.5), StillStartBendInRoll = true, LiveTimeScale = true,
            StartTiltOnSettledClock = true };

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
            int lanes = Vector<float>.Count;
            firstBlock = new int[classes + 1];
            for (int k = 0; k < classes; k++) firstBlock[k + 1] = firstBlock[k] + (count[k] + lanes - 1) / lanes;
            int blockCount = firstBlock[classes];
            blocks = new Vector<float>[blockCount * width];
            dual = new Vector<float>[blockCount * (classes - 1)];
            var lane = new float[lanes];
            for (int k = 0; k < classes; k++)
            {
                for (int bk = firstBlock[k]; bk < firstBlock[k + 1]; bk++)
                {
                    int first = start[k] + (bk - firstBlock[k]) * lanes, used = Math.Min(lanes, start[k] + count[k] - first);
                    for (int d = 0; d < width; d++)
                    {
                        Array.Clear(lane, 0, lanes);
                        for (int l = 0; l < used; l++) lane[l] = (float)supportVectors[(first + l) * width + d];
                        blocks[bk * width + d] = new Vector<float>(lane);
                    }
                    for (int r = 0; r < classes - 1; r++)
                    {
                        Array.Clear(lane, 0, lanes);
                        for (int l = 0; l < used; l++) lane[l] = (float)dualCoef[r * vectors + first + l];
                        dual[r * blockCount + bk] = new Vector<float>(lane);
                    }
                }
            }
            x = new float[WindowsPerPass * width];
            kernel = new Vector<float>[WindowsPerPass * blockCount];
            share = new double[WindowsPerPass * (classes - 1) * classes];
        }

        public SvmClassifier(string path) : this(ModelFile.Load(path)) { }

        /// <summary>
        /// Votes as probabilities for the time filter: each vote multiplies a class's odds by e (softmax of the votes). One-
        /// versus-one votes are not calibrated probabilities; this keeps their order and lets a clear winner dominate.
        /// </summary>
        protected override void ToProbabilities(double[] votes, double[] p) => Softmax(votes, p);

        /// <summary>The votes the pairs' decision values cast.</summary>
        protected override void ClassScores(double[] decision, double[] votes) => Votes(decision, null, votes);

        /// <summary>The votes of the wearer's shifted intercepts (decision value + shift) as probabilities.</summary>
        protected override bool WearerProbabilities(double[] decision, double[] p)
        {
            if (WearerShift == null) return false;
            Votes(decision, WearerShift, p);
            Softmax(p, p);
            return true;
        }

        /// <summary>Each pair's vote: for its first class where its decision value (plus <paramref name="shift"/>'s, if any) is positive, else for its second.</summary>
        void Votes(double[] decision, double[] shift, double[] votes)
        {
            Array.Clear(votes, 0, classes);
            int pair = 0;
            for (int i = 0; i < classes; i++)
                for (int j = i + 1; j < classes; j++, pair++)
                    votes[(shift == null ? decision[pair] : decision[pair] + shift[pair]) > 0 ? i : j]++;
        }

        static void Softmax(double[] votes, double[] p)
        {
            double max = double.NegativeInfinity, sum = 0;
            foreach (var v in votes) max = Math.Max(max, v);
            for (int k = 0; k < votes.Length; k++) sum += p[k] = Math.Exp(votes[k] - max);
            for (int k = 0; k < votes.Length; k++) p[k] /= sum;
        }

        public override string Name => Filter == null ? "SVM-raw" : "SVM";

        /// <summary>Pairwise decision values of the last window, in LIBSVM's order (0 vs 1, 0 vs 2, ..., K-2 vs K-1).</summary>
        public double[] LastDecision => WindowOutputs;

        public override string OutputBiasName => "intercept";
        public override bool PairwiseOutputs => true;
        public override double[] LastOutputs => WindowOutputs;

        protected override void Score(double[] standardised, double[] decision) => ScoreBatch(standardised, 1, decision);

        /// <summary>
        /// The windows' pair decision values, up to <see cref="WindowsPerPass"/> windows per pass over the support vectors:
        /// each block is loaded once for all of them. A window's sums run in the same order alone or with others, so
        /// batching leaves its decision values as they were.
        /// </summary>
        protected override void ScoreBatch(double[] features, int windows, double[] decision)
        {
            int pairs = intercept.Length;
            if (!VectorMath.UseVectors)
            {
                for (int w = 0; w < windows; w++) ScoreInDouble(features, w * width, decision, w * pairs);
                return;
            }
            for (int w0 = 0; w0 < windows; w0 += WindowsPerPass)
            {
                int n = Math.Min(WindowsPerPass, windows - w0);
                for (int i = 0; i < n * width; i++) x[i] = (float)features[w0 * width + i];
                if (n == WindowsPerPass) KernelsOfFour(); // the products, not the loads, are most of the cost: fewer go one by one
                else
                    for (int w = 0; w < n; w++) KernelsOfOne(w);
                // The polynomial apart from the products: a call there would make the JIT keep the sums on the stack.
                int used = n * firstBlock[classes];
                for (int i = 0; i < used; i++) kernel[i] = Kernel(kernel[i]);
                DecisionValues(n, decision, w0 * pairs, features, w0 * width);
            }
        }

        /// <summary>(gamma a.b + coef0)^degree, lane by lane.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        Vector<float> Kernel(Vector<float> dot)
        {
            var b = new Vector<float>((float)gamma) * dot + new Vector<float>((float)coef0);
            if (degree == 3) return b * b * b;
            var p = b;
            for (int d = 1; d < degree; d++) p *= b;
            return p;
        }

        /// <summary>Window w's dot products with the support vectors, eight blocks at a time (eight independent sums keep the adder busy).</summary>
        void KernelsOfOne(int w)
        {
            int blockCount = firstBlock[classes], ko = w * blockCount;
            var xw = new ReadOnlySpan<float>(x, w * width, width);
            int bk = 0;
            for (; bk + 8 <= blockCount; bk += 8)
            {
                Vector<float> s0 = Vector<float>.Zero, s1 = s0, s2 = s0, s3 = s0, s4 = s0, s5 = s0, s6 = s0, s7 = s0;
                var run = new ReadOnlySpan<Vector<float>>(blocks, bk * width, 8 * width);
                for (int d = 0; d < xw.Length; d++)
                {
                    var xd = new Vector<float>(xw[d]);
                    s0 += run[d] * xd;
                    s1 += run[width + d] * xd;
                    s2 += run[2 * width + d] * xd;
                    s3 += run[3 * width + d] * xd;
                    s4 += run[4 * width + d] * xd;
                    s5 += run[5 * width + d] * xd;
                    s6 += run[6 * width + d] * xd;
                    s7 += run[7 * width + d] * xd;
                }
                int o = ko + bk;
                kernel[o] = s0;
                kernel[o + 1] = s1;
                kernel[o + 2] = s2;
                kernel[o + 3] = s3;
                kernel[o + 4] = s4;
                kernel[o + 5] = s5;
                kernel[o + 6] = s6;
                kernel[o + 7] = s7;
            }
            for (; bk < blockCount; bk++)
            {
                var s = Vector<float>.Zero;
                var block = new ReadOnlySpan<Vector<float>>(blocks, bk * width, width);
                for (int d = 0; d < xw.Length; d++) s += block[d] * new Vector<float>(xw[d]);
                kernel[ko + bk] = s;
            }
        }

        /// <summary>Four windows' dot products with the support vectors, two blocks at a time: each block is loaded once for the four windows.</summary>
        void KernelsOfFour()
        {
            int blockCount = firstBlock[classes], stride = blockCount;
            var x0 = new ReadOnlySpan<float>(x, 0, width);
            var x1 = new ReadOnlySpan<float>(x, width, width);
            var x2 = new ReadOnlySpan<float>(x, 2 * width, width);
            var x3 = new ReadOnlySpan<float>(x, 3 * width, width);
            int bk = 0;
            for (; bk + 2 <= blockCount; bk += 2)
            {
                Vector<float> s0 = Vector<float>.Zero, s1 = s0, s2 = s0, s3 = s0, t0 = s0, t1 = s0, t2 = s0, t3 = s0;
                var run = new ReadOnlySpan<Vector<float>>(blocks, bk * width, 2 * width);
                for (int d = 0; d < x0.Length; d++)
                {
                    var u = run[d];
                    var v = run[width + d];
                    var a0 = new Vector<float>(x0[d]);
                    var a1 = new Vector<float>(x1[d]);
                    var a2 = new Vector<float>(x2[d]);
                    var a3 = new Vector<float>(x3[d]);
                    s0 += u * a0; s1 += u * a1; s2 += u * a2; s3 += u * a3;
                    t0 += v * a0; t1 += v * a1; t2 += v * a2; t3 += v * a3;
                }
                int o = bk;
                kernel[o] = s0;
                kernel[stride + o] = s1;
                kernel[2 * stride + o] = s2;
                kernel[3 * stride + o] = s3;
                kernel[o + 1] = t0;
                kernel[stride + o + 1] = t1;
                kernel[2 * stride + o + 1] = t2;
                kernel[3 * stride + o + 1] = t3;
            }
            for (; bk < blockCount; bk++)
            {
                Vector<float> s0 = Vector<float>.Zero, s1 = s0, s2 = s0, s3 = s0;
                var block = new ReadOnlySpan<Vector<float>>(blocks, bk * width, width);
                for (int d = 0; d < block.Length; d++)
                {
                    var v = block[d];
                    s0 += v * new Vector<float>(x0[d]);
                    s1 += v * new Vector<float>(x1[d]);
                    s2 += v * new Vector<float>(x2[d]);
                    s3 += v * new Vector<float>(x3[d]);
                }
                int o = bk;
                kernel[o] = s0;
                kernel[stride + o] = s1;
                kernel[2 * stride + o] = s2;
                kernel[3 * stride + o] = s3;
            }
        }

        /// <summary>
        /// The decision values of windows w0.. w0 + n - 1 from their kernel values: each class's share of each
        /// coefficient row over its own blocks (pair (i, j) adds class i's share of row j-1 and class j's share of row i, as
        /// LIBSVM lays the coefficients out), summed lane by lane in float32 and across the lanes in double. With several
        /// windows each coefficient block is loaded once for all of them.
        /// </summary>
        void DecisionValues(int n, double[] decision, int o, double[] features, int fo)
        {
            int blockCount = firstBlock[classes], rows = classes - 1;
            if (n == 1) VoteOne(rows, blockCount);
            else
            {
                var k = new ReadOnlySpan<Vector<float>>(kernel, 0, WindowsPerPass * blockCount);
                for (int r = 0; r < rows; r++)
                {
                    var row = new ReadOnlySpan<Vector<float>>(dual, r * blockCount, blockCount);
                    for (int c = 0; c < classes; c++)
                    {
                        Vector<float> a0 = Vector<float>.Zero, a1 = a0, a2 = a0, a3 = a0;
                        for (int b = firstBlock[c]; b < firstBlock[c + 1]; b++)
                        {
                            var d = row[b];
                            a0 += d * k[b];
                            a1 += d * k[blockCount + b];
                            a2 += d * k[2 * blockCount + b];
                            a3 += d * k[3 * blockCount + b];
                        }
                        Share(r, c, 0, a0);
                        Share(r, c, 1, a1);
                        if (n > 2) Share(r, c, 2, a2);
                        if (n > 3) Share(r, c, 3, a3);
                    }
                }
            }
            for (int w = 0; w < n; w++)
            {
                int pair = 0, wo = o + w * intercept.Length;
                for (int i = 0; i < classes; i++)
                {
                    for (int j = i + 1; j < classes; j++)
                    {
                        double sum = intercept[pair] + share[(w * rows + j - 1) * classes + i] + share[(w * rows + i) * classes + j];
                        if (Math.Abs(sum) < RecheckMargin) sum = DecideInDouble(pair, i, j, features, fo + w * width);
                        decision[wo + pair++] = sum;
                    }
                }
            }
        }

        /// <summary>
        /// Pairs whose float32 decision value lies this close to zero are decided again in double, so that every vote is cast
        /// as in double arithmetic (the C# network's; the ONNX export in Sentis stays in float32): float32 moves decision
        /// values by up to about 1e-3 (against LIBSVM's on the reference windows), and without the recheck 20 of 26,711
        /// real windows cast a vote otherwise (none changed the winner). About one window in a hundred has such a pair;
        /// each costs the two classes' kernels in double.
        /// </summary>
        public const double RecheckMargin = 0.01;

        /// <summary>
        /// Without SIMD lanes (<see cref="VectorMath.UseVectors"/>): one window in double, one support vector at a time, as
        /// LIBSVM computes it and as this class did before float32 lanes; the same votes as the lanes cast.
        /// </summary>
        void ScoreInDouble(double[] features, int fo, double[] decision, int o)
        {
            if (kernelInDouble == null) kernelInDouble = new double[vectors];
            for (int s = 0; s < vectors; s++) kernelInDouble[s] = KernelInDouble(s, features, fo);
            int rows = classes - 1;
            for (int r = 0; r < rows; r++)
                for (int c = 0; c < classes; c++)
                    share[r * classes + c] = VectorMath.Dot(dualCoef, r * vectors + start[c], kernelInDouble, start[c], count[c]);
            int pair = 0;
            for (int i = 0; i < classes; i++)
                for (int j = i + 1; j < classes; j++, pair++)
                    decision[o + pair] = intercept[pair] + share[(j - 1) * classes + i] + share[i * classes + j];
        }

        /// <summary>Pair (i, j)'s decision value in double, over the two classes' support vectors, as LIBSVM computes it.</summary>
        double DecideInDouble(int pair, int i, int j, double[] features, int fo)
        {
            double sum = intercept[pair];
            for (int s = start[i]; s < start[i] + count[i]; s++) sum += dualCoef[(j - 1) * vectors + s] * KernelInDouble(s, features, fo);
            for (int s = start[j]; s < start[j] + count[j]; s++) sum += dualCoef[i * vectors + s] * KernelInDouble(s, features, fo);
            return sum;
        }

        double KernelInDouble(int s, double[] features, int fo)
        {
            double b = gamma * VectorMath.Dot(supportVectors, s * width, features, fo, width) + coef0, p = b;
            for (int d = 1; d < degree; d++) p *= b;
            return p;
        }

        /// <summary>One window's shares, four coefficient rows at a time (each sum in the same order as with several windows).</summary>
        void VoteOne(int rows, int blockCount)
        {
            var k = new ReadOnlySpan<Vector<float>>(kernel, 0, blockCount);
            int r = 0;
            for (; r + 4 <= rows; r += 4)
            {
                var d0 = new ReadOnlySpan<Vector<float>>(dual, r * blockCount, blockCount);
                var d1 = new ReadOnlySpan<Vector<float>>(dual, (r + 1) * blockCount, blockCount);
                var d2 = new ReadOnlySpan<Vector<float>>(dual, (r + 2) * blockCount, blockCount);
                var d3 = new ReadOnlySpan<Vector<float>>(dual, (r + 3) * blockCount, blockCount);
                for (int c = 0; c < classes; c++)
                {
                    Vector<float> a0 = Vector<float>.Zero, a1 = a0, a2 = a0, a3 = a0;
                    for (int b = firstBlock[c]; b < firstBlock[c + 1]; b++)
                    {
                        var kb = k[b];
                        a0 += d0[b] * kb;
                        a1 += d1[b] * kb;
                        a2 += d2[b] * kb;
                        a3 += d3[b] * kb;
                    }
                    Share(r, c, 0, a0);
                    Share(r + 1, c, 0, a1);
                    Share(r + 2, c, 0, a2);
                    Share(r + 3, c, 0, a3);
                }
            }
            for (; r < rows; r++)
            {
                var row = new ReadOnlySpan<Vector<float>>(dual, r * blockCount, blockCount);
                for (int c = 0; c < classes; c++)
                {
                    var a = Vector<float>.Zero;
                    for (int b = firstBlock[c]; b < firstBlock[c + 1]; b++) a += row[b] * k[b];
                    Share(r, c, 0, a);
                }
            }
        }

        /// <summary>Window w's share of row r over class c: the lanes summed in double.</summary>
        void Share(int r, int c, int w, Vector<float> lanes)
        {
            Vector.Widen(lanes, out Vector<double> low, out Vector<double> high);
            share[(w * (classes - 1) + r) * classes + c] = Vector.Dot(low + high, Vector<double>.One);
        }
    }
}
