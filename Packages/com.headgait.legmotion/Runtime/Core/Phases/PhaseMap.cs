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
    /// </summary>
    public sealed class PhaseMap
    {
        readonly double[] onsets;

        public double RightOffset { get; }

        public PhaseMap(double[] onsets, double rightOffset = 0.5)
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
            this.onsets = (double[])onsets.Clone();
            RightOffset = rightOffset;
        }

        /// <summary>Perry's phase onsets as fractions of the gait cycle; stance (IC to toe-off) is the first 62 %.</summary>
        static readonly double[] PerryOnsets = { 0.0, 0.02, 0.12, 0.31, 0.50, 0.62, 0.75, 0.87 };
        public const double PerryStance = 0.62;

        public static PhaseMap Perry { get; } = new PhaseMap(PerryOnsets);

        /// <summary>
        /// Perry's phases with stance rescaled to <paramref name="stanceFraction"/> of the cycle and swing to the rest, which
        /// is how per-foot labels are made from measured contacts (IC to toe-off split 0-2-12-31-50-62 %, swing 62-75-87-100 %).
        /// </summary>
        public static PhaseMap FromStanceFraction(double stanceFraction, double rightOffset = 0.5)
        {
            if (!(stanceFraction > 0.2 && stanceFraction < 0.9)) throw new ArgumentException("Stance must be between 20 % and 90 % of the cycle.", nameof(stanceFraction));
            var onsets = new double[PerryOnsets.Length];
            for (int p = 0; p < onsets.Length; p++)
            {
                double u = PerryOnsets[p];
                onsets[p] = u < PerryStance ? u / PerryStance * stanceFraction : stanceFraction + (u - PerryStance) / (1 - PerryStance) * (1 - stanceFraction);
            }
            return new PhaseMap(onsets, rightOffset);
        }

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

        /// <summary>The phase of a foot at a stride position.</summary>
        public GaitPhase PhaseAt(Foot foot, double stridePosition)
        {
            double u = Wrap(foot == Foot.Left ? stridePosition : stridePosition - RightOffset);
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
            return sb.ToString();
        }

        public static PhaseMap Parse(string text)
        {
            if (text == null) throw new FormatException("Phase map text is missing.");
            string[] parts = text.Split(';');
            if (parts.Length != 2) throw new FormatException("Phase map must be '<8 onsets>;<right offset>'.");
            string[] values = parts[0].Split(',');
            if (values.Length != GaitPhases.WalkingPhaseCount) throw new FormatException("Phase map needs 8 onsets.");
            var onsets = new double[values.Length];
            for (int i = 0; i < values.Length; i++)
                onsets[i] = double.Parse(values[i], NumberStyles.Float, CultureInfo.InvariantCulture);
            double offset = double.Parse(parts[1], NumberStyles.Float, CultureInfo.InvariantCulture);
            try
            {
                return new PhaseMap(onsets, offset);
            }
            catch (ArgumentException e)
            {
                throw new FormatException(e.Message);
            }
        }
    }
}
