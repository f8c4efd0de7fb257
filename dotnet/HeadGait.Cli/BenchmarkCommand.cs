using System;
using System.Collections.Generic;
using System.CommandLine;
using System.IO;
using System.Linq;
using HeadGait.Synthetic;
using HeadGait.Training;

namespace HeadGait.Cli
{
    /// <summary>
    /// headgait benchmark: cross-validation on labelled recordings. THR and COR are trained inside each fold here;
    /// SVM and BLSTM are read from the fold models `headgait train --cv` wrote (MODELS/cv/SCHEME/FOLD/).
    /// </summary>
    static class BenchmarkCommand
    {
        public static Command Build()
        {
            var data = new Option<string[]>("--data") { Description = "labelled CSV recordings or folders of them (e.g. ../shared/data/real-train)", Required = true, AllowMultipleArgumentsPerToken = true };
            var models = new Option<string>("--models") { Description = "trained models whose cost is measured (default: the package's Models/)" };
            var cvModels = new Option<string>("--cv-models") { Description = "the SVM and BLSTM fold models `headgait train --cv` wrote (default: training/cv-models)" };
            var cv = new Option<string>("--cv") { Description = "cross-validation: style (leave one style out), file (5 folds of files), style,file, or none (cost only)", DefaultValueFactory = _ => "style,file" };
            var classifier = new Option<string>("--classifier") { Description = "thr, cor, svm, blstm, a comma-separated list or all", DefaultValueFactory = _ => "all" };
            var augment = new Option<int>("--augment") { Description = "augmented copies per training recording for THR and COR (as `train`)", DefaultValueFactory = _ => GaitTraining.DefaultAugmentedCopies };
            var perFold = new Option<bool>("--per-fold") { Description = "also print each fold's rows" };
            var pose = new Option<string[]>("--pose") { Description = "head-pose recordings of the same clips (e.g. ../shared/data/pose-train): each fold's classifiers also score the pose recordings of its held-out clips through the XR pose path", AllowMultipleArgumentsPerToken = true };
            var perRecording = new Option<string>("--per-recording") { Description = "also write every held-out recording's scores to this CSV (which recordings fail, and how), the variants' and pose path's too" };
            var earLike = new Option<bool>("--ear-like") { Description = $"also score each held-out clip with its sideways and forward acceleration halved and {100 * (RecordingAugmentation.EarLikeStretch - 1):F0} % slower, as a real ear-worn sensor and slower walkers differ from mocap-derived signals" };
            var slow = new Option<bool>("--slow") { Description = $"also score each held-out clip {100 * (RecordingAugmentation.SlowStretch - 1):F0} % slower, every movement scaled by 1/{RecordingAugmentation.SlowStretch}^2 and sideways and forward also by {RecordingAugmentation.SlowSidewaysGain}: a calmer, slower walker than any the classifiers trained on" };
            var tilted = new Option<bool>("--tilted") { Description = $"also score each held-out clip as a sensor pitched {RecordingAugmentation.TiltedPitchDegrees:F0} degrees down and rolled {RecordingAugmentation.TiltedRollDegrees:F0} degrees would give it (a headset worn tilted, a head held looking down)" };
            var turned = new Option<bool>("--turned") { Description = $"also score each held-out clip as a head turned {RecordingAugmentation.TurnedYawDegrees:F0} degrees to the left of where it walks would give it (looking around while walking)" };
            var jolted = new Option<bool>("--jolted") { Description = $"also score each held-out clip with a {RecordingAugmentation.JoltHz:F0} Hz jolt of {RecordingAugmentation.JoltPeak} m/s^2 at every initial contact and {RecordingAugmentation.JoltNoise} m/s^2 noise: content above the mocap's 12 Hz that a real head-worn sensor has (made-up sizes)" };
            var sensorRate = new Option<double?>("--sensor-rate") { Description = "also score each held-out clip as a sensor sampling at this many Hz gives it (e.g. 50: the preprocessor resamples it to 100 Hz)" };
            var startStop = new Option<bool>("--start-stop") { Description = "also score each held-out walking clip made into a walk that starts and stops (standing, the walk growing in from a toe-off and fading out to a contact, standing): how late each classifier starts and stops on people's steps" };
            var real = new Option<string[]>("--real") { Description = "unlabelled real recordings with '# activity=' headers that every fold's walking gates also learn from, as `train --real` (e.g. ../shared/data/glasses-train)", AllowMultipleArgumentsPerToken = true };
            var cache = new Option<string>("--fold-cache") { Description = "keep each fold's THR and COR here and reuse them while this build and the same --augment and --real trained them (else trained again); THR's and COR's runtime settings are read at scoring" };
            var command = new Command("benchmark", "Cross-validates all four classifiers on labelled recordings and prints accuracy, step timing and CPU cost.")
            {
                data, models, cvModels, cv, classifier, augment, perFold, pose, perRecording, earLike, slow, tilted, turned, jolted, sensorRate, startStop, real, cache,
            };
            command.SetAction(parse => Run(parse.GetValue(data), parse.GetValue(models), parse.GetValue(cvModels) ?? TrainCommand.DefaultCvModels(),
                parse.GetValue(cv), parse.GetValue(classifier), parse.GetValue(augment), parse.GetValue(perFold), parse.GetValue(pose), parse.GetValue(perRecording), parse.GetValue(earLike), parse.GetValue(slow), parse.GetValue(tilted), parse.GetValue(turned), parse.GetValue(jolted), parse.GetValue(sensorRate), parse.GetValue(startStop), parse.GetValue(real), parse.GetValue(cache)));
            return command;
        }

