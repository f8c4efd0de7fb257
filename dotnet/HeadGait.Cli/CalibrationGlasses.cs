using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using System.Threading.Tasks;
using HeadGait.Calibration;

namespace HeadGait.Cli
{
    /// <summary>
    /// The calibration on real head-worn recordings without labels (e.g. ../shared/data/glasses-train): each person's walking
    /// file is split after its first <c>seconds</c>; that first part is the calibration walk (self-supervised: no ankle
    /// trackers), the rest is replayed with and without the profile, and so are the person's standing, head-movement and
    /// pick-up files. Walking time is where the signal itself shows a regular step rhythm (<see cref="RhythmReference"/>).
    /// </summary>
    static class CalibrationGlasses
    {
        public static int Run(string[] data, string modelFolder, List<string> names, double seconds, string adapt)
        {
            var settings = CalibrationBenchmark.Settings(adapt).Self;
            if (adapt != null) Console.WriteLine($"Refitted (--adapt {adapt}): {CalibrationBenchmark.Describe(settings)}");
            var recordings = Inputs.LoadRecordings(Inputs.Expand(data, "*.csv"), false);
            string folder = modelFolder ?? SamplePaths.FindModelsFolder() ?? throw new UsageException("no --models and no package Models/ folder found");
            var shipped = Classifiers.Load(folder);
            var people = recordings.GroupBy(RealActivity.PersonOf).OrderBy(g => g.Key, StringComparer.Ordinal).ToList();
            Console.WriteLine($"HeadGait calibration on real recordings: {recordings.Count} recordings of {people.Count} people; each person calibrated (self-supervised) on the first {seconds:F0} s of their walking file");
            // classifier -> variant -> (walking rest scores, still scores by activity)
            var walking = new Dictionary<(string clf, int v), List<RealWorldScore>>();
            var still = new Dictionary<(string clf, int v, string activity), List<RealWorldScore>>();
            var notes = new List<string>();
            // classifier -> activity -> (people whose avatar shows that activity as walking longer after calibration, people scored)
            var rises = new Dictionary<(string clf, string activity), (List<string> risen, int people)>();
            foreach (var person in people)
            {
                var walk = person.FirstOrDefault(r => RealActivity.Of(r) == RealActivity.Walking);
                if (walk == null || walk.Samples.Count < 2) continue;
                double cut = walk.Samples[0].Imu.Time + seconds;
                var first = Part(walk, s => s.Imu.Time < cut, "_first");
                var rest = Part(walk, s => s.Imu.Time >= cut, "_rest");
                if (rest.Samples.Count < 500)
                {
                    notes.Add($"{person.Key}: walking file shorter than {seconds + 5:F0} s; skipped");
                    continue;
                }
                WearerProfile profile;
                var clock = System.Diagnostics.Stopwatch.StartNew();
                try
                {
                    profile = new CalibrationSession(first).Fit(shipped, Safe(person.Key), selfSupervised: true, settings);
                }
                catch (InvalidOperationException e)
                {
                    notes.Add($"{person.Key}: not calibrated ({e.Message}); {ContactRhythm(shipped, first)}");
                    continue;
                }
                double fitSeconds = clock.Elapsed.TotalSeconds;
                var adapted = profile.Apply(shipped);
                var scored = new List<Recording> { rest };
                scored.AddRange(person.Where(r => RealActivity.IsStill(RealActivity.Of(r))));
                var references = scored.Select(RhythmReference.Of).ToList();
                foreach (var clf in names)
                {
                    var avatarStill = new Dictionary<string, double[]>();
                    for (int v = 0; v < 2; v++)
                    {
                        var models = v == 0 ? shipped : adapted;
                        var scores = new RealWorldScore[scored.Count];
                        Parallel.For(0, scored.Count, i =>
                        {
                            var c = models.Create(clf, out _);
                            var result = ReplayEvaluator.Run(scored[i], c, keepTrace: true);
                            scores[i] = RealWorldScore.Of(scored[i], references[i], c.Name, result.Predictions, result.Frames);
                        });
                        Add(walking, (clf, v), scores[0]);
                        for (int i = 1; i < scores.Length; i++)
                        {
                            Add(still, (clf, v, scores[i].Activity), scores[i]);
                            if (!avatarStill.TryGetValue(scores[i].Activity, out var sec)) avatarStill[scores[i].Activity] = sec = new double[2];
                            sec[v] += scores[i].AvatarWalkingSeconds;
                        }
                    }
                    foreach (var kv in avatarStill)
                    {
                        rises.TryGetValue((clf, kv.Key), out var r);
                        r.risen ??= new List<string>();
                        if (kv.Value[1] > kv.Value[0] + 1e-9) r.risen.Add(string.Format(CultureInfo.InvariantCulture, "{0} {1:F1}->{2:F1} s", person.Key, kv.Value[0], kv.Value[1]));
                        rises[(clf, kv.Key)] = (r.risen, r.people + 1);
                    }
                }
                Console.WriteLine(string.Format(CultureInfo.InvariantCulture, "{0,-10} {1} sure steps of {2:F0} s; COR {3}, THR {4}, learned gain {5:F2}{7}; fitted in {6:F1} s", person.Key, profile.Steps, first.Duration,
                    profile.Correlation.Templates.Count > shipped.Correlation.Templates.Count ? "own step added" : "as shipped",
                    profile.Threshold.Serialize() == shipped.Threshold.Serialize() ? "as shipped" : "refitted", profile.LearnedGain, fitSeconds, profile.LearnedTimeScale != 1 ? string.Format(CultureInfo.InvariantCulture, ", learned time scale {0:F2}", profile.LearnedTimeScale) : ""));
            }
            Console.WriteLine();
            Console.WriteLine("Share of the rest of the walk (where the signal shows steps) shown as walking by the classifier / the avatar; still activities' time shown as walking (classifier / avatar):");
            // Every still activity these recordings hold (RealActivity.StillActivities' order): each was scored above.
            var stillActivities = RealActivity.StillActivities.Where(a => still.Keys.Any(k => k.activity == a)).ToList();
            Console.WriteLine($"{"clf",-7} {"walking, none",18} {"walking, self",18} {"d_clf",6} " + string.Join(" ", stillActivities.Select(a => $"{a + " none/self",34}")));
            foreach (var clf in names)
            {
                string Share(int v)
                {
                    if (!walking.TryGetValue((clf, v), out var l)) return "-";
                    double inRef = l.Sum(x => x.ReferenceWalkingSeconds);
                    return string.Format(CultureInfo.InvariantCulture, "{0:F1} / {1:F1} %", 100 * l.Sum(x => x.ClassifierWalkingInReference) / inRef, 100 * l.Sum(x => x.AvatarWalkingInReference) / inRef);
                }
                double Clf(int v) => walking.TryGetValue((clf, v), out var l) ? 100 * l.Sum(x => x.ClassifierWalkingInReference) / l.Sum(x => x.ReferenceWalkingSeconds) : double.NaN;
                string Still(string activity)
                {
                    string One(int v) => still.TryGetValue((clf, v, activity), out var l)
                        ? string.Format(CultureInfo.InvariantCulture, "{0:F1}/{1:F1}", 100 * l.Sum(x => x.ClassifierWalkingSeconds) / l.Sum(x => x.Seconds), 100 * l.Sum(x => x.AvatarWalkingSeconds) / l.Sum(x => x.Seconds))
                        : "-";
                    return $"{One(0) + " | " + One(1),34}";
                }
                Console.WriteLine(string.Format(CultureInfo.InvariantCulture, "{0,-7} {1,18} {2,18} {3,6:+0.0;-0.0} {4}", clf, Share(0), Share(1), Clf(1) - Clf(0),
                    string.Join(" ", stillActivities.Select(Still))));
            }
            Console.WriteLine();
            Console.WriteLine("People whose still activity the avatar shows as walking longer with their profile than without (time none->self):");
            foreach (var clf in names)
                foreach (var activity in stillActivities)
                    if (rises.TryGetValue((clf, activity), out var r))
                        Console.WriteLine($"{clf,-7} {activity,-22} {r.risen.Count} of {r.people}" + (r.risen.Count > 0 ? ": " + string.Join(", ", r.risen) : ""));
            foreach (var n in notes) Console.WriteLine("note: " + n);
            return 0;
        }

