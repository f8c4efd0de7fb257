using System;

namespace HeadGait.Unity
{
    /// <summary>
    /// Runs a <see cref="GaitPipeline"/> in one batch per frame (on a Unity job or inline) and decides what is shown when;
    /// plain C#, so it is tested without Unity (the Unity job is a thin wrapper, <see cref="GaitJobScheduler"/>).
    /// <list type="bullet">
    /// <item>Main thread: <see cref="Push"/> hands each sensor sample over (into a buffer that is reused, so no allocation
    /// once it has grown to the largest batch seen); <see cref="Step"/>, once per frame, schedules the samples handed over
    /// since the last frame, completes that batch and publishes its animator frame (<see cref="Latest"/>) in the same frame,
    /// so the Animator evaluates it this frame. The frame waits for its batch: a few 10 ms windows, microseconds for COR
    /// (README, CPU row), where publishing next frame instead added a whole frame to every start the avatar shows.</item>
    /// <item>Worker: <see cref="ExecuteBatch"/> feeds the batch to the pipeline, which resamples to its 100 Hz grid and
    /// classifies every grid step, so classification follows sensor time, not the frame rate (a learned classifier scores
    /// the batch's windows together: <see cref="GaitPipeline.PushBatch"/>).</item>
    /// </list>
    /// A frame never waits for samples: a frame without new samples schedules nothing and shows the last published frame.
    /// Samples handed over while no frame runs (the component disabled, its source still pushing) wait in a backlog bounded
    /// to the newest <see cref="MaxBacklogSeconds"/> of sensor time, oldest dropped first (<see cref="DroppedBacklog"/>).
    /// A Start or Finish Walk state that the core entered (it often lasts a single 10 ms window) is published for at least
    /// <see cref="MinTransientFrames"/> frames, held before the batch's latest frame when the core left it already, so the
    /// Animator sees every start and finish (<see cref="HeldFrames"/>); otherwise it would see Standing -> Walking and
    /// never play the start clip. One frame is not enough: on the update where a blend that cannot be interrupted (the
    /// shipped controller's blends into Start Walk) completes, the Animator starts no new transition, so a state published
    /// only then is skipped.
    /// Call everything except ExecuteBatch from the main thread.
    /// </summary>
    public sealed class GaitBatchRunner
    {
        /// <summary>Sensor time kept waiting for a batch (s): enough history for the classifier's window when frames resume.</summary>
        public const double MaxBacklogSeconds = 2;

        /// <summary>
        /// Samples always kept, whatever their times say: more than one frame brings at any sensor rate (1 kHz at 10 fps is
        /// 100), so a glitched timestamp inside a frame never drops that frame's good samples.
        /// </summary>
        public const int MinBacklogSamples = 256;

        /// <summary>
        /// Frames a Start or Finish Walk state is published at least: one more than the one update in which the Animator may
        /// be completing a blend and start nothing (see the class summary).
        /// </summary>
        public const int MinTransientFrames = 2;

        /// <summary>Samples never exceeded, whatever their times say (2 s at 4 kHz): bounds the backlog of a stream whose
        /// timestamps are garbage.</summary>
        public const int MaxBacklogSamples = 8192;

        readonly GaitPipeline pipeline;
        ImuSample[] pending;
        int pendingStart;         // the backlog's oldest sample, > 0 after dropping
        int pendingCount;
        ImuSample[] batch;
        int batchCount;

        double sourceLag;
        double lastSamples = double.NaN; // the frame time samples last came, for the silence rule
        string warning;

        // Written by the batch, read on the main thread only after it completed.
        AnimatorFrame batchLatest;
        GaitPrediction batchPrediction;
        long batchWindows;
        // The Start/Finish frames the batch entered, in order (bounded: more than a few in one frame is a stalled frame).
        const int MaxHeld = 4;
        readonly AnimatorFrame[] batchEntered = new AnimatorFrame[MaxHeld];
        int batchEnteredCount;
        LocomotionState batchState;

        // Main thread: frames still to show one per frame before the newest one (a queue in a fixed array).
        const int HeldCapacity = (MaxHeld + 1) * MinTransientFrames;
        readonly AnimatorFrame[] held = new AnimatorFrame[HeldCapacity];
        int heldStart, heldCount;
        int latestFrames;         // consecutive frames Latest.State has been published
        AnimatorFrame newest;
        GaitPrediction newestPrediction;

