using System.Collections.Generic;
using HeadGait.Unity;
using NUnit.Framework;
using UnityEngine;

namespace HeadGait.Tests
{
    /// <summary>The headset path: reported acceleration when it is real, the tracked pose otherwise, event times throughout.</summary>
    public class XrHeadStreamTests
    {
        const float G = HeadAxes.StandardGravity;
        const int PositionAndRotation = 3;
        const int PositionRotationAcceleration = 3 | 16;

        static readonly Quaternion FacingX = Quaternion.Euler(new Vector3(0, 90, 0));

        /// <summary>A still head at 90 Hz reporting <paramref name="acceleration"/>; returns the samples it produced.</summary>
        static List<HeadSample> Run(XrHeadStream stream, double from, int frames, Vector3 acceleration, bool hasAcceleration = true, int? tracking = PositionRotationAcceleration)
        {
            var outs = new List<HeadSample>();
            for (int i = 0; i < frames; i++)
            {
                var r = new HeadReport
                {
                    Time = from + i / 90.0,
                    HasPose = true,
                    Position = new Vector3(0.1f, 1.7f, -0.3f),
                    Rotation = FacingX,
                    HasAcceleration = hasAcceleration,
                    Acceleration = acceleration,
                    TrackingState = tracking,
                };
                if (stream.Push(r, out var s)) outs.Add(s);
            }
            return outs;
        }

        [Test]
        public void AllZeroAccelerationIsNotTakenAsRealThePoseIsUsed()
        {
            // Oculus XR Plugin 4.x: the control exists and reads (0, 0, 0), even with the flag set.
            var stream = new XrHeadStream();
            var outs = Run(stream, 5.0, 90, Vector3.zero);
            Assert.That(stream.UsingPose, Is.True);
            Assert.That(outs.Count, Is.GreaterThan(80));
            foreach (var s in outs)
            {
                Assert.That(s.Lag, Is.GreaterThan(0.02), "pose samples lag the motion by half the fit window");
                Assert.That(s.SpecificForce.z, Is.EqualTo(G).Within(1e-3f), "a still head reads gravity up");
            }
            // Each sample is stamped with its pose event's time (a 90 Hz grid), not the time a script ran.
            foreach (var s in outs) Assert.That(s.Time * 90 - System.Math.Round(s.Time * 90), Is.EqualTo(0).Within(1e-6));
        }

        [Test]
        public void RealAccelerationIsUsedAfterAFewReportsAndRotatedIntoTheHeadFrame()
        {
            var stream = new XrHeadStream();
            var linear = new Vector3(1, 0, 0); // tracking +x = forward for a head facing +x
            var outs = Run(stream, 0, 10, linear);
            Assert.That(stream.UsingPose, Is.False);
            var last = outs[outs.Count - 1];
            Assert.That(last.Lag, Is.EqualTo(0));
            Assert.That(last.Time, Is.EqualTo(9 / 90.0).Within(1e-12));
            Assert.That(last.SpecificForce.x, Is.EqualTo(1f).Within(1e-4f));
            Assert.That(last.SpecificForce.z, Is.EqualTo(G).Within(1e-4f));
        }

        [Test]
        public void ZerosAfterRealDataSwitchToThePoseAndRealDataSwitchesBack()
        {
            var stream = new XrHeadStream();
            var real = new Vector3(0.3f, -0.2f, 0.1f);
            Run(stream, 0, 20, real);
            Assert.That(stream.UsingPose, Is.False);
            // One zero report inside real data is not a dead stream.
            Run(stream, 20 / 90.0, 1, Vector3.zero);
            Assert.That(stream.UsingPose, Is.False);
            Run(stream, 21 / 90.0, 5, real);
            // A quarter of a second of zeros is.
            Run(stream, 26 / 90.0, 30, Vector3.zero);
            Assert.That(stream.UsingPose, Is.True);
            // Not latched: real data again.
            var back = Run(stream, 56 / 90.0, 10, real);
            Assert.That(stream.UsingPose, Is.False);
            Assert.That(back[back.Count - 1].Lag, Is.EqualTo(0));
            Assert.That(stream.Gate.Switches, Is.EqualTo(3));
        }

