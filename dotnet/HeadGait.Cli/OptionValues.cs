using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;

namespace HeadGait.Cli
{
    /// <summary>
    /// Checks of option values that the parser cannot make (ranges, lists, folders): a bad one is a <see cref="UsageException"/>
    /// (exit 2) naming the option, before any work starts.
    /// </summary>
    static class OptionValues
    {
        public static int Count(int value, string option, int min, int max)
        {
            if (value < min || value > max) throw new UsageException($"{option} must be {min} to {max}, not {value}");
            return value;
        }

        public static double Number(double value, string option, double min, double max)
        {
            if (double.IsNaN(value) || value < min || value > max)
                throw new UsageException(FormattableString.Invariant($"{option} must be a number from {min} to {max}, not {value}"));
            return value;
        }

        /// <summary>A comma-separated list of cross-validation schemes (style, file; and none where <paramref name="allowNone"/>).</summary>
        public static List<string> Schemes(string list, string option, bool allowNone)
        {
            var schemes = (list ?? "").Split(',', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries).Select(s => s.ToLowerInvariant()).Distinct().ToList();
            string allowed = allowNone ? "style, file, style,file or none" : "style, file or style,file";
            if (schemes.Count == 0) throw new UsageException($"{option} is empty: give {allowed}");
            foreach (var s in schemes)
                if (s != CrossValidation.ByStyle && s != CrossValidation.ByFile && !(allowNone && s == "none"))
                    throw new UsageException($"{option}: unknown scheme '{s}' ({allowed})");
            return schemes;
        }

        /// <summary>
        /// A comma-separated list of frame rates (Hz), each from <paramref name="min"/> to <paramref name="max"/> and, with
        /// <paramref name="whole"/>, a whole number. Null (the option left out) is no rates; given, the list must name one.
        /// </summary>
        public static List<double> FrameRates(string list, string option, double min, double max, bool whole = false)
        {
            var rates = new List<double>();
            if (list == null) return rates;
            string kind = whole ? "a whole frame rate" : "a frame rate";
            foreach (var part in list.Split(',', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries))
            {
                if (!double.TryParse(part, NumberStyles.Float, CultureInfo.InvariantCulture, out double r) || !(r >= min && r <= max)
                    || (whole && r != Math.Floor(r)))
                    throw new UsageException(FormattableString.Invariant($"{option}: '{part}' is not {kind} of {min} to {max} Hz"));
                rates.Add(r);
            }
            if (rates.Count == 0) throw new UsageException($"{option} names no frame rate: give one or more, comma-separated, e.g. 72,90");
            return rates;
        }

        /// <summary>A folder the user named: it must exist (null passes, for an option left out).</summary>
        public static string Folder(string path, string option)
        {
            if (path == null) return null;
            if (path.Trim().Length == 0) throw new UsageException($"{option} is empty");
            if (!Directory.Exists(path)) throw new UsageException($"{option}: no such folder: {path}");
            return path;
        }

        /// <summary>A path the user named for output: not empty (null passes).</summary>
        public static string Path(string path, string option)
        {
            if (path != null && path.Trim().Length == 0) throw new UsageException($"{option} is empty");
            return path;
        }
    }
}
