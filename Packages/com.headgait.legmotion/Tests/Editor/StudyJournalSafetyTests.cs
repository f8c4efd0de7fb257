using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text;
using HeadGait.Study;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>Regression tests for the study journal as the operator's only copy of a participant's answers (issue 34, items 1-5).</summary>
    public class StudyJournalSafetyTests
    {
        string folder;

        [SetUp]
        public void MakeFolder() => folder = Path.Combine(Path.GetTempPath(), "headgait-journal-" + Guid.NewGuid().ToString("N"));

        [TearDown]
        public void RemoveFolder()
        {
            if (Directory.Exists(folder)) Directory.Delete(folder, true);
        }

        static int[] Ssq(int seed) => Enumerable.Range(0, SimulatorSicknessQuestionnaire.ItemCount).Select(i => (seed * 7 + i * 3) % 4).ToArray();

        static void Close(object session) => (session as IDisposable)?.Dispose();

        /// <summary>A whole participant through every step, closed at the end.</summary>
        void Complete(string id)
        {
            var s = StudySession.Start(folder, id, new StudyConfig());
            while (s.Current.Kind != StudyStepKind.Done)
            {
                if (s.Current.Kind == StudyStepKind.Demographics) s.Answer("age", "31");
                if (s.Current.IsSsq) s.AnswerSsq(Ssq(s.Current.Index));
                s.CompleteStep();
            }
            Close(s);
        }

        [Test]
        public void ASecondOperatorOnTheSameIdIsRefusedWhileTheFirstHasItOpen()
        {
            var first = new StudyOperator(folder, new StudyConfig());
            Assert.That(first.Open("P07"), Is.True, first.Error);
            first.SetDemographic("age", "30");
            var second = new StudyOperator(folder, new StudyConfig());
            Assert.That(second.Open("P07"), Is.False, "two writers on one participant");
            Assert.That(second.Error, Does.Contain("P07").And.Contain("in use").And.Contain("since"));
            Assert.That(second.Session, Is.Null);
            Assert.That(first.SetDemographic("gender", "female"), Is.True, first.Error);
            Assert.That(first.Do(OperatorCommand.Abort), Is.True);
            Assert.That(second.Open("p07"), Is.True, "free again once the first closed it: " + second.Error);
            Assert.That(second.Session.AnswersOf(0).Count, Is.EqualTo(2));
        }

        /// <summary>
        /// The journal's files hold no write buffer: a line is with the operating system at its write. With a buffer, a line
        /// a full disk refused stayed in it (the journal's cut-back flushed first and failed again), and closing the journal
        /// once space was freed wrote the whole checksummed line the operator had been told was NOT saved.
        /// </summary>
        [Test]
        public void AJournalLineIsWithTheOperatingSystemAtItsWriteNotLeftInABuffer()
        {
            Directory.CreateDirectory(folder);
            string path = Path.Combine(folder, "buffer-check.txt");
            var line = Encoding.UTF8.GetBytes("1\t2026-12-07T00:00:00.000Z\tanswer\t0\tage\t31\n");
            using (var writer = JournalFileAccess.Default.Open(path, FileMode.Create, FileAccess.ReadWrite, FileShare.Read))
            {
                writer.Write(line, 0, line.Length);
                using (var reader = new FileStream(path, FileMode.Open, FileAccess.Read, FileShare.ReadWrite))
                    Assert.That(reader.Length, Is.EqualTo(line.Length), "the line reached the file at its write, before any flush");
            }
        }

        [Test]
        public void AZeroByteOrHalfWrittenJournalFromACrashAtCreationDoesNotBlockTheId()
        {
            Directory.CreateDirectory(folder);
            File.WriteAllBytes(Path.Combine(folder, "P03" + StudyJournal.Extension), new byte[0]);
            File.WriteAllText(Path.Combine(folder, "P04" + StudyJournal.Extension), "# headgait-stu");
            foreach (var id in new[] { "P03", "P04" })
            {
                var op = new StudyOperator(folder, new StudyConfig());
                Assert.That(op.Open(id), Is.True, op.Error);
                Assert.That(op.Notice, Does.StartWith("Started participant " + id));
                Assert.That(op.SetDemographic("age", "22"), Is.True, op.Error);
                Assert.That(op.Do(OperatorCommand.Abort), Is.True);
                var r = StudySession.Resume(folder, id, readOnly: true);
                Assert.That(r.AnswersOf(0)["age"], Is.EqualTo("22"));
            }
        }

        [Test]
        public void ACrashBetweenAnSsqAnswerAndItsDoneLineShowsTheSavedSsqAndKeepsIt()
        {
            var s = StudySession.Start(folder, "P05", new StudyConfig());
            s.Answer("age", "40");
            s.CompleteStep();
            s.AnswerSsq(Ssq(3));
            Close(s); // the process died before the "done" line
            var op = new StudyOperator(folder, new StudyConfig());
            Assert.That(op.Open("P05"), Is.True, op.Error);
            Assert.That(op.Current.Value.Kind, Is.EqualTo(StudyStepKind.PreExposureSsq));
            Assert.That(op.Ssq.IsComplete, Is.True, "the saved SSQ is shown as saved, not as an empty form");
            Assert.That(op.Ssq.Ratings(), Is.EqualTo(Ssq(3)));
            Assert.That(op.Notice, Does.Contain("SSQ").And.Contain("saved"));
            Assert.That(op.Do(OperatorCommand.Next), Is.True, op.Error);
            Assert.That(op.Do(OperatorCommand.Abort), Is.True);
            var journal = StudyJournal.Open(folder, "P05", false);
            Assert.That(journal.Entries.Count(e => e.Kind == "answer" && e.Key == "ssq"), Is.EqualTo(1), "going on does not save it again");
            Assert.That(StudySession.Resume(folder, "P05", readOnly: true).Current.Kind, Is.EqualTo(StudyStepKind.BaselineWalk));
        }

        [Test]
        public void ADamagedSsqValueIsReportedNotDroppedSilently()
        {
            Complete("P01");
            string path = Path.Combine(folder, "P01" + StudyJournal.Extension);
            var lines = File.ReadAllLines(path).ToList();
            int ssq = lines.FindIndex(l => l.Contains("\tssq\t"));
            int comma = lines[ssq].IndexOf(',');
            lines[ssq] = lines[ssq].Substring(0, comma) + "$" + lines[ssq].Substring(comma + 1);
            File.WriteAllText(path, string.Join("\n", lines) + "\n");
            var results = StudyResults.Load(folder);
            Assert.That(results.Problems, Has.Some.Contains("P01"), "a damaged value is reported");
            Assert.That(results.Participants.Single().PreExposure.HasValue, Is.False, "and not used");
        }

        [Test]
        public void AJournalWithWindowsLineEndsReadsTheSame()
        {
            Complete("P02");
            var before = StudyResults.Load(folder).Participants.Single();
            string path = Path.Combine(folder, "P02" + StudyJournal.Extension);
            File.WriteAllText(path, File.ReadAllText(path).Replace("\n", "\r\n"));
            var results = StudyResults.Load(folder);
            Assert.That(results.Problems, Is.Empty);
            var after = results.Participants.Single();
            Assert.That(after.Conditions.Keys, Is.EquivalentTo(before.Conditions.Keys));
            foreach (var c in before.Conditions.Keys) Assert.That(after.Conditions[c].Total, Is.EqualTo(before.Conditions[c].Total));
            Assert.That(after.PreExposure.Value.Total, Is.EqualTo(before.PreExposure.Value.Total));
        }

        [TestCase("CON")]
        [TestCase("nul")]
        [TestCase("Com1")]
        [TestCase("LPT9")]
        [TestCase("aux")]
        [TestCase("PRN")]
        [TestCase("--help")]
        [TestCase("-P01")]
        public void ReservedDeviceNamesAndOptionLikeIdsAreRefused(string id)
        {
            Assert.That(() => ParticipantIds.Validate(id), Throws.ArgumentException);
            var op = new StudyOperator(folder, new StudyConfig());
            Assert.That(op.Open(id), Is.False);
            Assert.That(Directory.Exists(folder), Is.False);
        }

        [Test]
        public void IdsDifferingOnlyInCaseAreOneParticipant()
        {
            var s = StudySession.Start(folder, "p01", new StudyConfig());
            s.Answer("age", "33");
            Close(s);
            var op = new StudyOperator(folder, new StudyConfig());
            Assert.That(op.Open("P01"), Is.True, op.Error);
            Assert.That(op.Notice, Does.StartWith("Resumed participant P01"));
            Assert.That(op.Session.AnswersOf(0)["age"], Is.EqualTo("33"));
            Assert.That(() => StudySession.Start(folder, "P01", new StudyConfig()), Throws.InstanceOf<StudyStorageException>());
        }
        [Test]
        public void AVersion1JournalStillReadsAndResumesWithCheckedLines()
        {
            // As the previous version wrote it: no checksums, a lower-case id, CRLF from a Windows copy.
            Directory.CreateDirectory(folder);
            string path = Path.Combine(folder, "p11" + StudyJournal.Extension);
            string T(int n) => $"2026-11-22T10:00:{n:00}.000Z";
            var lines = new List<string>
            {
                StudyJournal.MagicV1,
                $"1\t{T(1)}\tsession\t-1\tconditions\tno-avatar,block-avatar,humanoid-avatar",
                $"2\t{T(2)}\tsession\t-1\tpath_length_m\t16",
                $"3\t{T(3)}\tsession\t-1\thumanoid_classifier\tcor",
                $"4\t{T(4)}\tsession\t-1\trest_s\t120",
                $"5\t{T(5)}\tsession\t-1\torder\thumanoid-avatar,no-avatar,block-avatar",
                $"6\t{T(6)}\tanswer\t0\tage\t27",
                $"7\t{T(7)}\tdone\t0\t\t",
                $"8\t{T(8)}\tanswer\t1\tssq\t{string.Join(",", Ssq(1))}",
            };
            File.WriteAllText(path, string.Join("\r\n", lines) + "\r\n");
            var op = new StudyOperator(folder, new StudyConfig());
            Assert.That(op.Open("P11"), Is.True, op.Error);
            Assert.That(op.Session.Participant, Is.EqualTo("P11"));
            Assert.That(op.Session.JournalPath, Is.EqualTo(path), "the older lower-case file is found, not a second one made");
            Assert.That(op.Ssq.Ratings(), Is.EqualTo(Ssq(1)));
            Assert.That(op.Session.Steps.Where(st => st.Kind == StudyStepKind.Trial).Select(st => st.Condition),
                Is.EqualTo(new[] { "humanoid-avatar", "no-avatar", "block-avatar" }), "the saved order, whatever the id");
            Assert.That(op.Do(OperatorCommand.Next), Is.True, op.Error);
            op.Dispose();
            var text = File.ReadAllText(path);
            Assert.That(text, Does.StartWith(StudyJournal.MagicV1));
            Assert.That(text.Split('\n').Last(l => l.Length > 0), Does.Match(@"\tdone\t1\t\t\t\d+:[0-9a-f]{8}$"), "new lines carry checksums");
            var results = StudyResults.Load(folder);
            Assert.That(results.Participants.Single().PreExposure.Value.Total, Is.EqualTo(SimulatorSicknessQuestionnaire.Score(Ssq(1)).Total));
            Assert.That(results.Problems, Has.Some.Contains("v1"));
        }

        [Test]
        public void AnAbsurdlyLargeJournalIsRefusedNamingTheLimit()
        {
            Directory.CreateDirectory(folder);
            string path = Path.Combine(folder, "P12" + StudyJournal.Extension);
            using (var fs = new FileStream(path, FileMode.CreateNew)) fs.SetLength(StudyJournal.MaxBytes + 1);
            var results = StudyResults.Load(folder);
            Assert.That(results.Participants, Is.Empty);
            Assert.That(results.Problems.Single(), Does.Contain(path).And.Contain(StudyJournal.MaxBytes.ToString()));
            var op = new StudyOperator(folder, new StudyConfig());
            Assert.That(op.Open("P12"), Is.False);
            Assert.That(op.Error, Does.Contain(path));
        }
    }
}
