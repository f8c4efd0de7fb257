using HeadGait.Tooling;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>The mapping of the mannequin's angles to Unity Humanoid muscle values.</summary>
    public class HumanoidMusclesTests
    {
        [Test]
        public void StandingStraightIsTheTPosesLegMuscles()
        {
            var muscles = HumanoidMuscles.Of(new GaitClips(PhaseMap.Perry).Pose(LocomotionState.Standing, 0));
            var byName = new System.Collections.Generic.Dictionary<string, double>();
            foreach (var (name, value) in muscles) byName[name] = value;
            Assert.That(byName["Left Upper Leg Front-Back"], Is.EqualTo(0.6).Within(1e-9));
            Assert.That(byName["Right Lower Leg Stretch"], Is.EqualTo(1.0).Within(1e-9));
            Assert.That(byName["Left Foot Up-Down"], Is.EqualTo(0.0).Within(1e-9));
        }

        [Test]
        public void FlexingTheHipAndKneeLowersTheirMusclesAndTheMappingInverts()
        {
            var f = Foot.Right;
            Assert.That(HumanoidMuscles.UpperLegFrontBack(f).FromAngle(-20), Is.EqualTo(0.2).Within(1e-9), "20 deg hip flexion");
            Assert.That(HumanoidMuscles.UpperLegFrontBack(f).FromAngle(-60), Is.EqualTo(-1.0 / 3).Within(1e-9), "beyond the center the flexion range (90) applies");
            Assert.That(HumanoidMuscles.LowerLegStretch(f).FromAngle(-60), Is.EqualTo(0.25).Within(1e-9), "60 deg knee flexion");
            foreach (var a in new[] { new LegAngles(20, 3, 0), new LegAngles(-10, 40, -18), new LegAngles(45, 70, 10) })
            {
                var back = HumanoidMuscles.Leg(f,
                    HumanoidMuscles.UpperLegFrontBack(f).FromAngle(-a.Hip),
                    HumanoidMuscles.LowerLegStretch(f).FromAngle(-a.Knee),
                    HumanoidMuscles.FootUpDown(f).FromAngle(-a.Ankle));
                Assert.That(new[] { back.Hip, back.Knee, back.Ankle }, Is.EqualTo(new[] { a.Hip, a.Knee, a.Ankle }).Within(1e-9));
            }
        }
    }
}
