using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace HeadGait
{
    /// <summary>
    /// The text format of the small model files (THR settings, COR templates): a magic first line, '#' comments and
    /// key=value lines. Accepts a byte-order mark and LF, CRLF or CR line ends; every error names the source and the key.
    /// </summary>
    public sealed class KeyValueText
    {
        /// <summary>The closing line every file ends with: a file cut short anywhere (a full disk, a copy cut off) lacks it.</summary>
        public const string EndLine = "end";

        readonly Dictionary<string, string> values = new Dictionary<string, string>();

        KeyValueText(string source)
        {
            Source = source;
        }

        public string Source { get; }

        public static KeyValueText Parse(string text, string magic, string source)
        {
            if (text == null) throw new FormatException($"{source}: no text");
            var kv = new KeyValueText(source);
            if (text.Length > 0 && text[0] == '\uFEFF') text = text.Substring(1);
            bool first = true, ended = false;
            foreach (var raw in text.Replace("\r\n", "\n").Replace('\r', '\n').Split('\n'))
            {
                string line = raw.Trim();
                if (line.Length == 0) continue;
                if (ended) throw new FormatException($"{source}: '{Shorten(line)}' follows the closing '{EndLine}' line");
                if (first)
                {
                    if (line != magic) throw new FormatException($"{source}: first line must be '{magic}'");
                    first = false;
                    continue;
                }
                if (line.StartsWith("#", StringComparison.Ordinal)) continue;
                if (line == EndLine)
                {
                    ended = true;
                    continue;
                }
                int eq = line.IndexOf('=');
                if (eq <= 0) throw new FormatException($"{source}: line '{Shorten(line)}' is not key=value");
                string key = line.Substring(0, eq).Trim();
                if (kv.values.ContainsKey(key)) throw new FormatException($"{source}: '{key}' appears twice");
                kv.values[key] = line.Substring(eq + 1).Trim();
            }
            if (first) throw new FormatException($"{source}: empty; first line must be '{magic}'");
            if (!ended) throw new FormatException($"{source}: ends before its closing '{EndLine}' line: truncated (or written before the line was required: train again, or add '{EndLine}' after checking the values)");
            return kv;
        }

        public static KeyValueText Load(string path, string magic)
        {
            if (!File.Exists(path)) throw new FileNotFoundException($"{path}: file not found", path);
            return Parse(InputLimits.ReadAllText(path, InputLimits.MaxTextModelBytes, "a text model file"), magic, path);
        }

        public bool Has(string key) => values.ContainsKey(key);

        public string Need(string key) => values.TryGetValue(key, out var v) ? v : throw new FormatException($"{Source}: lacks '{key}'");

        /// <summary>A finite number within [min, max].</summary>
        public double Number(string key, double min, double max)
        {
            string v = Need(key);
            if (!TryNumber(v, out double d)) throw new FormatException($"{Source}: '{key}' is '{Shorten(v)}', not a finite number");
            if (d < min || d > max) throw new FormatException($"{Source}: '{key}' is {d.ToString("R", CultureInfo.InvariantCulture)}, outside {min.ToString(CultureInfo.InvariantCulture)}..{max.ToString(CultureInfo.InvariantCulture)}");
            return d;
        }

        public double Number(string key, double min, double max, double fallback) => Has(key) ? Number(key, min, max) : fallback;

        /// <summary>A comma-separated list of exactly <paramref name="count"/> finite numbers within [min, max].</summary>
        public double[] Numbers(string key, int count, double min, double max)
        {
            string[] parts = Need(key).Split(',');
            if (parts.Length != count) throw new FormatException($"{Source}: '{key}' has {parts.Length} values, expected {count}");
            var r = new double[count];
            for (int i = 0; i < count; i++)
            {
                if (!TryNumber(parts[i].Trim(), out r[i]) || r[i] < min || r[i] > max)
                    throw new FormatException($"{Source}: '{key}' value {i} ('{Shorten(parts[i])}') is not a finite number within {min.ToString(CultureInfo.InvariantCulture)}..{max.ToString(CultureInfo.InvariantCulture)}");
            }
            return r;
        }

        /// <summary>
        /// <paramref name="count"/> numbers as <see cref="Numbers(string, int, double, double)"/>, or as many as one of
        /// <paramref name="olderCounts"/> from a file written before the list changed; any other length is reported
        /// against <paramref name="count"/>.
        /// </summary>
        public double[] Numbers(string key, int count, int[] olderCounts, double min, double max)
        {
            int found = Need(key).Split(',').Length;
            return Numbers(key, Array.IndexOf(olderCounts, found) >= 0 ? found : count, min, max);
        }

        /// <summary>A walking gate as <see cref="WalkingGate.Serialize"/> writes it (also the shorter lists older models hold, <see cref="WalkingGate.OlderLengths"/>).</summary>
        public WalkingGate Gate(string key)
        {
            try
            {
                return WalkingGate.Parse(Need(key));
            }
            catch (FormatException e)
            {
                throw new FormatException($"{Source}: '{key}': {e.Message}");
            }
        }

        public PhaseMap PhaseMap(string key)
        {
            try
            {
                return HeadGait.PhaseMap.Parse(Need(key));
            }
            catch (FormatException e)
            {
                throw new FormatException($"{Source}: '{key}': {e.Message}");
            }
        }

        /// <summary>Parses like double.TryParse but never throws (Mono's double.Parse may overflow on 1e309) and rejects NaN/infinity.</summary>
        public static bool TryNumber(string s, out double v)
        {
            try
            {
                if (!double.TryParse(s, NumberStyles.Float, CultureInfo.InvariantCulture, out v)) return false;
            }
            catch (OverflowException)
            {
                v = 0;
                return false;
            }
            return !double.IsNaN(v) && !double.IsInfinity(v);
        }

        static string Shorten(string s) => s.Length > 40 ? s.Substring(0, 40) + "..." : s;

        /// <summary>Writes key=value lines after the magic line, LF line ends, no byte-order mark.</summary>
        public static string Write(string magic, IEnumerable<KeyValuePair<string, string>> pairs, string comment = null)
        {
            var sb = new StringBuilder();
            sb.Append(magic).Append('\n');
            if (!string.IsNullOrEmpty(comment)) sb.Append("# ").Append(comment.Replace("\n", " ")).Append('\n');
            foreach (var kv in pairs) sb.Append(kv.Key).Append('=').Append(kv.Value).Append('\n');
            sb.Append(EndLine).Append('\n');
            return sb.ToString();
        }
    }
}
