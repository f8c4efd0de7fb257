using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using HeadGait.Study;
using NUnit.Framework;

namespace HeadGait.Tests
{
    public class SsqFormTests
    {
        [Test]
        public void RatingMovesTheFocusToTheNextUnansweredItemWrappingAround()
        {
            var f = new SsqForm();
            Assert.That(f.Focus, Is.EqualTo(0));
            f.RateFocused(2);
            Assert.That(f.Focus, Is.EqualTo(1));
            f.Rate(15, 1);
            Assert.That(f.Focus, Is.EqualTo(1), "after the last item the focus wraps to the first unanswered one");
            for (int i = 1; i < 15; i++) f.RateFocused(i % 4);
            Assert.That(f.IsComplete, Is.True);
            Assert.That(f.Ratings(), Is.EqualTo(new[] { 2, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 1 }));
            f.Rate(4, 3);
            Assert.That(f.Focus, Is.EqualTo(4), "with every item answered the focus stays on the changed item");
            Assert.That(f.RatingOf(4), Is.EqualTo(3));
        }

        [Test]
        public void FocusStopsAtTheEndsAndBadRatingsAreRefused()
        {
            var f = new SsqForm();
            f.MoveFocus(-3);
            Assert.That(f.Focus, Is.EqualTo(0));
            f.MoveFocus(40);
            Assert.That(f.Focus, Is.EqualTo(15));
            Assert.That(() => f.RateFocused(4), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("0 (none) to 3"));
            Assert.That(() => f.Rate(16, 0), Throws.InstanceOf<ArgumentOutOfRangeException>());
            Assert.That(f.RatingOf(15), Is.Null);
        }

        [Test]
        public void AnIncompleteFormNamesTheFirstUnratedItem()
        {
            var f = new SsqForm();
            f.Rate(0, 0);
            f.Rate(1, 0);
            Assert.That(() => f.Ratings(), Throws.InvalidOperationException.With.Message.Contains("item 3 'Headache'").And.Message.Contains("2 of 16"));
            f.Clear();
            Assert.That(f.AnsweredCount, Is.EqualTo(0));
        }
    }

    public class StudyOperatorTests
    {
        string folder;

        [SetUp]
        public void MakeFolder() => folder = Path.Combine(Path.GetTempPath(), "headgait-operator-" + Guid.NewGuid().ToString("N"));

        [TearDown]
        public void RemoveFolder()
        {
            if (Directory.Exists(folder)) Directory.Delete(folder, true);
        }

        static void Fill(SsqForm form, int seed)
        {
            for (int i = 0; i < SimulatorSicknessQuestionnaire.ItemCount; i++) form.RateFocused((i * 7 + seed) % 4);
        }

        static int[] Expected(int seed) => Enumerable.Range(0, SimulatorSicknessQuestionnaire.ItemCount).Select(i => (i * 7 + seed) % 4).ToArray();

        /// <summary>Walks the operator through every step the way the operator view would, checking what the scene shows.</summary>
        static List<string> RunToEnd(StudyOperator op, int seed)
        {
            var shown = new List<string>();
            while (op.Current.Value.Kind != StudyStepKind.Done)
            {
                var step = op.Current.Value;
                switch (step.Kind)
                {
                    case StudyStepKind.Demographics:
                        Assert.That(op.SetDemographic("age", "31"), Is.True, op.Error);
                        break;
                    case StudyStepKind.BaselineWalk:
                    case StudyStepKind.Trial:
                        Assert.That(op.Do(OperatorCommand.Next), Is.False, "a walk is not finished before it started");
                        Assert.That(op.Do(OperatorCommand.Start), Is.True, op.Error);
                        Assert.That(op.Walking, Is.True);
                        Assert.That(op.ActiveCondition, Is.EqualTo(step.Condition));
                        if (step.Kind == StudyStepKind.Trial) shown.Add(op.ActiveCondition);
                        break;
                    default:
                        Assert.That(op.ActiveCondition, Is.Null, $"no avatar at {step}");
                        if (step.IsSsq)
                        {
                            Assert.That(op.SsqOpen, Is.True);
                            Assert.That(op.Do(OperatorCommand.Next), Is.False);
                            Assert.That(op.Error, Does.Contain("0 of 16 SSQ items"));
                            Fill(op.Ssq, seed + step.Index);
                        }
                        break;
                }
                Assert.That(op.Do(OperatorCommand.Next), Is.True, op.Error);
                Assert.That(op.Error, Is.Null);
            }
            return shown;
        }

