using System;
using System.Collections.Generic;
using System.CommandLine;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using HeadGait.Study;
using HeadGait.Synthetic;
using HeadGait.Tooling;

namespace HeadGait.Cli
{
    /// <summary>headgait study summarize|generate: the simulator-sickness study's results, like the paper's.</summary>
    static class StudyCommand
    {
        static readonly CultureInfo Ci = CultureInfo.InvariantCulture;
        static readonly string[] Scores = { "Total", "Nausea", "Oculomotor", "Disorientation" };

        static double Get(SsqScores s, string score) => score == "Total" ? s.Total : score == "Nausea" ? s.Nausea : score == "Oculomotor" ? s.Oculomotor : s.Disorientation;

        public static Command Build()
        {
            var folder = new Argument<string>("folder") { Description = "the study's data folder (one PARTICIPANT.journal.tsv each)" };
            var csv = new Option<string>("--csv") { Description = "tidy CSV, one row per participant and condition (default: FOLDER/ssq.csv)" };
            var plot = new Option<string>("--plot") { Description = "plot of the scores per condition (default: FOLDER/ssq.png; an .svg beside it)" };
            var summarize = new Command("summarize", "Prints mean and SD of the SSQ scores per condition, repeated-measures ANOVAs and Bonferroni-corrected pairwise tests; writes a CSV and a plot.")
            {
                folder, csv, plot,
            };
            summarize.SetAction(p => Summarize(p.GetValue(folder), p.GetValue(csv), p.GetValue(plot)));

            var target = new Argument<string>("folder") { Description = "empty or new folder for the generated journals" };
            var participants = new Option<int>("--participants") { Description = "how many", DefaultValueFactory = _ => 21 };
            var seed = new Option<ulong>("--seed") { DefaultValueFactory = _ => 8 };
            var generate = new Command("generate", "Writes a generated study (each participant through every step) to try the summary on; not data from people.")
            {
                target, participants, seed,
            };
            generate.SetAction(p => Generate(p.GetValue(target), p.GetValue(participants), p.GetValue(seed)));
            var package = new Argument<string>("package") { Description = "the package folder (Packages/com.headgait.legmotion)" };
            var scene = new Command("scene", "Rewrites the study sample's scene, Samples~/Study/Study.unity, from the generator (after changing it or the scripts' GUIDs).")
            {
                package,
            };
            scene.SetAction(p => WriteScene(p.GetValue(package)));
            return new Command("study", "The simulator-sickness study: summarise its data, generate a made-up one, or rewrite its scene.") { summarize, generate, scene };
        }

        static int WriteScene(string package)
        {
            string path = StudyScene.PathIn(package);
            PrimitiveMaterials.WriteAll(package); // the scene's renderers use the package's materials
            File.WriteAllText(path, StudyScene.Yaml(StudyScene.ScriptsIn(package)));
            Console.WriteLine($"wrote {path}");
            return 0;
        }

        static int Generate(string folder, int count, ulong seed)
        {
            if (count < 2 || count > 999) throw new UsageException("--participants must be 2 to 999");
            var random = new DeterministicRandom(seed);
            var config = new StudyConfig();
            // Made-up effect sizes: symptoms grow with exposure, less disorientation with the animated humanoid.
            var baseRate = new Dictionary<string, double> { [StudyConfig.NoAvatar] = 0.9, [StudyConfig.BlockAvatar] = 0.8, [StudyConfig.HumanoidAvatar] = 0.55 };
            for (int i = 1; i <= count; i++)
            {
                string id = $"P{i:00}";
                using var s = StudySession.Start(folder, id, config);
                double susceptibility = 0.5 + random.NextDouble();
                while (s.Current.Kind != StudyStepKind.Done)
                {
                    var step = s.Current;
                    if (step.Kind == StudyStepKind.Demographics)
                    {
                        s.Answer("age", (20 + (int)(random.NextDouble() * 25)).ToString(Ci));
                        s.Answer("gender", random.NextDouble() < 0.5 ? "female" : "male");
                    }
                    if (step.IsSsq)
                    {
                        double rate = step.Kind == StudyStepKind.ConditionSsq ? baseRate[step.Condition] : step.Kind == StudyStepKind.BaselineSsq ? 0.3 : 0.2;
                        var ratings = new int[SimulatorSicknessQuestionnaire.ItemCount];
                        for (int k = 0; k < ratings.Length; k++)
                        {
                            double disorientation = (SimulatorSicknessQuestionnaire.LoadingOf((SsqItem)k) & SimulatorSicknessQuestionnaire.Subscale.Disorientation) != 0 ? 1.3 : 0.8;
                            double mean = rate * susceptibility * (step.Kind == StudyStepKind.ConditionSsq ? disorientation : 1);
                            ratings[k] = Math.Max(0, Math.Min(3, (int)Math.Round(mean + 0.6 * random.NextGaussian())));
                        }
                        s.AnswerSsq(ratings);
                    }
                    if (step.Kind == StudyStepKind.Trial) s.Event("trial-start", step.Condition);
                    s.CompleteStep();
                }
            }
            Console.WriteLine($"wrote {count} generated participants to {folder}");
            return 0;
        }

