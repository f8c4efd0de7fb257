using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Runtime.InteropServices;
using Microsoft.ML.OnnxRuntime;

namespace HeadGait.Cost
{
    /// <summary>
    /// What the classifiers cost, measured as a user runs them: every walking window of the recordings goes to THR, COR,
    /// the SVM and the BLSTM (and the learned networks alone, and ONNX Runtime on the same standardised windows) in one
    /// interleaved run, the contenders' order turning from window to window so that whatever else the machine does hits
    /// them alike. Thread CPU time per call (less the timer's own cost), min / median / 95th percentile, and the medians of
    /// the run's rounds (consecutive slices of the recordings) as its spread. Then the whole pipeline per sample, with the
    /// managed memory it allocates once warmed up.
    /// </summary>
    static class Program
    {
        static int Main(string[] args)
        {
            string data = null, models = null;
            int rounds = 5, maxSamples = 60000;
            for (int i = 0; i < args.Length; i++)
            {
                string Next() => i + 1 < args.Length ? args[++i] : throw new ArgumentException($"{args[i]} needs a value");
                switch (args[i])
                {
                    case "--data": data = Next(); break;
                    case "--models": models = Next(); break;
                    case "--rounds": rounds = int.Parse(Next(), CultureInfo.InvariantCulture); break;
                    case "--samples": maxSamples = int.Parse(Next(), CultureInfo.InvariantCulture); break;
                    case "--no-vectors": VectorMath.UseVectors = false; break;
                    case "-h":
                    case "--help":
                        Console.WriteLine("headgait-cost [--data DIR] [--models DIR] [--samples N (default 60000)] [--rounds R (default 5)] [--no-vectors]");
                        Console.WriteLine("  --no-vectors: the learned classifiers' scalar paths, as where the runtime has no SIMD lanes (Unity's Mono).");
                        Console.WriteLine("  DIR: labelled recordings (*.csv); default: the package's embedded sample recordings.");
                        return 0;
                    default:
                        Console.Error.WriteLine($"unknown argument '{args[i]}' (--help)");
                        return 2;
                }
            }
            if (rounds < 1 || maxSamples < 1000)
            {
                Console.Error.WriteLine("--rounds must be at least 1 and --samples at least 1000");
                return 2;
            }
            models ??= SamplePaths.FindModelsFolder(AppContext.BaseDirectory, Directory.GetCurrentDirectory());
            if (models == null)
            {
                Console.Error.WriteLine("no --models and no package Models/ folder found");
                return 2;
            }
            string[] files;
            if (data != null)
            {
                if (!Directory.Exists(data))
                {
                    Console.Error.WriteLine($"{data}: no such folder");
                    return 2;
                }
                files = Directory.GetFiles(data, "*.csv").OrderBy(f => f, StringComparer.Ordinal).ToArray();
            }
            else files = SamplePaths.List(SamplePaths.RequireRecordingsFolder(AppContext.BaseDirectory, Directory.GetCurrentDirectory()), "eval");
            if (files.Length < 2)
            {
                Console.Error.WriteLine("needs at least two recordings (the first only warms up)");
                return 2;
            }
            var recordings = Pick(files, maxSamples);
            return new CostRun(models, recordings, rounds).Run();
        }

        /// <summary>Recordings spread evenly over the list until about <paramref name="maxSamples"/> samples are taken.</summary>
        static List<Recording> Pick(string[] files, int maxSamples)
        {
            var all = files.Select(f => RecordingCsv.Load(f, false)).Where(r => r.Samples.Count > 200).ToList();
            long total = all.Sum(r => (long)r.Samples.Count);
            int every = (int)Math.Max(1, total / maxSamples);
            var picked = new List<Recording>();
            long taken = 0;
            for (int i = 0; i < all.Count && (taken < maxSamples || picked.Count < 2); i += every)
            {
                picked.Add(all[i]);
                taken += all[i].Samples.Count;
            }
            // The first recording only warms up: at least one more is measured.
            if (picked.Count < 2 && all.Count >= 2) picked.Add(all[all.Count - 1]);
            return picked;
        }
    }

