using System;
using System.Collections.Generic;
using System.IO;

namespace HeadGait.Study
{
    /// <summary>One participant's SSQ results, read back from their journal.</summary>
    public sealed class ParticipantResults
    {
        public string Participant;
        public SsqScores? PreExposure;
        public SsqScores? Baseline;
        /// <summary>SSQ after each VR condition they finished, by condition name.</summary>
        public Dictionary<string, SsqScores> Conditions = new Dictionary<string, SsqScores>();
        /// <summary>The position (1-based) each condition had in their order.</summary>
        public Dictionary<string, int> Position = new Dictionary<string, int>();
    }

    /// <summary>All participants' results of a study folder, and which journals could not be used and why.</summary>
    public sealed class StudyResults
    {
        public List<ParticipantResults> Participants { get; } = new List<ParticipantResults>();
        public List<string> Problems { get; } = new List<string>();
        public List<string> Conditions { get; } = new List<string>();

        /// <summary>Reads every journal in the folder; an unreadable or malformed one is listed in <see cref="Problems"/> and skipped.</summary>
        public static StudyResults Load(string folder)
        {
            var results = new StudyResults();
            if (!Directory.Exists(folder))
            {
                results.Problems.Add($"{folder}: no such folder");
                return results;
            }
            var files = Directory.GetFiles(folder, "*" + StudyJournal.Extension);
            Array.Sort(files, StringComparer.Ordinal);
            foreach (var file in files)
            {
                string id = Path.GetFileName(file);
                id = id.Substring(0, id.Length - StudyJournal.Extension.Length);
                try
                {
                    if (!ParticipantIds.IsValidName(id)) throw new StudyStorageException($"{file}: '{id}' is not a valid participant id");
                    var session = StudySession.Resume(folder, id, readOnly: true);
                    var p = new ParticipantResults { Participant = id };
                    int position = 0;
                    foreach (var step in session.Steps)
                    {
                        if (step.Kind == StudyStepKind.Trial) p.Position[step.Condition] = ++position;
                        if (!step.IsSsq || !session.IsComplete(step.Index)) continue;
                        var ratings = session.SsqOf(step.Index);
                        if (ratings == null) continue;
                        var scores = SimulatorSicknessQuestionnaire.Score(ratings);
                        if (step.Kind == StudyStepKind.PreExposureSsq) p.PreExposure = scores;
                        else if (step.Kind == StudyStepKind.BaselineSsq) p.Baseline = scores;
                        else p.Conditions[step.Condition] = scores;
                    }
                    foreach (var c in session.Config.Conditions)
                        if (!results.Conditions.Contains(c)) results.Conditions.Add(c);
                    if (session.RecoveredTornLine) results.Problems.Add($"{file}: its last line was torn (a crash while writing) and was dropped");
                    results.Participants.Add(p);
                }
                catch (Exception e) when (e is StudyStorageException || e is FormatException || e is ArgumentException || e is InvalidOperationException || e is IOException)
                {
                    results.Problems.Add(e.Message.IndexOf(file, StringComparison.Ordinal) >= 0 ? e.Message : $"{file}: {e.Message}");
                }
            }
            return results;
        }
    }
}
