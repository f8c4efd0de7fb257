using System;
using System.Collections.Generic;
using System.IO;
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
            Assert.That(t.StridesUsed, Is.GreaterThan(70));
            // The learned onsets stay near Perry's (the training subjects' stance is 60-64 %).
            Assert.That(t.PhaseMap.Onset(GaitPhase.InitialSwing), Is.EqualTo(0.62).Within(0.03));
            Assert.That(t.PhaseMap.RightOffset, Is.EqualTo(0.5).Within(0.02));
            // Head vertical acceleration peaks early in the step, after initial contact.
            int peak = 0;
            for (int i = 1; i < t.StepSmv.Length; i++) if (t.StepSmv[i] > t.StepSmv[peak]) peak = i;
            Assert.That(peak, Is.InRange(2, 30));
        }

        [Test]
        public void SerializesAndParsesBack()
        {
            var t = TestData.Template;
            var back = CorrelationTemplate.Parse(t.Serialize());
            for (int i = 0; i < t.StepSmv.Length; i++) Assert.That(back.StepSmv[i], Is.EqualTo(t.StepSmv[i]).Within(1e-7));
            for (int i = 0; i < t.StrideLateral.Length; i++) Assert.That(back.StrideLateral[i], Is.EqualTo(t.StrideLateral[i]).Within(1e-7));
            Assert.That(back.MinWalkingStd, Is.EqualTo(t.MinWalkingStd));
            Assert.That(back.PhaseMap.Serialize(), Is.EqualTo(t.PhaseMap.Serialize()));
        }

        [Test]
        public void CommittedTemplateIsWhatTrainingProduces()
        {
            var committed = CorrelationTemplate.Load(Path.Combine(TestData.Folder, "cor_template.txt"));
            var t = TestData.Template;
            for (int i = 0; i < t.StepSmv.Length; i++) Assert.That(committed.StepSmv[i], Is.EqualTo(t.StepSmv[i]).Within(1e-6));
        }

        [Test]
        public void BrokenTemplatesAreRefusedWithAReason()
        {
            string good = TestData.Template.Serialize();
            Assert.That(() => CorrelationTemplate.Parse("step_smv=1,2"), Throws.TypeOf<FormatException>().With.Message.Contains("first line"));
            Assert.That(() => CorrelationTemplate.Parse(good.Replace("min_walking_std=", "min_walking=")), Throws.TypeOf<FormatException>().With.Message.Contains("min_walking_std"));
            Assert.That(() => CorrelationTemplate.Parse(good.Replace("step_smv=", "step_smv=1,")), Throws.TypeOf<FormatException>().With.Message.Contains("101 values"));
            Assert.That(() => CorrelationTemplate.Parse(good.Replace("stride_lateral=", "stride_lateral=NaN,")), Throws.TypeOf<FormatException>());
        }

        [Test]
        public void TrainingWithoutWalkingSaysSo()
        {
            var standing = WalkingStreamGenerator.Generate("s", GaitSubject.Random(1), new StreamScript().Stand(10), 1);
            Assert.That(() => CorrelationTemplate.Train(new[] { standing }), Throws.InvalidOperationException.With.Message.Contains("too small"));
        }
    }

    public class CorrelationClassifierTests
    {
        [Test]
        public void FindsThePhaseOfAWindowCutFromTheTemplate()
        {
            var t = TestData.Template;
            var cor = new CorrelationClassifier(t);
            int P = 55;
            foreach (double uEnd in new[] { 0.1, 0.37, 0.8 })
            {
                var w = new SignalWindow(50, 100) { };
                for (int i = 0; i < 50; i++)
                {
                    double u = uEnd - (49 - i) / (double)P;
                    w.Smv[i] = 3 * t.StepAt(u) + 0.5;
                    // Lateral of the left foot's step at that step fraction.
                    w.Lateral[i] = t.LateralAt(u * t.PhaseMap.RightOffset);
                }
                cor.Reset();
                var p = cor.Classify(w);
                Assert.That(p.IsWalking, Is.True);
                Assert.That(cor.LastCorrelation, Is.GreaterThan(0.99));
                Assert.That(PhaseMap.CyclicDelta(p.StridePosition, uEnd * t.PhaseMap.RightOffset), Is.EqualTo(0).Within(0.01), $"u={uEnd}");
                Assert.That(p.StepPeriod, Is.EqualTo(0.55).Within(0.011));
            }
        }

        [Test]
        public void MeetsThePapersMisclassificationOnStraightWalking()
        {
            var r = ReplayEvaluator.Run(TestData.Eval("walk_straight"), new CorrelationClassifier(TestData.Template));
            Assert.That(r.ClassifierMetrics.MisclassificationRate, Is.LessThan(0.087));
            Assert.That(r.AnimatorMetrics.MisclassificationRate, Is.LessThan(0.087));
            Assert.That(Math.Abs(r.ClassifierMetrics.MeanDelayMs), Is.LessThan(60));
        }

        [Test]
        public void StaysUsableAcrossAllEvaluationRecordings()
        {
            foreach (var rec in TestData.EvalSet())
            {
                var r = ReplayEvaluator.Run(rec, new CorrelationClassifier(TestData.Template));
                Assert.That(r.ClassifierMetrics.MisclassificationRate, Is.LessThan(0.15), rec.Name);
                Assert.That(r.ClassifierMetrics.ActivityErrorRate, Is.LessThan(0.08), rec.Name);
            }
        }

        [Test]
        public void NoddingWhileStandingIsNotWalking()
        {
            var rec = WalkingStreamGenerator.Generate("nods", GaitSubject.Random(77), new StreamScript().Stand(30, 0.9), 77);
            var r = ReplayEvaluator.Run(rec, new CorrelationClassifier(TestData.Template));
            // Strong rhythmic nods pass for a step now and then (bursts of ~0.2 s). The animator may begin a Start
            // clip on one, but cancels it before the lead foot lands: the avatar never reaches Walking.
            Assert.That(r.ClassifierMetrics.ActivityErrorRate, Is.LessThan(0.05));
            Assert.That(r.AnimatorMetrics.ActivityErrorRate, Is.LessThan(0.05));
            Assert.That(r.StateCounts.ContainsKey(LocomotionState.Walking), Is.False);
            Assert.That(r.StateCounts.ContainsKey(LocomotionState.FinishWalkLeft) || r.StateCounts.ContainsKey(LocomotionState.FinishWalkRight), Is.False);
        }

        [Test]
        public void PerWindowCostIsBelowThePapers()
        {
            var r = ReplayEvaluator.Run(TestData.Eval("walk_straight"), new CorrelationClassifier(TestData.Template));
            Assert.That(r.Windows, Is.GreaterThan(4000));
            Assert.That(r.MeanWindowMs, Is.LessThan(0.67), "paper: COR 0.67 ms per window");
        }
    }

    public class ThresholdClassifierTests
    {
        [Test]
        public void DetectsAboutOneInitialContactPerStep()
        {
            var rec = TestData.Eval("walk_straight");
            var thr = new ThresholdClassifier(ThresholdClassifier.Calibrate(TestData.Training));
            var r = ReplayEvaluator.Run(rec, thr, keepTrace: true);
            int detected = 0;
            for (int i = 1; i < r.Predictions.Count; i++)
            {
                var a = r.Predictions[i - 1];
                var b = r.Predictions[i];
                if (b.IsWalking && (!a.IsWalking || b.Confidence > a.Confidence + 0.5)) detected++;
            }
            int truth = PhaseEvents.TruthSteps(rec).Count + 1;
            Assert.That(detected, Is.EqualTo(truth).Within(truth / 10));
        }

        [Test]
        public void BeatsThePapersMisclassificationOnStraightWalking()
        {
            var thr = new ThresholdClassifier(ThresholdClassifier.Calibrate(TestData.Training), TestData.Template.PhaseMap);
            var r = ReplayEvaluator.Run(TestData.Eval("walk_straight"), thr);
            Assert.That(r.ClassifierMetrics.MisclassificationRate, Is.LessThan(0.51));
        }

        [Test]
        public void StandingStillIsStanding()
        {
            var rec = WalkingStreamGenerator.Generate("still", GaitSubject.Random(3), new StreamScript().Stand(20), 3);
            var r = ReplayEvaluator.Run(rec, new ThresholdClassifier(ThresholdClassifier.Calibrate(TestData.Training)));
            Assert.That(r.ClassifierMetrics.MisclassificationRate, Is.EqualTo(0));
        }

        [Test]
        public void CalibrationPicksAThresholdBetweenNoiseAndStepPeaks()
        {
            var s = ThresholdClassifier.Calibrate(TestData.Training);
            Assert.That(s.Threshold, Is.InRange(0.5, 4.0));
        }
    }
}
