using System;
using System.Collections.Generic;
using System.Linq;
using HeadGait.Unity;

namespace HeadGait.Tooling
{
    /// <summary>What the simulated Animator showed of the core's walk starts and stops at one frame rate.</summary>
    public sealed class AnimatorCheckResult
    {
        public int Fps;
        public int Starts, Stops, MissedStarts, MissedStops;
        /// <summary>Seconds from the core entering Start Walk (the sensor time of the sample whose arrival produced it) to the
        /// Animator standing fully in a walking state.</summary>
        public readonly List<double> StartLagFromCore = new List<double>();
        /// <summary>As <see cref="StartLagFromCore"/>, from the Start Walk frame's own time: the 100 Hz grid step it classified,
        /// which the resampler can only produce once the next sensor sample has come (up to one sample interval later).</summary>
        public readonly List<double> StartLagFromGrid = new List<double>();
        /// <summary>Seconds from the frame the runner first published the start to the Animator standing fully in a walking state.</summary>
        public readonly List<double> StartLagFromPublished = new List<double>();
        /// <summary>Starts the core cancelled before the Animator arrived (no lag).</summary>
        public int StartsCancelled;
        public readonly List<string> Misses = new List<string>();
        public long HeldFrames;

        public void Add(AnimatorCheckResult other)
        {
            Starts += other.Starts;
            Stops += other.Stops;
            MissedStarts += other.MissedStarts;
            MissedStops += other.MissedStops;
            StartsCancelled += other.StartsCancelled;
            StartLagFromCore.AddRange(other.StartLagFromCore);
            StartLagFromGrid.AddRange(other.StartLagFromGrid);
            StartLagFromPublished.AddRange(other.StartLagFromPublished);
            Misses.AddRange(other.Misses);
            HeldFrames += other.HeldFrames;
        }
    }

    /// <summary>
    /// Replays a recording as the drop-in prefab runs it: frames at a fixed rate, each handing the samples up to its time
    /// to <see cref="GaitBatchRunner"/> and stepping it once (a batch per frame, published in that frame), then writing the
    /// published frame to the Animator parameters and updating the shipped controller in <see cref="AnimatorLayerSimulator"/>.
    /// Every Start Walk and Finish Walk state the core enters is a walk start or stop; it is missed when the Animator never
    /// shows that state (as its state or its transition's destination) between the core entering it and three frames after
    /// the core left it (the runner publishes a frame's samples one frame later, and a frame may end just before a sample).
    /// </summary>
    public static class AnimatorStateCheck
    {
        public static bool IsStart(LocomotionState s) => s == LocomotionState.StartWalkLeft || s == LocomotionState.StartWalkRight;
        public static bool IsStop(LocomotionState s) => s == LocomotionState.FinishWalkLeft || s == LocomotionState.FinishWalkRight;
        static bool Moving(LocomotionState s) => s == LocomotionState.Walking || IsStart(s);

