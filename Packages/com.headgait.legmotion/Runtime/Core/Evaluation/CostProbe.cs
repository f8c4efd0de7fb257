using System;
using System.Collections.Generic;
using System.Diagnostics;

namespace HeadGait
{
    /// <summary>What running a classifier in the live pipeline costs on this machine.</summary>
    public sealed class CostReport
    {
        public string Classifier;
        public long Windows;
        public long Samples;
        /// <summary>Classifier time per window (ms): mean and 95th percentile.</summary>
        public double MeanWindowMs, P95WindowMs;
        /// <summary>Whole pipeline (resampling, classifier, animator) per input sample (µs).</summary>
        public double MicrosecondsPerSample;
        /// <summary>Managed bytes allocated per input sample once warmed up (0 = allocation-free in steady state).</summary>
        public double BytesPerSample;
    }

    /// <summary>
    /// Measures the live pipeline's cost: replays recordings through one <see cref="GaitPipeline"/> (the first one only
    /// warms up the JIT and caches and is not counted), timing each window's classification and counting the managed
    /// memory allocated on this thread. A benchmark, not a test: figures depend on the machine.
    /// </summary>
    public static class CostProbe
    {
        public static CostReport Measure(IGaitClassifier classifier, IReadOnlyList<Recording> recordings)
        {
            if (recordings.Count < 2) throw new ArgumentException("Needs at least two recordings: the first only warms up.");
            var pipeline = new GaitPipeline(classifier);
            var perWindow = new List<double>(1 << 16);
            long windows = 0, samples = 0;
            double totalTicks = 0;
            long allocated = 0;
            var sw = new Stopwatch();
            for (int r = 0; r < recordings.Count; r++)
            {
                var rows = recordings[r].Samples;
                pipeline.Reset();
                bool counted = r > 0;
                var before = pipeline.ClassifierTime;
                long beforeWindows = pipeline.Windows;
                long bytesBefore = GC.GetAllocatedBytesForCurrentThread();
                sw.Restart();
                for (int i = 0; i < rows.Count; i++)
                {
                    var w0 = pipeline.Windows;
                    var t0 = pipeline.ClassifierTime;
                    pipeline.Push(rows[i].Imu);
                    if (counted && pipeline.Windows > w0)
                    {
                        // Recording per-window times would allocate as the list grows: it was sized up front.
                        double ms = (pipeline.ClassifierTime - t0).TotalMilliseconds / (pipeline.Windows - w0);
                        if (perWindow.Count < perWindow.Capacity) perWindow.Add(ms);
                    }
                }
                sw.Stop();
                long bytes = GC.GetAllocatedBytesForCurrentThread() - bytesBefore;
                if (!counted) continue;
                allocated += bytes;
                totalTicks += sw.Elapsed.TotalMilliseconds;
                samples += rows.Count;
                windows += pipeline.Windows - beforeWindows;
            }
            perWindow.Sort();
            double sum = 0;
            foreach (var v in perWindow) sum += v;
            return new CostReport
            {
                Classifier = classifier.Name,
                Windows = windows,
                Samples = samples,
                MeanWindowMs = perWindow.Count > 0 ? sum / perWindow.Count : double.NaN,
                P95WindowMs = GaitMetrics.Percentile(perWindow, 0.95),
                MicrosecondsPerSample = samples > 0 ? 1000 * totalTicks / samples : double.NaN,
                BytesPerSample = samples > 0 ? (double)allocated / samples : double.NaN,
            };
        }
    }
}
