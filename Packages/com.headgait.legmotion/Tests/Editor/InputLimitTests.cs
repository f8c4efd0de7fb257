using System;
using System.Diagnostics;
using System.IO;
using System.Text;
using HeadGait.Mocap;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>
    /// Hostile files against every reader (<see cref="InputLimits"/>): each is refused with one error naming the file and the
    /// limit, quickly and without taking the memory the file asks for. Big files are sparse (SetLength), so they cost no disk.
    /// </summary>
    public class InputLimitTests
    {
        string folder;

        [SetUp]
        public void SetUp()
        {
            folder = Path.Combine(Path.GetTempPath(), "headgait-limits-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(folder);
        }

        [TearDown]
        public void TearDown() => Directory.Delete(folder, true);

        string Sparse(string name, long length, string head = "") => Sparse(folder, name, length, head);

        /// <summary>A file of <paramref name="length"/> bytes that starts with <paramref name="head"/>, the rest a hole (no disk used).</summary>
        public static string Sparse(string folder, string name, long length, string head)
        {
            string path = Path.Combine(folder, name);
            using (var fs = new FileStream(path, FileMode.CreateNew))
            {
                var bytes = Encoding.UTF8.GetBytes(head);
                fs.Write(bytes, 0, bytes.Length);
                fs.SetLength(length);
            }
            return path;
        }

        static T Refused<T>(TestDelegate read, string path, string limit) where T : Exception
        {
            long before = GC.GetTotalMemory(false);
            var watch = Stopwatch.StartNew();
            var e = Assert.Throws<T>(read);
            Assert.That(e.Message, Does.Contain(Path.GetFileName(path)), "the error names the file");
            Assert.That(e.Message, Does.Contain(limit), "the error names the limit");
            Assert.That(watch.Elapsed.TotalSeconds, Is.LessThan(20), "refused without reading the whole file");
            Assert.That(GC.GetTotalMemory(false) - before, Is.LessThan(200L << 20), "the refusal held no more than 200 MB");
            TestContext.WriteLine(e.Message);
            return e;
        }

        [Test]
        public void AHugeSparseRecordingIsRefusedBeforeItIsRead()
        {
            string path = Sparse("huge.csv", 1500L << 20, "timestamp_s,acc_x,acc_y,acc_z\n");
            Refused<InputLimitException>(() => RecordingCsv.Load(path), path, "InputLimits");
            Refused<InputLimitException>(() => PoseCsv.ToAcceleration(path), path, "InputLimits");
        }

        [Test]
        public void ALineWithoutEndIsRefusedAtTheLineLimit()
        {
            // 20 MB of zero bytes: under the file limit, but one endless line (what a sparse or corrupt file reads as).
            string path = Sparse("zeros.csv", 20L << 20);
            Refused<InputLimitException>(() => RecordingCsv.Load(path), path, "MaxLineChars");
        }

        [Test]
        public void TooManyBadRowsAreCountedNotListed()
        {
            var text = new StringBuilder("timestamp_s,acc_x,acc_y,acc_z\n");
            for (int i = 0; i < 5000; i++) text.Append("0,01;0,02;9,81\n");
            var rec = RecordingCsv.Parse(text.ToString(), "commas.csv");
            Assert.That(rec.Samples, Is.Empty);
            Assert.That(rec.Warnings.Count, Is.EqualTo(InputLimits.MaxListedWarnings + 1));
            Assert.That(rec.Warnings[rec.Warnings.Count - 1], Does.Contain("4000 more bad row(s)"));
        }

        [TestCase("/dev/zero")]
        [TestCase("fifo")]
        public void DevicesAndPipesReadAsEmptyWithoutBlocking(string name)
        {
            string path = name;
            if (name == "fifo")
            {
                path = Path.Combine(folder, "recording.csv");
                if (!MakeFifo(path)) Assert.Ignore("mkfifo is not available here");
            }
            else if (!File.Exists(path)) Assert.Ignore("no /dev/zero here");
            var watch = Stopwatch.StartNew();
            Assert.Throws<RecordingFormatException>(() => RecordingCsv.Load(path));
            Assert.Throws<BvhFormatException>(() => BvhFile.Load(path));
            Assert.Throws<ModelFormatException>(() => ModelFile.Load(path));
            Assert.Throws<FormatException>(() => ThresholdSettings.Load(path));
            Assert.That(watch.Elapsed.TotalSeconds, Is.LessThan(10), "nothing waited on the pipe or read the device for long");
        }

        static bool MakeFifo(string path)
        {
            try
            {
                using (var p = Process.Start(new ProcessStartInfo("mkfifo", path) { UseShellExecute = false }))
                {
                    p.WaitForExit();
                    return p.ExitCode == 0;
                }
            }
            catch (System.ComponentModel.Win32Exception)
            {
                return false;
            }
        }

        const string Skeleton = "HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 0\n CHANNELS 3 Xposition Yposition Zposition\n JOINT Head\n {\n  OFFSET 0 1 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n  End Site\n  {\n   OFFSET 0 1 0\n  }\n }\n}\n";

        [Test]
        public void ABvhDeclaringTwoBillionFramesIsRefusedAtOnce()
        {
            string path = Path.Combine(folder, "liar.bvh");
            File.WriteAllText(path, Skeleton + "MOTION\nFrames: 2000000000\nFrame Time: 0.0333\n0 0 0 0 0 0\n");
            Assert.That(new FileInfo(path).Length, Is.LessThan(300));
            Refused<BvhFormatException>(() => BvhFile.Load(path), path, "MaxBvhFrames");
            // Under the frame limit but more values than the text holds: refused before anything is allocated.
            File.WriteAllText(path, Skeleton + "MOTION\nFrames: 900000\nFrame Time: 0.0333\n0 0 0 0 0 0\n");
            Refused<BvhFormatException>(() => BvhFile.Load(path), path, "more values than the file holds");
        }

        [Test]
        public void TwoHundredThousandNestedJointsAreRefusedWithoutRecursion()
        {
            var sb = new StringBuilder("HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 0\n CHANNELS 0\n");
            const int depth = 200000;
            for (int i = 0; i < depth; i++) sb.Append("JOINT j").Append(i).Append("\n{\nOFFSET 0 1 0\nCHANNELS 0\n");
            for (int i = 0; i < depth; i++) sb.Append("}\n");
            sb.Append("}\nMOTION\nFrames: 2\nFrame Time: 0.0333\n\n\n");
            string path = Path.Combine(folder, "deep.bvh");
            File.WriteAllText(path, sb.ToString());
            Refused<BvhFormatException>(() => BvhFile.Load(path), path, "MaxBvhDepth");
            // A skeleton within the limit still reads, the same as before (iterative, same joint order and parents).
            var bvh = BvhFile.Parse(Skeleton + "MOTION\nFrames: 2\nFrame Time: 0.0333\n0 0 0 0 0 0\n0 0 0 0 0 0\n");
            Assert.That(bvh.Joints.Count, Is.EqualTo(3));
            Assert.That(bvh.Joints[1].Parent, Is.EqualTo(0));
            Assert.That(bvh.Joints[2].Parent, Is.EqualTo(1));
            Assert.That(bvh.Joints[2].IsEndSite, Is.True);
            Assert.That(bvh.ChannelCount, Is.EqualTo(6));
        }

        [Test]
        public void HugeModelFilesAreRefusedAndTheClassifierFallsBack()
        {
            string thr = Sparse(GaitModels.ThresholdFile, 1500L << 20, "# headgait-thr v1\n");
            string svm = Sparse(GaitModels.SvmFile, 1500L << 20, ModelFile.Magic + "\n");
            Refused<InputLimitException>(() => ThresholdSettings.Load(thr), thr, "InputLimits");
            Refused<ModelFormatException>(() => ModelFile.Load(svm), svm, "InputLimits");
            var models = GaitModels.Load(folder);
            Assert.That(models.Problems, Has.Some.Contains(GaitModels.ThresholdFile).And.Contains("limit"));
            models.Create("svm", out string warning);
            Assert.That(warning, Does.Contain("limit"));
        }
    }
}
