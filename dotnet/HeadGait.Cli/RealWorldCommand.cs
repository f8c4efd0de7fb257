using System;
using System.Collections.Generic;
using System.CommandLine;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Threading.Tasks;
using HeadGait.Synthetic;
using HeadGait.Training;

namespace HeadGait.Cli
{
    /// <summary>
    /// headgait realworld: unlabelled real recordings with an activity per file, replayed through the live pipeline and
    /// measured against the signal's own rhythm (<see cref="RhythmReference"/>, <see cref="RealWorldScore"/>,
    /// <see cref="RealWorldSummary"/>).
    /// </summary>
    static class RealWorldCommand
    {
        public static Command Build()
        {
            var data = new Option<string[]>("--data") { Description = "recordings with '# activity=' headers, or folders of them (e.g. ../shared/data/glasses-train)", Required = true, AllowMultipleArgumentsPerToken = true };
            var classifier = new Option<string>("--classifier") { Description = "thr, cor, svm, blstm, a comma-separated list or all", DefaultValueFactory = _ => "all" };
            var models = new Option<string>("--models") { Description = "folder of trained models (default: the package's Models/)" };
            var perPerson = new Option<string>("--per-person") { Description = "also write every recording's scores (person, activity, classifier) to this CSV" };
            var cv = new Option<string>("--cv") { Description = "person: leave one person out: each person's recordings are judged by walking gates trained on the --train recordings and the other people's recordings in --data (as `train --real` trains them); the rest of each model as shipped" };
            var train = new Option<string[]>("--train") { Description = "with --cv person: the labelled recordings the gates also learn from (as `train --data`, e.g. ../shared/data/real-train)", AllowMultipleArgumentsPerToken = true };
            var firstStep = new Option<string>("--first-step") { Description = "THR and COR start a provisional walk on a contact the walking gate refuses by less than MARGIN (FirstStepStartSettings): MARGIN[,CONFIRM_S[,KEEP_MARGIN[,RESUME_S[,AFTER_SHOWN_S]]]] (defaults 0.15 s, 0, 0: any time, 0: after any walk); replaces the shipped setting (THR 0.75,0.15,1,3; COR 0.75,0.15,1,3,2.5)" };
            var noPutOn = new Option<bool>("--no-put-on") { Description = "do not add the generated put-on streams (PutOnGlassesGenerator over each standing and sitting recording, reported as putting on glasses) that are added when --data holds no putting_on_glasses recordings of its own" };
            var putOnDraws = new Option<int>("--put-on-draws") { Description = "generated put-on streams per standing and sitting recording, each drawn afresh (default 1: one draw, seeded from the recording's name; more narrow the put-on figure's spread)", DefaultValueFactory = _ => 1 };
            var command = new Command("realworld", "Replays unlabelled real recordings (an activity per file) through the live pipeline and reports walking shown, cadence, alternation, fragments, the start of bouts met standing and non-walking shown as walking, against the rhythm the signal itself shows.")
            {
                data, classifier, models, perPerson, cv, train, firstStep, noPutOn, putOnDraws,
            };
            command.SetAction(parse => Run(parse.GetValue(data), parse.GetValue(classifier), parse.GetValue(models), parse.GetValue(perPerson), parse.GetValue(cv), parse.GetValue(train), ParseFirstStep(parse.GetValue(firstStep)), !parse.GetValue(noPutOn), parse.GetValue(putOnDraws)));
            return command;
        }

        /// <summary>
        /// Put-on stream <paramref name="draw"/> over a worn recording: the first as ever (seeded from its name), each further
        /// one from its own seed and named with its number, so that every draw is a recording of its own in the report.
        /// </summary>
        static Recording PutOnDraw(Recording worn, int draw)
        {
            if (draw == 0) return PutOnGlassesGenerator.From(worn, DeterministicRandom.SeedFrom(worn.Name));
            var generated = PutOnGlassesGenerator.From(worn, DeterministicRandom.SeedFrom(worn.Name + "#" + draw));
            var named = new Recording(generated.Name + "_" + (draw + 1), generated.Samples);
            foreach (var kv in generated.Metadata) named.Metadata[kv.Key] = kv.Value;
            return named;
        }

