using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using HeadGait.Synthetic;
using HeadGait.Unity;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>
    /// The fixed-rate job path (<see cref="GaitBatchRunner"/> with <see cref="GaitJobScheduler"/>): whatever the frame rate and
    /// however the sensor samples arrive, it must classify exactly what the plain core pipeline classifies, publish in each
    /// frame the state of the samples handed over up to that frame (not a frame later), and allocate nothing per frame once
    /// warm.
    /// </summary>
    [NeedsPackageFiles]
    public class GaitJobTests
    {
        static string ModelsFolder
        {
            get
            {
                string f = SamplePaths.FindModelsFolder(TestContext.CurrentContext.TestDirectory);
                Assert.That(f, Is.Not.Null, "the package's Models folder was not found above the test directory");
                return f;
            }
        }

        static CorrelationTemplate template;
        static CorrelationTemplate Template => template ?? (template = CorrelationTemplate.Load(Path.Combine(ModelsFolder, GaitModels.CorrelationFile)));

        static IGaitClassifier Cor() => new CorrelationClassifier(Template);

        static IGaitClassifier Blstm() => new BlstmClassifier(ModelFile.Load(Path.Combine(ModelsFolder, GaitModels.BlstmFile)));

        /// <summary>Stand, walk (with a turn), stand, walk: every animator state is visited.</summary>
        static List<ImuSample> Stream(bool irregular, double seconds = 14)
        {
            var script = new StreamScript { StartTime = 0 };
            double walk = (seconds - 3) / 2;
            script.Stand(1.5).Walk(walk, Foot.Left, 20).Stand(1.5).Walk(walk, Foot.Right);
            if (irregular)
            {
                // Slower, jittery, with dropped samples: frames see 0, 1 or several samples.
                script.SampleRate = 83;
                script.TimestampJitter = 0.003;
                script.DropProbability = 0.12;
            }
            var rec = WalkingStreamGenerator.Generate(irregular ? "irregular" : "regular", new GaitSubject(), script, irregular ? 7UL : 3UL);
            var list = new List<ImuSample>();
            foreach (var r in rec.Samples) list.Add(r.Imu);
            return list;
        }

        static string Describe(GaitPrediction p, AnimatorFrame f)
            => string.Format(CultureInfo.InvariantCulture, "{0:R} {1} {2:R} {3:R} {4:R} {5} {6} | {7:R} {8} {9:R} {10:R} {11:R} {12} {13} {14}",
                p.Time, p.IsWalking, p.StridePosition, p.StepPeriod, p.Confidence, p.Left, p.Right,
                f.Time, f.State, f.StridePosition, f.WalkWeight, f.StepPeriod, f.Left, f.Right, f.Resynchronised);

        static List<string> Record(GaitPipeline pipeline)
        {
            var log = new List<string>();
            pipeline.FrameProduced += (p, f) => log.Add(Describe(p, f));
            return log;
        }

        [Test]
        public void EveryFrameRateGivesThePlainPipelinesPredictions(
            [Values(60, 72, 90, 120)] int fps, [Values(false, true)] bool irregular)
        {
            var samples = Stream(irregular);

            var plain = new GaitPipeline(Cor());
            var expected = Record(plain);
            // The plain pipeline's frame after each sample count, to check what each video frame shows.
            var plainLatest = new AnimatorFrame[samples.Count + 1];
            plainLatest[0] = plain.Latest;
            var plainFrames = new HashSet<string>();
            var plainTransients = new List<LocomotionState>();
            plain.FrameProduced += (p, f) =>
            {
                plainFrames.Add(Describe(default, f));
                if (IsStartOrFinish(f.State) && (plainTransients.Count == 0 || plainTransients[plainTransients.Count - 1] != f.State)) plainTransients.Add(f.State);
            };
            for (int i = 0; i < samples.Count; i++)
            {
                plain.Push(samples[i]);
                plainLatest[i + 1] = plain.Latest;
            }

            var runner = new GaitBatchRunner(new GaitPipeline(Cor()), initialCapacity: 4);
            var actual = Record(runner.Pipeline);
            var shownTransients = new List<LocomotionState>();
            long held = 0;
            using (var scheduler = new GaitJobScheduler(runner))
            {
                int handed = 0;
                double end = samples[samples.Count - 1].Time + 0.1;
                for (int frame = 1; frame / (double)fps < end; frame++)
                {
                    double now = frame / (double)fps;
                    while (handed < samples.Count && samples[handed].Time <= now) runner.Push(samples[handed++]);
                    runner.Step(scheduler);
                    // What the avatar shows this frame: the pipeline's state after the samples handed over up to this frame,
                    // or a Start/Finish frame a batch entered and left again, held for frames of its own.
                    string shown = Describe(default, runner.Latest);
                    if (shown != Describe(default, plainLatest[handed]))
                    {
                        Assert.That(IsStartOrFinish(runner.Latest.State) && plainFrames.Contains(shown), Is.True,
                            $"frame {frame} at {fps} fps shows {runner.Latest}, neither the latest frame nor a held Start/Finish frame");
                        held++;
                    }
                    var s = runner.Latest.State;
                    if (IsStartOrFinish(s) && (shownTransients.Count == 0 || shownTransients[shownTransients.Count - 1] != s)) shownTransients.Add(s);
                }
                Assert.That(handed, Is.EqualTo(samples.Count));
            }

            Assert.That(expected.Count, Is.GreaterThan(samples.Count / 2), "the stream produced windows");
            Assert.That(actual, Is.EqualTo(expected));
            Assert.That(runner.Windows, Is.EqualTo(plain.Windows));
            Assert.That(runner.Latest.State, Is.EqualTo(plain.Latest.State));
            Assert.That(plainTransients, Has.Count.GreaterThanOrEqualTo(3), "the stream starts twice and stops once");
            Assert.That(shownTransients, Is.EqualTo(plainTransients), "every Start and Finish state the core entered was shown for a frame at least");
            Assert.That(runner.HeldFrames, Is.EqualTo(held));
        }

        static bool IsStartOrFinish(LocomotionState s) => s != LocomotionState.Standing && s != LocomotionState.Walking;

        /// <summary>The core's Start Walk often lasts one 10 ms window: the frame of a batch that enters and leaves it and the
        /// next show it first (the Animator may be ending an uninterruptible blend on the first and start nothing then).</summary>
        [Test]
        public void AStartWalkEnteredAndLeftWithinOneBatchIsShownForTwoFrames()
        {
            var samples = Stream(irregular: false);
            // Find the batch boundary that puts the core's whole Start Walk inside one batch, then hand the stream over in two batches.
            var probe = new GaitPipeline(Cor());
            int startSample = -1, walkingSample = -1;
            for (int i = 0; i < samples.Count && walkingSample < 0; i++)
            {
                probe.Push(samples[i]);
                if (startSample < 0 && (probe.Latest.State == LocomotionState.StartWalkLeft || probe.Latest.State == LocomotionState.StartWalkRight)) startSample = i;
                if (startSample >= 0 && probe.Latest.State == LocomotionState.Walking) walkingSample = i;
            }
            Assert.That(walkingSample, Is.GreaterThan(startSample).And.GreaterThan(0), "the stream starts walking");

            var runner = new GaitBatchRunner(new GaitPipeline(Cor()));
            var scheduler = new InlineBatchScheduler(runner);
            for (int i = 0; i < startSample - 1; i++) runner.Push(samples[i]);
            runner.Step(scheduler);
            runner.Step(scheduler);
            Assert.That(runner.Latest.State, Is.EqualTo(LocomotionState.Standing));
            for (int i = startSample - 1; i <= walkingSample; i++) runner.Push(samples[i]);
            runner.Step(scheduler); // runs the batch that starts and reaches Walking
            Assert.That(runner.Latest.State, Is.Not.EqualTo(LocomotionState.Walking), "the Start Walk frame comes first, in this frame");
            var start = runner.Latest.State;
            Assert.That(start == LocomotionState.StartWalkLeft || start == LocomotionState.StartWalkRight, Is.True, $"shows {start}");
            runner.Step(scheduler);
            Assert.That(runner.Latest.State, Is.EqualTo(start), "the Start Walk frame shows for a second frame");
            runner.Step(scheduler);
            Assert.That(runner.Latest.State, Is.EqualTo(LocomotionState.Walking), "then the batch's latest frame, with no new samples");
            Assert.That(runner.HeldFrames, Is.EqualTo(GaitBatchRunner.MinTransientFrames));
        }

        [Test]
        public void BlstmThroughTheJobGivesThePlainPipelinesPredictions()
        {
            var samples = Stream(irregular: true, seconds: 8);
            var plain = new GaitPipeline(Blstm());
            var expected = Record(plain);
            foreach (var s in samples) plain.Push(s);

            var runner = new GaitBatchRunner(new GaitPipeline(Blstm()));
            var actual = Record(runner.Pipeline);
            using (var scheduler = new GaitJobScheduler(runner))
            {
                int handed = 0;
                for (int frame = 1; handed < samples.Count; frame++)
                {
                    while (handed < samples.Count && samples[handed].Time <= frame / 72.0) runner.Push(samples[handed++]);
                    runner.Step(scheduler);
                }
                runner.Step(scheduler);
            }
            Assert.That(expected.Count, Is.GreaterThan(100));
            Assert.That(actual, Is.EqualTo(expected));
        }

        /// <summary>Runs the batch only when completed, on the completing thread: the latest a worker could, and countable by the allocation test.</summary>
        sealed class CountingScheduler : IGaitBatchScheduler
        {
            readonly GaitBatchRunner runner;
            bool scheduled;
            public int Schedules, Completes;

            public CountingScheduler(GaitBatchRunner runner) => this.runner = runner;

            public void Schedule()
            {
                if (scheduled) throw new InvalidOperationException("scheduled twice without completing");
                scheduled = true;
                Schedules++;
            }

            public void Complete()
            {
                if (!scheduled) return;
                scheduled = false;
                Completes++;
                runner.ExecuteBatch();
            }
        }

        /// <summary>Regression: the batch a frame scheduled was published only by the next frame, a frame more before every
        /// start the avatar shows (animator-check: max lag from the core's Start Walk 136 ms at 60 fps, limit 117).</summary>
        [Test]
        public void AFramePublishesTheSamplesHandedOverBeforeIt()
        {
            var samples = Stream(irregular: false, seconds: 6);
            var runner = new GaitBatchRunner(new GaitPipeline(Cor()));
            var scheduler = new CountingScheduler(runner);

            foreach (var s in samples) if (s.Time <= 3) runner.Push(s);
            runner.Step(scheduler);
            Assert.That(scheduler.Schedules, Is.EqualTo(1));
            Assert.That(scheduler.Completes, Is.EqualTo(1), "the frame's batch is completed in the frame");
            Assert.That(runner.Windows, Is.GreaterThan(200), "and published in it");
            Assert.That(runner.Pending, Is.EqualTo(0));
            Assert.That(runner.HeldFrames, Is.EqualTo(1), "the batch started a walk: its Start Walk frame shows first");

            // Frames without new samples (late or missing sensor data): nothing new is scheduled.
            runner.Step(scheduler);
            Assert.That(runner.HeldFrames, Is.EqualTo(GaitBatchRunner.MinTransientFrames), "and for a second frame");
            runner.Step(scheduler);
            var shown = runner.Latest;
            Assert.That(shown.State, Is.EqualTo(LocomotionState.Walking));
            for (int i = 0; i < 5; i++) runner.Step(scheduler);
            Assert.That(scheduler.Schedules, Is.EqualTo(1));
            Assert.That(Describe(default, runner.Latest), Is.EqualTo(Describe(default, shown)));
        }

        [Test]
        public void ResetStandsAtOnceAndStartsTheStreamOver()
        {
            var samples = Stream(irregular: false, seconds: 10);
            var runner = new GaitBatchRunner(new GaitPipeline(Cor()));
            var scheduler = new CountingScheduler(runner);
            int i = 0;
            for (; samples[i].Time <= 4.5; i++) runner.Push(samples[i]);
            runner.Step(scheduler);
            runner.Step(scheduler);
            Assert.That(runner.Latest.State, Is.Not.EqualTo(LocomotionState.Standing), "walking before the reset");

            for (; samples[i].Time <= 4.9; i++) runner.Push(samples[i]);
            runner.Reset(); // before the frame ran them: they are dropped
            Assert.That(runner.Latest.State, Is.EqualTo(LocomotionState.Standing));
            Assert.That(runner.Pending, Is.EqualTo(0));
            runner.Step(scheduler);
            Assert.That(runner.Latest.State, Is.EqualTo(LocomotionState.Standing));

            // The same stream again from its start is a new stream, not late samples.
            var preprocessor = runner.Pipeline.Preprocessor;
            long skippedBefore = preprocessor.Skipped, rebasesBefore = preprocessor.Rebases;
            for (int k = 0; samples[k].Time <= 4.5; k++) runner.Push(samples[k]);
            runner.Step(scheduler);
            runner.Step(scheduler);
            Assert.That(preprocessor.Skipped, Is.EqualTo(skippedBefore), "samples of the new stream skipped");
            Assert.That(preprocessor.Rebases, Is.EqualTo(rebasesBefore), "the new stream was taken for a clock jump of the old one");
            Assert.That(runner.Latest.State, Is.Not.EqualTo(LocomotionState.Standing), "walking again after the restart");
        }

        [Test]
        public void NonFiniteSamplesAreRefusedAtHandOver()
        {
            var runner = new GaitBatchRunner(new GaitPipeline(Cor()));
            Assert.That(runner.Push(new ImuSample(0.01, double.NaN, 0, 9.8)), Is.EqualTo(SampleOutcome.SkippedNotFinite));
            Assert.That(runner.Push(new ImuSample(0.02, 0, 0, 9.8)), Is.EqualTo(SampleOutcome.Accepted));
            Assert.That(runner.Pending, Is.EqualTo(1));
            Assert.That(runner.RejectedNotFinite, Is.EqualTo(1));
        }

        [Test]
        public void SamplesPushedWhileNoFrameRunsKeepOnlyTheNewestTwoSeconds()
        {
            // The component disabled for 14 s while a 500 Hz source kept pushing: no Step ran.
            var script = new StreamScript { StartTime = 0, SampleRate = 500 };
            script.Stand(1.5).Walk(12.5, Foot.Left);
            var samples = WalkingStreamGenerator.Generate("disabled", new GaitSubject(), script, 11UL).Samples;
            var runner = new GaitBatchRunner(new GaitPipeline(Cor()));
            foreach (var r in samples) Assert.That(runner.Push(r.Imu), Is.EqualTo(SampleOutcome.Accepted));

            double last = samples[samples.Count - 1].Imu.Time;
            int kept = 0;
            foreach (var r in samples) if (r.Imu.Time >= last - GaitBatchRunner.MaxBacklogSeconds) kept++;
            Assert.That(kept, Is.GreaterThan(GaitBatchRunner.MinBacklogSamples), "the time bound is what is tested here");
            Assert.That(runner.Pending, Is.EqualTo(kept), "the backlog is the newest 2 s");
            Assert.That(runner.DroppedBacklog, Is.EqualTo(samples.Count - kept));

            // Enabled again: the backlog is one batch, and the avatar walks on from the newest samples.
            var scheduler = new CountingScheduler(runner);
            runner.Step(scheduler);
            runner.Step(scheduler);
            Assert.That(runner.Latest.State, Is.EqualTo(LocomotionState.StartWalkLeft).Or.EqualTo(LocomotionState.StartWalkRight), "the walk's start, held for two frames");
            runner.Step(scheduler);
            runner.Step(scheduler);
            Assert.That(runner.Latest.Time, Is.EqualTo(last).Within(0.02));
            Assert.That(runner.Windows, Is.InRange(100, 201), "windows of the 2 s kept (100 Hz, after the first window fills), not of 14 s");
            Assert.That(runner.Latest.State, Is.EqualTo(LocomotionState.Walking));
        }

        [Test]
        public void TheBacklogIsBoundedWhateverTheTimestampsSay()
        {
            // Backward timestamps never look older than 2 s; the sample count bounds them.
            var runner = new GaitBatchRunner(new GaitPipeline(Cor()));
            for (int i = 0; i < 20000; i++) runner.Push(new ImuSample(1000 - i * 0.001, 0, 0, 9.81));
            Assert.That(runner.Pending, Is.EqualTo(GaitBatchRunner.MaxBacklogSamples));
            Assert.That(runner.DroppedBacklog, Is.EqualTo(20000 - GaitBatchRunner.MaxBacklogSamples));

            // A frame's worth of samples with one stamped 1e6 s ahead: the good ones before it are kept for the pipeline.
            runner.Reset();
            for (int i = 0; i < 10; i++) runner.Push(new ImuSample(i * 0.01, 0, 0, 9.81));
            runner.Push(new ImuSample(1e6, 0, 0, 9.81));
            for (int i = 10; i < 20; i++) runner.Push(new ImuSample(i * 0.01, 0, 0, 9.81));
            Assert.That(runner.Pending, Is.EqualTo(21));
            Assert.That(runner.DroppedBacklog, Is.EqualTo(20000 - GaitBatchRunner.MaxBacklogSamples), "nothing more dropped");
        }

        static long AllocatedPerFrameLoop(GaitBatchRunner runner, IGaitBatchScheduler scheduler, List<ImuSample> samples, int fps)
        {
            int handed = 0, frame = 1;
            double warmUp = 4;
            // Warm up: buffers grow to their largest batch, the classifier's and animator's lists fill.
            for (; frame / (double)fps < warmUp; frame++)
            {
                while (handed < samples.Count && samples[handed].Time <= frame / (double)fps) runner.Push(samples[handed++]);
                runner.Step(scheduler);
            }
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (; handed < samples.Count; frame++)
            {
                while (handed < samples.Count && samples[handed].Time <= frame / (double)fps) runner.Push(samples[handed++]);
                runner.Step(scheduler);
            }
            runner.Step(scheduler);
            return GC.GetAllocatedBytesForCurrentThread() - before;
        }

        [Test]
        public void SteadyStateFramesAllocateNothing([Values("cor", "thr", "svm", "blstm")] string classifier)
        {
            var samples = Stream(irregular: true, seconds: 9);
            IGaitClassifier make() => classifier == "cor" ? Cor() : classifier == "thr" ? new ThresholdClassifier()
                : classifier == "svm" ? new SvmClassifier(ModelFile.Load(Path.Combine(ModelsFolder, GaitModels.SvmFile))) : Blstm();

            // The batch runs on this thread here, so its allocations count too. Each loop runs twice on fresh runners and the
            // smaller count is judged: what the frames allocate comes back in both, while the runtime may allocate once on
            // this thread as code tiers up mid-loop (936 bytes once in a whole-suite run, COR; never in the next ones).
            long Inline()
            {
                var runner = new GaitBatchRunner(new GaitPipeline(make()));
                long allocated = AllocatedPerFrameLoop(runner, new CountingScheduler(runner), samples, 90);
                Assert.That(runner.Windows, Is.GreaterThan(700));
                return allocated;
            }
            Assert.That(Math.Min(Inline(), Inline()), Is.EqualTo(0), "bytes allocated by frames after warm-up (main thread and batch)");

            // The Unity job wrapper's main-thread side.
            long ThroughJob()
            {
                var jobRunner = new GaitBatchRunner(new GaitPipeline(make()));
                using (var scheduler = new GaitJobScheduler(jobRunner))
                    return AllocatedPerFrameLoop(jobRunner, scheduler, samples, 90);
            }
            Assert.That(Math.Min(ThroughJob(), ThroughJob()), Is.EqualTo(0), "bytes allocated by frames through the job");
        }
    
        [Test]
        public void ASilentSensorLeavesTheAvatarStandingAfterTheGapNotMidStride()
        {
            // Regression: frames without samples showed the last walking frame until three new samples came (a sensor that
            // stopped for seconds left the legs frozen mid-stride).
            var runner = new GaitBatchRunner(new GaitPipeline(Cor()));
            var scheduler = new InlineBatchScheduler(runner);
            var samples = Stream(irregular: false, seconds: 9);
            double frame = 1 / 72.0, now = 0;
            int next = 0;
            // Walk until the avatar walks: frames at 72 Hz, each handing over the samples of its time.
            while (next < samples.Count && (runner.Latest.State != LocomotionState.Walking || now < 4))
            {
                now += frame;
                while (next < samples.Count && samples[next].Time <= now) runner.Push(samples[next++]);
                runner.Step(scheduler, now);
            }
            Assert.That(runner.Latest.State, Is.EqualTo(LocomotionState.Walking), "walking when the sensor falls silent");
            double silentFrom = now;
            double maxGap = runner.Pipeline.Preprocessor.Settings.MaxGap;
            while (now < silentFrom + 2)
            {
                now += frame;
                runner.Step(scheduler, now);
                if (now - silentFrom <= maxGap - frame) Assert.That(runner.Latest.State, Is.Not.EqualTo(LocomotionState.Standing), "a frame or two without samples is no gap");
                if (now - silentFrom > maxGap + 2 * frame) Assert.That(runner.Latest.State, Is.EqualTo(LocomotionState.Standing), $"standing {now - silentFrom:F3} s into the silence");
            }
            // The sensor comes back on its own clock, 2 s on: the pipeline starts afresh and walks again.
            double offset = now - samples[next].Time;
            double back = now;
            bool walkingAgain = false;
            while (next < samples.Count && !walkingAgain)
            {
                now += frame;
                while (next < samples.Count && samples[next].Time + offset <= now)
                {
                    var s = samples[next++];
                    runner.Push(new ImuSample(s.Time + offset, s.X, s.Y, s.Z));
                }
                runner.Step(scheduler, now);
                walkingAgain = runner.Latest.State != LocomotionState.Standing;
            }
            Assert.That(walkingAgain, Is.True);
            Assert.That(now - back, Is.LessThan(1.5), "walking shown again soon after the sensor returns");
        }
}
}
