using System;
using System.Collections.Generic;

namespace HeadGait.Study
{
    /// <summary>What a study session is made of.</summary>
    public sealed class StudyConfig
    {
        /// <summary>The VR conditions, counterbalanced over participants (the paper: no avatar, a block avatar, an animated humanoid).</summary>
        public List<string> Conditions = new List<string> { NoAvatar, BlockAvatar, HumanoidAvatar };

        public const string NoAvatar = "no-avatar";
        public const string BlockAvatar = "block-avatar";
        public const string HumanoidAvatar = "humanoid-avatar";

        /// <summary>Length of the walking path from Start over Turn to End (m).</summary>
        public double PathLengthMeters = 16;

        /// <summary>Classifier that animates the humanoid (the paper: COR).</summary>
        public string HumanoidClassifier = "cor";

        /// <summary>Rest between conditions (s).</summary>
        public double RestSeconds = 120;

        public void Validate()
        {
            if (Conditions == null || Conditions.Count < 1 || Conditions.Count > 26) throw new ArgumentException("A study needs 1 to 26 conditions.");
            var seen = new HashSet<string>();
            foreach (var c in Conditions)
            {
                if (!ParticipantIds.IsValidName(c)) throw new ArgumentException($"Condition name '{c}' must be 1-32 letters, digits, '-' or '_'.");
                if (!seen.Add(c)) throw new ArgumentException($"Condition '{c}' is listed twice.");
            }
            if (!(PathLengthMeters > 0 && PathLengthMeters < 1000)) throw new ArgumentException("The path length must be between 0 and 1000 m.");
            if (!(RestSeconds >= 0 && RestSeconds < 3600)) throw new ArgumentException("The rest must be between 0 and 3600 s.");
        }
    }

    public enum StudyStepKind
    {
        Demographics,
        /// <summary>SSQ before any exposure.</summary>
        PreExposureSsq,
        /// <summary>Walking the path in the real room, no headset.</summary>
        BaselineWalk,
        BaselineSsq,
        /// <summary>Walking the path in VR under one condition.</summary>
        Trial,
        /// <summary>SSQ right after a condition's trial.</summary>
        ConditionSsq,
        Rest,
        Done,
    }

    public readonly struct StudyStep
    {
        public StudyStep(int index, StudyStepKind kind, string condition = null)
        {
            Index = index;
            Kind = kind;
            Condition = condition;
        }

        public int Index { get; }
        public StudyStepKind Kind { get; }

        /// <summary>The VR condition of a Trial or ConditionSsq step; null otherwise.</summary>
        public string Condition { get; }

        public bool IsSsq => Kind == StudyStepKind.PreExposureSsq || Kind == StudyStepKind.BaselineSsq || Kind == StudyStepKind.ConditionSsq;

        public override string ToString() => Condition == null ? $"{Index + 1}. {Kind}" : $"{Index + 1}. {Kind} ({Condition})";
    }

    /// <summary>
    /// A participant's session: demographics, pre-exposure SSQ, the physical baseline walk and its SSQ, then each VR
    /// condition in the participant's counterbalanced order with an SSQ after it and a rest between conditions.
    /// </summary>
    public static class StudyProtocol
    {
        public static List<StudyStep> StepsFor(string participantId, StudyConfig config)
        {
            config.Validate();
            return StepsFor(config, Counterbalancing.OrderFor(ParticipantIds.Canonical(participantId), config.Conditions.Count));
        }

        /// <summary>The steps for a given condition order (indices into the conditions), e.g. the one saved with a participant.</summary>
        public static List<StudyStep> StepsFor(StudyConfig config, int[] order)
        {
            config.Validate();
            var steps = new List<StudyStep>();
            void Add(StudyStepKind kind, string condition = null) => steps.Add(new StudyStep(steps.Count, kind, condition));
            Add(StudyStepKind.Demographics);
            Add(StudyStepKind.PreExposureSsq);
            Add(StudyStepKind.BaselineWalk);
            Add(StudyStepKind.BaselineSsq);
            for (int i = 0; i < order.Length; i++)
            {
                string c = config.Conditions[order[i]];
                Add(StudyStepKind.Trial, c);
                Add(StudyStepKind.ConditionSsq, c);
                if (i + 1 < order.Length) Add(StudyStepKind.Rest);
            }
            Add(StudyStepKind.Done);
            return steps;
        }
    }

    /// <summary>
    /// Participant ids name files: short, nothing that could leave the data folder, one canonical form (upper case: "p01"
    /// and "P01" are one participant, as they are one file on Windows and macOS disks), no names Windows reserves for
    /// devices (CON, PRN, AUX, NUL, COM1-9, LPT1-9) and nothing that reads as a command-line option (a leading '-').
    /// </summary>
    public static class ParticipantIds
    {
        public const int MaxLength = 32;

        static readonly string[] DeviceNames = { "CON", "PRN", "AUX", "NUL" };

        /// <summary>Letters, digits, '-' and '_', 1 to 32 of them (also the rule for condition names).</summary>
        public static bool IsValidName(string id)
        {
            if (string.IsNullOrEmpty(id) || id.Length > MaxLength) return false;
            foreach (char c in id)
                if (!(c >= 'A' && c <= 'Z' || c >= 'a' && c <= 'z' || c >= '0' && c <= '9' || c == '-' || c == '_')) return false;
            return true;
        }

        /// <summary>Throws <see cref="ArgumentException"/> saying what is wrong with an id.</summary>
        public static void Validate(string id)
        {
            if (string.IsNullOrEmpty(id)) throw new ArgumentException("The participant id is empty.");
            if (id.Length > MaxLength) throw new ArgumentException($"The participant id '{id.Substring(0, 10)}...' is longer than {MaxLength} characters.");
            if (!IsValidName(id)) throw new ArgumentException($"The participant id '{id}' may hold only letters, digits, '-' and '_' (no spaces, dots or path separators).");
            if (id[0] == '-') throw new ArgumentException($"The participant id '{id}' starts with '-', which reads as a command-line option; start it with a letter or digit.");
            string upper = id.ToUpperInvariant();
            bool device = Array.IndexOf(DeviceNames, upper) >= 0
                          || upper.Length == 4 && (upper.StartsWith("COM", StringComparison.Ordinal) || upper.StartsWith("LPT", StringComparison.Ordinal)) && upper[3] >= '1' && upper[3] <= '9';
            if (device) throw new ArgumentException($"The participant id '{id}' is a name Windows reserves for a device and cannot name a file; choose another (e.g. P01).");
        }

        /// <summary>The id's one form (trimmed, upper case); throws <see cref="ArgumentException"/> for an invalid id.</summary>
        public static string Canonical(string id)
        {
            id = (id ?? "").Trim();
            Validate(id);
            return id.ToUpperInvariant();
        }

        /// <summary>True (with its canonical form) for a valid id.</summary>
        public static bool TryCanonical(string id, out string canonical)
        {
            try
            {
                canonical = Canonical(id);
                return true;
            }
            catch (ArgumentException)
            {
                canonical = null;
                return false;
            }
        }
    }
}