        /// <summary>Reads --first-step (MARGIN[,CONFIRM_S[,KEEP_MARGIN[,RESUME_S[,AFTER_SHOWN_S]]]]); null when not given.</summary>
        static FirstStepStartSettings ParseFirstStep(string text)
        {
            if (string.IsNullOrWhiteSpace(text)) return null;
            var parts = text.Split(',');
            var values = new double[parts.Length];
            for (int i = 0; i < parts.Length; i++)
                if (parts.Length > 5 || !double.TryParse(parts[i].Trim(), NumberStyles.Float, CultureInfo.InvariantCulture, out values[i]) || !(values[i] >= 0) || values[i] > 100)
                    throw new UsageException($"--first-step '{text}' is not MARGIN[,CONFIRM_S[,KEEP_MARGIN[,RESUME_S[,AFTER_SHOWN_S]]]] (up to five numbers of 0 to 100)");
            var s = new FirstStepStartSettings { Margin = values[0] };
            if (values.Length > 1) s.ConfirmWithin = values[1];
            if (values.Length > 2) s.KeepMargin = values[2];
            if (values.Length > 3) s.ResumeWithin = values[3];
            if (values.Length > 4) s.ResumeAfterShown = values[4];
            return s;
        }

        /// <summary>THR or COR with its step clock's first-step start set to <paramref name="firstStep"/>; any other classifier as it is.</summary>
        static IGaitClassifier WithFirstStep(IGaitClassifier c, FirstStepStartSettings firstStep)
        {
            switch (c)
            {
                case ThresholdClassifier thr:
                    var s = thr.Settings.Clone();
                    s.Clock.FirstStep = firstStep.Clone();
                    return new ThresholdClassifier(s);
                case CorrelationClassifier cor:
                    var settings = new CorrelationSettings();
                    settings.Clock.FirstStep = firstStep.Clone();
                    return new CorrelationClassifier(cor.Template, settings);
                default:
                    return c;
            }
        }

