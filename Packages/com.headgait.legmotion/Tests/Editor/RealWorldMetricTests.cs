using System;
using System.Collections.Generic;
using System.Linq;
using HeadGait.Synthetic;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>
    /// The unlabelled real-recording measures (<see cref="RhythmReference"/>, <see cref="RealWorldScore"/>,
    /// <see cref="RealWorldSummary"/>) on generated walks whose steps are known.
    /// </summary>
    public class RealWorldMetricTests
    {
        static Recording Walk(ulong seed, double stepFrequency, double seconds = 30, string activity = RealActivity.Walking)
        {
            var subject = GaitSubject.Random(seed);
            subject.StepFrequency = stepFrequency;
            var rec = WalkingStreamGenerator.Generate($"p{seed}_e1_{activity}", subject, new StreamScript().Stand(5).Walk(seconds, Foot.Left).Stand(5), seed);
            rec.Metadata["activity"] = activity;
            rec.Metadata["subject"] = $"p{seed}";
            return rec;
        }

        /// <summary>Frames and predictions that show exactly the recording's labels, one per sample.</summary>
        static (List<GaitPrediction> Predictions, List<AnimatorFrame> Frames) Perfect(Recording rec)
        {
            var p = new List<GaitPrediction>();
            var f = new List<AnimatorFrame>();
            foreach (var s in rec.Samples)
            {
                bool walking = s.Left != GaitPhase.Standing;
                p.Add(walking ? GaitPrediction.Walking(s.Imu.Time, 0, 0.5, 1, s.Left, s.Right) : GaitPrediction.Standing(s.Imu.Time));
                f.Add(new AnimatorFrame(s.Imu.Time, walking ? LocomotionState.Walking : LocomotionState.Standing, 0, s.Left, s.Right, walking ? 1 : 0, 0.5, false));
            }
            return (p, f);
        }

        /// <summary>Frames that walk wherever the labels walk but step <paramref name="stepsPerTrueStep"/> times per true step.</summary>
        static (List<GaitPrediction> Predictions, List<AnimatorFrame> Frames) Stepping(Recording rec, double stepFrequency, double stepsPerTrueStep)
        {
            var p = new List<GaitPrediction>();
            var f = new List<AnimatorFrame>();
            var map = PhaseMap.Perry;
            foreach (var s in rec.Samples)
            {
                double t = s.Imu.Time;
                bool walking = s.Left != GaitPhase.Standing;
                double stride = PhaseMap.Wrap(t * stepFrequency * stepsPerTrueStep / 2);
                var l = walking ? map.PhaseAt(Foot.Left, stride) : GaitPhase.Standing;
                var r = walking ? map.PhaseAt(Foot.Right, stride) : GaitPhase.Standing;
                p.Add(walking ? GaitPrediction.Walking(t, stride, 0.5, 1, l, r) : GaitPrediction.Standing(t));
                f.Add(new AnimatorFrame(t, walking ? LocomotionState.Walking : LocomotionState.Standing, stride, l, r, walking ? 1 : 0, 0.5, false));
            }
            return (p, f);
        }

        [TestCase(11UL, 1.4)]
        [TestCase(12UL, 1.9)]
        public void TheSignalsRhythmFindsTheGeneratedWalkAndItsCadence(ulong seed, double stepFrequency)
        {
            var rec = Walk(seed, stepFrequency);
            var reference = RhythmReference.Of(rec);
            var labelledWalking = rec.Samples.Where(s => s.Left != GaitPhase.Standing).Select(s => s.Imu.Time).ToList();
            Assert.That(reference.Bouts.Count, Is.EqualTo(1), string.Join("; ", reference.Bouts));
            var (start, end) = reference.Bouts[0];
            Assert.That(start, Is.EqualTo(labelledWalking[0]).Within(0.3), "the bout starts with the first step");
            // The head still decelerates after the closing contact: the bout may end up to a second later.
            Assert.That(end, Is.InRange(labelledWalking[labelledWalking.Count - 1] - 0.5, labelledWalking[labelledWalking.Count - 1] + 1.0), "the bout ends with the last step");
            Assert.That(reference.MedianCadence, Is.EqualTo(60 * stepFrequency).Within(0.04 * 60 * stepFrequency));
        }

        [Test]
        public void AStandingStreamWithHeadMovementShowsNoWalking()
        {
            var rec = WalkingStreamGenerator.Generate("still", GaitSubject.Random(5), new StreamScript().Stand(60, headMovement: 2.5), 5);
            var reference = RhythmReference.Of(rec);
            Assert.That(reference.Bouts, Is.Empty);
            Assert.That(reference.WalkingSeconds, Is.EqualTo(0));
            var (p, f) = Perfect(rec);
            var score = RealWorldScore.Of(rec, reference, "perfect", p, f);
            Assert.That(score.AvatarWalkingSeconds, Is.EqualTo(0));
            Assert.That(score.AvatarWalkingShare, Is.NaN);
        }

        [TestCase(11UL, 1.4)]
        [TestCase(12UL, 1.9)]
        public void APerfectPredictorShowsAllWalkingAtTheSignalsCadenceWithAlternatingFeet(ulong seed, double stepFrequency)
        {
            var rec = Walk(seed, stepFrequency);
            var (p, f) = Perfect(rec);
            var score = RealWorldScore.Of(rec, RhythmReference.Of(rec), "perfect", p, f);
            Assert.That(score.AvatarWalkingShare, Is.GreaterThan(0.95));
            Assert.That(score.CadenceRatio, Is.EqualTo(1).Within(0.05));
            Assert.That((double)score.AlternatingContacts / score.ConsecutiveContacts, Is.GreaterThan(0.99));
            Assert.That(score.Fragments, Is.EqualTo(1));
            Assert.That(score.StandingStartDelays, Has.Count.EqualTo(1));
            Assert.That(score.StandingStartDelays[0], Is.LessThan(0.6));
        }

        [TestCase(2.0)]
        [TestCase(0.5)]
        public void DoubledOrHalvedStepsShowInTheCadenceRatio(double stepsPerTrueStep)
        {
            const double frequency = 1.5;
            var rec = Walk(13, frequency);
            var (p, f) = Stepping(rec, frequency, stepsPerTrueStep);
            var score = RealWorldScore.Of(rec, RhythmReference.Of(rec), "stepping", p, f);
            Assert.That(score.CadenceRatio, Is.EqualTo(stepsPerTrueStep).Within(0.08 * stepsPerTrueStep));
        }

        [Test]
        public void SameFootTwiceIsNotAlternating()
        {
            var rec = Walk(14, 1.6);
            var (p, f) = Perfect(rec);
            // The right foot never leaves the ground: every contact is the left's.
            var limp = f.Select(x => new AnimatorFrame(x.Time, x.State, x.StridePosition, x.Left, x.State == LocomotionState.Standing ? GaitPhase.Standing : GaitPhase.MidStance, x.WalkWeight, x.StepPeriod, false)).ToList();
            var score = RealWorldScore.Of(rec, RhythmReference.Of(rec), "limp", p, limp);
            Assert.That(score.ConsecutiveContacts, Is.GreaterThan(10));
            Assert.That(score.AlternatingContacts, Is.EqualTo(0));
            Assert.That(score.CadenceRatio, Is.EqualTo(0.5).Within(0.05));
        }

        [Test]
        public void TheSummaryPoolsWalkingFilesAndChargesStillFilesWithAllTheirWalking()
        {
            var walk = Walk(15, 1.5);
            var still = WalkingStreamGenerator.Generate("p15_e2_standing", GaitSubject.Random(15), new StreamScript().Stand(20, headMovement: 1), 15);
            still.Metadata["activity"] = RealActivity.Standing;
            still.Metadata["subject"] = "p15";
            var (wp, wf) = Perfect(walk);
            // A predictor that walks through the first half of the standing file.
            var sp = new List<GaitPrediction>();
            var sf = new List<AnimatorFrame>();
            double mid = still.Samples[still.Samples.Count / 2].Imu.Time;
            foreach (var s in still.Samples)
            {
                bool walking = s.Imu.Time < mid;
                sp.Add(walking ? GaitPrediction.Walking(s.Imu.Time, 0, 0.5, 1, GaitPhase.MidStance, GaitPhase.MidSwing) : GaitPrediction.Standing(s.Imu.Time));
                sf.Add(new AnimatorFrame(s.Imu.Time, walking ? LocomotionState.Walking : LocomotionState.Standing, 0, walking ? GaitPhase.MidStance : GaitPhase.Standing, walking ? GaitPhase.MidSwing : GaitPhase.Standing, 1, 0.5, false));
            }
            var scores = new[]
            {
                RealWorldScore.Of(walk, RhythmReference.Of(walk), "x", wp, wf),
                RealWorldScore.Of(still, RhythmReference.Of(still), "x", sp, sf),
            };
            var summary = RealWorldSummary.Of("x", scores);
            Assert.That(summary.WalkingFiles, Is.EqualTo(1));
            Assert.That(summary.People, Is.EqualTo(1));
            Assert.That(summary.AvatarWalking, Is.GreaterThan(0.95));
            Assert.That(summary.PersonWorstTenth, Is.EqualTo(summary.AvatarWalking));
            Assert.That(summary.Still[RealActivity.Standing].Avatar, Is.EqualTo(0.5).Within(0.01));
            Assert.That(summary.Still[RealActivity.Standing].Reference, Is.EqualTo(0));
            Assert.That(summary.TugAvatar, Is.NaN);
        }

        /// <summary>Two walks with a 3 s stand between them; the avatar's frames (one per sample) come from <paramref name="walking"/>.</summary>
        static (Recording Rec, RhythmReference Reference, List<GaitPrediction> Predictions, List<AnimatorFrame> Frames) TwoBouts(ulong seed, Func<RhythmReference, double, bool> walking)
        {
            var subject = GaitSubject.Random(seed);
            subject.StepFrequency = 1.6;
            var rec = WalkingStreamGenerator.Generate($"p{seed}_e1_walking", subject, new StreamScript().Stand(5).Walk(12, Foot.Left).Stand(3).Walk(12, Foot.Right).Stand(5), seed);
            rec.Metadata["activity"] = RealActivity.Walking;
            var reference = RhythmReference.Of(rec);
            var p = new List<GaitPrediction>();
            var f = new List<AnimatorFrame>();
            foreach (var s in rec.Samples)
            {
                double t = s.Imu.Time;
                bool w = walking(reference, t);
                p.Add(w ? GaitPrediction.Walking(t, 0, 0.5, 1, GaitPhase.MidStance, GaitPhase.MidSwing) : GaitPrediction.Standing(t));
                f.Add(new AnimatorFrame(t, w ? LocomotionState.Walking : LocomotionState.Standing, 0, w ? GaitPhase.MidStance : GaitPhase.Standing, w ? GaitPhase.MidSwing : GaitPhase.Standing, w ? 1 : 0, 0.5, false));
            }
            return (rec, reference, p, f);
        }

        [TestCase(0.1)]
        [TestCase(0.7)]
        public void BoutsMetStandingMeasureTheDelayFromTheFirstStepToTheAvatarWalking(double delay)
        {
            // The avatar walks from each bout's first step + delay to its end.
            var (rec, reference, p, f) = TwoBouts(21, (r, t) => r.Bouts.Any(b => t >= b.Start + delay && t < b.End));
            Assert.That(reference.Bouts.Count, Is.EqualTo(2), string.Join("; ", reference.Bouts));
            var score = RealWorldScore.Of(rec, reference, "late", p, f);
            Assert.That(score.StandingStartDelays, Has.Count.EqualTo(2));
            foreach (var d in score.StandingStartDelays) Assert.That(d, Is.EqualTo(delay).Within(0.02));
        }

        [Test]
        public void ABoutTheAvatarWalksIntoFromBeforeIsNotCountedAsMetStanding()
        {
            // The avatar walks from 0.2 s into the first bout through the stand to the end of the second (a hold carrying it).
            var (rec, reference, p, f) = TwoBouts(22, (r, t) => t >= r.Bouts[0].Start + 0.2 && t < r.Bouts[r.Bouts.Count - 1].End);
            Assert.That(reference.Bouts.Count, Is.EqualTo(2), string.Join("; ", reference.Bouts));
            var score = RealWorldScore.Of(rec, reference, "carried", p, f);
            // The second bout is not counted as started at once: only the first is met standing.
            Assert.That(score.StandingStartDelays, Has.Count.EqualTo(1));
            Assert.That(score.StandingStartDelays[0], Is.EqualTo(0.2).Within(0.02));
        }

        [Test]
        public void AStartOnTheFirstStepJustBeforeItsDatedEdgeCountsAsOnTime()
        {
            // The bout's date is a smoothed edge after the first step's rise: an avatar walking from 0.2 s before it started
            // on that step (delay 0), and one from 0.6 s before was already walking (left out).
            var (rec, reference, p, f) = TwoBouts(24, (r, t) => r.Bouts.Any(b => t >= b.Start - 0.2 && t < b.End));
            var early = RealWorldScore.Of(rec, reference, "early", p, f);
            Assert.That(early.StandingStartDelays, Is.EqualTo(new[] { 0.0, 0.0 }));
            var (rec2, reference2, p2, f2) = TwoBouts(24, (r, t) => r.Bouts.Any(b => t >= b.Start - 0.6 && t < b.End));
            Assert.That(RealWorldScore.Of(rec2, reference2, "carried", p2, f2).StandingStartDelays, Is.Empty);
        }

        [Test]
        public void EveryBoutCountsAsShownOnTimeWhenTheAvatarWalksWithin03SOfItsFirstStepMetStandingOrWalkedInto()
        {
            // Walked into from before (the second bout, as after a turn) counts as on time; the first, met standing 0.2 s
            // after its first step, too.
            var (rec, reference, p, f) = TwoBouts(22, (r, t) => t >= r.Bouts[0].Start + 0.2 && t < r.Bouts[r.Bouts.Count - 1].End);
            var carried = RealWorldScore.Of(rec, reference, "carried", p, f);
            Assert.That((carried.BoutsFromFirstStep, carried.BoutsShownOnTime), Is.EqualTo((2, 2)));
            // 0.7 s late at each: neither; 0.1 s late: both.
            var (rec2, reference2, p2, f2) = TwoBouts(21, (r, t) => r.Bouts.Any(b => t >= b.Start + 0.7 && t < b.End));
            var late = RealWorldScore.Of(rec2, reference2, "late", p2, f2);
            Assert.That((late.BoutsFromFirstStep, late.BoutsShownOnTime), Is.EqualTo((2, 0)));
            var (rec3, reference3, p3, f3) = TwoBouts(21, (r, t) => r.Bouts.Any(b => t >= b.Start + 0.1 && t < b.End));
            Assert.That(RealWorldScore.Of(rec3, reference3, "prompt", p3, f3).BoutsShownOnTime, Is.EqualTo(2));
            // An avatar that walked before the first step but stood at it, and starts late, is not on time.
            var (rec4, reference4, p4, f4) = TwoBouts(21, (r, t) => r.Bouts.Any(b => (t >= b.Start - 0.5 && t < b.Start - 0.1) || (t >= b.Start + 0.7 && t < b.End)));
            Assert.That(RealWorldScore.Of(rec4, reference4, "stood at it", p4, f4).BoutsShownOnTime, Is.EqualTo(0));
            // Pooled over files by the summary: 2 of 4.
            var summary = RealWorldSummary.Of("x", new[] { carried, late });
            Assert.That((summary.WalkingBouts, summary.WalkingBoutsOnTime), Is.EqualTo((4, 0.5)));
            Assert.That(summary.TugBoutsOnTime, Is.NaN);
        }

        [Test]
        public void ABoutTheAvatarNeverWalksCountsItsWholeLength()
        {
            var (rec, reference, p, f) = TwoBouts(23, (r, t) => false);
            var score = RealWorldScore.Of(rec, reference, "never", p, f);
            Assert.That(score.StandingStartDelays, Has.Count.EqualTo(2));
            for (int b = 0; b < 2; b++) Assert.That(score.StandingStartDelays[b], Is.EqualTo(reference.Bouts[b].End - reference.Bouts[b].Start).Within(0.02));
        }

        [Test]
        public void StandingStartsSummariseCountMedianNinetiethAndShareWithinTheLimit()
        {
            var starts = RealWorldSummary.StandingStarts.Of(new[] { 0.9, 0.1, 0.2, 0.3, 0.5, 0.25, 0.15, 0.4, 0.35, 2.0 });
            Assert.That(starts.Count, Is.EqualTo(10));
            Assert.That(starts.Median, Is.EqualTo(0.35));
            Assert.That(starts.Ninetieth, Is.EqualTo(0.9));
            Assert.That(starts.ShareWithin, Is.EqualTo(0.5));
            var none = RealWorldSummary.StandingStarts.Of(Array.Empty<double>());
            Assert.That(none.Count, Is.EqualTo(0));
            Assert.That(none.Median, Is.NaN);
        }
    }
}