        [Test]
        public void AFullSessionSavesEverySsqAndShowsTheConditionsInTheParticipantsOrder()
        {
            var op = new StudyOperator(folder, new StudyConfig());
            Assert.That(op.Open("P05"), Is.True, op.Error);
            var shown = RunToEnd(op, 1);

            var order = StudyProtocol.StepsFor("P05", new StudyConfig()).Where(s => s.Kind == StudyStepKind.Trial).Select(s => s.Condition).ToList();
            Assert.That(shown, Is.EqualTo(order));
            Assert.That(op.CanDo(OperatorCommand.Next), Is.False);
            Assert.That(op.Screen().Instruction, Does.Contain("study summarize"));

            var saved = StudySession.Resume(folder, "P05", readOnly: true);
            foreach (var s in saved.Steps.Where(s => s.IsSsq))
                Assert.That(saved.SsqOf(s.Index), Is.EqualTo(Expected(1 + s.Index)), $"{s}");
            Assert.That(saved.AnswersOf(0)["age"], Is.EqualTo("31"));
            var results = StudyResults.Load(folder);
            Assert.That(results.Participants.Single().Conditions.Keys, Is.EquivalentTo(order));
        }

        [Test]
        public void ReopeningAnIdResumesAtTheFirstUnfinishedStepAndChangesNothingSaved()
        {
            var first = new StudyOperator(folder, new StudyConfig());
            first.Open("P02");
            first.SetDemographic("age", "40");
            first.Do(OperatorCommand.Next);
            Fill(first.Ssq, 3);
            first.Do(OperatorCommand.Next);
            first.Do(OperatorCommand.Start);
            string path = first.Session.JournalPath;
            string before = File.ReadAllText(path);
            first.Dispose(); // the application dies: its handles, and the participant's lock, go with it

            // The application is closed mid-walk (a crash: nothing else is written) and reopened.
            var second = new StudyOperator(folder, new StudyConfig { Conditions = new List<string> { "other" } });
            Assert.That(second.Open(" P02 "), Is.True, second.Error);
            Assert.That(second.Current.Value.Kind, Is.EqualTo(StudyStepKind.BaselineWalk));
            Assert.That(second.Walking, Is.False, "an interrupted walk is started again");
            Assert.That(second.Notice, Does.Contain("Resumed participant P02 at step 3"));
            Assert.That(second.Session.Config.Conditions, Is.EqualTo(new StudyConfig().Conditions), "a resumed participant keeps the settings it was started with");
            Assert.That(File.ReadAllText(path), Is.EqualTo(before));
            Assert.That(second.Session.SsqOf(1), Is.EqualTo(Expected(3)));
        }

        [Test]
        public void AbortClosesTheParticipantAndOpeningItAgainResumes()
        {
            var op = new StudyOperator(folder, new StudyConfig());
            op.Open("P09");
            op.Do(OperatorCommand.Next);
            Assert.That(op.Do(OperatorCommand.Abort), Is.True);
            Assert.That(op.Session, Is.Null);
            Assert.That(op.Notice, Does.Contain("P09 aborted at step 2"));
            Assert.That(op.Screen().Participant, Is.Null);
            Assert.That(op.Do(OperatorCommand.Next), Is.False);
            Assert.That(op.Open("P09"), Is.True);
            Assert.That(op.Current.Value.Kind, Is.EqualTo(StudyStepKind.PreExposureSsq));
            Assert.That(StudyJournal.Open(folder, "P09", forWriting: false).Entries.Any(e => e.Kind == "event" && e.Key == "aborted"), Is.True);
        }