        /// <summary>Why a walk gave too few sure steps: how many contacts COR (gate open) found in it and how far apart.</summary>
        static string ContactRhythm(GaitModels models, Recording walk)
        {
            var cor = new CorrelationClassifier(models.Correlation.With(gate: WalkingGate.Open), WearerAdaptation.SelfLabelSettings);
            var times = new List<double>();
            cor.ContactDetected += (t, e, r, k) => times.Add(t);
            var pre = new StreamPreprocessor(new PreprocessorSettings { History = cor.WindowLength });
            foreach (var s in walk.Samples) pre.Push(s.Imu, w => cor.Classify(w));
            var gaps = times.Zip(times.Skip(1), (a, b) => b - a).ToList();
            if (gaps.Count == 0) return "COR (gate open) found no steps";
            gaps.Sort();
            double Q(double q) => gaps[(int)Math.Round(q * (gaps.Count - 1))];
            return string.Format(CultureInfo.InvariantCulture, "COR (gate open) found {0} contacts, {1:F2} / {2:F2} / {3:F2} s apart (quartiles), {4} of {5} gaps 0.3-1 s",
                times.Count, Q(0.25), Q(0.5), Q(0.75), gaps.Count(g => g >= 0.3 && g <= 1.0), gaps.Count);
        }

        static void Add<TKey>(Dictionary<TKey, List<RealWorldScore>> d, TKey key, RealWorldScore s)
        {
            if (!d.TryGetValue(key, out var l)) d[key] = l = new List<RealWorldScore>();
            l.Add(s);
        }

        static string Safe(string person)
        {
            var chars = person.Select(ch => ch < 128 && (char.IsLetterOrDigit(ch) || ch == '-' || ch == '_' || ch == '.') ? ch : '_').ToArray();
            string s = new string(chars).TrimStart('.');
            return s.Length == 0 ? "wearer" : s.Length > 64 ? s.Substring(0, 64) : s;
        }

        static Recording Part(Recording r, Func<RecordedSample, bool> keep, string suffix)
        {
            var part = new Recording(r.Name + suffix, r.Samples.Where(keep).ToList());
            foreach (var kv in r.Metadata) part.Metadata[kv.Key] = kv.Value;
            return part;
        }
    }
}
