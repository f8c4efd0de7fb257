using System;
using System.Collections.Generic;
using System.CommandLine;
using System.Globalization;
using System.IO;
using System.Linq;

namespace HeadGait.Cli
{
    /// <summary>headgait replay: recordings through the live pipeline with the trained classifiers.</summary>
    static class ReplayCommand
    {
        public static Command Build()
        {
            var files = new Argument<string[]>("recordings") { Arity = ArgumentArity.ZeroOrMore, Description = "CSV recordings or folders of them (default: the package's generated sample recordings, Samples~/Recordings/eval)" };
            var classifier = new Option<string>("--classifier") { Description = "thr, cor, svm, blstm, a comma-separated list or all", DefaultValueFactory = _ => "all" };
            var models = new Option<string>("--models") { Description = "folder of trained models (default: the package's Models/)" };
            var trace = new Option<string>("--trace") { Description = "write each window's prediction and avatar frame as CSV into this folder" };
            var strict = new Option<bool>("--strict") { Description = "reject a recording with any bad row instead of skipping the row" };
            var command = new Command("replay", "Replays recordings sample by sample through preprocessing, a classifier and the animator, and scores them against their labels.")
            {
                files, classifier, models, trace, strict,
            };
            command.SetAction(parse => Run(parse.GetValue(files), parse.GetValue(classifier), parse.GetValue(models), parse.GetValue(trace), parse.GetValue(strict)));
            return command;
        }

        static int Run(string[] files, string classifierList, string modelFolder, string traceDir, bool strict)
        {
            var names = Classifiers.Parse(classifierList);
            OptionValues.Folder(modelFolder, "--models");
            OptionValues.Path(traceDir, "--trace");
            bool samples = files == null || files.Length == 0;
            var paths = samples ? SamplePaths.List(SamplePaths.RequireRecordingsFolder(), "eval").ToList() : Inputs.Expand(files, "*.csv");
            if (paths.Count == 0) throw new UsageException("no recordings to replay");
            string folder = modelFolder ?? SamplePaths.FindModelsFolder() ?? throw new UsageException("no --models and no package Models/ folder found");
            var models = Classifiers.Load(folder);

            Console.WriteLine(samples
                ? $"HeadGait replay of the package's {paths.Count} generated sample recordings (synthetic walkers, not people), models from {folder}"
                : $"HeadGait replay of {paths.Count} recording(s), models from {folder}");

            // One recording at a time: it is read, replayed by every classifier and let go, so memory holds one recording's
            // samples however many files are given (only the scores are kept).
            var results = names.ToDictionary(n => n, n => new List<ReplayResult>());
            var warned = new HashSet<string>();
            var empty = new List<string>();
            bool labelled = false;
            using (var progress = new Progress("replay", paths.Count * names.Count))
            {
                foreach (var path in paths)
                {
                    var rec = Inputs.LoadRecordings(new[] { path }, strict)[0];
                    if (rec.Warnings.Count > 0)
                    {
                        Console.WriteLine($"{rec.Name}: skipped {rec.Warnings.Count} unreadable row(s):");
                        foreach (var w in rec.Warnings.Take(5)) Console.WriteLine($"  {w}");
                    }
                    if (rec.Samples.Count == 0)
                    {
                        // Nothing to replay: every row was unreadable (decimal commas, NaN) or the file holds none.
                        empty.Add(path);
                        progress.Step(rec.Name);
                        continue;
                    }
                    labelled |= rec.HasTruth;
                    foreach (var name in names)
                    {
                        var c = models.Create(name, out string warning);
                        if (warning != null && warned.Add(name)) Console.WriteLine($"warning: {warning}");
                        var res = ReplayEvaluator.Run(rec, c, keepTrace: traceDir != null);
                        if (traceDir != null)
                        {
                            WriteTrace(traceDir, name, res);
                            res.Predictions = null; // written: not kept
                            res.Frames = null;
                        }
                        results[name].Add(res);
                        progress.Step($"{rec.Name} {name}");
                    }
                }
            }
            Console.WriteLine();
            foreach (var path in empty) Console.Error.WriteLine($"error: {path}: no usable samples to replay");
            if (results[names[0]].Count == 0) return 1;
            // Every classifier sees the same samples, so the clock policy's account is the same for all: print it once.
            foreach (var r in results[names[0]].Where(r => r.SkipSummary.Length > 0))
                Console.WriteLine($"{r.Recording}: the clock policy {r.SkipSummary}");
            if (results[names[0]].Any(r => r.SkipSummary.Length > 0)) Console.WriteLine();
            if (labelled)
            {
                Report.PhaseHeader();
                foreach (var name in names)
                    foreach (var r in results[name]) Report.PhaseRow(r.Recording, r.Classifier, new[] { r });
                foreach (var name in names) Report.PhaseRow("ALL (pooled)", results[name][0].Classifier, results[name]);
                Console.WriteLine();
                Report.StepHeader();
                foreach (var name in names) Report.StepRows("ALL (pooled)", results[name][0].Classifier, results[name]);
                Console.WriteLine();
                Report.Legend();
            }
            foreach (var name in names)
            {
                foreach (var r in results[name].Where(r => r.ClassifierMetrics == null && r.Windows > 0))
                {
                    var parts = Enum.GetValues(typeof(LocomotionState)).Cast<LocomotionState>()
                        .Where(st => r.StateCounts.ContainsKey(st))
                        .Select(st => $"{st} {100.0 * r.StateCounts[st] / r.Windows:F0}%");
                    Console.WriteLine($"{r.Recording} ({r.Classifier}, no labels): avatar time in {string.Join(", ", parts)}");
                }
            }
            if (samples)
            {
                Console.WriteLine("These recordings come from the package's own walking generator: they show the pipeline works end to end;");
                Console.WriteLine("accuracy on people is measured by `headgait benchmark` on real recordings (see the README).");
            }
            return empty.Count > 0 ? 1 : 0;
        }

        static void WriteTrace(string dir, string name, ReplayResult r)
        {
            Directory.CreateDirectory(dir);
            string path = Path.Combine(dir, $"{r.Recording}.{name}.trace.csv");
            using var w = new StreamWriter(path);
            w.WriteLine("time_s,walking,stride_pos,pred_left,pred_right,confidence,state,anim_stride_pos,anim_left,anim_right,walk_weight");
            for (int i = 0; i < r.Predictions.Count; i++)
            {
                var p = r.Predictions[i];
                var f = r.Frames[i];
                w.WriteLine(string.Format(CultureInfo.InvariantCulture, "{0:F3},{1},{2:F4},{3},{4},{5:F3},{6},{7:F4},{8},{9},{10:F2}",
                    p.Time, p.IsWalking ? 1 : 0, p.StridePosition, GaitPhases.ShortName(p.Left), GaitPhases.ShortName(p.Right), p.Confidence,
                    f.State, f.StridePosition, GaitPhases.ShortName(f.Left), GaitPhases.ShortName(f.Right), f.WalkWeight));
            }
        }
    }
}
