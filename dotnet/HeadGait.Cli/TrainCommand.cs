using System;
using System.Collections.Generic;
using System.CommandLine;
using System.Diagnostics;
using System.IO;
using System.Linq;
using HeadGait.Training;

namespace HeadGait.Cli
{
    /// <summary>headgait train: all four classifiers from labelled recordings, into one model folder.</summary>
    static class TrainCommand
    {
        /// <summary>
        /// What the learned classifiers read: 1 s at 25 Hz of SMV minus gravity, lateral and forward acceleration, with a
        /// second whose mean specific force leans more than <see cref="WindowLevel.ToleranceDegrees"/> turned back to it
        /// (a head looking down at its legs otherwise feeds the vertical bounce into the forward channel). A second holds two steps; in
        /// cross-validation it beat the paper's 0.5 s window on unseen styles.
        /// </summary>
        public static readonly string DefaultFeatures = "samples:100 step:4 channels:smv,lateral,forward level:" + WindowLevel.ToleranceDegrees.ToString(System.Globalization.CultureInfo.InvariantCulture);

        /// <summary>Labels 40 ms ahead of each window's newest sample: in cross-validation this cancelled the learned classifiers' lateness.</summary>
        public const double DefaultLabelLead = 0.04;

        public static Command Build()
        {
            var data = new Option<string[]>("--data") { Description = "labelled CSV recordings or folders of them", Required = true, AllowMultipleArgumentsPerToken = true };
            var output = new Option<string>("--out") { Description = "model folder (default: the package's Models/)" };
            var augment = new Option<int>("--augment") { Description = "augmented copies per recording (time stretch, amplitude and axis scaling)", DefaultValueFactory = _ => GaitTraining.DefaultAugmentedCopies };
            var learned = new Option<string>("--learned") { Description = "learned classifiers to train with Python: svm,blstm, one of them, or none (the walking gate of the SVM and BLSTM files in --out is trained either way)", DefaultValueFactory = _ => "svm,blstm" };
            var cv = new Option<string>("--cv") { Description = "also train the learned classifiers per cross-validation fold (style, file or style,file) for `headgait benchmark`" };
            var cvModels = new Option<string>("--cv-models") { Description = "where the fold models go (default: training/cv-models, not part of the package)" };
            var features = new Option<string>("--features") { Description = "what the learned classifiers read", DefaultValueFactory = _ => DefaultFeatures };
            var stride = new Option<int>("--stride") { Description = "export every n-th window for the learned classifiers", DefaultValueFactory = _ => 6 };
            var lead = new Option<double>("--label-lead") { Description = "seconds ahead of each window's newest sample whose labels the learned classifiers are trained on", DefaultValueFactory = _ => DefaultLabelLead };
            var work = new Option<string>("--work") { Description = "folder for the exported windows (default: a temporary folder)" };
            var python = new Option<string>("--python") { Description = "Python with torch, scikit-learn and onnx", DefaultValueFactory = _ => "/usr/bin/python3" };
            var exportOnly = new Option<bool>("--export-only") { Description = "export the learned classifiers' windows and stop (for experiments with training/train_learned.py)" };
            var cvOnly = new Option<bool>("--cv-only") { Description = "train only the cross-validation fold models (--cv), leaving the model folder as it is" };
            var resume = new Option<bool>("--resume") { Description = "keep fold models an interrupted run finished for the same held-out recordings (same features and settings are assumed)" };
            var noStartStop = new Option<bool>("--no-start-stop") { Description = "leave out the BLSTM's copies of each walking recording made into a walk that starts and stops" };
            var real = new Option<string[]>("--real") { Description = "unlabelled real recordings with '# activity=' headers (e.g. ../shared/data/glasses-train) that the walking gates also learn from: walking files where the signal keeps a step rhythm, standing, sitting and picking up as standing", AllowMultipleArgumentsPerToken = true };
            var wearer = new Option<int>("--wearer-copies") { Description = "copies of each walking recording made slow and calm like a real headset wearer, for the learned classifiers", DefaultValueFactory = _ => GaitTraining.DefaultWearerCopies };
            var wearerRanges = new Option<string>("--wearer-ranges") { Description = "ranges of the wearer-like copies: narrow (the shipped models') or wide (slower and calmer walkers too)", DefaultValueFactory = _ => "narrow" };
            var realStill = new Option<int>("--real-still-stride") { Description = "also export every n-th window of --real's standing, sitting and picking-up recordings as standing for the learned classifiers (0: none)", DefaultValueFactory = _ => 0 };
            var realNear = new Option<double>("--real-still-near") { Description = "with --real-still-stride: only the still windows the package's shipped SVM walking gate passes or refuses by less than this (log-odds; 0: every window)", DefaultValueFactory = _ => 0 };
            var pythonArgs = new Option<string>("--python-args") { Description = "extra arguments for training/train_learned.py (e.g. \"--hidden 48 --epochs 16\")", DefaultValueFactory = _ => "" };
            var command = new Command("train", "Trains THR, COR, SVM and BLSTM from labelled recordings into one model folder.")
            {
                data, output, augment, learned, cv, cvModels, cvOnly, resume, noStartStop, wearer, features, stride, lead, work, python, pythonArgs, exportOnly, real,
                wearerRanges, realStill, realNear,
            };
            command.SetAction(parse =>
            {
                int copies = OptionValues.Count(parse.GetValue(augment), "--augment", 0, GaitTraining.MaxAugmentedCopies);
                int wearerCopies = OptionValues.Count(parse.GetValue(wearer), "--wearer-copies", 0, GaitTraining.MaxAugmentedCopies);
                int every = OptionValues.Count(parse.GetValue(stride), "--stride", 1, 1000);
                int stillEvery = OptionValues.Count(parse.GetValue(realStill), "--real-still-stride", 0, 1000);
                string ranges = parse.GetValue(wearerRanges);
                var wearerSettings = ranges == "narrow" ? new WearerSettings() : ranges == "wide" ? WearerSettings.Wide()
                    : throw new UsageException($"--wearer-ranges must be narrow or wide, not '{ranges}'");
                double leadSeconds = OptionValues.Number(parse.GetValue(lead), "--label-lead", -1, 1);
                var schemeList = parse.GetValue(cv) == null ? new List<string>() : OptionValues.Schemes(parse.GetValue(cv), "--cv", allowNone: false);
                string kinds = parse.GetValue(learned);
                if (!IsLearnedList(kinds)) throw new UsageException($"--learned must be svm, blstm, svm,blstm or none, not '{kinds}'");
                OptionValues.Path(parse.GetValue(output), "--out");
                OptionValues.Path(parse.GetValue(cvModels), "--cv-models");
                OptionValues.Path(parse.GetValue(work), "--work");
                string outDir = parse.GetValue(output) ?? SamplePaths.FindModelsFolder() ?? throw new UsageException("no --out and no package Models/ folder found");
                Directory.CreateDirectory(outDir);
                var recordings = Inputs.LoadRecordings(Inputs.Expand(parse.GetValue(data), "*.csv"), false).Where(r => r.HasTruth).ToList();
                if (recordings.Count == 0) throw new UsageException("no labelled recordings (phase_left/phase_right) in --data");
                var training = GaitTraining.WithAugmentation(recordings, copies);
                var map = PhaseMapTraining.Learn(recordings);
                Console.WriteLine($"{recordings.Count} labelled recordings, {training.Count - recordings.Count} augmented copies; phase map {map.Serialize()}");
                bool onlyFolds = parse.GetValue(cvOnly);
                if (onlyFolds && schemeList.Count == 0) throw new UsageException("--cv-only needs --cv");
                var realPaths = parse.GetValue(real);
                var realRecordings = realPaths == null || realPaths.Length == 0 ? null : Inputs.LoadRecordings(Inputs.Expand(realPaths, "*.csv"), false);
                if (stillEvery > 0 && realRecordings == null) throw new UsageException("--real-still-stride needs --real");
                var gates = onlyFolds ? default : GaitTraining.TrainGates(training, realRecordings);
                if (!onlyFolds)
                {
                    var thr = GaitTraining.TrainThreshold(training, map, gates.Threshold);
                    thr.Save(Path.Combine(outDir, GaitModels.ThresholdFile));
                    Console.WriteLine("walking gates: log-odds weights on the log spread of SMV, vertical, lateral and forward acceleration, of SMV change, the mean vertical over g, SMV's autocorrelation half a step (0.25 s) apart over 1 s, then their pairwise products; bias");
                    string passes = realRecordings == null ? $"{100 * WalkingGate.DetectorPass:F1} % of walking windows pass"
                        : $"{100 * WalkingGate.DetectorPass:F1} % of walking windows or at most {100 * GaitTraining.RealStandingPass:F1} % of standing ones pass, whichever is stricter; also fitted on {realRecordings.Count} real recordings";
                    Console.WriteLine($"THR's walking gate (also fitted on {GaitTraining.CalmGateCopies} calm-swaying copies of each recording; {passes}): {gates.Threshold.Serialize()}");
                    Console.WriteLine($"THR: floor {thr.Floor:F2} m/s^2, {thr.PeakFraction:F2} of recent peaks, contact lag {1000 * thr.ContactLag:F0} ms, clock lead {1000 * thr.Clock.Lead:F0} ms, {1000 * thr.Clock.LeadPerLogBounce:+0.0;-0.0} ms per log unit of bounce from {thr.Clock.LeadReferenceBounce:F1} m/s^2");
                    Console.WriteLine($"COR's walking gate (also fitted on the calm copies, spreads as they are; {passes}): {gates.Correlation.Serialize()}");
                    var cor = GaitTraining.TrainCorrelation(training, map, gates.Correlation);
                    cor.Save(Path.Combine(outDir, GaitModels.CorrelationFile));
                    Console.WriteLine($"COR: {cor.StepsUsed} steps in {cor.Templates.Count} templates (contact lags {string.Join(", ", cor.Templates.Select(t => $"{1000 * t.ContactLag:F0}"))} ms); r > {cor.MinCorrelation:F2}; clock lead {1000 * cor.ClockLead:F0} ms, {1000 * cor.LeadPerLogBounce:+0.0;-0.0} ms per log unit of bounce from {cor.LeadReferenceBounce:F1} m/s^2");
                }

                if (string.Equals(kinds, "none", StringComparison.OrdinalIgnoreCase))
                {
                    if (!onlyFolds) WriteLearnedGateAndStance(outDir, gates.Learned, map);
                    return 0;
                }
                string workDir = parse.GetValue(work) ?? Path.Combine(Path.GetTempPath(), "headgait-train-windows");
                var spec = WindowFeatures.Parse(parse.GetValue(features));
                var still = stillEvery > 0 ? GaitTraining.RealStillRecordings(realRecordings) : new List<Recording>();
                var names = recordings.Select(r => r.Name).Concat(still.Select(r => r.Name)).ToList();
                if (names.Distinct().Count() != names.Count) throw new UsageException("--real recordings share a name with a labelled one in --data");
                var index = names.Select((n, i) => (n, i)).ToDictionary(p => p.n, p => p.i);
                WindowDataset.Item Item(Recording r, bool startsAndStops) => new WindowDataset.Item
                {
                    Recording = r, FileIndex = index[RecordingAugmentation.OriginalName(r.Name)], Augmented = RecordingAugmentation.IsCopy(r.Name), StartsAndStops = startsAndStops,
                };
                var startStop = parse.GetValue(noStartStop) ? new List<Recording>() : GaitTraining.StartStopCopies(recordings);
                var wearerLike = GaitTraining.WearerCopies(recordings, wearerCopies, wearerSettings);
                var items = training.Concat(wearerLike).Select(r => Item(r, false)).Concat(startStop.Select(r => Item(r, true))).ToList();
                double near = OptionValues.Number(parse.GetValue(realNear), "--real-still-near", 0, 100);
                var nearGate = near > 0 ? ShippedSvmGate() : null;
                items.AddRange(still.Select(r => { var item = Item(r, false); item.Stride = stillEvery; item.NearGate = nearGate; item.NearLogOdds = near; return item; }));
                var summary = WindowDataset.Export(items, names, spec, new StrideSegments(map), every, workDir, leadSeconds);
                if (still.Count > 0) Console.WriteLine($"also exported every {stillEvery}th window of {still.Count} still real recordings as standing");
                Console.WriteLine($"exported {summary.Windows} windows ({spec}) to {workDir}, {wearerLike.Count} wearer-like copies, {startStop.Count} of the recordings also made into walks that start and stop (for the BLSTM); {summary.Unlabelled} windows have a label pair outside the stride segments and are not trained on");
                if (parse.GetValue(exportOnly)) return 0;

                string script = FindScript();
                string py = parse.GetValue(python);
                string extra = parse.GetValue(pythonArgs);
                if (!onlyFolds)
                {
                    RunPython(py, $"\"{script}\" --data \"{workDir}\" --out \"{outDir}\" --models {kinds} {extra}");
                    Verify(outDir);
                    WriteLearnedGateAndStance(outDir, gates.Learned, map);
                }
                foreach (var scheme in schemeList)
                {
                    var folds = CrossValidation.Make(scheme, names);
                    using var progress = new Progress($"train {scheme} CV folds", folds.Count);
                    foreach (var fold in folds)
                    {
                        progress.Step(fold.Name);
                        string foldDir = Path.Combine(parse.GetValue(cvModels) ?? DefaultCvModels(), scheme, Safe(fold.Name));
                        Directory.CreateDirectory(foldDir);
                        string exclude = Path.Combine(foldDir, "test-recordings.txt");
                        var held = fold.Test.OrderBy(n => n, StringComparer.Ordinal).ToArray();
                        if (parse.GetValue(resume) && FoldFinished(foldDir, exclude, held))
                        {
                            Console.WriteLine($"fold {scheme}/{fold.Name}: kept (finished earlier for the same {held.Length} held-out recordings)");
                            continue;
                        }
                        File.WriteAllLines(exclude, held);
                        Console.WriteLine($"fold {scheme}/{fold.Name}: {fold.Test.Count} held-out recordings");
                        RunPython(py, $"\"{script}\" --data \"{workDir}\" --out \"{foldDir}\" --models {kinds} --exclude \"{exclude}\" --no-onnx {extra}");
                    }
                }
                return 0;
            });
            return command;
        }

