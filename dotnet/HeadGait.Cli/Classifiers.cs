using System;
using System.Collections.Generic;
using System.Linq;

namespace HeadGait.Cli
{
    /// <summary>Parsing --classifier lists and making classifiers from a model folder.</summary>
    static class Classifiers
    {
        public static List<string> Parse(string list)
        {
            var names = new List<string>();
            foreach (var part in (list ?? "all").ToLowerInvariant().Split(',', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries))
            {
                if (part == "all") names.AddRange(GaitModels.Names);
                else if (GaitModels.Names.Contains(part) || part == "svm-raw" || part == "blstm-raw") names.Add(part);
                else throw new UsageException($"unknown classifier '{part}' (thr, cor, svm, blstm, all; svm-raw, blstm-raw: without the time filter)");
            }
            if (names.Count == 0) throw new UsageException($"--classifier '{list}' names no classifier (thr, cor, svm, blstm or all)");
            return names.Distinct().ToList();
        }

        /// <summary>Loads a model folder and says which files could not be used.</summary>
        public static GaitModels Load(string folder)
        {
            var models = GaitModels.Load(folder);
            foreach (var p in models.Problems) Console.WriteLine($"warning: {p}");
            return models;
        }
    }
}
