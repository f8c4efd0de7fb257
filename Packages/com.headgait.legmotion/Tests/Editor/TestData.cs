using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>The package's committed sample recordings, loaded once per test run.</summary>
    public static class TestData
    {
        static readonly Dictionary<string, Recording> Cache = new Dictionary<string, Recording>();
        static CorrelationTemplate template;
        static ThresholdSettings threshold;
        static (WalkingGate Threshold, WalkingGate Correlation, WalkingGate Learned)? gates;
        static PhaseMap map;
        static List<Recording> training;

        public static string Folder
        {
            get
            {
                string f = SamplePaths.FindRecordingsFolder(TestContext.CurrentContext.TestDirectory);
                Assert.That(f, Is.Not.Null, "Samples~/Recordings not found above the test directory");
                return f;
            }
        }

        public static Recording Eval(string name) => Load(Path.Combine(Folder, "eval", name + ".csv"));

        /// <summary>The package's Models/ folder; the test fails when none is found above the test directory.</summary>
        public static string ModelsFolder
            => SamplePaths.FindModelsFolder(TestContext.CurrentContext.TestDirectory) ?? throw new AssertionException("package Models/ folder not found");

        /// <summary>The package's shipped models, read afresh so a test may change them.</summary>
        public static GaitModels ShippedModels() => GaitModels.Load(ModelsFolder);

        /// <summary>The package's committed THR (trained on people), read afresh so a test may change it.</summary>
        public static ThresholdSettings CommittedThreshold => ThresholdSettings.Load(Path.Combine(ModelsFolder, GaitModels.ThresholdFile));

        public static Recording Load(string path)
        {
            lock (Cache)
            {
                if (!Cache.TryGetValue(path, out var r))
                {
                    r = RecordingCsv.Load(path);
                    Cache[path] = r;
                }
                return r;
            }
        }

        public static List<Recording> Training
        {
            get
            {
                lock (Cache)
                {
                    if (training == null)
                    {
                        training = new List<Recording>();
                        foreach (var f in SamplePaths.List(Folder, "train")) training.Add(Load(f));
                    }
                    return training;
                }
            }
        }

        public static List<Recording> EvalSet()
        {
            var list = new List<Recording>();
            foreach (var f in SamplePaths.List(Folder, "eval")) list.Add(Load(f));
            return list;
        }

        /// <summary>The phase map learned from the generated training recordings.</summary>
        public static PhaseMap Map => map ?? (map = global::HeadGait.Training.PhaseMapTraining.Learn(TrainingSet));

        /// <summary>Every classifier's walking gate, trained as `headgait train` does on the generated training recordings.</summary>
        public static (WalkingGate Threshold, WalkingGate Correlation, WalkingGate Learned) Gates => gates ?? (gates = global::HeadGait.Training.GaitTraining.TrainGates(TrainingSet)).Value;

        /// <summary>COR trained as `headgait train` does, on the generated training recordings.</summary>
        public static CorrelationTemplate Template => template ?? (template = global::HeadGait.Training.GaitTraining.TrainCorrelation(TrainingSet, Map, Gates.Correlation));

        /// <summary>THR trained as `headgait train` does, on the generated training recordings.</summary>
        public static ThresholdSettings Threshold => threshold ?? (threshold = global::HeadGait.Training.GaitTraining.TrainThreshold(TrainingSet, Map, Gates.Threshold));

        /// <summary>
        /// The generated training recordings with augmented copies, as `headgait train` makes them; eight per recording
        /// rather than two, because three recordings with two copies each would sample the amplitude range too thinly.
        /// </summary>
        static List<Recording> TrainingSet => augmented ?? (augmented = global::HeadGait.Training.GaitTraining.WithAugmentation(Training, 8));

        static List<Recording> augmented;

        public static ImuSample Still(double t) => new ImuSample(t, 0, 0, 9.80665);

        /// <summary>What <paramref name="read"/> gives at each full window, with whether the labels say walking there.</summary>
        public static List<(bool Walking, T Value)> PerWindowTruth<T>(Recording r, int history, Func<SignalWindow, T> read)
        {
            var rows = new List<(bool, T)>();
            var pre = new StreamPreprocessor(new PreprocessorSettings { History = history });
            var labels = new LabelCursor(r);
            foreach (var s in r.Samples)
                pre.Push(s.Imu, w =>
                {
                    if (labels.TryLabelsAt(w.EndTime, out var truth) && w.Count >= w.Length)
                        rows.Add((truth.Left != GaitPhase.Standing, read(w)));
                });
            return rows;
        }

        /// <summary>What <paramref name="read"/> makes of every full window (<paramref name="history"/> samples) of a recording.</summary>
        public static List<T> PerWindow<T>(Recording r, int history, Func<SignalWindow, T> read)
        {
            var rows = new List<T>();
            var pre = new StreamPreprocessor(new PreprocessorSettings { History = history });
            foreach (var s in r.Samples)
                pre.Push(s.Imu, w =>
                {
                    if (w.Count >= w.Length) rows.Add(read(w));
                });
            return rows;
        }

        /// <summary>
        /// A folder of the real-motion data beside the repository (../shared/data/SUB, or $HEADGAIT_DATA/SUB). The data is
        /// not part of the package (licence), so a test that needs it is skipped with the path it looked for when it is absent.
        /// </summary>
        public static string SharedData(string sub)
        {
            var env = Environment.GetEnvironmentVariable("HEADGAIT_DATA");
            var candidates = new List<string>();
            if (!string.IsNullOrEmpty(env)) candidates.Add(Path.Combine(env, sub));
            string package = Path.GetDirectoryName(Path.GetDirectoryName(Folder)); // .../Packages/com.headgait.legmotion
            string repo = Path.GetDirectoryName(Path.GetDirectoryName(package));
            candidates.Add(Path.Combine(Path.GetDirectoryName(repo), "shared", "data", sub));
            foreach (var c in candidates)
                if (Directory.Exists(c)) return c;
            Assert.Ignore($"real-motion data not found (looked for {string.Join(" and ", candidates)})");
            return null;
        }

        /// <summary>
        /// The real glasses recordings (`glasses-train` in <see cref="SharedData"/>) whose file names match
        /// <paramref name="pattern"/>, in ordinal name order; the test is skipped when there are none.
        /// </summary>
        public static List<string> GlassesFiles(string pattern = "*.csv")
        {
            string folder = SharedData("glasses-train");
            var files = Directory.GetFiles(folder, pattern).OrderBy(f => f, StringComparer.Ordinal).ToList();
            if (files.Count == 0) Assert.Ignore($"no {pattern} recordings in {folder}");
            return files;
        }
    }
}
