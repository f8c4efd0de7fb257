using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text;
using HeadGait.Study;
using NUnit.Framework;

namespace HeadGait.Tests
{
    public class SsqTests
    {
        static int[] Ratings(params (SsqItem item, int rating)[] given)
        {
            var r = new int[SimulatorSicknessQuestionnaire.ItemCount];
            foreach (var g in given) r[(int)g.item] = g.rating;
            return r;
        }

        [Test]
        public void NoSymptomsScoreZero()
        {
            var s = SimulatorSicknessQuestionnaire.Score(new int[16]);
            Assert.That(s.Total, Is.EqualTo(0));
            Assert.That(s.Nausea + s.Oculomotor + s.Disorientation, Is.EqualTo(0));
        }

        [Test]
        public void AHandWorkedExample()
        {
            // General discomfort slight (N, O), nausea moderate (N, D), headache severe (O), vertigo slight (D):
            // raw N = 1 + 2 = 3, raw O = 1 + 3 = 4, raw D = 2 + 1 = 3.
            var s = SimulatorSicknessQuestionnaire.Score(Ratings((SsqItem.GeneralDiscomfort, 1), (SsqItem.Nausea, 2), (SsqItem.Headache, 3), (SsqItem.Vertigo, 1)));
            Assert.That(s.RawNausea, Is.EqualTo(3));
            Assert.That(s.RawOculomotor, Is.EqualTo(4));
            Assert.That(s.RawDisorientation, Is.EqualTo(3));
            Assert.That(s.Nausea, Is.EqualTo(28.62).Within(1e-9));
            Assert.That(s.Oculomotor, Is.EqualTo(30.32).Within(1e-9));
            Assert.That(s.Disorientation, Is.EqualTo(41.76).Within(1e-9));
            Assert.That(s.Total, Is.EqualTo(37.4).Within(1e-9));
        }

        [Test]
        public void EverySymptomSevereGivesThePublishedMaxima()
        {
            // Seven items load on each subscale: raw 21 each. N 200.34, O 159.18, D 292.32, Total 235.62.
            var s = SimulatorSicknessQuestionnaire.Score(Enumerable.Repeat(3, 16).ToArray());
            Assert.That(s.Nausea, Is.EqualTo(200.34).Within(1e-9));
            Assert.That(s.Oculomotor, Is.EqualTo(159.18).Within(1e-9));
            Assert.That(s.Disorientation, Is.EqualTo(292.32).Within(1e-9));
            Assert.That(s.Total, Is.EqualTo(235.62).Within(1e-9));
        }

        [Test]
        public void ChangeIsPostMinusPre()
        {
            var pre = SimulatorSicknessQuestionnaire.Score(Ratings((SsqItem.Fatigue, 1)));
            var post = SimulatorSicknessQuestionnaire.Score(Ratings((SsqItem.Fatigue, 2), (SsqItem.DizzyEyesOpen, 2)));
            var change = post.Minus(pre);
            Assert.That(change.Oculomotor, Is.EqualTo(7.58).Within(1e-9));
            Assert.That(change.Disorientation, Is.EqualTo(27.84).Within(1e-9));
            Assert.That(change.Total, Is.EqualTo(3 * 3.74).Within(1e-9));
        }

        [Test]
        public void BadRatingsNameTheItem()
        {
            Assert.That(() => SimulatorSicknessQuestionnaire.Score(new int[15]), Throws.ArgumentException.With.Message.Contains("16"));
            var r = new int[16];
            r[(int)SsqItem.Burping] = 4;
            Assert.That(() => SimulatorSicknessQuestionnaire.Score(r), Throws.ArgumentException.With.Message.Contains("Burping"));
        }
    }

    public class CounterbalancingTests
    {
        [TestCase(2)]
        [TestCase(3)]
        [TestCase(4)]
        [TestCase(5)]
        public void EveryConditionTakesEveryPositionAndFollowsEveryOtherEquallyOften(int n)
        {
            var rows = Counterbalancing.WilliamsRows(n);
            Assert.That(rows.Length, Is.EqualTo(n % 2 == 0 ? n : 2 * n));
            var position = new int[n, n];
            var follows = new int[n, n];
            foreach (var row in rows)
            {
                Assert.That(row.OrderBy(x => x), Is.EqualTo(Enumerable.Range(0, n)), "each row is a permutation");
                for (int i = 0; i < n; i++)
                {
                    position[row[i], i]++;
                    if (i > 0) follows[row[i - 1], row[i]]++;
                }
            }
            for (int a = 0; a < n; a++)
            for (int b = 0; b < n; b++)
            {
                Assert.That(position[a, b], Is.EqualTo(rows.Length / n));
                if (a != b) Assert.That(follows[a, b], Is.EqualTo(rows.Length / n));
            }
        }

        [Test]
        public void ConsecutiveParticipantsWalkThroughTheRowsAndIdsAreStable()
        {
            var rows = Counterbalancing.WilliamsRows(3);
            for (int p = 1; p <= 12; p++)
                Assert.That(Counterbalancing.OrderFor($"P{p:00}", 3), Is.EqualTo(rows[(p - 1) % 6]));
            Assert.That(Counterbalancing.OrderFor("alice", 3), Is.EqualTo(Counterbalancing.OrderFor("alice", 3)));
        }
    }

