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

        public static int Run(string[] data, string bvhFolder, string modelFolder, List<string> names, int augment, string cache, double ankleRate, double walkSeconds, string cvModels, string adapt, string styles = null, bool perRecording = false)
        {
            var (feetSettings, selfSettings) = Settings(adapt);
            if (!Directory.Exists(bvhFolder)) throw new UsageException($"no such folder: {bvhFolder}");
            var recordings = Inputs.LoadRecordings(Inputs.Expand(data, "*.csv"), false).Where(r => r.HasTruth).ToList();
            if (recordings.Count == 0) throw new UsageException("no labelled recordings in --data");
            string folder = modelFolder ?? SamplePaths.FindModelsFolder() ?? throw new UsageException("no --models and no package Models/ folder found");
            var shipped = GaitModels.Load(folder);
            var byName = recordings.ToDictionary(r => r.Name);
            var folds = CrossValidation.LeaveOneStyleOut(byName.Keys);
            if (!string.IsNullOrWhiteSpace(styles))
            {
                var wanted = styles.Split(',', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries).ToList();
                var unknown = wanted.Where(w => folds.All(f => f.Name != w)).ToList();
                if (unknown.Count > 0) throw new UsageException($"--styles: no style fold named {string.Join(", ", unknown)} (folds: {string.Join(", ", folds.Select(f => f.Name))})");
                folds = folds.Where(f => wanted.Contains(f.Name)).ToList();
            }
            var cells = new Dictionary<(string style, string clf, string variant), Cell>();
            var notes = new List<string>();
            var cadence = new Dictionary<string, double>();
            Console.WriteLine($"HeadGait calibration benchmark: {recordings.Count} labelled recordings, motion capture from {bvhFolder}, ankle trackers at {ankleRate:0} Hz");
            Console.WriteLine(walkSeconds > 0
                ? $"Calibration walk: the held-out style's straight walks and turns in turn, joined into one session, up to {walkSeconds:F0} s (at most half of the style's forward walks; the rest are scored)"
                : "Calibration walk: the held-out style's first straight walk (one clip)");
            Console.WriteLine(cvModels == null
                ? "SVM and BLSTM: the shipped models, trained on every style (NOT held out); THR and COR trained inside each fold."
                : $"SVM and BLSTM: the style-fold models under {Path.Combine(cvModels, CrossValidation.ByStyle)} (held out), with the fold's walking gate and stance; THR and COR trained inside each fold.");
            if (adapt != null) Console.WriteLine($"Refitted (--adapt {adapt}): ankle trackers {Describe(feetSettings)}; self-supervised {Describe(selfSettings)}");
            foreach (var fold in folds)
            {
                var test = fold.Test.Select(n => byName[n]).OrderBy(r => r.Name, StringComparer.Ordinal).ToList();
                var steps = test.SelectMany(r => PhaseEvents.TruthSteps(r)).Select(s => s.Duration).ToList();
                if (steps.Count == 0) continue;
                cadence[fold.Name] = GaitMetrics.Median(steps);
                var calibration = CalibrationClips(test, bvhFolder, walkSeconds);
                if (calibration.Count == 0)
                {
                    notes.Add($"{fold.Name}: no straight walk with its motion capture in {bvhFolder}; not calibrated");
                    continue;
                }
                var watch = System.Diagnostics.Stopwatch.StartNew();
                var (models, gates, map) = FoldModels(fold, recordings.Where(r => !fold.IsTest(r.Name)).ToList(), augment, cache);
                if (cvModels == null)
                {
                    models.Svm = shipped.Svm;
                    models.Blstm = shipped.Blstm;
                }
                else
                {
                    string dir = Path.Combine(cvModels, CrossValidation.ByStyle, TrainCommand.Safe(fold.Name));
                    var learned = Directory.Exists(dir) ? GaitModels.Load(dir) : null;
                    models.Svm = InFold(learned?.Svm, gates.Learned, map);
                    models.Blstm = InFold(learned?.Blstm, gates.Learned, map);
                    foreach (var clf in names.Where(n => (n == "svm" && models.Svm == null) || (n == "blstm" && models.Blstm == null)))
                        notes.Add($"{fold.Name}: no {clf} fold model under {dir}; {clf} not scored for this style");
                }
                double trainSeconds = watch.Elapsed.TotalSeconds;
                var parts = calibration.Select(r => CalibrationSession.FromMotionCapture(BvhFile.Load(BvhOf(r, bvhFolder)), ankleRate)).ToList();
                var agreements = parts.Select((p, i) => Agreement(p.Labelled(), calibration[i])).ToList();
                var session = CalibrationSession.Join(parts);
                var labelled = session.Labelled();
                watch.Restart();
                WearerProfile feet = null;
                try
                {
                    feet = WearerAdaptation.Fit(models, new[] { labelled }, "style", WearerProfile.FromFootReferences, feetSettings);
                }
                catch (InvalidOperationException e)
                {
                    notes.Add($"{fold.Name}: not fitted with the ankle trackers, scored with the shipped models ({e.Message})");
                }
                double feetSeconds = watch.Elapsed.TotalSeconds;
                var sure = WearerAdaptation.SelfLabel(models, session.Head, selfSettings.LabelWithGateOpen, selfSettings.FillMissedSteps, selfSettings.FillMissedBelowSteps);
                int sureSteps = sure.Sum(r => PhaseEvents.TruthSteps(r).Count);
                WearerProfile self = null;
                try
                {
                    self = WearerAdaptation.Fit(models, sure, "style", WearerProfile.SelfSupervised, selfSettings, selfSettings.StillCheck ? session.Head : null);
                }
                catch (InvalidOperationException e)
                {
                    notes.Add($"{fold.Name}: self-supervised not fitted, scored with the shipped models ({e.Message})");
                }
                Console.WriteLine(string.Format(CultureInfo.InvariantCulture,
                    "{0,-14} calibrated on {1} ({2} clip{3}, {4:F1} s, {5} steps; ankle labels agree with the converter's on {6:F1} % of samples, contacts {7:F0} ms apart (median)); self-supervised {8} sure steps; fit {9:F1} s; fold training {10:F0} s",
                    fold.Name, calibration[0].Name + (calibration.Count > 1 ? " ..." : ""), calibration.Count, calibration.Count > 1 ? "s" : "", calibration.Sum(r => r.Duration),
                    PhaseEvents.TruthSteps(labelled).Count, 100 * agreements.Average(a => a.Agreement), GaitMetrics.Median(agreements.Select(a => a.ContactMs).ToList()), sureSteps, feetSeconds, trainSeconds));
                Console.WriteLine("  fitted: ankle trackers " + Fitted(feet, models) + "; self-supervised " + Fitted(self, models));
                // A walk that cannot be fitted leaves the wearer with the shipped models, as the product does.
                var variantModels = new[] { models, feet?.Apply(models) ?? models, self?.Apply(models) ?? models };
                // Each recording replayed by fresh classifiers; in parallel, as every replay is independent.
                var scored = test.Where(r => !calibration.Contains(r)).AsParallel().AsOrdered().WithDegreeOfParallelism(Math.Max(1, Environment.ProcessorCount))
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
                if (perRecording)
                    foreach (var (rec, metrics) in new[] { labelled }.Select(rec => (rec, metrics: names.SelectMany(clf => Enumerable.Range(0, Variants.Length).Select(v =>
                        (clf, v, variantModels[v].Create(clf, out string warning) is var c && warning == null ? ReplayEvaluator.Run(rec, c).ClassifierMetrics : null))).ToList())).Concat(scored))
                        foreach (var group in metrics.Where(m => m.Item3 != null).GroupBy(m => m.clf))
                            Console.WriteLine($"    {rec.Name,-32} {group.Key,-5} " + string.Join("  ", group.Select(m => string.Format(CultureInfo.InvariantCulture,
                                "{0} {1:F1} % (walking shown standing {2:F1}, beyond adjacent {5:F1}, contacts {3:+0;-0} ms, right foot {4:F0} %, {6} walking samples)", Variants[m.v], 100 * m.Item3.MisclassificationRate,
                                100 * m.Item3.WalkingAsStanding, m.Item3.StepTimingMedianMs, 100 * m.Item3.StepRightFoot, 100 * m.Item3.MisclassificationBeyondAdjacent, m.Item3.WalkingSamples))));
            }
            Print(cells, cadence, names);
            foreach (var n in notes) Console.WriteLine("note: " + n);
            return 0;
        }

        static bool IsStraightWalk(string name) => name.StartsWith("bn_wk_", StringComparison.Ordinal) || name.StartsWith("bn1_walk_", StringComparison.Ordinal);

        static bool IsTurn(string name) => name.StartsWith("bn_tl_", StringComparison.Ordinal) || name.StartsWith("bn_tr_", StringComparison.Ordinal);

        /// <summary>
        /// The held-out style's calibration walk: its straight walks and turns (forward walking with its motion capture) taken
        /// in turn (straight, turn, straight, turn...) until they last <paramref name="seconds"/>; at least one (the first
        /// straight walk: all of it when <paramref name="seconds"/> is 0), at most half of the style's forward walks, so that
        /// the rest of them are scored.
        /// </summary>
        static List<Recording> CalibrationClips(List<Recording> test, string bvhFolder, double seconds)
        {
            var straight = test.Where(r => IsStraightWalk(r.Name) && BvhOf(r, bvhFolder) != null).ToList();
            if (straight.Count == 0) return new List<Recording>();
            var turns = test.Where(r => IsTurn(r.Name) && BvhOf(r, bvhFolder) != null)
                .OrderBy(r => r.Name.Substring(6), StringComparer.Ordinal).ThenBy(r => r.Name, StringComparer.Ordinal).ToList(); // left and right turns in turn
            var order = new List<Recording>();
            for (int i = 0; i < Math.Max(straight.Count, turns.Count); i++)
            {
                if (i < straight.Count) order.Add(straight[i]);
                if (i < turns.Count) order.Add(turns[i]);
            }
            int most = Math.Max(1, (straight.Count + turns.Count) / 2);
            var walk = new List<Recording> { order[0] };
            double total = order[0].Duration;
            for (int i = 1; i < order.Count && walk.Count < most && total < seconds; i++)
            {
                walk.Add(order[i]);
                total += order[i].Duration;
            }
            return walk;
        }

        /// <summary>The fold's learned model with the fold's walking gate and stance written in (fold models may predate them or hold ones from other data).</summary>
        static ModelFile InFold(ModelFile model, WalkingGate gate, PhaseMap map)
        {
            if (model == null) return null;
            var copy = ModelFile.Parse(model.ToBytes(), model.Source);
            if (gate == null) copy.Values.Remove(WalkingGate.ModelKey);
            else copy.Set(WalkingGate.ModelKey, gate.Serialize());
            // The model's own onsets (its classes) with the fold's stance slope, as the benchmark's AdoptStance.
            copy.Set("phase_map", PhaseMap.Parse(copy.Need("phase_map")).WithStance(map.StanceSlope, map.ReferenceStridePeriod).Serialize());
            return copy;
        }

        /// <summary>
        /// The refitted parts, from <c>--adapt</c>: a comma-separated list applied on top of the defaults for each source
        /// (<see cref="AdaptationSettings.For"/>): cor-template, cor-threshold, cor-lead, cor-gate (COR's gate opened where it pays on the walk), thr, gates, learned-gate, learned-gain, learned-refit, learned-channels, learned-search,
        /// open-labels (self-supervised labels read with COR's gate open), fill-missed (a step COR missed in a steady rhythm filled in), cor-fuller (of COR's candidates that pay, the most refitted), each optionally prefixed no- to turn it off; prior=STEPS (THR's shrinkage), margin=SHARE (NaN: keep every part), short-margin=SHARE (COR's margin on a walk of under threshold-steps; NaN: margin), cor-gate-cap=LOGODDS (most cor-gate opens COR's gate), own-templates=N (the wearer's mean steps from a walk of threshold-steps or more), fill-below=N (self-supervised: missed steps filled in only below N sure steps; 0: always), template-steps=N (the wearer's own step from N steps), threshold-steps=N (COR's threshold refitted from N steps), gate-cap=LOGODDS (most a detector's gate opens), learned-gate-cap=LOGODDS (most the learned models' gate opens), search-cap=SHIFT (most the learned refit's search moves an output shift);
        /// self: or feet: before an item applies it to that source only.
        /// </summary>
        internal static (AdaptationSettings Feet, AdaptationSettings Self) Settings(string adapt)
        {
            var feet = AdaptationSettings.For(WearerProfile.FromFootReferences);
            var self = AdaptationSettings.For(WearerProfile.SelfSupervised);
            if (string.IsNullOrWhiteSpace(adapt)) return (feet, self);
            foreach (var raw in adapt.Split(',', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries))
            {
                string item = raw;
                var targets = new List<AdaptationSettings> { feet, self };
                if (item.StartsWith("self:", StringComparison.Ordinal)) { targets.Remove(feet); item = item.Substring(5); }
                else if (item.StartsWith("feet:", StringComparison.Ordinal)) { targets.Remove(self); item = item.Substring(5); }
                bool on = !item.StartsWith("no-", StringComparison.Ordinal);
                string key = on ? item : item.Substring(3);
                foreach (var a in targets)
                {
                    if (key.StartsWith("prior=", StringComparison.Ordinal)) a.ThresholdPriorSteps = Number(key.Substring(6));
                    else if (key.StartsWith("margin=", StringComparison.Ordinal)) a.AcceptMargin = Number(key.Substring(7));
                    else if (key.StartsWith("gate-cap=", StringComparison.Ordinal)) a.MaxGateShift = Number(key.Substring(9));
                    else if (key.StartsWith("learned-gate-cap=", StringComparison.Ordinal)) a.MaxLearnedGateShift = Number(key.Substring(17));
                    else if (key.StartsWith("shift-cap=", StringComparison.Ordinal)) a.LearnedShiftCap = Number(key.Substring(10));
                    else if (key.StartsWith("shift-prior=", StringComparison.Ordinal)) a.LearnedShiftPrior = Number(key.Substring(12));
                    else if (key.StartsWith("search-cap=", StringComparison.Ordinal)) a.LearnedSearchCap = Number(key.Substring(11));
                    else if (key.StartsWith("template-steps=", StringComparison.Ordinal)) a.CorTemplateSteps = (int)Math.Min(int.MaxValue, Number(key.Substring(15)));
                    else if (key.StartsWith("fill-below=", StringComparison.Ordinal)) a.FillMissedBelowSteps = (int)Math.Min(int.MaxValue, Number(key.Substring(11)));
                    else if (key.StartsWith("own-templates=", StringComparison.Ordinal)) a.CorOwnTemplates = (int)Math.Min(16, Number(key.Substring(14)));
                    else if (key.StartsWith("still-slack=", StringComparison.Ordinal)) a.StillSlack = Number(key.Substring(12));
                    else if (key.StartsWith("short-margin=", StringComparison.Ordinal)) a.ShortWalkMargin = Number(key.Substring(13));
                    else if (key.StartsWith("cor-gate-cap=", StringComparison.Ordinal)) a.MaxCorGateShift = Number(key.Substring(13));
                    else if (key.StartsWith("cor-margin=", StringComparison.Ordinal)) a.CorAcceptMargin = Number(key.Substring(11));
                    else if (key.StartsWith("threshold-steps=", StringComparison.Ordinal)) a.CorThresholdSteps = (int)Math.Min(int.MaxValue, Number(key.Substring(16)));
                    else if (key.StartsWith("time-scale-share=", StringComparison.Ordinal)) a.LearnedTimeScaleShare = Number(key.Substring(17));
                    else
                        switch (key)
                        {
                            case "cor-template": a.CorTemplate = on; break;
                            case "cor-threshold": a.CorThreshold = on; break;
                            case "cor-lead": a.CorLead = on; break;
                            case "thr": a.Threshold = on; break;
                            case "gates": a.DetectorGates = on; break;
                            case "cor-gate": a.CorGate = on; break;
                            case "cor-gate-walking": a.CorGateWhileWalking = on; break;
                            case "learned-gate": a.LearnedGate = on; break;
                            case "learned-gain": a.LearnedGain = on; break;
                            case "learned-refit": a.LearnedRefit = on; break;
                            case "learned-channels": a.LearnedChannelGains = on; break;
                            case "svm-channels": a.SvmChannelGains = on; break;
                            case "learned-search": a.LearnedShiftSearch = on; break;
                            case "learned-time-scale": a.LearnedTimeScale = on; break;
                            case "time-scale-up": a.LearnedTimeScaleUpward = on; break;
                            case "open-labels": a.LabelWithGateOpen = on; break;
                            case "fill-missed": a.FillMissedSteps = on; break;
                            case "cor-fuller": a.PreferFullerCorRefit = on; break;
                            case "still-check": a.StillCheck = on; break;
                            default: throw new UsageException($"--adapt: unknown part '{raw}' (cor-template, cor-threshold, cor-lead, cor-gate, thr, gates, learned-gate, learned-gain, learned-refit, learned-channels, svm-channels, learned-search, learned-time-scale, time-scale-up, open-labels, fill-missed, cor-fuller, still-check, still-slack=SECONDS, time-scale-share=SHARE, prior=STEPS, margin=SHARE, short-margin=SHARE, cor-margin=SHARE, cor-gate-cap=LOGODDS, own-templates=N, fill-below=N, template-steps=N, threshold-steps=N, gate-cap=LOGODDS, learned-gate-cap=LOGODDS, shift-cap=SHIFT, shift-prior=WEIGHT, search-cap=SHIFT; no- turns one off; self: or feet: for one source)");
                        }
                }
            }
            return (feet, self);

            static double Number(string text) => double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out var v) && !double.IsInfinity(v) && !(v < 0)
                ? v : throw new UsageException($"--adapt: '{text}' is not a number of 0 or more (or NaN for margin)");
        }

        internal static string Describe(AdaptationSettings a) => string.Join(" ", new[]
        {
            a.CorTemplate ? "cor-template" : null, a.CorThreshold ? "cor-threshold" : a.CorThresholdSteps < int.MaxValue ? $"cor-threshold from {a.CorThresholdSteps} steps" : null, a.CorLead ? "cor-lead" : null,
            a.Threshold ? $"thr(prior {a.ThresholdPriorSteps:0})" : null, a.DetectorGates ? "gates" : null, a.CorGate ? $"cor-gate ({(a.CorGateWhileWalking ? "walks in progress, " : "")}at most {a.MaxCorGateShift:0.##})" : null, a.LearnedGate ? "learned-gate" : null, a.DetectorGates || a.LearnedGate ? $"(gates opened by at most {a.MaxGateShift:0.##}, the learned models' {a.MaxLearnedGateShift:0.##})" : null,
            a.LearnedGain ? "learned-gain" : null, a.LearnedRefit ? "learned-refit" : null, a.LearnedChannelGains ? "learned-channels" : a.LearnedRefit && a.SvmChannelGains ? "svm-channels" : null, a.LearnedTimeScale ? $"learned-time-scale ({(a.LearnedTimeScaleUpward ? "" : "quicker wearers only, ")}share {a.LearnedTimeScaleShare:0.##})" : null, a.LearnedRefit && a.LearnedShiftSearch ? $"learned-search (cap {a.LearnedSearchCap:0.##})" : null, a.LabelWithGateOpen ? "open-labels" : null, a.FillMissedSteps ? (a.FillMissedBelowSteps > 0 ? $"fill-missed (below {a.FillMissedBelowSteps} sure steps)" : "fill-missed") : null, a.PreferFullerCorRefit ? "cor-fuller" : null, a.StillCheck ? $"still-check (slack {a.StillSlack:0.##} s)" : null, $"own-templates {a.CorOwnTemplates}", $"margin {a.AcceptMargin:0.###}", $"(COR {a.CorAcceptMargin:0.###}{(double.IsNaN(a.ShortWalkMargin) ? "" : $", {a.ShortWalkMargin:0.###} on a walk of under {a.CorThresholdSteps} steps")})", a.LearnedRefit ? $"(output shifts at most {a.LearnedShiftCap:0.##}, prior {a.LearnedShiftPrior:0.###})" : null,
        }.Where(x => x != null));

        /// <summary>What a profile changed against the fold's models, in a few words.</summary>
        static string Fitted(WearerProfile p, GaitModels models)
        {
            if (p == null) return "not fitted";
            var ci = CultureInfo.InvariantCulture;
            string refits = string.Concat(p.LearnedAdjustments.Select(a => string.Format(ci, ", {0} channel gains {1}, {2} output biases moved (largest {3:F2})",
                a.Kind, string.Join("/", a.ChannelGain.Select(g => g.ToString("0.##", ci))), a.BiasShift.Count(b => b != 0), a.BiasShift.Select(Math.Abs).DefaultIfEmpty(0).Max())));
            return string.Format(ci, "{0} steps: COR {1} (threshold {2:F2}, lead {3:F3} s{8}), THR {4}, learned gain {5:F2}{6}{7}", p.Steps,
                p.Correlation.Templates.Count > models.Correlation.Templates.Count ? "own step" : "as trained", p.Correlation.MinCorrelation, p.Correlation.ClockLead,
                p.Threshold.Serialize() == models.Threshold.Serialize() ? "as trained" : string.Format(ci, "floor {0:F2} (trained {1:F2})", p.Threshold.Floor, models.Threshold.Floor),
                p.LearnedGain, (p.LearnedGateShift != 0 ? string.Format(ci, ", learned gate +{0:F2}", p.LearnedGateShift) : "") + (p.LearnedTimeScale != 1 ? string.Format(ci, ", learned time scale {0:F2}", p.LearnedTimeScale) : ""), refits,
                p.Correlation.WalkingGateHoldShift != 0 ? string.Format(ci, ", gate +{0:F2} for walks in progress", p.Correlation.WalkingGateHoldShift) : "");
        }

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

        /// <summary>THR and COR trained on the fold's training styles, with the fold's gates and phase map (from the cache when it holds them).</summary>
        static (GaitModels Models, (WalkingGate Threshold, WalkingGate Correlation, WalkingGate Learned) Gates, PhaseMap Map) FoldModels(Fold fold, List<Recording> train, int augment, string cache)
            => cache == null ? BenchmarkCommand.TrainFold(train, augment, true, true)
                : BenchmarkCommand.CachedFold(Path.Combine(cache, TrainCommand.Safe(fold.Name)), $"augment {augment}; glasses gate windows none", () => BenchmarkCommand.TrainFold(train, augment, true, true));

        static void Print(Dictionary<(string style, string clf, string variant), Cell> cells, Dictionary<string, double> cadence, List<string> names)
        {
            var styles = cells.Keys.Select(k => k.style).Distinct().OrderBy(s => cadence.TryGetValue(s, out var p) ? -p : 0).ToList();
            Console.WriteLine();
            Console.WriteLine("Misclassification (classifier output, per foot and sample) of each held-out style's other recordings; styles slowest first (median step);");
            Console.WriteLine("standing shown as walking over its standing recordings (gestures, bows) after the slash. none = uncalibrated, feet = ankle trackers, self = self-supervised.");
            Console.WriteLine($"{"style",-14} {"step_s",6} {"clf",-6} {"none%",14} {"feet%",14} {"d_feet",7} {"self%",14} {"d_self",7}");
            string Cellf(Cell c) => c == null ? "-" : string.Format(CultureInfo.InvariantCulture, "{0:F1}/{1}", 100 * GaitMetrics.Pool(c.All).MisclassificationRate,
                c.Standing.Count == 0 ? "-" : (100 * GaitMetrics.Pool(c.Standing).StandingAsWalking).ToString("F1", CultureInfo.InvariantCulture));
            string Delta(Cell a, Cell b) => a == null || b == null ? "-" : (100 * (GaitMetrics.Pool(b.All).MisclassificationRate - GaitMetrics.Pool(a.All).MisclassificationRate)).ToString("+0.00;-0.00;+0.00", CultureInfo.InvariantCulture);
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
            // Where the errors are: walking the classifier shows as standing (the walking gate's and the model's standing
            // decision), against the rest (the wrong phase while walking).
            Console.WriteLine();
            Console.WriteLine("Walking shown as standing (share of walking samples), none / feet / self:");
            string Shown(Cell c) => c == null ? "-" : (100 * GaitMetrics.Pool(c.All).WalkingAsStanding).ToString("F1", CultureInfo.InvariantCulture);
            foreach (var clf in names)
                Console.WriteLine($"  {clf}: " + string.Join("  ", styles.Where(st => Get(st, clf, "none") != null)
                    .Select(st => $"{st} {Shown(Get(st, clf, "none"))}/{Shown(Get(st, clf, "feet"))}/{Shown(Get(st, clf, "self"))}")));
        }
    }
}
