using System;
using UnityEngine;

namespace HeadGait.Unity
{
    /// <summary>
    /// Where a head source's decoded input events go: the readers (Input System events, or the legacy per-frame poll)
    /// only decode controls and call these methods, so tests drive exactly the path a device's events take. Events that
    /// do not belong to the chosen <see cref="HeadImuMode"/> are ignored.
    /// </summary>
    public sealed class HeadSampleRouter
    {
        readonly Action<HeadSample> sink;

        public HeadSampleRouter(HeadImuMode mode, PhoneMounting mounting, Action<HeadSample> sink)
        {
            this.sink = sink ?? throw new ArgumentNullException(nameof(sink));
            Mode = mode;
            Head = new XrHeadStream(allowReported: mode != HeadImuMode.XRDevicePose);
            Phone = new PhoneAccelerometer(mounting);
        }

        public HeadImuMode Mode { get; }
        public XrHeadStream Head { get; }
        public PhoneAccelerometer Phone { get; }

        /// <summary>Samples handed on.</summary>
        public int Delivered { get; private set; }

        public bool WantsHead => Mode == HeadImuMode.XRDevice || Mode == HeadImuMode.XRDevicePose;
        public bool WantsPhone => Mode == HeadImuMode.MobileInput;

        public void OnHeadEvent(in HeadReport report)
        {
            if (WantsHead && Head.Push(report, out var s)) Deliver(s);
        }

        public void OnAccelerometerEvent(double time, Vector3 readingInG)
        {
            if (WantsPhone && Phone.PushAccelerometer(time, readingInG, out var s)) Deliver(s);
        }

        public void OnGravityEvent(Vector3 gravityInG)
        {
            if (WantsPhone) Phone.PushGravity(gravityInG);
        }

        public void OnLinearAccelerationEvent(double time, Vector3 linearInG)
        {
            if (WantsPhone && Phone.PushLinearAcceleration(time, linearInG, out var s)) Deliver(s);
        }

        void Deliver(in HeadSample s)
        {
            Delivered++;
            sink(s);
        }
    }
}
