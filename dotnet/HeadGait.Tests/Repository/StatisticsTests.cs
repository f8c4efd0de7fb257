using System.Collections.Generic;
using HeadGait.Tooling;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>The study summary's statistics against a worked example (six subjects, three conditions; values checked with SciPy).</summary>
    public class StatisticsTests
    {
        static readonly List<double[]> Data = new List<double[]>
        {
            new double[] { 45, 50, 55 }, new double[] { 42, 42, 45 }, new double[] { 36, 41, 43 },
            new double[] { 39, 35, 40 }, new double[] { 51, 55, 59 }, new double[] { 44, 49, 56 },
        };

        [Test]
        public void RepeatedMeasuresAnovaSplitsTheSumsOfSquaresAndCorrectsForSphericity()
        {
            var a = RepeatedMeasuresAnova.Compute(Data);
            Assert.That(a.SsConditions, Is.EqualTo(143.444444).Within(1e-5));
            Assert.That(a.SsSubjects, Is.EqualTo(658.277778).Within(1e-5));
            Assert.That(a.SsError, Is.EqualTo(57.222222).Within(1e-5));
            Assert.That(a.DfConditions, Is.EqualTo(2));
            Assert.That(a.DfError, Is.EqualTo(10));
            Assert.That(a.F, Is.EqualTo(12.533981).Within(1e-5));
            Assert.That(a.P, Is.EqualTo(0.00188559).Within(1e-7));
            Assert.That(a.Epsilon, Is.EqualTo(0.638380).Within(1e-5));
            Assert.That(a.PCorrected, Is.EqualTo(0.00898522).Within(1e-7));
            Assert.That(a.PartialEtaSquared, Is.EqualTo(0.714839).Within(1e-5));
        }

        [Test]
        public void PairedTestsAreBonferroniCorrected()
        {
            var x = new List<double>();
            var y = new List<double>();
            foreach (var row in Data)
            {
                x.Add(row[0]);
                y.Add(row[2]);
            }
            var t = PairedComparison.Compute("a", "c", x, y, 3);
            Assert.That(t.T, Is.EqualTo(-4.016521).Within(1e-5));
            Assert.That(t.P, Is.EqualTo(0.0101557).Within(1e-6));
            Assert.That(t.PBonferroni, Is.EqualTo(3 * 0.0101557).Within(3e-6));
        }

        [Test]
        public void SphericalDataNeedNoCorrection()
        {
            // Every subject differs from the others by a constant: the differences between conditions have equal variance.
            var data = new List<double[]> { new double[] { 1, 2, 4 }, new double[] { 2, 3, 5 }, new double[] { 3, 5, 6 }, new double[] { 4, 5, 7 } };
            var a = RepeatedMeasuresAnova.Compute(data);
            Assert.That(a.Epsilon, Is.InRange(0.5, 1.0));
            Assert.That(a.PCorrected, Is.GreaterThanOrEqualTo(a.P));
        }
    }
}
