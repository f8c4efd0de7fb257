using System;

namespace HeadGait
{
    /// <summary>The eight phases of one leg's gait cycle (Perry), plus standing.</summary>
    public enum GaitPhase
    {
        InitialContact = 0,
        LoadingResponse = 1,
        MidStance = 2,
        TerminalStance = 3,
        PreSwing = 4,
        InitialSwing = 5,
        MidSwing = 6,
        TerminalSwing = 7,
        Standing = 8,
    }

    public enum Foot
    {
        Left = 0,
        Right = 1,
    }

    public static class GaitPhases
    {
        /// <summary>Number of walking phases per leg.</summary>
        public const int WalkingPhaseCount = 8;

        static readonly string[] ShortNames = { "IC", "LR", "MST", "TST", "PSW", "ISW", "MSW", "TSW", "STAND" };

        public static string ShortName(GaitPhase phase)
        {
            int i = (int)phase;
            return i >= 0 && i < ShortNames.Length ? ShortNames[i] : phase.ToString();
        }

        public static bool IsStance(GaitPhase phase) => phase <= GaitPhase.PreSwing;

        public static bool IsSwing(GaitPhase phase) => phase >= GaitPhase.InitialSwing && phase <= GaitPhase.TerminalSwing;

        /// <summary>Whether a foot going from <paramref name="before"/> to <paramref name="now"/> lands (swing to stance).</summary>
        public static bool IsContact(GaitPhase before, GaitPhase now) => IsSwing(before) && IsStance(now);

        /// <summary>Whether a foot going from <paramref name="before"/> to <paramref name="now"/> lifts off (stance to swing).</summary>
        public static bool IsToeOff(GaitPhase before, GaitPhase now) => IsStance(before) && IsSwing(now);

        public static Foot Other(Foot foot) => foot == Foot.Left ? Foot.Right : Foot.Left;

        /// <summary>
        /// Parses a phase written either as its short name (IC, LR, MST, TST, PSW, ISW, MSW, TSW, STAND),
        /// its enum name (MidStance) or with separators (mid_stance, "Mid Stance"); case-insensitive.
        /// </summary>
        public static bool TryParse(string text, out GaitPhase phase)
        {
            phase = GaitPhase.Standing;
            if (text == null) return false;
            string t = text.Trim().Replace("_", "").Replace("-", "").Replace(" ", "").ToUpperInvariant();
            if (t.Length == 0) return false;
            for (int i = 0; i < ShortNames.Length; i++)
            {
                if (t == ShortNames[i] || t == ((GaitPhase)i).ToString().ToUpperInvariant())
                {
                    phase = (GaitPhase)i;
                    return true;
                }
            }
            if (t == "STANDING" || t == "ST" || t == "S")
            {
                phase = GaitPhase.Standing;
                return true;
            }
            return false;
        }

        /// <summary>
        /// Distance between two phases in phase steps: cyclic distance (0..4) between walking phases,
        /// 0 between two Standing, and 4 (the largest cyclic distance) between Standing and any walking phase.
        /// </summary>
        public static int Distance(GaitPhase a, GaitPhase b)
        {
            if (a == b) return 0;
            if (a == GaitPhase.Standing || b == GaitPhase.Standing) return WalkingPhaseCount / 2;
            int d = Math.Abs((int)a - (int)b);
            return Math.Min(d, WalkingPhaseCount - d);
        }
    }
}
