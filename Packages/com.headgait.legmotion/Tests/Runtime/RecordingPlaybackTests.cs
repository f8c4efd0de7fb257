using System.Collections.Generic;
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
    [NeedsPackageFiles]
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

        /// <summary>walk_straight with its middle row stamped absurdly: one row, or every row from there on.</summary>
        static Recording WithAbsurdRow(Recording source, string kind)
        {
            int middle = source.Samples.Count / 2;
            var rows = new List<RecordedSample>();
            for (int i = 0; i < source.Samples.Count; i++)
            {
                var s = source.Samples[i];
                double time = kind == "one row +1e6 s" && i == middle ? s.Imu.Time + 1e6
                    : kind == "one row at 1e308" && i == middle ? 1e308
                    : kind == "+1e6 s from the middle on" && i >= middle ? s.Imu.Time + 1e6
                    : s.Imu.Time;
                rows.Add(new RecordedSample(new ImuSample(time, s.Imu.X, s.Imu.Y, s.Imu.Z), s.Left, s.Right, s.Line));
            }
            return new Recording(source.Name + ", " + kind, rows);
        }

        [Test]
        public void ARowStampedFarAheadDoesNotStallThePlayer([Values("one row +1e6 s", "one row at 1e308", "+1e6 s from the middle on")] string kind)
        {
            // Regression (issue 9): rows were due at their time since the first row, so a row stamped 1e6 s ahead (or at
            // 1e308) was due after 11.6 days (or never) and every row behind it waited with it.
            var clean = Walk();
            var recording = WithAbsurdRow(clean, kind);
            long Windows(Recording r)
            {
                var runner = new GaitBatchRunner(new GaitPipeline(new ThresholdClassifier()));
                var playback = new RecordingPlayback(r) { Loop = false };
                playback.Restart(runner);
                Play(playback, runner, new InlineScheduler(runner), clean.Duration + RecordingPlayback.MaxRowGap + 0.5);
                Assert.That(playback.Finished, Is.True, r.Name + " stalled at row " + playback.Played);
                Assert.That(playback.Played, Is.EqualTo(r.Samples.Count));
                Assert.That(playback.LastRow.Imu.Time, Is.EqualTo(r.Samples[r.Samples.Count - 1].Imu.Time));
                return runner.Windows;
            }
            long cleanWindows = Windows(clean);
            // The rows after the absurd one still reach the pipeline and are classified (its clock policy drops or re-bases).
            Assert.That(Windows(recording), Is.EqualTo(cleanWindows).Within(100), "windows lost after the absurd row");
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
