using System.Collections.Generic;
using HeadGait.Synthetic;
using HeadGait.Training;
using NUnit.Framework;

namespace HeadGait.Tests
{
    public class RhythmHoldTests
    {
        /// <summary>The generated walk with turns made as slow and calm as a glasses wearer's (40 % slower, 0.4 of the movement).</summary>
        static Recording CalmWalkWithTurns()
            => RecordingAugmentation.Transform(TestData.Eval("walk_turns"), 1.4, 0.4, 0.4, 0.4, new AugmentationSettings().SlowWindowSeconds, "calm turns");

        /// <summary>Runs of the avatar walking (any state but Standing) that begin while the labels walk, and the share of labelled walking shown walking.</summary>
        static (int Fragments, double Shown) Walks(Recording r, ReplayResult result)
        {
            int fragments = 0, walkingFrames = 0, shown = 0, row = 0;
            bool was = false;
            foreach (var f in result.Frames)
            {
                while (row + 1 < r.Samples.Count && r.Samples[row + 1].Imu.Time <= f.Time) row++;
                bool labelled = r.Samples[row].Left != GaitPhase.Standing;
                bool walking = f.State != LocomotionState.Standing;
                if (labelled)
                {
                    walkingFrames++;
                    if (walking) shown++;
                    if (walking && !was) fragments++;
                }
                was = walking;
            }
            return (fragments, walkingFrames == 0 ? 0 : (double)shown / walkingFrames);
        }

        [Test]
        public void ACalmSlowWalkWithTurnsStaysOneWalk()
        {
            // COR loses the calm walker in the turns (the head yaws, the lateral channel takes in the forward one) and
            // at the quietest steps; the head's rhythm goes on, and so do the avatar's legs.
            var calm = CalmWalkWithTurns();
            var held = ReplayEvaluator.Run(calm, new CorrelationClassifier(TestData.Template), keepTrace: true);
            var unheld = ReplayEvaluator.Run(calm, new CorrelationClassifier(TestData.Template), keepTrace: true,
                holdSettings: new RhythmHoldSettings { Enabled = false });
            var (heldFragments, heldShown) = Walks(calm, held);
            var (unheldFragments, unheldShown) = Walks(calm, unheld);
            Assert.That(unheldFragments, Is.GreaterThan(1), "the classifier alone breaks the walk up");
            Assert.That(heldFragments, Is.EqualTo(1));
            Assert.That(heldShown, Is.GreaterThan(0.95));
            Assert.That(heldShown, Is.GreaterThan(unheldShown));
        }

        [Test]
        public void StandingWithHeadMovementStaysStanding()
        {
            // Standing and looking around, nodding and bobbing, with now and then a step's worth of head movement (THR and COR
            // take 2 % of it for walking): the hold keeps only walks the classifier started, and these short false walks
            // it does not prolong.
            var script = new StreamScript().Stand(30, 1.5).Stand(30, 3.0);
            var rec = WalkingStreamGenerator.Generate("standing with head movement", new GaitSubject(), script, 7);
            foreach (var make in new System.Func<IGaitClassifier>[] { () => new ThresholdClassifier(TestData.CommittedThreshold), () => new CorrelationClassifier(TestData.Template) })
            {
                var held = ReplayEvaluator.Run(rec, make(), keepTrace: true);
                var unheld = ReplayEvaluator.Run(rec, make(), keepTrace: true, holdSettings: new RhythmHoldSettings { Enabled = false });
                Assert.That(Walking(held.Frames), Is.LessThanOrEqualTo(Walking(unheld.Frames)));
            }
        }

        [Test]
        public void TheHeadsRhythmAloneDoesNotStartAWalk()
        {
            // A gate whose regression refuses every window but which passes any window that keeps a walking rhythm: on the
            // generated straight walk the rhythm is there throughout, yet a walk starts only where the regression scores
            // the window as walking (sitting and picking things up keep a step-like rhythm now and then). The same gate
            // with its regression passing walks, so the stream does start a walk where the score allows.
            var rec = TestData.Eval("walk_straight");
            var committed = TestData.CommittedThreshold;
            var stepped = 0;
            foreach (double bias in new[] { -1.0, 1.0 })
            {
                var weights = new double[WalkingGate.WeightCount];
                weights[WalkingGate.InputCount] = bias;
                var settings = committed.Clone();
                settings.Gate = new WalkingGate(weights, committed.Gate.LevelTolerance, usesStepRhythm: true);
                var result = ReplayEvaluator.Run(rec, new ThresholdClassifier(settings), keepTrace: true);
                if (bias < 0) Assert.That(Walking(result.Frames), Is.Zero, "the rhythm alone started a walk");
                else stepped = Walking(result.Frames);
            }
            Assert.That(stepped, Is.GreaterThan(0));
        }

        static int Walking(List<AnimatorFrame> frames) => frames.FindAll(f => f.State != LocomotionState.Standing).Count;

