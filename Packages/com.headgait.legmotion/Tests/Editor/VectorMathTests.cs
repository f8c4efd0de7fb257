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
    }
}
