using System;
using System.Collections.Generic;
using System.Globalization;

namespace HeadGait.Study
{
    /// <summary>
    /// One participant's run through the study, kept in a <see cref="StudyJournal"/>: the steps of
    /// <see cref="StudyProtocol"/>, the answers given at each, and events (trial started, repeated, aborted). Every call
    /// that records something is on disk when it returns. <see cref="Resume"/> rebuilds the session from the journal,
    /// with the settings and condition order it was started with, at the first unfinished step. A session open for
    /// writing holds the participant's lock until it is disposed.
    /// </summary>
    public sealed class StudySession : IDisposable
    {
        const string SessionKind = "session", AnswerKind = "answer", DoneKind = "done", EventKind = "event";
        const string SsqKey = "ssq", OrderKey = "order";

        readonly StudyJournal journal;
        readonly HashSet<int> done = new HashSet<int>();
        readonly Dictionary<int, Dictionary<string, string>> answers = new Dictionary<int, Dictionary<string, string>>();
        readonly Dictionary<int, List<string>> ssqAnswers = new Dictionary<int, List<string>>();

        StudySession(StudyJournal journal, StudyConfig config, int[] order)
        {
            this.journal = journal;
            Config = config;
            Steps = order == null ? StudyProtocol.StepsFor(journal.Participant, config) : StudyProtocol.StepsFor(config, order);
        }

        /// <summary>The participant's id in its canonical form.</summary>
        public string Participant => journal.Participant;
        public StudyConfig Config { get; }
        public IReadOnlyList<StudyStep> Steps { get; }
        public string JournalPath => journal.Path;
        public bool RecoveredTornLine => journal.RecoveredTornLine;
        /// <summary>Bytes of the torn last line cut (or, read only, skipped).</summary>
        public int TornBytes => journal.TornBytes;
        /// <summary>Lines of the journal that fail their checksum or cannot be read: left out of the session and reported.</summary>
        public IReadOnlyList<JournalDamage> Damage => journal.Damage;
        /// <summary>True for a journal written before checksums (v1): damage to its older lines cannot be detected.</summary>
        public bool IsV1Journal => journal.IsV1;

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
        public static StudySession Start(string folder, string participantId, StudyConfig config, JournalFileAccess files = null)
        {
            config.Validate();
            var journal = StudyJournal.OpenOrCreate(folder, participantId, files);
            if (IsStarted(journal))
            {
                journal.Dispose();
                throw new StudyStorageException($"Participant {journal.Participant} already has data in {journal.Path}; open it to resume, or choose another id.");
            }
            return StartOn(journal, config);
        }

        /// <summary>Opens a participant for writing: resumes one that has data, starts one that has none. <paramref name="resumed"/> says which.</summary>
        public static StudySession OpenOrStart(string folder, string participantId, StudyConfig config, out bool resumed, JournalFileAccess files = null)
        {
            config.Validate();
            var journal = StudyJournal.OpenOrCreate(folder, participantId, files);
            resumed = IsStarted(journal);
            return resumed ? FromJournal(journal) : StartOn(journal, config);
        }

        /// <summary>
        /// Reopens a participant at the first unfinished step, with the settings the session was started with.
        /// <paramref name="readOnly"/> leaves the file untouched and takes no lock (for reading results; a torn last line is then only skipped).
        /// </summary>
        public static StudySession Resume(string folder, string participantId, bool readOnly = false, JournalFileAccess files = null)
            => FromJournal(StudyJournal.Open(folder, participantId, !readOnly, files));

        /// <summary>True once the settings are saved in full or anything else is in the journal (a crash part-way through the settings is no data).</summary>
        static bool IsStarted(StudyJournal journal)
        {
            if (journal.Damage.Count > 0) return true;
            foreach (var e in journal.Entries)
                if (e.Kind != SessionKind || e.Key == OrderKey) return true;
            return false;
        }

        static StudySession StartOn(StudyJournal journal, StudyConfig config)
        {
            try
            {
                var session = new StudySession(journal, config, null);
                var ci = CultureInfo.InvariantCulture;
                journal.Append(SessionKind, -1, "conditions", string.Join(",", config.Conditions));
                journal.Append(SessionKind, -1, "path_length_m", config.PathLengthMeters.ToString("R", ci));
                journal.Append(SessionKind, -1, "humanoid_classifier", config.HumanoidClassifier);
                journal.Append(SessionKind, -1, "rest_s", config.RestSeconds.ToString("R", ci));
                var order = new List<string>();
                foreach (var s in session.Steps) if (s.Kind == StudyStepKind.Trial) order.Add(s.Condition);
                journal.Append(SessionKind, -1, OrderKey, string.Join(",", order));
                return session;
            }
            catch
            {
                journal.Dispose();
                throw;
            }
        }

