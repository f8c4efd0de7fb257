using System;
using System.Globalization;
using System.Text;

namespace HeadGait
{
    /// <summary>
    /// Maps a stride position (0..1, 0 = left initial contact) to each foot's gait phase.
    /// The left foot's phase onsets are fractions of its own cycle; the right foot runs the same
    /// phase onsets shifted by <see cref="RightOffset"/> (0.5 for symmetric gait).
    /// Defaults are Perry's percentages: IC 0, LR 2, MSt 12, TSt 31, PSw 50, ISw 62, MSw 75, TSw 87.
    /// Stance may lengthen with the stride period (<see cref="StanceSlope"/>): people spend a larger share of a slow stride
    /// on the ground, so a fixed toe-off misplaces it for fast and slow walkers alike.
    /// </summary>
    public sealed class PhaseMap
    {
        readonly double[] onsets;

        public double RightOffset { get; }

        /// <summary>Change of the stance share per second of stride period away from <see cref="ReferenceStridePeriod"/> (0: fixed onsets).</summary>
        public double StanceSlope { get; }

        /// <summary>Stride period (seconds, two steps) at which stance is <see cref="Onset"/>(InitialSwing).</summary>
        public double ReferenceStridePeriod { get; }

        /// <summary>How far the stance share may move from the reference either way, so an odd period estimate cannot empty a phase.</summary>
        public const double MaxStanceShift = 0.08;

        public PhaseMap(double[] onsets, double rightOffset = 0.5, double stanceSlope = 0, double referenceStridePeriod = 1)
        {
            if (onsets == null || onsets.Length != GaitPhases.WalkingPhaseCount)
                throw new ArgumentException("A phase map needs exactly 8 phase onsets.", nameof(onsets));
            if (Math.Abs(onsets[0]) > 1e-9)
                throw new ArgumentException("The first onset (initial contact) must be 0.", nameof(onsets));
            for (int i = 1; i < onsets.Length; i++)
            {
                if (!(onsets[i] > onsets[i - 1]) || !(onsets[i] < 1.0))
                    throw new ArgumentException("Phase onsets must increase strictly and stay below 1.", nameof(onsets));
            }
            if (!(rightOffset > 0.0 && rightOffset < 1.0))
                throw new ArgumentException("The right foot's offset must lie in (0, 1).", nameof(rightOffset));
            if (!(Math.Abs(stanceSlope) <= 1.0))
                throw new ArgumentException("The stance slope must lie within -1..1 per second.", nameof(stanceSlope));
            if (!(referenceStridePeriod > 0.2 && referenceStridePeriod < 5.0))
                throw new ArgumentException("The reference stride period must lie within 0.2..5 s.", nameof(referenceStridePeriod));
            this.onsets = (double[])onsets.Clone();
            RightOffset = rightOffset;
            StanceSlope = stanceSlope;
            ReferenceStridePeriod = referenceStridePeriod;
        }

        /// <summary>Perry's phase onsets as fractions of the gait cycle; stance (IC to toe-off) is the first 62 %.</summary>
        static readonly double[] PerryOnsets = { 0.0, 0.02, 0.12, 0.31, 0.50, 0.62, 0.75, 0.87 };
        public const double PerryStance = 0.62;

        public static PhaseMap Perry { get; } = new PhaseMap(PerryOnsets);

        /// <summary>
        /// Perry's phases with stance rescaled to <paramref name="stanceFraction"/> of the cycle and swing to the rest, which
        /// is how per-foot labels are made from measured contacts (IC to toe-off split 0-2-12-31-50-62 %, swing 62-75-87-100 %).
        /// </summary>
        public static PhaseMap FromStanceFraction(double stanceFraction, double rightOffset = 0.5, double stanceSlope = 0, double referenceStridePeriod = 1)
        {
            if (!(stanceFraction > 0.2 && stanceFraction < 0.9)) throw new ArgumentException("Stance must be between 20 % and 90 % of the cycle.", nameof(stanceFraction));
            var onsets = new double[PerryOnsets.Length];
            for (int p = 0; p < onsets.Length; p++)
            {
                double u = PerryOnsets[p];
                onsets[p] = u < PerryStance ? u / PerryStance * stanceFraction : stanceFraction + (u - PerryStance) / (1 - PerryStance) * (1 - stanceFraction);
            }
            return new PhaseMap(onsets, rightOffset, stanceSlope, referenceStridePeriod);
        }

        /// <summary>
        /// This map's onsets and right-foot offset with <paramref name="other"/>'s stance slope and reference period: for a
        /// model whose classes are this map's segments, given the slope learned in C# from the same recordings.
        /// </summary>
        public PhaseMap WithStanceOf(PhaseMap other)
        {
            if (other == null) throw new ArgumentNullException(nameof(other));
            bool same = Math.Abs(RightOffset - other.RightOffset) < 1e-9;
            for (int i = 0; i < onsets.Length && same; i++) same = Math.Abs(onsets[i] - other.onsets[i]) < 1e-9;
            if (!same) throw new ArgumentException($"phase map {other.Serialize()} has other onsets than {Serialize()}");
            return WithStance(other.StanceSlope, other.ReferenceStridePeriod);
        }

        /// <summary>This map's onsets and right-foot offset with another stance slope and reference stride period.</summary>
        public PhaseMap WithStance(double stanceSlope, double referenceStridePeriod)
            => new PhaseMap(onsets, RightOffset, stanceSlope, referenceStridePeriod);