    /// <summary>CPU time this thread has run (ns): CLOCK_THREAD_CPUTIME_ID on Linux, else wall time (said so in the output).</summary>
    static class ThreadClock
    {
        [StructLayout(LayoutKind.Sequential)]
        struct Timespec
        {
            public long Seconds, Nanoseconds;
        }

        [DllImport("libc", EntryPoint = "clock_gettime")]
        static extern int ClockGetTime(int clock, out Timespec time);

        const int ThreadCpuClock = 3;
        public static readonly bool IsCpuTime = Probe();

        static bool Probe()
        {
            try
            {
                return OperatingSystem.IsLinux() && ClockGetTime(ThreadCpuClock, out _) == 0;
            }
            catch (Exception e) when (e is DllNotFoundException || e is EntryPointNotFoundException)
            {
                return false;
            }
        }

        public static long Now()
        {
            if (IsCpuTime)
            {
                ClockGetTime(ThreadCpuClock, out var t);
                return t.Seconds * 1_000_000_000 + t.Nanoseconds;
            }
            return (long)(Stopwatch.GetTimestamp() * (1e9 / Stopwatch.Frequency));
        }
    }

    /// <summary>One contender's times (µs), kept per round.</summary>
    sealed class Times
    {
        public readonly string Name;
        public readonly List<double>[] Rounds;
        public Times(string name, int rounds)
        {
            Name = name;
            Rounds = Enumerable.Range(0, rounds).Select(_ => new List<double>(1 << 14)).ToArray();
        }

        public void Add(int round, double us) => Rounds[round].Add(us);
        public int Count => Rounds.Sum(r => r.Count);

        public static double Percentile(List<double> sorted, double q)
        {
            if (sorted.Count == 0) return double.NaN;
            double pos = q * (sorted.Count - 1);
            int lo = (int)Math.Floor(pos), hi = Math.Min(sorted.Count - 1, lo + 1);
            return sorted[lo] + (sorted[hi] - sorted[lo]) * (pos - lo);
        }

        public (double min, double median, double p95, double roundLo, double roundHi) Summary()
        {
            var all = Rounds.SelectMany(r => r).OrderBy(v => v).ToList();
            var medians = Rounds.Where(r => r.Count > 0).Select(r => Percentile(r.OrderBy(v => v).ToList(), 0.5)).ToList();
            return (all.Count > 0 ? all[0] : double.NaN, Percentile(all, 0.5), Percentile(all, 0.95),
                medians.Count > 0 ? medians.Min() : double.NaN, medians.Count > 0 ? medians.Max() : double.NaN);
        }
    }

    /// <summary>A learned model's ONNX export in ONNX Runtime: batch 1, one thread, buffers bound once.</summary>
    sealed class OnnxModel : IDisposable
    {
        readonly InferenceSession session;
        readonly RunOptions runOptions = new RunOptions();
        readonly float[] input;
        readonly float[][] outputs;
        readonly OrtValue inputValue;
        readonly OrtValue[] outputValues;
        readonly string[] inputNames, outputNames;

        public OnnxModel(string path, int width, params (string name, int length)[] outputSpec)
        {
            var options = new SessionOptions
            {
                IntraOpNumThreads = 1,
                InterOpNumThreads = 1,
                ExecutionMode = ExecutionMode.ORT_SEQUENTIAL,
                GraphOptimizationLevel = GraphOptimizationLevel.ORT_ENABLE_ALL,
            };
            session = new InferenceSession(path, options);
            inputNames = new[] { session.InputMetadata.Keys.First() };
            var dims = session.InputMetadata[inputNames[0]].Dimensions;
            input = new float[width];
            inputValue = OrtValue.CreateTensorValueFromMemory(input, new long[] { 1, dims[1], dims[2] });
            outputNames = outputSpec.Select(o => o.name).ToArray();
            outputs = outputSpec.Select(o => new float[o.length]).ToArray();
            outputValues = outputs.Select(o => OrtValue.CreateTensorValueFromMemory(o, new long[] { 1, o.Length })).ToArray();
        }

