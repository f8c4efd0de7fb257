using System;
using System.IO;
using HeadGait.Synthetic;
using NUnit.Framework;

namespace HeadGait.Tests
{
    public class RecordingCsvTests
    {
        [Test]
        public void ReadsColumnsByNameInAnyOrder()
        {
            var rec = RecordingCsv.Parse("# headgait-recording v1\n# note=hello\nacc_z,extra,timestamp_s,acc_y,acc_x,phase_right,phase_left\n9.8,x,0.01,0.2,0.1,PSW,IC\n9.7,y,0.02,0.3,0.2,,\n");
            Assert.That(rec.Samples.Count, Is.EqualTo(2));
            var s = rec.Samples[0];
            Assert.That(s.Imu.Time, Is.EqualTo(0.01));
            Assert.That(s.Imu.X, Is.EqualTo(0.1));
            Assert.That(s.Imu.Y, Is.EqualTo(0.2));
            Assert.That(s.Imu.Z, Is.EqualTo(9.8));
            Assert.That(s.Left, Is.EqualTo(GaitPhase.InitialContact));
            Assert.That(s.Right, Is.EqualTo(GaitPhase.PreSwing));
            Assert.That(rec.Samples[1].HasTruth, Is.False);
            Assert.That(rec.Metadata["note"], Is.EqualTo("hello"));
        }

        [Test]
        public void MissingColumnIsAClearError()
        {
            var e = Assert.Throws<RecordingFormatException>(() => RecordingCsv.Parse("timestamp_s,acc_x,acc_y\n0,1,2\n", "bad"));
            Assert.That(e.Message, Does.Contain("acc_z"));
            Assert.That(e.Line, Is.EqualTo(1));
            Assert.That(e.Message, Does.StartWith("bad:1:"));
        }

        [Test]
        public void AFileThatCannotBeReadIsNamedByItsPath()
        {
            string path = Path.Combine(Path.GetTempPath(), $"headgait-bad-{Guid.NewGuid():N}.csv");
            try
            {
                File.WriteAllText(path, "timestamp_s,acc_x,acc_y,acc_z\n0.00,0,0,9.8\n0.01,zero,0,9.8\n");
                var e = Assert.Throws<RecordingFormatException>(() => RecordingCsv.Load(path, strict: true));
                Assert.That(e.FileName, Is.EqualTo(path));
                Assert.That(e.Message, Does.StartWith(path + ":3:").And.Contain("acc_x"));
                Assert.That(RecordingCsv.Load(path).Name, Is.EqualTo(Path.GetFileNameWithoutExtension(path)), "the recording keeps its short name");
                File.WriteAllText(path, "# headgait-pose v1\ntimestamp_s,pos_x,pos_y\n0,0,1.6\n");
                var pose = Assert.Throws<RecordingFormatException>(() => PoseCsv.ToAcceleration(path));
                Assert.That(pose.Message, Does.StartWith(path + ":2:").And.Contain("pos_z"));
            }
            finally
            {
                File.Delete(path);
            }
        }

        [Test]
        public void HalfOfTheGroundTruthIsAnError()
        {
            Assert.Throws<RecordingFormatException>(() => RecordingCsv.Parse("timestamp_s,acc_x,acc_y,acc_z,phase_left\n0,1,2,3,IC\n"));
        }

        [Test]
        public void NoHeaderIsAnError()
        {
            Assert.Throws<RecordingFormatException>(() => RecordingCsv.Parse("# only a comment\n"));
            Assert.Throws<RecordingFormatException>(() => RecordingCsv.Parse("0.0,1,2,3\n"));
        }

        const string WithBadRows = "timestamp_s,acc_x,acc_y,acc_z\n0.00,0,0,9.8\n0.01,zero,0,9.8\n0.02,0,0\n0.03,NaN,0,9.8\n0.04,0,0,9.8\n";

        [Test]
        public void BadRowsAreSkippedWithTheirLineNumbers()
        {
            var rec = RecordingCsv.Parse(WithBadRows);
            Assert.That(rec.Samples.Count, Is.EqualTo(2));
            Assert.That(rec.Warnings.Count, Is.EqualTo(3));
            Assert.That(rec.Warnings[0], Does.StartWith("line 3:").And.Contain("acc_x"));
            Assert.That(rec.Warnings[1], Does.StartWith("line 4:"));
            Assert.That(rec.Warnings[2], Does.StartWith("line 5:").And.Contain("not finite"));
        }

