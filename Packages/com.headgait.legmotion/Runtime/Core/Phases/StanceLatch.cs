using System;

namespace HeadGait
{
    /// <summary>
    /// Each foot's phases with its stance share fixed from one of its initial contacts to the next. The share follows the
    /// step period (<see cref="PhaseMap.StanceSlope"/>), and the period changes at every contact, including the other
    /// foot's, which lands just before this foot's toe-off: read afresh, a longer period would put a foot that had just
    /// lifted back into stance, and the avatar would take a step that never happened.
    /// </summary>
    public sealed class StanceLatch
    {
        readonly double[] share = new double[2];
        readonly double[] lastCycle = new double[2];

        public StanceLatch() => Reset();

        /// <summary>Forgets both feet's shares (after standing): the next phase read takes the period as it is then.</summary>
        public void Reset()
        {
            share[0] = share[1] = double.NaN;
            lastCycle[0] = lastCycle[1] = double.NaN;
        }

        /// <summary>The foot's phase at a stride position; its stance share is taken anew when its cycle passes initial contact.</summary>
        public GaitPhase PhaseAt(PhaseMap map, Foot foot, double stridePosition, double stepPeriod)
        {
            if (map == null) throw new ArgumentNullException(nameof(map));
            int f = (int)foot;
            double u = map.CyclePosition(foot, stridePosition);
            // A drop of more than half a cycle is the cycle wrapping forward past contact, not the position stepping back.
            if (double.IsNaN(share[f]) || u < lastCycle[f] - 0.5) share[f] = map.StanceShare(stepPeriod);
            lastCycle[f] = u;
            return map.PhaseAtCycle(u, share[f]);
        }

        /// <summary>
        /// The foot's phase at a stride position as <see cref="PhaseAt"/> would show it with the share it holds now (the
        /// period's share when it holds none), without taking a new one: for checking a move before making it.
        /// </summary>
        public GaitPhase PhaseWithHeldShare(PhaseMap map, Foot foot, double stridePosition, double stepPeriod)
        {
            if (map == null) throw new ArgumentNullException(nameof(map));
            int f = (int)foot;
            return map.PhaseAtCycle(map.CyclePosition(foot, stridePosition), double.IsNaN(share[f]) ? map.StanceShare(stepPeriod) : share[f]);
        }
    }
}