        static int Run(string[] data, string modelFolder, string cvFolder, string schemes, string classifierList, int augment, bool perFold, string[] posePaths, string perRecordingCsv, bool earLike, bool slow, bool tilted, bool turned, bool jolted, double? sensorRate, bool startStop, string[] realPaths, string cache)
        {
            // Held-out clips changed as a real sensor or walk might differ from these recordings: each is scored by the same fold's classifiers.
            var variants = new List<(string Label, string Caption, Func<Recording, Recording> Make)>();
            if (earLike) variants.Add(("ear-like", $"made ear-like (sideways and forward acceleration halved, {100 * (RecordingAugmentation.EarLikeStretch - 1):F0} % slower)", RecordingAugmentation.EarLike));
            if (slow) variants.Add(("slow", $"made slow ({100 * (RecordingAugmentation.SlowStretch - 1):F0} % slower, calmer: movement over {RecordingAugmentation.SlowStretch}^2, sideways and forward also x{RecordingAugmentation.SlowSidewaysGain})", RecordingAugmentation.Slow));
            if (turned) variants.Add(("turned", $"as a head turned {RecordingAugmentation.TurnedYawDegrees:F0} degrees to the left of where it walks gives them", r => RecordingAugmentation.Turned(r)));
            if (tilted) variants.Add(("tilted", $"as a sensor pitched {RecordingAugmentation.TiltedPitchDegrees:F0} degrees down and rolled {RecordingAugmentation.TiltedRollDegrees:F0} degrees gives them", r => RecordingAugmentation.Tilted(r)));
            if (jolted) variants.Add(("jolted", $"with a {RecordingAugmentation.JoltHz:F0} Hz jolt at each contact and sensor noise (content above 12 Hz)", RecordingAugmentation.Jolted));
            if (sensorRate.HasValue)
            {
                double rate = OptionValues.Number(sensorRate.Value, "--sensor-rate", 1, 2000);
                string hz = rate.ToString("0.#", System.Globalization.CultureInfo.InvariantCulture) + " Hz";
                variants.Add((hz, $"as a sensor sampling at {hz} gives them", r => RecordingAugmentation.AtRate(r, rate)));
            }
            // Seeded by the clip's name, so every fold and classifier scores the same made-up starts and stops.
            if (startStop) variants.Add(("start-stop", "made into walks that start and stop (walking clips only)",
                r => RecordingAugmentation.StartingAndStopping(r, new DeterministicRandom(DeterministicRandom.SeedFrom(r.Name)))));
            var schemeList = OptionValues.Schemes(schemes, "--cv", allowNone: true);
            OptionValues.Count(augment, "--augment", 0, GaitTraining.MaxAugmentedCopies);
            OptionValues.Folder(modelFolder, "--models");
            OptionValues.Path(perRecordingCsv, "--per-recording");
            var names = Classifiers.Parse(classifierList);
            var perRecordingRows = new List<RecordingScoresCsv.Row>();
            var realGateWindows = realPaths == null || realPaths.Length == 0 ? null
                : GaitTraining.GateWindows.Of(GaitTraining.RealGateRecordings(Inputs.LoadRecordings(Inputs.Expand(realPaths, "*.csv"), false)));
            var poses = posePaths == null || posePaths.Length == 0 ? new List<Recording>() : Inputs.LoadRecordings(Inputs.Expand(posePaths, "*.csv"), false).Where(r => r.HasTruth).ToList();
            var recordings = Inputs.LoadRecordings(Inputs.Expand(data, "*.csv"), false).Where(r => r.HasTruth).ToList();
            if (recordings.Count == 0) throw new UsageException("no labelled recordings in --data");
            string folder = modelFolder ?? SamplePaths.FindModelsFolder() ?? throw new UsageException("no --models and no package Models/ folder found");
            var byName = recordings.ToDictionary(r => r.Name);
            Console.WriteLine($"HeadGait benchmark: {recordings.Count} labelled recordings from {string.Join(", ", data)}");
            foreach (var scheme in schemeList)
            {
                if (scheme == "none") continue;
                var folds = CrossValidation.Make(scheme, byName.Keys);
                using var progress = new Progress($"benchmark {scheme} CV", folds.Count * names.Count);
                var pooled = names.ToDictionary(n => n, n => new List<ReplayResult>());
                var pooledPose = names.ToDictionary(n => n, n => new List<ReplayResult>());
                var pooledVariant = variants.Select(_ => names.ToDictionary(n => n, n => new List<ReplayResult>())).ToList();
                var foldRows = new List<(string fold, string clf, List<ReplayResult> results)>();
                var missing = new List<string>();
                foreach (var fold in folds)
                {
                    var test = fold.Test.Select(n => byName[n]).ToList();
                    var variantTests = variants.Select(v => test.Select(v.Make).Where(r => r != null).ToList()).ToList();
                    var train = recordings.Where(r => !fold.IsTest(r.Name)).ToList();
                    if (train.Count == 0 || test.Count == 0) continue;
                    var (foldModels, gates, map) = cache == null
                        ? TrainFold(train, augment, FoldTrainsThreshold(names), names.Contains("cor"), realGateWindows)
                        : CachedFold(Path.Combine(cache, scheme, TrainCommand.Safe(fold.Name)), $"augment {augment}; glasses gate windows {(realGateWindows == null ? "none" : "yes")}", () => TrainFold(train, augment, true, true, realGateWindows));
                    string learnedDir = Path.Combine(cvFolder, scheme, TrainCommand.Safe(fold.Name));
                    var learned = Directory.Exists(learnedDir) ? GaitModels.Load(learnedDir) : null;
                    foldModels.Svm = learned?.Svm;
                    foldModels.Blstm = learned?.Blstm;
                    foreach (var name in names)
                    {
                        if ((name.StartsWith("svm") && foldModels.Svm == null) || (name.StartsWith("blstm") && foldModels.Blstm == null))
                        {
                            missing.Add($"{name} {fold.Name}");
                            continue;
                        }
                        // Each held-out recording replayed by a fresh classifier of this fold; every score also goes to the per-recording rows.
                        List<ReplayResult> Score(IEnumerable<Recording> recordings, string variant)
                        {
                            var scored = recordings.Select(r => ReplayEvaluator.Run(r, InFold(foldModels.Create(name, out _), gates.Learned, map))).ToList();
                            perRecordingRows.AddRange(scored.Select(r => new RecordingScoresCsv.Row { Scheme = scheme, Fold = fold.Name, Variant = variant, Result = r }));
                            return scored;
                        }
                        progress.Step($"{fold.Name} {name}");
                        var results = Score(test, null);
                        pooled[name].AddRange(results);
                        foldRows.Add((fold.Name, results[0].Classifier, results));
                        pooledPose[name].AddRange(Score(poses.Where(p => fold.IsTest(CrossValidation.ClipOf(p.Name))), "pose"));
                        for (int v = 0; v < variants.Count; v++)
                            pooledVariant[v][name].AddRange(Score(variantTests[v], variants[v].Label));
                    }
                }
                Console.WriteLine();
                Console.WriteLine(scheme == CrossValidation.ByStyle
                    ? $"Leave one style out ({folds.Count} folds: {string.Join(", ", folds.Select(f => f.Name))}); each style is scored by classifiers that never saw it"
                    : $"Grouped {folds.Count}-fold cross-validation over files");
                if (missing.Count > 0)
                    Console.WriteLine($"not evaluated (no fold model under {Path.Combine(cvFolder, scheme)}; run `headgait train --cv {scheme}`): {string.Join(", ", missing.Take(12))}{(missing.Count > 12 ? ", ..." : "")}");
                Report.PhaseHeader();
                if (perFold) foreach (var row in foldRows) Report.PhaseRow(row.fold, row.clf, row.results);
                foreach (var name in names.Where(n => pooled[n].Count > 0)) Report.PhaseRow($"{scheme} CV pooled", pooled[name][0].Classifier, pooled[name]);
                Console.WriteLine();
                Report.StepHeader();
                if (perFold) foreach (var row in foldRows) Report.StepRows(row.fold, row.clf, row.results);
                foreach (var name in names.Where(n => pooled[n].Count > 0)) Report.StepRows($"{scheme} CV pooled", pooled[name][0].Classifier, pooled[name]);
                if (poses.Count > 0)
                {
                    Console.WriteLine();
                    Console.WriteLine($"The same folds on {pooledPose.Values.Max(l => l.Count)} head-pose recordings of held-out clips, through the XR pose path (tracked pose differentiated twice):");
                    Report.PhaseHeader();
                    foreach (var name in names.Where(n => pooledPose[n].Count > 0))
                        foreach (var rate in pooledPose[name].GroupBy(r => RateOf(r.Recording)).OrderBy(g => g.Key))
                            Report.PhaseRow($"pose {rate.Key}", rate.First().Classifier, rate.ToList());
                    foreach (var name in names.Where(n => pooledPose[n].Count > 0)) Report.PhaseRow($"pose {scheme} pooled", pooledPose[name][0].Classifier, pooledPose[name]);
                    // The accelerometer path on exactly the clips the pose recordings come from, for a like-for-like comparison.
                    var clips = new HashSet<string>(poses.Select(p => CrossValidation.ClipOf(p.Name)));
                    foreach (var name in names.Where(n => pooledPose[n].Count > 0))
                        Report.PhaseRow($"accel same clips", pooled[name][0].Classifier, pooled[name].Where(r => clips.Contains(r.Recording)).ToList());
                    Console.WriteLine();
                    Report.StepHeader();
                    foreach (var name in names.Where(n => pooledPose[n].Count > 0)) Report.StepRows($"pose {scheme} pooled", pooledPose[name][0].Classifier, pooledPose[name]);
                }
                for (int v = 0; v < variants.Count; v++)
                {
                    var variant = pooledVariant[v];
                    string label = $"{variants[v].Label} {scheme}";
                    Console.WriteLine();
                    Console.WriteLine($"The same folds on the held-out clips {variants[v].Caption} (rows above: as recorded):");
                    Report.PhaseHeader();
                    foreach (var name in names.Where(n => variant[n].Count > 0)) Report.PhaseRow(label, variant[name][0].Classifier, variant[name]);
                    Console.WriteLine();
                    Report.StepHeader();
                    foreach (var name in names.Where(n => variant[n].Count > 0)) Report.StepRows(label, variant[name][0].Classifier, variant[name]);
                }
            }
            if (perRecordingCsv != null)
            {
                AtomicFile.WriteText(perRecordingCsv, w => RecordingScoresCsv.Write(w, perRecordingRows));
                Console.WriteLine($"\nPer-recording scores: {perRecordingCsv}");
            }
            Console.WriteLine();
            Report.Legend();
            Console.WriteLine();
            PrintCost(folder, names, recordings);
            return 0;
        }

