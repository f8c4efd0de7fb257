using System;

namespace HeadGait
{
    /// <summary>
    /// Butterworth low-pass filter as cascaded second-order sections (bilinear transform with pre-warping), applied
    /// forwards and backwards for zero phase, the way scipy's sosfiltfilt does: odd extension at both ends and each
    /// section started in its steady state for the first sample, so the ends do not ring.
    /// </summary>
    public sealed class ButterworthLowPass
    {
        readonly double[][] sections; // b0, b1, b2, a1, a2 (a0 = 1)

        public ButterworthLowPass(int order, double cutoffHz, double sampleRateHz)
        {
            if (order < 2 || order % 2 != 0) throw new ArgumentException("Order must be even and at least 2.", nameof(order));
            if (!(cutoffHz > 0) || !(cutoffHz < sampleRateHz / 2)) throw new ArgumentException("Cutoff must lie between 0 and half the sample rate.", nameof(cutoffHz));
            Order = order;
            double fs2 = 2 * sampleRateHz;
            double warped = fs2 * Math.Tan(Math.PI * cutoffHz / sampleRateHz);
            sections = new double[order / 2][];
            for (int k = 0; k < order / 2; k++)
            {
                // Analog pole in the upper half plane, scaled to the warped cutoff.
                double angle = Math.PI * (2 * k + 1 + order) / (2.0 * order);
                double pr = warped * Math.Cos(angle), pi = warped * Math.Sin(angle);
                // z = (fs2 + p) / (fs2 - p)
                double nr = fs2 + pr, ni = pi, dr = fs2 - pr, di = -pi;
                double den = dr * dr + di * di;
                double zr = (nr * dr + ni * di) / den, zi = (ni * dr - nr * di) / den;
                double a1 = -2 * zr, a2 = zr * zr + zi * zi;
                double gain = (1 + a1 + a2) / 4; // unity gain at DC; both zeros at z = -1
                sections[k] = new[] { gain, 2 * gain, gain, a1, a2 };
            }
        }

        public int Order { get; }

        /// <summary>Zero-phase filtering of a whole signal; returns a new array.</summary>
        public double[] FilterForwardBackward(double[] x)
        {
            if (x == null) throw new ArgumentNullException(nameof(x));
            int n = x.Length;
            if (n == 0) return Array.Empty<double>();
            int pad = Math.Min(n - 1, 3 * (2 * sections.Length + 1));
            var ext = new double[n + 2 * pad];
            for (int i = 0; i < pad; i++) ext[i] = 2 * x[0] - x[pad - i];
            Array.Copy(x, 0, ext, pad, n);
            for (int i = 0; i < pad; i++) ext[pad + n + i] = 2 * x[n - 1] - x[n - 2 - i];
            Run(ext);
            Array.Reverse(ext);
            Run(ext);
            Array.Reverse(ext);
            var y = new double[n];
            Array.Copy(ext, pad, y, 0, n);
            return y;
        }

        void Run(double[] v)
        {
            foreach (var s in sections)
            {
                double b0 = s[0], b1 = s[1], b2 = s[2], a1 = s[3], a2 = s[4];
                // Steady state for a constant input equal to the first sample (transposed direct form II).
                double z2 = (b2 - a2) * v[0];
                double z1 = (b1 - a1) * v[0] + z2;
                for (int i = 0; i < v.Length; i++)
                {
                    double x = v[i];
                    double y = b0 * x + z1;
                    z1 = b1 * x - a1 * y + z2;
                    z2 = b2 * x - a2 * y;
                    v[i] = y;
                }
            }
        }
    }
}