        static int Summarize(string folder, string csvPath, string plotPath)
        {
            var results = StudyResults.Load(folder);
            foreach (var p in results.Problems) Console.WriteLine($"problem: {p}");
            if (results.Participants.Count == 0) throw new UsageException($"no readable participant journals in {folder}");
            var conditions = results.Conditions;
            var complete = results.Participants.Where(p => conditions.All(c => p.Conditions.ContainsKey(c))).ToList();
            if (results.Problems.Count > 0) Console.WriteLine($"{results.Problems.Count} problem(s) above: the figures below leave out every value they name as not used");
            Console.WriteLine($"{results.Participants.Count} participants, {complete.Count} with every condition's SSQ (the ANOVAs use these)");
            Console.WriteLine();
            Console.WriteLine($"{"condition",-18} {"n",3} " + string.Join(" ", Scores.Select(s => $"{s,17}")));
            void Row(string name, List<SsqScores> values)
            {
                var cells = Scores.Select(s =>
                {
                    var v = values.Select(x => Get(x, s)).ToList();
                    return $"{Mean(v),8:F2} ± {Sd(v),6:F2}";
                });
                Console.WriteLine($"{name,-18} {values.Count,3} " + string.Join(" ", cells));
            }
            Row("pre-exposure", results.Participants.Where(p => p.PreExposure.HasValue).Select(p => p.PreExposure.Value).ToList());
            Row("baseline (real)", results.Participants.Where(p => p.Baseline.HasValue).Select(p => p.Baseline.Value).ToList());
            foreach (var c in conditions) Row(c, results.Participants.Where(p => p.Conditions.ContainsKey(c)).Select(p => p.Conditions[c]).ToList());
            Console.WriteLine("(mean ± SD; Kennedy et al. 1993 weights: N x 9.54, O x 7.58, D x 13.92, Total x 3.74)");

            if (complete.Count >= 2 && conditions.Count >= 2)
            {
                Console.WriteLine();
                Console.WriteLine("Repeated-measures ANOVA over the VR conditions (Greenhouse-Geisser corrected p beside the uncorrected):");
                int pairs = conditions.Count * (conditions.Count - 1) / 2;
                foreach (var s in Scores)
                {
                    var data = complete.Select(p => conditions.Select(c => Get(p.Conditions[c], s)).ToArray()).ToList();
                    var a = RepeatedMeasuresAnova.Compute(data);
                    Console.WriteLine(string.Format(Ci, "{0,-15} F({1:F0}, {2:F0}) = {3:F2}, p = {4:F4}; epsilon {5:F3}, p(GG) = {6:F4}; partial eta^2 = {7:F3}",
                        s, a.DfConditions, a.DfError, a.F, a.P, a.Epsilon, a.PCorrected, a.PartialEtaSquared));
                    for (int i = 0; i < conditions.Count; i++)
                    for (int j = i + 1; j < conditions.Count; j++)
                    {
                        var x = complete.Select(p => Get(p.Conditions[conditions[i]], s)).ToList();
                        var y = complete.Select(p => Get(p.Conditions[conditions[j]], s)).ToList();
                        var t = PairedComparison.Compute(conditions[i], conditions[j], x, y, pairs);
                        Console.WriteLine(string.Format(Ci, "    {0} - {1}: mean difference {2:F2}, t({3:F0}) = {4:F2}, p(Bonferroni x{5}) = {6:F4}",
                            t.A, t.B, t.MeanDifference, t.Df, t.T, pairs, t.PBonferroni));
                    }
                }
            }
            csvPath ??= Path.Combine(folder, "ssq.csv");
            WriteCsv(csvPath, results);
            Console.WriteLine();
            Console.WriteLine($"wrote {csvPath}");
            plotPath ??= Path.Combine(folder, "ssq.png");
            WritePlot(plotPath, results);
            return 0;
        }

        static double Mean(List<double> v) => v.Count == 0 ? double.NaN : v.Average();

        static double Sd(List<double> v)
        {
            if (v.Count < 2) return double.NaN;
            double m = v.Average();
            return Math.Sqrt(v.Sum(x => (x - m) * (x - m)) / (v.Count - 1));
        }

