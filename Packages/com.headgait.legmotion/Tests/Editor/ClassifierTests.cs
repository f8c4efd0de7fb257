using System;
using System.Collections.Generic;
using System.Linq;
using HeadGait.Synthetic;
using NUnit.Framework;

namespace HeadGait.Tests
{
    public class CorrelationTemplateTests
    {
        [Test]
        public void LearnsAStepTemplateAndThePhaseMapFromLabelledRecordings()
        {
            var t = TestData.Template;
            Assert.That(t.StepsUsed, Is.GreaterThan(150));
            // The generated subjects' stance is 60-64 % of the cycle; the right foot lands half a stride after the left.
            Assert.That(t.PhaseMap.Onset(GaitPhase.InitialSwing), Is.EqualTo(0.62).Within(0.03));
            Assert.That(t.PhaseMap.RightOffset, Is.EqualTo(0.5).Within(0.02));
            Assert.That(t.MinCorrelation, Is.InRange(0.3, 0.95));
            Assert.That(t.Templates.Count, Is.InRange(1, CorrelationTemplate.DefaultTemplateCount));
            foreach (var s in t.Templates)
            {
                Assert.That(Math.Abs(s.ContactLag), Is.LessThan(0.1));
                Assert.That(s.Steps, Is.GreaterThan(0.05 * t.StepsUsed), "no template of a handful of steps");
            }
        }

        [Test]
        public void SerializesAndParsesBack()
        {
            var t = TestData.Template;
            var back = CorrelationTemplate.Parse(t.Serialize());
            Assert.That(back.Templates.Count, Is.EqualTo(t.Templates.Count));
            for (int k = 0; k < t.Templates.Count; k++)
            {
                for (int i = 0; i < CorrelationTemplate.StepPoints; i++)
                {
                    Assert.That(back.Templates[k].Smv[i], Is.EqualTo(t.Templates[k].Smv[i]).Within(1e-7));
                    Assert.That(back.Templates[k].Lateral[i], Is.EqualTo(t.Templates[k].Lateral[i]).Within(1e-7));
                }
                Assert.That(back.Templates[k].ContactLag, Is.EqualTo(t.Templates[k].ContactLag));
            }
            Assert.That(back.MinCorrelation, Is.EqualTo(t.MinCorrelation));
            Assert.That(back.ClockLead, Is.EqualTo(t.ClockLead));
            var bouncy = t.With(leadPerLogBounce: 0.02, leadReferenceBounce: 7.5);
            var bouncyBack = CorrelationTemplate.Parse(bouncy.Serialize());
            Assert.That(bouncyBack.LeadPerLogBounce, Is.EqualTo(0.02));
            Assert.That(bouncyBack.LeadReferenceBounce, Is.EqualTo(7.5));
            Assert.That(back.Gate.Serialize(), Is.EqualTo(t.Gate.Serialize()));
            Assert.That(back.PhaseMap.Serialize(), Is.EqualTo(t.PhaseMap.Serialize()));
        }

        [Test]
        public void BrokenTemplatesAreRefusedNamingTheKey()
        {
            string good = TestData.Template.Serialize();
            Assert.That(() => CorrelationTemplate.Parse("step_smv=1,2", "t.txt"), Throws.TypeOf<FormatException>().With.Message.Contains("t.txt").And.Message.Contains("first line"));
            Assert.That(() => CorrelationTemplate.Parse(good.Replace("contact_lag.0=", "lag.0=")), Throws.TypeOf<FormatException>().With.Message.Contains("contact_lag.0"));
            Assert.That(() => CorrelationTemplate.Parse(good.Replace("step_smv.0=", "step_smv.0=1,")), Throws.TypeOf<FormatException>().With.Message.Contains("101 values"));
            Assert.That(() => CorrelationTemplate.Parse(good.Replace("step_lateral.0=", "step_lateral.0=NaN,")), Throws.TypeOf<FormatException>().With.Message.Contains("step_lateral.0"));
            Assert.That(() => CorrelationTemplate.Parse(good.Replace("templates=", "templates=9\nx=")), Throws.TypeOf<FormatException>().With.Message.Contains("lacks 'step_smv."));
            Assert.That(() => CorrelationTemplate.Parse(good.Replace("templates=", "templates=0\nx=")), Throws.TypeOf<FormatException>().With.Message.Contains("'templates'"));
            Assert.That(() => CorrelationTemplate.Parse(good.Replace("min_correlation=", "min_correlation=1e309\nx=")), Throws.TypeOf<FormatException>().With.Message.Contains("min_correlation"));
            Assert.That(() => CorrelationTemplate.Parse(good.Replace("clock_lead_per_log_bounce=", "clock_lead_per_log_bounce=0.5\nx=")), Throws.TypeOf<FormatException>().With.Message.Contains("clock_lead_per_log_bounce"));
            Assert.That(() => CorrelationTemplate.Parse(good.Replace("clock_lead_reference_bounce=", "clock_lead_reference_bounce=0\nx=")), Throws.TypeOf<FormatException>().With.Message.Contains("clock_lead_reference_bounce"));
            string constant = "step_smv.0=" + string.Join(",", new string('1', CorrelationTemplate.StepPoints).ToCharArray());
            string withConstant = System.Text.RegularExpressions.Regex.Replace(good, "step_smv\\.0=[^\n]*", constant);
            Assert.That(() => CorrelationTemplate.Parse(withConstant), Throws.TypeOf<FormatException>().With.Message.Contains("constant"));
        }

        [Test]
        public void ATemplateWithoutTheBounceLeadKeepsAFixedLead()
        {
            // Templates written before the lead followed the walker's bounce read as a fixed lead.
            string good = TestData.Template.With(leadPerLogBounce: 0.02).Serialize();
            string old = System.Text.RegularExpressions.Regex.Replace(good, "clock_lead_(per_log|reference)_bounce=[^\n]*\n", "");
            Assert.That(old, Does.Not.Contain("_bounce"));
            var t = CorrelationTemplate.Parse(old);
            Assert.That(t.LeadPerLogBounce, Is.EqualTo(0));
            Assert.That(t.LeadReferenceBounce, Is.EqualTo(StepClockSettings.DefaultLeadReferenceBounce));
        }

        [Test]
        public void ReadsAnyLineEndingAndAByteOrderMark()
        {
            string good = TestData.Template.Serialize();
            foreach (var variant in new[] { good.Replace("\n", "\r\n"), good.Replace("\n", "\r"), "\uFEFF" + good })
                Assert.That(CorrelationTemplate.Parse(variant).Templates[0].Smv[10], Is.EqualTo(TestData.Template.Templates[0].Smv[10]).Within(1e-7));
        }

        [Test]
        public void TrainingWithoutWalkingSaysSo()
        {
            var standing = WalkingStreamGenerator.Generate("s", GaitSubject.Random(1), new StreamScript().Stand(10), 1);
            Assert.That(() => CorrelationTemplate.Train(new[] { standing }, PhaseMap.Perry, WalkingGate.Open),
                Throws.InvalidOperationException.With.Message.Contains("too small"));
        }
    }

    public class CorrelationClassifierTests
    {
        /// <summary>The test template with its gate always open, no clock lead and no contact lag: contacts land where the steps do.</summary>
        static CorrelationTemplate OpenTemplate => TestData.Template.With(gate: WalkingGate.Open, clockLead: 0).WithLag(0);

