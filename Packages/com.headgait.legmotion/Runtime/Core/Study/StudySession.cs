using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;

namespace HeadGait.Study
{
    /// <summary>
    /// One participant's run through the study, kept in a <see cref="StudyJournal"/>: the steps of
    /// <see cref="StudyProtocol"/>, the answers given at each, and events (trial started, repeated, aborted). Every call
    /// that records something is on disk when it returns. <see cref="Resume"/> rebuilds the session from the journal,
    /// with the settings it was started with, at the first unfinished step.
    /// </summary>
    public sealed class StudySession
    {
        const string SessionKind = "session", AnswerKind = "answer", DoneKind = "done", EventKind = "event";
        const string SsqKey = "ssq";

        readonly StudyJournal journal;
        readonly HashSet<int> done = new HashSet<int>();
        readonly Dictionary<int, Dictionary<string, string>> answers = new Dictionary<int, Dictionary<string, string>>();

        StudySession(StudyJournal journal, StudyConfig config)
        {
            this.journal = journal;
            Config = config;
            Steps = StudyProtocol.StepsFor(journal.Participant, config);
        }

        public string Participant => journal.Participant;
        public StudyConfig Config { get; }
        public IReadOnlyList<StudyStep> Steps { get; }
        public string JournalPath => journal.Path;
        public bool RecoveredTornLine => journal.RecoveredTornLine;

        /// <summary>The first step not completed (Done once all are).</summary>
        public StudyStep Current
        {
            get
            {
                foreach (var s in Steps)
                    if (!done.Contains(s.Index)) return s;
                return Steps[Steps.Count - 1];
            }
        }

        public bool IsComplete(int step) => done.Contains(step);

        /// <summary>Starts a new participant (refused when the id already has data).</summary>
        public static StudySession Start(string folder, string participantId, StudyConfig config)
        {
            config.Validate();
            ParticipantIds.Validate(participantId);
            // A journal that holds nothing but its first line (a crash right after creating it) is no data: start on it.
            var journal = StudyJournal.Exists(folder, participantId) && StudyJournal.Open(folder, participantId).Entries.Count == 0
                ? StudyJournal.Open(folder, participantId)
                : StudyJournal.Create(folder, participantId);
            var session = new StudySession(journal, config);
            var ci = CultureInfo.InvariantCulture;
            journal.Append(SessionKind, -1, "conditions", string.Join(",", config.Conditions));
            journal.Append(SessionKind, -1, "path_length_m", config.PathLengthMeters.ToString("R", ci));
            journal.Append(SessionKind, -1, "humanoid_classifier", config.HumanoidClassifier);
            journal.Append(SessionKind, -1, "rest_s", config.RestSeconds.ToString("R", ci));
            var order = new List<string>();
            foreach (var s in session.Steps) if (s.Kind == StudyStepKind.Trial) order.Add(s.Condition);
            journal.Append(SessionKind, -1, "order", string.Join(",", order));
            return session;
        }

        /// <summary>
        /// Reopens a participant at the first unfinished step, with the settings the session was started with.
        /// <paramref name="readOnly"/> leaves the file untouched (for reading results; a torn last line is then only skipped).
        /// </summary>
        public static StudySession Resume(string folder, string participantId, bool readOnly = false)
        {
            var journal = StudyJournal.Open(folder, participantId, !readOnly);
            var config = new StudyConfig();
            bool haveConditions = false;
            foreach (var e in journal.Entries)
            {
                if (e.Kind != SessionKind) continue;
                var ci = CultureInfo.InvariantCulture;
                switch (e.Key)
                {
                    case "conditions":
                        config.Conditions = new List<string>(e.Value.Split(','));
                        haveConditions = true;
                        break;
                    case "path_length_m": config.PathLengthMeters = double.Parse(e.Value, ci); break;
                    case "humanoid_classifier": config.HumanoidClassifier = e.Value; break;
                    case "rest_s": config.RestSeconds = double.Parse(e.Value, ci); break;
                }
            }
            if (!haveConditions) throw new StudyStorageException($"{journal.Path}: the session settings were never saved; the journal holds no answers to resume.");
            var session = new StudySession(journal, config);
            foreach (var e in journal.Entries)
            {
                if (e.Kind == DoneKind) session.done.Add(e.Step);
                else if (e.Kind == AnswerKind) session.Remember(e.Step, e.Key, e.Value);
            }
            return session;
        }

        void Remember(int step, string key, string value)
        {
            if (!answers.TryGetValue(step, out var a)) answers[step] = a = new Dictionary<string, string>();
            a[key] = value;
        }

        /// <summary>An answer of the current step (e.g. a demographics field); saved before returning.</summary>
        public void Answer(string key, string value)
        {
            if (string.IsNullOrEmpty(key) || key == SsqKey) throw new ArgumentException("Answers need a key other than 'ssq'.");
            var step = Current;
            journal.Append(AnswerKind, step.Index, key, value);
            Remember(step.Index, key, value);
        }

        /// <summary>The 16 SSQ ratings of the current (SSQ) step, validated and saved as one line.</summary>
        public SsqScores AnswerSsq(IReadOnlyList<int> ratings)
        {
            var step = Current;
            if (!step.IsSsq) throw new InvalidOperationException($"Step {step} is not an SSQ.");
            var scores = SimulatorSicknessQuestionnaire.Score(ratings);
            string value = string.Join(",", ratings);
            journal.Append(AnswerKind, step.Index, SsqKey, value);
            Remember(step.Index, SsqKey, value);
            return scores;
        }

        /// <summary>Marks the current step complete and moves on; an SSQ step needs its ratings first.</summary>
        public StudyStep CompleteStep()
        {
            var step = Current;
            if (step.Kind == StudyStepKind.Done) return step;
            if (step.IsSsq && SsqOf(step.Index) == null) throw new InvalidOperationException($"Step {step} needs the 16 SSQ ratings before it is complete.");
            journal.Append(DoneKind, step.Index, "", "");
            done.Add(step.Index);
            return Current;
        }

        /// <summary>An operator or scene event for the current step (trial started, repeated, aborted, ...).</summary>
        public void Event(string name, string detail = "") => journal.Append(EventKind, Current.Index, name, detail);

        public IReadOnlyDictionary<string, string> AnswersOf(int step)
            => answers.TryGetValue(step, out var a) ? a : new Dictionary<string, string>();

        /// <summary>The SSQ ratings saved for a step, or null.</summary>
        public int[] SsqOf(int step)
        {
            if (!answers.TryGetValue(step, out var a) || !a.TryGetValue(SsqKey, out var v)) return null;
            var parts = v.Split(',');
            if (parts.Length != SimulatorSicknessQuestionnaire.ItemCount) return null;
            var r = new int[parts.Length];
            for (int i = 0; i < parts.Length; i++)
                if (!int.TryParse(parts[i], NumberStyles.Integer, CultureInfo.InvariantCulture, out r[i])) return null;
            return r;
        }
    }
}
