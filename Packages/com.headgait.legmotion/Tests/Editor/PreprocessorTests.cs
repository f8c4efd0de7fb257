using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace HeadGait.Tests
{
    public class PreprocessorTests
    {
        static List<SignalWindow> Feed(StreamPreprocessor p, IEnumerable<ImuSample> samples)
        {
            var windows = new List<SignalWindow>();
            foreach (var s in samples) p.Push(s, w => windows.Add(w.Clone()));
            return windows;
        }

        static IEnumerable<ImuSample> Regular(int count, double rate, Func<double, ImuSample> make)
        {
            for (int i = 0; i < count; i++) yield return make(i / rate);
        }

        [Test]
        public void GravityOnlyGivesZeroSmv()
        {
            var windows = Feed(new StreamPreprocessor(), Regular(200, 100, TestData.Still));
            Assert.That(windows.Count, Is.EqualTo(151));
            foreach (var w in windows)
                foreach (var v in w.Smv) Assert.That(v, Is.EqualTo(0).Within(1e-12));
        }

        [Test]
        public void SmvIsMagnitudeMinusGravityWhateverTheOrientation()
        {
            // 12 m/s^2 of specific force along a tilted axis: SMV is 12 - g regardless of the direction.
            var p = new StreamPreprocessor();
            var windows = Feed(p, Regular(60, 100, t => new ImuSample(t, 12 * Math.Sin(0.3), 12 * Math.Cos(0.3) * Math.Sin(1.1), 12 * Math.Cos(0.3) * Math.Cos(1.1))));
            Assert.That(windows[0].Smv[10], Is.EqualTo(12 - 9.80665).Within(1e-9));
        }

        [Test]
        public void SlidesOneSampleAtATimeAfterTheFirst50()
        {
            var windows = Feed(new StreamPreprocessor(), Regular(120, 100, t => new ImuSample(t, 0, t, 9.80665 + t)));
            Assert.That(windows.Count, Is.EqualTo(71));
            Assert.That(windows[0].EndTime, Is.EqualTo(0.49).Within(1e-9));
            for (int i = 1; i < windows.Count; i++)
            {
                Assert.That(windows[i].EndTime - windows[i - 1].EndTime, Is.EqualTo(0.01).Within(1e-9));
                // Oldest first: the window's first sample is the previous window's second.
                Assert.That(windows[i].Smv[0], Is.EqualTo(windows[i - 1].Smv[1]).Within(1e-9));
                Assert.That(windows[i].Lateral[48], Is.EqualTo(windows[i - 1].Lateral[49]).Within(1e-9));
            }
        }

        [Test]
        public void ResamplesIrregularTimestampsOntoA100HzGrid()
        {
            // |acc| = g + t exactly, so SMV = t, while the lateral channel is y = 2t; random intervals of 3 to 25 ms.
            var rnd = new Random(7);
            var samples = new List<ImuSample>();
            double t = 0;
            while (t < 3)
            {
                samples.Add(new ImuSample(t, 0, 2 * t, Math.Sqrt((9.80665 + t) * (9.80665 + t) - 4 * t * t)));
                t += 0.003 + 0.022 * rnd.NextDouble();
            }
            var windows = Feed(new StreamPreprocessor(), samples);
            double last = samples[samples.Count - 1].Time;
            Assert.That(windows.Count, Is.EqualTo((int)Math.Floor(last / 0.01 + 1e-9) + 1 - 49));
            foreach (var w in windows)
            {
                for (int i = 0; i < 50; i++)
                {
                    double ti = w.EndTime - (49 - i) * 0.01;
                    Assert.That(w.Smv[i], Is.EqualTo(ti).Within(1e-9));
                    Assert.That(w.Lateral[i], Is.EqualTo(2 * ti).Within(1e-9));
                }
            }
        }

        [Test]
        public void Upsamples50HzInput()
        {
            var windows = Feed(new StreamPreprocessor(), Regular(100, 50, t => new ImuSample(t, 0, 0, 9.80665 + Math.Sin(t))));
            // 1.98 s of input -> 199 grid samples -> 150 windows.
            Assert.That(windows.Count, Is.EqualTo(150));
            Assert.That(windows[75].Smv[25], Is.EqualTo(Math.Sin(windows[75].EndTime - 0.24)).Within(1e-3));
        }

        [Test]
        public void SkipsNonFiniteSamplesAndCountsThem()
        {
            var p = new StreamPreprocessor();
            var outcomes = new List<SampleOutcome>();
            int windows = 0;
            for (int i = 0; i < 100; i++)
            {
                double t = i * 0.01;
                var s = i % 10 == 3 ? new ImuSample(t, double.NaN, 0, 9.8)
                      : i % 10 == 7 ? new ImuSample(t, 0, double.PositiveInfinity, 9.8)
                      : i == 55 ? new ImuSample(double.NaN, 0, 0, 9.8)
                      : TestData.Still(t);
                outcomes.Add(p.Push(s, w => windows++));
            }
            Assert.That(p.SkippedNotFinite, Is.EqualTo(21));
            Assert.That(outcomes[3], Is.EqualTo(SampleOutcome.SkippedNotFinite));
            // Holes of 20 ms are bridged: the grid stays complete.
            Assert.That(windows, Is.EqualTo(100 - 49));
        }

        [Test]
        public void SkipsOutOfOrderAndRepeatedTimestamps()
        {
            var p = new StreamPreprocessor();
            int windows = 0;
            Assert.That(p.Push(TestData.Still(0.00), w => windows++), Is.EqualTo(SampleOutcome.Accepted));
            Assert.That(p.Push(TestData.Still(0.01), w => windows++), Is.EqualTo(SampleOutcome.Accepted));
            Assert.That(p.Push(TestData.Still(0.005), w => windows++), Is.EqualTo(SampleOutcome.SkippedOutOfOrder));
            Assert.That(p.Push(TestData.Still(0.01), w => windows++), Is.EqualTo(SampleOutcome.SkippedDuplicateTime));
            for (int i = 2; i < 60; i++) p.Push(TestData.Still(i * 0.01), w => windows++);
            Assert.That(p.SkippedOutOfOrder, Is.EqualTo(1));
            Assert.That(p.SkippedDuplicateTime, Is.EqualTo(1));
            Assert.That(windows, Is.EqualTo(11));
        }

        [Test]
        public void LongGapRestartsTheWindow()
        {
            var p = new StreamPreprocessor();
            var ends = new List<double>();
            for (int i = 0; i < 80; i++) p.Push(TestData.Still(i * 0.01), w => ends.Add(w.EndTime));
            Assert.That(ends.Count, Is.EqualTo(31));
            Assert.That(p.Push(TestData.Still(1.5), w => ends.Add(w.EndTime)), Is.EqualTo(SampleOutcome.AcceptedAfterGap));
            for (int i = 1; i < 49; i++) p.Push(TestData.Still(1.5 + i * 0.01), w => ends.Add(w.EndTime));
            Assert.That(ends.Count, Is.EqualTo(31), "no window may mix samples from both sides of the gap");
            p.Push(TestData.Still(1.5 + 49 * 0.01), w => ends.Add(w.EndTime));
            Assert.That(ends.Count, Is.EqualTo(32));
            Assert.That(ends[31], Is.EqualTo(1.99).Within(1e-9));
            Assert.That(p.Gaps, Is.EqualTo(1));
        }

        [Test]
        public void RejectsImplausibleMagnitudes()
        {
            var p = new StreamPreprocessor();
            p.Push(TestData.Still(0), null);
            Assert.That(p.Push(new ImuSample(0.01, 1e6, 0, 0), null), Is.EqualTo(SampleOutcome.SkippedImplausible));
        }

        [Test]
        public void InvalidSettingsAreRefused()
        {
            Assert.That(() => new StreamPreprocessor(new PreprocessorSettings { SampleRate = 0 }), Throws.ArgumentException);
            Assert.That(() => new StreamPreprocessor(new PreprocessorSettings { WindowLength = 1 }), Throws.ArgumentException);
            Assert.That(() => new StreamPreprocessor(new PreprocessorSettings { MaxGap = -1 }), Throws.ArgumentException);
        }
    }
}
