using System;
using System.Collections.Generic;
using System.Diagnostics;
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
        /// <summary>The line's number in the file (1 is the format line).</summary>
        public int LineNumber;
    }

    /// <summary>A line of a journal that cannot be trusted (fails its checksum or cannot be read): kept in the file, never used, always reported.</summary>
    public sealed class JournalDamage
    {
        public int LineNumber;
        public string Reason;
        /// <summary>The line as far as it could be decoded (at most 200 characters), for the report.</summary>
        public string Text;

        public override string ToString() => $"line {LineNumber}: {Reason}: '{Text}'";
    }

    /// <summary>
    /// A participant's data as an append-only journal (<c>ID.journal.tsv</c>), kept as trusted logs are:
    /// <list type="bullet">
    /// <item>One writer per participant: a journal open for writing holds an exclusive lock on <c>ID.journal.lock</c>
    /// (the open's sharing rule and a record lock on its first byte, operating-system locks, so they end with the process
    /// that held them: a crash never blocks the id); a second open,
    /// from this process or another, is refused naming the holder and since when (<c>ID.journal.owner</c>).</item>
    /// <item>Every line carries its length and CRC-32 (format v2), so a torn or damaged line is recognised, never misread.</item>
    /// <item>An answer is acknowledged (the call returns) only once its whole line is flushed to the disk; a failed write
    /// (full disk) is cut back, so the journal stays readable and the retry lands where the failed line began.</item>
    /// <item>A torn last line (a crash mid-write: never acknowledged) is cut on the next open for writing and reported;
    /// damaged lines elsewhere are kept as they are, left out and reported.</item>
    /// <item>A new journal appears whole (written beside it, then renamed), so a crash or full disk at creation leaves no
    /// 0-byte file; one left by older versions counts as empty.</item>
    /// </list>
    /// v1 journals (no checksums) are still read, and appended to with checked lines.
    /// </summary>
    public sealed class StudyJournal : IDisposable
    {
        public const string Magic = "# headgait-study-journal v2";
        public const string MagicV1 = "# headgait-study-journal v1";
        public const string Extension = ".journal.tsv";
        public const string LockExtension = ".journal.lock";
        public const string OwnerExtension = ".journal.owner";
        /// <summary>Far above any study (a session writes a few kilobytes): a larger file is not read.</summary>
        public const long MaxBytes = 64L << 20;

        static readonly UTF8Encoding Utf8 = new UTF8Encoding(false);

        readonly List<JournalEntry> entries = new List<JournalEntry>();
        readonly List<JournalDamage> damage = new List<JournalDamage>();
        readonly JournalFileAccess files;
        Stream lockStream, stream;
        string ownerPath;
        long goodLength;
        int lineCount;

        StudyJournal(string path, string participant, JournalFileAccess files)
        {
            Path = path;
            Participant = participant;
            this.files = files ?? JournalFileAccess.Default;
        }

        public string Path { get; }
        /// <summary>The participant's id in its one canonical form (upper case).</summary>
        public string Participant { get; }
        public IReadOnlyList<JournalEntry> Entries => entries;
        /// <summary>Lines that fail their checksum or cannot be read, in file order.</summary>
        public IReadOnlyList<JournalDamage> Damage => damage;
        /// <summary>True for a journal without checksums (written before format v2).</summary>
        public bool IsV1 { get; private set; }
        /// <summary>True when the last line was torn (a crash mid-write); it was never acknowledged.</summary>
        public bool RecoveredTornLine => TornBytes > 0;
        /// <summary>Bytes of a torn last line: cut from the file when opened for writing, skipped when only read.</summary>
        public int TornBytes { get; private set; }
        /// <summary>True when the file held no complete format line (a crash at creation under an older version): treated as empty.</summary>
        bool RepairedHeader { get; set; }

        /// <summary>Opens a participant's journal for writing, creating it when the id has none; holds the id's lock until disposed.</summary>
        public static StudyJournal OpenOrCreate(string folder, string participantId, JournalFileAccess files = null)
        {
            string id = ParticipantIds.Canonical(participantId);
            files = files ?? JournalFileAccess.Default;
            try
            {
                Directory.CreateDirectory(folder);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException || e is NotSupportedException)
            {
                throw new StudyStorageException($"Cannot create the data folder {folder} for participant {id}: {e.Message}", e);
            }
            var journal = new StudyJournal(Resolve(folder, id), id, files);
            journal.Lock(folder);
            try
            {
                if (files.Exists(journal.Path)) journal.OpenForWriting();
                else journal.CreateFile();
            }
            catch
            {
                journal.Dispose();
                throw;
            }
            return journal;
        }

        /// <summary>
        /// Reads an existing participant's journal. <paramref name="forWriting"/> takes the id's lock and cuts a torn last
        /// line, so that new lines can follow; otherwise the file is only read (no lock: results can be read while a
        /// session is running) and left exactly as it is.
        /// </summary>
        public static StudyJournal Open(string folder, string participantId, bool forWriting = true, JournalFileAccess files = null)
        {
            string id = ParticipantIds.Canonical(participantId);
            var journal = new StudyJournal(Resolve(folder, id), id, files);
            if (!journal.files.Exists(journal.Path)) throw new StudyStorageException($"Participant {id} has no data: {journal.Path} does not exist.");
            if (!forWriting)
            {
                byte[] bytes;
                try
                {
                    using (var s = journal.files.Open(journal.Path, FileMode.Open, FileAccess.Read, FileShare.ReadWrite | FileShare.Delete))
                        bytes = journal.ReadAll(s);
                }
                catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
                {
                    throw new StudyStorageException($"Cannot read the data of participant {id} at {journal.Path}: {e.Message}", e);
                }
                journal.Parse(bytes);
                return journal;
            }
            journal.Lock(folder);
            try
            {
                journal.OpenForWriting();
            }
            catch
            {
                journal.Dispose();
                throw;
            }
            return journal;
        }

        static string Resolve(string folder, string id)
        {
            string exact = System.IO.Path.Combine(folder, id + Extension);
            if (!Directory.Exists(folder)) return exact;
            var matches = new List<string>();
            foreach (var f in Directory.GetFiles(folder, "*" + Extension))
                if (string.Equals(System.IO.Path.GetFileName(f), id + Extension, StringComparison.OrdinalIgnoreCase)) matches.Add(f);
            if (matches.Count <= 1) return matches.Count == 1 ? matches[0] : exact;
            matches.Sort(StringComparer.Ordinal);
            throw new StudyStorageException($"Participant {id} has {matches.Count} journals whose names differ only in case ({string.Join(", ", matches)}); " +
                                            $"ids are one participant whatever their case: merge them into {exact} by hand.");
        }

        static bool IsSharingViolation(IOException e)
        {
            // Windows and Mono: ERROR_SHARING_VIOLATION / ERROR_LOCK_VIOLATION; .NET on Unix: flock's EWOULDBLOCK (Linux 11, macOS 35).
            int h = e.HResult;
            return e.GetType() == typeof(IOException) && (h == unchecked((int)0x80070020) || h == unchecked((int)0x80070021) || h == 11 || h == 35);
        }

        /// <summary>
        /// A record lock on the lock file's first byte beside the open's own sharing rule: .NET refuses a second open across
        /// processes (flock), but Unity's runtimes on Android and other Unix players check sharing only within their own
        /// process (IL2CPP's and Mono's file layer), where the record lock (fcntl) also refuses another process. .NET on macOS
        /// has no record locks: the open's rule alone holds there. A failed lock disposes the stream.
        /// </summary>
        static void LockRecord(Stream stream)
        {
            if (!(stream is FileStream file)) return;
            try
            {
                file.Lock(0, 1);
            }
            catch (PlatformNotSupportedException)
            {
            }
            catch
            {
                stream.Dispose();
                throw;
            }
        }

        void Lock(string folder)
        {
            string lockPath = System.IO.Path.Combine(folder, Participant + LockExtension);
            ownerPath = System.IO.Path.Combine(folder, Participant + OwnerExtension);
            try
            {
                var held = files.Open(lockPath, FileMode.OpenOrCreate, FileAccess.ReadWrite, FileShare.None);
                LockRecord(held);
                lockStream = held;
            }
            catch (IOException e) when (IsSharingViolation(e))
            {
                throw new StudyStorageException($"Participant {Participant} is in use by {ReadOwner()}: close it there first (Abort, or quit that application). Nothing was changed.", e);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                throw new StudyStorageException($"Cannot lock participant {Participant} ({lockPath}): {e.Message}", e);
            }
            try
            {
                // Only for the message a second opener shows; the lock itself is the open handle above.
                using (var s = files.Open(ownerPath, FileMode.Create, FileAccess.Write, FileShare.ReadWrite | FileShare.Delete))
                {
                    var bytes = Utf8.GetBytes($"{DescribeThisProcess()}\t{DateTime.UtcNow.ToString("yyyy-MM-ddTHH:mm:ssZ", CultureInfo.InvariantCulture)}\n");
                    s.Write(bytes, 0, bytes.Length);
                }
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                ownerPath = null;
            }
        }

        static string DescribeThisProcess()
        {
            string who;
            try
            {
                who = $"process {Process.GetCurrentProcess().Id}";
            }
            catch (Exception)
            {
                who = "a process";
            }
            try
            {
                who += $" on {Environment.MachineName}";
            }
            catch (Exception)
            {
            }
            return who;
        }

        string ReadOwner()
        {
            try
            {
                string text;
                using (var s = files.Open(ownerPath, FileMode.Open, FileAccess.Read, FileShare.ReadWrite | FileShare.Delete))
                using (var r = new StreamReader(s, Utf8))
                    text = r.ReadLine() ?? "";
                var cells = text.Split('\t');
                if (cells.Length == 2 && DateTime.TryParse(cells[1], CultureInfo.InvariantCulture, DateTimeStyles.AdjustToUniversal, out var since))
                {
                    string who = cells[0] == DescribeThisProcess() ? $"this application ({cells[0]})" : cells[0];
                    return $"{who} (since {since.ToString("yyyy-MM-dd HH:mm:ss", CultureInfo.InvariantCulture)} UTC)";
                }
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
            }
            return "another session (since a time it did not record)";
        }

        byte[] ReadAll(Stream s)
        {
            long length = s.Length;
            if (length > MaxBytes)
                throw new StudyStorageException($"{Path} is {length} bytes, more than any study journal holds ({MaxBytes} at most); it is not read.");
            var bytes = new byte[length];
            int read = 0;
            while (read < bytes.Length)
            {
                int n = s.Read(bytes, read, bytes.Length - read);
                if (n <= 0) break;
                read += n;
            }
            if (read < bytes.Length) Array.Resize(ref bytes, read);
            return bytes;
        }

        void CreateFile()
        {
            string temp = Path + ".new";
            try
            {
                // Written beside the journal and renamed, so the journal never exists half-made.
                if (files.Exists(temp)) files.Delete(temp);
                using (var s = files.Open(temp, FileMode.CreateNew, FileAccess.Write, FileShare.None))
                {
                    var bytes = Utf8.GetBytes(Magic + "\n");
                    s.Write(bytes, 0, bytes.Length);
                    files.FlushToDisk(s);
                }
                files.Move(temp, Path);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                try
                {
                    if (files.Exists(temp)) files.Delete(temp);
                }
                catch (Exception d) when (d is IOException || d is UnauthorizedAccessException)
                {
                }
                throw new StudyStorageException($"Cannot create the data file of participant {Participant} at {Path}: {e.Message}. Nothing is saved for {Participant} yet " +
                                                "and the id stays free: fix the cause (free space, permissions) and open it again.", e);
            }
            OpenForWriting();
        }

        void OpenForWriting()
        {
            try
            {
                stream = files.Open(Path, FileMode.Open, FileAccess.ReadWrite, FileShare.Read);
                stream.Position = 0;
                Parse(ReadAll(stream));
                if (RepairedHeader)
                {
                    var bytes = Utf8.GetBytes(Magic + "\n");
                    stream.SetLength(0);
                    stream.Position = 0;
                    stream.Write(bytes, 0, bytes.Length);
                    files.FlushToDisk(stream);
                    goodLength = bytes.Length;
                }
                else if (stream.Length != goodLength)
                {
                    // A line complete but for its line end (a bit lost from it) gets the end back; a torn line is cut.
                    if (TornBytes == 0)
                    {
                        stream.Position = goodLength - 1;
                        stream.WriteByte((byte)'\n');
                    }
                    stream.SetLength(goodLength);
                    files.FlushToDisk(stream);
                }
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                throw new StudyStorageException($"Cannot open the data of participant {Participant} at {Path} for writing: {e.Message}. Nothing in it was changed.", e);
            }
        }

        /// <summary>Reads the bytes of a journal; sets <see cref="goodLength"/> to the end of the last whole line.</summary>
        void Parse(byte[] bytes)
        {
            int end = Array.LastIndexOf(bytes, (byte)'\n') + 1;
            int tail = bytes.Length - end;
            if (end == 0)
            {
                // No whole line yet: a crash or full disk while an older version created the file. Nothing in it was ever acknowledged.
                if (!IsMagicPrefix(Decode(bytes, 0, bytes.Length).TrimEnd('\r').TrimStart('\uFEFF')))
                    throw NotAJournal();
                RepairedHeader = true;
                goodLength = 0;
                return;
            }
            int lineStart = 0, lineNo = 0;
            bool headerOk = false;
            var pending = new List<(int start, int length, int number)>();
            while (lineStart < end)
            {
                int nl = Array.IndexOf(bytes, (byte)'\n', lineStart, end - lineStart);
                int length = nl - lineStart;
                lineNo++;
                if (lineNo == 1)
                {
                    string header = Decode(bytes, lineStart, length).TrimEnd('\r').TrimStart('\uFEFF');
                    if (header == Magic) headerOk = true;
                    else if (header == MagicV1)
                    {
                        headerOk = true;
                        IsV1 = true;
                    }
                    else pending.Add((lineStart, length, -1));
                }
                else pending.Add((lineStart, length, lineNo));
                lineStart = nl + 1;
            }
            goodLength = end;
            // A last line complete but for its line end is a whole line (a flipped or lost '\n'); anything else there is torn.
            if (tail > 0)
            {
                if (headerOk && Verify(bytes, end, TrimCr(bytes, end, tail), out _)) { pending.Add((end, tail, ++lineNo)); goodLength = bytes.Length + 1; }
                else TornBytes = tail;
            }
            if (!headerOk)
            {
                // A damaged format line: still a journal when its other lines carry valid checksums.
                bool anyChecked = false;
                foreach (var p in pending)
                    if (p.number > 0 && Verify(bytes, p.start, TrimCr(bytes, p.start, p.length), out _)) anyChecked = true;
                if (!anyChecked)
                    throw NotAJournal();
                damage.Add(new JournalDamage { LineNumber = 1, Reason = "the format line is damaged", Text = Excerpt(bytes, pending[0].start, pending[0].length) });
            }
            foreach (var p in pending)
            {
                if (p.number < 0) continue;
                int length = TrimCr(bytes, p.start, p.length);
                if (length == 0) continue;
                lineCount++;
                if (Verify(bytes, p.start, length, out int payload))
                {
                    var entry = ParsePayload(Decode(bytes, p.start, payload), p.number);
                    if (entry != null)
                    {
                        entries.Add(entry);
                        continue;
                    }
                }
                else if (IsV1 && !HasChecksumField(bytes, p.start, length))
                {
                    var entry = ParsePayload(Decode(bytes, p.start, length), p.number);
                    if (entry != null)
                    {
                        entries.Add(entry);
                        continue;
                    }
                    damage.Add(new JournalDamage { LineNumber = p.number, Reason = "not a journal line (sequence, UTC time, kind, step, key, value separated by tabs)", Text = Excerpt(bytes, p.start, length) });
                    continue;
                }
                damage.Add(new JournalDamage { LineNumber = p.number, Reason = "damaged (its length or checksum does not match)", Text = Excerpt(bytes, p.start, length) });
            }
        }

        StudyStorageException NotAJournal() => new StudyStorageException($"{Path} is not a HeadGait study journal (its first line must be '{Magic}' or '{MagicV1}').");

        static bool IsMagicPrefix(string s) => Magic.StartsWith(s, StringComparison.Ordinal) || MagicV1.StartsWith(s, StringComparison.Ordinal);

        static int TrimCr(byte[] bytes, int start, int length) => length > 0 && bytes[start + length - 1] == (byte)'\r' ? length - 1 : length;

        static string Decode(byte[] bytes, int start, int length) => Utf8.GetString(bytes, start, length);

        static string Excerpt(byte[] bytes, int start, int length)
        {
            string s = Decode(bytes, start, Math.Min(length, 400)).Replace("\t", " | ").Replace("\r", "\\r");
            return s.Length > 200 ? s.Substring(0, 200) + "..." : s;
        }

        /// <summary>A checked line ends in a tab, the payload's byte count, a colon and its CRC-32 in 8 hex digits.</summary>
        static bool HasChecksumField(byte[] bytes, int start, int length)
        {
            int tab = Array.LastIndexOf(bytes, (byte)'\t', start + length - 1, length);
            if (tab < 0) return false;
            int colon = Array.IndexOf(bytes, (byte)':', tab, start + length - tab);
            return colon > tab + 1 && start + length - colon - 1 == 8;
        }

        static bool Verify(byte[] bytes, int start, int length, out int payload)
        {
            payload = 0;
            if (length <= 0) return false;
            int tab = Array.LastIndexOf(bytes, (byte)'\t', start + length - 1, length);
            if (tab < 0) return false;
            string field = Encoding.ASCII.GetString(bytes, tab + 1, start + length - tab - 1);
            int colon = field.IndexOf(':');
            if (colon <= 0 || field.Length - colon - 1 != 8) return false;
            if (!int.TryParse(field.Substring(0, colon), NumberStyles.None, CultureInfo.InvariantCulture, out int declared)) return false;
            if (!uint.TryParse(field.Substring(colon + 1), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out uint crc)) return false;
            if (field.Substring(colon + 1) != crc.ToString("x8", CultureInfo.InvariantCulture)) return false;
            payload = tab - start;
            return declared == payload && Crc32.Compute(bytes, start, payload) == crc;
        }

        static JournalEntry ParsePayload(string line, int lineNo)
        {
            var cells = line.Split('\t');
            if (cells.Length != 6
                || !int.TryParse(cells[0], NumberStyles.Integer, CultureInfo.InvariantCulture, out int seq)
                || !DateTime.TryParse(cells[1], CultureInfo.InvariantCulture, DateTimeStyles.AdjustToUniversal | DateTimeStyles.AssumeUniversal, out var time)
                || !int.TryParse(cells[3], NumberStyles.Integer, CultureInfo.InvariantCulture, out int step))
                return null;
            return new JournalEntry { Sequence = seq, TimeUtc = time, Kind = cells[2], Step = step, Key = Unescape(cells[4]), Value = Unescape(cells[5]), LineNumber = lineNo };
        }

        /// <summary>
        /// Appends one entry and flushes it to the disk before returning: when it returns, the answer is saved. When the write
        /// fails (full disk, disk removed), what was written of the line is cut again, so the journal stays as it was and the
        /// same call can be repeated once the cause is fixed.
        /// </summary>
        public JournalEntry Append(string kind, int step, string key, string value, DateTime? timeUtc = null)
        {
            if (stream == null) throw new InvalidOperationException($"The journal of participant {Participant} is open only for reading, or closed.");
            var entry = new JournalEntry
            {
                Sequence = lineCount + 1,
                TimeUtc = timeUtc ?? DateTime.UtcNow,
                Kind = kind,
                Step = step,
                Key = key ?? "",
                Value = value ?? "",
                LineNumber = lineCount + 2,
            };
            var bytes = Line(entry);
            try
            {
                // A write that failed earlier may have left part of its line: start where the last whole line ended.
                if (stream.Length != goodLength) stream.SetLength(goodLength);
                stream.Position = goodLength;
                stream.Write(bytes, 0, bytes.Length);
                files.FlushToDisk(stream);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException || e is NotSupportedException)
            {
                try
                {
                    stream.SetLength(goodLength);
                    files.FlushToDisk(stream);
                }
                catch (Exception cut) when (cut is IOException || cut is UnauthorizedAccessException || cut is NotSupportedException)
                {
                    // The next append (or the next open) cuts it.
                }
                throw new StudyStorageException($"Could not save {kind} '{entry.Key}' of participant {Participant} to {Path}: {e.Message}. " +
                                                "This answer is NOT saved; nothing was lost that was saved before. Free space or fix permissions and submit again.", e);
            }
            goodLength += bytes.Length;
            lineCount++;
            entries.Add(entry);
            return entry;
        }

        static byte[] Line(JournalEntry entry)
        {
            var ci = CultureInfo.InvariantCulture;
            string payload = string.Join("\t", entry.Sequence.ToString(ci), entry.TimeUtc.ToString("yyyy-MM-ddTHH:mm:ss.fffZ", ci), Escape(entry.Kind),
                entry.Step.ToString(ci), Escape(entry.Key), Escape(entry.Value));
            var p = Utf8.GetBytes(payload);
            var trailer = Encoding.ASCII.GetBytes($"\t{p.Length.ToString(ci)}:{Crc32.Compute(p, 0, p.Length).ToString("x8", ci)}\n");
            var line = new byte[p.Length + trailer.Length];
            Buffer.BlockCopy(p, 0, line, 0, p.Length);
            Buffer.BlockCopy(trailer, 0, line, p.Length, trailer.Length);
            return line;
        }

        /// <summary>Closes the journal and releases the participant's lock (the lock file stays: removing it could let two writers in).</summary>
        public void Dispose()
        {
            var s = stream;
            stream = null;
            try
            {
                s?.Dispose();
            }
            catch (IOException)
            {
            }
            if (lockStream == null) return;
            try
            {
                if (ownerPath != null) files.Delete(ownerPath);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
            }
            try
            {
                lockStream.Dispose();
            }
            catch (IOException)
            {
            }
            lockStream = null;
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

    /// <summary>CRC-32 (IEEE 802.3, as zip and PNG use it).</summary>
    static class Crc32
    {
        static readonly uint[] Table = MakeTable();

        static uint[] MakeTable()
        {
            var t = new uint[256];
            for (uint n = 0; n < 256; n++)
            {
                uint c = n;
                for (int k = 0; k < 8; k++) c = (c & 1) != 0 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
                t[n] = c;
            }
            return t;
        }

        public static uint Compute(byte[] bytes, int start, int length)
        {
            uint c = 0xFFFFFFFFu;
            for (int i = start; i < start + length; i++) c = Table[(c ^ bytes[i]) & 0xFF] ^ (c >> 8);
            return c ^ 0xFFFFFFFFu;
        }
    }
}
