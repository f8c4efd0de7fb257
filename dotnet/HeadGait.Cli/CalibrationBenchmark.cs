using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using HeadGait.Calibration;
using HeadGait.Mocap;

namespace HeadGait.Cli
{
    /// <summary>
    /// The calibration benchmark: leave one style out; THR and COR trained on the other styles; each held-out style's first
    /// walking recording is the calibration walk, made again from its motion capture as a headset and two ankle trackers
    /// record it; its other recordings are scored by the uncalibrated classifiers, by those fitted with the ankle trackers'
    /// labels and by those fitted self-supervised. The SVM and BLSTM are the shipped models (trained on every style: not held out).
    /// </summary>
    static class CalibrationBenchmark
    {
        static readonly string[] Variants = { "none", "feet", "self" };

        sealed class Cell
        {
            public readonly List<GaitMetrics> All = new List<GaitMetrics>(), Standing = new List<GaitMetrics>();
        }

        public static int Run(string[] data, string bvhFolder, string modelFolder, List<string> names, int augment, string cache, double ankleRate)
        {
            if (!Directory.Exists(bvhFolder)) throw new UsageException($"no such folder: {bvhFolder}");
            var recordings = Inputs.LoadRecordings(Inputs.Expand(data, "*.csv"), false).Where(r => r.HasTruth).ToList();
            if (recordings.Count == 0) throw new UsageException("no labelled recordings in --data");
            string folder = modelFolder ?? SamplePaths.FindModelsFolder() ?? throw new UsageException("no --models and no package Models/ folder found");
            var shipped = GaitModels.Load(folder);
            var byName = recordings.ToDictionary(r => r.Name);
            var folds = CrossValidation.LeaveOneStyleOut(byName.Keys);
            var cells = new Dictionary<(string style, string clf, string variant), Cell>();
            var notes = new List<string>();
            var cadence = new Dictionary<string, double>();
            Console.WriteLine($"HeadGait calibration benchmark: {recordings.Count} labelled recordings, motion capture from {bvhFolder}, ankle trackers at {ankleRate:0} Hz");
            Console.WriteLine("SVM and BLSTM: the shipped models, trained on every style (NOT held out); THR and COR trained inside each fold.");
            foreach (var fold in folds)
            {
                var test = fold.Test.Select(n => byName[n]).OrderBy(r => r.Name, StringComparer.Ordinal).ToList();
                var steps = test.SelectMany(r => PhaseEvents.TruthSteps(r)).Select(s => s.Duration).ToList();
                if (steps.Count == 0) continue;
                cadence[fold.Name] = GaitMetrics.Median(steps);
                var calibration = test.FirstOrDefault(r => IsStraightWalk(r.Name) && BvhOf(r, bvhFolder) != null);
                if (calibration == null)
                {
                    notes.Add($"{fold.Name}: no straight walk with its motion capture in {bvhFolder}; not calibrated");
                    continue;
                }
                var watch = System.Diagnostics.Stopwatch.StartNew();
                var models = FoldModels(fold, recordings.Where(r => !fold.IsTest(r.Name)).ToList(), augment, cache, names);
                models.Svm = shipped.Svm;
                models.Blstm = shipped.Blstm;
                double trainSeconds = watch.Elapsed.TotalSeconds;
                var session = CalibrationSession.FromMotionCapture(BvhFile.Load(BvhOf(calibration, bvhFolder)), ankleRate);
                var labelled = session.Labelled();
                var (agreement, contactMs) = Agreement(labelled, calibration);
                watch.Restart();
                WearerProfile feet = null;
                try
                {
                    feet = WearerAdaptation.Fit(models, new[] { labelled }, "style", WearerProfile.FromFootReferences);
                }
                catch (InvalidOperationException e)
                {
                    notes.Add($"{fold.Name}: not fitted with the ankle trackers, scored with the shipped models ({e.Message})");
                }
                double feetSeconds = watch.Elapsed.TotalSeconds;
                var sure = WearerAdaptation.SelfLabel(models, session.Head);
                int sureSteps = sure.Sum(r => PhaseEvents.TruthSteps(r).Count);
                WearerProfile self = null;
                try
                {
                    self = WearerAdaptation.Fit(models, sure, "style", WearerProfile.SelfSupervised);
                }
                catch (InvalidOperationException e)
                {
                    notes.Add($"{fold.Name}: self-supervised not fitted, scored with the shipped models ({e.Message})");
                }
                Console.WriteLine(string.Format(CultureInfo.InvariantCulture,
                    "{0,-14} calibrated on {1} ({2:F1} s, {3} steps; ankle labels agree with the converter's on {4:F1} % of samples, contacts {5:F0} ms apart (median)); self-supervised {6} sure steps; fit {7:F1} s; fold training {8:F0} s",
                    fold.Name, calibration.Name, calibration.Duration, PhaseEvents.TruthSteps(labelled).Count, 100 * agreement, contactMs, sureSteps, feetSeconds, trainSeconds));
                // A walk that cannot be fitted leaves the wearer with the shipped models, as the product does.
                var variantModels = new[] { models, feet?.Apply(models) ?? models, self?.Apply(models) ?? models };
                // Each recording replayed by fresh classifiers; in parallel, as every replay is independent.
                var scored = test.Where(r => r != calibration).AsParallel().AsOrdered().WithDegreeOfParallelism(Math.Max(1, Environment.ProcessorCount))
                    .Select(rec => (rec, metrics: names.SelectMany(clf => Enumerable.Range(0, Variants.Length).Select(v =>
                    {
                        if (variantModels[v] == null) return (clf, v, (GaitMetrics)null);
                        var classifier = variantModels[v].Create(clf, out string warning);
                        return (clf, v, warning != null ? null : ReplayEvaluator.Run(rec, classifier).ClassifierMetrics);
                    })).ToList())).ToList();
                foreach (var (rec, metrics) in scored)
                {
                    bool standing = rec.Samples.All(s => !s.HasTruth || s.Left == GaitPhase.Standing);
                    foreach (var (clf, v, m) in metrics)
                    {
                        if (m == null) continue;
                        var key = (fold.Name, clf, Variants[v]);
                        if (!cells.TryGetValue(key, out var cell)) cells[key] = cell = new Cell();
                        cell.All.Add(m);
                        if (standing) cell.Standing.Add(m);
                    }
                }
                foreach (var clf in names)
                    Console.WriteLine("  " + clf + ": " + string.Join("  ", Variants.Select(v => cells.TryGetValue((fold.Name, clf, v), out var c)
                        ? $"{v} {100 * GaitMetrics.Pool(c.All).MisclassificationRate:F1} %" : $"{v} -")));
            }
            Print(cells, cadence, names);
            foreach (var n in notes) Console.WriteLine("note: " + n);
            return 0;
        }