        /// <summary>THR and COR (as asked) trained on a fold's training recordings as `headgait train` does, with every classifier's walking gate and the phase map.</summary>
        /// <summary>THR and COR trained on a fold's recordings as `headgait train` does, every classifier's walking gate with them
        /// (also on <paramref name="realGateWindows"/>, unlabelled real recordings' windows, where given).</summary>
        /// <summary>
        /// Whether a fold needs its own THR for <paramref name="names"/>: THR itself, and the SVM and BLSTM, whose step clock runs
        /// on the fold's THR as the shipped ones run on the shipped THR (<see cref="GaitModels.SvmOf"/>). Without it a run of the
        /// learned classifiers alone gave them THR's defaults (style CV, SVM: standing with gestures shown as walking 0.9 % alone,
        /// 1.0 % beside THR).
        /// </summary>
        internal static bool FoldTrainsThreshold(IEnumerable<string> names) => names.Any(n => n == "thr" || n.StartsWith("svm") || n.StartsWith("blstm"));

        internal static (GaitModels Models, (WalkingGate Threshold, WalkingGate Correlation, WalkingGate Learned) Gates, PhaseMap Map) TrainFold(
            List<Recording> train, int augment, bool thr, bool cor, GaitTraining.GateWindows realGateWindows = null)
        {
            var map = PhaseMapTraining.Learn(train);
            var augmented = GaitTraining.WithAugmentation(train, augment);
            var models = new GaitModels();
            var gates = GaitTraining.GatesFrom(GaitTraining.GateWindows.Of(GaitTraining.WithCalmCopies(augmented)), realGateWindows);
            if (thr) models.Threshold = GaitTraining.TrainThreshold(augmented, map, gates.Threshold);
            if (cor) models.Correlation = GaitTraining.TrainCorrelation(augmented, map, gates.Correlation);
            return (models, gates, map);
        }