        static void WriteCsv(string path, StudyResults results)
        {
            var sb = new StringBuilder("participant,condition,position,total,nausea,oculomotor,disorientation,pre_total,pre_nausea,pre_oculomotor,pre_disorientation\n");
            string F(double v) => v.ToString("F2", Ci);
            foreach (var p in results.Participants)
            {
                void Line(string condition, int position, SsqScores s)
                {
                    sb.Append(p.Participant).Append(',').Append(condition).Append(',').Append(position > 0 ? position.ToString(Ci) : "").Append(',')
                      .Append(string.Join(",", Scores.Select(k => F(Get(s, k))))).Append(',');
                    sb.Append(p.PreExposure.HasValue ? string.Join(",", Scores.Select(k => F(Get(p.PreExposure.Value, k)))) : ",,,").Append('\n');
                }
                if (p.Baseline.HasValue) Line("baseline", 0, p.Baseline.Value);
                foreach (var c in results.Conditions)
                    if (p.Conditions.TryGetValue(c, out var s)) Line(c, p.Position.TryGetValue(c, out int pos) ? pos : 0, s);
            }
            AtomicFile.WriteAllText(path, sb.ToString());
        }

        /// <summary>Grouped bars (mean and SD) per score and condition as SVG; PNG through rsvg-convert (librsvg2-bin).</summary>
        static void WritePlot(string pngPath, StudyResults results)
        {
            var groups = new List<(string name, List<SsqScores> values)>
            {
                ("baseline", results.Participants.Where(p => p.Baseline.HasValue).Select(p => p.Baseline.Value).ToList()),
            };
            foreach (var c in results.Conditions) groups.Add((c, results.Participants.Where(p => p.Conditions.ContainsKey(c)).Select(p => p.Conditions[c]).ToList()));
            string[] colours = { "#9e9e9e", "#4e79a7", "#f28e2b", "#59a14f", "#e15759", "#76b7b2" };
            double max = 10;
            foreach (var g in groups)
                foreach (var s in Scores)
                {
                    var v = g.values.Select(x => Get(x, s)).ToList();
                    if (v.Count > 0) max = Math.Max(max, Mean(v) + (double.IsNaN(Sd(v)) ? 0 : Sd(v)));
                }
            max = Math.Ceiling(max / 20) * 20;
            const int width = 760, height = 420, left = 60, bottom = 360, top = 40;
            double groupWidth = (width - left - 20) / (double)Scores.Length, bar = groupWidth * 0.8 / groups.Count;
            var svg = new StringBuilder();
            svg.Append($"<svg xmlns='http://www.w3.org/2000/svg' width='{width}' height='{height}' font-family='sans-serif' font-size='12'>");
            svg.Append($"<rect width='{width}' height='{height}' fill='white'/>");
            svg.Append($"<text x='{width / 2}' y='22' text-anchor='middle' font-size='15'>SSQ scores per condition (mean and SD)</text>");
            for (double y = 0; y <= max + 1e-9; y += max / 5)
            {
                double py = bottom - y / max * (bottom - top);
                svg.Append(string.Format(Ci, "<line x1='{0}' y1='{1:F1}' x2='{2}' y2='{1:F1}' stroke='#ddd'/><text x='{3}' y='{4:F1}' text-anchor='end'>{5:F0}</text>", left, py, width - 20, left - 6, py + 4, y));
            }
            for (int si = 0; si < Scores.Length; si++)
            {
                double gx = left + si * groupWidth + groupWidth * 0.1;
                for (int gi = 0; gi < groups.Count; gi++)
                {
                    var v = groups[gi].values.Select(x => Get(x, Scores[si])).ToList();
                    if (v.Count == 0) continue;
                    double m = Mean(v), sd = double.IsNaN(Sd(v)) ? 0 : Sd(v);
                    double x = gx + gi * bar, h = m / max * (bottom - top);
                    svg.Append(string.Format(Ci, "<rect x='{0:F1}' y='{1:F1}' width='{2:F1}' height='{3:F1}' fill='{4}'/>", x, bottom - h, bar * 0.9, h, colours[gi % colours.Length]));
                    double cx = x + bar * 0.45, y1 = bottom - (m + sd) / max * (bottom - top), y0 = bottom - Math.Max(0, m - sd) / max * (bottom - top);
                    svg.Append(string.Format(Ci, "<line x1='{0:F1}' y1='{1:F1}' x2='{0:F1}' y2='{2:F1}' stroke='black'/>", cx, y0, y1));
                }
                svg.Append(string.Format(Ci, "<text x='{0:F1}' y='{1}' text-anchor='middle'>{2}</text>", left + (si + 0.5) * groupWidth, bottom + 18, Scores[si]));
            }
            for (int gi = 0; gi < groups.Count; gi++)
                svg.Append(string.Format(Ci, "<rect x='{0}' y='{1}' width='12' height='12' fill='{2}'/><text x='{3}' y='{4}'>{5} (n={6})</text>",
                    left + gi * 170, height - 30, colours[gi % colours.Length], left + gi * 170 + 16, height - 20, groups[gi].name, groups[gi].values.Count));
            svg.Append("</svg>");
            SvgPicture.Write(svg.ToString(), pngPath);
        }
    }
}
