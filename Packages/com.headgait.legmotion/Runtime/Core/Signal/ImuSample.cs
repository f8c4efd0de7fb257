using System;

namespace HeadGait
{
    /// <summary>
    /// One accelerometer reading of the headset, in the head frame used throughout the package:
    /// x forward, y left (lateral), z up; units m/s^2; specific force, so a headset at rest reads
    /// about (0, 0, +9.81). Time is in seconds on any monotonic clock.
    /// </summary>
    public readonly struct ImuSample
    {
        public readonly double Time;
        public readonly double X;
        public readonly double Y;
        public readonly double Z;

        public ImuSample(double time, double x, double y, double z)
        {
            Time = time;
            X = x;
            Y = y;
            Z = z;
        }

        /// <summary>Length of the specific force (m/s^2): about g at rest, whatever the head's tilt.</summary>
        public double Magnitude => Math.Sqrt(X * X + Y * Y + Z * Z);

        public bool IsFinite => IsFiniteNumber(Time) && IsFiniteNumber(X) && IsFiniteNumber(Y) && IsFiniteNumber(Z);

        internal static bool IsFiniteNumber(double v) => !double.IsNaN(v) && !double.IsInfinity(v);

        public override string ToString() => $"t={Time:F4} acc=({X:F3}, {Y:F3}, {Z:F3})";
    }
}