        [Test]
        public void StrictModeStopsAtTheFirstBadRow()
        {
            var e = Assert.Throws<RecordingFormatException>(() => RecordingCsv.Parse(WithBadRows, "r", strict: true));
            Assert.That(e.Line, Is.EqualTo(3));
        }

        [Test]
        public void UnknownOrInconsistentLabelsAreRejected()
        {
            var rec = RecordingCsv.Parse("timestamp_s,acc_x,acc_y,acc_z,phase_left,phase_right\n0,0,0,9.8,WALK,IC\n0.01,0,0,9.8,STAND,IC\n0.02,0,0,9.8,IC,PSW\n");
            Assert.That(rec.Samples.Count, Is.EqualTo(1));
            Assert.That(rec.Warnings.Count, Is.EqualTo(2));
        }

        [Test]
        public void WriteThenReadKeepsTheData()
        {
            var original = WalkingStreamGenerator.Generate("rt", GaitSubject.Random(5), new StreamScript().Stand(1).Walk(3, Foot.Right), 5);
            var sw = new StringWriter();
            RecordingCsv.Write(original, sw);
            var back = RecordingCsv.Parse(sw.ToString(), "rt", strict: true);
            Assert.That(back.Samples.Count, Is.EqualTo(original.Samples.Count));
            for (int i = 0; i < back.Samples.Count; i += 7)
            {
                Assert.That(back.Samples[i].Imu.Time, Is.EqualTo(original.Samples[i].Imu.Time).Within(1e-4));
                Assert.That(back.Samples[i].Imu.Z, Is.EqualTo(original.Samples[i].Imu.Z).Within(1e-4));
                Assert.That(back.Samples[i].Left, Is.EqualTo(original.Samples[i].Left));
                Assert.That(back.Samples[i].Right, Is.EqualTo(original.Samples[i].Right));
            }
            Assert.That(back.Metadata["seed"], Is.EqualTo("5"));
        }

        [Test]
        public void LoadingAMissingFileSaysWhichFile()
        {
            var e = Assert.Throws<FileNotFoundException>(() => RecordingCsv.Load("/nonexistent/walk.csv"));
            Assert.That(e.Message, Does.Contain("/nonexistent/walk.csv"));
        }

        [Test]
        public void AccelerationInGOrWithGravityRemovedIsAClearError()
        {
            var walk = TestData.Eval("walk_straight");
            string Saved(Func<ImuSample, ImuSample> map)
            {
                var copy = new Recording("walk", walk.Samples.ConvertAll(s => new RecordedSample(map(s.Imu), s.Left, s.Right)));
                var text = new StringWriter();
                RecordingCsv.Write(copy, text);
                return text.ToString();
            }
            Assert.That(RecordingCsv.Parse(Saved(a => a), "walk").Samples.Count, Is.EqualTo(walk.Samples.Count));
            const double g = 9.80665;
            var inG = Assert.Throws<RecordingFormatException>(() => RecordingCsv.Parse(Saved(a => new ImuSample(a.Time, a.X / g, a.Y / g, a.Z / g)), "walk"));
            Assert.That(inG.Message, Does.StartWith("walk:").And.Contain("units of g"));
            var linear = Assert.Throws<RecordingFormatException>(() => RecordingCsv.Parse(Saved(a => new ImuSample(a.Time, a.X, a.Y, a.Z - g)), "walk"));
            Assert.That(linear.Message, Does.Contain("gravity removed"));
            Assert.That(linear.Line, Is.EqualTo(3), "the first data row, after the magic line and the header");
        }

        [Test]
        public void CommittedSamplesAreReadable()
        {
            foreach (var e in SampleLibrary.All)
            {
                var rec = TestData.Load(Path.Combine(TestData.Folder, e.Set, e.Name + ".csv"));
                Assert.That(rec.HasTruth, Is.True, e.Name);
                Assert.That(rec.Duration, Is.GreaterThan(20), e.Name);
                Assert.That(rec.Warnings.Count, Is.EqualTo(e.Name == "glitchy" ? 5 : 0), e.Name);
            }
        }

