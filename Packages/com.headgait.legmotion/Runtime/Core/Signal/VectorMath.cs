using System.Numerics;

namespace HeadGait
{
    /// <summary>The inner loops every classifier spends its time in, in SIMD lanes where the runtime has them.</summary>
    public static class VectorMath
    {
        /// <summary>Sum of a[aStart + i] * b[bStart + i] for i in [0, n).</summary>
        public static double Dot(double[] a, int aStart, double[] b, int bStart, int n)
        {
            int lanes = Vector<double>.Count, simd = Vector.IsHardwareAccelerated ? n - n % lanes : 0;
            var acc = Vector<double>.Zero;
            for (int i = 0; i < simd; i += lanes) acc += new Vector<double>(a, aStart + i) * new Vector<double>(b, bStart + i);
            double dot = Vector.Dot(acc, Vector<double>.One);
            for (int i = simd; i < n; i++) dot += a[aStart + i] * b[bStart + i];
            return dot;
        }

        /// <summary>
        /// result[r] = the dot product of x with row r of a row-major matrix whose rows are n long, for r in [0, rows).
        /// Four rows at a time, so each lane of x is loaded once for four products.
        /// </summary>
        public static void MultiplyRows(double[] matrix, int rows, double[] x, int n, double[] result)
        {
            int lanes = Vector<double>.Count, simd = Vector.IsHardwareAccelerated ? n - n % lanes : 0, r = 0;
            for (; r + 4 <= rows; r += 4)
            {
                int a0 = r * n, a1 = a0 + n, a2 = a1 + n, a3 = a2 + n;
                Vector<double> s0 = Vector<double>.Zero, s1 = s0, s2 = s0, s3 = s0;
                for (int i = 0; i < simd; i += lanes)
                {
                    var xi = new Vector<double>(x, i);
                    s0 += new Vector<double>(matrix, a0 + i) * xi;
                    s1 += new Vector<double>(matrix, a1 + i) * xi;
                    s2 += new Vector<double>(matrix, a2 + i) * xi;
                    s3 += new Vector<double>(matrix, a3 + i) * xi;
                }
                double d0 = Vector.Dot(s0, Vector<double>.One), d1 = Vector.Dot(s1, Vector<double>.One);
                double d2 = Vector.Dot(s2, Vector<double>.One), d3 = Vector.Dot(s3, Vector<double>.One);
                for (int i = simd; i < n; i++)
                {
                    d0 += matrix[a0 + i] * x[i];
                    d1 += matrix[a1 + i] * x[i];
                    d2 += matrix[a2 + i] * x[i];
                    d3 += matrix[a3 + i] * x[i];
                }
                result[r] = d0;
                result[r + 1] = d1;
                result[r + 2] = d2;
                result[r + 3] = d3;
            }
            for (; r < rows; r++) result[r] = Dot(matrix, r * n, x, 0, n);
        }
    }
}
