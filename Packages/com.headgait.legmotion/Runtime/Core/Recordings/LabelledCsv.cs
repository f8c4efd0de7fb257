using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;

namespace HeadGait
{
    /// <summary>
    /// The CSV layout recordings share: '#' comment and 'key=value' metadata lines, a header naming the columns (any
    /// order, extra ones ignored), numeric columns with stated limits, and optional per-foot phase labels
    /// (phase_left, phase_right: both or neither). Byte-order marks and LF, CRLF or CR line ends are accepted.
    /// </summary>
    static class LabelledCsv
    {
        public static readonly string[] TruthColumns = { "phase_left", "phase_right" };

        public sealed class Result
        {
            public readonly List<string> Warnings = new List<string>();
            public readonly Dictionary<string, string> Metadata = new Dictionary<string, string>();
            /// <summary>Bad rows beyond <see cref="InputLimits.MaxListedWarnings"/>: counted in one closing warning.</summary>
            public int Unlisted;
        }

        /// <summary>
        /// Reads the rows, calling <paramref name="row"/> with each good one's values (in <paramref name="required"/> order),
        /// its 1-based line and its labels (null without labels). A missing header or column throws
        /// <see cref="RecordingFormatException"/> naming <paramref name="source"/> (the file); a bad row throws in strict mode
        /// and is skipped with a warning otherwise.
        /// </summary>
        public static Result Read(TextReader reader, string source, bool strict, string[] required, double[] limits, string[] units,
            Action<double[], int, GaitPhase?, GaitPhase?> row)
        {
            var result = new Result();
            reader = InputLimits.BoundLines(reader, source); // a line without end (a file of zeros) is refused, not held
            int lineNo = 0, rows = 0;
            int[] idx = null;
            int tl = -1, tr = -1, columnCount = 0;
            string line;
            var v = new double[required.Length];
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
                        if (key.Length > 0 && key.IndexOf(' ') < 0) result.Metadata[key] = trimmed.Substring(eq + 1).Trim();
                    }
                    continue;
                }
                string[] cells = trimmed.Split(',');
                if (idx == null)
                {
                    ParseHeader(cells, source, lineNo, required, out idx, out tl, out tr);
                    columnCount = cells.Length;
                    continue;
                }
                InputLimits.CheckRows(++rows, source);
                if (cells.Length != columnCount)
                {
                    Bad(strict, result, source, lineNo, $"expected {columnCount} cells, found {cells.Length}");
                    continue;
                }
                string error = null;
                for (int c = 0; c < required.Length && error == null; c++)
                {
                    string cell = cells[idx[c]].Trim();
                    if (!KeyValueText.TryNumber(cell, out v[c]))
                        error = double.TryParse(cell, NumberStyles.Float, CultureInfo.InvariantCulture, out _) ? $"{required[c]} is not finite" : $"{required[c]} '{Shorten(cell)}' is not a number";
                    else if (Math.Abs(v[c]) > limits[c])
                        error = $"{required[c]} {Shorten(cell)} is beyond the limit of {limits[c].ToString("G", CultureInfo.InvariantCulture)} {units[c]}";
                }
                if (error != null)
                {
                    Bad(strict, result, source, lineNo, error);
                    continue;
                }
                if (tl < 0)
                {
                    row(v, lineNo, null, null);
                    continue;
                }
                string l = cells[tl].Trim(), r = cells[tr].Trim();
                if (l.Length == 0 && r.Length == 0)
                {
                    row(v, lineNo, null, null);
                    continue;
                }
                if (!GaitPhases.TryParse(l, out var pl) || !GaitPhases.TryParse(r, out var pr))
                {
                    Bad(strict, result, source, lineNo, $"unknown phase label '{Shorten(l)}' / '{Shorten(r)}'");
                    continue;
                }
                if ((pl == GaitPhase.Standing) != (pr == GaitPhase.Standing))
                {
                    Bad(strict, result, source, lineNo, "one foot is labelled STAND and the other walking");
                    continue;
                }
                row(v, lineNo, pl, pr);
            }
            if (idx == null)
                throw new RecordingFormatException(source, Math.Max(lineNo, 1), $"no header line (expected {string.Join(",", required)}[,phase_left,phase_right])");
            if (result.Unlisted > 0)
                result.Warnings.Add($"line {lineNo}: and {result.Unlisted} more bad row(s) after these (rows skipped, not listed)");
            return result;
        }

        static void ParseHeader(string[] cells, string source, int lineNo, string[] required, out int[] idx, out int tl, out int tr)
        {
            var names = new Dictionary<string, int>(StringComparer.OrdinalIgnoreCase);
            for (int i = 0; i < cells.Length; i++)
            {
                string c = cells[i].Trim();
                if (c.Length == 0) continue;
                if (names.ContainsKey(c)) throw new RecordingFormatException(source, lineNo, $"column '{Shorten(c)}' appears twice");
                names[c] = i;
            }
            idx = new int[required.Length];
            var missing = new List<string>();
            for (int c = 0; c < required.Length; c++)
                if (!names.TryGetValue(required[c], out idx[c])) missing.Add(required[c]);
            if (missing.Count > 0)
                throw new RecordingFormatException(source, lineNo,
                    $"missing column(s) {string.Join(", ", missing)}; header must name {string.Join(",", required)} (found: {Shorten(string.Join(",", cells))})");
            bool hasL = names.TryGetValue(TruthColumns[0], out tl);
            bool hasR = names.TryGetValue(TruthColumns[1], out tr);
            if (hasL != hasR) throw new RecordingFormatException(source, lineNo, "ground truth needs both phase_left and phase_right");
            if (!hasL) tl = tr = -1;
        }

        static void Bad(bool strict, Result result, string source, int lineNo, string message)
        {
            if (strict) throw new RecordingFormatException(source, lineNo, message);
            if (result.Warnings.Count < InputLimits.MaxListedWarnings) result.Warnings.Add($"line {lineNo}: {message} (row skipped)");
            else result.Unlisted++;
        }

        static string Shorten(string s) => s.Length > 40 ? s.Substring(0, 40) + "..." : s;
    }
}