        /// <summary>A stream whose SMV repeats the template step after step (period 0.55 s unless given), left foot first.</summary>
        static List<ImuSample> TemplateWalk(CorrelationTemplate t, double seconds, out List<double> contacts, double gain = 2.0, double step = 0.55)
        {
            var samples = new List<ImuSample>();
            contacts = new List<double>();
            for (int k = 1; k * step < seconds; k++) contacts.Add(k * step);
            for (int i = 0; i < seconds * 100; i++)
            {
                double time = i * 0.01;
                int k = (int)Math.Floor(time / step + 1e-9);
                double u = Math.Max(0, time / step - k);
                double smv = gain * CorrelationTemplate.At(t.Templates[0].Smv, u);
                double side = k % 2 == 0 ? 1 : -1; // even steps are left steps
                double lateral = side * CorrelationTemplate.At(t.Templates[0].Lateral, u);
                samples.Add(new ImuSample(time, 0, lateral, 9.80665 + smv));
            }
            return samples;
        }

        [Test]
        public void DetectsEachContactOfAStreamMadeOfTheTemplate()
        {
            var t = OpenTemplate;
            var cor = new CorrelationClassifier(t);
            var detected = new List<(double time, double evidence)>();
            cor.ContactDetected += (time, evidence, r, template) => detected.Add((time, evidence));
            var pipeline = new GaitPipeline(cor);
            var walk = TemplateWalk(t, 12, out var contacts);
            foreach (var s in walk) pipeline.Push(s);
            Assert.That(detected.Count, Is.EqualTo(contacts.Count).Within(2));
            int matched = 0, rightSide = 0;
            foreach (var d in detected)
            {
                int nearest = 0;
                for (int i = 1; i < contacts.Count; i++)
                    if (Math.Abs(contacts[i] - d.time) < Math.Abs(contacts[nearest] - d.time)) nearest = i;
                if (Math.Abs(contacts[nearest] - d.time) > 0.015) continue;
                matched++;
                // Contact k ends step k-1: odd k lands the right foot (a left step just ended), so its left-evidence is negative.
                int k = (int)Math.Round(contacts[nearest] / 0.55);
                if ((d.evidence < 0) == (k % 2 == 1)) rightSide++;
            }
            Assert.That(matched, Is.GreaterThanOrEqualTo(detected.Count - 1), "contacts found within 15 ms");
            Assert.That(rightSide, Is.EqualTo(matched), "side evidence names the landing foot");
            Assert.That(cor.Clock.StepPeriod, Is.EqualTo(0.55).Within(0.02));
        }

        /// <summary>When COR first shows walking on a walk of the template's own steps (NaN: never).</summary>
        static double FirstWalking(CorrelationSettings settings = null, double gain = 2.0)
        {
            var t = TestData.Template.With(gate: WalkingGate.Open);
            var pipeline = new GaitPipeline(new CorrelationClassifier(t, settings));
            double firstWalking = double.NaN;
            pipeline.FrameProduced += (p, f) =>
            {
                if (p.IsWalking && double.IsNaN(firstWalking)) firstWalking = p.Time;
            };
            foreach (var s in TemplateWalk(t, 5, out _, gain)) pipeline.Push(s);
            return firstWalking;
        }

        [Test]
        public void StartsWalkingWithinTheFirstWindowOfAWalk()
        {
            Assert.That(FirstWalking(), Is.LessThan(0.6), "the standing search recognises the step in the first 0.5 s window");
        }

        [Test]
        public void TheStandingSearchMarginIsASetting()
        {
            // Off (negative), walking waits for a correlation peak at a contact; a margin no r can clear (r <= 1) is the same as off.
            double searched = FirstWalking(), off = FirstWalking(new CorrelationSettings { StartMargin = -1 });
            double unreachable = FirstWalking(new CorrelationSettings { StartMargin = 1 });
            Assert.That(off, Is.GreaterThan(searched + 0.05));
            Assert.That(unreachable, Is.EqualTo(off));
        }

        [Test]
        public void TheStandingSearchGuessesNoLongStepAndTheWalkThenFindsItsOwnPeriod()
        {
            // Steps of 0.85 s: the standing search tries steps up to 0.75 s here, so the walk starts from a guessed
            // period, and the contacts that follow set the walk's own.
            var t = OpenTemplate;
            var settings = new CorrelationSettings { StartMaxStepSamples = 75 };
            var cor = new CorrelationClassifier(t, settings);
            var pipeline = new GaitPipeline(cor);
            double startPeriod = double.NaN;
            bool measuredAtStart = true;
            pipeline.FrameProduced += (p, f) =>
            {
                if (!p.IsWalking || !double.IsNaN(startPeriod)) return;
                startPeriod = cor.Clock.StepPeriod;
                measuredAtStart = cor.Clock.PeriodMeasured;
            };
            foreach (var s in TemplateWalk(t, 8, out _, step: 0.85)) pipeline.Push(s);
            Assert.That(startPeriod, Is.LessThanOrEqualTo(0.75 + 1e-9), "the start's guessed period");
            Assert.That(measuredAtStart, Is.False);
            Assert.That(cor.Clock.PeriodMeasured, Is.True);
            Assert.That(cor.Clock.StepPeriod, Is.EqualTo(0.85).Within(0.03), "the walk's own period");
        }

        /// <summary>Times at which COR shows the left foot's initial contact begin, over a template walk of the given gain.</summary>
        static List<double> ShownLeftContacts(CorrelationTemplate t, double gain)
        {
            var cor = new CorrelationClassifier(t);
            var pipeline = new GaitPipeline(cor);
            var shown = new List<double>();
            GaitPhase before = GaitPhase.Standing;
            pipeline.FrameProduced += (p, f) =>
            {
                if (p.Left == GaitPhase.InitialContact && before != GaitPhase.InitialContact && p.Time > 3) shown.Add(p.Time);
                before = p.Left;
            };
            foreach (var s in TemplateWalk(t, 10, out _, gain)) pipeline.Push(s);
            return shown;
        }

        /// <summary>Mean of the shown left contacts' offsets within half a step of the calm walk's (same steps, same times).</summary>
        static double MeanShift(List<double> calm, List<double> bouncy)
        {
            double sum = 0;
            int n = 0;
            foreach (var b in bouncy)
            {
                double nearest = calm.OrderBy(c => Math.Abs(c - b)).First();
                if (Math.Abs(nearest - b) > 0.275) continue;
                sum += b - nearest;
                n++;
            }
            Assert.That(n, Is.GreaterThan(5), "contacts shown on both walks");
            return sum / n;
        }

        [Test]
        public void ABouncierWalkLeadsTheClockByTheLearnedSlope()
        {
            // The same steps at 4 times the bounce: with 0.03 s per log unit the clock runs 0.03 * ln 4 = 42 ms further ahead.
            var fixedLead = OpenTemplate;
            var following = OpenTemplate.With(leadPerLogBounce: 0.03);
            double shift = MeanShift(ShownLeftContacts(following, 2), ShownLeftContacts(following, 8));
            Assert.That(shift, Is.EqualTo(-0.03 * Math.Log(4)).Within(0.012));
            Assert.That(MeanShift(ShownLeftContacts(fixedLead, 2), ShownLeftContacts(fixedLead, 8)), Is.EqualTo(0).Within(0.006), "a fixed lead");
        }

        /// <summary>
        /// A labelled template walk of the given gain whose labels put every contact <paramref name="early"/> s before the
        /// step the signal shows (as if its walker's contacts came out that late).
        /// </summary>
        static Recording LabelledTemplateWalk(CorrelationTemplate t, double gain, double early, string name)
        {
            const double step = 0.55;
            var map = t.PhaseMap;
            double leftContact = map.StridePositionOfOnset(Foot.Left, GaitPhase.InitialContact);
            var samples = new List<RecordedSample>();
            foreach (var s in TemplateWalk(t, 12, out _, gain, step))
            {
                // Contacts at even multiples of the step land the left foot (see TemplateWalk).
                double stride = leftContact + (s.Time + early) / (2 * step);
                samples.Add(new RecordedSample(s, map.PhaseAt(Foot.Left, stride, step), map.PhaseAt(Foot.Right, stride, step)));
            }
            return new Recording(name, samples);
        }

