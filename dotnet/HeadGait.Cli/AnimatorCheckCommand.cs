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
            string models = SamplePaths.FindModelsFolder() ?? throw new UsageException("package folder not found");
            string package = Path.GetDirectoryName(models);
            List<string> paths;
            if (files == null || files.Length == 0)
            {
                string folder = SamplePaths.RequireRecordingsFolder();
                paths = SamplePaths.List(folder, "eval").Concat(SamplePaths.List(folder, "train")).ToList();
            }
            else paths = Inputs.Expand(files, "*.csv");
            var rates = fpsList.Split(',', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries)
                .Select(s => int.TryParse(s, NumberStyles.Integer, CultureInfo.InvariantCulture, out int v) && v > 0 ? v : throw new UsageException($"--fps: '{s}' is not a frame rate"))
                .ToList();
            string name = Classifiers.Parse(classifierName).Single();
            var loaded = Classifiers.Load(models);
            string controllerFile = controllerPath ?? Path.Combine(package, GaitAssetFiles.Controller);
            var asset = AnimatorControllerAsset.Load(controllerFile, Path.GetDirectoryName(controllerFile));
            var recordings = Inputs.LoadRecordings(paths, strict: false);
            double duration = AnimatorStateCheck.LongestStartTransition(asset);

            Console.WriteLine($"animator-check: {recordings.Count} recording(s), classifier {name}, controller {controllerFile}");
            Console.WriteLine($"longest transition into a walking state: {duration * 1000:F0} ms");
            Console.WriteLine("fps  reading                  starts missed  stops missed  held  lag_core med/max ms  lag_published med/max ms  limit ms  cancelled");
            int missed = 0;
            foreach (var reading in new[] { AnyStateReading.AlwaysEvaluated, AnyStateReading.ObeyInterruptionSource })
                foreach (int fps in rates)
                {
                    var total = new AnimatorCheckResult { Fps = fps };
                    foreach (var r in recordings) total.Add(AnimatorStateCheck.Run(r, loaded.Create(name, out _), asset, fps, reading));
                    missed += total.MissedStarts + total.MissedStops;
                    Console.WriteLine(string.Format(CultureInfo.InvariantCulture,
                        "{0,3}  {1,-23} {2,7} {3,6} {4,6} {5,6} {6,5}  {7,8:F0} / {8,-8:F0}  {9,12:F0} / {10,-10:F0} {11,8:F0} {12,10}",
                        fps, reading, total.Starts, total.MissedStarts, total.Stops, total.MissedStops, total.HeldFrames,
                        Median(total.StartLagFromCore) * 1000, Max(total.StartLagFromCore) * 1000,
                        Median(total.StartLagFromPublished) * 1000, Max(total.StartLagFromPublished) * 1000,
                        AnimatorStateCheck.LagLimit(asset, fps) * 1000, total.StartsCancelled));
                    if (listMisses)
                        foreach (var m in total.Misses) Console.WriteLine("  " + m);
                }
            Console.WriteLine();
            Console.WriteLine("missed: Start or Finish Walk states of the core that the Animator never showed (as its state or its transition's");
            Console.WriteLine("destination) up to three frames after the core left them. lag: from the core's Start Walk (sensor time), and from");
            Console.WriteLine("the frame the runner published it, to the Animator standing fully in a walking state; limit: the transition in");
            Console.WriteLine("whole frames plus one (a start published on the frame another blend ends starts its own the next frame).");
            Console.WriteLine("held: frames the runner showed a Start/Finish state the core had already left (each is shown for at least");
            Console.WriteLine($"{GaitBatchRunner.MinTransientFrames} frames). Readings: how Any State transitions meet a transition in progress (see AnimatorLayerSimulator).");
            return missed == 0 ? 0 : 1;
        }

        static double Median(List<double> v) => v.Count == 0 ? double.NaN : v.OrderBy(x => x).ElementAt(v.Count / 2);
        static double Max(List<double> v) => v.Count == 0 ? double.NaN : v.Max();
    }
}