        static int Run(string[] data, string classifierList, string modelFolder, string perPersonCsv, string cv, string[] train, FirstStepStartSettings firstStep, bool putOn, int putOnDraws)
        {
            if (putOnDraws < 1 || putOnDraws > 20) throw new UsageException($"--put-on-draws is 1 to 20, not {putOnDraws}");
            bool byPerson = cv switch
            {
                null or "" or "none" => false,
                "person" => true,
                _ => throw new UsageException($"--cv is 'person' or 'none', not '{cv}'"),
            };
            if (byPerson && (train == null || train.Length == 0)) throw new UsageException("--cv person needs --train (the labelled recordings the gates also learn from)");
            var recordings = Inputs.LoadRecordings(Inputs.Expand(data, "*.csv"), false);
            var unknown = recordings.Where(r => RealActivity.Of(r).Length == 0).Select(r => r.Name).ToList();
            if (unknown.Count > 0) Console.WriteLine($"warning: no '# activity=' for {string.Join(", ", unknown.Take(5))}{(unknown.Count > 5 ? ", ..." : "")}: counted under no activity");
            string folder = modelFolder ?? SamplePaths.FindModelsFolder() ?? throw new UsageException("no --models and no package Models/ folder found");
            var models = Classifiers.Load(folder);
            var names = Classifiers.Parse(classifierList);
            Console.WriteLine($"HeadGait realworld: {recordings.Count} recordings of {recordings.Select(RealActivity.PersonOf).Distinct().Count()} people from {string.Join(", ", data)}, models from {folder}");
            var gates = byPerson ? PersonGates(recordings, train) : null;
            bool generatedPutOns = false;
            if (putOn && !recordings.Any(r => RealActivity.Of(r) == RealActivity.PuttingOnGlasses))
            {
                // The judges' putting on glasses, which these recordings lack: generated over the wearers' own still
                // recordings, after the gates were trained (they never learn from it).
                var worn = recordings.Where(r => RealActivity.Of(r) is RealActivity.Standing or RealActivity.SittingHeadMovement
                                                 && r.Samples.Count >= PutOnGlassesGenerator.MinSamples).ToList();
                for (int draw = 0; draw < putOnDraws; draw++)
                    recordings.AddRange(worn.Select(r => PutOnDraw(r, draw)));
                generatedPutOns = worn.Count > 0;
                if (worn.Count > 0) Console.WriteLine($"Putting on glasses: generated over the {worn.Count} standing and sitting recordings{(putOnDraws > 1 ? $", {putOnDraws} draws each" : "")} (PutOnGlassesGenerator; --no-put-on leaves them out).");
            }
            var references = new RhythmReference[recordings.Count];
            Parallel.For(0, recordings.Count, i => references[i] = RhythmReference.Of(recordings[i]));
            if (firstStep != null) Console.WriteLine($"THR and COR start on a first step the gate refuses by less than {firstStep.Margin} log-odds (confirmed within {firstStep.ConfirmWithin} s{(firstStep.KeepMargin > 0 ? $", withdrawn at once at -{firstStep.KeepMargin}" : "")}{(firstStep.ResumeWithin > 0 ? $", only within {firstStep.ResumeWithin} s of a walk" : "")}).");
            if (byPerson) Console.WriteLine($"Leave one person out: each person judged by walking gates trained on {string.Join(", ", train)} and the other {gates.Count - 1} people.");
            Console.WriteLine();

            var summaries = new List<RealWorldSummary>();
            var all = new List<RealWorldScore>();
            foreach (var name in names)
            {
                var scores = new RealWorldScore[recordings.Count];
                string warning = null;
                Parallel.For(0, recordings.Count, i =>
                {
                    var c = models.Create(name, out string w);
                    if (w != null) warning = w;
                    if (gates != null) c = WithGates(c, gates[RealActivity.PersonOf(recordings[i])]);
                    if (firstStep != null) c = WithFirstStep(c, firstStep);
                    var result = ReplayEvaluator.Run(recordings[i], c, keepTrace: true);
                    scores[i] = RealWorldScore.Of(recordings[i], references[i], c.Name, result.Predictions, result.Frames);
                });
                if (warning != null) Console.WriteLine($"warning: {warning}");
                all.AddRange(scores);
                summaries.Add(RealWorldSummary.Of(scores[0]?.Classifier ?? name, scores));
            }
            Print(summaries, generatedPutOns);
            if (perPersonCsv != null) WriteCsv(perPersonCsv, all);
            return 0;
        }

        /// <summary>Per person, the walking gates trained without that person's recordings (and with the labelled ones).</summary>
        static Dictionary<string, (WalkingGate Threshold, WalkingGate Correlation, WalkingGate Learned)> PersonGates(List<Recording> recordings, string[] train)
        {
            var labelled = Inputs.LoadRecordings(Inputs.Expand(train, "*.csv"), false).Where(r => r.HasTruth).ToList();
            if (labelled.Count == 0) throw new UsageException("no labelled recordings in --train");
            var labelledWindows = GaitTraining.GateWindows.Of(GaitTraining.WithCalmCopies(GaitTraining.WithAugmentation(labelled, GaitTraining.DefaultAugmentedCopies)));
            var people = recordings.GroupBy(RealActivity.PersonOf).ToList();
            var windows = new GaitTraining.GateWindows[people.Count];
            Parallel.For(0, people.Count, i => windows[i] = GaitTraining.GateWindows.Of(GaitTraining.RealGateRecordings(people[i])));
            var gates = new Dictionary<string, (WalkingGate, WalkingGate, WalkingGate)>();
            for (int i = 0; i < people.Count; i++)
                gates[people[i].Key] = GaitTraining.GatesFrom(labelledWindows, GaitTraining.GateWindows.Union(windows.Where((_, k) => k != i)));
            return gates;
        }

