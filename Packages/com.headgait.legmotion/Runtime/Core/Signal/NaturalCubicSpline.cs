using System;

namespace HeadGait
{
    /// <summary>Natural cubic spline through (x, y) with strictly increasing x; values and first derivatives anywhere.</summary>
    public sealed class NaturalCubicSpline
    {
        readonly double[] x;
        readonly double[] y;
        readonly double[] m; // second derivatives at the knots

        public NaturalCubicSpline(double[] x, double[] y)
        {
            if (x == null || y == null || x.Length != y.Length) throw new ArgumentException("x and y must have the same length.");
            if (x.Length < 2) throw new ArgumentException("A spline needs at least two points.");
            for (int i = 1; i < x.Length; i++)
                if (!(x[i] > x[i - 1])) throw new ArgumentException("Spline knots must increase strictly.");
            this.x = (double[])x.Clone();
            this.y = (double[])y.Clone();
            int n = x.Length;
            m = new double[n];
            if (n < 3) return;
            // Tridiagonal system for the interior second derivatives (Thomas algorithm).
            var c = new double[n];
            var d = new double[n];
            for (int i = 1; i < n - 1; i++)
            {
                double h0 = x[i] - x[i - 1], h1 = x[i + 1] - x[i];
                double a = h0, b = 2 * (h0 + h1), cc = h1;
                double r = 6 * ((y[i + 1] - y[i]) / h1 - (y[i] - y[i - 1]) / h0);
                double denom = b - a * c[i - 1];
                c[i] = cc / denom;
                d[i] = (r - a * d[i - 1]) / denom;
            }
            for (int i = n - 2; i >= 1; i--) m[i] = d[i] - c[i] * m[i + 1];
        }

        int Segment(double t)
        {
            int i = Array.BinarySearch(x, t);
            if (i < 0) i = ~i - 1;
            if (i < 0) i = 0;
            if (i > x.Length - 2) i = x.Length - 2;
            return i;
        }

        public double Value(double t)
        {
            int i = Segment(t);
            double h = x[i + 1] - x[i], a = (x[i + 1] - t) / h, b = (t - x[i]) / h;
            return a * y[i] + b * y[i + 1] + ((a * a * a - a) * m[i] + (b * b * b - b) * m[i + 1]) * h * h / 6;
        }

        public double Derivative(double t)
        {
            int i = Segment(t);
            double h = x[i + 1] - x[i], a = (x[i + 1] - t) / h, b = (t - x[i]) / h;
            return (y[i + 1] - y[i]) / h + (-(3 * a * a - 1) * m[i] + (3 * b * b - 1) * m[i + 1]) * h / 6;
        }
    }
}
