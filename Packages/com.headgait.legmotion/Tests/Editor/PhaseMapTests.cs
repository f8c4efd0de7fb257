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
    }
}