        [Test]
        public void CalibrationLearnsHowMuchLaterABouncierWalkersContactsComeOut()
        {
            var t = TestData.Template.With(gate: WalkingGate.Open);
            const double slope = 0.025;
            var walks = new List<Recording>();
            foreach (var gain in new[] { 1.0, 2.0, 4.0, 8.0 })
                walks.Add(LabelledTemplateWalk(t, gain, slope * Math.Log(gain / 2.8), "gain" + gain));
            var calibrated = CorrelationClassifier.Calibrate(t, walks);
            Assert.That(calibrated.LeadPerLogBounce, Is.EqualTo(slope).Within(0.008));
            var even = new List<Recording>();
            foreach (var gain in new[] { 1.0, 2.0, 4.0, 8.0 }) even.Add(LabelledTemplateWalk(t, gain, 0, "even" + gain));
            Assert.That(CorrelationClassifier.Calibrate(t, even).LeadPerLogBounce, Is.EqualTo(0).Within(0.005), "contacts as late for every bounce");
        }

        /// <summary>
        /// A second of standing, then a walk of <paramref name="step"/> s steps: COR's step period when the walk is first
        /// shown, and right after the first contact that follows.
        /// </summary>
        static (double atStart, double afterFirstContact) PeriodsOfAWalkFromStanding(CorrelationSettings settings, double step)
        {
            var t = OpenTemplate;
            settings.Clock.StandingAfterPeriods = 3; // the walk lasts until its first contact, however slow
            var cor = new CorrelationClassifier(t, settings);
            var pipeline = new GaitPipeline(cor);
            double atStart = double.NaN, afterFirst = double.NaN;
            pipeline.FrameProduced += (p, f) =>
            {
                if (p.IsWalking && double.IsNaN(atStart)) atStart = cor.Clock.StepPeriod;
            };
            cor.ContactDetected += (time, e, r, k) =>
            {
                if (!double.IsNaN(atStart) && double.IsNaN(afterFirst)) afterFirst = cor.Clock.StepPeriod;
            };
            for (int i = 0; i < 100; i++) pipeline.Push(new ImuSample(i * 0.01, 0, 0, 9.80665));
            foreach (var s in TemplateWalk(t, 6, out _, step: step)) pipeline.Push(new ImuSample(1 + s.Time, s.X, s.Y, s.Z));
            return (atStart, afterFirst);
        }

        [Test]
        public void AWalkFromStandingRunsAtTheTypicalStepUntilItsFirstContactSearchedAroundTheMatchedLength()
        {
            // The window that starts the walk holds the onset of the movement: its matched length says nothing of the step.
            var onset = PeriodsOfAWalkFromStanding(new CorrelationSettings(), 0.85);
            Assert.That(onset.atStart, Is.EqualTo(new StepClockSettings().InitialStepPeriod), "the typical step until a contact");
            // Searched around the typical 0.55 s (within FirstStepTolerance), a 0.85 s step would be out of reach.
            Assert.That(onset.afterFirstContact, Is.EqualTo(0.85).Within(0.03), "the first contact, searched around the matched length");
            var off = PeriodsOfAWalkFromStanding(new CorrelationSettings { OnsetSpanRatio = 0 }, 0.85);
            Assert.That(off.atStart, Is.Not.EqualTo(new StepClockSettings().InitialStepPeriod).Within(0.02), "off: the matched length");
            Assert.That(off.afterFirstContact, Is.EqualTo(0.85).Within(0.03));
        }

        /// <summary>
        /// A walk of 0.55 s steps whose clock is restarted at 2 s as if a start had guessed 0.75 s steps (the last contact
        /// right, at 1.65 s): the step period COR's clock holds after the next contact.
        /// </summary>
        static double PeriodAfterAGuessedStart(int firstStepTolerance)
        {
            var t = OpenTemplate;
            var cor = new CorrelationClassifier(t, new CorrelationSettings { FirstStepTolerance = firstStepTolerance });
            var pipeline = new GaitPipeline(cor);
            double period = double.NaN;
            cor.ContactDetected += (time, e, r, k) =>
            {
                if (time > 2 && double.IsNaN(period)) period = cor.Clock.StepPeriod;
            };
            foreach (var s in TemplateWalk(t, 4, out _))
            {
                if (Math.Abs(s.Time - 2.0) < 1e-9)
                {
                    cor.Clock.Stop();
                    cor.Clock.Start(1.65, -1, 0.75);
                }
                pipeline.Push(s);
            }
            return period;
        }

        [Test]
        public void AWalksFirstContactIsSearchedWidelyAroundAGuessedPeriod()
        {
            Assert.That(PeriodAfterAGuessedStart(20), Is.EqualTo(0.55).Within(0.02));
            Assert.That(PeriodAfterAGuessedStart(6), Is.Not.EqualTo(0.55).Within(0.05), "searched as narrowly as a measured period");
        }

        /// <summary>
        /// A walk made of the template that slows from 0.6 to 0.75 s steps at 4 s: how far COR's contacts after the
        /// slowing come from the true ones (ms, negative early). The clock's period follows each new step only partly, so
        /// the steps searched lag behind the walker's.
        /// </summary>
        static List<double> ContactOffsetsAfterSlowingDown(double toleranceShare)
        {
            var t = OpenTemplate;
            var cor = new CorrelationClassifier(t, new CorrelationSettings { PeriodToleranceShare = toleranceShare });
            var pipeline = new GaitPipeline(cor);
            var slow = TemplateWalk(t, 6, out var slowContacts, step: 0.75);
            var offsets = new List<double>();
            cor.ContactDetected += (time, e, r, k) =>
            {
                double nearest = slowContacts.Select(c => c + 4).OrderBy(c => Math.Abs(c - time)).First();
                if (time > 4.5 && Math.Abs(time - nearest) <= 0.25) offsets.Add(1000 * (time - nearest));
            };
            foreach (var s in TemplateWalk(t, 4, out _, step: 0.6)) pipeline.Push(s);
            foreach (var s in slow) pipeline.Push(new ImuSample(4 + s.Time, s.X, -s.Y, s.Z));
            return offsets;
        }

        [Test]
        public void ASlowingWalkersContactsComeOnTimeSoonerWhenTheSearchReachesAShareOfThePeriod()
        {
            var share = ContactOffsetsAfterSlowingDown(0.12);
            var fixedReach = ContactOffsetsAfterSlowingDown(0);
            Assert.That(share.Count, Is.GreaterThanOrEqualTo(6), "the slowed walk is followed");
            Assert.That(fixedReach.Count, Is.GreaterThanOrEqualTo(6));
            int EarlyCount(List<double> o) => o.Count(x => x <= -20);
            Assert.That(EarlyCount(share), Is.LessThan(EarlyCount(fixedReach)), $"contacts 20 ms early or more: {string.Join(", ", share)} against {string.Join(", ", fixedReach)}");
            Assert.That(share.Skip(4), Is.All.InRange(-10.0, 10.0), "on time from the fifth slow step on");
        }

