using System;
using System.Collections.Generic;
using System.CommandLine;
using System.Globalization;
using System.IO;
using System.Linq;
using HeadGait.Calibration;
using HeadGait.Mocap;

namespace HeadGait.Cli
{
    /// <summary>
    /// headgait calibrate: a wearer's calibration walk into a profile (fit), profiles reset, calibration sessions made from
    /// motion capture (session), and the calibration benchmark on the real recordings (benchmark).
    /// </summary>
    static class CalibrateCommand
    {
        public static Command Build()
        {
            var command = new Command("calibrate", "Fits the classifiers to one wearer from a calibration walk (head plus, optionally, two ankle trackers) and manages wearer profiles.");
            command.Subcommands.Add(Fit());
            command.Subcommands.Add(Reset());
            command.Subcommands.Add(Session());
            command.Subcommands.Add(Benchmark());
            command.Subcommands.Add(Glasses());
            return command;
        }

        static Option<string> ModelsOption() => new Option<string>("--models") { Description = "the shipped models the profile adapts (default: the package's Models/)" };
        static Option<string> ProfilesOption() => new Option<string>("--profiles") { Description = "folder of wearer profiles", DefaultValueFactory = _ => "profiles" };
        static Option<string> WearerOption() => new Option<string>("--wearer") { Description = "wearer id (letters, digits, '-', '_', '.')", Required = true };

        static Option<string> AdaptOption() => new Option<string>("--adapt")
        {
            Description = "what to refit, on top of the defaults: cor-template, cor-threshold, cor-lead, thr, gates, learned-gate, learned-gain, learned-refit, learned-channels, svm-channels, learned-search, open-labels, fill-missed (no-X: off), prior=STEPS, margin=SHARE, template-steps=N, threshold-steps=N, gate-cap=LOGODDS, shift-cap=SHIFT, shift-prior=WEIGHT, search-cap=SHIFT; self: or feet: for one source",
        };

        static Command Fit()
        {
            var session = new Argument<string>("session") { Description = "a calibration session folder (head.csv, and left-ankle.csv and right-ankle.csv from ankle trackers)" };
            var wearer = WearerOption();
            var models = ModelsOption();
            var profiles = ProfilesOption();
            var self = new Option<bool>("--self-supervised") { Description = "ignore the ankle streams: fit on the steps the shipped COR is sure of" };
            var c = new Command("fit", "Writes the wearer's profile from a calibration session.") { session, wearer, models, profiles, self };
            c.SetAction(parse =>
            {
                string folder = parse.GetValue(models) ?? SamplePaths.FindModelsFolder() ?? throw new UsageException("no --models and no package Models/ folder found");
                var shipped = Classifiers.Load(folder);
                var s = CalibrationSession.Load(parse.GetValue(session));
                string id = parse.GetValue(wearer);
                if (!WearerProfile.IsValidWearer(id)) throw new UsageException($"wearer id '{id}' is not 1-64 letters, digits, '-', '_' or '.'");
                var watch = System.Diagnostics.Stopwatch.StartNew();
                var profile = s.Fit(shipped, id, parse.GetValue(self));
                watch.Stop();
                var store = new WearerProfiles(parse.GetValue(profiles));
                store.Save(profile);
                Console.WriteLine($"{store.PathOf(id)}: {profile.Source}, {profile.Steps} steps, fitted in {watch.Elapsed.TotalSeconds:F1} s");
                Console.WriteLine(string.Format(CultureInfo.InvariantCulture, "COR: {0} step templates, threshold {1:F2} (shipped {2:F2}); THR floor {3:F2} (shipped {4:F2}) m/s^2; learned input gain {5:F2}, gate opened by {6:F2}",
                    profile.Correlation.Templates.Count, profile.Correlation.MinCorrelation, shipped.Correlation.MinCorrelation, profile.Threshold.Floor, shipped.Threshold.Floor, profile.LearnedGain, profile.LearnedGateShift));
                return 0;
            });
            return c;
        }

        static Command Reset()
        {
            var wearer = WearerOption();
            var profiles = ProfilesOption();
            var c = new Command("reset", "Deletes the wearer's profile: the shipped models apply again.") { wearer, profiles };
            c.SetAction(parse =>
            {
                var store = new WearerProfiles(parse.GetValue(profiles));
                string id = parse.GetValue(wearer);
                Console.WriteLine(store.Reset(id) ? $"{store.PathOf(id)}: deleted; wearer '{id}' gets the shipped models" : $"{store.PathOf(id)}: no profile to reset");
                return 0;
            });
            return c;
        }

