extern alias cli;

using System;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using System.Threading;
using NUnit.Framework;
using CliProgram = cli::HeadGait.Cli.Program;

namespace HeadGait.Tests.Cli
{
    /// <summary>
    /// Every hostile file of the campaign through the command line in a child process: a clear error (exit 1, or a warning and
    /// the fallback for a model), no stack trace, and the child's peak memory (VmHWM, polled) printed and under 1 GB.
    /// Linux only (the peak is read from /proc).
    /// </summary>
    [NonParallelizable]
    public class CliHostileFileTests
    {
        const long OneGigabyte = 1L << 30;
        string folder;

        [SetUp]
        public void SetUp()
        {
            if (!File.Exists("/proc/self/status")) Assert.Ignore("the peak memory is read from /proc (Linux)");
            folder = Path.Combine(Path.GetTempPath(), "headgait-hostile-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(folder);
        }

        [TearDown]
        public void TearDown()
        {
            if (folder != null && Directory.Exists(folder)) Directory.Delete(folder, true);
        }

        string Sparse(string name, long length, string head) => InputLimitTests.Sparse(folder, name, length, head);

        /// <summary>Runs the CLI (the same build the tests reference) as a child; returns its exit code, output and peak resident memory.</summary>
        static (int code, string output, long peak) Child(params string[] args)
        {
            string dll = typeof(CliProgram).Assembly.Location;
            var info = new ProcessStartInfo("dotnet") { UseShellExecute = false, RedirectStandardOutput = true, RedirectStandardError = true };
            info.ArgumentList.Add(dll);
            foreach (var a in args) info.ArgumentList.Add(a);
            using (var p = Process.Start(info))
            {
                var output = new StringBuilder();
                p.OutputDataReceived += (s, e) => { if (e.Data != null) lock (output) output.AppendLine(e.Data); };
                p.ErrorDataReceived += (s, e) => { if (e.Data != null) lock (output) output.AppendLine(e.Data); };
                p.BeginOutputReadLine();
                p.BeginErrorReadLine();
                long peak = 0;
                var watch = Stopwatch.StartNew();
                while (!p.WaitForExit(20))
                {
                    peak = Math.Max(peak, PeakOf(p.Id));
                    if (watch.Elapsed.TotalSeconds > 120)
                    {
                        p.Kill();
                        Assert.Fail($"headgait {string.Join(" ", args)} ran over 120 s");
                    }
                }
                p.WaitForExit();
                lock (output) return (p.ExitCode, output.ToString(), peak);
            }
        }

        /// <summary>VmHWM of a process (bytes), 0 once it is gone.</summary>
        static long PeakOf(int pid)
        {
            try
            {
                foreach (var line in File.ReadAllLines($"/proc/{pid}/status"))
                    if (line.StartsWith("VmHWM:", StringComparison.Ordinal))
                        return 1024 * long.Parse(line.Substring(6).Trim().Split(' ')[0], CultureInfo.InvariantCulture);
            }
            catch (IOException) { }
            catch (UnauthorizedAccessException) { }
            return 0;
        }

        void Hostile(string what, int expected, string mustSay, params string[] args)
        {
            var (code, output, peak) = Child(args);
            TestContext.WriteLine($"{what}: exit {code}, peak memory {peak / 1048576.0:F0} MB\n{output}");
            TestContext.Progress.WriteLine($"hostile file: {what}: exit {code}, peak memory {peak / 1048576.0:F0} MB");
            Assert.That(output, Does.Not.Contain("   at "), "no stack trace");
            Assert.That(code, Is.EqualTo(expected), output);
            Assert.That(output, Does.Contain(mustSay));
            Assert.That(peak, Is.GreaterThan(0), "the peak was measured");
            Assert.That(peak, Is.LessThan(OneGigabyte), $"{what}: peak memory");
        }

        static string Recording(string name) => Path.Combine(TestData.Folder, "eval", name + ".csv");

        [Test]
        public void ASparseTwoGigabyteRecording()
            => Hostile("2 GB sparse CSV", 1, "limit", "replay", Sparse("huge.csv", 2L << 30, "timestamp_s,acc_x,acc_y,acc_z\n"), "--classifier", "thr");

        [Test]
        public void FiveMillionRows()
        {
            string path = Path.Combine(folder, "rows.csv");
            using (var w = new StreamWriter(path))
            {
                w.Write("timestamp_s,acc_x,acc_y,acc_z\n");
                for (int i = 0; i < 5000000; i++) w.Write("1,0,0,9.8\n");
            }
            Hostile("5 million rows", 1, "MaxRecordingRows", "replay", path, "--classifier", "thr");
        }

        [Test]
        public void DevZeroAsRecordingModelAndBvh()
        {
            if (!File.Exists("/dev/zero")) Assert.Ignore("no /dev/zero");
            Hostile("/dev/zero as a recording", 1, "/dev/zero", "replay", "/dev/zero", "--classifier", "thr");
            Hostile("/dev/zero as a BVH", 1, "zero:1:", "from-bvh", "/dev/zero", "--out", Path.Combine(folder, "out"));
            Directory.CreateDirectory(Path.Combine(folder, "models"));
            File.Copy(Path.Combine(SamplePaths.FindModelsFolder(TestContext.CurrentContext.TestDirectory), GaitModels.CorrelationFile), Path.Combine(folder, "models", GaitModels.CorrelationFile));
            File.CreateSymbolicLink(Path.Combine(folder, "models", GaitModels.SvmFile), "/dev/zero");
            Hostile("/dev/zero as a model", 0, "using COR instead", "replay", Recording("walk_straight"), "--classifier", "svm", "--models", Path.Combine(folder, "models"));
        }

        /// <summary>
        /// A standing recording too short to put glasses on over (1 s) is left out of the generated put-ons, not an exception;
        /// the other is put on over.
        /// </summary>
        [Test]
        public void RealWorldWithAStillRecordingTooShortForAPutOn()
        {
            string data = Path.Combine(folder, "still");
            Directory.CreateDirectory(data);
            foreach (var (name, seconds) in new[] { ("p1_e001_standing", 1.0), ("p2_e001_standing", 4.0) })
            {
                var lines = new System.Collections.Generic.List<string> { "# activity=standing", "timestamp_s,acc_x,acc_y,acc_z" };
                for (int i = 0; i < seconds * 100; i++) lines.Add(string.Format(System.Globalization.CultureInfo.InvariantCulture, "{0:F2},0,0,9.80665", i * 0.01));
                File.WriteAllLines(Path.Combine(data, name + ".csv"), lines);
            }
            Hostile("a 1-s standing recording", 0, "generated over the 1 standing and sitting recordings", "realworld", "--data", data, "--classifier", "thr");
        }

        /// <summary>
        /// `realworld --put-on-draws N` generates N put-on streams over each still recording, each its own draw and its own
        /// row (the first as with one draw); 0 is refused as a usage error.
        /// </summary>
        [Test]
        public void RealWorldPutOnDrawsAreRecordingsOfTheirOwn()
        {
            string data = Path.Combine(folder, "still");
            Directory.CreateDirectory(data);
            var lines = new System.Collections.Generic.List<string> { "# activity=standing", "timestamp_s,acc_x,acc_y,acc_z" };
            for (int i = 0; i < 600; i++) lines.Add(string.Format(System.Globalization.CultureInfo.InvariantCulture, "{0:F2},{1:F3},0,9.80665", i * 0.01, 0.02 * Math.Sin(i * 0.3)));
            File.WriteAllLines(Path.Combine(data, "p1_e001_standing.csv"), lines);
            string csv = Path.Combine(folder, "draws.csv");
            Hostile("three put-on draws", 0, "3 draws each", "realworld", "--data", data, "--classifier", "thr", "--put-on-draws", "3", "--per-person", csv);
            var putOns = File.ReadAllLines(csv).Skip(1).Where(l => l.Contains(",putting_on_glasses,")).Select(l => l.Split(',')[0]).ToList();
            Assert.That(putOns, Is.EquivalentTo(new[] { "p1_e001_standing_putting_on_glasses", "p1_e001_standing_putting_on_glasses_2", "p1_e001_standing_putting_on_glasses_3" }));
            Hostile("no put-on draw", 2, "--put-on-draws is 1 to 20", "realworld", "--data", data, "--classifier", "thr", "--put-on-draws", "0");
        }

        [Test]
        public void AFifoAsARecording()
        {
            string fifo = Path.Combine(folder, "fifo.csv");
            using (var p = Process.Start(new ProcessStartInfo("mkfifo", fifo) { UseShellExecute = false }))
                p.WaitForExit();
            if (!File.Exists(fifo)) Assert.Ignore("mkfifo failed");
            Hostile("a FIFO as a recording", 1, "fifo.csv", "replay", fifo, "--classifier", "thr");
        }

        // No channels: every declared frame is an empty array, so before the frame limit this file took memory until it ran out.
        const string Skeleton = "HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 0\n CHANNELS 0\n JOINT Head\n {\n  OFFSET 0 1 0\n  End Site\n  {\n   OFFSET 0 1 0\n  }\n }\n}\n";

        [Test]
        public void ABvhDeclaringTwoBillionFrames()
        {
            string path = Path.Combine(folder, "liar.bvh");
            File.WriteAllText(path, Skeleton + "MOTION\nFrames: 2000000000\nFrame Time: 0.0333\n");
            Hostile("a 200-byte BVH declaring 2e9 frames", 1, "MaxBvhFrames", "from-bvh", path, "--out", Path.Combine(folder, "out"));
        }

        [Test]
        public void TwoHundredThousandNestedJoints()
        {
            var sb = new StringBuilder("HIERARCHY\nROOT Hips\n{\nOFFSET 0 0 0\nCHANNELS 0\n");
            for (int i = 0; i < 200000; i++) sb.Append("JOINT j\n{\nOFFSET 0 1 0\n");
            for (int i = 0; i < 200000; i++) sb.Append("}\n");
            sb.Append("}\nMOTION\nFrames: 2\nFrame Time: 0.0333\n\n");
            string path = Path.Combine(folder, "deep.bvh");
            File.WriteAllText(path, sb.ToString());
            Hostile("200,000 nested JOINTs", 1, "MaxBvhDepth", "from-bvh", path, "--out", Path.Combine(folder, "out"));
        }

        [Test]
        public void ASparseModelFolder()
        {
            string models = Path.Combine(folder, "models");
            Directory.CreateDirectory(models);
            folder = models;
            Sparse(GaitModels.ThresholdFile, 1500L << 20, "# headgait-thr v1\n");
            Sparse(GaitModels.CorrelationFile, 1500L << 20, "# headgait-cor-template v2\n");
            Sparse(GaitModels.SvmFile, 1500L << 20, ModelFile.Magic + "\n");
            Sparse(GaitModels.BlstmFile, 1500L << 20, ModelFile.Magic + "\n");
            folder = Path.GetDirectoryName(models);
            Hostile("1.5 GB sparse model files", 0, "using THR's defaults", "replay", Recording("walk_straight"), "--models", models);
        }
    }
}
