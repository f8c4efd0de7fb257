using UnityEngine;

namespace HeadGait.Unity
{
    /// <summary>
    /// The clock <see cref="HeadImuSource"/> stamps head samples on, for whatever is recorded beside them (the calibration
    /// walk's ankle trackers, <see cref="WearerCalibration.AddAnklePoses"/>). With the Input System a sample keeps its
    /// event's time, which is on <c>Time.realtimeSinceStartupAsDouble</c>'s timeline (InputEvent.time); the legacy reader
    /// stamps the frame's <c>Time.unscaledTimeAsDouble</c>. The two clocks need not agree (real time since start-up counts
    /// a headset's sleep on XR and mobile platforms, by Unity's documentation; the frame clock is not documented to), and
    /// ankle poses on the other clock could lie outside the head stream: the walk was then fitted without them.
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
