using System;
using System.Collections.Generic;
using System.IO;

namespace HeadGait
{
    /// <summary>Finds the package's sample recordings from a working directory anywhere inside the repository (or a Unity project).</summary>
    public static class SamplePaths
    {
        public const string PackageFolder = "Packages/com.headgait.legmotion";
        public const string RecordingsFolder = PackageFolder + "/Samples~/Recordings";
        public const string ModelsFolder = PackageFolder + "/Models";

        /// <summary>The Samples~/Recordings folder, searched upwards from each start directory; null when not found.</summary>
        public static string FindRecordingsFolder(params string[] startDirectories) => FindAbove(RecordingsFolder, startDirectories);

        /// <summary>The package's trained models (Models/), searched like <see cref="FindRecordingsFolder"/>; null when not found.</summary>
        public static string FindModelsFolder(params string[] startDirectories) => FindAbove(ModelsFolder, startDirectories);

        static string FindAbove(string relative, string[] startDirectories)
        {
            var starts = new List<string>(startDirectories ?? Array.Empty<string>());
            starts.Add(Directory.GetCurrentDirectory());
            starts.Add(AppContext.BaseDirectory);
            foreach (var start in starts)
            {
                if (string.IsNullOrEmpty(start)) continue;
                var dir = new DirectoryInfo(start);
                while (dir != null)
                {
                    string candidate = Path.Combine(dir.FullName, relative);
                    if (Directory.Exists(candidate)) return candidate;
                    dir = dir.Parent;
                }
            }
            return null;
        }

        public static string RequireRecordingsFolder(params string[] startDirectories)
            => FindRecordingsFolder(startDirectories)
               ?? throw new DirectoryNotFoundException($"Could not find {RecordingsFolder} above {Directory.GetCurrentDirectory()}.");

        public static string[] List(string folder, string set)
        {
            string dir = Path.Combine(folder, set);
            if (!Directory.Exists(dir)) return Array.Empty<string>();
            var files = Directory.GetFiles(dir, "*.csv");
            Array.Sort(files, StringComparer.Ordinal);
            return files;
        }
    }
}