        [TestCase("../P01", "path separators")]
        [TestCase("", "empty")]
        [TestCase("P 1", "no spaces")]
        public void BadIdsAreShownAsErrorsAndTouchNoFile(string id, string message)
        {
            var op = new StudyOperator(folder, new StudyConfig());
            Assert.That(op.Open(id), Is.False);
            Assert.That(op.Screen().Error, Does.Contain(message));
            Assert.That(op.Session, Is.Null);
            Assert.That(Directory.Exists(folder), Is.False);
        }

        [Test]
        public void AFailingDiskIsAnErrorOnTheScreenAndTheSameCommandWorksOnceFixed()
        {
            var files = new FaultyFileAccess();
            var op = new StudyOperator(folder, new StudyConfig(), files);
            op.Open("P04");
            op.Do(OperatorCommand.Next);
            Fill(op.Ssq, 2);
            string path = op.Session.JournalPath;
            string saved = File.ReadAllText(path);
            files.FillDiskAfter(writes: 0, keepBytes: 20);

            Assert.That(op.Do(OperatorCommand.Next), Is.False);
            var screen = op.Screen();
            Assert.That(screen.Error, Does.Contain("P04").And.Contain(path).And.Contain("NOT saved").And.Contain("nothing was lost"));
            Assert.That(op.Current.Value.Kind, Is.EqualTo(StudyStepKind.PreExposureSsq), "the step is not left unsaved");
            Assert.That(op.Ssq.IsComplete, Is.True, "the participant's answers stay on the form for the retry");
            Assert.That(File.ReadAllText(path), Is.EqualTo(saved));

            files.FreeSpace();
            Assert.That(op.Do(OperatorCommand.Next), Is.True, op.Error);
            Assert.That(op.Screen().Error, Is.Null);
            var r = StudySession.Resume(folder, "P04", readOnly: true);
            Assert.That(r.SsqOf(1), Is.EqualTo(Expected(2)));
            Assert.That(r.SsqAnswersOf(1).Count, Is.EqualTo(1));
            Assert.That(r.Damage, Is.Empty);
        }

        [Test]
        public void AnUncreatableDataFolderIsAnErrorNamingIt()
        {
            Directory.CreateDirectory(folder);
            string blocked = Path.Combine(folder, "file");
            File.WriteAllText(blocked, "");
            var op = new StudyOperator(Path.Combine(blocked, "data"), new StudyConfig());
            Assert.That(op.Open("P01"), Is.False);
            Assert.That(op.Error, Does.Contain("P01").And.Contain(blocked));
        }

        [Test]
        public void TheScreenShowsTheOrderAndMarksTheConditionBeingWalkedOrRated()
        {
            var op = new StudyOperator(folder, new StudyConfig());
            op.Open("P03");
            var order = StudyProtocol.StepsFor("P03", new StudyConfig()).Where(s => s.Kind == StudyStepKind.Trial).Select(s => s.Condition).ToList();
            Assert.That(op.Screen().ConditionOrder, Is.EqualTo(order));
            Assert.That(op.Screen().CurrentCondition, Is.EqualTo(-1));
            while (op.Current.Value.Kind != StudyStepKind.Trial)
            {
                if (op.CanDo(OperatorCommand.Start)) op.Do(OperatorCommand.Start);
                if (op.SsqOpen) Fill(op.Ssq, 0);
                Assert.That(op.Do(OperatorCommand.Next), Is.True, op.Error);
            }
            var screen = op.Screen();
            Assert.That(screen.Participant, Is.EqualTo("P03"));
            Assert.That(screen.Step, Does.StartWith("Step 5 of 13: Trial (" + order[0] + ")"));
            Assert.That(screen.CurrentCondition, Is.EqualTo(0));
            Assert.That(screen.Instruction, Does.Contain("press Start"));
            op.Do(OperatorCommand.Start);
            Assert.That(op.Do(OperatorCommand.RepeatTrial), Is.True);
            Assert.That(op.Walking, Is.True);
            op.Do(OperatorCommand.Next);
            Assert.That(op.Screen().CurrentCondition, Is.EqualTo(0), "the SSQ after a trial still marks its condition");
            Assert.That(op.ActiveCondition, Is.Null);
            Assert.That(op.Session.Steps.Count, Is.EqualTo(13));
        }
    }
}
