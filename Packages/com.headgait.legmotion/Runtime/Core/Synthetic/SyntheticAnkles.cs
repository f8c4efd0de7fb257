using System;
using System.Collections.Generic;

namespace HeadGait.Synthetic
{
    /// <summary>
    /// Made-up poses of two tracked devices strapped above the ankles of a labelled walk (a generated walker's), for tests
    /// and samples of the calibration walk: each foot rests at ankle height while its labels say stance and swings forward
    /// by a stride, lifting 10 cm, from its heel rise (<see cref="Calibration.FootContactLabeller.ToeOffDelay"/> before the
    /// toe-off) to its next initial contact; tracking space (x right, y up, z forward), tracking noise and frame jitter added.
    /// </summary>
    public static class SyntheticAnkles
    {
        const double AnkleHeight = 0.08, Lift = 0.10, StrideLength = 1.2, HalfWidth = 0.1;

        public static (List<PoseSample> Left, List<PoseSample> Right) From(Recording labelled, double frameRate = 72, ulong seed = 1, double noiseSd = 0.002)
        {
            if (!labelled.HasTruth) throw new ArgumentException($"{labelled.Name}: the ankles are made from the walk's labels, and it has none.");
            var random = new DeterministicRandom(seed);
            var times = new List<double>();
            var left = new List<bool>();
            var right = new List<bool>();
            foreach (var s in labelled.Samples)
            {
                if (!s.HasTruth) continue;
                times.Add(s.Imu.Time);
                left.Add(Down(s.Left));
                right.Add(Down(s.Right));
            }
            var l = Track(times, left, -HalfWidth, 0, frameRate, random, noiseSd);
            var r = Track(times, right, HalfWidth, StrideLength / 2, frameRate, random, noiseSd);
            return (l, r);
        }

        static bool Down(GaitPhase p) => p == GaitPhase.Standing || GaitPhases.IsStance(p);

        static List<PoseSample> Track(List<double> times, List<bool> stance, double x, double startZ, double frameRate, DeterministicRandom random, double noiseSd)
        {
            // Swings: [heel rise, next contact) from each stance's end.
            var swings = new List<(double from, double to)>();
            for (int i = 1; i < times.Count; i++)
            {
                if (!(stance[i - 1] && !stance[i])) continue;
                int j = i;
                while (j < times.Count && !stance[j]) j++;
                if (j >= times.Count) break;
                swings.Add((times[i] - Calibration.FootContactLabeller.ToeOffDelay, times[j]));
            }
            var poses = new List<PoseSample>();
            double t0 = times[0], t1 = times[times.Count - 1];
            for (int k = 0; ; k++)
            {
                double t = t0 + k / frameRate + 0.001 * random.NextGaussian();
                if (t > t1) break;
                if (poses.Count > 0 && t <= poses[poses.Count - 1].Time + 1e-4) continue;
                double z = startZ, y = AnkleHeight;
                foreach (var (from, to) in swings)
                {
                    if (t >= to) z += StrideLength;
                    else if (t > from)
                    {
                        double u = (t - from) / (to - from);
                        z += StrideLength * 0.5 * (1 - Math.Cos(Math.PI * u));
                        y += Lift * Math.Sin(Math.PI * u);
                    }
                }
                poses.Add(new PoseSample(t, x + noiseSd * random.NextGaussian(), y + noiseSd * random.NextGaussian(), z + noiseSd * random.NextGaussian(), 0, 0, 0, 1));
            }
            return poses;
        }
    }
}
