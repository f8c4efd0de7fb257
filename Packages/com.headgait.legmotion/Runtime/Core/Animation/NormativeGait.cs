using System;

namespace HeadGait
{
    /// <summary>Sagittal joint angles of one leg, degrees: hip flexion (+ thigh forward), knee flexion (+ bent), ankle dorsiflexion (+ toes up).</summary>
    public readonly struct LegAngles
    {
        public readonly double Hip;
        public readonly double Knee;
        public readonly double Ankle;

        public LegAngles(double hip, double knee, double ankle)
        {
            Hip = hip;
            Knee = knee;
            Ankle = ankle;
        }

        public static LegAngles Lerp(LegAngles a, LegAngles b, double t)
            => new LegAngles(a.Hip + (b.Hip - a.Hip) * t, a.Knee + (b.Knee - a.Knee) * t, a.Ankle + (b.Ankle - a.Ankle) * t);
    }

    /// <summary>
    /// Normal adult walking at natural cadence: sagittal hip, knee and ankle angles over one gait cycle of a leg
    /// (0 = its initial contact), every 5 % of the cycle. Values are the ensemble-average curves of Winter,
    /// "Biomechanics and Motor Control of Human Movement" (4th ed., 2009, Appendix A, natural cadence), read off and rounded
    /// to the degree; their landmarks agree with Perry &amp; Burnfield, "Gait Analysis: Normal and Pathological Function"
    /// (2nd ed., 2010, ch. 4-6): hip ~20 deg flexed at initial contact and ~10 deg extended at 50 %, knee ~18 deg in loading
    /// response and ~60 deg in initial swing, ankle ~5 deg plantarflexed in loading response, ~10 deg dorsiflexed in terminal
    /// stance and ~18 deg plantarflexed just after toe-off (62 %).
    /// </summary>
    public static class NormativeGait
    {
        /// <summary>Spacing of the table, fraction of the cycle.</summary>
        public const double Step = 0.05;

        static readonly double[] HipTable = { 20, 20, 18, 14, 10, 6, 2, -1, -4, -7, -9, -8, -3, 4, 11, 17, 21, 23, 23, 21, 20 };
        static readonly double[] KneeTable = { 3, 10, 16, 18, 16, 12, 8, 5, 4, 6, 11, 20, 32, 48, 58, 58, 50, 36, 20, 7, 3 };
        static readonly double[] AnkleTable = { 0, -4, -3, 0, 3, 5, 7, 8, 10, 9, 5, -4, -14, -18, -12, -5, -1, 1, 1, 0, 0 };

        /// <summary>Angles at a fraction of the leg's own cycle in Perry's timing (toe-off at 62 %), periodic Catmull-Rom through the table.</summary>
        public static LegAngles AtPerryCycle(double cycleFraction)
        {
            double u = PhaseMap.Wrap(cycleFraction);
            return new LegAngles(Periodic(HipTable, u), Periodic(KneeTable, u), Periodic(AnkleTable, u));
        }

        /// <summary>
        /// Angles at a fraction of the leg's own cycle, time-warped piecewise-linearly so that each of Perry's phase onsets
        /// falls where <paramref name="map"/> puts it (the trained map's stance is shorter than Perry's 62 %).
        /// </summary>
        public static LegAngles At(PhaseMap map, double cycleFraction)
        {
            double u = PhaseMap.Wrap(cycleFraction);
            int p = (int)map.PhaseAt(Foot.Left, u);
            double start = map.Onset((GaitPhase)p);
            double end = p + 1 < GaitPhases.WalkingPhaseCount ? map.Onset((GaitPhase)(p + 1)) : 1.0;
            double perryStart = PhaseMap.Perry.Onset((GaitPhase)p);
            double perryEnd = p + 1 < GaitPhases.WalkingPhaseCount ? PhaseMap.Perry.Onset((GaitPhase)(p + 1)) : 1.0;
            double t = end > start ? (u - start) / (end - start) : 0;
            return AtPerryCycle(perryStart + t * (perryEnd - perryStart));
        }

        /// <summary>Quiet standing: hip, knee and ankle neutral.</summary>
        public static LegAngles Standing => new LegAngles(0, 0, 0);

        static double Periodic(double[] table, double u)
        {
            int n = table.Length - 1; // the last entry repeats the first (100 % = 0 %)
            double x = u / Step;
            int i = (int)Math.Floor(x);
            double t = x - i;
            double p0 = table[(i - 1 + n) % n], p1 = table[i % n], p2 = table[(i + 1) % n], p3 = table[(i + 2) % n];
            return 0.5 * (2 * p1 + (-p0 + p2) * t + (2 * p0 - 5 * p1 + 4 * p2 - p3) * t * t + (-p0 + 3 * p1 - 3 * p2 + p3) * t * t * t);
        }
    }
}
