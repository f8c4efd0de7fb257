using System;
using System.Collections.Generic;

namespace HeadGait.Training
{
    /// <summary>Learns the phase map from labelled recordings: how much of each foot's cycle is stance, and where the right foot lands.</summary>
    public static class PhaseMapTraining
    {
        /// <summary>
        /// Perry's phases with stance scaled to the mean measured stance fraction (IC to toe-off over IC to IC), and the right
        /// foot's offset as the mean position of right contacts within left strides. This is the map the labels themselves
        /// follow, so a perfect stride position reproduces them. Falls back to Perry's map with too few strides.
        /// </summary>
        public static PhaseMap Learn(IEnumerable<Recording> recordings)
        {
            double stanceSum = 0, offsetSum = 0;
            int stances = 0, offsets = 0;
            foreach (var rec in recordings)
            {
                PhaseEvents.ExtractTruth(rec, out var times, out var left, out var right);
                var icLeft = new List<double>();
                var icRight = new List<double>();
                for (int f = 0; f < 2; f++)
                {
                    var labels = f == 0 ? left : right;
                    var ics = f == 0 ? icLeft : icRight;
                    double ic = double.NaN, toeOff = double.NaN;
                    for (int i = 1; i < labels.Count; i++)
                    {
                        if (labels[i] == GaitPhase.Standing)
                        {
                            ic = toeOff = double.NaN;
                            continue;
                        }
                        bool contact = GaitPhases.IsStance(labels[i]) && GaitPhases.IsSwing(labels[i - 1]);
                        bool lift = GaitPhases.IsSwing(labels[i]) && GaitPhases.IsStance(labels[i - 1]);
                        if (lift && !double.IsNaN(ic)) toeOff = times[i];
                        if (!contact) continue;
                        ics.Add(times[i]);
                        if (!double.IsNaN(ic) && !double.IsNaN(toeOff) && toeOff > ic && times[i] - ic < 2.0)
                        {
                            stanceSum += (toeOff - ic) / (times[i] - ic);
                            stances++;
                        }
                        ic = times[i];
                        toeOff = double.NaN;
                    }
                }
                for (int i = 0; i + 1 < icLeft.Count; i++)
                {
                    double a = icLeft[i], b = icLeft[i + 1];
                    if (b - a > 2.0) continue;
                    foreach (var r in icRight)
                    {
                        if (r <= a || r >= b) continue;
                        offsetSum += (r - a) / (b - a);
                        offsets++;
                        break;
                    }
                }
            }
            if (stances < 4 || offsets < 2) return PhaseMap.Perry;
            return PhaseMap.FromStanceFraction(stanceSum / stances, offsetSum / offsets);
        }
    }
}