        /// <summary>The walking gate of the package's shipped SVM (<see cref="GaitModels.SvmFile"/>).</summary>
        static WalkingGate ShippedSvmGate()
        {
            string path = Path.Combine(SamplePaths.FindModelsFolder() ?? throw new UsageException("--real-still-near: no package Models/ folder found"), GaitModels.SvmFile);
            var model = ModelFile.Load(path);
            if (!model.Values.TryGetValue(WalkingGate.ModelKey, out var text)) throw new UsageException($"{path}: no {WalkingGate.ModelKey} line for --real-still-near");
            return WalkingGate.Parse(text);
        }

        static bool IsLearnedList(string kinds)
        {
            if (string.Equals(kinds, "none", StringComparison.OrdinalIgnoreCase)) return true;
            var parts = (kinds ?? "").Split(',', StringSplitOptions.TrimEntries);
            return parts.Length > 0 && parts.All(p => p == "svm" || p == "blstm");
        }

        /// <summary>
        /// The training script writes Reference~/training.json after every model of a fold: a fold holding it, newer than its
        /// held-out list and that list unchanged, was finished.
        /// </summary>
        static bool FoldFinished(string foldDir, string exclude, string[] held)
        {
            string report = Path.Combine(foldDir, "Reference~", "training.json");
            return File.Exists(report) && File.Exists(exclude)
                && File.GetLastWriteTimeUtc(report) >= File.GetLastWriteTimeUtc(exclude)
                && File.ReadAllLines(exclude).SequenceEqual(held);
        }