        public float[] Input => input;
        public float[] Output(int i) => outputs[i];

        public void Run() => session.Run(runOptions, inputNames, new[] { inputValue }, outputNames, outputValues);

        public void Dispose()
        {
            inputValue.Dispose();
            foreach (var o in outputValues) o.Dispose();
            runOptions.Dispose();
            session.Dispose();
        }
    }

    sealed class CostRun
    {
        readonly string modelsFolder;
        readonly List<Recording> recordings;
        readonly int rounds;
        readonly GaitModels models;

        public CostRun(string modelsFolder, List<Recording> recordings, int rounds)
        {
            this.modelsFolder = modelsFolder;
            this.recordings = recordings;
            this.rounds = rounds;
            models = GaitModels.Load(modelsFolder);
        }

        static double overheadNs;

        /// <summary>The timer's own cost (ns): the median of many empty measurements, subtracted from every call.</summary>
        static void Calibrate()
        {
            var v = new List<double>(20000);
            for (int i = 0; i < 20000; i++)
            {
                long a = ThreadClock.Now();
                long b = ThreadClock.Now();
                v.Add(b - a);
            }
            v.Sort();
            overheadNs = v[v.Count / 2];
        }

        static double Us(long startNs, long endNs) => Math.Max(0, endNs - startNs - overheadNs) / 1000.0;

        public int Run()
        {
            foreach (var p in models.Problems) Console.WriteLine($"warning: {p}");
            if (models.Threshold == null || models.Correlation == null || models.Svm == null || models.Blstm == null)
            {
                Console.Error.WriteLine($"{modelsFolder}: all four models are needed");
                return 1;
            }
            Calibrate();
            Console.WriteLine($"headgait-cost: {recordings.Count} recordings, {recordings.Sum(r => r.Samples.Count)} samples; {rounds} rounds; "
                + $"{(ThreadClock.IsCpuTime ? "thread CPU time" : "wall time (no thread CPU clock here)")}, timer cost {overheadNs:F0} ns subtracted; "
                + $"SIMD {(System.Numerics.Vector.IsHardwareAccelerated ? "on" : "off")}, {System.Numerics.Vector<float>.Count} float lanes, learned classifiers {(VectorMath.UseVectors ? "in lanes" : "on their scalar paths")}; {Environment.ProcessorCount} cores");
            string svmOnnx = Path.Combine(modelsFolder, "svm.onnx"), blstmOnnx = Path.Combine(modelsFolder, "blstm.onnx");
            OnnxModel ortSvm = null, ortBlstm = null;
            try
            {
                ortBlstm = new OnnxModel(blstmOnnx, new BlstmClassifier(models.Blstm).Features.Width, ("probabilities", 17));
                ortSvm = new OnnxModel(svmOnnx, new SvmClassifier(models.Svm).Features.Width, ("votes", 17), ("decision", 136));
                Console.WriteLine($"ONNX Runtime {OrtEnv.Instance().GetVersionString()}: {Path.GetFileName(blstmOnnx)}, {Path.GetFileName(svmOnnx)}; batch 1, one thread");
            }
            catch (Exception e) when (e is DllNotFoundException || e is TypeInitializationException || e is OnnxRuntimeException || e is BadImageFormatException || e is FileNotFoundException || e is EntryPointNotFoundException)
            {
                var cause = e.InnerException ?? e;
                Console.WriteLine($"ONNX Runtime could not be used ({cause.GetType().Name}: {cause.Message.Split('\n')[0]}): C# figures only, no ratios.");
                ortBlstm?.Dispose();
                ortBlstm = null;
                ortSvm = null;
            }
            PerWindow(ortBlstm, ortSvm);
            PerSample();
            ortBlstm?.Dispose();
            ortSvm?.Dispose();
            return 0;
        }

        int RoundOf(int recording) => Math.Min(rounds - 1, (recording - 1) * rounds / Math.Max(1, recordings.Count - 1));

