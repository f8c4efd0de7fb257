using System;
using System.Collections.Generic;
using System.Diagnostics;

namespace HeadGait
{
    /// <summary>
    /// The whole chain for live use: samples in, animator frames out.
    /// Push every accelerometer sample; <see cref="Latest"/> is the avatar's current leg state.
    /// </summary>
    public sealed class GaitPipeline
    {
        readonly StreamPreprocessor preprocessor;
        readonly IGaitClassifier classifier;
        readonly GaitAnimatorStateMachine animator;
        readonly Action<SignalWindow> onWindow;
        readonly Stopwatch stopwatch = new Stopwatch();
        readonly StanceLatch advancedStance = new StanceLatch(); // the feet's stance shares of predictions moved ahead by SourceLag
        readonly LearnedWindowBatch batch; // null unless the classifier is a learned one
        readonly RhythmHold hold;
        readonly List<RhythmReading> batchRhythm = new List<RhythmReading>(); // the hold's reading of each batched window, in order
        bool batching;                      // inside PushBatch: windows and restarts are queued, not run
        bool settled = true;                // standing since a restart, no window since: a refused stream need not restart again

        public GaitPipeline(IGaitClassifier classifier, PreprocessorSettings preprocessorSettings = null, AnimatorSettings animatorSettings = null, RhythmHoldSettings holdSettings = null)
        {
            this.classifier = classifier ?? throw new ArgumentNullException(nameof(classifier));
            hold = new RhythmHold(classifier.PhaseMap, holdSettings);
            var settings = preprocessorSettings ?? new PreprocessorSettings();
            int history = Math.Max(classifier.WindowLength, hold.History);
            if (settings.History < history)
            {
                // The classifier or the hold reads more history than the settings keep: carry it in every window.
                settings = settings.Clone();
                settings.History = history;
            }
            preprocessor = new StreamPreprocessor(settings);
            animator = new GaitAnimatorStateMachine(classifier.PhaseMap, animatorSettings);
            onWindow = OnWindow;
            if (classifier is LearnedClassifier learned) batch = new LearnedWindowBatch(learned);
            Latest = AnimatorFrame.Standing(0);
        }

        public StreamPreprocessor Preprocessor => preprocessor;
        public IGaitClassifier Classifier => classifier;
        public GaitAnimatorStateMachine Animator => animator;

        public GaitPrediction LatestPrediction { get; private set; }

        /// <summary>
        /// How late the samples describe the motion (s): 0 for an accelerometer, <see cref="PoseAccelerationEstimator.Lag"/>
        /// for acceleration derived from the tracked pose. Walking predictions are moved that far ahead before the animator,
        /// and where it is not 0 also by the classifier's <see cref="IGaitClassifier.PoseFitDelay"/>.
        /// </summary>
        public double SourceLag { get; set; }
        public AnimatorFrame Latest { get; private set; }
        public long Windows { get; private set; }

        /// <summary>Total time spent inside the classifier, for per-window cost.</summary>
        public TimeSpan ClassifierTime => stopwatch.Elapsed;

        /// <summary>Called after each window with the prediction and the resulting animator frame.</summary>
        public event Action<GaitPrediction, AnimatorFrame> FrameProduced;

        public SampleOutcome Push(in ImuSample sample)
        {
            var outcome = preprocessor.Push(sample, onWindow);
            // A hole or a new clock, or a stream no window can come from (timestamps too coarse, samples slower than the lowest
            // rate): the avatar stands rather than hold its last frame.
            if (outcome == SampleOutcome.AcceptedAfterGap || outcome == SampleOutcome.AcceptedAfterRebase
                || (!settled && (outcome == SampleOutcome.SkippedCoarseClock || preprocessor.BelowLowestRate)))
            {
                settled = true;
                hold.ForgetRhythm();
                if (batching) batch.AddRestart(sample.Time);
                else Restart(sample.Time);
            }
            return outcome;
        }