        static bool IsStraightWalk(string name) => name.StartsWith("bn_wk_", StringComparison.Ordinal) || name.StartsWith("bn1_walk_", StringComparison.Ordinal);

        /// <summary>The BVH a converted recording names in its source line, when it is in the folder.</summary>
        static string BvhOf(Recording r, string folder)
        {
            if (!r.Metadata.TryGetValue("source", out var source)) return null;
            // "repository@commit path/clip.bvh" or a path: the clip's file name is the last word's.
            var words = source.Trim().Split(' ', StringSplitOptions.RemoveEmptyEntries);
            if (words.Length == 0) return null;
            string path = Path.Combine(folder, Path.GetFileName(words[words.Length - 1]));
            return File.Exists(path) ? path : null;
        }

        /// <summary>Share of per-foot samples whose ankle-tracker label equals the converter's, and the median distance between their contacts (ms).</summary>
        static (double Agreement, double ContactMs) Agreement(Recording fromAnkles, Recording converted)
        {
            var contacts = PhaseEvents.TruthContacts(converted);
            var offsets = PhaseEvents.TruthContacts(fromAnkles).Select(c => Math.Abs(PhaseEvents.OffsetFromNearest(contacts, c.Time)) * 1000).ToList();
            return (FootContactLabeller.Agreement(fromAnkles, converted), offsets.Count > 0 ? GaitMetrics.Median(offsets) : double.NaN);
        }