        public static string Safe(string foldName) => foldName.Replace('/', '_');

        static string FindScript()
        {
            foreach (var start in new[] { Directory.GetCurrentDirectory(), AppContext.BaseDirectory })
            {
                for (var dir = new DirectoryInfo(start); dir != null; dir = dir.Parent)
                {
                    string candidate = Path.Combine(dir.FullName, "training", "train_learned.py");
                    if (File.Exists(candidate)) return candidate;
                }
            }
            throw new UsageException("training/train_learned.py not found above the working directory");
        }

        /// <summary>training/cv-models in the repository: fold models are for the benchmark, not for the package.</summary>
        public static string DefaultCvModels() => Path.Combine(Path.GetDirectoryName(FindScript()) ?? ".", "cv-models");

        static void RunPython(string python, string arguments)
        {
            var info = new ProcessStartInfo(python, arguments) { UseShellExecute = false };
            Process process;
            try
            {
                process = Process.Start(info);
            }
            catch (System.ComponentModel.Win32Exception e)
            {
                throw new InvalidOperationException($"cannot start {python} ({e.Message}); install python3-torch python3-sklearn python3-onnx with apt, or pass --python");
            }
            process.WaitForExit();
            if (process.ExitCode != 0) throw new InvalidOperationException($"{python} {arguments} failed with exit code {process.ExitCode}");
        }

