using HeadGait.Unity;
using NUnit.Framework;
using UnityEngine;

namespace HeadGait.Tests
{
    /// <summary>
    /// A phone in a headset, screen towards the eyes. Readings are what Unity reports: g, along gravity, in the phone's
    /// right-handed axes (portrait: x right, y up, z out of the screen, i.e. towards the user).
    /// </summary>
    public class PhoneAccelerometerTests
    {
        const float G = HeadAxes.StandardGravity;

        /// <summary>The reading a phone gives for a head-frame specific force (forward, left, up), for each mounting.</summary>
        static Vector3 ReadingFor(Vector3 head, PhoneMounting mounting)
        {
            float forward = head.x, left = head.y, up = head.z, right = -left;
            float fx, fy;
            switch (mounting)
            {
                case PhoneMounting.Portrait: fx = right; fy = up; break;            // x right, y up
                case PhoneMounting.LandscapeLeft: fx = up; fy = left; break;        // top of the phone to the left
                case PhoneMounting.PortraitUpsideDown: fx = left; fy = -up; break;
                default: fx = -up; fy = right; break;                               // LandscapeRight: top to the right
            }
            float fz = -forward;                                                    // the screen faces backwards
            return new Vector3(-fx / G, -fy / G, -fz / G);
        }

        static Vector3 Convert(Vector3 reading, PhoneMounting mounting, int compensation = 0)
        {
            var phone = new PhoneAccelerometer(mounting) { CompensationDegrees = compensation };
            Assert.That(phone.PushAccelerometer(1.0, reading, out var s), Is.True);
            return s.SpecificForce;
        }

        static void AssertClose(Vector3 actual, Vector3 expected)
        {
            Assert.That(actual.x, Is.EqualTo(expected.x).Within(1e-4f), "forward");
            Assert.That(actual.y, Is.EqualTo(expected.y).Within(1e-4f), "left");
            Assert.That(actual.z, Is.EqualTo(expected.z).Within(1e-4f), "up");
        }

        [Test]
        public void UprightPortraitPhoneAtRestReadsOneGUp()
        {
            // Unity: a phone standing upright in portrait reads (0, -1, 0) g.
            AssertClose(Convert(new Vector3(0, -1, 0), PhoneMounting.Portrait), new Vector3(0, 0, G));
        }

        [Test]
        public void LandscapeLeftPhoneAtRestReadsOneGUp()
        {
            // Cardboard: top of the phone to the left, so gravity pulls along the phone's -x.
            AssertClose(Convert(new Vector3(-1, 0, 0), PhoneMounting.LandscapeLeft), new Vector3(0, 0, G));
        }

        [Test]
        public void SidewaysPushToTheLeftIsPositiveLateralInLandscape()
        {
            // Pushed 2 m/s^2 towards the user's left = towards the top of a LandscapeLeft phone (its +y).
            var reading = new Vector3(-1, -2 / G, 0);
            AssertClose(Convert(reading, PhoneMounting.LandscapeLeft), new Vector3(0, 2, G));
            // The same push with the phone the other way round (LandscapeRight: top to the right) is still left.
            AssertClose(Convert(ReadingFor(new Vector3(0, 2, G), PhoneMounting.LandscapeRight), PhoneMounting.LandscapeRight), new Vector3(0, 2, G));
        }

        [Test]
        public void ForwardPushIsPositiveForwardInEveryMounting()
        {
            // Accelerating forward: specific force along the phone's -z (into the screen); Unity reads minus that, +z.
            foreach (PhoneMounting m in new[] { PhoneMounting.Portrait, PhoneMounting.LandscapeLeft, PhoneMounting.PortraitUpsideDown, PhoneMounting.LandscapeRight })
            {
                var head = new Vector3(1.5f, 0, G);
                var reading = ReadingFor(head, m);
                Assert.That(reading.z, Is.EqualTo(1.5f / G).Within(1e-6f), $"{m}: a forward push reads +z (out of the screen, towards the user)");
                AssertClose(Convert(reading, m), head);
            }
        }

