using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;
using HeadGait.Mocap;
using NUnit.Framework;

namespace HeadGait.Tests
{
    public class MocapConverterTests
    {
        const string Skeleton = @"HIERARCHY
ROOT Hips
{
	OFFSET 0 0 0
	CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation
	JOINT Spine
	{
		OFFSET 0 20 0
		CHANNELS 3 Zrotation Xrotation Yrotation
		JOINT Head
		{
			OFFSET 0 45 0
			CHANNELS 3 Zrotation Xrotation Yrotation
			End Site
			{
				OFFSET 0 10 0
			}
		}
	}
	JOINT LeftUpLeg
	{
		OFFSET 10 0 0
		CHANNELS 3 Xposition Yposition Zposition
		JOINT LeftFoot
		{
			OFFSET 0 -80 0
			CHANNELS 3 Zrotation Xrotation Yrotation
			JOINT LeftToeBase
			{
				OFFSET 0 -5 12
				CHANNELS 3 Zrotation Xrotation Yrotation
				End Site
				{
					OFFSET 0 0 5
				}
			}
		}
	}
	JOINT RightUpLeg
	{
		OFFSET -10 0 0
		CHANNELS 3 Xposition Yposition Zposition
		JOINT RightFoot
		{
			OFFSET 0 -80 0
			CHANNELS 3 Zrotation Xrotation Yrotation
			JOINT RightToeBase
			{
				OFFSET 0 -5 12
				CHANNELS 3 Zrotation Xrotation Yrotation
				End Site
				{
					OFFSET 0 0 5
				}
			}
		}
	}
}
";

        /// <summary>
        /// A CMU-named skeleton (cm, y up, facing +z) that stands for 1.5 s, steps in place for 4 s (each foot lifted 8 cm
        /// for 0.4 s, a step every 0.5 s, left first), then stands. The hips bob 2 cm at the step rate.
        /// </summary>
        static string SteppingInPlace(out List<(double time, Foot foot)> contacts, double swayCm = 0)
        {
            contacts = new List<(double, Foot)>();
            const double frameTime = 1.0 / 120;
            const double walkStart = 1.5, step = 0.5, swing = 0.4;
            const int steps = 8;
            int frames = (int)((walkStart + steps * step + 1.5) / frameTime);
            // 8 sin(pi u) cm falls below the 4 cm contact height at u = 5/6.
            for (int k = 0; k < steps; k++) contacts.Add((walkStart + k * step + swing * 5 / 6, k % 2 == 0 ? Foot.Left : Foot.Right));
            var sb = new StringBuilder(Skeleton);
            sb.Append("MOTION\nFrames: ").Append(frames).Append("\nFrame Time: ").Append(frameTime.ToString("R", CultureInfo.InvariantCulture)).Append('\n');
            for (int f = 0; f < frames; f++)
            {
                double t = f * frameTime;
                double lift(Foot foot)
                {
                    for (int k = 0; k < steps; k++)
                    {
                        var foot_k = k % 2 == 0 ? Foot.Left : Foot.Right;
                        double u = (t - (walkStart + k * step)) / swing;
                        if (foot_k == foot && u > 0 && u < 1) return 8 * Math.Sin(Math.PI * u);
                    }
                    return 0;
                }
                bool walking = t > walkStart && t < walkStart + steps * step;
                double bob = walking ? 2 * Math.Cos(2 * Math.PI * (t - walkStart) / step) - 2 : 0;
                // Optional sideways sway of the whole body along +x, the skeleton's left.
                double sway = swayCm * Math.Sin(2 * Math.PI * t);
                var v = new List<double> { sway, 90 + bob, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 };
                v.AddRange(new[] { 10.0, lift(Foot.Left) - bob, 0, 0, 0, 0, 0, 0, 0 });
                v.AddRange(new[] { -10.0, lift(Foot.Right) - bob, 0, 0, 0, 0, 0, 0, 0 });
                for (int i = 0; i < v.Count; i++) sb.Append(i > 0 ? " " : "").Append(v[i].ToString("R", CultureInfo.InvariantCulture));
                sb.Append('\n');
            }
            return sb.ToString();
        }

        static MocapSettings Clean() => new MocapSettings { BiasSd = 0, NoiseSd = 0, JitterSd = 0 };

        [Test]
        public void SteppingInPlaceGivesOneLabelledContactPerFootfallAndStandsBeforeAndAfter()
        {
            var rec = MocapConverter.Convert(BvhFile.Parse(SteppingInPlace(out var truth), "stepping.bvh"), Clean());
            Assert.That(rec.Metadata["metres_per_unit"], Is.EqualTo("0.01"));
            Assert.That(rec.Metadata["up_axis"], Is.EqualTo("y"));
            Assert.That(rec.Metadata["joints"], Does.StartWith("Head,LeftFoot,LeftToeBase,RightFoot,RightToeBase"));
            PhaseEvents.ExtractTruth(rec, out var times, out var left, out var right);
            var contacts = PhaseEvents.Contacts(times, left, right);
            Assert.That(contacts.Count, Is.EqualTo(truth.Count), "one contact per footfall");
            for (int i = 0; i < truth.Count; i++)
            {
                Assert.That(contacts[i].Foot, Is.EqualTo(truth[i].foot));
                // The converter's time starts after the 0.25 s trim.
                Assert.That(contacts[i].Time + 0.25, Is.EqualTo(truth[i].time).Within(0.04));
            }
            Assert.That(left[10], Is.EqualTo(GaitPhase.Standing));
            Assert.That(left[left.Count - 10], Is.EqualTo(GaitPhase.Standing));
            Assert.That(left[(int)(2.5 / 0.01)], Is.Not.EqualTo(GaitPhase.Standing));
        }