        /// <summary>The classifier with its walking gate replaced (THR, COR and the learned ones; the rest as loaded).</summary>
        static IGaitClassifier WithGates(IGaitClassifier c, (WalkingGate Threshold, WalkingGate Correlation, WalkingGate Learned) gates)
        {
            switch (c)
            {
                case ThresholdClassifier thr:
                    var s = thr.Settings.Clone();
                    s.Gate = gates.Threshold;
                    return new ThresholdClassifier(s);
                case CorrelationClassifier cor:
                    return new CorrelationClassifier(cor.Template.With(gate: gates.Correlation));
                case LearnedClassifier learned:
                    learned.Gate = gates.Learned;
                    return learned;
                default:
                    return c;
            }
        }

        static string Pct(double v) => double.IsNaN(v) ? "-" : (100 * v).ToString("F1", CultureInfo.InvariantCulture) + " %";
        static string Num(double v, string format) => double.IsNaN(v) ? "-" : v.ToString(format, CultureInfo.InvariantCulture);

        static void Print(List<RealWorldSummary> s, bool generatedPutOns)
        {
            var first = s[0];
            Console.WriteLine($"Walking files: {first.WalkingFiles} ({first.People} people); the signal shows regular steps in {Pct(first.ReferenceShare)} of their time, median cadence {Num(first.SignalCadence, "F0")} steps/min, {Num(first.ReferenceBouts, "F0")} bouts per file (median).");
            Console.WriteLine();
            var rows = new List<(string Label, Func<RealWorldSummary, string> Cell)>
            {
                ("walking time shown as walking, avatar (pooled)", x => Pct(x.AvatarWalking)),
                ("  per person: median / worst tenth", x => $"{Pct(x.PersonMedian)} / {Pct(x.PersonWorstTenth)}"),
                ("  slower / faster half of the people", x => $"{Pct(x.SlowerHalf)} / {Pct(x.FasterHalf)}"),
                ("walking time predicted walking, classifier (pooled)", x => Pct(x.ClassifierWalking)),
                ("steps shown / the signal's cadence (median)", x => Num(x.CadenceRatio, "F2")),
                ("consecutive steps alternating feet", x => Pct(x.Alternating)),
                ("walking fragments per walking file (median)", x => Num(x.Fragments, "F0")),
                ($"every bout shown walking within {RealWorldSummary.StandingStarts.Within:0.0} s of its first step, walking files / TUG", x => $"{Pct(x.WalkingBoutsOnTime)} / {Pct(x.TugBoutsOnTime)}"),
                ("bouts met standing, walking files / TUG", x => $"{x.WalkingStarts.Count} / {x.TugStarts.Count}"),
                ("  their delay, median / 90th pct (s)", x => $"{Num(x.WalkingStarts.Median, "F2")}/{Num(x.WalkingStarts.Ninetieth, "F2")} | {Num(x.TugStarts.Median, "F2")}/{Num(x.TugStarts.Ninetieth, "F2")}"),
                ($"  started within {RealWorldSummary.StandingStarts.Within:0.0} s", x => $"{Pct(x.WalkingStarts.ShareWithin)} / {Pct(x.TugStarts.ShareWithin)}"),
                ("  classifier's own, walking files: n, median / 90th", x => $"{x.ClassifierStarts.Count}, {Num(x.ClassifierStarts.Median, "F2")}/{Num(x.ClassifierStarts.Ninetieth, "F2")}"),
            };
            foreach (var activity in RealActivity.StillActivities)
                if (s.Any(x => x.Still.ContainsKey(activity)))
                    rows.Add(($"{activity.Replace('_', ' ')}{(activity == RealActivity.PuttingOnGlasses && generatedPutOns ? " (generated)" : "")} shown as walking: avatar / classifier", x => x.Still.TryGetValue(activity, out var v) ? $"{Pct(v.Avatar)} / {Pct(v.Classifier)}" : "-"));
            rows.Add(($"TUG time shown walking (signal: {Pct(first.TugReference)}); of its walking", x => $"{Pct(x.TugAvatar)}; {Pct(x.TugAvatarOfReference)}"));
            int labelWidth = rows.Max(r => r.Label.Length) + 2;
            int cellWidth = Math.Max(18, rows.SelectMany(r => s.Select(r.Cell)).Max(c => c.Length) + 2);
            Console.WriteLine("".PadRight(labelWidth) + string.Concat(s.Select(x => x.Classifier.PadLeft(cellWidth))));
            Console.WriteLine(new string('-', labelWidth + cellWidth * s.Count));
            foreach (var (label, cell) in rows) Console.WriteLine(label.PadRight(labelWidth) + string.Concat(s.Select(x => cell(x).PadLeft(cellWidth))));
            Console.WriteLine();
            var still = string.Join(", ", first.Still.Select(kv => $"{kv.Key} {Pct(kv.Value.Reference)}"));
            if (still.Length > 0) Console.WriteLine($"The signal's rhythm in the still activities (should be near 0): {still}.");
            Console.WriteLine("Walking time: where the signal itself shows a regular step rhythm (SMV repeating one step and one stride later, the head");
            Console.WriteLine("swaying to the other side each step; 4 s around each moment, edges at the first and last step); cadence: its step period.");
            Console.WriteLine("Steps shown count the avatar's foot contacts while both walk. Every bout: the avatar walking at some moment from the");
            Console.WriteLine($"bout's first step to {RealWorldSummary.StandingStarts.Within:0.0} s after it, whether it met the bout standing or walked into it (as after a turn).");
            Console.WriteLine("Bouts met standing: bouts after >= 1 s without walking (or");
            Console.WriteLine($"the recording's start) with the avatar standing {RealWorldScore.EarlyStart:0.0} s before the first step; delay from the first step to the");
            Console.WriteLine($"avatar leaving Standing (0 within those {RealWorldScore.EarlyStart:0.0} s before it; the bout's length when it never does).");
            Console.WriteLine("A bout's first step is a smoothed edge, not a contact: the first moment whose next 0.5 s of SMV spreads at half the");
            Console.WriteLine("bout's typical level (RhythmReference), i.e. the first step's rise; THR's first threshold crossing of a bout on the");
            Console.WriteLine("glasses comes a median 0.16 s before it (10th-90th percentile 0.27 s before to 0.44 s after).");
        }