        [Test]
        public void AWalkHandedBackOnTheOtherFootKeepsTheFeetAlternating()
        {
            // A 0.5-s-step walk: the classifier drops it to standing for a second (the hold runs its clock on), and picks it
            // up again anywhere from a little to well over half a stride off the held clock (the other foot's phase, or
            // its own phase flipping feet). However far, and whichever way, the avatar's feet keep alternating.
            const double step = 0.5, dt = 0.01;
            for (double offset = 0.1; offset < 0.95; offset += 0.05)
            {
                var hold = new RhythmHold(PhaseMap.Perry);
                var animator = new GaitAnimatorStateMachine(PhaseMap.Perry);
                var times = new List<double>();
                var left = new List<GaitPhase>();
                var right = new List<GaitPhase>();
                var rhythm = new RhythmReading(true, step);
                for (int i = 0; i < 800; i++)
                {
                    double t = i * dt, position = t / (2 * step);
                    var p = t < 3 ? GaitPrediction.Walking(t, position, step, 1, PhaseMap.Perry)
                        : t < 4 ? GaitPrediction.Standing(t)
                        : GaitPrediction.Walking(t, PhaseMap.Wrap(position + offset), step, 1, PhaseMap.Perry);
                    var f = animator.Update(hold.Apply(p, rhythm));
                    if (t > 0.5) Assert.That(f.State, Is.Not.EqualTo(LocomotionState.Standing), $"offset {offset:F2}: the walk is shown throughout");
                    times.Add(t);
                    left.Add(f.Left);
                    right.Add(f.Right);
                }
                var contacts = PhaseEvents.Contacts(times, left, right);
                Assert.That(contacts.Count, Is.GreaterThan(14));
                for (int c = 1; c < contacts.Count; c++)
                    Assert.That(contacts[c].Foot, Is.Not.EqualTo(contacts[c - 1].Foot), $"offset {offset:F2}: at {contacts[c].Time:F2} s the {contacts[c].Foot} foot lands twice");
            }
        }

        [Test]
        public void TheHoldNeverStartsAWalk()
        {
            // However steady the rhythm, a walk the classifier never started is not shown.
            var hold = new RhythmHold(PhaseMap.Perry);
            var rhythm = new RhythmReading(true, 0.6);
            for (int i = 0; i < 500; i++) Assert.That(hold.Apply(GaitPrediction.Standing(i * 0.01), rhythm).IsWalking, Is.False);
        }

        [Test]
        public void AHeldWalkRunsOnItsClockAndLetsGoWhenTheRhythmEnds()
        {
            var hold = new RhythmHold(PhaseMap.Perry);
            var walking = GaitPrediction.Walking(1.0, 0.25, 0.5, 1, PhaseMap.Perry);
            Assert.That(hold.Apply(walking, default).StridePosition, Is.EqualTo(0.25));
            // The classifier drops the walk; the rhythm (step period 0.6 s) holds it, its stride position moving on at that period.
            var held = hold.Apply(GaitPrediction.Standing(1.3), new RhythmReading(true, 0.6));
            Assert.That(held.IsWalking, Is.True);
            Assert.That(held.StridePosition, Is.EqualTo(0.25 + 0.3 / 1.2).Within(1e-9));
            Assert.That(held.StepPeriod, Is.EqualTo(0.6));
            Assert.That(hold.Apply(GaitPrediction.Standing(1.4), new RhythmReading(true, 0.6)).StridePosition, Is.EqualTo(0.5 + 0.1 / 1.2).Within(1e-9));
            // The rhythm ends: standing, and a returning rhythm does not bring the walk back.
            Assert.That(hold.Apply(GaitPrediction.Standing(1.5), new RhythmReading(false, 0.6)).IsWalking, Is.False);
            Assert.That(hold.Apply(GaitPrediction.Standing(1.6), new RhythmReading(true, 0.6)).IsWalking, Is.False);
            Assert.That(hold.HeldWindows, Is.EqualTo(2));
        }

        [Test]
        public void AnEstablishedWalkRidesOutAStepWithoutRhythmButNotAStop()
        {
            foreach (bool stilled in new[] { false, true })
            {
                var hold = new RhythmHold(PhaseMap.Perry);
                // The classifier walks 3 s (longer than the rhythm's span) at 0.5-s steps, then says standing.
                for (int i = 0; i <= 300; i++) hold.Apply(GaitPrediction.Walking(i * 0.01, i * 0.01, 0.5, 1, PhaseMap.Perry), default);
                var failing = new RhythmReading(false, 0.5, stilled);
                // The rhythm fails: a walker still moving is held for one step, one who has calmed is let go at once.
                Assert.That(hold.Apply(GaitPrediction.Standing(3.01), failing).IsWalking, Is.EqualTo(!stilled));
                Assert.That(hold.Apply(GaitPrediction.Standing(3.4), failing).IsWalking, Is.EqualTo(!stilled));
                Assert.That(hold.Apply(GaitPrediction.Standing(3.52), failing).IsWalking, Is.False);
            }
            // A walk shown for less than the rhythm's span is not held past its rhythm (the classifier's short false walks).
            var young = new RhythmHold(PhaseMap.Perry);
            for (int i = 0; i <= 100; i++) young.Apply(GaitPrediction.Walking(i * 0.01, i * 0.01, 0.5, 1, PhaseMap.Perry), default);
            Assert.That(young.Apply(GaitPrediction.Standing(1.01), new RhythmReading(false, 0.5)).IsWalking, Is.False);
        }