        public static AnimatorCheckResult Run(Recording recording, IGaitClassifier classifier, AnimatorControllerAsset controller, int fps,
            AnyStateReading reading = AnyStateReading.AlwaysEvaluated)
        {
            var stateOf = new Dictionary<ControllerState, LocomotionState>();
            foreach (var s in controller.States)
                foreach (var l in GaitClips.All)
                    if (GaitClips.Name(l) == s.Name) stateOf[s] = l;
            var pipeline = new GaitPipeline(classifier) { SourceLag = recording.SourceLag };
            var runner = new GaitBatchRunner(pipeline);
            var scheduler = new InlineBatchScheduler(runner);
            var coreChanges = new List<(double Time, LocomotionState State)>();
            var last = LocomotionState.Standing;
            pipeline.FrameProduced += (p, f) =>
            {
                if (f.State == last) return;
                last = f.State;
                coreChanges.Add((f.Time, f.State));
            };
            var animator = new AnimatorLayerSimulator(controller, reading);
            var frames = new List<(double Time, LocomotionState Published, LocomotionState Shown, bool Arrived)>();
            var samples = recording.Samples;
            double dt = 1.0 / fps;
            double start = samples.Count > 0 ? samples[0].Imu.Time : 0;
            double end = samples.Count > 0 ? samples[samples.Count - 1].Imu.Time + 0.5 : 0;
            int handed = 0;
            for (long k = 1; start + k * dt <= end; k++)
            {
                double now = start + k * dt;
                while (handed < samples.Count && samples[handed].Imu.Time <= now) runner.Push(samples[handed++].Imu);
                runner.Step(scheduler);
                var f = runner.Latest;
                animator.Set(AnimatorParameters.State, (int)f.State);
                animator.Set(AnimatorParameters.StridePhase, f.StridePosition);
                animator.Set(AnimatorParameters.WalkWeight, f.WalkWeight);
                animator.Set(AnimatorParameters.StepPeriod, f.StepPeriod);
                animator.Update(dt);
                stateOf.TryGetValue(animator.Shown, out var shown);
                stateOf.TryGetValue(animator.Current, out var current);
                frames.Add((now, f.State, shown, animator.Transition == null && Moving(current)));
            }

            var result = new AnimatorCheckResult { Fps = fps, HeldFrames = runner.HeldFrames };
            int known = 0;
            for (int i = 0; i < coreChanges.Count; i++)
            {
                var (t0, state) = coreChanges[i];
                bool startEvent = IsStart(state);
                if (!startEvent && !IsStop(state)) continue;
                double t1 = i + 1 < coreChanges.Count ? coreChanges[i + 1].Time : end;
                if (startEvent) result.Starts++;
                else result.Stops++;
                bool seen = frames.Any(f => f.Time >= t0 && f.Time <= t1 + 3 * dt && f.Shown == state);
                if (!seen)
                {
                    if (startEvent) result.MissedStarts++;
                    else result.MissedStops++;
                    result.Misses.Add($"{recording.Name} at {fps} fps: {state} at {t0:F2}-{t1:F2} s not shown");
                }
                if (!startEvent) continue;
                // The walk this start begins: until the core stands again.
                int j = i + 1;
                while (j < coreChanges.Count && coreChanges[j].State != LocomotionState.Standing) j++;
                double walkEnd = j < coreChanges.Count ? coreChanges[j].Time : end;
                int published = frames.FindIndex(f => f.Time >= t0 && Moving(f.Published));
                int arrived = frames.FindIndex(f => f.Time >= t0 && f.Arrived);
                if (published < 0 || arrived < 0 || frames[arrived].Time > walkEnd + 3 * dt)
                {
                    result.StartsCancelled++;
                    continue;
                }
                // The grid step t0 is interpolated between the samples around it, so the core enters the state when the first
                // sample at or after t0 arrives.
                while (known < samples.Count && samples[known].Imu.Time < t0) known++;
                double entered = known < samples.Count ? samples[known].Imu.Time : t0;
                result.StartLagFromCore.Add(frames[arrived].Time - entered);
                result.StartLagFromGrid.Add(frames[arrived].Time - t0);
                result.StartLagFromPublished.Add(frames[arrived].Time - frames[published].Time);
            }
            return result;
        }

        /// <summary>
        /// The most a walk start may take, from the core entering Start Walk to the Animator standing fully in a walking state
        /// (s): one frame (the frame that brings the sample which completes the Start Walk window comes up to one frame after
        /// it) plus the longest blend into a walking state in whole updates (see <see cref="AnimatorLayerSimulator"/>).
        /// </summary>
        public static double LagLimit(AnimatorControllerAsset controller, int fps)
            => (Math.Ceiling(LongestStartTransition(controller) * fps - 1e-6) + 1) / fps + 1e-6;

        /// <summary>The most from the frame the runner publishes a start to the Animator standing in a walking state (s): the
        /// longest blend into a walking state in whole updates.</summary>
        public static double PublishedLagLimit(AnimatorControllerAsset controller, int fps)
            => Math.Ceiling(LongestStartTransition(controller) * fps - 1e-6) / fps + 1e-6;

        /// <summary>The longest transition into a walking state (s, fixed durations; the lag the Animator itself adds).</summary>
        public static double LongestStartTransition(AnimatorControllerAsset controller)
            => controller.AnyStateTransitions.Concat(controller.States.SelectMany(s => s.Transitions))
                .Where(t => t.Destination != null && GaitClips.All.Any(l => Moving(l) && GaitClips.Name(l) == t.Destination.Name))
                .Select(t => t.HasFixedDuration ? t.Duration : t.Duration * (t.Source?.ClipLength ?? 1)).DefaultIfEmpty(0).Max();
    }
}
