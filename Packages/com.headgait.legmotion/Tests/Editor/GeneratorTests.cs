using System;
using System.Collections.Generic;
using HeadGait.Synthetic;
using NUnit.Framework;

namespace HeadGait.Tests
{
    public class GeneratorTests
    {
        static Recording Walk(ulong seed, double seconds, Foot lead, double rate = 100)
            => WalkingStreamGenerator.Generate("w", GaitSubject.Random(seed), new StreamScript { SampleRate = rate }.Stand(2).Walk(seconds, lead).Stand(2), seed);

        [Test]
        public void SameSeedSameStream()
        {
            var a = Walk(3, 5, Foot.Left);
            var b = Walk(3, 5, Foot.Left);
            var c = Walk(4, 5, Foot.Left);
            Assert.That(a.Samples.Count, Is.EqualTo(b.Samples.Count));
            for (int i = 0; i < a.Samples.Count; i++) Assert.That(a.Samples[i].Imu.Z, Is.EqualTo(b.Samples[i].Imu.Z));
            Assert.That(c.Samples[300].Imu.Z, Is.Not.EqualTo(a.Samples[300].Imu.Z));
        }

        [Test]
        public void EachFootRunsThroughItsPhasesInOrder()
        {
            var rec = Walk(8, 20, Foot.Left);
            foreach (Foot foot in new[] { Foot.Left, Foot.Right })
            {
                GaitPhase prev = GaitPhase.Standing;
                int transitions = 0;
                foreach (var s in rec.Samples)
                {
                    var p = s.PhaseOf(foot);
                    if (p == prev) continue;
                    if (prev != GaitPhase.Standing && p != GaitPhase.Standing)
                    {
                        Assert.That((int)p, Is.EqualTo(((int)prev + 1) % 8), $"{foot} jumped from {prev} to {p} at {s.Imu.Time:F3}");
                        transitions++;
                    }
                    prev = p;
                }
                Assert.That(transitions, Is.GreaterThan(100));
            }
        }

        [Test]
        public void LeadFootIsTheFirstToLandAndFeetAlternate()
        {
            foreach (Foot lead in new[] { Foot.Left, Foot.Right })
            {
                var onsets = PhaseEvents.TruthOnsets(Walk(9, 10, lead));
                var contacts = onsets.FindAll(o => o.Phase == GaitPhase.InitialContact);
                Assert.That(contacts[0].Foot, Is.EqualTo(lead));
                for (int i = 1; i < contacts.Count; i++) Assert.That(contacts[i].Foot, Is.Not.EqualTo(contacts[i - 1].Foot));
            }
        }

        [Test]
        public void CadenceMatchesTheSubject()
        {
            var subject = GaitSubject.Random(12);
            var rec = WalkingStreamGenerator.Generate("c", subject, new StreamScript().Walk(30, Foot.Left), 12);
            var steps = PhaseEvents.TruthSteps(rec);
            double mean = 0;
            foreach (var s in steps) mean += s.Duration;
            mean /= steps.Count;
            Assert.That(1 / mean, Is.EqualTo(subject.StepFrequency).Within(0.05 * subject.StepFrequency));
        }

        [Test]
        public void HeadIsStillerStandingThanWalkingAndReadsGravityAtRest()
        {
            var rec = Walk(13, 10, Foot.Right);
            var stand = new List<double>();
            var walk = new List<double>();
            foreach (var s in rec.Samples)
            {
                var a = s.Imu;
                double smv = a.Magnitude - 9.80665;
                (s.Left == GaitPhase.Standing ? stand : walk).Add(smv);
            }
            Assert.That(Std(stand), Is.LessThan(0.15));
            Assert.That(Std(walk), Is.GreaterThan(0.8));
            Assert.That(Mean(stand), Is.EqualTo(0).Within(0.1));
        }

        [Test]
        public void OutputRateFollowsTheScript()
        {
            var rec = Walk(14, 5, Foot.Left, rate: 72);
            Assert.That(rec.Samples.Count / rec.Duration, Is.EqualTo(72).Within(1.0));
        }

        static double Mean(List<double> v)
        {
            double m = 0;
            foreach (var x in v) m += x;
            return m / v.Count;
        }

        static double Std(List<double> v)
        {
            double m = Mean(v), ss = 0;
            foreach (var x in v) ss += (x - m) * (x - m);
            return Math.Sqrt(ss / v.Count);
        }
    }
}
