using System;
using System.Collections.Generic;
using System.IO;
using System.Text.RegularExpressions;

namespace HeadGait
{
    /// <summary>
    /// Finds the package's folders (sample recordings, trained models) from a working directory anywhere inside the
    /// repository or a Unity project, however the package is installed: embedded (Packages/com.headgait.legmotion), from
    /// git or a registry (Library/PackageCache/com.headgait.legmotion@&lt;hash&gt;), as a local "file:" dependency in
    /// Packages/manifest.json, or when a start directory lies inside the package itself.
    /// </summary>
    public static class SamplePaths
    {
        public const string PackageName = "com.headgait.legmotion";
        const string RecordingsInPackage = "Samples~/Recordings";
        const string ModelsInPackage = "Models";

        /// <summary>The Samples~/Recordings folder, searched upwards from each start directory; null when not found.</summary>
        public static string FindRecordingsFolder(params string[] startDirectories) => FindInPackage(RecordingsInPackage, startDirectories);

        /// <summary>The package's trained models (Models/), searched like <see cref="FindRecordingsFolder"/>; null when not found.</summary>
        public static string FindModelsFolder(params string[] startDirectories) => FindInPackage(ModelsInPackage, startDirectories);

        /// <summary>The first package root (a folder whose package.json names this package) holding <paramref name="relative"/>.</summary>
        static string FindInPackage(string relative, string[] startDirectories)
        {
            foreach (var root in CandidateRoots(startDirectories))
            {
                string candidate = Path.Combine(root, relative);
                if (Directory.Exists(candidate)) return candidate;
            }
            return null;
        }

        /// <summary>Package roots seen from each start directory and every directory above it, nearest first.</summary>
        public static IEnumerable<string> CandidateRoots(params string[] startDirectories)
        {
            var starts = new List<string>(startDirectories ?? Array.Empty<string>());
            starts.Add(Directory.GetCurrentDirectory());
            starts.Add(AppContext.BaseDirectory);
            foreach (var start in starts)
            {
                if (string.IsNullOrEmpty(start)) continue;
                for (var dir = new DirectoryInfo(start); dir != null; dir = dir.Parent)
                {
                    if (IsPackageRoot(dir.FullName)) yield return dir.FullName;
                    string embedded = Path.Combine(dir.FullName, "Packages", PackageName);
                    if (IsPackageRoot(embedded)) yield return embedded;
                    string local = FromManifest(Path.Combine(dir.FullName, "Packages"));
                    if (local != null && IsPackageRoot(local)) yield return local;
                    string cache = Path.Combine(dir.FullName, "Library", "PackageCache");
                    if (Directory.Exists(cache))
                    {
                        var cached = Directory.GetDirectories(cache, PackageName + "@*");
                        Array.Sort(cached, StringComparer.Ordinal);
                        foreach (var c in cached)
                            if (IsPackageRoot(c)) yield return c;
                    }
                }
            }
        }

        static bool IsPackageRoot(string dir)
        {
            string manifest = Path.Combine(dir, "package.json");
            if (!File.Exists(manifest)) return false;
            return Regex.IsMatch(File.ReadAllText(manifest), "\"name\"\\s*:\\s*\"" + Regex.Escape(PackageName) + "\"");
        }

        /// <summary>The folder of a local ("file:") dependency on this package in Packages/manifest.json, or null.</summary>
        static string FromManifest(string packagesDir)
        {
            string manifest = Path.Combine(packagesDir, "manifest.json");
            if (!File.Exists(manifest)) return null;
            var m = Regex.Match(File.ReadAllText(manifest), "\"" + Regex.Escape(PackageName) + "\"\\s*:\\s*\"file:([^\"]+)\"");
            if (!m.Success) return null;
            string path = m.Groups[1].Value.Replace('/', Path.DirectorySeparatorChar);
            return Path.GetFullPath(Path.IsPathRooted(path) ? path : Path.Combine(packagesDir, path));
        }

        public static string RequireRecordingsFolder(params string[] startDirectories)
            => FindRecordingsFolder(startDirectories)
               ?? throw new DirectoryNotFoundException($"Could not find {PackageName}'s {RecordingsInPackage} from {Directory.GetCurrentDirectory()} (looked for the package embedded in Packages/, in Library/PackageCache/{PackageName}@*, as a file: dependency in Packages/manifest.json, and above).");

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
