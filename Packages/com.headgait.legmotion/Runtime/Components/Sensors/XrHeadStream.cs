using UnityEngine;

namespace HeadGait.Unity
{
    /// <summary>What one head-device input event carried (Unity tracking space: left-handed, y up, metres).</summary>
    public struct HeadReport
    {
        public double Time;
        public bool HasPose;
        public Vector3 Position;
        public Quaternion Rotation;
        /// <summary>False when the event (or the device) has no acceleration control.</summary>
        public bool HasAcceleration;
        /// <summary>Linear acceleration in tracking space, gravity removed (XR deviceAcceleration / centerEyeAcceleration).</summary>
        public Vector3 Acceleration;
        /// <summary>UnityEngine.XR.InputTrackingState bits, or null when the device reports none.</summary>
        public int? TrackingState;
        /// <summary>
        /// Whether someone wears the headset (XR userPresence: its proximity sensor), or null when the device reports none.
        /// False while it is being put on or taken off, or lies on a table: those motions are no walk.
        /// </summary>
        public bool? UserPresent;
    }

    /// <summary>
    /// A headset's head samples: its reported acceleration while <see cref="ReportedAccelerationGate"/> trusts it, otherwise
    /// acceleration from the tracked pose through <see cref="PoseAccelerationEstimator"/>, which is fed every pose so it is
    /// ready the moment it is needed. Every sample carries its event's time (never the time the script ran) and its lag.
    /// While the headset says nobody wears it (<see cref="HeadReport.UserPresent"/> false, once it has said someone does) no
    /// sample comes out: the pipeline meets a hole, the avatar stands, and a fresh window starts once it is worn again, so
    /// putting it on and taking it off never reach the classifier (the gate and the pose estimate still follow every
    /// report, ready when it is worn).
    /// </summary>
    public sealed class XrHeadStream
    {
        /// <summary>UnityEngine.XR.InputTrackingState.Position.</summary>
        const int PositionTrackedBit = 1 << 0;

        readonly EventTimeline timeline = new EventTimeline();
        readonly ReportedAccelerationGate gate = new ReportedAccelerationGate();
        readonly PoseAccelerationEstimator fromPose = new PoseAccelerationEstimator();
        Quaternion rotation = Quaternion.identity;
        bool hasRotation;
        bool presenceSeen; // a runtime without the sensor may expose the control and never set it: false counts once it said worn

        /// <param name="allowReported">False: always derive acceleration from the pose.</param>
        public XrHeadStream(bool allowReported = true) { AllowReported = allowReported; }

        public bool AllowReported { get; set; }
        public EventTimeline Timeline => timeline;
        public ReportedAccelerationGate Gate => gate;

        /// <summary>A pose rate too low for the pose path (once), for the caller to log; null when none is new.</summary>
        public string TakeWarning() => fromPose.TakeWarning();

        /// <summary>True while samples come from the tracked pose.</summary>
        public bool UsingPose => !(AllowReported && gate.TrustReported);

        public bool Push(in HeadReport report, out HeadSample sample)
        {
            sample = default;
            if (!timeline.Accept(report.Time)) return false;

            bool poseTracked = report.HasPose && (!report.TrackingState.HasValue || (report.TrackingState.Value & PositionTrackedBit) != 0);
            ImuSample fromPoseSample = default;
            bool havePoseSample = false;
            if (report.HasPose)
            {
                rotation = report.Rotation;
                hasRotation = true;
            }
            if (poseTracked)
            {
                Vector3 p = report.Position;
                Quaternion q = report.Rotation;
                havePoseSample = fromPose.Push(report.Time, p.x, p.y, p.z, q.x, q.y, q.z, q.w, out fromPoseSample);
            }

            bool trust = gate.Observe(report.Time, report.HasAcceleration, report.Acceleration, report.TrackingState);
            if (report.UserPresent == true) presenceSeen = true;
            if (report.UserPresent == false && presenceSeen) return false;
            if (AllowReported && trust && report.HasAcceleration && hasRotation)
            {
                sample = new HeadSample(report.Time, HeadAxes.SpecificForceFromLinear(report.Acceleration, rotation), 0);
                return true;
            }
            if (!havePoseSample) return false;
            sample = new HeadSample(fromPoseSample.Time, new Vector3((float)fromPoseSample.X, (float)fromPoseSample.Y, (float)fromPoseSample.Z), fromPose.Lag);
            return true;
        }
    }
}
