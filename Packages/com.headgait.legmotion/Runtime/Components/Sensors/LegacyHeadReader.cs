#if ENABLE_LEGACY_INPUT_MANAGER
using UnityEngine;
using UnityEngine.XR;

namespace HeadGait.Unity
{
    /// <summary>
    /// Fallback for projects whose Active Input Handling excludes the Input System: polls the legacy Input Manager and
    /// UnityEngine.XR once per frame, stamped with the frame's time (never the moment the script runs). One sample per
    /// frame at most; the Input System reader delivers every sensor event instead.
    /// </summary>
    sealed class LegacyHeadReader
    {
        readonly HeadSampleRouter router;
        UnityEngine.XR.InputDevice head;

        public LegacyHeadReader(HeadSampleRouter router) { this.router = router; }

        public void Poll(double frameTime)
        {
            if (router.WantsPhone)
            {
                router.Phone.CompensationDegrees = Input.compensateSensors ? PhoneAccelerometer.CompensationFor(Screen.orientation) : 0;
                router.OnAccelerometerEvent(frameTime, Input.acceleration);
                return;
            }
            if (!router.WantsHead) return;
            if (!head.isValid) head = InputDevices.GetDeviceAtXRNode(XRNode.Head);
            if (!head.isValid) return;
            var report = new HeadReport { Time = frameTime };
            report.HasPose = head.TryGetFeatureValue(CommonUsages.devicePosition, out report.Position)
                             & head.TryGetFeatureValue(CommonUsages.deviceRotation, out report.Rotation);
            report.HasAcceleration = head.TryGetFeatureValue(CommonUsages.deviceAcceleration, out report.Acceleration);
            if (head.TryGetFeatureValue(CommonUsages.trackingState, out InputTrackingState tracking)) report.TrackingState = (int)tracking;
            if (head.TryGetFeatureValue(CommonUsages.userPresence, out bool present)) report.UserPresent = present;
            router.OnHeadEvent(report);
        }
    }
}
#endif
