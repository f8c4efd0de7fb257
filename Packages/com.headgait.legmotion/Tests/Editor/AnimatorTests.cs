using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace HeadGait.Tests
{
    public class AnimatorTests
    {
        const double Dt = 0.01;
        const double Step = 0.55;
        static readonly PhaseMap Map = PhaseMap.Perry;

        static GaitPrediction Walk(double t, double s) => GaitPrediction.Walking(t, s, Step, 1, Map);
        static GaitPrediction Stand(double t) => GaitPrediction.Standing(t);

        /// <summary>Feeds n predictions of steady walking starting at stride position s0; returns the last frame.</summary>
        static AnimatorFrame WalkFor(GaitAnimatorStateMachine a, ref double t, double s0, int n, List<AnimatorFrame> frames = null)
        {
            AnimatorFrame f = default;
            for (int i = 0; i < n; i++)
            {
                f = a.Update(Walk(t, s0 + i * Dt / (2 * Step)));
                frames?.Add(f);
                t += Dt;
            }
            return f;
        }

        /// <summary>The frames of a fresh animator fed n predictions of steady walking from stride position s0.</summary>
        static List<AnimatorFrame> FramesFromStanding(double s0, int n)
        {
            var frames = new List<AnimatorFrame>();
            double t = 0;
            WalkFor(new GaitAnimatorStateMachine(Map), ref t, s0, n, frames);
            return frames;
        }

        [Test]
        public void StartsWithTheFootThatIsInSwing()
        {
            // Left toe-off (s = 0.62): the left foot swings and lands first.
            var a = new GaitAnimatorStateMachine(Map);
            double t = 0;
            Assert.That(a.Update(Walk(t, 0.62)).State, Is.EqualTo(LocomotionState.Standing)); t += Dt;
            Assert.That(a.Update(Walk(t, 0.63)).State, Is.EqualTo(LocomotionState.Standing)); t += Dt;
            Assert.That(a.Update(Walk(t, 0.64)).State, Is.EqualTo(LocomotionState.StartWalkLeft)); t += Dt;

            var b = new GaitAnimatorStateMachine(Map);
            t = 0;
            AnimatorFrame f = default;
            for (int i = 0; i < 3; i++, t += Dt) f = b.Update(Walk(t, 0.12 + i * 0.01));
            Assert.That(f.State, Is.EqualTo(LocomotionState.StartWalkRight));
        }

        [Test]
        public void AWalkRecognisedJustAfterAFootLandedStartsByLandingThatFoot()
        {
            // The right foot landed at s = 0.5 and the walk is recognised a little after: the avatar swings that foot in
            // and lands it, instead of planting it straight from standing (the step would not be seen).
            var frames = FramesFromStanding(0.505, 20);
            int start = frames.FindIndex(f => f.State != LocomotionState.Standing);
            Assert.That(frames[start].State, Is.EqualTo(LocomotionState.StartWalkRight));
            Assert.That(frames[start].Right, Is.EqualTo(GaitPhase.TerminalSwing));
            Assert.That(frames.FindIndex(start, f => f.Right == GaitPhase.InitialContact), Is.GreaterThan(start));

            // Recognised later than StartLookBack after that contact: the left foot, in swing, leads as before.
            frames = FramesFromStanding(0.5 + new AnimatorSettings().StartLookBack + 0.02, 20);
            Assert.That(frames.Find(f => f.State != LocomotionState.Standing).State, Is.EqualTo(LocomotionState.StartWalkLeft));
        }

        [Test]
        public void StartClipEndsWhenTheLeadFootLands()
        {
            var frames = FramesFromStanding(0.62, 80);
            int landing = frames.FindIndex(f => f.State == LocomotionState.Walking);
            Assert.That(landing, Is.GreaterThan(0));
            // Walking begins at the left initial contact (s wraps to ~0), ~0.38 strides after the start.
            Assert.That(frames[landing].StridePosition, Is.LessThan(0.05).Or.GreaterThan(0.97));
            Assert.That(frames[landing].Left, Is.EqualTo(GaitPhase.InitialContact).Or.EqualTo(GaitPhase.TerminalSwing));
            Assert.That(frames[landing - 1].WalkWeight, Is.GreaterThan(frames[5].WalkWeight));
        }

        [Test]
        public void IgnoresUpToTwoWrongPredictions()
        {
            var a = new GaitAnimatorStateMachine(Map);
            double t = 0;
            var f = WalkFor(a, ref t, 0.0, 200);
            Assert.That(f.State, Is.EqualTo(LocomotionState.Walking));
            double s = f.StridePosition;
            // Two standing predictions, one right one, then two that are half a stride off: nothing changes course.
            double d = Dt / (2 * Step);
            f = a.Update(Stand(t)); t += Dt;
            f = a.Update(Stand(t)); t += Dt;
            Assert.That(f.State, Is.EqualTo(LocomotionState.Walking));
            f = a.Update(Walk(t, s + 3 * d)); t += Dt;
            double expected = s + 5 * d;
            f = a.Update(Walk(t, expected - d + 0.5)); t += Dt;
            f = a.Update(Walk(t, expected + 0.5)); t += Dt;
            Assert.That(f.State, Is.EqualTo(LocomotionState.Walking));
            Assert.That(Math.Abs(PhaseMap.CyclicDelta(f.StridePosition, expected)), Is.LessThan(0.03));
        }

        [Test]
        public void ThreeConsecutiveWrongPhasesMakeItBlendToTheNewPhase()
        {
            var a = new GaitAnimatorStateMachine(Map);
            double t = 0;
            var f = WalkFor(a, ref t, 0.0, 200);
            double s = f.StridePosition + Dt / (2 * Step);
            // The classifier now insists the stride is 0.3 further on.
            bool resynced = false;
            for (int i = 0; i < 3; i++, t += Dt, s += Dt / (2 * Step))
            {
                f = a.Update(Walk(t, s + 0.3));
                if (i < 2) Assert.That(f.Resynchronised, Is.False);
                resynced |= f.Resynchronised;
            }
            Assert.That(resynced, Is.True);
            // After the blend time it follows the new phase.
            for (int i = 0; i < 15; i++, t += Dt, s += Dt / (2 * Step)) f = a.Update(Walk(t, s + 0.3));
            Assert.That(Math.Abs(PhaseMap.CyclicDelta(f.StridePosition, s - Dt / (2 * Step) + 0.3)), Is.LessThan(0.03));
        }

        [Test]
        public void FinishesWithTheFootThatLandsNextThenStands()
        {
            var a = new GaitAnimatorStateMachine(Map);
            double t = 0;
            // Walk until the stride is at 0.4: the left foot landed 0.4 strides ago (too long to be the closing
            // step), the right foot is in swing and lands next (at 0.5).
            double s0 = 0.4 - 200 * Dt / (2 * Step);
            var f = WalkFor(a, ref t, s0, 200);
            for (int i = 0; i < 3; i++, t += Dt) f = a.Update(Stand(t));
            Assert.That(f.State, Is.EqualTo(LocomotionState.FinishWalkRight));
            var states = new List<LocomotionState>();
            for (int i = 0; i < 60; i++, t += Dt) states.Add(a.Update(Stand(t)).State);
            Assert.That(states[states.Count - 1], Is.EqualTo(LocomotionState.Standing));
            int standAt = states.IndexOf(LocomotionState.Standing);
            // It stood once the right foot had landed: (0.5 - 0.4) of a 1.1 s stride = 0.11 s.
            Assert.That(standAt * Dt + 3 * Dt, Is.EqualTo(0.11).Within(0.04));
        }

        [Test]
        public void FootThatJustLandedClosesTheGaitWithoutAnotherStep()
        {
            // Standing is recognised ~0.2 s late, so typically a foot has just landed: here the right foot, at 0.5,
            // 0.1 strides before the standing predictions. The avatar settles on it instead of stepping again.
            var a = new GaitAnimatorStateMachine(Map);
            double t = 0;
            double s0 = 0.6 - 200 * Dt / (2 * Step);
            var f = WalkFor(a, ref t, s0, 200);
            for (int i = 0; i < 3; i++, t += Dt) f = a.Update(Stand(t));
            Assert.That(f.State, Is.EqualTo(LocomotionState.FinishWalkRight));
            double frozen = f.StridePosition;
            int n = 0;
            while (f.State != LocomotionState.Standing && n < 100)
            {
                f = a.Update(Stand(t));
                t += Dt;
                n++;
                if (f.State != LocomotionState.Standing) Assert.That(f.StridePosition, Is.EqualTo(frozen), "the pose holds while settling");
            }
            Assert.That(n * Dt, Is.EqualTo(a.Settings.BlendTime).Within(0.02));
        }

        [Test]
        public void ResumesWalkingIfWalkingReturnsDuringTheFinish()
        {
            var a = new GaitAnimatorStateMachine(Map);
            double t = 0;
            var f = WalkFor(a, ref t, 0.1, 200);
            double s = f.StridePosition;
            for (int i = 0; i < 3; i++, t += Dt) f = a.Update(Stand(t));
            Assert.That(f.State, Is.EqualTo(LocomotionState.FinishWalkRight).Or.EqualTo(LocomotionState.FinishWalkLeft));
            f = WalkFor(a, ref t, s + 6 * Dt / (2 * Step), 3);
            Assert.That(f.State, Is.EqualTo(LocomotionState.Walking));
        }

        [Test]
        public void SmoothingKeepsThePhaseSteadierThanNoisyPredictions()
        {
            var rnd = new Random(3);
            var a = new GaitAnimatorStateMachine(Map);
            double t = 0, s = 0, predErr = 0, animErr = 0;
            int n = 0;
            for (int i = 0; i < 1000; i++, t += Dt, s += Dt / (2 * Step))
            {
                double noise = 0.03 * (rnd.NextDouble() * 2 - 1);
                var f = a.Update(Walk(t, s + noise));
                if (i < 300) continue;
                predErr += Math.Abs(noise);
                animErr += Math.Abs(PhaseMap.CyclicDelta(f.StridePosition, s));
                n++;
            }
            Assert.That(animErr / n, Is.LessThan(0.6 * predErr / n));
        }

        [Test]
        public void AStepBackStopsAtTheToeOffTheFramesShowNotTheMaps()
        {
            // The right foot's stance share is latched at its contact at a 0.55 s step; the walk then slows, and at the
            // slower period the map's stance lasts longer. Predictions a little behind the clock just after the right toe-off
            // pull it back: checked against the map's later toe-off the step back looked clear, crossed the latched one, and
            // the right foot landed twice.
            var map = Map.WithStance(0.2, 1.1);
            var a = new GaitAnimatorStateMachine(map);
            var frames = new List<AnimatorFrame>();
            double t = 0;
            for (int i = 0; i < 200 && !(frames.Count > 20 && a.StridePosition > 0.6 && a.StridePosition < 0.7); i++, t += Dt)
                frames.Add(a.Update(GaitPrediction.Walking(t, 0.3 + i * Dt / (2 * Step), Step, 1, map)));
            Assert.That(a.StridePosition, Is.InRange(0.6, 0.7), "walked past the right foot's contact");
            double toeOff = PhaseMap.Wrap(map.StridePositionOfOnset(Foot.Right, GaitPhase.InitialContact) + map.StanceShare(Step));
            for (int i = 0; i < 400 && !(a.StridePosition > toeOff + 0.003 && a.StridePosition < toeOff + 0.1); i++, t += Dt)
                frames.Add(a.Update(GaitPrediction.Walking(t, a.StridePosition + 0.01, 0.9, 1, map)));
            Assert.That(frames[frames.Count - 1].Right, Is.EqualTo(GaitPhase.InitialSwing), "the right foot has lifted");
            Assert.That(GaitPhases.IsStance(map.PhaseAt(Foot.Right, a.StridePosition, 0.8)), Is.True, "where the map at the slower period still has it standing");
            for (int i = 0; i < 30; i++, t += Dt)
                frames.Add(a.Update(GaitPrediction.Walking(t, a.StridePosition - 0.05, 0.9, 1, map)));
            // On to the right foot's next contact: a second one in a row shows only once it comes.
            for (int i = 0; i < 400 && !(a.StridePosition > 0.55 && a.StridePosition < 0.6); i++, t += Dt)
                frames.Add(a.Update(GaitPrediction.Walking(t, a.StridePosition + 0.01, 0.9, 1, map)));
            Assert.That(a.StridePosition, Is.InRange(0.55, 0.6), "walked past the right foot's next contact");
            var contacts = PhaseEvents.Contacts(frames.ConvertAll(f => f.Time), frames.ConvertAll(f => f.Left), frames.ConvertAll(f => f.Right));
            for (int c = 1; c < contacts.Count; c++)
                Assert.That(contacts[c].Foot, Is.Not.EqualTo(contacts[c - 1].Foot), $"at {contacts[c].Time:F2} s the {contacts[c].Foot} foot lands twice");
        }

        [Test]
        public void StandingReportsStandingForBothFeet()
        {
            var a = new GaitAnimatorStateMachine(Map);
            var f = a.Update(Stand(0));
            Assert.That(f.State, Is.EqualTo(LocomotionState.Standing));
            Assert.That(f.Left, Is.EqualTo(GaitPhase.Standing));
            Assert.That(f.Right, Is.EqualTo(GaitPhase.Standing));
            Assert.That(f.WalkWeight, Is.EqualTo(0));
        }
    }
}
