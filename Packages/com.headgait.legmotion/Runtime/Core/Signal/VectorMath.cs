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
    }
}
