using UnityEngine;

namespace HeadGait.Unity
{
    /// <summary>One head sample for the pipeline: specific force in the head frame (x forward, y left, z up), m/s^2.</summary>
    public readonly struct HeadSample
    {
        public HeadSample(double time, Vector3 specificForce, double lag)
        {
            Time = time;
            SpecificForce = specificForce;
            Lag = lag;
        }

        /// <summary>The input event's time (s, realtimeSinceStartup timeline).</summary>
        public double Time { get; }

        public Vector3 SpecificForce { get; }

        /// <summary>How far behind <see cref="Time"/> the motion it describes lies (s): 0 for an accelerometer.</summary>
        public double Lag { get; }
    }
}