        [Test]
        public void SearchSettingsOutOfRangeAreRefusedNamingTheSetting()
        {
            var t = TestData.Template;
            Assert.That(() => new CorrelationClassifier(t, new CorrelationSettings { MaxStepSamples = 20 }), Throws.ArgumentException.With.Message.Contains("Step search range"));
            Assert.That(() => new CorrelationClassifier(t, new CorrelationSettings { PeakConfirmSamples = 0 }), Throws.ArgumentException.With.Message.Contains("PeakConfirmSamples"));
            Assert.That(() => new CorrelationClassifier(t, new CorrelationSettings { StartMaxStepSamples = 10 }), Throws.ArgumentException.With.Message.Contains("StartMaxStepSamples"));
            Assert.That(() => new CorrelationClassifier(t, new CorrelationSettings { FirstStepTolerance = -1 }), Throws.ArgumentException.With.Message.Contains("FirstStepTolerance"));
            Assert.That(() => new CorrelationClassifier(t, new CorrelationSettings { PeriodTolerance = -1 }), Throws.ArgumentException.With.Message.Contains("PeriodTolerance"));
            Assert.That(() => new CorrelationClassifier(t, new CorrelationSettings { PeriodToleranceShare = double.NaN }), Throws.ArgumentException.With.Message.Contains("PeriodToleranceShare"));
            Assert.That(() => new CorrelationClassifier(t, new CorrelationSettings { OnsetSpanRatio = double.NaN }), Throws.ArgumentException.With.Message.Contains("OnsetSpanRatio"));
            Assert.That(() => new CorrelationClassifier(t, new CorrelationSettings { OnsetSpanRatio = -1 }), Throws.ArgumentException.With.Message.Contains("OnsetSpanRatio"));
            Assert.That(() => new CorrelationClassifier(t, new CorrelationSettings { StartMaxStepSamples = 30, FirstStepTolerance = 0 }), Throws.Nothing);
        }

        [Test]
        public void AStepShapedBobTooSmallForAStepIsNoWalk()
        {
            var smv = TestData.Template.Templates[0].Smv;
            double span = smv.Max() - smv.Min();
            // The template's own step shape, correlating perfectly, with SMV spanning half of the least a step must span.
            double gain = 0.5 * new CorrelationSettings().MinStepSpan / span;
            Assert.That(FirstWalking(gain: gain), Is.NaN, "a bob spanning half the least step span");
            Assert.That(FirstWalking(new CorrelationSettings { MinStepSpan = 0 }, gain), Is.LessThan(0.6), "the same bob with no least span");
            Assert.That(FirstWalking(gain: 1.5 * new CorrelationSettings().MinStepSpan / span), Is.LessThan(0.6), "a step half again the least span");
        }

        [Test]
        public void StaysUsableAcrossTheGeneratedEvaluationRecordings()
        {
            var all = new List<GaitMetrics>();
            foreach (var rec in TestData.EvalSet())
            {
                var r = ReplayEvaluator.Run(rec, new CorrelationClassifier(TestData.Template));
                TestContext.WriteLine($"{rec.Name}: {r.ClassifierMetrics.MisclassificationRate:P1}, walking as standing {r.ClassifierMetrics.WalkingAsStanding:P1}");
                Assert.That(r.ClassifierMetrics.MisclassificationRate, Is.LessThan(0.4), rec.Name);
                Assert.That(r.ClassifierMetrics.WalkingAsStanding, Is.LessThan(0.1), rec.Name);
                all.Add(r.ClassifierMetrics);
            }
            Assert.That(GaitMetrics.Pool(all).MisclassificationRate, Is.LessThan(0.25));
        }

        [Test]
        public void AnEstablishedThrWalkRidesOutTheGateLongerThanAYoungOne()
        {
            // In turns and at slow wearers' calm steps the gate shuts for a few tenths of a second while the walk goes on;
            // false walks in still activities are younger than the rhythm's span and stop as before.
            var clock = new ThresholdSettings().Clock;
            Assert.That(clock.StopAfterStillWindowsAfter(double.NaN), Is.EqualTo(clock.StopAfterStillWindows), "no walk shown");
            Assert.That(clock.StopAfterStillWindowsAfter(clock.EstablishedAfter - 0.01), Is.EqualTo(clock.StopAfterStillWindows), "a young walk");
            Assert.That(clock.StopAfterStillWindowsAfter(clock.EstablishedAfter), Is.GreaterThan(clock.StopAfterStillWindows), "an established one");
            Assert.That(new CorrelationSettings().Clock.StopAfterStillWindowsAfter(60), Is.EqualTo(clock.StopAfterStillWindows), "COR as before");
        }

        [Test]
        public void StandingStillIsStanding()
        {
            var rec = WalkingStreamGenerator.Generate("still", GaitSubject.Random(3), new StreamScript().Stand(20), 3);
            var r = ReplayEvaluator.Run(rec, new CorrelationClassifier(TestData.Template));
            Assert.That(r.ClassifierMetrics.MisclassificationRate, Is.EqualTo(0));
        }

        [Test]
        public void TheCorrelationThresholdIsASetting()
        {
            // The paper's rule (r > 0.9, no tracking margin) or any other replaces the learned threshold: stricter means fewer contacts taken.
            int Contacts(double threshold)
            {
                var cor = new CorrelationClassifier(TestData.Template, new CorrelationSettings { MinCorrelationOverride = threshold, TrackingMargin = 0 });
                int n = 0;
                cor.ContactDetected += (t, e, r, k) =>
                {
                    Assert.That(r, Is.GreaterThanOrEqualTo(threshold));
                    n++;
                };
                ReplayEvaluator.Run(TestData.Eval("walk_turns"), cor);
                return n;
            }
            int loose = Contacts(0.3), paper = Contacts(CorrelationTemplate.PaperMinCorrelation), strict = Contacts(0.999);
            Assert.That(loose, Is.GreaterThanOrEqualTo(paper));
            Assert.That(paper, Is.GreaterThan(strict));
        }

        [Test]
        public void AStepDueNowMayMatchALittleWorseThanTheThreshold()
        {
            // The committed template, learned from people, matches the generated walker's steps at r of about 0.8 to 0.95.
            var template = TestData.ShippedModels().Correlation;
            var rec = TestData.Eval("walk_straight");
            var found = new List<double>();
            var open = new CorrelationClassifier(template, new CorrelationSettings { MinCorrelationOverride = 0.3, TrackingMargin = 0 });
            open.ContactDetected += (t, e, r, k) => found.Add(r);
            ReplayEvaluator.Run(rec, open);
            found.Sort();
            // A threshold only a quarter of the steps reach: without a margin most steps are missed.
            double threshold = found[found.Count * 3 / 4];
            (int contacts, double recall) Run(double margin)
            {
                var cor = new CorrelationClassifier(template, new CorrelationSettings { MinCorrelationOverride = threshold, TrackingMargin = margin });
                int n = 0;
                cor.ContactDetected += (t, e, r, k) =>
                {
                    Assert.That(r, Is.GreaterThanOrEqualTo(threshold - margin - 1e-12));
                    n++;
                };
                double recall = ReplayEvaluator.Run(rec, cor).ClassifierMetrics.StepRecall;
                return (n, recall);
            }
            var strict = Run(0);
            var tracking = Run(0.1);
            Assert.That(tracking.contacts, Is.GreaterThan(strict.contacts + 10), "steps that come when due are taken");
            Assert.That(tracking.recall, Is.GreaterThan(strict.recall));
        }

        static GaitModels Shipped => TestData.ShippedModels();

        static Recording RealClip(string name)
        {
            string file = System.IO.Path.Combine(TestData.SharedData("real-train"), name + ".csv");
            if (!System.IO.File.Exists(file)) Assert.Ignore($"{file} not found");
            return RecordingCsv.Load(file);
        }

        [Test]
        public void AStepsFullMatchTakesThePlaceOfAnEarlierBumpOfIt()
        {
            // A recorded calm walker turning (Bandai Namco *feminine*): a weak peak on a bump of a step was taken as its contact,
            // and the step's own full match, too soon after it to be a step, was refused; the stride ran early (69.9 % wrong).
            // The full match now takes the bump's place (CorrelationSettings.ReplaceMargin).
            var template = Shipped.Correlation;
            var rec = RealClip("bn_tr_fem_001");
            double Wrong(double margin) => ReplayEvaluator.Run(rec, new CorrelationClassifier(template, new CorrelationSettings { ReplaceMargin = margin })).ClassifierMetrics.MisclassificationRate;
            double replaced = Wrong(new CorrelationSettings().ReplaceMargin), kept = Wrong(-1);
            Assert.That(replaced, Is.LessThan(0.6));
            Assert.That(replaced, Is.LessThan(kept - 0.1));
        }

