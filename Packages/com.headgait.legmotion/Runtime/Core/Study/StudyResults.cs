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

    /// <summary>
    /// All participants' results of a study folder, and every problem met reading them: journals that could not be used,
    /// and every value left out or in doubt (a damaged line, an SSQ answer that does not read, a corrected answer, a torn
    /// last line). Nothing is left out without a line in <see cref="Problems"/>; the files are only read.
    /// </summary>
    public sealed class StudyResults
    {
        public List<ParticipantResults> Participants { get; } = new List<ParticipantResults>();
        public List<string> Problems { get; } = new List<string>();
        public List<string> Conditions { get; } = new List<string>();

        /// <summary>Reads every journal in the folder; what cannot be used is listed in <see cref="Problems"/>, naming the file.</summary>
        public static StudyResults Load(string folder)
        {
            var results = new StudyResults();
            if (!Directory.Exists(folder))
            {
                results.Problems.Add($"{folder}: no such folder");
                return results;
            }
            var files = new List<string>();
            foreach (var f in Directory.GetFiles(folder, "*" + StudyJournal.Extension))
                if (f.EndsWith(StudyJournal.Extension, StringComparison.Ordinal)) files.Add(f);
            files.Sort(StringComparer.Ordinal);
            // Ids are one participant whatever their case: two files for one id are reported, not merged or picked from.
            var byId = new Dictionary<string, List<string>>();
            foreach (var file in files)
            {
                string name = Path.GetFileName(file);
                name = name.Substring(0, name.Length - StudyJournal.Extension.Length);
                if (!ParticipantIds.TryCanonical(name, out string id))
                {
                    results.Problems.Add($"{file}: '{name}' is not a valid participant id; skipped");
                    continue;
                }
                if (!byId.TryGetValue(id, out var list)) byId[id] = list = new List<string>();
                list.Add(file);
            }
            foreach (var file in files)
            {
                string name = Path.GetFileName(file);
                name = name.Substring(0, name.Length - StudyJournal.Extension.Length);
                if (!ParticipantIds.TryCanonical(name, out string id)) continue;
                if (byId[id].Count > 1)
                {
                    if (byId[id][0] == file)
                        results.Problems.Add($"participant {id} has {byId[id].Count} journals whose names differ only in case ({string.Join(", ", byId[id])}); all skipped until they are merged into one");
                    continue;
                }
                try
                {
                    using (var session = StudySession.Resume(folder, id, readOnly: true))
                        results.Add(session, file);
                }
                catch (Exception e) when (e is StudyStorageException || e is FormatException || e is ArgumentException || e is InvalidOperationException || e is IOException)
                {
                    results.Problems.Add((e.Message.IndexOf(file, StringComparison.Ordinal) >= 0 ? e.Message : $"{file}: {e.Message}") + " Skipped.");
                }
            }
            return results;
        }

        void Add(StudySession session, string file)
        {
            foreach (var d in session.Damage) Problems.Add($"{file}:{d.LineNumber}: {d.Reason}; not used: '{d.Text}'");
            if (session.IsV1Journal) Problems.Add($"{file}: written before lines carried checksums (journal v1): damage to its older lines cannot be detected");
            if (session.RecoveredTornLine) Problems.Add($"{file}: its last line is torn (a crash while writing, or a session writing now); it was never acknowledged and is not used");
            var p = new ParticipantResults { Participant = session.Participant };
            int position = 0;
            foreach (var step in session.Steps)
            {
                if (step.Kind == StudyStepKind.Trial) p.Position[step.Condition] = ++position;
                if (!step.IsSsq) continue;
                var saved = session.SsqAnswersOf(step.Index);
                if (saved.Count == 0)
                {
                    if (session.IsComplete(step.Index)) Problems.Add($"{file}: step {step} is marked done but has no SSQ answer that could be read");
                    continue;
                }
                if (!StudySession.TryReadSsq(saved[saved.Count - 1], out var ratings, out string problem))
                {
                    Problems.Add($"{file}: the SSQ of step {step} cannot be read ({problem}); not used");
                    continue;
                }
                if (saved.Count > 1)
                    Problems.Add($"{file}: the SSQ of step {step} was answered {saved.Count} times (corrected); the last is used, the earlier ones stay in the journal");
                if (!session.IsComplete(step.Index))
                    Problems.Add($"{file}: the SSQ of step {step} was saved but its step never marked done (the session stopped right after it); it is used");
                var scores = SimulatorSicknessQuestionnaire.Score(ratings);
                if (step.Kind == StudyStepKind.PreExposureSsq) p.PreExposure = scores;
                else if (step.Kind == StudyStepKind.BaselineSsq) p.Baseline = scores;
                else p.Conditions[step.Condition] = scores;
            }
            foreach (var c in session.Config.Conditions)
                if (!Conditions.Contains(c)) Conditions.Add(c);
            Participants.Add(p);
        }
    }
}
