using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace HeadGait.Tests
{
    public class PhaseMapTests
    {
        [TestCase(0.00, GaitPhase.InitialContact, GaitPhase.PreSwing)]
        [TestCase(0.05, GaitPhase.LoadingResponse, GaitPhase.PreSwing)]
        [TestCase(0.20, GaitPhase.MidStance, GaitPhase.InitialSwing)]
        [TestCase(0.40, GaitPhase.TerminalStance, GaitPhase.TerminalSwing)]
        [TestCase(0.50, GaitPhase.PreSwing, GaitPhase.InitialContact)]
        [TestCase(0.55, GaitPhase.PreSwing, GaitPhase.LoadingResponse)]
        [TestCase(0.70, GaitPhase.InitialSwing, GaitPhase.MidStance)]
        [TestCase(0.80, GaitPhase.MidSwing, GaitPhase.MidStance)]
        [TestCase(0.90, GaitPhase.TerminalSwing, GaitPhase.TerminalStance)]
        [TestCase(1.90, GaitPhase.TerminalSwing, GaitPhase.TerminalStance)]
        [TestCase(-0.10, GaitPhase.TerminalSwing, GaitPhase.TerminalStance)]
        public void PerryPhasesOfBothFeet(double s, GaitPhase left, GaitPhase right)
        {
            Assert.That(PhaseMap.Perry.PhaseAt(Foot.Left, s), Is.EqualTo(left));
            Assert.That(PhaseMap.Perry.PhaseAt(Foot.Right, s), Is.EqualTo(right));
        }

        [Test]
        public void OnsetsAreWhereThePhasesBegin()
        {
            var m = PhaseMap.Perry;
            for (int p = 0; p < 8; p++)
            {
                foreach (Foot f in new[] { Foot.Left, Foot.Right })
                {
                    double at = m.StridePositionOfOnset(f, (GaitPhase)p);
                    Assert.That(m.PhaseAt(f, at + 1e-9), Is.EqualTo((GaitPhase)p));
                }
            }
        }

        [Test]
        public void DistanceIsCyclicAndStandingIsFarthest()
        {
            Assert.That(GaitPhases.Distance(GaitPhase.InitialContact, GaitPhase.TerminalSwing), Is.EqualTo(1));
            Assert.That(GaitPhases.Distance(GaitPhase.MidStance, GaitPhase.MidSwing), Is.EqualTo(4));
            Assert.That(GaitPhases.Distance(GaitPhase.Standing, GaitPhase.LoadingResponse), Is.EqualTo(4));
            Assert.That(GaitPhases.Distance(GaitPhase.Standing, GaitPhase.Standing), Is.EqualTo(0));
        }

        [TestCase("IC", GaitPhase.InitialContact)]
        [TestCase("mst", GaitPhase.MidStance)]
        [TestCase("Mid Swing", GaitPhase.MidSwing)]
        [TestCase("terminal_stance", GaitPhase.TerminalStance)]
        [TestCase("PreSwing", GaitPhase.PreSwing)]
        [TestCase("STAND", GaitPhase.Standing)]
        [TestCase("standing", GaitPhase.Standing)]
        public void ParsesPhaseNames(string text, GaitPhase expected)
        {
            Assert.That(GaitPhases.TryParse(text, out var p), Is.True);
            Assert.That(p, Is.EqualTo(expected));
        }

        [Test]
        public void RejectsUnknownPhaseNames()
        {
            Assert.That(GaitPhases.TryParse("WALKING", out _), Is.False);
            Assert.That(GaitPhases.TryParse("", out _), Is.False);
            Assert.That(GaitPhases.TryParse(null, out _), Is.False);
        }

        [Test]
        public void SerializesAndRefusesBadMaps()
        {
            var m = new PhaseMap(new[] { 0, 0.03, 0.13, 0.30, 0.49, 0.61, 0.74, 0.88 }, 0.51);
            var back = PhaseMap.Parse(m.Serialize());
            Assert.That(back.RightOffset, Is.EqualTo(0.51));
            Assert.That(back.Onset(GaitPhase.MidSwing), Is.EqualTo(0.74));
            Assert.That(() => new PhaseMap(new[] { 0, 0.2, 0.1, 0.3, 0.4, 0.5, 0.6, 0.7 }), Throws.ArgumentException);
            Assert.That(() => new PhaseMap(new[] { 0.0, 0.5 }), Throws.ArgumentException);
            Assert.That(() => PhaseMap.Parse("0,0.1;0.5"), Throws.TypeOf<System.FormatException>());
        }

        static PhaseMap PeriodDependent => PhaseMap.FromStanceFraction(0.58, 0.5, stanceSlope: 0.12, referenceStridePeriod: 1.1);

        [Test]
        public void StanceLengthensWithTheStridePeriodWithinItsLimit()
        {
            var m = PeriodDependent;
            Assert.That(m.StanceShare(0.55), Is.EqualTo(0.58).Within(1e-12), "at the reference period");
            Assert.That(m.StanceShare(0.65), Is.EqualTo(0.58 + 0.12 * 0.2).Within(1e-12), "0.2 s longer stride");
            Assert.That(m.StanceShare(0.40), Is.EqualTo(0.58 - 0.12 * 0.3).Within(1e-12));
            Assert.That(m.StanceShare(3.0), Is.EqualTo(0.58 + PhaseMap.MaxStanceShift).Within(1e-12), "held to its limit");
            Assert.That(m.StanceShare(0), Is.EqualTo(0.58), "no period: the reference share");
            // At 0.6 of its cycle a foot is still in pre-swing on a slow stride and already swinging on a fast one.
            Assert.That(m.PhaseAt(Foot.Left, 0.60, 0.70), Is.EqualTo(GaitPhase.PreSwing));
            Assert.That(m.PhaseAt(Foot.Left, 0.60, 0.45), Is.EqualTo(GaitPhase.InitialSwing));
            Assert.That(m.PhaseAt(Foot.Right, 0.10, 0.70), Is.EqualTo(GaitPhase.PreSwing));
            // Contact stays at the cycle's start and the fixed-share reading is the reference map's.
            Assert.That(m.PhaseAt(Foot.Left, 0.001, 0.45), Is.EqualTo(GaitPhase.InitialContact));
            Assert.That(m.PhaseAt(Foot.Left, 0.60), Is.EqualTo(PhaseMap.FromStanceFraction(0.58).PhaseAt(Foot.Left, 0.60)));
        }

        [Test]
        public void SerializesTheStanceSlopeAndReadsMapsWithout()
        {
            var back = PhaseMap.Parse(PeriodDependent.Serialize());
            Assert.That(back.StanceSlope, Is.EqualTo(0.12));
            Assert.That(back.ReferenceStridePeriod, Is.EqualTo(1.1));
            Assert.That(back.StanceShare(0.65), Is.EqualTo(PeriodDependent.StanceShare(0.65)));
            var fixedShare = PhaseMap.Parse("0,0.02,0.12,0.31,0.5,0.62,0.75,0.87;0.5");
            Assert.That(fixedShare.StanceSlope, Is.EqualTo(0));
            Assert.That(fixedShare.Serialize(), Is.EqualTo("0,0.02,0.12,0.31,0.5,0.62,0.75,0.87;0.5"), "a fixed map keeps the two-part text");
            Assert.That(() => PhaseMap.Parse("0,0.02,0.12,0.31,0.5,0.62,0.75,0.87;0.5;0.1"), Throws.TypeOf<System.FormatException>());
            Assert.That(() => PhaseMap.Parse("0,0.02,0.12,0.31,0.5,0.62,0.75,0.87;0.5;NaN,1.1"), Throws.TypeOf<System.FormatException>());
            Assert.That(() => PhaseMap.Parse("0,0.02,0.12,0.31,0.5,0.62,0.75,0.87;0.5;0.1,0"), Throws.TypeOf<System.FormatException>());
            Assert.That(() => PhaseMap.Parse("0,0.02,0.12,0.31,0.5,0.62,0.75,0.87;0.5;1e999,1.1"),
                Throws.TypeOf<System.FormatException>().With.Message.Contains("1e999"), "an overflow is a format error too");
            Assert.That(() => PhaseMap.Parse("0,0.02,x,0.31,0.5,0.62,0.75,0.87;0.5"), Throws.TypeOf<System.FormatException>().With.Message.Contains("'x'"));
        }

        [Test]
        public void ALatchedFootDoesNotFallBackIntoStanceWhenThePeriodGrows()
        {
            var m = PeriodDependent;
            var latch = new StanceLatch();
            // The left foot lands on a fast stride and has just lifted (cycle 0.57) when the right foot's contact
            // lengthens the period: read afresh it would be back in pre-swing.
            double fast = 0.50, slow = 0.64;
            for (double s = 0; s < 0.57; s += 0.01) latch.PhaseAt(m, Foot.Left, s, fast);
            Assert.That(latch.PhaseAt(m, Foot.Left, 0.57, fast), Is.EqualTo(GaitPhase.InitialSwing));
            Assert.That(m.PhaseAt(Foot.Left, 0.58, slow), Is.EqualTo(GaitPhase.PreSwing), "what an unlatched reading shows");
            Assert.That(latch.PhaseAt(m, Foot.Left, 0.58, slow), Is.EqualTo(GaitPhase.InitialSwing));
            // At its next contact the foot takes the new period's longer stance.
            for (double s = 0.6; s < 1.0; s += 0.01) latch.PhaseAt(m, Foot.Left, s, slow);
            for (double s = 0.0; s < 0.58; s += 0.01) latch.PhaseAt(m, Foot.Left, s, slow);
            Assert.That(latch.PhaseAt(m, Foot.Left, 0.58, slow), Is.EqualTo(GaitPhase.PreSwing));
            latch.Reset();
            Assert.That(latch.PhaseAt(m, Foot.Left, 0.58, fast), Is.EqualTo(GaitPhase.InitialSwing), "after a reset the period as it is");
        }
    }

    public class AdvancedPredictionTests
    {
        /// <summary>Walks at a step period that switches every 0.37 s, so it changes at every point of the feet's cycles.</summary>
        sealed class SwitchingWalker : IGaitClassifier
        {
            double s, lastTime = double.NaN;
            public string Name => "switching";
            public PhaseMap PhaseMap { get; } = PhaseMap.FromStanceFraction(0.574, 0.5, stanceSlope: 0.3, referenceStridePeriod: 1.1);
            public int WindowLength => 50;
            public double PoseFitDelay => 0;
            public void Reset() => lastTime = double.NaN;

            public GaitPrediction Classify(SignalWindow window)
            {
                double t = window.EndTime, period = (int)(t / 0.37) % 2 == 0 ? 0.45 : 0.65;
                if (!double.IsNaN(lastTime)) s += (t - lastTime) / (2 * period);
                lastTime = t;
                return GaitPrediction.Walking(t, s, period, 1, GaitPhase.InitialContact, GaitPhase.PreSwing);
            }
        }

        [Test]
        public void APredictionMovedAheadLandsEachFootOncePerStride()
        {
            // The pose path's predictions are moved ahead by the source lag and their phases read anew: a foot that has
            // just lifted must not go back to stance when the period grows.
            var walker = new SwitchingWalker();
            var pipeline = new GaitPipeline(walker) { SourceLag = 0.05 };
            int landings = 0, strides = 0;
            GaitPhase previous = GaitPhase.Standing;
            double lastCycle = double.NaN;
            for (int i = 0; i < 3000; i++)
            {
                pipeline.Push(0.01 * i, 0, 0, 9.80665 + Math.Sin(0.2 * i));
                var p = pipeline.LatestPrediction;
                if (!p.IsWalking) continue;
                if (GaitPhases.IsStance(p.Left) && GaitPhases.IsSwing(previous)) landings++;
                previous = p.Left;
                double cycle = walker.PhaseMap.CyclePosition(Foot.Left, p.StridePosition);
                if (cycle < lastCycle - 0.5) strides++;
                lastCycle = cycle;
            }
            Assert.That(strides, Is.GreaterThan(20));
            Assert.That(landings, Is.EqualTo(strides).Within(1));
        }

        [Test]
        public void APoseSourceIsLookedAheadFurtherByTheClassifiersPoseFitDelay()
        {
            // THR on a generated walk, once without and once with a pose fit delay of 20 ms: on an accelerometer (no source
            // lag) the two must agree window for window; on the pose path the second must run 20 ms further along each step
            // (stride positions wrap at 1).
            var walk = TestData.Eval("walk_straight");
            List<GaitPrediction> Run(double poseFitDelay, double sourceLag)
            {
                var settings = TestData.CommittedThreshold;
                settings.Clock.PoseFitDelay = poseFitDelay;
                var pipeline = new GaitPipeline(new ThresholdClassifier(settings)) { SourceLag = sourceLag };
                var predictions = new List<GaitPrediction>();
                pipeline.FrameProduced += (prediction, frame) => predictions.Add(prediction);
                foreach (var sample in walk.Samples) pipeline.Push(sample.Imu);
                return predictions;
            }
            var accelerometer = Run(0, 0);
            var accelerometerWithDelay = Run(0.02, 0);
            Assert.That(accelerometerWithDelay.Count, Is.EqualTo(accelerometer.Count));
            for (int i = 0; i < accelerometer.Count; i++)
                Assert.That(accelerometerWithDelay[i].StridePosition, Is.EqualTo(accelerometer[i].StridePosition), $"window {i}");

            var pose = Run(0, 0.05);
            var poseWithDelay = Run(0.02, 0.05);
            int walking = 0;
            for (int i = 0; i < pose.Count; i++)
            {
                Assert.That(poseWithDelay[i].IsWalking, Is.EqualTo(pose[i].IsWalking), $"window {i}");
                if (!pose[i].IsWalking) continue;
                walking++;
                Assert.That(PhaseMap.Wrap(poseWithDelay[i].StridePosition - pose[i].StridePosition), Is.EqualTo(0.02 / (2 * pose[i].StepPeriod)).Within(1e-9), $"window {i}");
            }
            Assert.That(walking, Is.GreaterThan(pose.Count / 2));
        }
    }
}
