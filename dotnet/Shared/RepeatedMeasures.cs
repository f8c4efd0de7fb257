using System;
using System.Collections.Generic;
using MathNet.Numerics.Distributions;

namespace HeadGait.Tooling
{
    /// <summary>One-way repeated-measures ANOVA with the Greenhouse-Geisser correction.</summary>
    public sealed class RepeatedMeasuresAnova
    {
        public int Subjects, Conditions;
        public double SsConditions, SsSubjects, SsError;
        public double DfConditions, DfError;
        public double F, P;
        /// <summary>Greenhouse-Geisser epsilon (1 = sphericity holds; 1/(k-1) its lower bound).</summary>
        public double Epsilon;
        public double PCorrected;
        /// <summary>Partial eta squared: SS conditions / (SS conditions + SS error).</summary>
        public double PartialEtaSquared;

        /// <summary>
        /// data[subject][condition], complete cases only. Sums of squares split into conditions, subjects and error
        /// (the subject-by-condition interaction); F = MS conditions / MS error; p from the F distribution, and again with
        /// both degrees of freedom multiplied by the Greenhouse-Geisser epsilon from the conditions' covariance matrix.
        /// </summary>
        public static RepeatedMeasuresAnova Compute(IReadOnlyList<double[]> data)
        {
            int n = data.Count;
            if (n < 2) throw new ArgumentException("A repeated-measures ANOVA needs at least two subjects.");
            int k = data[0].Length;
            if (k < 2) throw new ArgumentException("A repeated-measures ANOVA needs at least two conditions.");
            foreach (var row in data)
                if (row.Length != k) throw new ArgumentException("Every subject needs a value for every condition.");
            double grand = 0;
            var conditionMean = new double[k];
            var subjectMean = new double[n];
            for (int i = 0; i < n; i++)
            for (int j = 0; j < k; j++)
            {
                grand += data[i][j];
                conditionMean[j] += data[i][j] / n;
                subjectMean[i] += data[i][j] / k;
            }
            grand /= n * k;
            var a = new RepeatedMeasuresAnova { Subjects = n, Conditions = k };
            double total = 0;
            for (int i = 0; i < n; i++)
            for (int j = 0; j < k; j++) total += (data[i][j] - grand) * (data[i][j] - grand);
            for (int j = 0; j < k; j++) a.SsConditions += n * (conditionMean[j] - grand) * (conditionMean[j] - grand);
            for (int i = 0; i < n; i++) a.SsSubjects += k * (subjectMean[i] - grand) * (subjectMean[i] - grand);
            a.SsError = Math.Max(0, total - a.SsConditions - a.SsSubjects);
            a.DfConditions = k - 1;
            a.DfError = (k - 1) * (n - 1);
            double msError = a.SsError / a.DfError;
            a.F = msError > 0 ? a.SsConditions / a.DfConditions / msError : double.PositiveInfinity;
            a.P = double.IsPositiveInfinity(a.F) ? 0 : 1 - FisherSnedecor.CDF(a.DfConditions, a.DfError, a.F);
            a.PartialEtaSquared = a.SsConditions + a.SsError > 0 ? a.SsConditions / (a.SsConditions + a.SsError) : 0;
            a.Epsilon = GreenhouseGeisser(data, conditionMean);
            double e = a.Epsilon;
            a.PCorrected = double.IsPositiveInfinity(a.F) ? 0 : 1 - FisherSnedecor.CDF(e * a.DfConditions, e * a.DfError, a.F);
            return a;
        }

        /// <summary>epsilon = trace(S)^2 / ((k - 1) trace(S S)) with S the double-centred covariance matrix of the conditions.</summary>
        static double GreenhouseGeisser(IReadOnlyList<double[]> data, double[] means)
        {
            int n = data.Count, k = means.Length;
            var cov = new double[k, k];
            for (int a = 0; a < k; a++)
            for (int b = 0; b < k; b++)
            {
                double s = 0;
                for (int i = 0; i < n; i++) s += (data[i][a] - means[a]) * (data[i][b] - means[b]);
                cov[a, b] = s / (n - 1);
            }
            var rowMean = new double[k];
            double all = 0;
            for (int a = 0; a < k; a++)
            {
                for (int b = 0; b < k; b++) rowMean[a] += cov[a, b] / k;
                all += rowMean[a] / k;
            }
            var centred = new double[k, k];
            for (int a = 0; a < k; a++)
            for (int b = 0; b < k; b++) centred[a, b] = cov[a, b] - rowMean[a] - rowMean[b] + all;
            double trace = 0, traceSq = 0;
            for (int a = 0; a < k; a++)
            {
                trace += centred[a, a];
                for (int b = 0; b < k; b++) traceSq += centred[a, b] * centred[b, a];
            }
            if (traceSq <= 0) return 1;
            double eps = trace * trace / ((k - 1) * traceSq);
            return Math.Max(1.0 / (k - 1), Math.Min(1, eps));
        }
    }

    /// <summary>A paired t-test between two conditions, with its Bonferroni-corrected p.</summary>
    public sealed class PairedComparison
    {
        public string A, B;
        public double MeanDifference, T, Df, P, PBonferroni;

        public static PairedComparison Compute(string a, string b, IReadOnlyList<double> x, IReadOnlyList<double> y, int comparisons)
        {
            int n = x.Count;
            if (n != y.Count || n < 2) throw new ArgumentException("A paired t-test needs at least two pairs.");
            double mean = 0;
            for (int i = 0; i < n; i++) mean += (x[i] - y[i]) / n;
            double ss = 0;
            for (int i = 0; i < n; i++) ss += (x[i] - y[i] - mean) * (x[i] - y[i] - mean);
            double sd = Math.Sqrt(ss / (n - 1));
            var c = new PairedComparison { A = a, B = b, MeanDifference = mean, Df = n - 1 };
            c.T = sd > 0 ? mean / (sd / Math.Sqrt(n)) : (mean == 0 ? 0 : double.PositiveInfinity * Math.Sign(mean));
            c.P = double.IsInfinity(c.T) ? 0 : 2 * (1 - StudentT.CDF(0, 1, c.Df, Math.Abs(c.T)));
            c.PBonferroni = Math.Min(1, c.P * comparisons);
            return c;
        }
    }
}