        public SampleOutcome Push(double time, double x, double y, double z) => Push(new ImuSample(time, x, y, z));

        /// <summary>
        /// Pushes <paramref name="count"/> samples in order, with the same predictions, frames and events as pushing them
        /// one by one. With a learned classifier the windows they complete are scored together, in one call of its
        /// evaluator (one inference when that is Sentis), and then decided in order; other classifiers run window by window.
        /// </summary>
        public void PushBatch(ImuSample[] samples, int count)
        {
            if (samples == null) throw new ArgumentNullException(nameof(samples));
            if (count < 0 || count > samples.Length) throw new ArgumentOutOfRangeException(nameof(count));
            if (batch == null)
            {
                for (int i = 0; i < count; i++) Push(samples[i]);
                return;
            }
            batch.Clear();
            batchRhythm.Clear();
            int rhythmIndex = 0;
            batching = true;
            try
            {
                for (int i = 0; i < count; i++) Push(samples[i]);
            }
            finally
            {
                batching = false;
            }
            stopwatch.Start();
            batch.Evaluate();
            stopwatch.Stop();
            for (int i = 0; i < batch.Count; i++)
            {
                if (batch.IsRestart(i, out double time))
                {
                    Restart(time);
                    continue;
                }
                stopwatch.Start();
                var prediction = batch.Classify(i);
                stopwatch.Stop();
                Publish(prediction, batchRhythm[rhythmIndex++]);
            }
            batch.Clear();
            batchRhythm.Clear();
        }

        /// <summary>
        /// The sensor fell silent for longer than the preprocessor's MaxGap (the caller measures the silence, e.g. in frames
        /// without samples): the avatar stands now instead of holding its last frame until new samples arrive.
        /// </summary>
        public void Settle(double time)
        {
            if (settled) return;
            settled = true;
            hold.ForgetRhythm();
            Restart(time);
        }

        /// <summary>
        /// The signal broke off or its clock moved: forget the stale history and let the avatar stand rather than freeze
        /// mid-stride until the next full window.
        /// </summary>
        void Restart(double time)
        {
            settled = true;
            classifier.Reset();
            hold.Reset();
            animator.Reset();
            LatestPrediction = GaitPrediction.Standing(time);
            Latest = AnimatorFrame.Standing(time);
        }

        void OnWindow(SignalWindow window)
        {
            var rhythm = hold.Observe(window);
            if (batching)
            {
                batch.AddWindow(window);
                batchRhythm.Add(rhythm);
                return;
            }
            stopwatch.Start();
            var prediction = classifier.Classify(window);
            stopwatch.Stop();
            Publish(prediction, rhythm);
        }

        void Publish(GaitPrediction prediction, RhythmReading rhythm)
        {
            settled = false;
            if (SourceLag != 0) prediction = Advanced(prediction, SourceLag + classifier.PoseFitDelay);
            LatestPrediction = prediction;
            Latest = animator.Update(hold.Apply(prediction, rhythm));
            Windows++;
            FrameProduced?.Invoke(prediction, Latest);
        }

        /// <summary>
        /// The prediction moved <paramref name="lead"/> seconds ahead along its own step period (standing stays standing), so
        /// the avatar shows where the legs are now; each foot keeps its stance share from contact to contact, as in the clocks.
        /// </summary>
        GaitPrediction Advanced(GaitPrediction p, double lead)
        {
            if (!p.IsWalking) advancedStance.Reset();
            if (!p.IsWalking || !(p.StepPeriod > 0)) return p;
            return GaitPrediction.Walking(p.Time, p.StridePosition + lead / (2 * p.StepPeriod), p.StepPeriod, p.Confidence, classifier.PhaseMap, advancedStance);
        }

        public void Reset()
        {
            advancedStance.Reset();
            preprocessor.Reset();
            classifier.Reset();
            hold.Reset();
            hold.ForgetRhythm();
            animator.Reset();
            LatestPrediction = default;
            Latest = AnimatorFrame.Standing(0);
            settled = true;
        }
    }
}
