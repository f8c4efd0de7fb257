using HeadGait.Synthetic;
using NUnit.Framework;

namespace HeadGait.Tests
{
    public class VectorMathTests
    {
        [Test]
        public void MultiplyRowsEqualsEachRowsOwnSumAtEveryShape()
        {
            // Row counts around the four-row block and lengths around the SIMD lanes, so both remainders are exercised.
            var random = new DeterministicRandom(7);
            for (int rows = 0; rows <= 9; rows++)
            {
                for (int n = 1; n <= 13; n++)
                {
                    var matrix = new double[rows * n];
                    var x = new double[n];
                    for (int i = 0; i < matrix.Length; i++) matrix[i] = random.NextGaussian();
                    for (int i = 0; i < n; i++) x[i] = random.NextGaussian();
                    var result = new double[rows + 1];
                    result[rows] = 42; // past the rows: untouched
                    VectorMath.MultiplyRows(matrix, rows, x, n, result);
                    for (int r = 0; r < rows; r++)
                    {
                        double expected = 0;
                        for (int i = 0; i < n; i++) expected += matrix[r * n + i] * x[i];
                        Assert.That(result[r], Is.EqualTo(expected).Within(1e-12), $"row {r} of {rows}, length {n}");
                    }
                    Assert.That(result[rows], Is.EqualTo(42));
                }
            }
        }

        /// <summary>The learned classifiers' activations: within 5e-7 (a few float32 steps) of Math.Tanh and the logistic, lanes and scalar alike.</summary>
        [Test]
        public void TanhAndSigmoidFollowTheExactFunctions()
        {
            int lanes = System.Numerics.Vector<float>.Count;
            var values = new float[lanes];
            double worstTanh = 0, worstSigmoid = 0;
            for (int i = -40000; i <= 40000; i += lanes)
            {
                for (int l = 0; l < lanes; l++) values[l] = (i + l) * 0.0005f; // -20 .. 20
                var t = VectorMath.Tanh(new System.Numerics.Vector<float>(values));
                var s = VectorMath.Sigmoid(new System.Numerics.Vector<float>(values));
                for (int l = 0; l < lanes; l++)
                {
                    double v = values[l];
                    worstTanh = System.Math.Max(worstTanh, System.Math.Abs(t[l] - System.Math.Tanh(v)));
                    worstSigmoid = System.Math.Max(worstSigmoid, System.Math.Abs(s[l] - 1 / (1 + System.Math.Exp(-v))));
                    Assert.That(VectorMath.Tanh(values[l]), Is.EqualTo(t[l]), "scalar and lanes alike");
                    Assert.That(VectorMath.Sigmoid(values[l]), Is.EqualTo(s[l]), "scalar and lanes alike");
                }
            }
            Assert.That(worstTanh, Is.LessThan(5e-7));
            Assert.That(worstSigmoid, Is.LessThan(5e-7));
        }
    }
}