        public GaitBatchRunner(GaitPipeline pipeline, int initialCapacity = 256)
        {
            this.pipeline = pipeline ?? throw new ArgumentNullException(nameof(pipeline));
            if (initialCapacity < 1) throw new ArgumentOutOfRangeException(nameof(initialCapacity));
            pending = new ImuSample[initialCapacity];
            batch = new ImuSample[initialCapacity];
            sourceLag = pipeline.SourceLag;
            Latest = newest = AnimatorFrame.Standing(0);
            pipeline.FrameProduced += OnFrame;
        }

        /// <summary>The pipeline the batches run; read it on the main thread outside <see cref="Step"/>.</summary>
        public GaitPipeline Pipeline => pipeline;

        /// <summary>The animator frame of the last completed batch: what the avatar shows.</summary>
        public AnimatorFrame Latest { get; private set; }

        /// <summary>The prediction behind <see cref="Latest"/>.</summary>
        public GaitPrediction LatestPrediction { get; private set; }

        /// <summary>Frames published showing a Start/Finish state the core had already left, to show it for
        /// <see cref="MinTransientFrames"/> frames (see the class summary).</summary>
        public long HeldFrames { get; private set; }

        /// <summary>Windows classified by completed batches (one per 100 Hz grid step of sensor time).</summary>
        public long Windows { get; private set; }

        /// <summary>Samples handed over and not yet scheduled.</summary>
        public int Pending => pendingCount;

        /// <summary>Samples refused at hand-over because a value was NaN or infinite (the pipeline would skip them too).</summary>
        public int RejectedNotFinite { get; private set; }

        /// <summary>
        /// Samples dropped, oldest first, because more than <see cref="MaxBacklogSeconds"/> (at least
        /// <see cref="MinBacklogSamples"/>, at most <see cref="MaxBacklogSamples"/>) waited for a batch: frames stopped
        /// (the component disabled) while the source kept pushing.
        /// </summary>
        public long DroppedBacklog { get; private set; }

        /// <summary>
        /// Passed to <see cref="GaitPipeline.SourceLag"/> before the next batch (seconds; the pose path sets it), so it never
        /// changes under a running batch.
        /// </summary>
        public double SourceLag
        {
            get => sourceLag;
            set => sourceLag = value;
        }

        /// <summary>
        /// Hands one sample over (main thread). <see cref="SampleOutcome.Accepted"/> means queued for the next batch, where
        /// the pipeline judges it (its counters: <c>Pipeline.Preprocessor</c>); a non-finite sample is refused here.
        /// </summary>
        public SampleOutcome Push(in ImuSample sample)
        {
            if (!sample.IsFinite)
            {
                RejectedNotFinite++;
                return SampleOutcome.SkippedNotFinite;
            }
            if (pendingStart + pendingCount == pending.Length)
            {
                // Grow while the backlog fills half the buffer, else move it to the front: amortised O(1) when dropping.
                if (pendingCount >= pending.Length / 2) Array.Resize(ref pending, pending.Length * 2);
                MoveBacklogToFront();
            }
            pending[pendingStart + pendingCount++] = sample;
            while (pendingCount > MinBacklogSamples
                   && (pendingCount > MaxBacklogSamples || sample.Time - pending[pendingStart].Time > MaxBacklogSeconds))
            {
                pendingStart++;
                pendingCount--;
                DroppedBacklog++;
            }
            return SampleOutcome.Accepted;
        }

        void MoveBacklogToFront()
        {
            if (pendingStart == 0) return;
            Array.Copy(pending, pendingStart, pending, 0, pendingCount);
            pendingStart = 0;
        }

        /// <summary>
        /// The stream starts over (a recording restarts, the source changes): drops what was handed over, resets the pipeline
        /// and shows the standing pose at once.
        /// </summary>
        public void Reset()
        {
            pendingStart = 0;
            pendingCount = 0;
            pipeline.Reset();
            Latest = newest = AnimatorFrame.Standing(0);
            LatestPrediction = newestPrediction = default;
            heldCount = 0;
            latestFrames = 0;
        }

