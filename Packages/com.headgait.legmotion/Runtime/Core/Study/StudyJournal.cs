using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace HeadGait.Study
{
    /// <summary>The study's data could not be written or read; the message names the participant, the file and the cause.</summary>
    public sealed class StudyStorageException : Exception
    {
        public StudyStorageException(string message, Exception inner = null) : base(message, inner) { }
    }

    /// <summary>One line of a participant's journal.</summary>
    public sealed class JournalEntry
    {
        public int Sequence;
        public DateTime TimeUtc;
        /// <summary>session, answer, done, event.</summary>
        public string Kind;
        public int Step;
        public string Key;
        public string Value;
    }

    /// <summary>
    /// A participant's data as an append-only journal (<c>ID.journal.tsv</c>): every answer and event is a line written
    /// and flushed to the disk before the call returns, so a crash, a quit or a power cut loses nothing already
    /// submitted. Reopening reads it back; a last line torn by a crash mid-write is dropped (it was never acknowledged)
    /// and reported. A participant that already has a journal is never started over: <see cref="Create"/> refuses and
    /// <see cref="Open"/> resumes.
    /// </summary>
    public sealed class StudyJournal
    {
        public const string Magic = "# headgait-study-journal v1";
        public const string Extension = ".journal.tsv";

        readonly List<JournalEntry> entries = new List<JournalEntry>();

        StudyJournal(string path, string participant)
        {
            Path = path;
            Participant = participant;
        }

        public string Path { get; }
        public string Participant { get; }
        public IReadOnlyList<JournalEntry> Entries => entries;

        /// <summary>True when reopening dropped a torn last line.</summary>
        public bool RecoveredTornLine { get; private set; }

        public static string PathFor(string folder, string participantId)
        {
            ParticipantIds.Validate(participantId);
            return System.IO.Path.Combine(folder, participantId + Extension);
        }

        public static bool Exists(string folder, string participantId) => File.Exists(PathFor(folder, participantId));

        /// <summary>Starts a new participant; refuses (with the path) when the id already has data.</summary>
        public static StudyJournal Create(string folder, string participantId)
        {
            string path = PathFor(folder, participantId);
            try
            {
                Directory.CreateDirectory(folder);
                using (var fs = new FileStream(path, FileMode.CreateNew, FileAccess.Write, FileShare.Read))
                {
                    var bytes = Encoding.UTF8.GetBytes(Magic + "\n");
                    fs.Write(bytes, 0, bytes.Length);
                    fs.Flush(true);
                }
            }
            catch (IOException e) when (File.Exists(path))
            {
                throw new StudyStorageException($"Participant {participantId} already has data in {path}; open it to resume, or choose another id.", e);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                throw new StudyStorageException($"Cannot create the data file for participant {participantId} at {path}: {e.Message}", e);
            }
            return new StudyJournal(path, participantId);
        }

        /// <summary>
        /// Reads an existing participant's journal back, dropping a torn last line; with <paramref name="repair"/> the torn
        /// bytes are also cut from the file, so that new lines can follow (readers that only look leave the file as it is).
        /// </summary>
        public static StudyJournal Open(string folder, string participantId, bool repair = true)
        {
            string path = PathFor(folder, participantId);
            var journal = new StudyJournal(path, participantId);
            byte[] bytes;
            try
            {
                bytes = File.ReadAllBytes(path);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                throw new StudyStorageException($"Cannot read the data of participant {participantId} at {path}: {e.Message}", e);
            }
            int complete = bytes.Length;
            while (complete > 0 && bytes[complete - 1] != (byte)'\n') complete--;
            if (complete < bytes.Length)
            {
                journal.RecoveredTornLine = true;
                if (repair) try
                {
                    using (var fs = new FileStream(path, FileMode.Open, FileAccess.Write))
                    {
                        fs.SetLength(complete);
                        fs.Flush(true);
                    }
                }
                catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
                {
                    throw new StudyStorageException($"Participant {participantId}: {path} ends in a torn line that cannot be removed: {e.Message}", e);
                }
            }
            var lines = Encoding.UTF8.GetString(bytes, 0, complete).Split('\n');
            if (lines.Length == 0 || lines[0].TrimStart('\uFEFF') != Magic)
                throw new StudyStorageException($"{path} is not a HeadGait study journal (first line must be '{Magic}').");
            for (int i = 1; i < lines.Length; i++)
            {
                if (lines[i].Length == 0) continue;
                journal.entries.Add(ParseLine(lines[i], path, i + 1));
            }
            return journal;
        }

        static JournalEntry ParseLine(string line, string path, int lineNo)
        {
            var cells = line.Split('\t');
            if (cells.Length != 6
                || !int.TryParse(cells[0], NumberStyles.Integer, CultureInfo.InvariantCulture, out int seq)
                || !DateTime.TryParse(cells[1], CultureInfo.InvariantCulture, DateTimeStyles.AdjustToUniversal | DateTimeStyles.AssumeUniversal, out var time)
                || !int.TryParse(cells[3], NumberStyles.Integer, CultureInfo.InvariantCulture, out int step))
                throw new StudyStorageException($"{path}:{lineNo}: not a journal line (sequence, UTC time, kind, step, key, value separated by tabs).");
            return new JournalEntry { Sequence = seq, TimeUtc = time, Kind = cells[2], Step = step, Key = Unescape(cells[4]), Value = Unescape(cells[5]) };
        }

        /// <summary>Appends one entry and flushes it to the disk before returning; on failure nothing is half-written in memory.</summary>
        public JournalEntry Append(string kind, int step, string key, string value, DateTime? timeUtc = null)
        {
            var entry = new JournalEntry
            {
                Sequence = entries.Count + 1,
                TimeUtc = timeUtc ?? DateTime.UtcNow,
                Kind = kind,
                Step = step,
                Key = key ?? "",
                Value = value ?? "",
            };
            string line = string.Join("\t", entry.Sequence.ToString(CultureInfo.InvariantCulture),
                entry.TimeUtc.ToString("yyyy-MM-ddTHH:mm:ss.fffZ", CultureInfo.InvariantCulture), Escape(kind),
                step.ToString(CultureInfo.InvariantCulture), Escape(entry.Key), Escape(entry.Value)) + "\n";
            try
            {
                using (var fs = new FileStream(Path, FileMode.Append, FileAccess.Write, FileShare.Read))
                {
                    var bytes = Encoding.UTF8.GetBytes(line);
                    fs.Write(bytes, 0, bytes.Length);
                    fs.Flush(true);
                }
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                throw new StudyStorageException($"Could not save {kind} '{entry.Key}' of participant {Participant} to {Path}: {e.Message}. " +
                                                "Nothing was lost that was saved before; free space or fix permissions and submit again.", e);
            }
            entries.Add(entry);
            return entry;
        }

        static string Escape(string s) => (s ?? "").Replace("\\", "\\\\").Replace("\t", "\\t").Replace("\n", "\\n").Replace("\r", "\\r");

        static string Unescape(string s)
        {
            var sb = new StringBuilder(s.Length);
            for (int i = 0; i < s.Length; i++)
            {
                if (s[i] != '\\' || i + 1 == s.Length)
                {
                    sb.Append(s[i]);
                    continue;
                }
                char c = s[++i];
                sb.Append(c == 't' ? '\t' : c == 'n' ? '\n' : c == 'r' ? '\r' : c);
            }
            return sb.ToString();
        }
    }
}
