using System;
using System.Collections.Generic;
using System.CommandLine;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Threading.Tasks;

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
            var command = new Command("realworld", "Replays unlabelled real recordings (an activity per file) through the live pipeline and reports walking shown, cadence, alternation, fragments, late start and non-walking shown as walking, against the rhythm the signal itself shows.")
            {
                data, classifier, models, perPerson,
            };
            command.SetAction(parse => Run(parse.GetValue(data), parse.GetValue(classifier), parse.GetValue(models), parse.GetValue(perPerson)));
            return command;
        }

        static int Run(string[] data, string classifierList, string modelFolder, string perPersonCsv)
        {
            var recordings = Inputs.LoadRecordings(Inputs.Expand(data, "*.csv"), false);
            var unknown = recordings.Where(r => RealActivity.Of(r).Length == 0).Select(r => r.Name).ToList();
            if (unknown.Count > 0) Console.WriteLine($"warning: no '# activity=' for {string.Join(", ", unknown.Take(5))}{(unknown.Count > 5 ? ", ..." : "")}: counted under no activity");
            string folder = modelFolder ?? SamplePaths.FindModelsFolder() ?? throw new UsageException("no --models and no package Models/ folder found");
            var models = Classifiers.Load(folder);
            var names = Classifiers.Parse(classifierList);
            var references = new RhythmReference[recordings.Count];
            Parallel.For(0, recordings.Count, i => references[i] = RhythmReference.Of(recordings[i]));
            Console.WriteLine($"HeadGait realworld: {recordings.Count} recordings of {recordings.Select(RealActivity.PersonOf).Distinct().Count()} people from {string.Join(", ", data)}, models from {folder}");
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
                    var result = ReplayEvaluator.Run(recordings[i], c, keepTrace: true);
                    scores[i] = RealWorldScore.Of(recordings[i], references[i], c.Name, result.Predictions, result.Frames);
                });
                if (warning != null) Console.WriteLine($"warning: {warning}");
                all.AddRange(scores);
                summaries.Add(RealWorldSummary.Of(scores[0]?.Classifier ?? name, scores));
            }
            Print(summaries);
            if (perPersonCsv != null) WriteCsv(perPersonCsv, all);
            return 0;
        }

        static string Pct(double v) => double.IsNaN(v) ? "-" : (100 * v).ToString("F1", CultureInfo.InvariantCulture) + " %";
        static string Num(double v, string format) => double.IsNaN(v) ? "-" : v.ToString(format, CultureInfo.InvariantCulture);

        static void Print(List<RealWorldSummary> s)
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
                ("late start, walking files / TUG bouts (median, s)", x => $"{Num(x.StartDelay, "F2")} / {Num(x.TugStartDelay, "F2")}"),
            };
            foreach (var activity in new[] { RealActivity.Standing, RealActivity.SittingHeadMovement, RealActivity.StandingPickup })
                if (s.Any(x => x.Still.ContainsKey(activity)))
                    rows.Add(($"{activity.Replace('_', ' ')} shown as walking: avatar / classifier", x => x.Still.TryGetValue(activity, out var v) ? $"{Pct(v.Avatar)} / {Pct(v.Classifier)}" : "-"));
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
            Console.WriteLine("Steps shown count the avatar's foot contacts while both walk. Late start: from a bout's first step to the avatar walking.");
        }

        static void WriteCsv(string path, List<RealWorldScore> scores)
        {
            var lines = new List<string> { "recording,person,activity,classifier,seconds,signal_walking_s,signal_cadence_spm,avatar_walking_of_signal,classifier_walking_of_signal,avatar_walking_s,classifier_walking_s,steps_shown,signal_steps,cadence_ratio,consecutive_steps,alternating_steps,fragments,signal_bouts,start_delays_s" };
            foreach (var x in scores)
                lines.Add(string.Join(",", Csv(x.Recording), Csv(x.Person), x.Activity, x.Classifier,
                    F(x.Seconds), F(x.ReferenceWalkingSeconds), F(x.SignalCadence), F(x.AvatarWalkingShare), F(x.ClassifierWalkingShare),
                    F(x.AvatarWalkingSeconds), F(x.ClassifierWalkingSeconds), x.Contacts, F(x.SignalSteps), F(x.CadenceRatio),
                    x.ConsecutiveContacts, x.AlternatingContacts, x.Fragments, x.ReferenceBouts, string.Join(" ", x.StartDelays.Select(F))));
            AtomicFile.WriteAllText(path, string.Join("\n", lines) + "\n");
            Console.WriteLine($"Wrote {scores.Count} rows to {path}");
        }

        static string F(double v) => double.IsNaN(v) ? "" : v.ToString("0.####", CultureInfo.InvariantCulture);
        static string Csv(string s) => s.Contains(',') || s.Contains('"') ? "\"" + s.Replace("\"", "\"\"") + "\"" : s;
    }
}