        /// <summary>The SVM's and BLSTM's walking gate and stance slope, learned from the same recordings, into whichever of their files the folder holds.</summary>
        static void WriteLearnedGateAndStance(string folder, WalkingGate gate, PhaseMap map)
        {
            var files = new[] { GaitModels.SvmFile, GaitModels.BlstmFile }.Select(f => Path.Combine(folder, f)).Where(File.Exists).ToList();
            if (files.Count == 0) return;
            foreach (var path in files) GaitTraining.WriteGateAndStance(path, gate, map);
            Console.WriteLine(gate == null
                ? $"no standing in the recordings: {string.Join(", ", files.Select(Path.GetFileName))} run without a walking gate"
                : $"walking gate of {string.Join(" and ", files.Select(Path.GetFileName))} (also fitted on {GaitTraining.CalmGateCopies} calm-swaying copies of each recording; {100 * WalkingGate.LearnedPass:F1} % of walking windows pass): {gate.Serialize()}");
        }

        /// <summary>The package's C# forward passes must reproduce what the training framework computed for the reference windows.</summary>
        static void Verify(string folder)
        {
            foreach (var file in new[] { GaitModels.SvmFile, GaitModels.BlstmFile })
            {
                string path = Path.Combine(folder, file), refPath = ReferenceCheck.ReferencePath(path);
                if (!File.Exists(path) || !File.Exists(refPath)) continue;
                double diff = ReferenceCheck.MaxDifference(ModelFile.Load(path), ModelFile.Load(refPath));
                double decision = ReferenceCheck.MaxDecisionDifference(ModelFile.Load(path), ModelFile.Load(refPath));
                Console.WriteLine($"{file}: C# forward pass vs the training framework on the reference windows: max |probability difference| {diff:G3}"
                    + (file == GaitModels.SvmFile ? $", max |decision value difference| {decision:G3} (float32 sums)" : ""));
                if (!(diff <= 1e-5)) throw new InvalidOperationException($"{path}: the C# forward pass differs from the training framework by {diff:G3} (limit 1e-5)");
            }
        }
    }
}
