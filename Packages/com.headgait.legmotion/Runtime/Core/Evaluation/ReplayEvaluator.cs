using System;
using System.Collections.Generic;
using System.Diagnostics;

namespace HeadGait
{
    /// <summary>Result of replaying one recording through one classifier.</summary>
    public sealed class ReplayResult
    {
        public string Recording;
        public string Classifier;
        public int InputSamples;
        public int SkippedSamples;
        public int Gaps;
        /// <summary>The clock policy's account of what it skipped (<see cref="StreamPreprocessor.DescribeSkips"/>); empty when nothing.</summary>
        public string SkipSummary = "";
        public int FileWarnings;
        public long Windows;
        /// <summary>Mean and 95th-percentile classifier time per window (ms).</summary>
        public double MeanWindowMs;
        public double P95WindowMs;
        /// <summary>Mean whole-pipeline time per input sample (ms): preprocessing, classifier and animator.</summary>
        public double MeanSampleMs;
        /// <summary>Classifier output against truth (null without labels).</summary>
        public GaitMetrics ClassifierMetrics;
        /// <summary>Animator output (what the avatar shows) against truth (null without labels).</summary>
        public GaitMetrics AnimatorMetrics;
        /// <summary>Labelled samples scored: all from the first window on.</summary>
        public int ScoredSamples;

        /// <summary>Labelled samples before the first window (nothing to show yet): not scored.</summary>
        public int UnscoredSamples;
        public Dictionary<LocomotionState, int> StateCounts = new Dictionary<LocomotionState, int>();
        public List<GaitPrediction> Predictions = new List<GaitPrediction>();
        public List<AnimatorFrame> Frames = new List<AnimatorFrame>();
    }

    public static class ReplayEvaluator
    {
        /// <summary>
        /// Replays a recording sample by sample through preprocessing, the classifier and the animator,
        /// exactly as live; then scores each labelled sample against the latest prediction made at or before
        /// its timestamp (causal, zero-order hold).
        /// </summary>
        public static ReplayResult Run(Recording recording, IGaitClassifier classifier,
            PreprocessorSettings preprocessorSettings = null, AnimatorSettings animatorSettings = null, bool keepTrace = false,
            RhythmHoldSettings holdSettings = null)
        {
            if (recording == null) throw new ArgumentNullException(nameof(recording));
            classifier.Reset();
            var pipeline = new GaitPipeline(classifier, preprocessorSettings, animatorSettings, holdSettings) { SourceLag = recording.SourceLag };
            var predictions = new List<GaitPrediction>();
            var frames = new List<AnimatorFrame>();
            pipeline.FrameProduced += (p, f) =>
            {
                predictions.Add(p);
                frames.Add(f);
            };
            var perWindow = new List<double>();
            var total = Stopwatch.StartNew();
            TimeSpan lastClassifier = TimeSpan.Zero;
            long lastWindows = 0;
            foreach (var s in recording.Samples)
            {
                pipeline.Push(s.Imu);
                if (pipeline.Windows != lastWindows)
                {
                    var elapsed = pipeline.ClassifierTime;
                    double ms = (elapsed - lastClassifier).TotalMilliseconds / (pipeline.Windows - lastWindows);
                    for (long k = lastWindows; k < pipeline.Windows; k++) perWindow.Add(ms);
                    lastClassifier = elapsed;
                    lastWindows = pipeline.Windows;
                }
            }
            total.Stop();

            var result = new ReplayResult
            {
                Recording = recording.Name,
                Classifier = classifier.Name,
                InputSamples = recording.Samples.Count,
                SkippedSamples = pipeline.Preprocessor.Skipped,
                Gaps = pipeline.Preprocessor.Gaps,
                SkipSummary = pipeline.Preprocessor.DescribeSkips(),
                FileWarnings = recording.Warnings.Count,
                Windows = pipeline.Windows,
                MeanSampleMs = recording.Samples.Count > 0 ? total.Elapsed.TotalMilliseconds / recording.Samples.Count : 0,
            };
            if (perWindow.Count > 0)
            {
                result.MeanWindowMs = pipeline.ClassifierTime.TotalMilliseconds / pipeline.Windows;
                perWindow.Sort();
                result.P95WindowMs = GaitMetrics.Percentile(perWindow, 0.95);
            }
            foreach (var f in frames)
            {
                result.StateCounts.TryGetValue(f.State, out int c);
                result.StateCounts[f.State] = c + 1;
            }
            if (keepTrace)
            {
                result.Predictions = predictions;
                result.Frames = frames;
            }

            if (!recording.HasTruth || predictions.Count == 0) return result;
            PhaseEvents.ExtractTruth(recording, out var times, out var tl, out var tr);
            var st = new List<double>();
            var sl = new List<GaitPhase>();
            var sr = new List<GaitPhase>();
            var pl = new List<GaitPhase>();
            var pr = new List<GaitPhase>();
            var al = new List<GaitPhase>();
            var ar = new List<GaitPhase>();
            int j = -1;
            for (int i = 0; i < times.Count; i++)
            {
                while (j + 1 < predictions.Count && predictions[j + 1].Time <= times[i] + 1e-9) j++;
                if (j < 0) continue;
                // Once the first window is out, every labelled sample is scored against what the avatar shows then, even
                // when no window has come for a while: a frozen stream must show up in the scores, not drop out of them.
                st.Add(times[i]);
                sl.Add(tl[i]);
                sr.Add(tr[i]);
                pl.Add(predictions[j].Left);
                pr.Add(predictions[j].Right);
                al.Add(frames[j].Left);
                ar.Add(frames[j].Right);
            }
            result.ScoredSamples = st.Count;
            result.UnscoredSamples = times.Count - st.Count;
            if (st.Count == 0) return result;
            result.ClassifierMetrics = GaitMetrics.Compute(st, sl, sr, pl, pr);
            result.AnimatorMetrics = GaitMetrics.Compute(st, sl, sr, al, ar);
            return result;
        }
    }
}