        [Test]
        public void AnyHeadForceRoundTripsThroughEachMounting()
        {
            var head = new Vector3(0.7f, -1.3f, 8.9f);
            foreach (PhoneMounting m in new[] { PhoneMounting.Portrait, PhoneMounting.LandscapeLeft, PhoneMounting.PortraitUpsideDown, PhoneMounting.LandscapeRight })
                AssertClose(Convert(ReadingFor(head, m), m), head);
        }

        [Test]
        public void ScreenCompensatedReadingsGiveTheSameHeadForce()
        {
            // With compensateForScreenOrientation the Input System turns readings by Euler(0, 0, 90) in LandscapeLeft:
            // (x, y) -> (-y, x), i.e. into screen axes.
            var head = new Vector3(0.4f, 2f, G);
            var raw = ReadingFor(head, PhoneMounting.LandscapeLeft);
            var screen = new Vector3(-raw.y, raw.x, raw.z);
            int compensation = PhoneAccelerometer.CompensationFor(ScreenOrientation.LandscapeLeft);
            Assert.That(compensation, Is.EqualTo(90));
            AssertClose(Convert(screen, PhoneMounting.LandscapeLeft, compensation), head);
            Assert.That(PhoneAccelerometer.CompensationFor(ScreenOrientation.LandscapeRight), Is.EqualTo(270));
            Assert.That(PhoneAccelerometer.CompensationFor(ScreenOrientation.Portrait), Is.EqualTo(0));
        }

        [Test]
        public void LinearPlusGravityEqualsTheAccelerometer()
        {
            var phone = new PhoneAccelerometer(PhoneMounting.LandscapeLeft);
            Assert.That(phone.PushLinearAcceleration(0.00, new Vector3(0, -0.2f, 0), out _), Is.False, "no gravity reading yet");
            phone.PushGravity(new Vector3(-1, 0, 0));
            Assert.That(phone.PushLinearAcceleration(0.01, new Vector3(0, -0.2f, 0), out var s), Is.True);
            Assert.That(s.Time, Is.EqualTo(0.01));
            AssertClose(s.SpecificForce, new Vector3(0, 0.2f * G, G));
        }

        [Test]
        public void AClockThatMovesFarBackIsPassedOnNotRefusedForEver()
        {
            // Regression: every event older than the last accepted one was refused, so a sensor clock that restarted
            // froze the source until it caught up again. Far-back steps now go to the pipeline's clock policy.
            var phone = new PhoneAccelerometer(PhoneMounting.LandscapeLeft);
            var kept = new System.Collections.Generic.List<double>();
            foreach (double t in new[] { 100.00, 100.01, 100.02, 3.00, 3.01, 2.98, 3.02 })
                if (phone.PushAccelerometer(t, new Vector3(-1, 0, 0), out var s)) kept.Add(s.Time);
            Assert.That(kept, Is.EqualTo(new[] { 100.00, 100.01, 100.02, 3.00, 3.01, 3.02 }));
            Assert.That(phone.Timeline.ClockRestarts, Is.EqualTo(1));
            Assert.That(phone.Timeline.OutOfOrder, Is.EqualTo(1), "a late event on the new clock is still refused");
        }

        [Test]
        public void EachSampleKeepsItsEventTimeAndRepeatsAreRefused()
        {
            var phone = new PhoneAccelerometer(PhoneMounting.LandscapeLeft);
            var times = new[] { 10.000, 10.010, 10.010, 10.020, 10.015, 10.030, double.NaN };
            var kept = new System.Collections.Generic.List<double>();
            foreach (double t in times)
                if (phone.PushAccelerometer(t, new Vector3(-1, 0, 0), out var s)) kept.Add(s.Time);
            Assert.That(kept, Is.EqualTo(new[] { 10.000, 10.010, 10.020, 10.030 }));
            Assert.That(phone.Timeline.Duplicates, Is.EqualTo(1));
            Assert.That(phone.Timeline.OutOfOrder, Is.EqualTo(1));
            Assert.That(phone.Timeline.NotFinite, Is.EqualTo(1));
        }

        [Test]
        public void MountingOtherThanQuarterTurnsIsRefusedClearly()
        {
            var e = Assert.Throws<System.ArgumentException>(() => HeadAxes.SpecificForceFromPhone(new Vector3(0, -1, 0), 45));
            Assert.That(e.Message, Does.Contain("45"));
        }
    }
}
