using System;
using System.Collections.Generic;

namespace HeadGait
{
    /// <summary>
    /// The stride cut wherever either foot changes phase: each segment is one pair of phases (left, right), e.g.
    /// (IC, PSW) right after the left foot lands. With stance longer than half the stride there are 16 of them.
    /// Learned classifiers predict a segment (or Standing), which names both feet's phases at once.
    /// </summary>
    public sealed class StrideSegments
    {
        readonly double[] starts;
        readonly GaitPhase[] left;
        readonly GaitPhase[] right;

        public StrideSegments(PhaseMap map)
        {
            Map = map ?? throw new ArgumentNullException(nameof(map));
            var bounds = new List<double>();
            for (int p = 0; p < GaitPhases.WalkingPhaseCount; p++)
            {
                bounds.Add(map.StridePositionOfOnset(Foot.Left, (GaitPhase)p));
                bounds.Add(map.StridePositionOfOnset(Foot.Right, (GaitPhase)p));
            }
            bounds.Sort();
            var unique = new List<double>();
            foreach (var b in bounds)
                if (unique.Count == 0 || b - unique[unique.Count - 1] > 1e-9) unique.Add(b);
            if (unique.Count > 1 && 1 - unique[unique.Count - 1] + unique[0] < 1e-9) unique.RemoveAt(unique.Count - 1);
            starts = unique.ToArray();
            left = new GaitPhase[starts.Length];
            right = new GaitPhase[starts.Length];
            for (int k = 0; k < starts.Length; k++)
            {
                double mid = Center(k);
                left[k] = map.PhaseAt(Foot.Left, mid);
                right[k] = map.PhaseAt(Foot.Right, mid);
            }
        }

        public PhaseMap Map { get; }

        /// <summary>Walking segments per stride.</summary>
        public int Count => starts.Length;

        /// <summary>Classes of a learned classifier: the segments, then Standing.</summary>
        public int ClassCount => starts.Length + 1;

        public int StandingClass => starts.Length;

        public GaitPhase Left(int cls) => cls == StandingClass ? GaitPhase.Standing : left[cls];
        public GaitPhase Right(int cls) => cls == StandingClass ? GaitPhase.Standing : right[cls];

        /// <summary>Stride position where segment k starts, and its length.</summary>
        public double Start(int k) => starts[k];
        public double Length(int k) => PhaseMap.Wrap(starts[(k + 1) % starts.Length] - starts[k] - 1e-12) + 1e-12;
        public double Center(int k) => PhaseMap.Wrap(starts[k] + 0.5 * Length(k));

        /// <summary>The walking class whose segment holds stride position <paramref name="x"/> (wrapped).</summary>
        public int At(double x)
        {
            for (int k = 0; k < starts.Length; k++)
                if (PhaseMap.Wrap(x - Start(k)) < Length(k)) return k;
            return 0;
        }

        /// <summary>The class of a pair of labels: a segment, Standing, or -1 when the pair does not occur in this map's stride.</summary>
        public int ClassOf(GaitPhase leftPhase, GaitPhase rightPhase)
        {
            if (leftPhase == GaitPhase.Standing || rightPhase == GaitPhase.Standing)
                return leftPhase == rightPhase ? StandingClass : -1;
            for (int k = 0; k < starts.Length; k++)
                if (left[k] == leftPhase && right[k] == rightPhase) return k;
            return -1;
        }

        /// <summary>Short name of a class, e.g. "IC/PSW" or "STAND".</summary>
        public string Name(int cls) => cls == StandingClass ? "STAND" : GaitPhases.ShortName(left[cls]) + "/" + GaitPhases.ShortName(right[cls]);

        /// <summary>All class names, in class order, comma-separated: written into model files and checked when they load.</summary>
        public string Names()
        {
            var names = new string[ClassCount];
            for (int c = 0; c < names.Length; c++) names[c] = Name(c);
            return string.Join(",", names);
        }
    }
}
