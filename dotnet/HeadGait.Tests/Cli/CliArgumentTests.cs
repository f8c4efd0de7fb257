extern alias cli;

using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Text;
using NUnit.Framework;
using CliProgram = cli::HeadGait.Cli.Program;

namespace HeadGait.Tests.Cli
{
    /// <summary>
    /// The command line's exit-code rule, table-driven through its entry point in-process: 0 success, 1 a runtime or data
    /// error (nothing to do included), 2 usage; every missing, empty, negative, NaN, huge and garbage option value is refused
    /// before any work, and nothing prints a stack trace. Hostile files run in a child process whose peak memory is measured.
    /// </summary>
    [NonParallelizable]
    public class CliArgumentTests
    {
        static string folder;
        static string Good => Path.Combine(folder, "data", "walk.csv");
        static string Data => Path.Combine(folder, "data");
        static string Missing => Path.Combine(folder, "no-such-folder");

        [OneTimeSetUp]
        public void MakeFiles()
        {
            folder = Path.Combine(Path.GetTempPath(), "headgait-cli-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(Path.Combine(folder, "data"));
            // A short labelled walk (3 s of the sample recording), so a command that does run finishes at once.
            var lines = File.ReadAllLines(Path.Combine(TestData.Folder, "eval", "walk_straight.csv"));
            File.WriteAllLines(Good, lines.Take(320));
            var commas = new StringBuilder("timestamp_s,acc_x,acc_y,acc_z\n");
            for (int i = 0; i < 200; i++) commas.Append($"{i / 100},{i % 100:00},0,01,0,02,9,81\n");
            File.WriteAllText(Path.Combine(folder, "commas.csv"), commas.ToString());
            var nan = new StringBuilder(PoseCsv.Magic + "\n" + string.Join(",", PoseCsv.RequiredColumns) + "\n");
            for (int i = 0; i < 200; i++) nan.Append("NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN\n");
            File.WriteAllText(Path.Combine(folder, "nan-pose.csv"), nan.ToString());
            File.WriteAllText(Path.Combine(folder, "no-header.csv"), "hello\n");
        }

        [OneTimeTearDown]
        public void RemoveFiles() => Directory.Delete(folder, true);

        static (int code, string output, string error) Run(params string[] args)
        {
            var outWriter = new StringWriter();
            var errWriter = new StringWriter();
            var oldOut = Console.Out;
            var oldErr = Console.Error;
            Console.SetOut(outWriter);
            Console.SetError(errWriter);
            try
            {
                int code = CliProgram.Main(args);
                return (code, outWriter.ToString(), errWriter.ToString());
            }
            finally
            {
                Console.SetOut(oldOut);
                Console.SetError(oldErr);
            }
        }

        /// <summary>Every case: the arguments (FILE, DATA, MISSING stand for the generated files) and the exit code the rule gives.</summary>
        static IEnumerable<TestCaseData> Cases()
        {
            TestCaseData Case(int code, params string[] args) => new TestCaseData(args, code).SetName($"{code} <- {string.Join(" ", args.Select(a => a.Length == 0 ? "''" : a))}");
            yield return Case(2);
            yield return Case(2, "no-such-command");
            yield return Case(0, "--help");
            yield return Case(0, "replay", "FILE", "--classifier", "thr");
            // replay
            yield return Case(2, "replay", "FILE", "--classifier", ",");
            yield return Case(2, "replay", "FILE", "--classifier", "");
            yield return Case(2, "replay", "FILE", "--classifier");
            yield return Case(2, "replay", "FILE", "--classifier", "garbage");
            yield return Case(2, "replay", "FILE", "--models", "MISSING");
            yield return Case(2, "replay", "FILE", "--models", "");
            yield return Case(2, "replay", "FILE", "--models");
            yield return Case(2, "replay", "FILE", "--trace", "");
            yield return Case(2, "replay", "MISSING");
            yield return Case(2, "replay", "FILE", "--strict", "garbage");
            yield return Case(1, "replay", "COMMAS");
            yield return Case(1, "replay", "NANPOSE");
            yield return Case(1, "replay", "NOHEADER");
            // benchmark
            yield return Case(2, "benchmark");
            yield return Case(2, "benchmark", "--data");
            yield return Case(2, "benchmark", "--data", "MISSING");
            yield return Case(2, "benchmark", "--data", "DATA", "--cv", "garbage");
            yield return Case(2, "benchmark", "--data", "DATA", "--cv", "");
            yield return Case(2, "benchmark", "--data", "DATA", "--cv", ",");
            yield return Case(2, "benchmark", "--data", "DATA", "--cv");
            yield return Case(2, "benchmark", "--data", "DATA", "--augment", "-1");
            yield return Case(2, "benchmark", "--data", "DATA", "--augment", "2000000000");
            yield return Case(2, "benchmark", "--data", "DATA", "--augment", "99999999999999");
            yield return Case(2, "benchmark", "--data", "DATA", "--augment", "NaN");
            yield return Case(2, "benchmark", "--data", "DATA", "--augment", "");
            yield return Case(2, "benchmark", "--data", "DATA", "--sensor-rate", "NaN");
            yield return Case(2, "benchmark", "--data", "DATA", "--sensor-rate", "-5");
            yield return Case(2, "benchmark", "--data", "DATA", "--sensor-rate", "1e300");
            yield return Case(2, "benchmark", "--data", "DATA", "--sensor-rate", "garbage");
            yield return Case(2, "benchmark", "--data", "DATA", "--models", "MISSING");
            yield return Case(2, "benchmark", "--data", "DATA", "--classifier", ",");
            yield return Case(2, "benchmark", "--data", "DATA", "--per-recording", "");
            // train
            yield return Case(2, "train");
            yield return Case(2, "train", "--data", "MISSING");
            yield return Case(2, "train", "--data", "DATA", "--stride", "0");
            yield return Case(2, "train", "--data", "DATA", "--stride", "-1");
            yield return Case(2, "train", "--data", "DATA", "--stride", "2000000000");
            yield return Case(2, "train", "--data", "DATA", "--stride", "garbage");
            yield return Case(2, "train", "--data", "DATA", "--stride");
            yield return Case(2, "train", "--data", "DATA", "--augment", "-1");
            yield return Case(2, "train", "--data", "DATA", "--augment", "2000000000");
            yield return Case(2, "train", "--data", "DATA", "--label-lead", "NaN");
            yield return Case(2, "train", "--data", "DATA", "--label-lead", "1e300");
            yield return Case(2, "train", "--data", "DATA", "--label-lead", "-1e300");
            yield return Case(2, "train", "--data", "DATA", "--label-lead", "garbage");
            yield return Case(2, "train", "--data", "DATA", "--cv", "");
            yield return Case(2, "train", "--data", "DATA", "--cv", "garbage");
            yield return Case(2, "train", "--data", "DATA", "--learned", "garbage");
            yield return Case(2, "train", "--data", "DATA", "--learned", "");
            yield return Case(2, "train", "--data", "DATA", "--out", "");
            yield return Case(2, "train", "--data", "DATA", "--cv-only");
            // from-bvh
            yield return Case(2, "from-bvh");
            yield return Case(2, "from-bvh", "MISSING", "--out", "OUT");
            yield return Case(2, "from-bvh", "DATA", "--out", "OUT");
            yield return Case(2, "from-bvh", "DATA", "--out");
            yield return Case(2, "from-bvh", "DATA", "--out", "OUT", "--pose", "garbage");
            yield return Case(2, "from-bvh", "DATA", "--out", "OUT", "--pose", "NaN");
            yield return Case(2, "from-bvh", "DATA", "--out", "OUT", "--pose", "-72");
            yield return Case(2, "from-bvh", "DATA", "--out", "OUT", "--pose", "1e300");
            yield return Case(2, "from-bvh", "DATA", "--out", "OUT", "--pose", ",");
            // animator-check
            yield return Case(2, "animator-check", "FILE", "--fps", "garbage");
            yield return Case(2, "animator-check", "FILE", "--fps", "0");
            yield return Case(2, "animator-check", "FILE", "--fps", "NaN");
            yield return Case(2, "animator-check", "FILE", "--fps", "1e300");
            yield return Case(2, "animator-check", "FILE", "--fps", ",");
            yield return Case(2, "from-bvh", "DATA", "--out", "OUT", "--units", "garbage");
            yield return Case(2, "from-bvh", "DATA", "--out", "OUT", "--up", "");
            yield return Case(2, "from-bvh", "DATA", "--out", "OUT", "--seed", "-1");
            yield return Case(2, "from-bvh", "DATA", "--out", "OUT", "--seed", "99999999999999999999999");
            // study, clips, generate
            yield return Case(2, "study", "generate", "OUT", "--participants", "-1");
            yield return Case(2, "study", "generate", "OUT", "--participants", "2000000000");
            yield return Case(2, "study", "generate", "OUT", "--participants", "NaN");
            yield return Case(2, "study", "generate", "OUT", "--participants", "");
            yield return Case(2, "study", "generate", "OUT", "--seed", "garbage");
            yield return Case(2, "study", "summarize");
            yield return Case(2, "clips", "--template", "MISSING");
            // calibrate benchmark / glasses
            yield return Case(2, "calibrate", "benchmark", "--data", "DATA", "--bvh", "DATA", "--walk-seconds", "-1");
            yield return Case(2, "calibrate", "benchmark", "--data", "DATA", "--bvh", "DATA", "--walk-seconds", "NaN");
            yield return Case(2, "calibrate", "benchmark", "--data", "DATA", "--bvh", "DATA", "--cv-models", "MISSING");
            yield return Case(2, "calibrate", "benchmark", "--data", "DATA", "--bvh", "DATA", "--adapt", "garbage");
            yield return Case(2, "calibrate", "benchmark", "--data", "DATA", "--bvh", "DATA", "--adapt", "prior=-1");
            yield return Case(2, "calibrate", "glasses", "--data", "DATA", "--adapt", "gate-cap=x");
            yield return Case(2, "generate", "--out");
            // Empty values anywhere are usage errors (before: an empty --out wrote into the working folder).
            yield return Case(2, "generate", "--out", "");
            yield return Case(2, "generate", "--out", " ");
            yield return Case(2, "from-bvh", "DATA", "--out", "");
            yield return Case(2, "study", "generate", "");
            yield return Case(2, "replay", "");
        }

        /// <summary>Regression: an empty frame-rate list ran nothing (animator-check exited 0 having checked no frame rate;
        /// from-bvh --pose wrote acceleration recordings as if --pose were left out).</summary>
        [Test]
        public void AnEmptyFrameRateListIsAUsageErrorNamingTheOption()
        {
            string bvh = Path.Combine(folder, "not-a.bvh");
            File.WriteAllText(bvh, "hello\n");
            foreach (var args in new[]
            {
                new[] { "animator-check", Good, "--fps", "," },
                new[] { "animator-check", Good, "--fps", ", ," },
                new[] { "from-bvh", bvh, "--out", Path.Combine(folder, "out"), "--pose", "," },
                new[] { "from-bvh", bvh, "--out", Path.Combine(folder, "out"), "--pose", ", ," },
            })
            {
                var (code, _, error) = Run(args);
                Assert.That(code, Is.EqualTo(2), string.Join(" ", args) + ": " + error);
                Assert.That(error, Does.Contain(args[args.Length - 2] + " names no frame rate"), string.Join(" ", args));
            }
            var (wholeCode, _, wholeError) = Run("animator-check", Good, "--fps", "72.5");
            Assert.That(wholeCode, Is.EqualTo(2));
            Assert.That(wholeError, Does.Contain("--fps: '72.5' is not a whole frame rate"));
        }

        [TestCaseSource(nameof(Cases))]
        public void ExitCodesFollowTheRuleAndNothingPrintsAStackTrace(string[] args, int expected)
        {
            var real = args.Select(a => a == "FILE" ? Good : a == "DATA" ? Data : a == "MISSING" ? Missing : a == "OUT" ? Path.Combine(folder, "out")
                : a == "COMMAS" ? Path.Combine(folder, "commas.csv") : a == "NANPOSE" ? Path.Combine(folder, "nan-pose.csv")
                : a == "NOHEADER" ? Path.Combine(folder, "no-header.csv") : a).ToArray();
            var (code, output, error) = Run(real);
            TestContext.WriteLine($"exit {code}\n{error}");
            Assert.That(error + output, Does.Not.Contain("   at "), "no stack trace");
            Assert.That(error + output, Does.Not.Contain("Unhandled exception"));
            Assert.That(code, Is.EqualTo(expected), error);
            if (code != 0) Assert.That(error, Does.StartWith("error: ").Or.Contain("\nerror: ").Or.StartWith("Required command"), "one clear error on standard error");
        }
    }
}