        [Test]
        public void AWalkResumedSoonAfterAnEstablishedOneLetGoIsHeldAsThatWalk()
        {
            // Walks 3 s at 0.5-s steps, lets go (rhythm failing beyond its grace, the head moving or stilled), then the
            // classifier walks again from `resume` s for 0.2 s and says standing with the rhythm still failing.
            bool HeldAfterResume(double resume, bool stilledAtLetGo, double resumeWithin)
            {
                var hold = new RhythmHold(PhaseMap.Perry, new RhythmHoldSettings { ResumeWithin = resumeWithin });
                for (int i = 0; i <= 300; i++) hold.Apply(GaitPrediction.Walking(i * 0.01, i * 0.01, 0.5, 1, PhaseMap.Perry), default);
                var failing = new RhythmReading(false, 0.5);
                Assert.That(hold.Apply(GaitPrediction.Standing(3.01), new RhythmReading(false, 0.5, stilledAtLetGo)).IsWalking, Is.EqualTo(!stilledAtLetGo));
                Assert.That(hold.Apply(GaitPrediction.Standing(3.6), failing).IsWalking, Is.False, "let go after one step");
                for (int i = 0; i <= 20; i++) hold.Apply(GaitPrediction.Walking(resume + i * 0.01, i * 0.01, 0.5, 1, PhaseMap.Perry), default);
                return hold.Apply(GaitPrediction.Standing(resume + 0.21), failing).IsWalking;
            }
            // The walk back after a turn: resumed within the rhythm's span of the let-go, it rides out a step as the walk did.
            Assert.That(new RhythmHoldSettings().ResumeWithin, Is.EqualTo(new RhythmHoldSettings().EstablishedAfter));
            Assert.That(HeldAfterResume(4.0, false, new RhythmHoldSettings().ResumeWithin), Is.True);
            Assert.That(HeldAfterResume(4.0, false, 0), Is.False, "off: a young walk");
            // Not after a stop (the head stilled), nor long after the let-go: a young walk, let go at its first refusal.
            Assert.That(HeldAfterResume(4.0, true, new RhythmHoldSettings().ResumeWithin), Is.False);
            Assert.That(HeldAfterResume(3.6 + 2.6, false, new RhythmHoldSettings().ResumeWithin), Is.False);
        }

        [Test]
        public void TheGlassesUpAndGosWalkBackAfterTheTurnIsShownMore()
        {
            // A real glasses wearer's timed up-and-go (d2 user 9): each walk back begins as the hold lets go of the turn, and
            // the shipped COR's first walks there were young and dropped (shown 1.8 s after the first step of one).
            var rec = RecordingCsv.Load(TestData.GlassesFiles("cg2_u09_*_tug.csv")[0]);
            var reference = RhythmReference.Of(rec);
            var models = TestData.ShippedModels();
            double Shown(RhythmHoldSettings hold)
            {
                var result = ReplayEvaluator.Run(rec, models.Create("cor", out _), keepTrace: true, holdSettings: hold);
                int inBouts = 0, walking = 0;
                foreach (var f in result.Frames)
                {
                    if (!reference.IsWalking(f.Time)) continue;
                    inBouts++;
                    if (f.State != LocomotionState.Standing) walking++;
                }
                return (double)walking / inBouts;
            }
            double resumed = Shown(new RhythmHoldSettings()), young = Shown(new RhythmHoldSettings { ResumeWithin = 0 });
            Assert.That(resumed, Is.GreaterThan(young + 0.03), $"resumed {resumed:P1}, young {young:P1}");
        }

        [Test]
        public void AStopIsNotHeld()
        {
            // The generated start-stop walk: the avatar stands within a second of every stop, held or not.
            var rec = TestData.Eval("start_stop");
            var held = ReplayEvaluator.Run(rec, new ThresholdClassifier(TestData.CommittedThreshold), keepTrace: true);
            var unheld = ReplayEvaluator.Run(rec, new ThresholdClassifier(TestData.CommittedThreshold), keepTrace: true,
                holdSettings: new RhythmHoldSettings { Enabled = false });
            var stops = new List<double>();
            for (int i = 1; i < rec.Samples.Count; i++)
                if (rec.Samples[i - 1].Left != GaitPhase.Standing && rec.Samples[i].Left == GaitPhase.Standing) stops.Add(rec.Samples[i].Imu.Time);
            Assert.That(stops.Count, Is.EqualTo(6));
            foreach (var stop in stops)
            {
                double stood = held.Frames.Find(f => f.Time >= stop && f.State == LocomotionState.Standing).Time;
                double stoodUnheld = unheld.Frames.Find(f => f.Time >= stop && f.State == LocomotionState.Standing).Time;
                Assert.That(stood - stop, Is.InRange(0.0, 1.0), $"stop at {stop:F1} s");
                Assert.That(stood - stoodUnheld, Is.LessThanOrEqualTo(0.4), $"stop at {stop:F1} s");
            }
        }
    }
}