        [Test]
        public void ASlowCalmWalkGoesOnThroughTheGatesLongerRefusalsButAGesturesFalseWalkDoesNot()
        {
            // A recorded turn (*masculine*) made slow and calm (the benchmark's --slow): the gate refuses for longer than 0.15 s
            // between its steps of about 0.9 s, and COR ended the walk there (57.8 % wrong). Its refusal counts now stretch with
            // the step period while the head's tilt holds and once the walk's contacts span 0.85 s.
            var template = Shipped.Correlation;
            var slow = Training.RecordingAugmentation.Slow(RealClip("bn_tr_mas_008"));
            var shipped = new CorrelationSettings();
            var unstretched = new CorrelationSettings();
            unstretched.Clock.StillWindowsStepPeriod = 0;
            double wrong = ReplayEvaluator.Run(slow, new CorrelationClassifier(template, shipped)).ClassifierMetrics.MisclassificationRate;
            Assert.That(wrong, Is.LessThan(0.4));
            Assert.That(wrong, Is.LessThan(ReplayEvaluator.Run(slow, new CorrelationClassifier(template, unstretched)).ClassifierMetrics.MisclassificationRate - 0.1));
            // Gestures and bows (the same style's, and the waves whose false walks a stretch from the first contact showed longer)
            // are shown as walking no more than without the stretch.
            var gestures = new[] { "bn_neg_rb_mas_001", "bn_neg_rr_mas_001", "bn_neg_wb_mas_001", "bn_neg_wl_mas_001", "bn1_guide_active_001", "bn1_byebye_active_001" }.Select(RealClip).ToList();
            double Shown(CorrelationSettings s) => GaitMetrics.Pool(gestures.Select(r => ReplayEvaluator.Run(r, new CorrelationClassifier(template, s)).ClassifierMetrics)).StandingAsWalking;
            Assert.That(Shown(shipped), Is.LessThanOrEqualTo(Shown(unstretched)));
        }

        [Test]
        public void AWeakPeakInsideTheStandingSearchsWindowDoesNotKeepAWavesFalseWalkGoing()
        {
            // A waving clip (bn1 *byebye active*) at the threshold its held-out style's fold chose (0.74): the standing search
            // started a walk at 2.45 s, dating its step's contact 0.74 s back (before its window), and a weak peak inside that
            // window (r 0.68, taken on the tracking margin as due) kept the walk shown 0.6 s longer (251 samples shown walking).
            var template = Shipped.Correlation;
            var waving = RealClip("bn1_byebye_active_001");
            double Shown(bool weakContactsInStartWindow)
            {
                var m = ReplayEvaluator.Run(waving, new CorrelationClassifier(template, new CorrelationSettings { MinCorrelationOverride = 0.74, WeakContactsInStartWindow = weakContactsInStartWindow })).ClassifierMetrics;
                return m.StandingAsWalking * m.StandingSamples;
            }
            double refused = Shown(false), taken = Shown(true);
            Assert.That(refused, Is.LessThan(220));
            Assert.That(refused, Is.LessThan(taken - 40));
            // Walks, as recorded and made slow, are classified as well as before.
            var walks = new[] { RealClip("bn_tr_fem_001"), RealClip("bn_wk_mas_018"), Training.RecordingAugmentation.Slow(RealClip("bn_tr_mas_008")) };
            double Wrong(bool weak) => GaitMetrics.Pool(walks.Select(r => ReplayEvaluator.Run(r, new CorrelationClassifier(template, new CorrelationSettings { MinCorrelationOverride = 0.74, WeakContactsInStartWindow = weak })).ClassifierMetrics)).MisclassificationRate;
            Assert.That(Wrong(false), Is.LessThanOrEqualTo(Wrong(true) + 0.005));
        }
    }

    public class StepClockTests
    {
        [Test]
        public void AContactReplacingTheLastOneLeavesTheClockAsIfTheLastHadNeverCome()
        {
            var settings = new StepClockSettings { ContactsToStart = 1 };
            var direct = new StepClock(PhaseMap.Perry, settings);
            direct.Contact(0, 1);
            direct.Contact(0.9, -1);
            direct.Contact(1.85, 1);
            var bumped = new StepClock(PhaseMap.Perry, settings);
            bumped.Contact(0, 1);
            bumped.Contact(0.9, -1);
            Assert.That(bumped.Contact(1.5, -1), Is.True, "a bump taken as a contact");
            Assert.That(bumped.Contact(1.85, 1), Is.False, "too soon after it");
            Assert.That(bumped.ReplaceLastContact(1.85, 1), Is.True);
            Assert.That(bumped.LastContactTime, Is.EqualTo(direct.LastContactTime));
            Assert.That(bumped.StepPeriod, Is.EqualTo(direct.StepPeriod));
            Assert.That(bumped.LastFoot, Is.EqualTo(direct.LastFoot));
            Assert.That(bumped.StridePosition(2.0), Is.EqualTo(direct.StridePosition(2.0)));
            bumped.Stop();
            Assert.That(bumped.ReplaceLastContact(2.5, 1), Is.False, "nothing to replace after a stop");
        }

        [Test]
        public void ABouncierWalkerLeadsTheStridePositionByTheSlopeWithinItsLimit()
        {
            var clock = new StepClock(PhaseMap.Perry, new StepClockSettings { ContactsToStart = 1, LeadPerLogBounce = 0.02, LeadReferenceBounce = 4 });
            clock.Contact(0, 1);
            double level = clock.StridePosition(0.2);
            clock.FollowBounce(16);
            Assert.That(clock.BounceLead, Is.EqualTo(0.02 * Math.Log(4)).Within(1e-12));
            Assert.That(clock.StridePosition(0.2) - level, Is.EqualTo(0.02 * Math.Log(4) / (2 * clock.StepPeriod)).Within(1e-12));
            clock.FollowBounce(double.NaN);
            Assert.That(clock.BounceLead, Is.EqualTo(0.02 * Math.Log(4)).Within(1e-12), "no bounce measured: the lead stays");
            clock.FollowBounce(1e30);
            Assert.That(clock.BounceLead, Is.EqualTo(StepClockSettings.MaxBounceLead));
            clock.Reset();
            Assert.That(clock.BounceLead, Is.EqualTo(0));
        }

        [Test]
        public void FittingTheBounceLeadRecoversAPlantedSlopeAndNeedsEnoughVariedContacts()
        {
            var random = new HeadGait.Synthetic.DeterministicRandom(5);
            var offsets = new List<double>();
            var bounces = new List<double>();
            for (int i = 0; i < 400; i++)
            {
                double bounce = 1 + 9 * random.NextDouble();
                bounces.Add(bounce);
                offsets.Add(0.01 + 0.025 * Math.Log(bounce) + 0.02 * random.NextGaussian());
            }
            Assert.That(StepClock.FitBounceLead(offsets, bounces, out double slope, out double reference), Is.True);
            Assert.That(slope, Is.EqualTo(0.025).Within(0.005));
            Assert.That(reference, Is.InRange(4.0, 7.0), "the median bounce");
            Assert.That(StepClock.FitBounceLead(offsets.GetRange(0, 20), bounces.GetRange(0, 20), out _, out _), Is.False, "too few contacts");
            var same = new List<double>();
            foreach (var _ in offsets) same.Add(3);
            Assert.That(StepClock.FitBounceLead(offsets, same, out _, out _), Is.False, "every bounce alike");
        }

