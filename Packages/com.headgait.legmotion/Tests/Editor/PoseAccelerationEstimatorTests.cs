using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace HeadGait.Tests
{
    public class PoseAccelerationEstimatorTests
    {
        const double G = 9.80665;

        static double[] Yaw(double degrees)
        {
            double h = degrees * Math.PI / 360;
            return new[] { 0, Math.Sin(h), 0, Math.Cos(h) };
        }

        [Test]
        public void StillHeadReadsGravityUpWhateverItsYaw()
        {
            foreach (double yaw in new[] { 0.0, 45, -120 })
            {
                var e = new PoseAccelerationEstimator();
                var q = Yaw(yaw);
                ImuSample s = default;
                bool got = false;
                for (int i = 0; i < 9; i++) got = e.Push(i / 72.0, 0.3, 1.7, -0.2, q[0], q[1], q[2], q[3], out s);
                Assert.That(got, Is.True);
                Assert.That(s.Z, Is.EqualTo(G).Within(1e-9));
                Assert.That(s.X, Is.EqualTo(0).Within(1e-9));
                Assert.That(s.Y, Is.EqualTo(0).Within(1e-9));
            }
        }

        [Test]
        public void RecoversTheAccelerationOfABobbingWalkFromJitteredFrames()
        {
            // Head moving along Unity +x (it faces +x: yaw 90), bobbing up and down at 1.9 Hz and swaying along z.
            var rnd = new Random(4);
            var e = new PoseAccelerationEstimator();
            var q = Yaw(90);
            double w1 = 2 * Math.PI * 1.9, w2 = 2 * Math.PI * 0.95;
            double t = 0, worst = 0;
            int n = 0;
            for (int i = 0; i < 400; i++)
            {
                t += 1 / 72.0 + 0.001 * (rnd.NextDouble() - 0.5);
                double px = 1.3 * t, py = 1.7 + 0.02 * Math.Sin(w1 * t), pz = 0.015 * Math.Sin(w2 * t);
                if (!e.Push(t, px, py, pz, q[0], q[1], q[2], q[3], out var s)) continue;
                // Each sample describes the motion Lag before its stamp (the middle of the fitted poses).
                Assert.That(s.Time, Is.EqualTo(t));
                Assert.That(e.Lag, Is.InRange(0.025, 0.065));
                double tm = s.Time - e.Lag;
                double up = -0.02 * w1 * w1 * Math.Sin(w1 * tm) + G;
                double along = 0;                                   // constant speed forward
                double sideZ = -0.015 * w2 * w2 * Math.Sin(w2 * tm); // along Unity +z = the head's left when facing +x
                worst = Math.Max(worst, Math.Abs(s.Z - up));
                worst = Math.Max(worst, Math.Abs(s.X - along));
                worst = Math.Max(worst, Math.Abs(s.Y - sideZ));
                n++;
            }
            // Seven poses (83 ms at 72 Hz) are the first odd count spanning half the fit window.
            Assert.That(n, Is.EqualTo(394));
            TestContext.WriteLine($"worst error {worst:F3} m/s^2 of a {0.02 * w1 * w1:F2} m/s^2 bob");
            // The quadratic fit flattens a sinusoid over its 120 ms window a little (about 4 % of the bob at 1.9 Hz).
            Assert.That(worst, Is.LessThan(0.15));
        }

        [Test]
        public void StartsOverWhenTheClockMovesFarBack()
        {
            // Regression: every pose not later than the last was skipped, so a tracking clock that restarted stopped
            // the pose path for good. A step back beyond a late pose now starts the fit over on the new clock.
            var e = new PoseAccelerationEstimator();
            var outs = new List<double>();
            void Push(double t)
            {
                if (e.Push(t, 0, 1.7, 0, 0, 0, 0, 1, out var s)) outs.Add(Math.Round(s.Time, 6));
            }
            for (int i = 0; i < 10; i++) Push(500 + i / 100.0);
            int before = outs.Count;
            Assert.That(before, Is.GreaterThan(0));
            Push(500.05);                                   // late: skipped
            for (int i = 0; i < 10; i++) Push(2 + i / 100.0);
            Assert.That(e.Skipped, Is.EqualTo(1));
            // Seven poses on the new clock give the first estimate again, stamped on that clock.
            Assert.That(outs.GetRange(before, outs.Count - before), Is.EqualTo(new[] { 2.06, 2.07, 2.08, 2.09 }));
        }

        [Test]
        public void SkipsBadPosesAndRestartsAfterAHole()
        {
            var e = new PoseAccelerationEstimator();
            var outs = new List<double>();
            void Push(double t, double y)
            {
                if (e.Push(t, 0, y, 0, 0, 0, 0, 1, out var s)) outs.Add(Math.Round(s.Time, 6));
            }
            Push(0.00, 1.7);
            Push(0.01, double.NaN);
            Push(0.01, 1.7);
            Push(0.005, 1.7);   // backwards
            for (int i = 2; i <= 6; i++) Push(i / 100.0, 1.7);
            // At 100 Hz the first estimate needs seven poses (an odd count spanning half the 120 ms window).
            Assert.That(outs, Is.EqualTo(new[] { 0.06 }));
            for (int i = 0; i < 6; i++) Push(0.50 + i / 100.0, 1.7);   // a hole: start again
            Assert.That(outs.Count, Is.EqualTo(1));
            Push(0.56, 1.7);
            Assert.That(outs, Is.EqualTo(new[] { 0.06, 0.56 }));
            Assert.That(e.Skipped, Is.EqualTo(2));
        }
    }
}