    public class StudySessionTests
    {
        string folder;

        [SetUp]
        public void MakeFolder() => folder = Path.Combine(Path.GetTempPath(), "headgait-study-" + Guid.NewGuid().ToString("N"));

        [TearDown]
        public void RemoveFolder()
        {
            if (!Directory.Exists(folder)) return;
            foreach (var f in Directory.GetFiles(folder)) File.SetAttributes(f, FileAttributes.Normal);
            Directory.Delete(folder, true);
        }

        static int[] Ssq(int seed)
        {
            var r = new int[16];
            for (int i = 0; i < 16; i++) r[i] = (seed * 7 + i * 3) % 4;
            return r;
        }

        /// <summary>Runs the whole protocol, calling back after every recorded action with the number of actions so far.</summary>
        static void RunAll(StudySession s, Action<int> afterAction)
        {
            int actions = 0;
            while (s.Current.Kind != StudyStepKind.Done)
            {
                var step = s.Current;
                if (step.Kind == StudyStepKind.Demographics)
                {
                    s.Answer("age", "31");
                    afterAction(++actions);
                    s.Answer("gender", "female");
                    afterAction(++actions);
                }
                if (step.IsSsq)
                {
                    s.AnswerSsq(Ssq(step.Index));
                    afterAction(++actions);
                }
                if (step.Kind == StudyStepKind.Trial)
                {
                    s.Event("trial-start", step.Condition);
                    afterAction(++actions);
                }
                s.CompleteStep();
                afterAction(++actions);
            }
        }

        [Test]
        public void StepsFollowThePaperAndTheParticipantsOrder()
        {
            var steps = StudyProtocol.StepsFor("P02", new StudyConfig());
            var kinds = steps.Select(s => s.Kind).ToList();
            Assert.That(kinds.Take(4), Is.EqualTo(new[] { StudyStepKind.Demographics, StudyStepKind.PreExposureSsq, StudyStepKind.BaselineWalk, StudyStepKind.BaselineSsq }));
            var trials = steps.Where(s => s.Kind == StudyStepKind.Trial).Select(s => s.Condition).ToList();
            var order = Counterbalancing.OrderFor("P02", 3).Select(i => new StudyConfig().Conditions[i]);
            Assert.That(trials, Is.EqualTo(order));
            Assert.That(kinds.Count(k => k == StudyStepKind.Rest), Is.EqualTo(2));
            Assert.That(kinds.Last(), Is.EqualTo(StudyStepKind.Done));
        }

        [Test]
        public void ACrashBetweenAnyTwoActionsLosesNothingAndResumesAtTheFirstUnfinishedStep()
        {
            // Reference run: how many actions a full session takes.
            int total = 0;
            RunAll(StudySession.Start(folder, "P00", new StudyConfig()), n => total = n);
            for (int crashAfter = 1; crashAfter < total; crashAfter++)
            {
                string id = $"P{crashAfter:00}";
                var session = StudySession.Start(folder, id, new StudyConfig());
                var saved = new List<(int step, string key, string value)>();
                try
                {
                    RunAll(session, n =>
                    {
                        if (n == crashAfter) throw new OperationCanceledException("crash");
                    });
                }
                catch (OperationCanceledException)
                {
                }
                // The process died (its handles, and with them the participant's lock, are closed): reopen from disk only.
                session.Dispose();
                var resumed = StudySession.Resume(folder, id);
                Assert.That(resumed.Current.Index, Is.EqualTo(session.Current.Index), $"crash after action {crashAfter}");
                foreach (var step in session.Steps)
                {
                    Assert.That(resumed.IsComplete(step.Index), Is.EqualTo(session.IsComplete(step.Index)));
                    Assert.That(resumed.AnswersOf(step.Index), Is.EquivalentTo(session.AnswersOf(step.Index)), $"crash after action {crashAfter}, step {step}");
                }
                RunAll(resumed, n => { });
                Assert.That(resumed.Current.Kind, Is.EqualTo(StudyStepKind.Done));
            }
        }

        [Test]
        public void ATornLastLineIsDroppedAndEverythingBeforeItKept()
        {
            var s = StudySession.Start(folder, "P05", new StudyConfig());
            s.Answer("age", "40");
            s.CompleteStep();
            s.AnswerSsq(Ssq(1));
            s.Dispose();
            using (var fs = new FileStream(s.JournalPath, FileMode.Append))
            {
                var half = Encoding.UTF8.GetBytes("17\t2026-11-22T10:00:00.000Z\tans");
                fs.Write(half, 0, half.Length);
            }
            var r = StudySession.Resume(folder, "P05");
            Assert.That(r.RecoveredTornLine, Is.True);
            Assert.That(r.AnswersOf(0)["age"], Is.EqualTo("40"));
            Assert.That(r.SsqOf(1), Is.EqualTo(Ssq(1)));
            Assert.That(r.Current.Kind, Is.EqualTo(StudyStepKind.PreExposureSsq));
            r.CompleteStep();
            r.Dispose();
            Assert.That(StudySession.Resume(folder, "P05").Current.Kind, Is.EqualTo(StudyStepKind.BaselineWalk), "appends after the cut stay readable");
        }