        static GaitModels FoldModels(Fold fold, List<Recording> train, int augment, string cache, List<string> names)
        {
            string dir = cache == null ? null : Path.Combine(cache, TrainCommand.Safe(fold.Name));
            if (dir != null && File.Exists(Path.Combine(dir, GaitModels.ThresholdFile)) && File.Exists(Path.Combine(dir, GaitModels.CorrelationFile)))
                return GaitModels.Load(dir);
            var (models, _, _) = BenchmarkCommand.TrainFold(train, augment, true, true);
            if (dir != null)
            {
                Directory.CreateDirectory(dir);
                models.Threshold.Save(Path.Combine(dir, GaitModels.ThresholdFile));
                models.Correlation.Save(Path.Combine(dir, GaitModels.CorrelationFile));
            }
            return models;
        }

        static void Print(Dictionary<(string style, string clf, string variant), Cell> cells, Dictionary<string, double> cadence, List<string> names)
        {
            var styles = cells.Keys.Select(k => k.style).Distinct().OrderBy(s => cadence.TryGetValue(s, out var p) ? -p : 0).ToList();
            Console.WriteLine();
            Console.WriteLine("Misclassification (classifier output, per foot and sample) of each held-out style's other recordings; styles slowest first (median step);");
            Console.WriteLine("standing shown as walking over its standing recordings (gestures, bows) after the slash. none = uncalibrated, feet = ankle trackers, self = self-supervised.");
            Console.WriteLine($"{"style",-14} {"step_s",6} {"clf",-6} {"none%",14} {"feet%",14} {"d_feet",7} {"self%",14} {"d_self",7}");
            string Cellf(Cell c) => c == null ? "-" : string.Format(CultureInfo.InvariantCulture, "{0:F1}/{1}", 100 * GaitMetrics.Pool(c.All).MisclassificationRate,
                c.Standing.Count == 0 ? "-" : (100 * GaitMetrics.Pool(c.Standing).StandingAsWalking).ToString("F1", CultureInfo.InvariantCulture));
            string Delta(Cell a, Cell b) => a == null || b == null ? "-" : (100 * (GaitMetrics.Pool(b.All).MisclassificationRate - GaitMetrics.Pool(a.All).MisclassificationRate)).ToString("+0.0;-0.0", CultureInfo.InvariantCulture);
            Cell Get(string s, string c, string v) => cells.TryGetValue((s, c, v), out var x) ? x : null;
            foreach (var clf in names)
            {
                foreach (var s in styles)
                {
                    var none = Get(s, clf, "none");
                    if (none == null) continue;
                    Console.WriteLine(string.Format(CultureInfo.InvariantCulture, "{0,-14} {1,6:F3} {2,-6} {3,14} {4,14} {5,7} {6,14} {7,7}", s, cadence.TryGetValue(s, out var p) ? p : double.NaN, clf,
                        Cellf(none), Cellf(Get(s, clf, "feet")), Delta(none, Get(s, clf, "feet")), Cellf(Get(s, clf, "self")), Delta(none, Get(s, clf, "self"))));
                }
                Cell Pooled(string v)
                {
                    var c = new Cell();
                    foreach (var s in styles)
                    {
                        var x = Get(s, clf, v);
                        if (x == null) return null; // a style without this variant: no like-for-like pool
                        c.All.AddRange(x.All);
                        c.Standing.AddRange(x.Standing);
                    }
                    return c;
                }
                var pn = Pooled("none");
                if (pn == null) continue;
                Console.WriteLine(string.Format(CultureInfo.InvariantCulture, "{0,-14} {1,6} {2,-6} {3,14} {4,14} {5,7} {6,14} {7,7}", "pooled", "", clf,
                    Cellf(pn), Cellf(Pooled("feet")), Delta(pn, Pooled("feet")), Cellf(Pooled("self")), Delta(pn, Pooled("self"))));
            }
        }
    }
}
