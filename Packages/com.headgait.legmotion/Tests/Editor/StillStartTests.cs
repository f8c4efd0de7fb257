using System;
using System.Collections.Generic;
using System.Linq;
using HeadGait.Synthetic;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>
    /// Walks that start from a still head (<see cref="StepClockSettings.StillStartMaxBend"/>,
    /// <see cref="PhaseFilterSettings.StillStartMaxBend"/>): bending down to the floor that begins with step-like bumps is
    /// not shown as walking, or only briefly; the same bumps with the head level walk as they did without the rule.
    /// </summary>
    public class StillStartTests
    {
        const double G = 9.80665, Cycle = 6, First = 2;

        /// <summary>
        /// Standing still, then <paramref name="times"/> times: three heel-strike-like bumps of SMV 0.5 s apart (3 m/s^2; on
        /// the real glasses, false walks in the picking-up files are mostly begun by such a bump just before the bend) with
        /// the head swaying to alternate sides, while it pitches forward by <paramref name="degrees"/> over 0.8 s from the first
        /// bump on, stays down a second and comes up over a second. <paramref name="degrees"/> 0: the bumps with the head level.
        /// </summary>
        static Recording BumpsThenBend(int times, double degrees, int bumps = 3)
        {
            var rows = new List<RecordedSample>();
            for (int i = 0; i < (First + times * Cycle) * 100; i++)
            {
                double t = i * 0.01, c = (t - First) % Cycle;
                double pitch = 0, bump = 0, sway = 0;
                if (t >= First)
                {
                    if (c < 0.8) pitch = c / 0.8;
                    else if (c < 1.8) pitch = 1;
                    else if (c < 2.8) pitch = 1 - (c - 1.8);
                    for (int k = 0; k < bumps; k++)
                    {
                        double d = c - k * 0.5;
                        bump += 3 * Math.Exp(-d * d / (2 * 0.04 * 0.04));
                    }
                    if (c < 0.5 * bumps) sway = 0.8 * Math.Sin(Math.PI * c / 0.5);
                }
                double angle = pitch * degrees * Math.PI / 180, a = G + bump;
                rows.Add(new RecordedSample(new ImuSample(t, a * Math.Sin(angle), sway + 0.05 * Math.Sin(7 * t), a * Math.Cos(angle))));
            }
            return new Recording("bumps then a bend", rows);
        }

        static GaitModels Models => TestData.ShippedModels();

        /// <summary>THR's default settings with a walking gate that passes everything, its clock changed by <paramref name="change"/>.</summary>
        static IGaitClassifier OpenGateThr(Action<StepClockSettings> change)
        {
            var s = new ThresholdSettings { Gate = WalkingGate.Open };
            change(s.Clock);
            return new ThresholdClassifier(s);
        }

        /// <summary>THR or COR as shipped, but with a walking gate that passes everything (the bumps are the gate's to judge otherwise).</summary>
        static IGaitClassifier StepClocked(string name, double maxBend)
        {
            if (name == "thr") return OpenGateThr(c => c.StillStartMaxBend = maxBend);
            var settings = new CorrelationSettings();
            settings.Clock.StillStartMaxBend = maxBend;
            return new CorrelationClassifier(Models.Correlation.With(gate: WalkingGate.Open), settings);
        }

        /// <summary>Windows shown walking, the longest run of them, and the first one's time.</summary>
        internal static (int Walking, int Longest, double First) Walks(IGaitClassifier c, Recording r, Action<double> beforeEach = null)
        {
            int walking = 0, run = 0, longest = 0;
            double first = double.NaN;
            var pre = new StreamPreprocessor(new PreprocessorSettings { History = Math.Max(c.WindowLength, StepRhythm.HistorySamples) });
            foreach (var s in r.Samples)
                pre.Push(s.Imu, w =>
                {
                    beforeEach?.Invoke(w.EndTime);
                    if (c.Classify(w).IsWalking)
                    {
                        walking++;
                        longest = Math.Max(longest, ++run);
                        if (double.IsNaN(first)) first = w.EndTime;
                    }
                    else run = 0;
                });
            return (walking, longest, first);
        }

        [TestCase("thr")]
        [TestCase("cor")]
        public void BumpsAsTheHeadBendsFromStillAreNoWalk(string name)
        {
            var bends = BumpsThenBend(5, 60);
            var without = Walks(StepClocked(name, 0), bends);
            Assert.That(without.Longest, Is.GreaterThan(30), "without the rule the bumps start a walk that lasts");
            var with = Walks(StepClocked(name, HeadTilt.DefaultStillStartMaxBend), bends);
            // The first bump comes with the head still level; its pitch passes the limit a quarter second into the bend (over
            // BendMean), and the next reading of the head (every EveryWindows) withdraws the walk.
            Assert.That(with.Longest, Is.LessThan(35), "withdrawn within 0.35 s, if started at all");
            Assert.That(with.Walking, Is.LessThan(without.Walking / 2));
        }

        [TestCase("thr")]
        [TestCase("cor")]
        public void TheSameBumpsWithTheHeadLevelWalkAsBefore(string name)
        {
            var level = BumpsThenBend(5, 0);
            var without = Walks(StepClocked(name, 0), level);
            var with = Walks(StepClocked(name, HeadTilt.DefaultStillStartMaxBend), level);
            Assert.That(without.Walking, Is.GreaterThan(300), "the bumps walk");
            Assert.That(with.Walking, Is.EqualTo(without.Walking));
            Assert.That(with.First, Is.EqualTo(without.First), "no later start");
        }

        /// <summary>
        /// Standing still 4 s, the head pitching <paramref name="degrees"/> down over 0.8 s, staying down a second and coming
        /// back up over a second (up at 6.8 s), then, once it has been back up 1.7 s, <paramref name="bumps"/> heel-strike-like
        /// bumps 0.5 s apart with the head swaying to alternate sides, and standing again: picking something up, and the
        /// bumps of straightening up and shifting the feet after it. <paramref name="degrees"/> 0: the bumps alone.
        /// </summary>
        static Recording BendThenBumps(double degrees, int bumps)
            => HeadBendThenBumps("a bend, then bumps", degrees, down: 4, moveDown: 0.8, hold: 1, moveUp: 1, bumpsAt: 8.5, bumps, seconds: 14);

        /// <summary>
        /// Standing still (head level) until <paramref name="down"/> s, the head pitching <paramref name="degrees"/> down over
        /// <paramref name="moveDown"/> s, staying down <paramref name="hold"/> s and coming back up over <paramref name="moveUp"/> s;
        /// from <paramref name="bumpsAt"/> s, <paramref name="bumps"/> heel-strike-like bumps 0.5 s apart with the head swaying
        /// to alternate sides; <paramref name="seconds"/> long at 100 Hz.
        /// </summary>
        static Recording HeadBendThenBumps(string name, double degrees, double down, double moveDown, double hold, double moveUp, double bumpsAt, int bumps, double seconds)
        {
            double up = down + moveDown + hold;
            var rows = new List<RecordedSample>();
            for (int i = 0; i < seconds * 100; i++)
            {
                double t = i * 0.01, pitch = 0, bump = 0, sway = 0;
                if (t >= down && t < down + moveDown) pitch = (t - down) / moveDown;
                else if (t >= down + moveDown && t < up) pitch = 1;
                else if (t >= up && t < up + moveUp) pitch = 1 - (t - up) / moveUp;
                for (int k = 0; k < bumps; k++)
                {
                    double d = t - bumpsAt - k * 0.5;
                    bump += 3 * Math.Exp(-d * d / (2 * 0.04 * 0.04));
                }
                if (t >= bumpsAt && t < bumpsAt + 0.5 * bumps) sway = 0.8 * Math.Sin(Math.PI * (t - bumpsAt) / 0.5);
                double angle = pitch * degrees * Math.PI / 180, a = G + bump;
                rows.Add(new RecordedSample(new ImuSample(t, a * Math.Sin(angle), sway + 0.05 * Math.Sin(7 * t), a * Math.Cos(angle))));
            }
            return new Recording(name, rows);
        }

        /// <summary>
        /// COR waits for a third contact when a walk starts within <see cref="HeadTilt.MoveStartRecent"/> of the head's tilt
        /// moving more than <see cref="HeadTilt.MoveStartChange"/> (<see cref="StepClockSettings.TiltMoveStartContacts"/>):
        /// two bumps after coming up from a 60-degree bend are no walk, where without the rule (and with the head level) they
        /// are one. On the real glasses most of COR's false walks in the picking-up files started so.
        /// </summary>
        [Test]
        public void CorShowsNoWalkForTwoBumpsAfterTheHeadComesBackUp()
        {
            IGaitClassifier Cor(int contacts)
            {
                // The bumps come after 5 s of standing, where the shipped still-start rule (3 contacts) alone holds two
                // back; held at 2 here, so the tilt rule is what this test judges.
                var settings = new CorrelationSettings();
                settings.Clock.StillStartContacts = 2;
                if (contacts >= 0) settings.Clock.TiltMoveStartContacts = contacts;
                return new CorrelationClassifier(Models.Correlation.With(gate: WalkingGate.Open), settings);
            }
            var bent = BendThenBumps(60, 2);
            Assert.That(Walks(Cor(0), bent).Walking, Is.GreaterThan(30), "without the rule the two bumps walk");
            Assert.That(Walks(Cor(0), BendThenBumps(0, 2)).Walking, Is.GreaterThan(30), "the bumps alone walk");
            Assert.That(Walks(Cor(-1), BendThenBumps(0, 2)).Walking, Is.GreaterThan(30), "the bumps alone walk with the shipped tilt rule");
            Assert.That(Walks(Cor(-1), bent).Walking, Is.EqualTo(0), "with the shipped tilt rule, after the bend they do not");
            var walk = Walks(Cor(-1), BendThenBumps(60, 6));
            Assert.That(walk.Longest, Is.GreaterThan(30), "six bumps after the bend still walk, from their third");
        }

        /// <summary>
        /// Standing still (head level) until 1.6 s, the head pitching <paramref name="degrees"/> down over 0.3 s, staying down
        /// <paramref name="hold"/> seconds and coming back up over 0.3 s, then, from <paramref name="bumpsAt"/> seconds,
        /// <paramref name="bumps"/> heel-strike-like bumps 0.5 s apart with the head swaying to alternate sides: a glance to
        /// the floor, then a shift of the feet (one bump) or a walk (several). The bumps come within 5 s of the stream's start
        /// and less than 40 degrees of tilt move, so neither <see cref="StepClockSettings.StillStartContacts"/> nor
        /// <see cref="StepClockSettings.TiltMoveStartContacts"/> holds them back.
        /// </summary>
        static Recording StillBendThenBumps(double degrees, double hold, double bumpsAt, int bumps)
            => HeadBendThenBumps("a bend from a still head, then bumps", degrees, down: 1.6, moveDown: 0.3, hold, moveUp: 0.3, bumpsAt, bumps, seconds: bumpsAt + 0.5 * bumps + 4);

        /// <summary>
        /// COR waits for a second contact when a walk starts within <see cref="HeadTilt.BendStartRecent"/> of the head's pitch
        /// lying more than <see cref="HeadTilt.BendStartBend"/> from a still head's (<see cref="StepClockSettings.BendStartContacts"/>):
        /// one bump after a 38-degree glance to the floor is no walk, where without the rule (and with the head level) it is
        /// one; six bumps after it walk, shown from their second, with the walk they are without the rule.
        /// </summary>
        [Test]
        public void CorShowsNoWalkForOneBumpAfterTheHeadBentFromStill()
        {
            IGaitClassifier Cor(int contacts)
            {
                var settings = new CorrelationSettings();
                if (contacts >= 0) settings.Clock.BendStartContacts = contacts;
                return new CorrelationClassifier(Models.Correlation.With(gate: WalkingGate.Open), settings);
            }
            var bent = StillBendThenBumps(38, 0.5, 4.6, 1);
            Assert.That(Walks(Cor(0), bent).Walking, Is.GreaterThan(30), "without the rule the bump walks");
            Assert.That(Walks(Cor(-1), StillBendThenBumps(0, 0.5, 4.6, 1)).Walking, Is.GreaterThan(30), "the bump with the head level walks as shipped");
            Assert.That(Walks(Cor(-1), bent).Walking, Is.EqualTo(0), "as shipped, after the bend it does not");
            var without = Walks(Cor(0), StillBendThenBumps(38, 0.5, 4.6, 6));
            var with = Walks(Cor(-1), StillBendThenBumps(38, 0.5, 4.6, 6));
            Assert.That(with.Longest, Is.GreaterThan(250), "six bumps after the bend walk");
            Assert.That(with.First - without.First, Is.InRange(0.4, 0.6), "from their second contact, a step later");
            Assert.That(without.Walking - with.Walking, Is.InRange(40, 60), "the walk otherwise as without the rule");
        }

        /// <summary>
        /// COR's false walks in still activities mostly began with a step-like bump from a still head and took no second step
        /// (<see cref="StepClockSettings.StillStartContacts"/>): on the real glasses' picking-up and standing recordings
        /// (shipped models) COR shows a fifth less time as walking with the rule (2 contacts) than without.
        /// </summary>
        [Test]
        public void CorShowsLessOfTheGlassesStillRecordingsAsWalkingWithTheStillStartRule()
        {
            var files = TestData.GlassesFiles("*_standing_pickup.csv").Concat(TestData.GlassesFiles("*_standing.csv")).ToList();
            int Shown(bool rule)
            {
                int walking = 0;
                foreach (var f in files)
                {
                    var settings = new CorrelationSettings();
                    settings.Clock.StillStartContacts = rule ? 2 : 0;
                    walking += Walks(new CorrelationClassifier(Models.Correlation, settings), RecordingCsv.Load(f)).Walking;
                }
                return walking;
            }
            int without = Shown(false), with = Shown(true);
            Assert.That(without, Is.GreaterThan(0), "COR shows some of them as walking without the rule");
            Assert.That(with, Is.LessThan(0.8 * without));
        }

        /// <summary>
        /// The shipped COR waits for a still-start walk's third contact (<see cref="StepClockSettings.StillStartContacts"/> 3):
        /// on the real glasses its standing, sitting and picking-up files are shown walking less than with 2 (all 21 people,
        /// in-sample, avatar: standing 0.95 to 0.63 %, picking up 1.62 to 1.39 % of their time) and its walking files as much.
        /// </summary>
        [Test]
        public void ShippedCorShowsLessOfTheGlassesStillRecordingsAsWalkingThanWithTwoContactsAndAsMuchOfTheirWalking()
        {
            var shipped = new CorrelationSettings();
            Assert.That(shipped.Clock.StillStartContacts, Is.EqualTo(3), "COR ships 3");
            var two = new CorrelationSettings();
            two.Clock.StillStartContacts = 2;
            var still = TestData.GlassesFiles("*_standing.csv").Concat(TestData.GlassesFiles("*_sitting*.csv")).Concat(TestData.GlassesFiles("*_standing_pickup.csv"));
            ShowsLessOfTheseAndAsMuchWalking(() => new CorrelationClassifier(Models.Correlation, shipped), () => new CorrelationClassifier(Models.Correlation, two),
                Load(still), 0.85, "standing, sitting and picking up");
        }

        /// <summary>
        /// The bend from a still head read as the whole direction of gravity (<see cref="HeadTilt.BendInRoll"/>, the SVM's and
        /// BLSTM's still-start rule): a still, level head rolled 25 degrees sideways bends 25 degrees that way and none by
        /// its pitch alone; pitched 25 degrees forward it bends 25 either way.
        /// </summary>
        [Test]
        public void ARollFromAStillHeadCountsOnlyWhereTheBendIsReadInRoll()
        {
            double Bend(bool inRoll, double rollDegrees, double pitchDegrees)
            {
                var tilt = new HeadTilt { BendInRoll = inRoll };
                var pre = new StreamPreprocessor(new PreprocessorSettings { History = 300 });
                double bend = double.NaN;
                for (int i = 0; i < 360; i++)
                {
                    double t = i * 0.01, turned = Math.Min(1, Math.Max(0, (t - 3) / 0.1));
                    double roll = turned * rollDegrees * Math.PI / 180, pitch = turned * pitchDegrees * Math.PI / 180;
                    double wobble = 0.01 * Math.Sin(9 * t);
                    pre.Push(new ImuSample(t, G * Math.Sin(pitch) * Math.Cos(roll), G * Math.Sin(roll) + wobble, G * Math.Cos(pitch) * Math.Cos(roll)), w =>
                    {
                        tilt.Follow(w, still: true);
                        bend = tilt.Reading.BendFromStill;
                    });
                }
                return bend; // 0.5 s after the turn: the still head is the level one before it
            }
            Assert.That(Bend(false, 25, 0), Is.LessThan(2), "pitch alone: a roll is no bend");
            Assert.That(Bend(true, 25, 0), Is.EqualTo(25).Within(2), "in roll");
            Assert.That(Bend(false, 0, 25), Is.EqualTo(25).Within(2));
            Assert.That(Bend(true, 0, 25), Is.EqualTo(25).Within(2));
        }

        /// <summary>
        /// The SVM reads its still-start bend in roll too (<see cref="PhaseFilterSettings.StillStartBendInRoll"/>): on glasses
        /// taken off and put on over the glasses wearers' standing and sitting recordings (<see cref="PutOnGlassesGenerator"/>)
        /// it shows fewer windows as walking than with the bend read in pitch alone, and the walking files nearly as many
        /// (over every file and five draws: the measurements log).
        /// </summary>
        [Test]
        public void ShippedSvmShowsLessOfTheGeneratedPutOnsAsWalkingWithTheBendReadInRoll()
        {
            var models = Models;
            Assert.That(SvmClassifier.DefaultFilter().StillStartBendInRoll, Is.True, "shipped");
            Func<IGaitClassifier> Svm(bool inRoll) => () =>
            {
                var svm = models.SvmOf(models.Svm); // as shipped: with THR's trained step clock
                svm.Filter.Settings.StillStartBendInRoll = inRoll;
                return svm;
            };
            // The standing files' put-ons and nine people's walks: enough to show the effect, in half the time of every file.
            var putOns = Load(TestData.GlassesFiles("*_standing.csv")).Where(r => r.Samples.Count >= PutOnGlassesGenerator.MinSamples)
                .Select(r => PutOnGlassesGenerator.From(r, DeterministicRandom.SeedFrom(r.Name)));
            ShowsLessOfTheseAndAsMuchWalking(Svm(true), Svm(false), putOns, 0.95, "the put-ons", TestData.GlassesFiles("cg1a_u0*_walking.csv"));
        }

        static List<Recording> Load(IEnumerable<string> files) => files.Select(f => RecordingCsv.Load(f)).ToList();

        /// <summary>
        /// A start rule judged on the real glasses, in windows shown walking (classifier output): <paramref name="shipped"/>
        /// shows less than <paramref name="share"/> of what <paramref name="without"/> shows of <paramref name="these"/>,
        /// and the walking files (<paramref name="walkingFiles"/>, every one by default) at least 99.8 % as much.
        /// </summary>
        static void ShowsLessOfTheseAndAsMuchWalking(Func<IGaitClassifier> shipped, Func<IGaitClassifier> without, IEnumerable<Recording> these, double share, string what,
                                                     IEnumerable<string> walkingFiles = null)
        {
            int Shown(Func<IGaitClassifier> make, List<Recording> recordings) => recordings.Sum(r => Walks(make(), r).Walking);
            var files = these.ToList();
            var walking = Load(walkingFiles ?? TestData.GlassesFiles("*_walking.csv"));
            int with = Shown(shipped, files), before = Shown(without, files);
            int walkingWith = Shown(shipped, walking), walkingBefore = Shown(without, walking);
            TestContext.WriteLine($"{what} shown walking {before} -> {with} windows; walking {walkingBefore} -> {walkingWith}");
            Assert.That(with, Is.LessThan(share * before), $"less of {what} shown as walking");
            Assert.That(walkingWith, Is.GreaterThan(0.998 * walkingBefore), "the walks shown as before");
        }

        /// <summary>
        /// THR shows a walk from a still head after standing from its second contact too (<see cref="StepClockSettings.StillStartContacts"/>,
        /// 2 as shipped): one bump after 8 s of standing is no walk, where without the rule it is one; six walk.
        /// </summary>
        [Test]
        public void ThrShowsNoWalkForOneBumpFromAStillHead()
        {
            IGaitClassifier Thr(int contacts) => OpenGateThr(c => { if (contacts >= 0) c.StillStartContacts = contacts; });
            var one = BendThenBumps(0, 1);
            Assert.That(Walks(Thr(0), one).Walking, Is.GreaterThan(30), "without the rule one bump walks");
            Assert.That(Walks(Thr(-1), one).Walking, Is.EqualTo(0), "as shipped it does not");
            Assert.That(Walks(Thr(-1), BendThenBumps(0, 6)).Longest, Is.GreaterThan(150), "six bumps walk");
        }

        /// <summary>
        /// THR waits for a second contact when a walk starts within <see cref="HeadTilt.MoveStartRecent"/> of the head's tilt
        /// moving more than <see cref="HeadTilt.MoveStartChange"/> (<see cref="StepClockSettings.TiltMoveStartContacts"/>, 2 as
        /// shipped): one bump as the head comes up from a 60-degree bend is no walk, where without the rule it is one; six
        /// walk, from their second. The bumps come 1.7 s after the head is back up (past the tilt's start limit,
        /// <see cref="StepClockSettings.MaxStartTiltChange"/>) and within 5 s of the stream's start, so the still-start rule
        /// does not hold them back.
        /// </summary>
        [Test]
        public void ThrShowsNoWalkForOneBumpAsTheHeadComesBackUp()
        {
            IGaitClassifier Thr(int contacts) => OpenGateThr(c => { if (contacts >= 0) c.TiltMoveStartContacts = contacts; });
            Recording Bumps(double degrees, int bumps) => HeadBendThenBumps("a bend early, then bumps", degrees, down: 0.5, moveDown: 0.8, hold: 1, moveUp: 1, bumpsAt: 5, bumps, seconds: 10);
            Assert.That(Walks(Thr(0), Bumps(60, 1)).Walking, Is.GreaterThan(30), "without the rule the bump walks");
            Assert.That(Walks(Thr(-1), Bumps(0, 1)).Walking, Is.GreaterThan(30), "the bump with the head level walks as shipped");
            Assert.That(Walks(Thr(-1), Bumps(60, 1)).Walking, Is.EqualTo(0), "as shipped, after the bend it does not");
            var without = Walks(Thr(0), Bumps(60, 6));
            var with = Walks(Thr(-1), Bumps(60, 6));
            Assert.That(with.Longest, Is.GreaterThan(250), "six bumps after the bend walk");
            Assert.That(with.First - without.First, Is.InRange(0.4, 0.6), "from their second contact, a step later");
        }

        /// <summary>
        /// The shipped THR on the real glasses (<see cref="StepClockSettings.TiltMoveStartContacts"/> 2): the picking-up files
        /// are shown walking less than with the rule off (windows, classifier output; all 21 people, in-sample: avatar 1.73 to
        /// 0.97 % of their time, people held out 1.96 to 0.99 %) and the walking files as much.
        /// </summary>
        [Test]
        public void ShippedThrShowsLessOfTheGlassesPickingUpAsWalkingAndAsMuchOfTheirWalking()
        {
            var shipped = Models.Threshold;
            Assert.That(shipped.Clock.TiltMoveStartContacts, Is.EqualTo(2), "THR ships the rule");
            var off = shipped.Clone();
            off.Clock.TiltMoveStartContacts = 0;
            ShowsLessOfTheseAndAsMuchWalking(() => new ThresholdClassifier(shipped), () => new ThresholdClassifier(off), Load(TestData.GlassesFiles("*_standing_pickup.csv")), 0.75, "picking things up");
        }

        /// <summary>
        /// A generated walker who stands 8 s, head still, then walks (<see cref="StepClockSettings.StillStartContacts"/>):
        /// the rule (as shipped: THR 2 contacts, COR 3) shows the walk from that contact, with the phase it has without the rule. While the walk was kept
        /// back, COR's contact search looked for steps of every length, found the walker's next contacts up to a third of a
        /// stride off, and the walk was shown late and out of phase (replay 16.9 to 20.7 % wrong).
        /// </summary>
        [TestCase("cor")]
        [TestCase("thr")]
        public void AGeneratedWalkFromStillIsShownInPhaseWithTheStillStartRule(string name)
        {
            var rec = WalkingStreamGenerator.Generate("walk from still", GaitSubject.Random(7), new StreamScript().Stand(8).Walk(15, Foot.Left).Stand(2), 7);
            List<GaitPrediction> Run(int contacts)
            {
                IGaitClassifier c;
                if (name == "thr")
                {
                    var thr = Models.Threshold.Clone();
                    thr.Clock.StillStartContacts = contacts;
                    c = new ThresholdClassifier(thr);
                }
                else
                {
                    var settings = new CorrelationSettings();
                    settings.Clock.StillStartContacts = contacts;
                    c = new CorrelationClassifier(Models.Correlation, settings);
                }
                var shown = new List<GaitPrediction>();
                var pre = new StreamPreprocessor(new PreprocessorSettings { History = Math.Max(c.WindowLength, StepRhythm.HistorySamples) });
                foreach (var sample in rec.Samples) pre.Push(sample.Imu, w => shown.Add(c.Classify(w)));
                return shown;
            }
            int shipped = name == "thr" ? Models.Threshold.Clock.StillStartContacts : new CorrelationSettings().Clock.StillStartContacts;
            Assert.That(shipped, Is.GreaterThanOrEqualTo(2), "the rule ships on");
            List<GaitPrediction> without = Run(0), with = Run(shipped);
            Assert.That(with.Count, Is.EqualTo(without.Count));
            double First(List<GaitPrediction> p) => p.First(x => x.IsWalking).Time;
            Assert.That(First(without), Is.InRange(8.0, 9.0), "without the rule the walk starts within a second");
            Assert.That(First(with), Is.GreaterThan(First(without)), "the rule keeps the walk back");
            int both = 0, apart = 0;
            for (int i = 0; i < with.Count; i++)
            {
                if (!with[i].IsWalking || !without[i].IsWalking) continue;
                both++;
                double d = Math.Abs(with[i].StridePosition - without[i].StridePosition) % 1;
                if (Math.Min(d, 1 - d) > 0.05) apart++;
            }
            Assert.That(both, Is.GreaterThan(1000));
            Assert.That(apart, Is.LessThan(0.01 * both), "once shown, the walk's phase is the one it has without the rule");
            Assert.That(First(with) - First(without), Is.LessThan(0.8 * (shipped - 1)), "for about a step per contact waited for");
        }

        /// <summary>A model the bumps fool: walking (the stride's segments in order, 1.1-s stride) for the first 1.2 s of each cycle, standing otherwise.</summary>
        sealed class FooledByTheBumps : ILearnedEvaluator
        {
            readonly LearnedClassifier classifier;
            public double Time;

            public FooledByTheBumps(LearnedClassifier classifier) => this.classifier = classifier;

            public void Evaluate(double[] features, int windows, double[] outputs)
            {
                var segments = classifier.Segments;
                double c = (Time - First) % Cycle;
                int shown = Time >= First && c < 1.2 ? (int)(c / 1.1 * segments.Count) % segments.Count : segments.StandingClass;
                SureOutputs.Write(classifier, shown, outputs);
            }
        }

        static LearnedClassifier Learned(bool svm, double maxBend)
        {
            var models = Models;
            var filter = svm ? SvmClassifier.DefaultFilter() : new PhaseFilterSettings();
            filter.StillStartMaxBend = maxBend;
            LearnedClassifier learned = svm ? new SvmClassifier(models.Svm, filter) : new BlstmClassifier(models.Blstm, filter);
            learned.Gate = null;
            return learned;
        }

        [TestCase(false)]
        [TestCase(true)]
        public void TheLearnedClassifiersWithdrawAWalkTheHeadBendsFromStill(bool svm)
        {
            (int Walking, int Longest, double First) Run(double maxBend, double degrees)
            {
                var learned = Learned(svm, maxBend);
                var fooled = new FooledByTheBumps(learned);
                learned.Evaluator = fooled;
                return Walks(learned, BumpsThenBend(5, degrees), t => fooled.Time = t);
            }
            var without = Run(0, 60);
            Assert.That(without.Longest, Is.GreaterThan(40), "without the rule the model's walk lasts until the tilt's own limit");
            var with = Run(HeadTilt.DefaultStillStartMaxBend, 60);
            Assert.That(with.Longest, Is.LessThan(without.Longest / 2));
            var level = Run(HeadTilt.DefaultStillStartMaxBend, 0);
            Assert.That(level.Walking, Is.EqualTo(Run(0, 0).Walking), "the head level: walking as without the rule");
        }
    }
}