        [Test]
        public void AnIdWithDataIsNeverStartedOver()
        {
            var s = StudySession.Start(folder, "P09", new StudyConfig());
            s.Answer("age", "22");
            s.Dispose();
            var e = Assert.Throws<StudyStorageException>(() => StudySession.Start(folder, "P09", new StudyConfig()));
            Assert.That(e.Message, Does.Contain("P09").And.Contain("already has data"));
            Assert.That(StudySession.Resume(folder, "P09").AnswersOf(0)["age"], Is.EqualTo("22"));
        }

        [TestCase("../evil")]
        [TestCase("a/b")]
        [TestCase("P 1")]
        [TestCase("")]
        [TestCase("P.1")]
        [TestCase("abcdefghijklmnopqrstuvwxyz0123456789")]
        public void BadIdsAreRefusedBeforeAnyFileIsTouched(string id)
        {
            Assert.That(() => StudySession.Start(folder, id, new StudyConfig()), Throws.ArgumentException);
            Assert.That(Directory.Exists(folder), Is.False);
        }

        [Test]
        public void AnUnwritableFolderIsAClearErrorAndKeepsWhatWasSaved()
        {
            if (Environment.OSVersion.Platform != PlatformID.Unix || Environment.UserName == "root")
                Assert.Ignore("needs a non-root Unix user for a read-only file");
            var s = StudySession.Start(folder, "P03", new StudyConfig());
            s.Answer("age", "50");
            File.SetAttributes(s.JournalPath, FileAttributes.ReadOnly);
            var e = Assert.Throws<StudyStorageException>(() => s.Answer("gender", "male"));
            Assert.That(e.Message, Does.Contain("P03").And.Contain(s.JournalPath));
            File.SetAttributes(s.JournalPath, FileAttributes.Normal);
            s.Dispose();
            Assert.That(StudySession.Resume(folder, "P03").AnswersOf(0).Count, Is.EqualTo(1));
        }

        [Test]
        public void AFailingWriteIsAClearErrorAndKeepsWhatWasSaved()
        {
            // The disk fills in the middle of the line: part of it reaches the file, then the write fails.
            var files = new FaultyFileAccess();
            var s = StudySession.Start(folder, "P04", new StudyConfig(), files);
            s.Answer("age", "50");
            string path = s.JournalPath;
            string saved = File.ReadAllText(path);
            files.FillDiskAfter(writes: 0, keepBytes: 7);
            var e = Assert.Throws<StudyStorageException>(() => s.Answer("gender", "male"));
            Assert.That(e.Message, Does.Contain("P04").And.Contain(path).And.Contain("NOT saved").And.Contain("nothing was lost"));
            Assert.That(File.ReadAllText(path), Is.EqualTo(saved), "the part that reached the disk is cut again");
            files.FreeSpace();
            s.Answer("gender", "male");
            s.Dispose();
            var r = StudySession.Resume(folder, "P04", readOnly: true);
            Assert.That(r.AnswersOf(0)["gender"], Is.EqualTo("male"));
            Assert.That(r.Damage, Is.Empty);
            Assert.That(r.RecoveredTornLine, Is.False);
        }

        [Test]
        public void ResultsSkipMalformedJournalsNamingThemAndLeaveTheFilesAlone()
        {
            var s = StudySession.Start(folder, "P01", new StudyConfig());
            while (s.Current.Kind != StudyStepKind.Done)
            {
                if (s.Current.IsSsq) s.AnswerSsq(Ssq(s.Current.Index));
                s.CompleteStep();
            }
            File.WriteAllText(Path.Combine(folder, "P02" + StudyJournal.Extension), "not a journal\n");
            File.WriteAllText(Path.Combine(folder, "P03" + StudyJournal.Extension), StudyJournal.Magic + "\n1\tnot-a-time\tanswer\t0\tage\t3\n");
            var torn = StudySession.Start(folder, "P04", new StudyConfig());
            torn.Answer("age", "30");
            File.AppendAllText(torn.JournalPath, "9\t2026");
            long tornLength = new FileInfo(torn.JournalPath).Length;
            var results = StudyResults.Load(folder);
            Assert.That(results.Participants.Select(p => p.Participant), Is.EqualTo(new[] { "P01", "P04" }));
            Assert.That(results.Problems, Has.Some.Contains("P02").And.Some.Contains("P03.journal.tsv:2"));
            Assert.That(results.Problems, Has.Some.Contains("P04").And.Some.Contains("torn"));
            Assert.That(new FileInfo(torn.JournalPath).Length, Is.EqualTo(tornLength), "reading results never rewrites a journal");
            var p1 = results.Participants[0];
            Assert.That(p1.Conditions.Count, Is.EqualTo(3));
            Assert.That(p1.PreExposure.HasValue && p1.Baseline.HasValue, Is.True);
            Assert.That(p1.Position.Values.OrderBy(v => v), Is.EqualTo(new[] { 1, 2, 3 }));
        }
    }
}
