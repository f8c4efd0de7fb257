using System;
using System.Collections.Generic;
using System.CommandLine;
using System.Globalization;
using System.IO;
using System.Linq;
using HeadGait.Tooling;
using HeadGait.Unity;

namespace HeadGait.Cli
{
    /// <summary>
    /// headgait animator-check: the shipped Animator Controller, run as Unity runs it (<see cref="AnimatorLayerSimulator"/>),
    /// fed by the component's runner frame by frame; counts the walk starts and stops the avatar never shows and the lag.
    /// </summary>
    static class AnimatorCheckCommand
    {
        public static Command Build()
        {
            var files = new Argument<string[]>("recordings") { Arity = ArgumentArity.ZeroOrMore, Description = "CSV recordings or folders of them (default: the package's generated recordings, Samples~/Recordings eval and train)" };
            var fps = new Option<string>("--fps") { Description = "frame rates, comma-separated", DefaultValueFactory = _ => "60,72,90,120" };
            var classifier = new Option<string>("--classifier") { Description = "thr, cor, svm or blstm (the prefab's default: cor)", DefaultValueFactory = _ => "cor" };
            var controller = new Option<string>("--controller") { Description = "the .controller to run (default: the package's HeadGait Legs.controller)" };
            var list = new Option<bool>("--list-misses") { Description = "print each missed start or stop" };
            var command = new Command("animator-check", "Runs recordings through the component's frame-by-frame runner and the shipped Animator Controller (simulated as Unity's Animator runs it) and counts the walk starts and stops the avatar misses, at each frame rate.")
            {
                files, fps, classifier, controller, list,
            };
            command.SetAction(parse => Run(parse.GetValue(files), parse.GetValue(fps), parse.GetValue(classifier), parse.GetValue(controller), parse.GetValue(list)));
            return command;
        }

        static int Run(string[] files, string fpsList, string classifierName, string controllerPath, bool listMisses)
        {
            var rates = OptionValues.FrameRates(fpsList ?? "", "--fps", 1, 1000, whole: true).Select(r => (int)r).ToList();
            string models = SamplePaths.FindModelsFolder() ?? throw new UsageException("package folder not found");
            string package = Path.GetDirectoryName(models);
            List<string> paths;
            if (files == null || files.Length == 0)
            {
                string folder = SamplePaths.RequireRecordingsFolder();
                paths = SamplePaths.List(folder, "eval").Concat(SamplePaths.List(folder, "train")).ToList();
            }
            else paths = Inputs.Expand(files, "*.csv");
            string name = Classifiers.Parse(classifierName).Single();
            var loaded = Classifiers.Load(models);
            string controllerFile = controllerPath ?? Path.Combine(package, GaitAssetFiles.Controller);
            var asset = AnimatorControllerAsset.Load(controllerFile, Path.GetDirectoryName(controllerFile));
            var recordings = Inputs.LoadRecordings(paths, strict: false);
            double duration = AnimatorStateCheck.LongestStartTransition(asset);

            Console.WriteLine($"animator-check: {recordings.Count} recording(s), classifier {name}, controller {controllerFile}");
            Console.WriteLine($"longest transition into a walking state: {duration * 1000:F0} ms");
            Console.WriteLine("fps  reading                  starts missed  stops missed  held  lag_core med/max ms  limit ms  lag_published med/max ms  limit ms  lag_grid med/max ms  cancelled");
            int missed = 0, late = 0;
            foreach (var reading in new[] { AnyStateReading.AlwaysEvaluated, AnyStateReading.ObeyInterruptionSource })
                foreach (int fps in rates)
                {
                    var total = new AnimatorCheckResult { Fps = fps };
                    foreach (var r in recordings) total.Add(AnimatorStateCheck.Run(r, loaded.Create(name, out _), asset, fps, reading));
                    missed += total.MissedStarts + total.MissedStops;
                    double limit = AnimatorStateCheck.LagLimit(asset, fps), publishedLimit = AnimatorStateCheck.PublishedLagLimit(asset, fps);
                    if (Max(total.StartLagFromCore) > limit || Max(total.StartLagFromPublished) > publishedLimit) late++;
                    Console.WriteLine(string.Format(CultureInfo.InvariantCulture,
                        "{0,3}  {1,-23} {2,7} {3,6} {4,6} {5,6} {6,5}  {7,8:F0} / {8,-8:F0} {9,8:F0}  {10,12:F0} / {11,-10:F0} {12,8:F0}  {13,8:F0} / {14,-8:F0} {15,10}",
                        fps, reading, total.Starts, total.MissedStarts, total.Stops, total.MissedStops, total.HeldFrames,
                        Median(total.StartLagFromCore) * 1000, Max(total.StartLagFromCore) * 1000, limit * 1000,
                        Median(total.StartLagFromPublished) * 1000, Max(total.StartLagFromPublished) * 1000, publishedLimit * 1000,
                        Median(total.StartLagFromGrid) * 1000, Max(total.StartLagFromGrid) * 1000, total.StartsCancelled));
                    if (listMisses)
                        foreach (var m in total.Misses) Console.WriteLine("  " + m);
                }
            Console.WriteLine();
            Console.WriteLine("missed: Start or Finish Walk states of the core that the Animator never showed (as its state or its transition's");
            Console.WriteLine("destination) up to three frames after the core left them. lag_core: from the core entering Start Walk (the");
            Console.WriteLine("sensor time of the sample that completed its window) to the Animator standing fully in a walking state; limit:");
            Console.WriteLine("one frame plus the transition in whole frames. lag_published: from the frame the runner published the start;");
            Console.WriteLine("limit: the transition in whole frames. lag_grid: from the Start Walk window's 100 Hz grid time, which the");
            Console.WriteLine("resampler can produce only once the next sample has come (up to one sample interval more; no limit).");
            Console.WriteLine("held: frames the runner showed a Start/Finish state the core had already left (each is shown for at least");
            Console.WriteLine($"{GaitBatchRunner.MinTransientFrames} frames). Readings: how Any State transitions meet a transition in progress (see AnimatorLayerSimulator).");
            if (late > 0) Console.WriteLine($"{late} row(s) with a start lag over its limit.");
            return missed == 0 && late == 0 ? 0 : 1;
        }

        static double Median(List<double> v) => v.Count == 0 ? double.NaN : v.OrderBy(x => x).ElementAt(v.Count / 2);
        static double Max(List<double> v) => v.Count == 0 ? double.NaN : v.Max();
    }
}