        /// <summary>
        /// The frame's work (main thread): runs the samples handed over since the last frame as one batch (scheduled, then
        /// completed) and publishes its latest frame, or first a Start/Finish frame the batch passed through, held for
        /// <see cref="MinTransientFrames"/> frames. <paramref name="now"/> is the frame's real time (s; Unity's unscaled
        /// time): when no sample has come for longer than the preprocessor's MaxGap (0.1 s, the hole that restarts the
        /// window) the avatar stands, rather than hold its last walking frame until new samples arrive. NaN leaves that
        /// rule out.
        /// </summary>
        public void Step(IGaitBatchScheduler scheduler, double now = double.NaN)
        {
            if (scheduler == null) throw new ArgumentNullException(nameof(scheduler));
            bool samples = pendingCount > 0;
            if (samples)
            {
                lastSamples = now;
                RunBatch(scheduler);
            }
            ShowNext();
            if (!samples && heldCount == 0 && now - lastSamples > pipeline.Preprocessor.Settings.MaxGap
                && Latest.State != LocomotionState.Standing)
            {
                pipeline.Settle(pipeline.LatestPrediction.Time);
                Latest = newest = pipeline.Latest;
                LatestPrediction = newestPrediction = pipeline.LatestPrediction;
            }
        }

        /// <summary>A clock or rate problem the pipeline met (each kind once), for the main thread to log; null when none is new.</summary>
        public string TakeWarning()
        {
            string w = warning;
            warning = null;
            return w;
        }

        void RunBatch(IGaitBatchScheduler scheduler)
        {
            pipeline.SourceLag = sourceLag;
            MoveBacklogToFront(); // the batch reads from index 0
            // Swap buffers: the batch owns the samples now, hand-overs go to the other buffer.
            var full = pending;
            pending = batch;
            batch = full;
            batchCount = pendingCount;
            pendingCount = 0;
            scheduler.Schedule();
            scheduler.Complete();
            string w = pipeline.Preprocessor.TakeWarning();
            if (w != null) warning = warning == null ? w : warning + "; " + w;
            LocomotionState shown = heldCount > 0 ? held[(heldStart + heldCount - 1) % HeldCapacity].State : Latest.State;
            // A Start/Finish state published fewer frames than its minimum, which this batch left: show it again first.
            if (heldCount == 0 && IsTransient(Latest.State) && latestFrames < MinTransientFrames)
            {
                LocomotionState next = batchEnteredCount > 0 ? batchEntered[0].State : batchLatest.State;
                if (next != Latest.State)
                    for (int k = latestFrames; k < MinTransientFrames; k++) Hold(Latest);
            }
            for (int i = 0; i < batchEnteredCount; i++)
            {
                var f = batchEntered[i];
                if (f.State == shown) continue;
                for (int k = 0; k < MinTransientFrames; k++) Hold(f);
                shown = f.State;
            }
            // The newest frame shows the last one's state anyway (and is held again if the next batch leaves it at once).
            while (heldCount > 0 && held[(heldStart + heldCount - 1) % HeldCapacity].State == batchLatest.State) heldCount--;
            newest = batchLatest;
            newestPrediction = batchPrediction;
            Windows += batchWindows;
        }

        static bool IsTransient(LocomotionState s) => s != LocomotionState.Standing && s != LocomotionState.Walking;

        void Hold(in AnimatorFrame frame)
        {
            if (heldCount < HeldCapacity) held[(heldStart + heldCount++) % HeldCapacity] = frame;
        }

        /// <summary>Publishes the oldest held Start/Finish frame, or else the newest frame.</summary>
        void ShowNext()
        {
            var before = Latest.State;
            if (heldCount > 0)
            {
                Latest = held[heldStart];
                heldStart = (heldStart + 1) % HeldCapacity;
                heldCount--;
                HeldFrames++;
            }
            else
            {
                Latest = newest;
                LatestPrediction = newestPrediction;
            }
            latestFrames = Latest.State == before ? latestFrames + 1 : 1;
        }

        /// <summary>The batch itself (a job's worker thread, or inline): every sample through the pipeline, in order.</summary>
        public void ExecuteBatch()
        {
            long before = pipeline.Windows;
            batchState = pipeline.Latest.State;
            batchEnteredCount = 0;
            pipeline.PushBatch(batch, batchCount); // a learned classifier scores the batch's windows in one evaluator call
            batchLatest = pipeline.Latest;
            batchPrediction = pipeline.LatestPrediction;
            batchWindows = pipeline.Windows - before;
            batchCount = 0;
        }
    

        /// <summary>Each frame the batch's pipeline produces (worker thread): notes the Start/Finish states it enters.</summary>
        void OnFrame(GaitPrediction prediction, AnimatorFrame frame)
        {
            if (frame.State == batchState) return;
            batchState = frame.State;
            if (IsTransient(frame.State) && batchEnteredCount < MaxHeld) batchEntered[batchEnteredCount++] = frame;
        }
    }
}
