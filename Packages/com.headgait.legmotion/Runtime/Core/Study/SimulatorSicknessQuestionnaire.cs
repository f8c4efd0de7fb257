using System;
using System.Collections.Generic;

namespace HeadGait.Study
{
    /// <summary>The 16 symptoms of the Simulator Sickness Questionnaire (Kennedy, Lane, Berbaum and Lilienthal, 1993).</summary>
    public enum SsqItem
    {
        GeneralDiscomfort = 0,
        Fatigue = 1,
        Headache = 2,
        Eyestrain = 3,
        DifficultyFocusing = 4,
        IncreasedSalivation = 5,
        Sweating = 6,
        Nausea = 7,
        DifficultyConcentrating = 8,
        FullnessOfHead = 9,
        BlurredVision = 10,
        DizzyEyesOpen = 11,
        DizzyEyesClosed = 12,
        Vertigo = 13,
        StomachAwareness = 14,
        Burping = 15,
    }

    /// <summary>SSQ subscales and total, weighted as Kennedy et al. (1993) define them.</summary>
    public readonly struct SsqScores
    {
        public SsqScores(int rawNausea, int rawOculomotor, int rawDisorientation)
        {
            RawNausea = rawNausea;
            RawOculomotor = rawOculomotor;
            RawDisorientation = rawDisorientation;
        }

        public int RawNausea { get; }
        public int RawOculomotor { get; }
        public int RawDisorientation { get; }

        public double Nausea => RawNausea * SimulatorSicknessQuestionnaire.NauseaWeight;
        public double Oculomotor => RawOculomotor * SimulatorSicknessQuestionnaire.OculomotorWeight;
        public double Disorientation => RawDisorientation * SimulatorSicknessQuestionnaire.DisorientationWeight;
        public double Total => (RawNausea + RawOculomotor + RawDisorientation) * SimulatorSicknessQuestionnaire.TotalWeight;

        /// <summary>Post-exposure minus pre-exposure, subscale by subscale.</summary>
        public SsqScores Minus(SsqScores pre) => new SsqScores(RawNausea - pre.RawNausea, RawOculomotor - pre.RawOculomotor, RawDisorientation - pre.RawDisorientation);

        public override string ToString() => $"N {Nausea:F2} O {Oculomotor:F2} D {Disorientation:F2} Total {Total:F2}";
    }

    /// <summary>
    /// The SSQ: each symptom rated 0 (none), 1 (slight), 2 (moderate) or 3 (severe); each symptom loads on one or two of
    /// the subscales Nausea (N), Oculomotor (O) and Disorientation (D). Scores: N = raw N x 9.54, O = raw O x 7.58,
    /// D = raw D x 13.92, Total = (raw N + raw O + raw D) x 3.74.
    /// </summary>
    public static class SimulatorSicknessQuestionnaire
    {
        public const double NauseaWeight = 9.54, OculomotorWeight = 7.58, DisorientationWeight = 13.92, TotalWeight = 3.74;
        public const int ItemCount = 16;
        public const int MaxRating = 3;

        [Flags]
        public enum Subscale
        {
            None = 0,
            Nausea = 1,
            Oculomotor = 2,
            Disorientation = 4,
        }

        static readonly Subscale[] Loadings =
        {
            Subscale.Nausea | Subscale.Oculomotor,        // general discomfort
            Subscale.Oculomotor,                          // fatigue
            Subscale.Oculomotor,                          // headache
            Subscale.Oculomotor,                          // eyestrain
            Subscale.Oculomotor | Subscale.Disorientation,// difficulty focusing
            Subscale.Nausea,                              // increased salivation
            Subscale.Nausea,                              // sweating
            Subscale.Nausea | Subscale.Disorientation,    // nausea
            Subscale.Nausea | Subscale.Oculomotor,        // difficulty concentrating
            Subscale.Disorientation,                      // fullness of head
            Subscale.Oculomotor | Subscale.Disorientation,// blurred vision
            Subscale.Disorientation,                      // dizzy (eyes open)
            Subscale.Disorientation,                      // dizzy (eyes closed)
            Subscale.Disorientation,                      // vertigo
            Subscale.Nausea,                              // stomach awareness
            Subscale.Nausea,                              // burping
        };

        static readonly string[] Labels =
        {
            "General discomfort", "Fatigue", "Headache", "Eyestrain", "Difficulty focusing", "Increased salivation", "Sweating",
            "Nausea", "Difficulty concentrating", "Fullness of head", "Blurred vision", "Dizzy (eyes open)", "Dizzy (eyes closed)",
            "Vertigo", "Stomach awareness", "Burping",
        };

        static readonly string[] RatingLabels = { "None", "Slight", "Moderate", "Severe" };

        public static Subscale LoadingOf(SsqItem item) => Loadings[(int)item];

        /// <summary>The wording shown to participants.</summary>
        public static string Label(SsqItem item) => Labels[(int)item];

        public static string RatingLabel(int rating) => rating >= 0 && rating <= MaxRating ? RatingLabels[rating] : "?";

        /// <summary>Scores 16 ratings (in <see cref="SsqItem"/> order, each 0..3); throws <see cref="ArgumentException"/> naming a bad one.</summary>
        public static SsqScores Score(IReadOnlyList<int> ratings)
        {
            if (ratings == null || ratings.Count != ItemCount) throw new ArgumentException($"The SSQ has {ItemCount} items; got {ratings?.Count ?? 0} ratings.");
            int n = 0, o = 0, d = 0;
            for (int i = 0; i < ItemCount; i++)
            {
                int r = ratings[i];
                if (r < 0 || r > MaxRating) throw new ArgumentException($"SSQ item '{Labels[i]}' is rated {r}; ratings are 0 (none) to 3 (severe).");
                var l = Loadings[i];
                if ((l & Subscale.Nausea) != 0) n += r;
                if ((l & Subscale.Oculomotor) != 0) o += r;
                if ((l & Subscale.Disorientation) != 0) d += r;
            }
            return new SsqScores(n, o, d);
        }
    }
}