        /// <summary>
        /// A fold's THR and COR, gates and phase map from <paramref name="dir"/> when it holds them and they were trained by
        /// this build of the core with the same <paramref name="options"/> (<see cref="FoldCacheStamp"/>), else trained by
        /// <paramref name="train"/> (THR and COR both) and kept there, the stamp written last: the runs that change only how
        /// the classifiers run score the same fold models without training them again, and a cache another build trained
        /// (its fold models can differ: COR's clock lead moved with its replaced contacts) is trained again, not read.
        /// </summary>
        internal static (GaitModels Models, (WalkingGate Threshold, WalkingGate Correlation, WalkingGate Learned) Gates, PhaseMap Map) CachedFold(
            string dir, string options, Func<(GaitModels Models, (WalkingGate Threshold, WalkingGate Correlation, WalkingGate Learned) Gates, PhaseMap Map)> train)
        {
            string gateFile = Path.Combine(dir, "learned-gate.txt"), mapFile = Path.Combine(dir, "phase-map.txt"), stampFile = Path.Combine(dir, FoldCacheStampFile);
            string stamp = FoldCacheStamp(options);
            bool complete = File.Exists(Path.Combine(dir, GaitModels.ThresholdFile)) && File.Exists(Path.Combine(dir, GaitModels.CorrelationFile)) && File.Exists(gateFile) && File.Exists(mapFile);
            if (complete && File.Exists(stampFile) && File.ReadAllText(stampFile).Trim() == stamp)
            {
                var cached = GaitModels.Load(dir);
                string gateText = File.ReadAllText(gateFile).Trim();
                var learnedGate = gateText.Length == 0 ? null : WalkingGate.Parse(gateText);
                return (cached, (cached.Threshold.Gate, cached.Correlation.Gate, learnedGate), PhaseMap.Parse(File.ReadAllText(mapFile).Trim()));
            }
            if (complete) Console.Error.WriteLine($"note: the fold cache {dir} was trained by another build or other options; training it again");
            var trained = train();
            Directory.CreateDirectory(dir);
            File.Delete(stampFile);
            trained.Models.Threshold.Save(Path.Combine(dir, GaitModels.ThresholdFile));
            trained.Models.Correlation.Save(Path.Combine(dir, GaitModels.CorrelationFile));
            File.WriteAllText(gateFile, trained.Gates.Learned?.Serialize() ?? "");
            File.WriteAllText(mapFile, trained.Map.Serialize());
            File.WriteAllText(stampFile, stamp);
            return trained;
        }

