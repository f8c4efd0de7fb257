using System;
using System.Numerics;
using System.Runtime.CompilerServices;

namespace HeadGait
{
    /// <summary>The inner loops every classifier spends its time in, in SIMD lanes where the runtime has them.</summary>
    public static class VectorMath
    {
        /// <summary>
        /// Whether the learned classifiers run in <see cref="Vector{T}"/> lanes: only where the runtime turns them into SIMD
        /// instructions (<see cref="Vector.IsHardwareAccelerated"/>). Unity's Mono does not (its fix, Unity-Technologies/mono
        /// #2049, was reverted in #2114), and there a Vector&lt;T&gt; operation costs far more than the scalar loop, so
        /// the classifiers take their scalar paths instead. Settable to compare the two paths (tests, cost benchmark).
        /// </summary>
        public static bool UseVectors { get; set; } = Vector.IsHardwareAccelerated;

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

        // Odd numerator and even denominator of a [13/6] rational approximation of tanh on [-TanhLimit, TanhLimit], the
        // form Eigen uses for float32; beyond the limit tanh is +-1 within float precision. Largest error against
        // Math.Tanh about 3e-7 (VectorMathTests).
        const float TanhLimit = 7.90531110763549805f;
        const float A1 = 4.89352455891786e-03f, A3 = 6.37261928875436e-04f, A5 = 1.48572235717979e-05f;
        const float A7 = 5.12229709037114e-08f, A9 = -8.60467152213735e-11f, A11 = 2.00018790482477e-13f;
        const float A13 = -2.76076847742355e-16f;
        const float B0 = 4.89352518554385e-03f, B2 = 2.26843463243900e-03f, B4 = 1.18534705686654e-04f;
        const float B6 = 1.19825839466702e-06f;

        /// <summary>tanh of every lane, from a rational approximation (no exp): about 3e-7 from Math.Tanh.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector<float> Tanh(Vector<float> x)
        {
            x = Vector.Min(Vector.Max(x, new Vector<float>(-TanhLimit)), new Vector<float>(TanhLimit));
            var x2 = x * x;
            var p = x2 * new Vector<float>(A13) + new Vector<float>(A11);
            p = p * x2 + new Vector<float>(A9);
            p = p * x2 + new Vector<float>(A7);
            p = p * x2 + new Vector<float>(A5);
            p = p * x2 + new Vector<float>(A3);
            p = p * x2 + new Vector<float>(A1);
            var q = x2 * new Vector<float>(B6) + new Vector<float>(B4);
            q = q * x2 + new Vector<float>(B2);
            q = q * x2 + new Vector<float>(B0);
            return x * p / q;
        }

        /// <summary>The scalar form of <see cref="Tanh(Vector{float})"/>, the same arithmetic.</summary>
        public static float Tanh(float x)
        {
            x = Math.Min(Math.Max(x, -TanhLimit), TanhLimit);
            float x2 = x * x;
            float p = x2 * A13 + A11;
            p = p * x2 + A9;
            p = p * x2 + A7;
            p = p * x2 + A5;
            p = p * x2 + A3;
            p = p * x2 + A1;
            float q = x2 * B6 + B4;
            q = q * x2 + B2;
            q = q * x2 + B0;
            return x * p / q;
        }

        /// <summary>The scalar form of <see cref="Sigmoid(Vector{float})"/>.</summary>
        public static float Sigmoid(float x) => 0.5f + 0.5f * Tanh(0.5f * x);

        /// <summary>The logistic function of every lane, as 0.5 + 0.5 tanh(x / 2).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector<float> Sigmoid(Vector<float> x)
        {
            var half = new Vector<float>(0.5f);
            return half + half * Tanh(half * x);
        }
    }
}