        static Command Session()
        {
            var bvh = new Argument<string[]>("bvh") { Description = "motion-capture clips (BVH); several are joined, in order, into one walk", Arity = ArgumentArity.OneOrMore };
            var output = new Option<string>("--out") { Description = "session folder to write", Required = true };
            var rate = new Option<double>("--ankle-rate") { Description = "ankle trackers' frame rate (Hz)", DefaultValueFactory = _ => 72 };
            var c = new Command("session", "Makes a calibration session (head acceleration plus two ankle trackers' poses) from motion capture; several clips are joined into one walk.") { bvh, output, rate };
            c.SetAction(parse =>
            {
                var s = CalibrationSession.FromMotionCapture(parse.GetValue(bvh).Select(BvhFile.Load), parse.GetValue(rate));
                s.Save(parse.GetValue(output));
                Console.WriteLine($"{parse.GetValue(output)}: {s.Head.Samples.Count} head samples, {s.LeftAnkle.Count} + {s.RightAnkle.Count} ankle poses");
                return 0;
            });
            return c;
        }

        static Command Glasses()
        {
            var data = new Option<string[]>("--data") { Description = "unlabelled real recordings with '# activity=' (e.g. ../shared/data/glasses-train)", Required = true, AllowMultipleArgumentsPerToken = true };
            var models = ModelsOption();
            var classifier = new Option<string>("--classifier") { Description = "thr, cor, svm, blstm, a list or all", DefaultValueFactory = _ => "all" };
            var seconds = new Option<double>("--seconds") { Description = "calibrate on this much of each person's walking file (s)", DefaultValueFactory = _ => 60 };
            var adapt = AdaptOption();
            var c = new Command("glasses", "Calibrates each person (self-supervised) on the start of their walking file and replays the rest and their still activities with and without the profile.") { data, models, classifier, seconds, adapt };
            c.SetAction(parse => CalibrationGlasses.Run(parse.GetValue(data), parse.GetValue(models), Classifiers.Parse(parse.GetValue(classifier)), parse.GetValue(seconds), parse.GetValue(adapt)));
            return c;
        }

        static Command Benchmark()
        {
            var data = new Option<string[]>("--data") { Description = "labelled recordings (e.g. ../shared/data/real-train)", Required = true, AllowMultipleArgumentsPerToken = true };
            var bvh = new Option<string>("--bvh") { Description = "the motion capture behind the walking recordings (e.g. ../shared/data/bvh/train)", Required = true };
            var models = ModelsOption();
            var classifier = new Option<string>("--classifier") { Description = "thr, cor, svm, blstm, a list or all", DefaultValueFactory = _ => "all" };
            var augment = new Option<int>("--augment") { Description = "augmented copies per training recording for THR and COR (as `train`)", DefaultValueFactory = _ => Training.GaitTraining.DefaultAugmentedCopies };
            var cache = new Option<string>("--fold-cache") { Description = "keep each style fold's THR and COR here and reuse them while this build and the same --augment trained them (else trained again)" };
            var rate = new Option<double>("--ankle-rate") { Description = "ankle trackers' frame rate (Hz)", DefaultValueFactory = _ => 72 };
            var seconds = new Option<double>("--walk-seconds") { Description = "the calibration walk: the held-out style's straight walks and turns joined up to this long (s); 0: its first straight walk alone", DefaultValueFactory = _ => 60 };
            var cvModels = new Option<string>("--cv-models") { Description = "judge the SVM and BLSTM with the style-fold models `headgait train --cv style --cv-only` wrote under DIR/style/<fold>/ (e.g. training/cv-models); default: the shipped models (not held out)" };
            var adapt = AdaptOption();
            var styles = new Option<string>("--styles") { Description = "run only these held-out styles (comma-separated fold names, e.g. bn1/feminine,bn1/giant); default: every style" };
            var perRecording = new Option<bool>("--per-recording") { Description = "also print each scored recording's misclassification, walking shown as standing, contact timing and right foot, per variant" };
            var c = new Command("benchmark", "Leave one style out: calibrate on up to a minute of the held-out style's walking (from its motion capture, with ankle trackers and self-supervised) and score the style's other recordings against the uncalibrated classifiers.")
            {
                data, bvh, models, classifier, augment, cache, rate, seconds, cvModels, adapt, styles, perRecording,
            };
            c.SetAction(parse => CalibrationBenchmark.Run(parse.GetValue(data), parse.GetValue(bvh), parse.GetValue(models), Classifiers.Parse(parse.GetValue(classifier)),
                parse.GetValue(augment), parse.GetValue(cache), parse.GetValue(rate), OptionValues.Number(parse.GetValue(seconds), "--walk-seconds", 0, 600),
                parse.GetValue(cvModels) == null ? null : OptionValues.Folder(parse.GetValue(cvModels), "--cv-models"), parse.GetValue(adapt),
                parse.GetValue(styles), parse.GetValue(perRecording)));
            return c;
        }
    }
}
