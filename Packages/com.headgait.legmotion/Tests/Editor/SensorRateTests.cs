using System;
using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>
    /// Head-worn sensors come at other rates than the glasses' 100 Hz (hearing aids at 200 Hz): the pipeline resamples any
    /// rate onto its 100 Hz grid, so a real stream sampled twice as fast is shown as it is at 100 Hz.
    /// </summary>
    public class SensorRateTests
    {
        /// <summary>
        /// One glasses wearer's walk, picking things up and timed up-and-go (dataset 2, user 1) at 200 Hz: two samples in each
        /// interval, a quarter and three quarters through it, on the cubic (Catmull-Rom) through the samples around it, so no
        /// 200 Hz sample is one of the 100 Hz stream's and the grid, which starts on the first sample, reads the cubic's values.
        /// Shipped models, avatar, judged against the 100 Hz stream's own rhythm.
        /// </summary>
        [TestCase("thr")]
        [TestCase("cor")]
        [TestCase("svm")]
        [TestCase("blstm")]
        public void ARealWalkSampledAt200HzIsShownAsAt100Hz(string kind)
        {
            var models = TestData.ShippedModels();
            foreach (var file in TestData.GlassesFiles("cg2_u01_*.csv"))
            {
                var at100 = RecordingCsv.Load(file);
                var at200 = Doubled(at100);
                var reference = RhythmReference.Of(at100);
                var slow = Score(at100, reference, models, kind);
                var fast = Score(at200, reference, models, kind);
                TestContext.WriteLine($"{at100.Name}: walking shown {slow.AvatarWalkingSeconds:F2} / {fast.AvatarWalkingSeconds:F2} s, of the signal's {slow.AvatarWalkingInReference:F2} / {fast.AvatarWalkingInReference:F2} s, contacts {slow.Contacts} / {fast.Contacts}, fragments {slow.Fragments} / {fast.Fragments}");
                // The stream read a quarter sample later moves single contacts and gate verdicts: THR showed 2 % less of this
                // walk (86.0 -> 84.2 s), COR 5 % more contacts (129 -> 136); a stream read at the wrong rate or with every
                // other sample lost shows none of its walk or half its steps.
                Assert.That(fast.AvatarWalkingInReference, Is.EqualTo(slow.AvatarWalkingInReference).Within(0.03 * reference.WalkingSeconds + 0.2), $"{at100.Name}: the signal's walking shown");
                Assert.That(fast.AvatarWalkingSeconds - fast.AvatarWalkingInReference, Is.EqualTo(slow.AvatarWalkingSeconds - slow.AvatarWalkingInReference).Within(0.5), $"{at100.Name}: walking shown outside the signal's walking");
                Assert.That(fast.Contacts, Is.EqualTo(slow.Contacts).Within(Math.Max(3, 0.08 * slow.Contacts)), $"{at100.Name}: steps shown");
            }
        }

        static RealWorldScore Score(Recording recording, RhythmReference reference, GaitModels models, string kind)
        {
            var result = ReplayEvaluator.Run(recording, models.Create(kind, out _), keepTrace: true);
            return RealWorldScore.Of(recording, reference, kind, result.Predictions, result.Frames);
        }

        /// <summary>The recording at twice its rate, a quarter and three quarters through each interval on the Catmull-Rom cubic; its header kept.</summary>
        static Recording Doubled(Recording source)
        {
            var s = source.Samples.Select(x => x.Imu).ToList();
            var doubled = new List<RecordedSample>(2 * s.Count);
            for (int i = 0; i + 1 < s.Count; i++)
            {
                ImuSample p0 = s[Math.Max(0, i - 1)], p1 = s[i], p2 = s[i + 1], p3 = s[Math.Min(s.Count - 1, i + 2)];
                foreach (double u in new[] { 0.25, 0.75 })
                {
                    double At(double a, double b, double c, double d)
                        => 0.5 * (2 * b + (c - a) * u + (2 * a - 5 * b + 4 * c - d) * u * u + (3 * b - a - 3 * c + d) * u * u * u);
                    doubled.Add(new RecordedSample(new ImuSample(p1.Time + u * (p2.Time - p1.Time), At(p0.X, p1.X, p2.X, p3.X), At(p0.Y, p1.Y, p2.Y, p3.Y), At(p0.Z, p1.Z, p2.Z, p3.Z))));
                }
            }
            var recording = new Recording(source.Name + "_200hz", doubled);
            foreach (var entry in source.Metadata) recording.Metadata[entry.Key] = entry.Value;
            return recording;
        }
    }
}