        void PerWindow(OnnxModel ortBlstm, OnnxModel ortSvm)
        {
            var thr = new ThresholdClassifier(models.Threshold);
            var cor = new CorrelationClassifier(models.Correlation);
            var svm = (SvmClassifier)models.SvmOf(models.Svm); // as the product makes it (THR's trained step clock beside it)
            var blstm = (BlstmClassifier)models.BlstmOf(models.Blstm);
            // The networks alone run on the classifiers' own instances (one copy of the weights, as in an app): scoring
            // does not touch the time filter's state.
            var blstmNet = blstm;
            var svmNet = svm;
            var svmBatch = svm;
            var classifiers = new IGaitClassifier[] { thr, cor, svm, blstm };
            int history = classifiers.Max(c => c.WindowLength);
            var pre = new StreamPreprocessor(new PreprocessorSettings { History = Math.Max(history, new PreprocessorSettings().History) });
            int width = svm.Features.Width, classes = svm.Segments.ClassCount, pairs = svm.OutputCount;
            var t = new List<Times>
            {
                new Times("THR classify", rounds), new Times("COR classify", rounds), new Times("SVM classify", rounds), new Times("BLSTM classify", rounds),
                new Times("BLSTM network, batch 1", rounds), new Times("SVM network, batch 1", rounds),
                new Times("SVM network, 2 per call (per window)", rounds), new Times("SVM network, 4 per call (per window)", rounds),
                new Times("BLSTM ONNX Runtime, batch 1", rounds), new Times("SVM ONNX Runtime, batch 1", rounds),
            };
            var blstmFeatures = new double[blstm.Features.Width];
            var svmFeatures = new double[width];
            var batch = new double[4 * width];
            var batchDecisions = new double[4 * pairs];
            var pairDecisions = new double[2 * pairs];
            var singleDecisions = new double[4 * pairs];
            var net = new double[classes];       // the BLSTM network's probabilities
            var svmDecision = new double[pairs]; // the SVM network's decision values
            int inBatch = 0, rotation = 0, round = 0;
            double blstmDiff = 0, svmVoteDiff = 0, svmDecisionDiff = 0, batchDiff = 0;
            long blstmDisagree = 0, svmDisagree = 0, compared = 0;
            bool counted = false, walking = false;
            void Window(SignalWindow w)
            {
                if (!counted || !walking)
                {
                    foreach (var c in classifiers) c.Classify(w);
                    return;
                }
                // The timed classifiers read a copy: the preprocessor's window keeps the rhythm one of them read
                // (StepRhythm.Of), which would spare the next its cost; the pipeline rows below share it as an app does.
                var copy = w.Clone();
                Array.Copy(blstm.Standardise(w), blstmFeatures, blstmFeatures.Length);
                Array.Copy(svm.Standardise(w), svmFeatures, width);
                // Windows scored together (a 72 Hz frame holds one or two; four per pass) are timed in the rotation too,
                // when this window completes a pair or a four.
                Array.Copy(svmFeatures, 0, batch, inBatch * width, width);
                inBatch++;
                for (int k = 0; k < Timed.Length; k++)
                {
                    int which = Timed[(k + rotation) % Timed.Length];
                    long a, b;
                    switch (which)
                    {
                        case 0: case 1: case 2: case 3:
                            a = ThreadClock.Now();
                            classifiers[which].Classify(copy);
                            b = ThreadClock.Now();
                            t[which].Add(round, Us(a, b));
                            break;
                        case 4:
                            a = ThreadClock.Now();
                            blstmNet.Network.Evaluate(blstmFeatures, 1, net);
                            b = ThreadClock.Now();
                            t[4].Add(round, Us(a, b));
                            break;
                        case 5:
                            a = ThreadClock.Now();
                            svmNet.Network.Evaluate(svmFeatures, 1, svmDecision);
                            b = ThreadClock.Now();
                            t[5].Add(round, Us(a, b));
                            break;
                        case 6:
                            if (inBatch % 2 != 0) break;
                            var pair = Pair(batch, inBatch - 2, width);
                            a = ThreadClock.Now();
                            svmBatch.Network.Evaluate(pair, 2, pairDecisions);
                            b = ThreadClock.Now();
                            t[6].Add(round, Us(a, b) / 2);
                            break;
                        case 7:
                            if (inBatch != 4) break;
                            a = ThreadClock.Now();
                            svmBatch.Network.Evaluate(batch, 4, batchDecisions);
                            b = ThreadClock.Now();
                            t[7].Add(round, Us(a, b) / 4);
                            break;
                        case 8:
                            if (ortBlstm == null) break;
                            for (int i = 0; i < blstmFeatures.Length; i++) ortBlstm.Input[i] = (float)blstmFeatures[i];
                            a = ThreadClock.Now();
                            ortBlstm.Run();
                            b = ThreadClock.Now();
                            t[8].Add(round, Us(a, b));
                            break;
                        case 9:
                            if (ortSvm == null) break;
                            for (int i = 0; i < width; i++) ortSvm.Input[i] = (float)svmFeatures[i];
                            a = ThreadClock.Now();
                            ortSvm.Run();
                            b = ThreadClock.Now();
                            t[9].Add(round, Us(a, b));
                            break;
                    }
                }
                rotation++;
                // Outputs side by side: the BLSTM's probabilities, the SVM's votes and decision values.
                blstmNet.Network.Evaluate(blstmFeatures, 1, net);
                if (ortBlstm != null)
                {
                    compared++;
                    var o = ortBlstm.Output(0);
                    int mine = 0, theirs = 0;
                    for (int k = 0; k < classes; k++)
                    {
                        blstmDiff = Math.Max(blstmDiff, Math.Abs(net[k] - o[k]));
                        if (net[k] > net[mine]) mine = k;
                        if (o[k] > o[theirs]) theirs = k;
                    }
                    if (mine != theirs) blstmDisagree++;
                    var myVotes = svmNet.ScoreFeatures(svmFeatures);
                    var votes = ortSvm.Output(0);
                    var decision = ortSvm.Output(1);
                    mine = 0;
                    theirs = 0;
                    for (int k = 0; k < classes; k++)
                    {
                        svmVoteDiff = Math.Max(svmVoteDiff, Math.Abs(myVotes[k] - votes[k]));
                        if (myVotes[k] > myVotes[mine]) mine = k;
                        if (votes[k] > votes[theirs]) theirs = k;
                    }
                    if (mine != theirs) svmDisagree++;
                    for (int k = 0; k < decision.Length; k++) svmDecisionDiff = Math.Max(svmDecisionDiff, Math.Abs(svmNet.LastDecision[k] - decision[k]));
                }
                svmNet.Network.Evaluate(svmFeatures, 1, svmDecision);
                Array.Copy(svmDecision, 0, singleDecisions, (inBatch - 1) * pairs, pairs);
                if (inBatch == 4)
                {
                    for (int i = 0; i < 4 * pairs; i++) batchDiff = Math.Max(batchDiff, Math.Abs(batchDecisions[i] - singleDecisions[i]));
                    inBatch = 0;
                }
            }
            Action<SignalWindow> onWindow = Window;
            for (int r = 0; r < recordings.Count; r++)
            {
                counted = r > 0;
                round = counted ? RoundOf(r) : 0;
                pre.Reset();
                foreach (var c in classifiers) c.Reset();
                inBatch = 0;
                foreach (var s in recordings[r].Samples)
                {
                    walking = s.HasTruth && s.Left != GaitPhase.Standing;
                    pre.Push(s.Imu, onWindow);
                }
            }
            Console.WriteLine();
            Console.WriteLine($"Per walking window ({t[0].Count} windows), µs of thread CPU: min / median / 95th percentile; the rounds' medians (the run's spread)");
            Console.WriteLine($"{"",-40} {"min",8} {"median",8} {"p95",8}   rounds' medians");
            foreach (var x in t)
            {
                if (x.Count == 0) continue;
                var s = x.Summary();
                Console.WriteLine($"{x.Name,-40} {s.min,8:F2} {s.median,8:F2} {s.p95,8:F2}   {s.roundLo:F2}-{s.roundHi:F2}");
            }
            Console.WriteLine("(classify: features, network, time filter and decision, as the pipeline calls it, on a copy of the window (each pays its own step rhythm); network: the model alone on standardised features)");
            Console.WriteLine($"SVM windows scored together give the decision values they get alone: largest difference {batchDiff:G3}");
            if (ortBlstm != null)
            {
                var b = t[4].Summary();
                var ob = t[8].Summary();
                var s = t[5].Summary();
                var os = t[9].Summary();
                var s4 = t[7].Summary();
                Console.WriteLine();
                Console.WriteLine($"Beside ONNX Runtime (same windows, batch 1, one thread; medians, µs): ratio C# / ONNX Runtime");
                Console.WriteLine($"BLSTM {b.median:F1} / {ob.median:F1} = {b.median / ob.median:F2}x; largest probability difference {blstmDiff:G3}; other winning class on {blstmDisagree} of {compared} windows");
                Console.WriteLine($"SVM   {s.median:F1} / {os.median:F1} = {s.median / os.median:F2}x (4 per call: {s4.median:F1} µs per window, {s4.median / os.median:F2}x); largest vote difference {svmVoteDiff:G3}, decision value difference {svmDecisionDiff:G3}; other winning class on {svmDisagree} of {compared} windows");
            }
        }

