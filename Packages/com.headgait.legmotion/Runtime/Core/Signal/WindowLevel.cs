using System;

namespace HeadGait
{
    /// <summary>
    /// Turns a window's head frame towards level: by the smallest rotation that brings the mean specific force of a stretch
    /// of the window to within a tolerated tilt of +z. A sensor worn tilted, or a head looking down at its legs, turns part
    /// of the vertical bounce into the forward and sideways channels; over a second of walking the dynamic parts average
    /// out and the mean is gravity. Tilts up to the tolerance are left as they are: the heads in the training data lean
    /// that much while they walk, and the learned classifiers know them so.
    /// </summary>
    public readonly struct WindowLevel
    {
        // Rows of the rotation: forward, lateral, vertical as combinations of the head's (x, y, z).
        readonly double r00, r01, r02, r10, r11, r12, r20, r21, r22;

        /// <summary>A rotation by angle (cos <paramref name="c"/>, sin <paramref name="s"/>) about the horizontal unit axis (kx, ky, 0).</summary>
        WindowLevel(double kx, double ky, double c, double s)
        {
            // Rodrigues: R = c I + s [k]x + (1 - c) k k^T.
            double v = 1 - c;
            r00 = c + v * kx * kx; r01 = v * kx * ky; r02 = s * ky;
            r10 = v * kx * ky; r11 = c + v * ky * ky; r12 = -s * kx;
            r20 = -s * ky; r21 = s * kx; r22 = c;
        }

        /// <summary>
        /// The tilt (degrees) the learned classifiers and THR's and the learned walking gates tolerate before levelling: nine
        /// in ten walking seconds of the real training data lean less (median 5.5, 95th percentile 17.8 degrees).
        /// </summary>
        public const double ToleranceDegrees = 15;

        /// <summary>The identity: the window is left as it is.</summary>
        public static WindowLevel None => new WindowLevel(1, 0, 1, 0);

        /// <summary>
        /// The levelling for samples <paramref name="first"/> to the window's newest: their mean specific force is turned
        /// to <paramref name="toleranceDegrees"/> from +z when it leans further (0: straight up). A flat mean, or one
        /// pointing down, leaves the window as it is.
        /// </summary>
        public static WindowLevel Of(SignalWindow w, int first, double toleranceDegrees = 0)
        {
            double x = 0, y = 0, z = 0;
            for (int i = Math.Max(0, first); i < w.Length; i++)
            {
                x += w.Forward[i];
                y += w.Lateral[i];
                z += w.Vertical[i];
            }
            double norm = Math.Sqrt(x * x + y * y + z * z), horizontal = Math.Sqrt(x * x + y * y);
            if (!(norm > 1e-6) || !(horizontal > 1e-9 * norm) || z <= 0) return None;
            double turn = Math.Atan2(horizontal, z) - toleranceDegrees * Math.PI / 180;
            if (turn <= 0) return None;
            // About the axis mean x up, normalised: (y, -x, 0) / horizontal.
            return new WindowLevel(y / horizontal, -x / horizontal, Math.Cos(turn), Math.Sin(turn));
        }

        /// <summary>Whether <paramref name="degrees"/> is a tolerance a levelling can have: 0..90.</summary>
        public static bool IsTolerance(double degrees) => degrees >= 0 && degrees <= 90;

        /// <summary>Reads a tolerance as the model files write it (invariant culture, 0..90 degrees).</summary>
        public static bool TryParseTolerance(string text, out double degrees)
            => double.TryParse(text, System.Globalization.NumberStyles.Float, System.Globalization.CultureInfo.InvariantCulture, out degrees) && IsTolerance(degrees);

        /// <summary>Sample <paramref name="i"/> of a channel of the levelled window (SMV, which no turn changes, as it is).</summary>
        public double Read(SignalWindow w, WindowChannel channel, int i)
        {
            switch (channel)
            {
                case WindowChannel.Smv: return w.Smv[i];
                case WindowChannel.Lateral: return Lateral(w, i);
                case WindowChannel.Forward: return Forward(w, i);
                default: return Vertical(w, i);
            }
        }

        public double Forward(SignalWindow w, int i) => r00 * w.Forward[i] + r01 * w.Lateral[i] + r02 * w.Vertical[i];
        public double Lateral(SignalWindow w, int i) => r10 * w.Forward[i] + r11 * w.Lateral[i] + r12 * w.Vertical[i];
        public double Vertical(SignalWindow w, int i) => r20 * w.Forward[i] + r21 * w.Lateral[i] + r22 * w.Vertical[i];
    }
}