        [Test]
        public void CommittedSamplesMatchTheirGenerator()
        {
            // Regenerates every sample recording and compares it with the committed file, so the files and the
            // generator cannot drift apart. Values are compared numerically (last-digit libm differences are tolerated).
            foreach (var e in SampleLibrary.All)
            {
                var committed = TestData.Load(Path.Combine(TestData.Folder, e.Set, e.Name + ".csv"));
                var fresh = RecordingCsv.Parse(SampleLibrary.ToCsv(e), e.Name);
                Assert.That(fresh.Samples.Count, Is.EqualTo(committed.Samples.Count), e.Name);
                for (int i = 0; i < fresh.Samples.Count; i++)
                {
                    var a = fresh.Samples[i];
                    var b = committed.Samples[i];
                    if (Math.Abs(a.Imu.Time - b.Imu.Time) > 2e-4 || Math.Abs(a.Imu.X - b.Imu.X) > 2e-4 || Math.Abs(a.Imu.Y - b.Imu.Y) > 2e-4
                        || Math.Abs(a.Imu.Z - b.Imu.Z) > 2e-4 || a.Left != b.Left || a.Right != b.Right)
                        Assert.Fail($"{e.Name}: row {i} (line {b.Line}) differs from the generator; run 'headgait generate'");
                }
            }
        }

        [Test]
        public void ByteOrderMarksAndAnyLineEndingsAreRead()
        {
            const string body = "# headgait-recording v1\ntimestamp_s,acc_x,acc_y,acc_z\n0.00,0,0,9.8\n0.01,0,0,9.9\n";
            foreach (var text in new[] { "\uFEFF" + body, "\uFEFF\uFEFF" + body, body.Replace("\n", "\r\n"), body.Replace("\n", "\r") })
            {
                var r = RecordingCsv.Parse(text, "bom");
                Assert.That(r.Samples.Count, Is.EqualTo(2));
                Assert.That(r.Warnings, Is.Empty);
            }
        }

        [Test]
        public void AbsurdTimestampsAndValuesAreRefusedInStrictModeAndReportedOtherwise()
        {
            // Regression: 1e308 s was accepted even in strict mode and silently dropped most of a replay.
            const string text = "# headgait-recording v1\ntimestamp_s,acc_x,acc_y,acc_z\n0.00,0,0,9.8\n1e308,0,0,9.8\n0.02,0,5000,9.8\n0.03,0,0,9.8\n";
            var e = Assert.Throws<RecordingFormatException>(() => RecordingCsv.Parse(text, "absurd", strict: true));
            Assert.That(e.Message, Does.StartWith("absurd:4:").And.Contain("timestamp_s"));
            var lenient = RecordingCsv.Parse(text, "absurd");
            Assert.That(lenient.Samples.Count, Is.EqualTo(2));
            Assert.That(lenient.Warnings[0], Does.Contain("line 4").And.Contain("limit"));
            Assert.That(lenient.Warnings[1], Does.Contain("line 5").And.Contain("acc_y"));
        }

        [Test]
        public void ALabelCursorGivesTheLabelsInForceAtEachTimeAndNoneBeforeTheFirstOrOnAnUnlabelledRow()
        {
            var rec = RecordingCsv.Parse(
                "timestamp_s,acc_x,acc_y,acc_z,phase_left,phase_right\n" +
                "0.10,0,0,9.81,STAND,STAND\n" +
                "0.20,0,0,9.81,IC,PSW\n" +
                "0.30,0,0,9.81,,\n" +
                "0.40,0,0,9.81,LR,ISW\n");
            var cursor = new LabelCursor(rec);
            Assert.That(cursor.TryLabelsAt(0.05, out _), Is.False, "before the first row");
            Assert.That(cursor.TryLabelsAt(0.15, out var a), Is.True);
            Assert.That(a.Left, Is.EqualTo(GaitPhase.Standing));
            Assert.That(cursor.TryLabelsAt(0.2 - 1e-10, out var b), Is.True, "a time within 1e-9 of a row is at it");
            Assert.That((b.Left, b.Right), Is.EqualTo((GaitPhase.InitialContact, GaitPhase.PreSwing)));
            Assert.That(cursor.TryLabelsAt(0.35, out _), Is.False, "the row in force holds no labels");
            Assert.That(cursor.TryLabelsAt(9, out var c), Is.True, "after the last row, the last row's");
            Assert.That((c.Left, c.Right), Is.EqualTo((GaitPhase.LoadingResponse, GaitPhase.InitialSwing)));
        }
    }
}