        /// <summary>The contenders timed window by window, by their index in the list of times.</summary>
        static readonly int[] Timed = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9 };

        static double[] pairBuffer;

        static double[] Pair(double[] batch, int first, int width)
        {
            pairBuffer ??= new double[2 * width];
            Array.Copy(batch, first * width, pairBuffer, 0, 2 * width);
            return pairBuffer;
        }

        void PerSample()
        {
            var names = new[] { "thr", "cor", "svm", "blstm" };
            var pipelines = names.Select(n => new GaitPipeline(models.Create(n, out _))).ToArray();
            var times = names.Select(n => new Times(n.ToUpperInvariant(), rounds)).ToArray();
            var bytes = new long[names.Length];
            long samples = 0;
            int rotation = 0;
            for (int r = 0; r < recordings.Count; r++)
            {
                bool counted = r > 0;
                int round = counted ? RoundOf(r) : 0;
                foreach (var p in pipelines) p.Reset();
                foreach (var s in recordings[r].Samples)
                {
                    for (int k = 0; k < pipelines.Length; k++)
                    {
                        int which = (k + rotation) % pipelines.Length;
                        long m0 = GC.GetAllocatedBytesForCurrentThread();
                        long a = ThreadClock.Now();
                        pipelines[which].Push(s.Imu);
                        long b = ThreadClock.Now();
                        long m1 = GC.GetAllocatedBytesForCurrentThread();
                        if (!counted) continue;
                        times[which].Add(round, Us(a, b));
                        bytes[which] += m1 - m0;
                    }
                    rotation++;
                    if (counted) samples++;
                }
            }
            Console.WriteLine();
            Console.WriteLine($"Whole pipeline per sample ({samples} samples: preprocessing, classifier, animator), µs of thread CPU; managed bytes allocated per sample once warmed up");
            Console.WriteLine($"{"",-8} {"min",8} {"median",8} {"p95",8} {"mean",8}   rounds' medians   bytes/sample");
            for (int k = 0; k < names.Length; k++)
            {
                var s = times[k].Summary();
                double mean = times[k].Rounds.SelectMany(x => x).Average();
                Console.WriteLine($"{times[k].Name,-8} {s.min,8:F2} {s.median,8:F2} {s.p95,8:F2} {mean,8:F2}   {s.roundLo:F2}-{s.roundHi:F2}   {(double)bytes[k] / samples:F2}");
            }
        }
    }
}