        [Test]
        public void HeadAccelerationIsGravityAtRestAndFollowsTheBob()
        {
            var rec = MocapConverter.Convert(BvhFile.Parse(SteppingInPlace(out _), "stepping.bvh"), Clean());
            var still = rec.Samples[50].Imu;
            Assert.That(still.Z, Is.EqualTo(MocapConverter.Gravity).Within(1e-6));
            Assert.That(still.X, Is.EqualTo(0).Within(1e-9));
            // Bob 2 cm at 2 Hz: vertical acceleration amplitude (2 pi 2)^2 * 0.02 = 3.16 m/s^2, barely touched by a 12 Hz low-pass.
            double max = double.MinValue, min = double.MaxValue;
            foreach (var s in rec.Samples)
            {
                if (s.Imu.Time < 2.0 || s.Imu.Time > 4.5) continue;
                max = Math.Max(max, s.Imu.Z);
                min = Math.Min(min, s.Imu.Z);
            }
            Assert.That(max - MocapConverter.Gravity, Is.EqualTo(3.16).Within(0.15));
            Assert.That(MocapConverter.Gravity - min, Is.EqualTo(3.16).Within(0.15));
        }

        [TestCase(72.0)]
        [TestCase(90.0)]
        [TestCase(120.0)]
        public void PoseRecordingsReplayedThroughThePosePathGiveTheSameAccelerationAndLabels(double rate)
        {
            var bvh = BvhFile.Parse(SteppingInPlace(out _, swayCm: 3), "sway.bvh");
            var clean = new MocapSettings { BiasSd = 0, NoiseSd = 0, JitterSd = 0, PositionNoiseSd = 0, RotationNoiseDegrees = 0 };
            var accel = MocapConverter.Convert(bvh, clean);
            var poses = MocapConverter.ConvertPose(bvh, rate, clean);
            Assert.That(poses.Name, Is.EqualTo($"sway_{rate:0}hz"));
            string path = Path.Combine(Path.GetTempPath(), $"headgait-pose-{Guid.NewGuid():N}.csv");
            try
            {
                PoseCsv.Save(poses, path);
                Assert.That(PoseCsv.IsPoseFile(path), Is.True);
                var replayed = PoseCsv.ToAcceleration(path, strict: true);
                Assert.That(replayed.SourceLag, Is.InRange(0.04, 0.065));
                // Each replayed sample describes the motion SourceLag before its stamp: compare with the 100 Hz recording there.
                var a = new List<double>[3];
                var b = new List<double>[3];
                for (int k = 0; k < 3; k++) { a[k] = new List<double>(); b[k] = new List<double>(); }
                int labels = 0, agree = 0;
                foreach (var r in replayed.Samples)
                {
                    int i = (int)Math.Round((r.Imu.Time - replayed.SourceLag) / 0.01);
                    if (i < 0 || i >= accel.Samples.Count) continue;
                    var q = accel.Samples[i].Imu;
                    a[0].Add(r.Imu.X); a[1].Add(r.Imu.Y); a[2].Add(r.Imu.Z);
                    b[0].Add(q.X); b[1].Add(q.Y); b[2].Add(q.Z);
                    // Labels belong to the newest pose: compare at the stamp.
                    int j = (int)Math.Round(r.Imu.Time / 0.01);
                    if (j >= accel.Samples.Count) continue;
                    labels++;
                    if (accel.Samples[j].Left == r.Left && accel.Samples[j].Right == r.Right) agree++;
                }
                // Sideways (left, +y) and vertical acceleration follow the sway and the bob, with the same signs.
                Assert.That(Pearson(a[1], b[1]), Is.GreaterThan(0.98), "lateral");
                Assert.That(Pearson(a[2], b[2]), Is.GreaterThan(0.98), "vertical");
                double forward = 0;
                foreach (var x in a[0]) forward = Math.Max(forward, Math.Abs(x));
                Assert.That(forward, Is.LessThan(0.1), "no forward motion in the clip");
                Assert.That(agree, Is.GreaterThan(0.97 * labels));
            }
            finally
            {
                File.Delete(path);
            }
        }

