using System;
using System.Collections.Generic;

namespace HeadGait
{
    /// <summary>
    /// Unity Humanoid muscle values (-1..1) for the mannequin's sagittal angles, so the clips retarget to any humanoid
    /// avatar. A muscle m maps to an angle from the avatar's T-pose as angle = center + m * (m &gt;= 0 ? max : -min), with
    /// Unity's default limits (HumanTrait.GetMuscleDefaultMin/Max) and the center implied by the T-pose's muscle value:
    /// Upper Leg Front-Back -90..50, center -30 (T-pose 0.6; forward is negative), Lower Leg Stretch -80..80, center -80
    /// (T-pose 1: straight), Foot and Toes Up-Down -50..50 (up is negative), Arm Down-Up -60..100, center -40 (T-pose 0.4),
    /// Arm Front-Back -100..100, center -30 (T-pose 0.3), Forearm Stretch -80..80, center -80. (Values as tabulated in a
    /// public reference of Unity's muscle space; not yet checked against an avatar in the editor.)
    /// </summary>
    public static class HumanoidMuscles
    {
        public readonly struct Muscle
        {
            public readonly string Name;
            public readonly double Min, Max, Center;

            public Muscle(string name, double min, double max, double center)
            {
                Name = name;
                Min = min;
                Max = max;
                Center = center;
            }

            public double FromAngle(double angle) => angle >= Center ? (angle - Center) / Max : (angle - Center) / -Min;

            public double ToAngle(double muscle) => Center + muscle * (muscle >= 0 ? Max : -Min);
        }

        public static Muscle UpperLegFrontBack(Foot f) => new Muscle(Mannequin.Side(f) + " Upper Leg Front-Back", -90, 50, -30);
        public static Muscle LowerLegStretch(Foot f) => new Muscle(Mannequin.Side(f) + " Lower Leg Stretch", -80, 80, -80);
        public static Muscle FootUpDown(Foot f) => new Muscle(Mannequin.Side(f) + " Foot Up-Down", -50, 50, 0);
        public static Muscle ToesUpDown(Foot f) => new Muscle(Mannequin.Side(f) + " Toes Up-Down", -50, 50, 0);
        public static Muscle ArmDownUp(Foot f) => new Muscle(Mannequin.Side(f) + " Arm Down-Up", -60, 100, -40);
        public static Muscle ArmFrontBack(Foot f) => new Muscle(Mannequin.Side(f) + " Arm Front-Back", -100, 100, -30);
        public static Muscle ForearmStretch(Foot f) => new Muscle(Mannequin.Side(f) + " Forearm Stretch", -80, 80, -80);

        /// <summary>Arms hang 80 deg below the T-pose's horizontal, elbows bent 15 deg as on the mannequin.</summary>
        const double ArmsDown = -80, ElbowFlexion = 15;

        /// <summary>Every muscle the clips animate and its value in a pose.</summary>
        public static List<(string Name, double Value)> Of(BodyPose pose)
        {
            var list = new List<(string, double)>();
            foreach (Foot f in new[] { Foot.Left, Foot.Right })
            {
                var leg = pose.Of(f);
                list.Add((UpperLegFrontBack(f).Name, UpperLegFrontBack(f).FromAngle(-leg.Hip)));
                list.Add((LowerLegStretch(f).Name, LowerLegStretch(f).FromAngle(-leg.Knee)));
                list.Add((FootUpDown(f).Name, FootUpDown(f).FromAngle(-leg.Ankle)));
                list.Add((ToesUpDown(f).Name, ToesUpDown(f).FromAngle(-pose.Leg(f).ToeBend)));
                list.Add((ArmDownUp(f).Name, ArmDownUp(f).FromAngle(ArmsDown)));
                list.Add((ArmFrontBack(f).Name, ArmFrontBack(f).FromAngle(-(f == Foot.Left ? pose.LeftArm : pose.RightArm))));
                list.Add((ForearmStretch(f).Name, ForearmStretch(f).FromAngle(-ElbowFlexion)));
            }
            return list;
        }

        /// <summary>The leg angles a pose's muscle values stand for (the inverse of <see cref="Of"/> for one leg).</summary>
        public static LegAngles Leg(Foot f, double upperLegFrontBack, double lowerLegStretch, double footUpDown)
            => new LegAngles(-UpperLegFrontBack(f).ToAngle(upperLegFrontBack), -LowerLegStretch(f).ToAngle(lowerLegStretch), -FootUpDown(f).ToAngle(footUpDown));
    }
}
