using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace HeadGait
{
    /// <summary>
    /// The recorded-stream CSV format:
    /// <code>
    /// # headgait-recording v1
    /// # any_key=any value            (optional metadata lines)
    /// timestamp_s,acc_x,acc_y,acc_z,phase_left,phase_right
    /// 0.0000,0.0512,-0.0213,9.8031,STAND,STAND
    /// </code>
    /// Columns are found by name in the header, in any order; extra columns are ignored.
    /// timestamp_s is seconds; acc_* are m/s^2 in the head frame (x forward, y left, z up).
    /// phase_left/phase_right are optional (both or neither): IC, LR, MST, TST, PSW, ISW, MSW, TSW, STAND
    /// (full names such as MidStance are accepted); an empty cell means "no label" for that row.
    /// </summary>
    public static class RecordingCsv
    {
        public const string Magic = "# headgait-recording v1";
        public static readonly string[] RequiredColumns = { "timestamp_s", "acc_x", "acc_y", "acc_z" };
        public static readonly string[] TruthColumns = { "phase_left", "phase_right" };

        /// <summary>Largest timestamp magnitude read (s): about 31 years. Larger is a unit mix-up (µs as s) or corruption.</summary>
        public const double MaxTimestamp = 1e9;

        /// <summary>Largest acceleration magnitude per axis read (m/s^2): 100 g, far beyond any head.</summary>
        public const double MaxAcceleration = 1000;

        public static Recording Load(string path, bool strict = false)
        {
            if (path == null) throw new ArgumentNullException(nameof(path));
            if (!File.Exists(path)) throw new FileNotFoundException($"Recording not found: {path}", path);
            using (var reader = new StreamReader(path, Encoding.UTF8))
            {
                return Read(reader, Path.GetFileNameWithoutExtension(path), strict);
            }
        }

        public static Recording Parse(string text, string name = "recording", bool strict = false)
        {
            using (var reader = new StringReader(text ?? throw new ArgumentNullException(nameof(text))))
            {
                return Read(reader, name, strict);
            }
        }

        /// <summary>
        /// Reads a recording. A missing or malformed header (no timestamp_s/acc_x/acc_y/acc_z, one phase
        /// column without the other) always throws <see cref="RecordingFormatException"/>. Bad rows (wrong
        /// cell count, unparsable or non-finite numbers, unknown phase names) throw in strict mode; otherwise
        /// they are skipped and listed in <see cref="Recording.Warnings"/>. Timestamps are not reordered here:
        /// the preprocessor skips out-of-order samples when the stream is replayed.
        /// </summary>
        public static Recording Read(TextReader reader, string name, bool strict = false)
        {
            var samples = new List<RecordedSample>();
            var warnings = new List<string>();
            var metadata = new Dictionary<string, string>();
            int lineNo = 0;
            int[] idx = null;
            int tl = -1, tr = -1, columnCount = 0;
            string line;
            while ((line = reader.ReadLine()) != null)
            {
                lineNo++;
                // Byte-order marks (one or several, from tools that add one when saving) are not content.
                string trimmed = line.TrimStart('\uFEFF').Trim();
                if (trimmed.Length == 0) continue;
                if (trimmed.StartsWith("#", StringComparison.Ordinal))
                {
                    int eq = trimmed.IndexOf('=');
                    if (eq > 1)
                    {
                        string key = trimmed.Substring(1, eq - 1).Trim();
                        if (key.Length > 0 && key.IndexOf(' ') < 0) metadata[key] = trimmed.Substring(eq + 1).Trim();
                    }
                    continue;
                }
                string[] cells = trimmed.Split(',');
                if (idx == null)
                {
                    ParseHeader(cells, name, lineNo, out idx, out tl, out tr);
                    columnCount = cells.Length;
                    continue;
                }
                if (cells.Length != columnCount)
                {
                    Bad(strict, warnings, name, lineNo, $"expected {columnCount} cells, found {cells.Length}");
                    continue;
                }
                var v = new double[4];
                string error = null;
                for (int c = 0; c < 4 && error == null; c++)
                {
                    string cell = cells[idx[c]].Trim();
                    if (!double.TryParse(cell, NumberStyles.Float, CultureInfo.InvariantCulture, out v[c]))
                        error = $"{RequiredColumns[c]} '{cell}' is not a number";
                    else if (double.IsNaN(v[c]) || double.IsInfinity(v[c]))
                        error = $"{RequiredColumns[c]} is not finite";
                    else if (Math.Abs(v[c]) > (c == 0 ? MaxTimestamp : MaxAcceleration))
                        error = $"{RequiredColumns[c]} {cell} is beyond the limit of {(c == 0 ? MaxTimestamp : MaxAcceleration).ToString("G", CultureInfo.InvariantCulture)} {(c == 0 ? "s" : "m/s^2")}";
                }
                if (error != null)
                {
                    Bad(strict, warnings, name, lineNo, error);
                    continue;
                }
                var imu = new ImuSample(v[0], v[1], v[2], v[3]);
                if (tl >= 0)
                {
                    string l = cells[tl].Trim(), r = cells[tr].Trim();
                    if (l.Length == 0 && r.Length == 0)
                    {
                        samples.Add(new RecordedSample(imu, lineNo));
                        continue;
                    }
                    if (!GaitPhases.TryParse(l, out var pl) || !GaitPhases.TryParse(r, out var pr))
                    {
                        Bad(strict, warnings, name, lineNo, $"unknown phase label '{l}' / '{r}'");
                        continue;
                    }
                    if ((pl == GaitPhase.Standing) != (pr == GaitPhase.Standing))
                    {
                        Bad(strict, warnings, name, lineNo, "one foot is labelled STAND and the other walking");
                        continue;
                    }
                    samples.Add(new RecordedSample(imu, pl, pr, lineNo));
                }
                else
                {
                    samples.Add(new RecordedSample(imu, lineNo));
                }
            }
            if (idx == null) throw new RecordingFormatException(name, Math.Max(lineNo, 1), "no header line (expected timestamp_s,acc_x,acc_y,acc_z[,phase_left,phase_right])");
            var rec = new Recording(name, samples, warnings);
            foreach (var kv in metadata) rec.Metadata[kv.Key] = kv.Value;
            return rec;
        }

        static void ParseHeader(string[] cells, string name, int lineNo, out int[] idx, out int tl, out int tr)
        {
            var names = new Dictionary<string, int>(StringComparer.OrdinalIgnoreCase);
            for (int i = 0; i < cells.Length; i++)
            {
                string c = cells[i].Trim();
                if (c.Length == 0) continue;
                if (names.ContainsKey(c)) throw new RecordingFormatException(name, lineNo, $"column '{c}' appears twice");
                names[c] = i;
            }
            idx = new int[4];
            var missing = new List<string>();
            for (int c = 0; c < 4; c++)
            {
                if (!names.TryGetValue(RequiredColumns[c], out idx[c])) missing.Add(RequiredColumns[c]);
            }
            if (missing.Count > 0)
            {
                throw new RecordingFormatException(name, lineNo,
                    $"missing column(s) {string.Join(", ", missing)}; header must name timestamp_s,acc_x,acc_y,acc_z (found: {string.Join(",", cells)})");
            }
            bool hasL = names.TryGetValue(TruthColumns[0], out tl);
            bool hasR = names.TryGetValue(TruthColumns[1], out tr);
            if (hasL != hasR)
                throw new RecordingFormatException(name, lineNo, "ground truth needs both phase_left and phase_right");
            if (!hasL)
            {
                tl = -1;
                tr = -1;
            }
        }

        static void Bad(bool strict, List<string> warnings, string name, int lineNo, string message)
        {
            if (strict) throw new RecordingFormatException(name, lineNo, message);
            warnings.Add($"line {lineNo}: {message} (row skipped)");
        }

        public static void Save(Recording recording, string path)
        {
            string dir = Path.GetDirectoryName(Path.GetFullPath(path));
            if (!string.IsNullOrEmpty(dir)) Directory.CreateDirectory(dir);
            using (var w = new StreamWriter(path, false, new UTF8Encoding(false)))
            {
                Write(recording, w);
            }
        }

        public static void Write(Recording recording, TextWriter w)
        {
            w.NewLine = "\n";
            w.WriteLine(Magic);
            foreach (var kv in recording.Metadata) w.WriteLine($"# {kv.Key}={kv.Value}");
            bool truth = recording.HasTruth;
            w.WriteLine(truth ? "timestamp_s,acc_x,acc_y,acc_z,phase_left,phase_right" : "timestamp_s,acc_x,acc_y,acc_z");
            var ci = CultureInfo.InvariantCulture;
            var sb = new StringBuilder(64);
            foreach (var s in recording.Samples)
            {
                sb.Clear();
                sb.Append(s.Imu.Time.ToString("F4", ci)).Append(',')
                  .Append(s.Imu.X.ToString("F4", ci)).Append(',')
                  .Append(s.Imu.Y.ToString("F4", ci)).Append(',')
                  .Append(s.Imu.Z.ToString("F4", ci));
                if (truth)
                {
                    sb.Append(',');
                    if (s.HasTruth) sb.Append(GaitPhases.ShortName(s.Left));
                    sb.Append(',');
                    if (s.HasTruth) sb.Append(GaitPhases.ShortName(s.Right));
                }
                w.WriteLine(sb.ToString());
            }
        }
    }
}
