using System.IO;
using HeadGait.Unity;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>
    /// <see cref="RecordingPlayback"/> (behind RecordingPlayer) on a committed sample recording. Its timestamps jump back to
    /// the start on every restart; without a reset the pipeline took those samples for late ones or a clock jump and the
    /// avatar froze.
    /// </summary>
    public class RecordingPlaybackTests
    {
        static Recording Walk()
        {
            string folder = SamplePaths.FindRecordingsFolder(TestContext.CurrentContext.TestDirectory);
            Assert.That(folder, Is.Not.Null, "Samples~/Recordings not found above the test directory");
            return RecordingCsv.Load(Path.Combine(folder, "eval", "walk_straight.csv"));
        }

        /// <summary>Runs each batch inline when the next frame completes it.</summary>
        sealed class InlineScheduler : IGaitBatchScheduler
        {
            readonly GaitBatchRunner runner;
            bool scheduled;
            public InlineScheduler(GaitBatchRunner runner) => this.runner = runner;
            public void Schedule() => scheduled = true;

            public void Complete()
            {
                if (!scheduled) return;
                scheduled = false;
                runner.ExecuteBatch();
            }
        }

        static void Play(RecordingPlayback playback, GaitBatchRunner runner, IGaitBatchScheduler scheduler, double seconds)
        {
            const double frame = 1 / 72.0;
            for (double t = 0; t < seconds; t += frame)
            {
                playback.Advance(frame, runner);
                runner.Step(scheduler);
            }
        }

        [Test]
        public void ReEnablingStartsANewStreamThatIsClassified([Values(0.05, 6.0)] double playedBeforeDisable)
        {
            var recording = Walk();
            var runner = new GaitBatchRunner(new GaitPipeline(new ThresholdClassifier()));
            var scheduler = new InlineScheduler(runner);
            var playback = new RecordingPlayback(recording);
            playback.Restart(runner); // OnEnable
            Play(playback, runner, scheduler, playedBeforeDisable);

            var pre = runner.Pipeline.Preprocessor;
            int skipped = pre.Skipped, rebases = pre.Rebases;
            long windows = runner.Windows;
            playback.Restart(runner); // disabled and enabled again: the recording plays from its first row
            Play(playback, runner, scheduler, 8);

            Assert.That(pre.Skipped, Is.EqualTo(skipped), "samples of the replay rejected (as late or suspect)");
            Assert.That(pre.Rebases, Is.EqualTo(rebases), "the replay was taken for a jump of the old clock");
            Assert.That(runner.Windows - windows, Is.GreaterThan(700), "the replay was classified");
            Assert.That(runner.Latest.Time, Is.GreaterThan(recording.Samples[0].Imu.Time + 7), "the avatar follows the replay's clock");
        }

        [Test]
        public void LoopingRestartsTheStreamEachPass()
        {
            var recording = Walk();
            var runner = new GaitBatchRunner(new GaitPipeline(new ThresholdClassifier()));
            var scheduler = new InlineScheduler(runner);
            var playback = new RecordingPlayback(recording) { Loop = true };
            playback.Restart(runner);
            Play(playback, runner, scheduler, recording.Duration * 2.5);

            var pre = runner.Pipeline.Preprocessor;
            Assert.That(pre.Skipped, Is.EqualTo(0));
            Assert.That(pre.Rebases, Is.EqualTo(0));
            Assert.That(runner.Windows, Is.GreaterThan(2 * recording.Samples.Count - 200), "every pass was classified");
        }

        [Test]
        public void WithoutLoopingPlaybackStopsAtTheEnd()
        {
            var recording = Walk();
            var runner = new GaitBatchRunner(new GaitPipeline(new ThresholdClassifier()));
            var playback = new RecordingPlayback(recording) { Loop = false };
            playback.Restart(runner);
            Play(playback, runner, new InlineScheduler(runner), recording.Duration + 1);
            Assert.That(playback.Finished, Is.True);
            Assert.That(playback.Played, Is.EqualTo(recording.Samples.Count));
        }
    }
}