        /// <summary>The file in a fold cache that says what trained it (<see cref="FoldCacheStamp"/>).</summary>
        internal const string FoldCacheStampFile = "trained-by.txt";

        /// <summary>What trains a fold cache: this build of the core (its module version id, which a deterministic build changes only with the code) and the training options.</summary>
        internal static string FoldCacheStamp(string options) => $"core {typeof(GaitModels).Assembly.ManifestModule.ModuleVersionId:N}; {options}";

        /// <summary>A learned classifier with the fold's own gate and stance slope (fold models may predate them or hold ones from other data).</summary>
        static IGaitClassifier InFold(IGaitClassifier c, WalkingGate gate, PhaseMap map)
        {
            if (c is LearnedClassifier learned)
            {
                learned.Gate = gate;
                learned.AdoptStance(map);
            }
            return c;
        }

        static string RateOf(string recording)
        {
            int us = recording.LastIndexOf('_');
            return us >= 0 && recording.EndsWith("hz", StringComparison.Ordinal) ? recording.Substring(us + 1) : "?";
        }

        /// <summary>CPU time and allocation of each classifier with the models in the folder, on walking recordings.</summary>
        static void PrintCost(string folder, List<string> names, List<Recording> recordings)
        {
            var models = GaitModels.Load(folder);
            var walking = recordings.Where(r => r.Samples.Count > 300 && r.Samples.All(s => !s.HasTruth || s.Left != GaitPhase.Standing)).Take(40).ToList();
            if (walking.Count < 2) return;
            Console.WriteLine($"Cost on this machine ({Environment.ProcessorCount} cores), models from {folder}, {walking.Count - 1} walking recordings after one to warm up:");
            Console.WriteLine($"{"clf",-9} {"ms/win",8} {"p95_ms",8} {"us/sample",9} {"bytes/sample",12}");
            foreach (var name in names)
            {
                var c = models.Create(name, out string warning);
                if (warning != null)
                {
                    Console.WriteLine($"{name,-9} not measured: {warning}");
                    continue;
                }
                var cost = CostProbe.Measure(c, walking);
                Console.WriteLine(string.Format(System.Globalization.CultureInfo.InvariantCulture, "{0,-9} {1,8:F4} {2,8:F4} {3,9:F1} {4,12:F2}",
                    cost.Classifier, cost.MeanWindowMs, cost.P95WindowMs, cost.MicrosecondsPerSample, cost.BytesPerSample));
            }
            Console.WriteLine("ms/win = classifier per window; us/sample = whole pipeline per input sample; bytes/sample = managed allocation in steady state.");
        }
    }
}
