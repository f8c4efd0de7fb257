using System;
using System.Collections.Generic;
using System.IO;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>The generated gait clips (normative joint angles on the mannequin) against the phase map and the core's state machine.</summary>
    public class GaitClipTests
    {
        /// <summary>A foot is on the ground when its lowest point is within this height (metres).</summary>
        const double Contact = 0.002;

        static CorrelationTemplate shipped;

        /// <summary>The COR template the prefab ships with; the clips are generated from its phase map.</summary>
        static CorrelationTemplate Shipped
        {
            get
            {
                if (shipped != null) return shipped;
                return shipped = CorrelationTemplate.Load(Path.Combine(TestData.ModelsFolder, GaitModels.CorrelationFile));
            }
        }

        static GaitClips Clips => new GaitClips(Shipped.PhaseMap);

        [Test]
        public void EachFootLandsExactlyAtItsInitialContactAndIsOffTheGroundInSwing()
        {
            var clips = Clips;
            foreach (Foot foot in new[] { Foot.Left, Foot.Right })
            {
                double ic = clips.InitialContact(foot);
                double toeOff = clips.ToeOff(foot);
                Assert.That(clips.FootHeight(LocomotionState.Walking, foot, ic), Is.EqualTo(0).Within(1e-9), $"{foot} at its initial contact");
                // Swing: from shortly after toe-off to shortly before the next contact the foot is clear of the ground.
                double swing = PhaseMap.Wrap(ic - toeOff);
                for (double f = 0.08; f <= 0.97; f += 0.01)
                {
                    double s = toeOff + f * swing;
                    Assert.That(clips.FootHeight(LocomotionState.Walking, foot, s), Is.GreaterThan(Contact), $"{foot} at stride {PhaseMap.Wrap(s):F3} ({f:P0} of swing)");
                }
                // 10 ms before contact (a stride is about 1.1 s) the heel is still coming down.
                Assert.That(clips.FootHeight(LocomotionState.Walking, foot, ic - 0.01), Is.GreaterThan(Contact), $"{foot} just before contact");
            }
        }

        [Test]
        public void InDoubleSupportTheTrailingFootStaysNearTheGround()
        {
            // The hips follow the foot that landed last; the normative angles and Winter's segment lengths must keep the
            // other stance foot on the ground too, or the avatar would hover or sink at each contact.
            var clips = Clips;
            foreach (Foot foot in new[] { Foot.Left, Foot.Right })
            {
                Foot other = foot == Foot.Left ? Foot.Right : Foot.Left;
                double ic = clips.InitialContact(foot), otherToeOff = clips.ToeOff(other);
                for (double s = ic; PhaseMap.Wrap(s - ic) < PhaseMap.Wrap(otherToeOff - ic) - 0.01; s += 0.005)
                    Assert.That(Math.Abs(clips.FootHeight(LocomotionState.Walking, other, s)), Is.LessThan(0.015), $"{other} at stride {PhaseMap.Wrap(s):F3}");
            }
        }

        [Test]
        public void StartClipsEndInTheWalkingPoseAndFinishClipsInTheStandingPose()
        {
            var clips = Clips;
            foreach (Foot foot in new[] { Foot.Left, Foot.Right })
            {
                var start = foot == Foot.Left ? LocomotionState.StartWalkLeft : LocomotionState.StartWalkRight;
                var finish = foot == Foot.Left ? LocomotionState.FinishWalkLeft : LocomotionState.FinishWalkRight;
                double ic = clips.InitialContact(foot);
                double before = ic - 1e-6;
                Assert.That(clips.WalkWeight(start, before), Is.EqualTo(1).Within(1e-6));
                Assert.That(clips.Pose(start, before).Of(foot).Hip, Is.EqualTo(clips.Pose(LocomotionState.Walking, before).Of(foot).Hip).Within(1e-3));
                Assert.That(clips.WalkWeight(finish, before), Is.EqualTo(0).Within(1e-6));
                Assert.That(clips.FootHeight(finish, foot, before), Is.LessThan(Contact), "the closing foot is down");
                // The step begins where the other foot landed: standing for a start, walking for a finish.
                double stepStart = clips.InitialContact(foot == Foot.Left ? Foot.Right : Foot.Left);
                Assert.That(clips.WalkWeight(start, stepStart), Is.EqualTo(0).Within(1e-9));
                Assert.That(clips.WalkWeight(finish, stepStart), Is.EqualTo(1).Within(1e-9));
            }
            var stand = clips.Pose(LocomotionState.Standing, 0.3);
            Assert.That(stand.FootHeight(Foot.Left), Is.EqualTo(0).Within(1e-9));
            Assert.That(stand.FootHeight(Foot.Right), Is.EqualTo(0).Within(1e-9));
            Assert.That(stand.HipHeight, Is.EqualTo(Mannequin.StandingHipHeight).Within(1e-9));
        }

        [Test]
        public void NormativeAnglesHaveThePublishedLandmarks()
        {
            // Perry & Burnfield / Winter landmarks: knee peak ~60 deg in initial swing, ankle peak plantarflexion just after toe-off.
            double kneePeak = 0, kneePeakAt = 0, anklePeak = 0, anklePeakAt = 0;
            for (double u = 0; u < 1; u += 0.005)
            {
                var a = NormativeGait.AtPerryCycle(u);
                if (a.Knee > kneePeak) { kneePeak = a.Knee; kneePeakAt = u; }
                if (a.Ankle < anklePeak) { anklePeak = a.Ankle; anklePeakAt = u; }
            }
            Assert.That(kneePeak, Is.InRange(55.0, 65.0));
            Assert.That(kneePeakAt, Is.InRange(0.68, 0.76));
            Assert.That(anklePeak, Is.InRange(-22.0, -14.0));
            Assert.That(anklePeakAt, Is.InRange(0.6, 0.68));
            // Time-warped to a map, each phase onset lands on the same angles as Perry's onset.
            var map = Shipped.PhaseMap;
            foreach (GaitPhase p in new[] { GaitPhase.MidStance, GaitPhase.PreSwing, GaitPhase.InitialSwing, GaitPhase.TerminalSwing })
                Assert.That(NormativeGait.At(map, map.Onset(p)).Knee, Is.EqualTo(NormativeGait.AtPerryCycle(PhaseMap.Perry.Onset(p)).Knee).Within(1e-9), p.ToString());
        }

        [Test]
        public void ReplayedRecordingWalksTheControllerThroughStartWalkingFinishWithFeetLandingOnThePredictedContacts()
        {
            // The code path of GaitLegAnimator: each sample pushed into the pipeline, each frame's state and stride
            // position written to the Animator, whose moving states play their clip at that stride position.
            var recording = TestData.Eval("start_stop");
            var pipeline = new GaitPipeline(new CorrelationClassifier(Shipped));
            var frames = new List<AnimatorFrame>();
            pipeline.FrameProduced += (p, f) => frames.Add(f);
            foreach (var row in recording.Samples) pipeline.Push(row.Imu);
            Assert.That(frames.Count, Is.GreaterThan(1000));

            var visited = new List<LocomotionState>();
            foreach (var f in frames)
                if (visited.Count == 0 || visited[visited.Count - 1] != f.State) visited.Add(f.State);
            for (int i = 1; i < visited.Count; i++)
                Assert.That(LocomotionTransitions.Allowed(visited[i - 1], visited[i]), $"{visited[i - 1]} -> {visited[i]} is not a controller transition");
            int walk = IndexAfter(visited, 0, s => s == LocomotionState.StartWalkLeft || s == LocomotionState.StartWalkRight);
            Assert.That(visited[0], Is.EqualTo(LocomotionState.Standing));
            Assert.That(walk, Is.GreaterThan(0), "a Start Walk state: " + string.Join(",", visited));
            int walking = IndexAfter(visited, walk, s => s == LocomotionState.Walking);
            int finish = IndexAfter(visited, walking, s => s == LocomotionState.FinishWalkLeft || s == LocomotionState.FinishWalkRight);
            int stand = IndexAfter(visited, finish, s => s == LocomotionState.Standing);
            Assert.That(stand, Is.GreaterThan(0), "Standing, Start Walk, Walking, Finish Walk, Standing in order: " + string.Join(",", visited));

            // Feet land where the core predicts initial contact, within one 10 ms sample.
            var clips = Clips;
            int checkedContacts = 0;
            foreach (Foot foot in new[] { Foot.Left, Foot.Right })
            {
                var predicted = new List<double>();
                var landed = new List<double>();
                for (int i = 1; i < frames.Count; i++)
                {
                    var a = frames[i - 1];
                    var b = frames[i];
                    if (a.State != LocomotionState.Walking || b.State != LocomotionState.Walking || b.Resynchronised) continue;
                    // The core predicts the contact on the frame whose stride position reaches the foot's initial contact
                    // (a fast resynchronisation can step over the short IC phase label, never over the position).
                    double moved = PhaseMap.Wrap(b.StridePosition - a.StridePosition);
                    double toContact = PhaseMap.Wrap(clips.InitialContact(foot) - a.StridePosition);
                    if (moved < 0.5 && toContact > 0 && toContact <= moved) predicted.Add(b.Time);
                    bool downBefore = clips.FootHeight(a.State, foot, a.StridePosition) <= Contact;
                    bool downNow = clips.FootHeight(b.State, foot, b.StridePosition) <= Contact;
                    // A backward blend undoes a toe-off; that is no landing.
                    if (downNow && !downBefore && moved > 0 && moved < 0.5) landed.Add(b.Time);
                }
                Assert.That(predicted.Count, Is.GreaterThan(5), $"{foot} contacts while walking");
                foreach (double t in predicted)
                {
                    Assert.That(Nearest(landed, t), Is.LessThanOrEqualTo(0.0101), $"{foot} predicted contact at {t:F3} s has no landing within 10 ms");
                    checkedContacts++;
                }
                foreach (double t in landed)
                    Assert.That(Nearest(predicted, t), Is.LessThanOrEqualTo(0.0101), $"{foot} lands at {t:F3} s where the core predicts no contact");
            }
            Assert.That(checkedContacts, Is.GreaterThan(10));
        }

        [Test]
        public void TheStateMachineOnlyTakesTransitionsTheControllerHas()
        {
            foreach (var recording in TestData.EvalSet())
            {
                var pipeline = new GaitPipeline(new CorrelationClassifier(Shipped));
                var last = LocomotionState.Standing;
                pipeline.FrameProduced += (p, f) =>
                {
                    Assert.That(f.State == last || LocomotionTransitions.Allowed(last, f.State), $"{recording.Name}: {last} -> {f.State} at {f.Time:F2} s");
                    last = f.State;
                };
                foreach (var row in recording.Samples) pipeline.Push(row.Imu);
            }
        }

        static int IndexAfter(List<LocomotionState> states, int from, Predicate<LocomotionState> match)
        {
            for (int i = from + 1; i < states.Count; i++)
                if (match(states[i])) return i;
            return -1;
        }

        static double Nearest(List<double> times, double t)
        {
            double best = double.PositiveInfinity;
            foreach (double x in times) best = Math.Min(best, Math.Abs(x - t));
            return best;
        }
    }
}
