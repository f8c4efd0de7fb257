using UnityEngine;

namespace HeadGait.Unity
{
    /// <summary>
    /// Decides whether a headset's reported acceleration is real. OpenXR exposes none and some runtimes (Oculus XR Plugin
    /// 4.x) fill the control with zeros, so a report counts only when the device has the control, its tracking state
    /// (where it has one) sets the Acceleration bit, and the vector is not exactly zero. Trust is earned by
    /// <see cref="RecoverCount"/> real reports in a row and lost after <see cref="ZeroSpan"/> seconds without one; it is
    /// re-earned whenever real data comes back, never latched.
    /// </summary>
    public sealed class ReportedAccelerationGate
    {
        /// <summary>UnityEngine.XR.InputTrackingState.Acceleration.</summary>
        public const int AccelerationTrackedBit = 1 << 4;

        int realInARow;
        double lastReal = double.NegativeInfinity;

        /// <summary>Seconds without a real report before the pose takes over (long enough to ride out one zero sample).</summary>
        public double ZeroSpan { get; set; } = 0.25;

        /// <summary>Real reports in a row before they are trusted (again).</summary>
        public int RecoverCount { get; set; } = 5;

        public bool TrustReported { get; private set; }

        /// <summary>How often trust was gained or lost.</summary>
        public int Switches { get; private set; }

        /// <summary>
        /// One report: <paramref name="present"/> false when the event carried no acceleration; <paramref name="trackingState"/>
        /// null when the device has no tracking-state control.
        /// </summary>
        public bool Observe(double time, bool present, Vector3 acceleration, int? trackingState)
        {
            bool real = present
                        && (!trackingState.HasValue || (trackingState.Value & AccelerationTrackedBit) != 0)
                        && !(acceleration.x == 0f && acceleration.y == 0f && acceleration.z == 0f);
            if (real)
            {
                realInARow++;
                lastReal = time;
                if (!TrustReported && realInARow >= RecoverCount) Set(true);
            }
            else
            {
                realInARow = 0;
                if (TrustReported && time - lastReal >= ZeroSpan) Set(false);
            }
            return TrustReported;
        }

        void Set(bool trust)
        {
            TrustReported = trust;
            Switches++;
        }
    }
}
