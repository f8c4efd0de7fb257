using System;
using System.Collections.Generic;
using System.Text.RegularExpressions;

namespace HeadGait
{
    /// <summary>One split: which recordings are held out for testing.</summary>
    public sealed class Fold
    {
        public Fold(string scheme, string name, IReadOnlyCollection<string> test)
        {
            Scheme = scheme;
            Name = name;
            Test = new HashSet<string>(test);
        }

        public string Scheme { get; }
        public string Name { get; }

        /// <summary>Names of the held-out recordings; every other recording trains.</summary>
        public HashSet<string> Test { get; }

        public bool IsTest(string recording) => Test.Contains(recording);
    }

    /// <summary>
    /// Splits for cross-validation that never let a recording (or its augmented copies) be trained and tested on:
    /// leave-one-style-out, so each style (a corpus's actor or acting style) is tested by classifiers that never saw it,
    /// and a grouped k-fold over files.
    /// </summary>
    public static class CrossValidation
    {
        public const string ByStyle = "style";
        public const string ByFile = "file";

        static readonly Regex StyledName = new Regex(@"^(?<corpus>[A-Za-z0-9]+)_(?:neg_)?[^_]+_(?<style>[^_]+)_\d+(?:_\d+hz)?$");
        static readonly Regex RateSuffix = new Regex(@"_\d+hz$");

        /// <summary>The clip a recording was made from: a pose recording "bn_tl_act_006_72hz" comes from "bn_tl_act_006".</summary>
        public static string ClipOf(string recording) => RateSuffix.Replace(recording ?? "", "");

        /// <summary>
        /// The style group of a recording name: "corpus/style" for names like <c>bn_wk_act_001</c>,
        /// <c>bn_neg_wl_fem_002</c>, <c>bn1_walk-back_giant_001</c> or <c>bn_tl_act_006_72hz</c>; otherwise the name itself.
        /// </summary>
        public static string StyleOf(string recording)
        {
            var m = StyledName.Match(recording ?? "");
            return m.Success ? m.Groups["corpus"].Value + "/" + m.Groups["style"].Value : recording;
        }

        /// <summary>Leave one style out: one fold per style group that holds walking.</summary>
        public static List<Fold> LeaveOneStyleOut(IEnumerable<string> recordings)
        {
            var groups = new SortedDictionary<string, List<string>>(StringComparer.Ordinal);
            foreach (var r in recordings)
            {
                string g = StyleOf(r);
                if (!groups.TryGetValue(g, out var list)) groups[g] = list = new List<string>();
                list.Add(r);
            }
            var folds = new List<Fold>();
            foreach (var kv in groups) folds.Add(new Fold(ByStyle, kv.Key, kv.Value));
            return folds;
        }

        /// <summary>k folds of whole files, assigned by a seeded shuffle of the sorted names.</summary>
        public static List<Fold> FileFolds(IEnumerable<string> recordings, int k = 5, ulong seed = 1)
        {
            var names = new List<string>(recordings);
            names.Sort(StringComparer.Ordinal);
            var random = new Synthetic.DeterministicRandom(seed);
            for (int i = names.Count - 1; i > 0; i--)
            {
                int j = (int)(random.NextDouble() * (i + 1));
                var t = names[i];
                names[i] = names[j];
                names[j] = t;
            }
            var parts = new List<string>[k];
            for (int f = 0; f < k; f++) parts[f] = new List<string>();
            for (int i = 0; i < names.Count; i++) parts[i % k].Add(names[i]);
            var folds = new List<Fold>();
            for (int f = 0; f < k; f++) folds.Add(new Fold(ByFile, $"file{f + 1}of{k}", parts[f]));
            return folds;
        }

        public static List<Fold> Make(string scheme, IEnumerable<string> recordings)
        {
            switch (scheme)
            {
                case ByStyle: return LeaveOneStyleOut(recordings);
                case ByFile: return FileFolds(recordings);
                default: throw new ArgumentException($"Unknown cross-validation scheme '{scheme}' (style or file).");
            }
        }
    }
}
