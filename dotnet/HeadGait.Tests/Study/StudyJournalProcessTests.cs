using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Threading;
using HeadGait.Study;
using HeadGait.Synthetic;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>
    /// The study journal across real processes (the child is HeadGait.Tests.JournalChild): a second process is refused
    /// while one holds a participant, two processes racing for one id never both get it, and a process killed while it
    /// answers loses nothing it acknowledged and leaves no lock behind. Part of the journal campaign (HEADGAIT_LONG_CAMPAIGN=1: 10x).
    /// </summary>
    public class StudyJournalProcessTests
    {
        static readonly int Scale = Environment.GetEnvironmentVariable("HEADGAIT_LONG_CAMPAIGN") == "1" ? 10 : 1;
        const string Id = "P07";
        string folder;
        readonly List<Process> started = new List<Process>();

        [SetUp]
        public void MakeFolder() => folder = Path.Combine(Path.GetTempPath(), "headgait-processes-" + Guid.NewGuid().ToString("N"));

        [TearDown]
        public void CleanUp()
        {
            foreach (var p in started)
            {
                try
                {
                    if (!p.HasExited) p.Kill();
                    p.WaitForExit(5000);
                }
                catch (InvalidOperationException)
                {
                }
                p.Dispose();
            }
            started.Clear();
            if (Directory.Exists(folder)) Directory.Delete(folder, true);
        }

        Process Child(string mode)
        {
            string dll = Path.Combine(TestContext.CurrentContext.TestDirectory, "HeadGait.Tests.JournalChild.dll");
            Assert.That(File.Exists(dll), Is.True, dll);
            var info = new ProcessStartInfo(Environment.GetEnvironmentVariable("DOTNET_HOST_PATH") ?? "dotnet", $"\"{dll}\" {mode} \"{folder}\" {Id}")
            {
                UseShellExecute = false,
                RedirectStandardInput = true,
                RedirectStandardOutput = true,
                RedirectStandardError = true,
            };
            var p = Process.Start(info);
            started.Add(p);
            return p;
        }

        static void Release(Process holder)
        {
            holder.StandardInput.Close();
            Assert.That(holder.WaitForExit(20000), Is.True, "the holder exits once its input closes");
        }

        [Test]
        public void AnotherProcessIsRefusedWhileThisOneHoldsTheIdAndGetsItAfter()
        {
            var op = new StudyOperator(folder, new StudyConfig());
            Assert.That(op.Open(Id), Is.True, op.Error);
            var child = Child("hold");
            string line = child.StandardOutput.ReadLine();
            Assert.That(line, Does.StartWith("refused"));
            Assert.That(line, Does.Contain(Id + " is in use by process " + Process.GetCurrentProcess().Id).And.Contain("since"));
            child.WaitForExit(20000);
            op.Dispose();
            var again = Child("hold");
            Assert.That(again.StandardOutput.ReadLine(), Is.EqualTo("opened"));
            var second = new StudyOperator(folder, new StudyConfig());
            Assert.That(second.Open(Id), Is.False);
            Assert.That(second.Error, Does.Contain("in use by process " + again.Id));
            Release(again);
            Assert.That(second.Open(Id), Is.True, second.Error);
            second.Dispose();
        }

        /// <summary>
        /// Unity's runtimes on Android and other Unix players check file sharing only within their own process, so there a
        /// second process's open of the lock file succeeds; the record lock on its first byte is what refuses it. The child
        /// opens the lock file sharing it, as such a runtime would, and asks for that lock: refused while this process holds
        /// the participant, granted once it closed it.
        /// </summary>
        [Test]
        public void AnotherProcessThatGetsPastTheSharingRuleIsRefusedTheRecordLock()
        {
            if (OperatingSystem.IsMacOS()) Assert.Ignore(".NET on macOS has no record locks");
            var op = new StudyOperator(folder, new StudyConfig());
            Assert.That(op.Open(Id), Is.True, op.Error);
            var child = Child("record");
            Assert.That(child.StandardOutput.ReadLine(), Does.StartWith("refused"), "the record lock is held");
            child.WaitForExit(20000);
            op.Dispose();
            var after = Child("record");
            Assert.That(after.StandardOutput.ReadLine(), Is.EqualTo("locked"), "released with the journal");
            after.WaitForExit(20000);
        }

        [Test]
        public void TwoProcessesRacingForOneIdNeverBothGetIt()
        {
            int rounds = 8 * Scale, both = 0, refused = 0, other = 0;
            for (int round = 0; round < rounds; round++)
            {
                var a = Child("hold");
                var b = Child("hold");
                string la = a.StandardOutput.ReadLine(), lb = b.StandardOutput.ReadLine();
                if (la == "opened" && lb == "opened") both++;
                foreach (var l in new[] { la, lb })
                    if (l != "opened")
                    {
                        if (l != null && l.Contains("in use")) refused++;
                        else other++;
                    }
                Release(a);
                Release(b);
            }
            TestContext.Progress.WriteLine($"study journal campaign, two processes racing for one id (x{Scale}): rounds {rounds}, refused as in use {refused}, both opened {both}, other errors {other}");
            Assert.That((both, other), Is.EqualTo((0, 0)));
            Assert.That(refused, Is.EqualTo(rounds));
        }

        [Test]
        public void AProcessKilledWhileAnsweringLosesNothingAcknowledgedAndLeavesNoLock()
        {
            int kills = 5 * Scale, lost = 0, changed = 0, blocked = 0, unreadable = 0, acknowledged = 0;
            var random = new DeterministicRandom(38);
            for (int k = 0; k < kills; k++)
            {
                var child = Child("answer");
                Assert.That(child.StandardOutput.ReadLine(), Is.EqualTo("opened"));
                int acks = 0, target = 5 + (int)(random.NextDouble() * 60);
                string line;
                while (acks < target && (line = child.StandardOutput.ReadLine()) != null)
                    if (line.StartsWith("ack ", StringComparison.Ordinal)) acks = int.Parse(line.Substring(4));
                child.Kill();
                // Acknowledgements already printed but not yet read count too: read the rest of the output.
                string rest = child.StandardOutput.ReadToEnd();
                foreach (var l in rest.Split('\n'))
                    if (l.StartsWith("ack ", StringComparison.Ordinal)) acks = int.Parse(l.Substring(4).Trim());
                child.WaitForExit(20000);
                acknowledged += acks;
                StudySession s;
                try
                {
                    s = StudySession.Resume(folder, Id);
                }
                catch (StudyStorageException e)
                {
                    TestContext.Out.WriteLine($"kill {k}: {e.Message}");
                    if (e.Message.Contains("in use")) blocked++;
                    else unreadable++;
                    continue;
                }
                using (s)
                {
                    var answers = s.AnswersOf(0);
                    for (int n = 1; n <= acks; n++)
                    {
                        if (!answers.TryGetValue("a" + n, out var v)) lost++;
                        else if (v != "value " + n) changed++;
                    }
                    if (s.Damage.Count > 0) unreadable++;
                }
            }
            TestContext.Progress.WriteLine($"study journal campaign, processes killed while answering (x{Scale}): kills {kills}, answers acknowledged {acknowledged}, " +
                                           $"acknowledged answers lost {lost}, answers changed without a warning {changed}, ids blocked {blocked}, journals unreadable {unreadable}");
            Assert.That((lost, changed, blocked, unreadable), Is.EqualTo((0, 0, 0, 0)));
        }
    }
}
