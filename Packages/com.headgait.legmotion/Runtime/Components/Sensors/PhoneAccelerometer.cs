using UnityEngine;

namespace HeadGait.Unity
{
    /// <summary>
    /// A phone in a headset: turns Unity's accelerometer readings (g, along gravity, phone axes; see
    /// <see cref="HeadAxes.SpecificForceFromPhone"/>) into head-frame samples, each with its own event time. Reads either
    /// an accelerometer or a linear-acceleration sensor plus a gravity sensor (their sum is the accelerometer's reading).
    /// </summary>
    public sealed class PhoneAccelerometer
    {
        readonly EventTimeline timeline = new EventTimeline();
        Vector3 gravity;
        bool hasGravity;

        public PhoneAccelerometer(PhoneMounting mounting = PhoneMounting.LandscapeLeft) { Mounting = mounting; }

        public PhoneMounting Mounting { get; set; }

        /// <summary>
        /// Degrees (counter-clockwise) by which Unity has already turned the readings into screen axes: the Input System's
        /// compensateForScreenOrientation (or legacy Input.compensateSensors) rotates by the screen orientation; 0 when off.
        /// </summary>
        public int CompensationDegrees { get; set; }

        public EventTimeline Timeline => timeline;

        /// <summary>The turn Unity's orientation compensation applies for a screen orientation (CompensateDirectionProcessor).</summary>
        public static int CompensationFor(ScreenOrientation orientation)
        {
            switch (orientation)
            {
                case ScreenOrientation.PortraitUpsideDown: return 180;
                case ScreenOrientation.LandscapeLeft: return 90;
                case ScreenOrientation.LandscapeRight: return 270;
                default: return 0;
            }
        }

        public bool PushAccelerometer(double time, Vector3 readingInG, out HeadSample sample)
        {
            sample = default;
            if (!timeline.Accept(time)) return false;
            sample = new HeadSample(time, HeadAxes.SpecificForceFromPhone(readingInG, (int)Mounting - CompensationDegrees), 0);
            return true;
        }

        /// <summary>Remembers the gravity sensor's latest reading (g); it changes slowly, so it is paired with later linear samples.</summary>
        public void PushGravity(Vector3 gravityInG)
        {
            gravity = gravityInG;
            hasGravity = true;
        }

        /// <summary>A linear-acceleration reading (g, gravity removed): a sample once a gravity reading is known.</summary>
        public bool PushLinearAcceleration(double time, Vector3 linearInG, out HeadSample sample)
        {
            sample = default;
            if (!hasGravity) return false;
            return PushAccelerometer(time, linearInG + gravity, out sample);
        }
    }
}