        static void WriteCsv(string path, List<RealWorldScore> scores)
        {
            var lines = new List<string> { "recording,person,activity,classifier,seconds,signal_walking_s,signal_cadence_spm,avatar_walking_of_signal,classifier_walking_of_signal,avatar_walking_s,classifier_walking_s,steps_shown,signal_steps,cadence_ratio,consecutive_steps,alternating_steps,fragments,signal_bouts,standing_start_delays_s,bouts_from_first_step,bouts_shown_on_time" };
            foreach (var x in scores)
                lines.Add(string.Join(",", Csv(x.Recording), Csv(x.Person), x.Activity, x.Classifier,
                    F(x.Seconds), F(x.ReferenceWalkingSeconds), F(x.SignalCadence), F(x.AvatarWalkingShare), F(x.ClassifierWalkingShare),
                    F(x.AvatarWalkingSeconds), F(x.ClassifierWalkingSeconds), x.Contacts, F(x.SignalSteps), F(x.CadenceRatio),
                    x.ConsecutiveContacts, x.AlternatingContacts, x.Fragments, x.ReferenceBouts, string.Join(" ", x.StandingStartDelays.Select(F)),
                    x.BoutsFromFirstStep, x.BoutsShownOnTime));
            AtomicFile.WriteAllText(path, string.Join("\n", lines) + "\n");
            Console.WriteLine($"Wrote {scores.Count} rows to {path}");
        }

        static string F(double v) => double.IsNaN(v) ? "" : v.ToString("0.####", CultureInfo.InvariantCulture);
        static string Csv(string s) => s.Contains(',') || s.Contains('"') ? "\"" + s.Replace("\"", "\"\"") + "\"" : s;
    }
}