        /// <summary>
        /// The headset's proximity sensor says nobody wears it (XR userPresence false: being put on, taken off, lying on a
        /// table): no sample comes out, whatever it reports, so the pipeline meets a hole and the avatar stands. Worn again,
        /// samples come at once, from reported acceleration as before (the gate kept following it); a headset without the
        /// sensor (null), or whose sensor never said worn, is read as worn.
        /// </summary>
        [Test]
        public void NoSampleComesOutWhileNobodyWearsTheHeadset()
        {
            var stream = new XrHeadStream();
            int Samples(double from, int frames, bool? present, Vector3 acceleration)
            {
                int n = 0;
                for (int i = 0; i < frames; i++)
                {
                    var r = new HeadReport
                    {
                        Time = from + i / 90.0, HasPose = true, Position = new Vector3(0.1f, 1.7f + 0.2f * i / frames, -0.3f), Rotation = FacingX,
                        HasAcceleration = true, Acceleration = acceleration, TrackingState = PositionRotationAcceleration, UserPresent = present,
                    };
                    if (stream.Push(r, out _)) n++;
                }
                return n;
            }
            var lift = new Vector3(0.4f, 2f, -0.3f);
            Assert.That(Samples(0, 90, null, lift), Is.GreaterThan(80), "no proximity sensor: worn (the pose estimate fills first)");
            Assert.That(Samples(1, 45, false, lift), Is.EqualTo(45), "a sensor that never said worn (a runtime that exposes the control and never sets it): worn");
            Assert.That(Samples(1.5, 45, true, lift), Is.EqualTo(45));
            Assert.That(Samples(2, 90, false, lift), Is.EqualTo(0), "taken off and put on again");
            Assert.That(stream.UsingPose, Is.False, "the gate followed the reports while nobody wore it");
            Assert.That(Samples(3, 90, true, lift), Is.EqualTo(90), "worn again");
        }

        [Test]
        public void AccelerationTheTrackingStateDoesNotFlagIsIgnored()
        {
            var stream = new XrHeadStream();
            Run(stream, 0, 30, new Vector3(0.5f, 0.5f, 0.5f), tracking: PositionAndRotation);
            Assert.That(stream.UsingPose, Is.True);
        }

        [Test]
        public void AHeadsetWithoutAccelerationUsesThePose()
        {
            // OpenXR: no acceleration control at all.
            var stream = new XrHeadStream();
            var outs = Run(stream, 0, 30, default, hasAcceleration: false, tracking: PositionAndRotation);
            Assert.That(stream.UsingPose, Is.True);
            Assert.That(outs.Count, Is.GreaterThan(20));
        }

        [Test]
        public void PoseModeIgnoresRealAcceleration()
        {
            var stream = new XrHeadStream(allowReported: false);
            var outs = Run(stream, 0, 30, new Vector3(1, 0, 0));
            Assert.That(stream.UsingPose, Is.True);
            Assert.That(outs[outs.Count - 1].SpecificForce.x, Is.EqualTo(0).Within(1e-3f), "the still pose, not the reported push");
        }

        [Test]
        public void DuplicatedAndLateEventsAreRefusedOnce()
        {
            var stream = new XrHeadStream();
            var r = new HeadReport { Time = 1.0, HasPose = true, Position = new Vector3(0, 1.7f, 0), Rotation = Quaternion.identity, HasAcceleration = true, Acceleration = new Vector3(0.1f, 0, 0) };
            for (int i = 0; i < 6; i++)
            {
                r.Time = 1.0 + i * 0.01;
                stream.Push(r, out _);
            }
            Assert.That(stream.Push(r, out _), Is.False, "the same event again");
            r.Time = 1.02;
            Assert.That(stream.Push(r, out _), Is.False, "an event older than the last");
            Assert.That(stream.Timeline.Duplicates, Is.EqualTo(1));
            Assert.That(stream.Timeline.OutOfOrder, Is.EqualTo(1));
        }

        [Test]
        public void UntrackedPositionsDoNotFeedThePoseFit()
        {
            var stream = new XrHeadStream();
            var outs = Run(stream, 0, 30, default, hasAcceleration: false, tracking: 2 /* rotation only */);
            Assert.That(outs, Is.Empty);
        }
    }
}
