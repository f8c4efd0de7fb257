using System;
using System.Collections.Generic;
using System.IO;

namespace HeadGait.Calibration
{
    /// <summary>
    /// The wearers' profiles in one folder (<c>WEARER.profile.txt</c>): chosen at start-up by wearer id, saved whole or not
    /// at all, reset by deleting. A wearer without a usable profile gets the shipped models, and the reason is said.
    /// Wearer ids are one wearer whatever their case: on a standalone headset the folder lies in Android's shared storage
    /// (<c>Application.persistentDataPath</c>), whose file names fold case, so "anna" saved over "Anna"'s file there; the
    /// first saved spelling names the file everywhere.
    /// </summary>
    public sealed class WearerProfiles
    {
        public WearerProfiles(string folder)
        {
            if (string.IsNullOrEmpty(folder)) throw new ArgumentException("A profile folder is needed.", nameof(folder));
            Folder = folder;
        }

        public string Folder { get; }

        /// <summary>
        /// The wearer's profile file: the one here whose name matches the id whatever its case, else the id's own. Throws
        /// <see cref="ArgumentException"/> for an id that is no file name, and <see cref="IOException"/> naming the files
        /// when several differ only in case (written where names keep case, before ids were one wearer whatever their case).
        /// </summary>
        public string PathOf(string wearer)
        {
            if (!WearerProfile.IsValidWearer(wearer)) throw new ArgumentException($"Wearer id '{wearer}' is not 1-64 letters, digits, '-', '_' or '.'.");
            string exact = Path.Combine(Folder, wearer + WearerProfile.Extension);
            if (!Directory.Exists(Folder)) return exact;
            var matches = new List<string>();
            foreach (var f in Directory.GetFiles(Folder, "*" + WearerProfile.Extension))
                if (string.Equals(Path.GetFileName(f), wearer + WearerProfile.Extension, StringComparison.OrdinalIgnoreCase)) matches.Add(f);
            if (matches.Count <= 1) return matches.Count == 1 ? matches[0] : exact;
            matches.Sort(StringComparer.Ordinal);
            throw new IOException($"Wearer '{wearer}' has {matches.Count} profiles whose names differ only in case ({string.Join(", ", matches)}); " +
                                  "wearer ids are one wearer whatever their case: delete the ones not wanted.");
        }

        /// <summary>Whether two wearer ids name the same wearer.</summary>
        public static bool SameWearer(string a, string b) => string.Equals(a, b, StringComparison.OrdinalIgnoreCase);

        /// <summary>Wearers with a profile file here, sorted.</summary>
        public List<string> Wearers()
        {
            var list = new List<string>();
            if (!Directory.Exists(Folder)) return list;
            foreach (var f in Directory.GetFiles(Folder, "*" + WearerProfile.Extension))
            {
                string name = Path.GetFileName(f);
                list.Add(name.Substring(0, name.Length - WearerProfile.Extension.Length));
            }
            list.Sort(StringComparer.Ordinal);
            return list;
        }

        public void Save(WearerProfile profile)
        {
            Directory.CreateDirectory(Folder);
            profile.Save(PathOf(profile.Wearer));
        }

        /// <summary>Deletes the wearer's profile (the shipped models apply again); false when there was none.</summary>
        public bool Reset(string wearer)
        {
            string path = PathOf(wearer);
            if (!File.Exists(path)) return false;
            File.Delete(path);
            return true;
        }

        /// <summary>
        /// The models for <paramref name="wearer"/>: the shipped ones adapted by the wearer's profile, or the shipped ones as
        /// they are when the wearer has none, it is unreadable, names another wearer, or was fitted against other models
        /// (<paramref name="note"/> then says why; null when the profile applies or none was asked for).
        /// </summary>
        public GaitModels ModelsFor(string wearer, GaitModels shipped, out WearerProfile profile, out string note)
        {
            profile = null;
            note = null;
            if (string.IsNullOrEmpty(wearer)) return shipped;
            string path;
            try
            {
                path = PathOf(wearer);
            }
            catch (Exception e) when (e is ArgumentException || e is IOException || e is UnauthorizedAccessException)
            {
                note = e.Message + " Using the shipped models.";
                return shipped;
            }
            if (!File.Exists(path))
            {
                note = $"{path}: no profile for wearer '{wearer}'; using the shipped models (run the calibration walk to make one).";
                return shipped;
            }
            try
            {
                var p = WearerProfile.Load(path);
                if (!SameWearer(p.Wearer, wearer)) throw new FormatException($"{path}: holds wearer '{p.Wearer}', not '{wearer}'");
                string current = WearerProfile.Fingerprint(shipped);
                if (p.BaseModels.Length > 0 && current.Length > 0 && p.BaseModels != current)
                {
                    note = $"{path}: fitted against other models ({p.BaseModels}, these are {current}); using the shipped models until the wearer calibrates again.";
                    return shipped;
                }
                profile = p;
                return p.Apply(shipped);
            }
            catch (Exception e) when (e is FormatException || e is IOException || e is UnauthorizedAccessException || e is ModelFormatException || e is ArgumentException)
            {
                note = $"{(e.Message.StartsWith(path, StringComparison.Ordinal) ? e.Message : path + ": " + e.Message)}; using the shipped models.";
                return shipped;
            }
        }
    }
}
