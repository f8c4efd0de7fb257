using System;
using System.Collections.Generic;
using System.IO;

namespace HeadGait.Cli
{
    /// <summary>A command-line mistake: printed with the command's help, exit code 2.</summary>
    sealed class UsageException : Exception
    {
        public UsageException(string message) : base(message) { }
    }

    static class Inputs
    {
        /// <summary>Files as given, and the matching files of each folder given (sorted); a path that is neither is an error.</summary>
        public static List<string> Expand(IEnumerable<string> paths, string pattern)
        {
            var list = new List<string>();
            foreach (var p in paths ?? Array.Empty<string>())
            {
                if (Directory.Exists(p))
                {
                    var files = Directory.GetFiles(p, pattern);
                    Array.Sort(files, StringComparer.Ordinal);
                    if (files.Length == 0) throw new UsageException($"no {pattern} files in folder {p}");
                    list.AddRange(files);
                }
                else if (File.Exists(p)) list.Add(p);
                else throw new UsageException($"no such file or folder: {p}");
            }
            return list;
        }

        /// <summary>Acceleration recordings as they are; head-pose recordings through the XR pose path (PoseCsv.ToAcceleration).</summary>
        public static List<Recording> LoadRecordings(IEnumerable<string> files, bool strict)
        {
            var list = new List<Recording>();
            foreach (var f in files) list.Add(PoseCsv.IsPoseFile(f) ? PoseCsv.ToAcceleration(f, strict) : RecordingCsv.Load(f, strict));
            return list;
        }
    }
}