        /// <summary>The phase a foot is in at a fraction of its own cycle under Perry's onsets (0 = its initial contact).</summary>
        public static GaitPhase PerryPhaseAt(double cycleFraction) => Perry.PhaseAt(Foot.Left, cycleFraction);

        /// <summary>Onset of a phase as a fraction of that foot's own cycle.</summary>
        public double Onset(GaitPhase phase)
        {
            if (phase == GaitPhase.Standing) throw new ArgumentException("Standing has no onset in the cycle.");
            return onsets[(int)phase];
        }

        /// <summary>Stride position (0 = left IC) at which the foot enters the phase.</summary>
        public double StridePositionOfOnset(Foot foot, GaitPhase phase)
        {
            double u = Onset(phase);
            return foot == Foot.Left ? u : Wrap(u + RightOffset);
        }

        /// <summary>The phase of a foot at a stride position, with stance at its reference share.</summary>
        public GaitPhase PhaseAt(Foot foot, double stridePosition) => PhaseAtCycle(CyclePosition(foot, stridePosition));

        /// <summary>The phase of a foot at a stride position while walking with this step period (seconds, half a stride).</summary>
        public GaitPhase PhaseAt(Foot foot, double stridePosition, double stepPeriod)
            => PhaseAtCycle(CyclePosition(foot, stridePosition), StanceShare(stepPeriod));

        /// <summary>Where a foot is in its own cycle (0 = its initial contact) at a stride position.</summary>
        public double CyclePosition(Foot foot, double stridePosition)
            => Wrap(foot == Foot.Left ? stridePosition : stridePosition - RightOffset);

        /// <summary>Share of the cycle a foot spends in stance at this step period (seconds, half a stride).</summary>
        public double StanceShare(double stepPeriod)
        {
            double reference = onsets[(int)GaitPhase.InitialSwing];
            if (StanceSlope == 0 || !(stepPeriod > 0)) return reference;
            double shift = StanceSlope * (2 * stepPeriod - ReferenceStridePeriod);
            // Both stance and swing keep some of the cycle whatever the map's own onsets.
            return Math.Max(0.05, Math.Min(0.95, reference + Math.Max(-MaxStanceShift, Math.Min(MaxStanceShift, shift))));
        }

        /// <summary>The phase at a position in the foot's own cycle when stance takes <paramref name="stanceShare"/> of it.</summary>
        public GaitPhase PhaseAtCycle(double cyclePosition, double stanceShare)
        {
            double u = cyclePosition, reference = onsets[(int)GaitPhase.InitialSwing];
            // Stretch stance to the given share and squeeze swing into the rest, then read the reference onsets.
            u = u < stanceShare ? u / stanceShare * reference : reference + (u - stanceShare) / (1 - stanceShare) * (1 - reference);
            return PhaseAtCycle(u);
        }

        GaitPhase PhaseAtCycle(double u)
        {
            for (int i = onsets.Length - 1; i >= 0; i--)
            {
                if (u >= onsets[i]) return (GaitPhase)i;
            }
            return GaitPhase.InitialContact;
        }

        public static double Wrap(double x)
        {
            x -= Math.Floor(x);
            return x >= 1.0 ? 0.0 : x;
        }

        /// <summary>Signed cyclic difference a - b in (-0.5, 0.5].</summary>
        public static double CyclicDelta(double a, double b)
        {
            double d = Wrap(a - b);
            return d > 0.5 ? d - 1.0 : d;
        }

        public string Serialize()
        {
            var sb = new StringBuilder();
            for (int i = 0; i < onsets.Length; i++)
            {
                if (i > 0) sb.Append(',');
                sb.Append(onsets[i].ToString("R", CultureInfo.InvariantCulture));
            }
            sb.Append(';').Append(RightOffset.ToString("R", CultureInfo.InvariantCulture));
            if (StanceSlope != 0)
            {
                sb.Append(';').Append(StanceSlope.ToString("R", CultureInfo.InvariantCulture))
                  .Append(',').Append(ReferenceStridePeriod.ToString("R", CultureInfo.InvariantCulture));
            }
            return sb.ToString();
        }

        /// <summary>A finite number, or a <see cref="FormatException"/> that quotes the text (never an overflow: Mono's parser throws one).</summary>
        static double Number(string text)
        {
            if (!KeyValueText.TryNumber(text.Trim(), out double v)) throw new FormatException($"'{text.Trim()}' is not a finite number.");
            return v;
        }

        public static PhaseMap Parse(string text)
        {
            if (text == null) throw new FormatException("Phase map text is missing.");
            string[] parts = text.Split(';');
            if (parts.Length != 2 && parts.Length != 3)
                throw new FormatException("Phase map must be '<8 onsets>;<right offset>[;<stance slope>,<reference stride period>]'.");
            string[] values = parts[0].Split(',');
            if (values.Length != GaitPhases.WalkingPhaseCount) throw new FormatException("Phase map needs 8 onsets.");
            var onsets = new double[values.Length];
            for (int i = 0; i < values.Length; i++)
                onsets[i] = Number(values[i]);
            double offset = Number(parts[1]);
            double slope = 0, reference = 1;
            if (parts.Length == 3)
            {
                string[] stance = parts[2].Split(',');
                if (stance.Length != 2) throw new FormatException("Phase map's stance part must be '<slope>,<reference stride period>'.");
                slope = Number(stance[0]);
                reference = Number(stance[1]);
            }
            try
            {
                return new PhaseMap(onsets, offset, slope, reference);
            }
            catch (ArgumentException e)
            {
                throw new FormatException(e.Message);
            }
        }
    }
}
