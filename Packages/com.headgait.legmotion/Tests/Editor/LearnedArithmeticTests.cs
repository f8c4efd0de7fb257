using System;
using System.Collections.Generic;
using System.IO;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>
    /// The learned classifiers' float32 SIMD arithmetic must answer as the plain double arithmetic it replaced (written out
    /// again here, loop by loop, from the model file): the same winning class on every window, the BLSTM's probabilities
    /// within 1e-5 and the SVM's votes equal, on generated recordings and, when the data is there, on every real one.
    /// </summary>
    public class LearnedArithmeticTests
    {
        static string ModelsFolder => TestData.ModelsFolder;

        static ModelFile Model(string file) => ModelFile.Load(Path.Combine(ModelsFolder, file));

        /// <summary>The SVM in double, one support vector at a time, as LIBSVM computes it.</summary>
        static double[] SvmVotes(ModelFile m, double[] x, int classes)
        {
            var nSupport = m.Tensor("n_support", classes);
            int width = x.Length, vectors = 0;
            foreach (var n in nSupport) vectors += (int)n;
            var sv = m.Tensor("support_vectors", vectors, width);
            var coef = m.Tensor("dual_coef", classes - 1, vectors);
            var intercept = m.Tensor("intercept", classes * (classes - 1) / 2);
            double gamma = m.NeedDouble("gamma"), coef0 = m.NeedDouble("coef0");
            int degree = m.NeedInt("degree", 1, 5);
            var kernel = new double[vectors];
            for (int s = 0; s < vectors; s++)
            {
                double dot = 0;
                for (int d = 0; d < width; d++) dot += sv[s * width + d] * x[d];
                kernel[s] = Math.Pow(gamma * dot + coef0, degree);
            }
            var start = new int[classes];
            for (int k = 1; k < classes; k++) start[k] = start[k - 1] + (int)nSupport[k - 1];
            var votes = new double[classes];
            int pair = 0;
            for (int i = 0; i < classes; i++)
                for (int j = i + 1; j < classes; j++)
                {
                    double sum = intercept[pair++];
                    for (int s = 0; s < (int)nSupport[i]; s++) sum += coef[(j - 1) * vectors + start[i] + s] * kernel[start[i] + s];
                    for (int s = 0; s < (int)nSupport[j]; s++) sum += coef[i * vectors + start[j] + s] * kernel[start[j] + s];
                    if (sum > 0) votes[i]++;
                    else votes[j]++;
                }
            return votes;
        }

        /// <summary>The BLSTM in double with Math.Exp and Math.Tanh, as PyTorch defines it.</summary>
        static double[] BlstmProbabilities(ModelFile m, double[] x, int inputs, int classes)
        {
            int hidden = m.ShapeOf("lstm_w_hh")[2], steps = x.Length / inputs, g4 = 4 * hidden;
            var ih = m.Tensor("lstm_w_ih", 2, g4, inputs);
            var hh = m.Tensor("lstm_w_hh", 2, g4, hidden);
            var b = m.Tensor("lstm_b", 2, g4);
            var joined = new double[2 * hidden];
            for (int dir = 0; dir < 2; dir++)
            {
                var h = new double[hidden];
                var c = new double[hidden];
                var gates = new double[g4];
                for (int n = 0; n < steps; n++)
                {
                    int t = dir == 0 ? n : steps - 1 - n;
                    for (int g = 0; g < g4; g++)
                    {
                        double z = b[dir * g4 + g];
                        for (int i = 0; i < inputs; i++) z += ih[(dir * g4 + g) * inputs + i] * x[t * inputs + i];
                        for (int j = 0; j < hidden; j++) z += hh[(dir * g4 + g) * hidden + j] * h[j];
                        gates[g] = z;
                    }
                    for (int j = 0; j < hidden; j++)
                    {
                        double ig = 1 / (1 + Math.Exp(-gates[j])), fg = 1 / (1 + Math.Exp(-gates[hidden + j]));
                        double cg = Math.Tanh(gates[2 * hidden + j]), og = 1 / (1 + Math.Exp(-gates[3 * hidden + j]));
                        c[j] = fg * c[j] + ig * cg;
                        h[j] = og * Math.Tanh(c[j]);
                    }
                }
                Array.Copy(h, 0, joined, dir * hidden, hidden);
            }
            var fcW = m.Tensor("fc_w", classes, 2 * hidden);
            var fcB = m.Tensor("fc_b", classes);
            var p = new double[classes];
            double max = double.NegativeInfinity, sum = 0;
            for (int k = 0; k < classes; k++)
            {
                p[k] = fcB[k];
                for (int j = 0; j < 2 * hidden; j++) p[k] += fcW[k * 2 * hidden + j] * joined[j];
                max = Math.Max(max, p[k]);
            }
            for (int k = 0; k < classes; k++) sum += p[k] = Math.Exp(p[k] - max);
            for (int k = 0; k < classes; k++) p[k] /= sum;
            return p;
        }

        static int ArgMax(IList<double> v)
        {
            int best = 0;
            for (int i = 1; i < v.Count; i++)
                if (v[i] > v[best]) best = i;
            return best;
        }

        /// <summary>Every <paramref name="every"/>-th window of the recordings through both arithmetics; returns the windows compared.</summary>
        static int Compare(IEnumerable<Recording> recordings, int every)
        {
            var svmFile = Model(GaitModels.SvmFile);
            var blstmFile = Model(GaitModels.BlstmFile);
            var svm = new SvmClassifier(svmFile);
            var blstm = new BlstmClassifier(blstmFile);
            int classes = svm.Segments.ClassCount, inputs = blstm.Features.Channels.Length, compared = 0, seen = 0;
            double worst = 0;
            foreach (var rec in recordings)
            {
                var pre = new StreamPreprocessor(new PreprocessorSettings { History = Math.Max(svm.WindowLength, blstm.WindowLength) });
                foreach (var s in rec.Samples)
                    pre.Push(s.Imu, w =>
                    {
                        if (seen++ % every != 0) return;
                        compared++;
                        var x = (double[])svm.Standardise(w).Clone();
                        var votes = svm.ScoreFeatures(x);
                        var expectedVotes = SvmVotes(svmFile, x, classes);
                        Assert.That(votes, Is.EqualTo(expectedVotes), $"{rec.Name}, window at {w.EndTime:F2} s: SVM votes");
                        var y = (double[])blstm.Standardise(w).Clone();
                        var p = blstm.ScoreFeatures(y);
                        var expected = BlstmProbabilities(blstmFile, y, inputs, classes);
                        Assert.That(ArgMax(p), Is.EqualTo(ArgMax(expected)), $"{rec.Name}, window at {w.EndTime:F2} s: BLSTM class");
                        for (int k = 0; k < classes; k++) worst = Math.Max(worst, Math.Abs(p[k] - expected[k]));
                    });
            }
            Assert.That(worst, Is.LessThanOrEqualTo(1e-5), "largest BLSTM probability difference");
            TestContext.WriteLine($"{compared} windows: the same SVM votes and BLSTM class on every one; largest BLSTM probability difference {worst:G3}");
            return compared;
        }

        [Test]
        public void FloatArithmeticAnswersAsDoubleOnTheGeneratedRecordings()
            => Assert.That(Compare(TestData.EvalSet(), 3), Is.GreaterThan(1000));

        /// <summary>Where the runtime has no SIMD lanes (Unity's Mono) the scalar paths answer the same.</summary>
        [Test]
        public void WithoutLanesTheScalarPathsAnswerAsDouble()
        {
            bool before = VectorMath.UseVectors;
            VectorMath.UseVectors = false;
            try
            {
                Assert.That(Compare(TestData.EvalSet(), 29), Is.GreaterThan(200));
            }
            finally
            {
                VectorMath.UseVectors = before;
            }
        }

        [Test]
        public void FloatArithmeticAnswersAsDoubleOnTheRealRecordings()
        {
            string folder = TestData.SharedData("real-train");
            var recordings = new List<Recording>();
            foreach (var f in Directory.GetFiles(folder, "*.csv")) recordings.Add(TestData.Load(f));
            // Every 12th window of every recording: about 15,000 windows through the double SVM and BLSTM.
            Assert.That(Compare(recordings, 12), Is.GreaterThan(10000));
        }

        /// <summary>The four committed models load without a byte array per value: under twice their size on disk.</summary>
        [Test]
        public void LoadingTheModelsAllocatesLessThanTwiceTheirSize()
        {
            string folder = ModelsFolder;
            long onDisk = 0;
            foreach (var f in new[] { GaitModels.ThresholdFile, GaitModels.CorrelationFile, GaitModels.SvmFile, GaitModels.BlstmFile })
                onDisk += new FileInfo(Path.Combine(folder, f)).Length;
            GaitModels.Load(folder); // JIT and type initialisation out of the count
            long before = GC.GetAllocatedBytesForCurrentThread();
            var models = GaitModels.Load(folder);
            long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
            Assert.That(models.Problems, Is.Empty);
            TestContext.WriteLine($"{allocated} bytes allocated to load {onDisk} bytes of models");
            Assert.That(allocated, Is.LessThan(2 * onDisk));
        }
    }
}