        [Test]
        public void SensorErrorsAreSeededByTheFileName()
        {
            string text = SteppingInPlace(out _);
            var a = MocapConverter.Convert(BvhFile.Parse(text, "a.bvh"));
            var a2 = MocapConverter.Convert(BvhFile.Parse(text, "a.bvh"));
            var b = MocapConverter.Convert(BvhFile.Parse(text, "b.bvh"));
            Assert.That(a.Samples[100].Imu.Z, Is.EqualTo(a2.Samples[100].Imu.Z));
            Assert.That(a.Samples[100].Imu.Z, Is.Not.EqualTo(b.Samples[100].Imu.Z));
            Assert.That(a.Samples[100].Imu.Z, Is.EqualTo(MocapConverter.Gravity).Within(0.2));
        }

        [Test]
        public void MalformedFilesNameTheFileTheLineAndTheProblem()
        {
            string good = SteppingInPlace(out _);
            var cases = new Dictionary<string, string>
            {
                ["truncated"] = good.Substring(0, good.Length - 200),
                ["not a number"] = good.Replace("Frame Time: ", "Frame Time: x"),
                ["unknown channel"] = good.Replace("CHANNELS 3 Xposition Yposition Zposition", "CHANNELS 3 Xposition Wposition Zposition"),
                ["expected 'HIERARCHY'"] = "hello",
                ["frames"] = good.Replace("Frames: ", "Frames: 9"),
            };
            foreach (var kv in cases)
            {
                var e = Assert.Throws<BvhFormatException>(() => BvhFile.Parse(kv.Value, "broken.bvh"), kv.Key);
                Assert.That(e.Message, Does.StartWith("broken.bvh:"), kv.Key);
                Assert.That(e.Line, Is.GreaterThan(0), kv.Key);
            }
            var nan = Assert.Throws<BvhFormatException>(() => BvhFile.Parse(good.Replace("\n0 90 0", "\n0 NaN 0"), "nan.bvh"));
            Assert.That(nan.Message, Does.Contain("not a finite number"));
            var missing = Assert.Throws<BvhFormatException>(() => MocapConverter.Convert(BvhFile.Parse(good, "x.bvh"), new MocapSettings { Head = "Skull" }));
            Assert.That(missing.Message, Does.Contain("Skull").And.Contain("LeftFoot"));
        }

        [Test]
        public void ReproducesTheRealTrainingRecordingsFromTheirBvh()
        {
            string bvhDir = TestData.SharedData("bvh");
            string csvDir = TestData.SharedData("real-train");
            var pairs = new Dictionary<string, string>
            {
                ["dataset-2_walk_active_001"] = "bn_wk_act_001",
                ["dataset-2_walk_feminine_004"] = "bn_wk_fem_004",
                ["dataset-2_walk-turn-left_masculine_002"] = "bn_tl_mas_002",
                ["dataset-2_walk-turn-right_feminine_003"] = "bn_tr_fem_003",
            };
            foreach (var kv in pairs)
            {
                var mine = MocapConverter.Convert(BvhFile.Load(Path.Combine(bvhDir, kv.Key + ".bvh")), Clean());
                var theirs = RecordingCsv.Load(Path.Combine(csvDir, kv.Value + ".csv"));
                int n = Math.Min(mine.Samples.Count, theirs.Samples.Count);
                Assert.That(n, Is.GreaterThan(0.98 * theirs.Samples.Count), kv.Key);
                for (int axis = 0; axis < 3; axis++)
                {
                    double r = Correlation(mine.Samples, theirs.Samples, n, axis);
                    Assert.That(r, Is.GreaterThan(0.995), $"{kv.Key} axis {axis}");
                }
                int agreeL = 0, agreeR = 0;
                for (int i = 0; i < n; i++)
                {
                    if (mine.Samples[i].Left == theirs.Samples[i].Left) agreeL++;
                    if (mine.Samples[i].Right == theirs.Samples[i].Right) agreeR++;
                }
                Assert.That((double)agreeL / n, Is.GreaterThan(0.95), kv.Key + " left labels");
                Assert.That((double)agreeR / n, Is.GreaterThan(0.95), kv.Key + " right labels");
            }
        }

        static double Correlation(List<RecordedSample> a, List<RecordedSample> b, int n, int axis)
        {
            double Get(RecordedSample s) => axis == 0 ? s.Imu.X : axis == 1 ? s.Imu.Y : s.Imu.Z;
            var x = new double[n];
            var y = new double[n];
            for (int i = 0; i < n; i++)
            {
                x[i] = Get(a[i]);
                y[i] = Get(b[i]);
            }
            return Pearson(x, y);
        }

        /// <summary>Pearson's r. Written here because Unity compiles these tests with NUnit as their only library (the
        /// asmdef overrides references), so no statistics package is at hand there.</summary>
        static double Pearson(IReadOnlyList<double> x, IReadOnlyList<double> y)
        {
            double mx = 0, my = 0;
            for (int i = 0; i < x.Count; i++)
            {
                mx += x[i];
                my += y[i];
            }
            mx /= x.Count;
            my /= y.Count;
            double sxy = 0, sxx = 0, syy = 0;
            for (int i = 0; i < x.Count; i++)
            {
                double dx = x[i] - mx, dy = y[i] - my;
                sxy += dx * dy;
                sxx += dx * dx;
                syy += dy * dy;
            }
            return sxy / Math.Sqrt(sxx * syy);
        }
    }
}