        /// <summary>
        /// Steps of 0.55 s, then a slower one of 0.7 s confirmed 20 ms late: the clock ran on at the old period, so the
        /// right foot had already left the ground when the left contact dated the stride back. Predicted every 10 ms.
        /// </summary>
        static List<double> Positions(double holdBack, out int rightLandings)
        {
            var clock = new StepClock(PhaseMap.Perry, new StepClockSettings { ContactsToStart = 1, HoldBack = holdBack });
            var contacts = new Queue<(double at, double time, double side)>(new[] { (0.0, 0.0, 1.0), (0.55, 0.55, -1.0), (1.27, 1.25, 1.0), (1.85, 1.85, -1.0) });
            var positions = new List<double>();
            rightLandings = 0;
            GaitPhase previous = GaitPhase.Standing;
            for (int i = 0; i <= 200; i++)
            {
                double now = 0.01 * i;
                while (contacts.Count > 0 && contacts.Peek().at <= now + 1e-9)
                {
                    var c = contacts.Dequeue();
                    clock.Contact(c.time, c.side);
                }
                var p = clock.Predict(now, 1);
                if (!p.IsWalking) continue;
                positions.Add(p.StridePosition);
                if (GaitPhases.IsSwing(previous) && GaitPhases.IsStance(p.Right)) rightLandings++;
                previous = p.Right;
            }
            return positions;
        }

        static int StepsBack(List<double> positions)
        {
            int back = 0;
            for (int i = 1; i < positions.Count; i++)
            {
                double d = PhaseMap.Wrap(positions[i - 1] - positions[i]);
                if (d > 0 && d < 0.5) back++;
            }
            return back;
        }

        [Test]
        public void AStartedWalkTakesItsPeriodFromItsFirstIntervalNotFromTheGuess()
        {
            var clock = new StepClock(PhaseMap.Perry, new StepClockSettings { ContactsToStart = 1 });
            foreach (var t in new[] { 0.0, 0.5, 1.0 }) clock.Contact(t, t == 0.5 ? -1 : 1);
            Assert.That(clock.PeriodMeasured, Is.True);
            Assert.That(clock.StepPeriod, Is.EqualTo(0.5).Within(1e-9));

            // That walk ran out without a stop; a detector starts a new one guessing 0.9 s steps.
            clock.Start(3.0, 1, 0.9);
            Assert.That(clock.PeriodMeasured, Is.False);
            clock.Contact(3.55, -1);
            Assert.That(clock.PeriodMeasured, Is.True);
            Assert.That(clock.StepPeriod, Is.EqualTo(0.55).Within(1e-9), "the first interval replaces the guess");
            clock.Contact(4.15, 1);
            double w = clock.Settings.PeriodWeight;
            Assert.That(w, Is.GreaterThan(0).And.LessThan(1));
            Assert.That(clock.StepPeriod, Is.EqualTo((1 - w) * 0.55 + w * 0.6).Within(1e-9), "later intervals are weighed in");

            clock.Stop();
            Assert.That(clock.PeriodMeasured, Is.False);
        }

        /// <summary>Slow steps of 0.8 s, each with a second bump 0.4 s after its contact that a detector also reports.</summary>
        static (int taken, double period) SlowStepsWithSecondBumps(double minStepShare)
        {
            var clock = new StepClock(PhaseMap.Perry, new StepClockSettings { ContactsToStart = 1, MinStepShare = minStepShare });
            int taken = 0;
            for (int step = 0; step < 8; step++)
            {
                double side = step % 2 == 0 ? 1 : -1;
                if (clock.Contact(0.8 * step, side)) taken++;
                if (step > 0 && clock.Contact(0.8 * step + 0.4, -side)) taken++;
            }
            return (taken, clock.StepPeriod);
        }

        [Test]
        public void APeriodWeightOutsideZeroToOneIsRefusedNamingIt()
        {
            foreach (var w in new[] { 0.0, -0.1, 1.5, double.NaN })
                Assert.That(() => new StepClock(PhaseMap.Perry, new StepClockSettings { PeriodWeight = w }), Throws.ArgumentException.With.Message.Contains("PeriodWeight"), w.ToString());
            Assert.That(() => new StepClock(PhaseMap.Perry, new StepClockSettings { PeriodWeight = 1 }), Throws.Nothing);
        }

        [Test]
        public void OnceThePeriodIsKnownABumpHalfAStepAfterAContactIsNotAStep()
        {
            var kept = SlowStepsWithSecondBumps(new StepClockSettings().MinStepShare);
            Assert.That(kept.taken, Is.EqualTo(8), "only the steps");
            Assert.That(kept.period, Is.EqualTo(0.8).Within(1e-9));
            var off = SlowStepsWithSecondBumps(0);
            Assert.That(off.taken, Is.GreaterThan(12), "every bump counts without it");
            Assert.That(off.period, Is.LessThan(0.5), "and the clock runs at twice the step rate");
        }

        [Test]
        public void ALateConfirmedContactDoesNotMoveTheStrideBackNorLandAFootTwice()
        {
            var held = Positions(0.3, out int heldLandings);
            var free = Positions(0, out int freeLandings);
            Assert.That(StepsBack(free), Is.GreaterThan(0), "dating the clock back to the late contact steps the stride back");
            Assert.That(StepsBack(held), Is.EqualTo(0), "the reported stride position holds instead");
            Assert.That(freeLandings, Is.EqualTo(3), "without the hold the right foot lands again when the stride is dated back");
            Assert.That(heldLandings, Is.EqualTo(2), "the right foot lands at 0.55 and 1.85 s only");
        }
    }

    public class ThresholdClassifierTests
    {
        [Test]
        public void DetectsAboutOneContactPerStep()
        {
            var rec = TestData.Eval("walk_straight");
            var thr = new ThresholdClassifier(TestData.Threshold);
            int detected = 0;
            thr.ContactDetected += (t, e) => detected++;
            ReplayEvaluator.Run(rec, thr);
            int truth = PhaseEvents.TruthSteps(rec).Count + 1;
            Assert.That(detected, Is.EqualTo(truth).Within(truth / 10));
        }

        [Test]
        public void AStreamThatBeginsMidStepDatesItsFirstContactWhenItHappened()
        {
            // The first window arrives 0.49 s into the stream; SMV rose through the threshold at 0.40 s and is still up.
            // Compared with the previous window only, that step would be taken as a contact at 0.49 s (or, read between the
            // window's last two samples alone, missed); the first window looks back and dates it at 0.40 s.
            var settings = ThresholdSettings.Parse(TestData.Threshold.Serialize());
            settings.Gate = WalkingGate.Open;
            Assert.That(settings.Floor, Is.LessThan(3));
            var thr = new ThresholdClassifier(settings);
            var contacts = new List<double>();
            thr.ContactDetected += (t, e) => contacts.Add(t);
            var pre = new StreamPreprocessor(new PreprocessorSettings { History = thr.WindowLength });
            for (int i = 0; i < 60; i++)
                pre.Push(new ImuSample(0.01 * i, 0, 0, 9.80665 + (i >= 40 ? 3 : 0)), w => thr.Classify(w));
            Assert.That(contacts.Count, Is.EqualTo(1));
            Assert.That(contacts[0] + settings.ContactLag, Is.EqualTo(0.40).Within(0.011));

            // Later windows read the crossing between their last two samples only: a rise 0.2 s later is a contact now.
            contacts.Clear();
            thr.Reset();
            pre = new StreamPreprocessor(new PreprocessorSettings { History = thr.WindowLength });
            for (int i = 0; i < 120; i++)
                pre.Push(new ImuSample(0.01 * i, 0, 0, 9.80665 + (i >= 80 ? 3 : 0)), w => thr.Classify(w));
            Assert.That(contacts.Count, Is.EqualTo(1));
            Assert.That(contacts[0] + settings.ContactLag, Is.EqualTo(0.80).Within(0.011));
        }

