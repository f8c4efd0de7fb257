using UnityEngine;

namespace HeadGait.Unity
{
    /// <summary>
    /// The clock <see cref="HeadImuSource"/> stamps head samples on, for whatever is recorded beside them (the calibration
    /// walk's ankle trackers, <see cref="WearerCalibration.AddAnklePoses"/>). With the Input System a sample keeps its
    /// event's time, which is on <c>Time.realtimeSinceStartupAsDouble</c>'s timeline (InputEvent.time); the legacy reader
    /// stamps the frame's <c>Time.unscaledTimeAsDouble</c>. The two clocks part after the headset sleeps (real time counts
    /// the sleep on XR and mobile platforms), and ankle poses on the other clock then lie outside the head stream: the walk
    /// was fitted without them.
    /// </summary>
    public static class HeadClock
    {
        /// <summary>Now, on the head samples' clock (s).</summary>
        public static double Now =>
#if ENABLE_INPUT_SYSTEM
            Time.realtimeSinceStartupAsDouble;
#else
            Time.unscaledTimeAsDouble;
#endif
    }
}