        static StudySession FromJournal(StudyJournal journal)
        {
            try
            {
                var config = new StudyConfig();
                bool haveConditions = false;
                string order = null;
                var ci = CultureInfo.InvariantCulture;
                foreach (var e in journal.Entries)
                {
                    if (e.Kind != SessionKind) continue;
                    switch (e.Key)
                    {
                        case "conditions":
                            config.Conditions = new List<string>(e.Value.Split(','));
                            haveConditions = true;
                            break;
                        case "path_length_m": config.PathLengthMeters = ParseSetting(journal, e, ci); break;
                        case "humanoid_classifier": config.HumanoidClassifier = e.Value; break;
                        case "rest_s": config.RestSeconds = ParseSetting(journal, e, ci); break;
                        case OrderKey: order = e.Value; break;
                    }
                }
                if (!haveConditions)
                    throw new StudyStorageException($"{journal.Path}: the session settings were never saved, or their line is damaged; the journal cannot be resumed." +
                                                    (journal.Damage.Count > 0 ? $" Damaged: {journal.Path}:{journal.Damage[0].LineNumber}: {journal.Damage[0].Reason}." : ""));
                try
                {
                    config.Validate();
                }
                catch (ArgumentException e)
                {
                    throw new StudyStorageException($"{journal.Path}: the saved session settings are not usable: {e.Message}", e);
                }
                var session = new StudySession(journal, config, SavedOrder(order, config));
                foreach (var e in journal.Entries)
                {
                    if (e.Kind == DoneKind) session.done.Add(e.Step);
                    else if (e.Kind == AnswerKind) session.Remember(e.Step, e.Key, e.Value);
                }
                return session;
            }
            catch
            {
                journal.Dispose();
                throw;
            }
        }

        static double ParseSetting(StudyJournal journal, JournalEntry e, CultureInfo ci)
        {
            if (double.TryParse(e.Value, NumberStyles.Float, ci, out double v)) return v;
            throw new StudyStorageException($"{journal.Path}:{e.LineNumber}: the saved setting {e.Key} '{e.Value}' is not a number.");
        }

        /// <summary>The condition order saved with the participant (so a resumed participant keeps it), or null to derive it from the id.</summary>
        static int[] SavedOrder(string order, StudyConfig config)
        {
            if (order == null) return null;
            var names = order.Split(',');
            if (names.Length != config.Conditions.Count) return null;
            var indices = new int[names.Length];
            var seen = new HashSet<int>();
            for (int i = 0; i < names.Length; i++)
            {
                indices[i] = config.Conditions.IndexOf(names[i]);
                if (indices[i] < 0 || !seen.Add(indices[i])) return null;
            }
            return indices;
        }

        void Remember(int step, string key, string value)
        {
            if (!answers.TryGetValue(step, out var a)) answers[step] = a = new Dictionary<string, string>();
            a[key] = value;
            if (key != SsqKey) return;
            if (!ssqAnswers.TryGetValue(step, out var list)) ssqAnswers[step] = list = new List<string>();
            list.Add(value);
        }

        /// <summary>An answer of the current step (e.g. a demographics field); saved before returning.</summary>
        public void Answer(string key, string value)
        {
            if (string.IsNullOrEmpty(key) || key == SsqKey) throw new ArgumentException("Answers need a key other than 'ssq'.");
            var step = Current;
            journal.Append(AnswerKind, step.Index, key, value);
            Remember(step.Index, key, value);
        }

        /// <summary>
        /// The 16 SSQ ratings of the current (SSQ) step, validated and saved as one line. Given again for the same step (a
        /// correction), the earlier answer stays in the journal and the latest counts; summaries say so.
        /// </summary>
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

        /// <summary>The SSQ ratings saved for a step (the latest, when it was corrected), or null when there are none or they cannot be read.</summary>
        public int[] SsqOf(int step)
        {
            var saved = SsqAnswersOf(step);
            return saved.Count > 0 && TryReadSsq(saved[saved.Count - 1], out var r, out _) ? r : null;
        }

        /// <summary>Every SSQ answer saved for a step, as saved, oldest first (more than one when it was corrected).</summary>
        public IReadOnlyList<string> SsqAnswersOf(int step) => ssqAnswers.TryGetValue(step, out var list) ? list : (IReadOnlyList<string>)Array.Empty<string>();

        /// <summary>Reads a saved SSQ answer: 16 ratings 0..3 separated by commas; otherwise false with the reason.</summary>
        public static bool TryReadSsq(string value, out int[] ratings, out string problem)
        {
            ratings = null;
            var parts = (value ?? "").Split(',');
            if (parts.Length != SimulatorSicknessQuestionnaire.ItemCount)
            {
                problem = $"'{value}' is not {SimulatorSicknessQuestionnaire.ItemCount} ratings separated by commas";
                return false;
            }
            var r = new int[parts.Length];
            for (int i = 0; i < parts.Length; i++)
                if (parts[i].Length != 1 || !int.TryParse(parts[i], NumberStyles.None, CultureInfo.InvariantCulture, out r[i]) || r[i] > SimulatorSicknessQuestionnaire.MaxRating)
                {
                    problem = $"'{value}': item {i + 1} '{parts[i]}' is not a rating 0-{SimulatorSicknessQuestionnaire.MaxRating}";
                    return false;
                }
            ratings = r;
            problem = null;
            return true;
        }

        /// <summary>Closes the journal and releases the participant for another session.</summary>
        public void Dispose() => journal.Dispose();
    }
}