        [Test]
        public void AContactIsDatedWhereSmvRoseThroughGravity()
        {
            // SMV - g sits at -1, then rises by 0.2 per sample from 0.80 s: above 0 from 0.85 s, above the floor (under 1)
            // from 0.88 s. The contact is dated at the rise through 0; with no dating level, at the threshold crossing.
            double DatedAt(double datingLevel)
            {
                var settings = ThresholdSettings.Parse(TestData.Threshold.Serialize());
                settings.Gate = WalkingGate.Open;
                settings.DatingLevel = datingLevel;
                Assert.That(settings.Floor, Is.InRange(0.1, 0.9));
                var thr = new ThresholdClassifier(settings);
                var contacts = new List<double>();
                thr.ContactDetected += (t, e) => contacts.Add(t + settings.ContactLag);
                var pre = new StreamPreprocessor(new PreprocessorSettings { History = thr.WindowLength });
                for (int i = 0; i < 120; i++)
                    pre.Push(new ImuSample(0.01 * i, 0, 0, 9.80665 + (i < 80 ? -1 : Math.Min(3, -0.9 + 0.2 * (i - 80)))), w => thr.Classify(w));
                Assert.That(contacts.Count, Is.EqualTo(1));
                return contacts[0];
            }
            Assert.That(DatedAt(0), Is.EqualTo(0.85).Within(0.006));
            Assert.That(DatedAt(double.NaN), Is.EqualTo(Math.Round(0.80 + 0.01 * Math.Ceiling((TestData.Threshold.Floor + 0.9) / 0.2), 2)).Within(0.006));
        }

        [Test]
        public void AnAccelerometerScaleErrorBarelyMovesTheDatedContacts()
        {
            // Contacts are dated at SMV rising through 1 g, an absolute level: a sensor reading 3 % high or low shifts SMV - g
            // by about 0.3 m/s^2. The committed THR (trained on people) on the generated walker, scaled both ways.
            var thr = TestData.CommittedThreshold;
            // The clock's lead for the walker's bounce follows the scale on purpose (3 % of a 4 m/s^2 peak: 2 ms); the dating alone here.
            thr.Clock.LeadPerLogBounce = 0;
            var rec = TestData.Eval("walk_straight");
            Recording Scaled(double k)
            {
                var rows = new List<RecordedSample>();
                foreach (var r in rec.Samples)
                {
                    var imu = new ImuSample(r.Imu.Time, k * r.Imu.X, k * r.Imu.Y, k * r.Imu.Z);
                    rows.Add(r.HasTruth ? new RecordedSample(imu, r.Left, r.Right) : new RecordedSample(imu));
                }
                return new Recording(rec.Name, rows);
            }
            var exact = ReplayEvaluator.Run(rec, new ThresholdClassifier(thr)).ClassifierMetrics;
            foreach (double k in new[] { 0.97, 1.03 })
            {
                var m = ReplayEvaluator.Run(Scaled(k), new ThresholdClassifier(thr)).ClassifierMetrics;
                Assert.That(m.StepRecall, Is.GreaterThan(exact.StepRecall - 0.03), $"scale {k}");
                Assert.That(m.MisclassificationRate, Is.LessThan(exact.MisclassificationRate + 0.03), $"scale {k}");
                Assert.That(Math.Abs(m.StepTimingMeanMs - exact.StepTimingMeanMs), Is.LessThan(15), $"scale {k}");
                TestContext.WriteLine($"scale {k}: recall {m.StepRecall:P1}, misclassification {m.MisclassificationRate:P1}, contacts {m.StepTimingMeanMs:F0} ms (exact: {exact.StepRecall:P1}, {exact.MisclassificationRate:P1}, {exact.StepTimingMeanMs:F0} ms)");
            }
        }

        [Test]
        public void ThresholdFilesWithoutADatingLevelDateAtTheCrossing()
        {
            // Their contact lag was measured at the crossing.
            var s = TestData.Threshold;
            Assert.That(s.DatingLevel, Is.EqualTo(0));
            string text = s.Serialize();
            int at = text.IndexOf("dating_level=", StringComparison.Ordinal), end = text.IndexOf('\n', at);
            var old = ThresholdSettings.Parse(text.Remove(at, end - at + 1), "thr.txt");
            Assert.That(old.DatingLevel, Is.NaN);
            Assert.That(ThresholdSettings.Parse(text).DatingLevel, Is.EqualTo(0));
        }

        [Test]
        public void FollowsACalmWalkerAsWellAsABouncyOne()
        {
            // The same walk at half its amplitude: a fixed threshold learned on the original would miss it. The committed
            // THR (trained on people) is used: the generator's standing nods swing at step frequency, so a walking gate
            // trained on generated data can tell them from steps only by their size, and refuses a calm walker too.
            var thr = TestData.CommittedThreshold;
            var rec = TestData.Eval("walk_straight");
            var calm = Training.RecordingAugmentation.Transform(rec, 1.0, 0.5, 0.5, 0.5, 1.0, "calm");
            var normal = ReplayEvaluator.Run(rec, new ThresholdClassifier(thr));
            var quiet = ReplayEvaluator.Run(calm, new ThresholdClassifier(thr));
            Assert.That(quiet.ClassifierMetrics.StepRecall, Is.GreaterThan(0.8));
            Assert.That(quiet.ClassifierMetrics.MisclassificationRate, Is.LessThan(normal.ClassifierMetrics.MisclassificationRate + 0.15));
        }

        [Test]
        public void ASlowerWalkRidesOutTheGateForLonger()
        {
            // A slow walker's head lies still between steps for longer: the gate-refusal counts stretch with the step period
            // beyond StillWindowsStepPeriod (the typical step), and hold at the typical step or faster; COR's only once its walk's
            // contacts span StillWindowsAfterWalked (and while the head's tilt holds, StillWindowsMaxTiltChange).
            var thr = new ThresholdSettings().Clock;
            int established = thr.StopAfterStillWindowsAfter(thr.EstablishedAfter);
            Assert.That(thr.StopAfterStillWindowsAfter(thr.EstablishedAfter, StepClockSettings.TypicalStepPeriod), Is.EqualTo(established));
            Assert.That(thr.StopAfterStillWindowsAfter(thr.EstablishedAfter, 0.45), Is.EqualTo(established), "a faster walk as before");
            Assert.That(thr.StopAfterStillWindowsAfter(thr.EstablishedAfter, 2 * StepClockSettings.TypicalStepPeriod), Is.EqualTo(2 * established));
            Assert.That(thr.ContactAllowed(false, true, thr.ContactWhileStillWindows + 2, StepClockSettings.TypicalStepPeriod), Is.False);
            Assert.That(thr.ContactAllowed(false, true, thr.ContactWhileStillWindows + 2, 0.9), Is.True, "a contact of a walk stepping at 0.9 s");
            Assert.That(thr.ContactAllowed(false, false, 0, 0.9), Is.False, "no walk under way");
            var cor = new CorrelationSettings().Clock;
            cor.ContactsToStart = 1;
            var clock = new StepClock(PhaseMap.Perry, cor);
            clock.Contact(0, 1);
            clock.Contact(0.8, -1);
            Assert.That(clock.RefusalStepPeriod, Is.EqualTo(0), "a young walk: COR's counts as at the typical step");
            Assert.That(cor.StopAfterStillWindowsAfter(double.NaN, clock.RefusalStepPeriod), Is.EqualTo(cor.StopAfterStillWindows));
            clock.Contact(1.6, 1);
            Assert.That(clock.RefusalStepPeriod, Is.EqualTo(clock.StepPeriod), "contacts spanning 0.85 s and more");
            Assert.That(cor.StopAfterStillWindowsAfter(double.NaN, clock.RefusalStepPeriod), Is.GreaterThan(cor.StopAfterStillWindows));
        }

        [Test]
        public void ACountThatShrinksWhileTheGateRefusesStillEndsTheWalk()
        {
            // The gate-refusal count may shrink while the refusals go on: here an established walk's own, smaller count takes
            // over mid-refusal (a contact's new step period or a moving tilt shrink it the same way). THR ended a walk only
            // when the refusals reached the count exactly, so a count that dropped below them never ended it and the clock's
            // own timeout did, later. With the smaller count taking over at any moment, the walk must end no later than with
            // the larger count throughout.
            var rec = WalkingStreamGenerator.Generate("walk then stand", new GaitSubject(), new StreamScript().Walk(6, Foot.Left).Stand(5), 5);
            double LastWalking(double establishedAfter)
            {
                var s = TestData.CommittedThreshold.Clone();
                s.Clock.StopAfterStillWindows = 60;
                s.Clock.EstablishedStopAfterStillWindows = 15;
                s.Clock.EstablishedAfter = establishedAfter;
                s.Clock.StandingAfterPeriods = 4; // the clock's own timeout well after either count
                s.Clock.HoldOnRhythm = false;
                var result = ReplayEvaluator.Run(rec, new ThresholdClassifier(s), keepTrace: true);
                return result.Predictions.FindLast(p => p.IsWalking).Time;
            }
            double withTheLargerCount = LastWalking(double.PositiveInfinity);
            Assert.That(withTheLargerCount, Is.LessThan(6 + 2), "the larger count ends the walk before the clock's timeout");
            int earlier = 0;
            for (double after = 4.5; after <= 7.5; after += 0.05)
            {
                double end = LastWalking(after);
                Assert.That(end, Is.LessThanOrEqualTo(withTheLargerCount), $"the smaller count taking over {after:0.00} s into the walk");
                if (end < withTheLargerCount) earlier++;
            }
            Assert.That(earlier, Is.GreaterThan(0), "the smaller count does end some walks sooner");
        }

        [Test]
        public void StartsASlowCalmWalkAsWellAsItsOwnPace()
        {
            // The same walk 40 % slower and calmer (the benchmark's --slow): its gate score dips below walking at each heel
            // strike, so THR, asking for the score at the crossing alone, never started it (all of its walking shown as
            // standing); it now takes a score that passed within StepClockSettings.StartGateScoreWithin before.
            var thr = TestData.CommittedThreshold;
            var rec = TestData.Eval("walk_straight");
            var normal = ReplayEvaluator.Run(rec, new ThresholdClassifier(thr)).ClassifierMetrics;
            var slow = ReplayEvaluator.Run(Training.RecordingAugmentation.Slow(rec), new ThresholdClassifier(thr)).ClassifierMetrics;
            Assert.That(slow.StepRecall, Is.GreaterThan(normal.StepRecall - 0.05), "steps found");
            Assert.That(slow.WalkingAsStanding, Is.LessThan(normal.WalkingAsStanding + 0.05), "walking shown as standing");
            Assert.That(slow.MisclassificationRate, Is.LessThan(normal.MisclassificationRate + 0.05));
        }

        [Test]
        public void StandingStillIsStanding()
        {
            var rec = WalkingStreamGenerator.Generate("still", GaitSubject.Random(3), new StreamScript().Stand(20), 3);
            var r = ReplayEvaluator.Run(rec, new ThresholdClassifier(TestData.Threshold));
            Assert.That(r.ClassifierMetrics.MisclassificationRate, Is.EqualTo(0));
        }

        [Test]
        public void SettingsRoundTripAndBadOnesNameTheKey()
        {
            var s = TestData.Threshold;
            var back = ThresholdSettings.Parse(s.Serialize());
            Assert.That(back.Floor, Is.EqualTo(s.Floor));
            Assert.That(back.ContactLag, Is.EqualTo(s.ContactLag));
            Assert.That(back.LateralProfile[20], Is.EqualTo(s.LateralProfile[20]).Within(1e-8));
            Assert.That(back.Gate.Serialize(), Is.EqualTo(s.Gate.Serialize()));
            Assert.That(() => ThresholdSettings.Parse(s.Serialize().Replace("floor=", "floor=Infinity\nx="), "thr.txt"),
                Throws.TypeOf<FormatException>().With.Message.Contains("thr.txt").And.Message.Contains("floor"));
            var bouncy = s.Clone();
            bouncy.Clock.LeadPerLogBounce = 0.03;
            bouncy.Clock.LeadReferenceBounce = 4.5;
            var bouncyBack = ThresholdSettings.Parse(bouncy.Serialize());
            Assert.That(bouncyBack.Clock.LeadPerLogBounce, Is.EqualTo(0.03));
            Assert.That(bouncyBack.Clock.LeadReferenceBounce, Is.EqualTo(4.5));
            Assert.That(() => ThresholdSettings.Parse(bouncy.Serialize().Replace("clock_lead_per_log_bounce=", "clock_lead_per_log_bounce=-1\nx="), "thr.txt"),
                Throws.TypeOf<FormatException>().With.Message.Contains("clock_lead_per_log_bounce"));
            // Written before the lead followed the bounce: a fixed lead.
            string old = System.Text.RegularExpressions.Regex.Replace(bouncy.Serialize(), "clock_lead_(per_log|reference)_bounce=[^\n]*\n", "");
            Assert.That(old, Does.Not.Contain("_bounce"));
            Assert.That(ThresholdSettings.Parse(old).Clock.LeadPerLogBounce, Is.EqualTo(0));
        }

        [Test]
        public void TheClockIsLedForTheWalkersStepPeaks()
        {
            var settings = TestData.Threshold.Clone();
            settings.Clock.LeadPerLogBounce = 0.03;
            settings.Clock.LeadReferenceBounce = 1;
            var thr = new ThresholdClassifier(settings);
            double lastBounce = double.NaN, leadThen = double.NaN;
            thr.ContactDetected += (t, e) =>
            {
                lastBounce = thr.WalkBounce;
                leadThen = thr.Clock.BounceLead;
            };
            ReplayEvaluator.Run(TestData.Eval("walk_straight"), thr);
            Assert.That(lastBounce, Is.GreaterThan(1));
            Assert.That(leadThen, Is.EqualTo(Math.Min(StepClockSettings.MaxBounceLead, 0.03 * Math.Log(lastBounce))).Within(1e-12));
        }

        [Test]
        public void TheSidewaysProfileCoversAStrideAndAHalfSecondOneStillReads()
        {
            var s = TestData.Threshold;
            Assert.That(s.LateralProfile.Length, Is.EqualTo(ThresholdSettings.ProfileSamples));
            // A file from before: the profile's newest half second only. THR reads it and names the feet from it.
            var half = new double[ThresholdSettings.HalfSecondProfileSamples];
            Array.Copy(s.LateralProfile, s.LateralProfile.Length - half.Length, half, 0, half.Length);
            string text = s.Serialize();
            int at = text.IndexOf("lateral_profile=", StringComparison.Ordinal), end = text.IndexOf('\n', at);
            string old = text.Substring(0, at) + "lateral_profile=" + string.Join(",", Array.ConvertAll(half, v => v.ToString("R", System.Globalization.CultureInfo.InvariantCulture))) + text.Substring(end);
            var read = ThresholdSettings.Parse(old, "thr.txt");
            Assert.That(read.LateralProfile, Is.EqualTo(half));
            var r = ReplayEvaluator.Run(TestData.Eval("walk_straight"), new ThresholdClassifier(read));
            Assert.That(r.ClassifierMetrics.StepRightFoot, Is.GreaterThan(0.9));
            Assert.That(() => ThresholdSettings.Parse(text.Substring(0, at) + "lateral_profile=1,2,3" + text.Substring(end), "thr.txt"),
                Throws.TypeOf<FormatException>().With.Message.Contains("thr.txt").And.Message.Contains("lateral_profile"));
        }

        [Test]
        public void CalibrationPicksAFloorBetweenNoiseAndStepPeaks()
        {
            Assert.That(TestData.Threshold.Floor, Is.InRange(0.3, 4.0));
        }
    }
}
