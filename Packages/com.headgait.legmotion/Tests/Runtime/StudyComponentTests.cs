using System;
using System.Collections.Generic;
using System.IO;
using HeadGait.Study;
using HeadGait.Unity;
using NUnit.Framework;
using UnityEngine;

namespace HeadGait.Tests
{
    /// <summary>The study scene's components: the operator's keys and the avatar condition switcher.</summary>
    public class StudyComponentTests
    {
        string folder;
        readonly TestObjects objects = new TestObjects();

        [SetUp]
        public void MakeFolder() => folder = Path.Combine(Path.GetTempPath(), "headgait-keys-" + Guid.NewGuid().ToString("N"));

        [TearDown]
        public void RemoveFolderAndObjects()
        {
            if (Directory.Exists(folder)) Directory.Delete(folder, true);
            objects.DestroyAll();
        }

        [Test]
        public void DigitsRateTheFocusedItemArrowsMoveAndReturnSavesTheSsq()
        {
            var op = new StudyOperator(folder, new StudyConfig());
            op.Open("K01");
            Assert.That(StudyKeyboard.Handle(KeyCode.Alpha2, op), Is.False, "keys do nothing outside an SSQ (the demographics step)");
            op.Do(OperatorCommand.Next);
            Assert.That(op.SsqOpen, Is.True);

            Assert.That(StudyKeyboard.Handle(KeyCode.Alpha2, op), Is.True);
            Assert.That(op.Ssq.RatingOf(0), Is.EqualTo(2));
            StudyKeyboard.Handle(KeyCode.Keypad3, op);
            Assert.That(op.Ssq.RatingOf(1), Is.EqualTo(3));
            StudyKeyboard.Handle(KeyCode.UpArrow, op);
            StudyKeyboard.Handle(KeyCode.UpArrow, op);
            StudyKeyboard.Handle(KeyCode.Alpha0, op);
            Assert.That(op.Ssq.RatingOf(0), Is.EqualTo(0), "Up twice went back to the first item");
            StudyKeyboard.Handle(KeyCode.DownArrow, op);
            Assert.That(op.Ssq.Focus, Is.EqualTo(3), "rating item 1 moved to item 3 (the next unanswered), Down to item 4");

            Assert.That(StudyKeyboard.Handle(KeyCode.Return, op), Is.True);
            Assert.That(op.Current.Value.Kind, Is.EqualTo(StudyStepKind.PreExposureSsq), "an incomplete SSQ is not saved");
            Assert.That(op.Error, Does.Contain("2 of 16"));
            for (int i = 0; i < 14; i++) StudyKeyboard.Handle(KeyCode.Keypad1, op);
            Assert.That(StudyKeyboard.Handle(KeyCode.KeypadEnter, op), Is.True);
            Assert.That(op.Current.Value.Kind, Is.EqualTo(StudyStepKind.BaselineWalk));
            var saved = StudySession.Resume(folder, "K01", readOnly: true).SsqOf(1);
            Assert.That(saved, Is.EqualTo(new[] { 0, 3, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1 }));
            Assert.That(StudyKeyboard.Handle(KeyCode.Alpha1, op), Is.False, "keys do nothing during a walk");
        }

        [Test]
        public void OnlyDigitsZeroToThreeAreRatings()
        {
            Assert.That(StudyKeyboard.RatingOf(KeyCode.Alpha3), Is.EqualTo(3));
            Assert.That(StudyKeyboard.RatingOf(KeyCode.Keypad0), Is.EqualTo(0));
            Assert.That(StudyKeyboard.RatingOf(KeyCode.Return), Is.EqualTo(-1));
            Assert.That(StudyKeyboard.RatingOf((KeyCode)((int)KeyCode.Alpha3 + 1)), Is.EqualTo(-1));
            Assert.That(StudyKeyboard.RatingOf((KeyCode)((int)KeyCode.Keypad3 + 1)), Is.EqualTo(-1));
        }

        [Test]
        public void TheSwitcherShowsOneConditionsAvatarAndHidesTheRest()
        {
            var block = objects.New("Block Avatar");
            var humanoid = objects.New("Humanoid Avatar");
            var switcher = objects.New("Avatars").AddComponent<AvatarConditionSwitcher>();
            switcher.Configure(new List<AvatarCondition>
            {
                new AvatarCondition { condition = StudyConfig.NoAvatar },
                new AvatarCondition { condition = StudyConfig.BlockAvatar, root = block },
                new AvatarCondition { condition = StudyConfig.HumanoidAvatar, root = humanoid },
            });

            Assert.That(switcher.Show(StudyConfig.BlockAvatar), Is.True);
            Assert.That(block.activeSelf, Is.True);
            Assert.That(humanoid.activeSelf, Is.False);
            Assert.That(switcher.Show(StudyConfig.HumanoidAvatar), Is.True);
            Assert.That(block.activeSelf, Is.False);
            Assert.That(humanoid.activeSelf, Is.True);
            Assert.That(switcher.Show(StudyConfig.NoAvatar), Is.True);
            Assert.That(block.activeSelf || humanoid.activeSelf, Is.False);
            switcher.Show(StudyConfig.HumanoidAvatar);
            Assert.That(switcher.Show(null), Is.True);
            Assert.That(humanoid.activeSelf, Is.False, "between trials no avatar is shown");
            Assert.That(switcher.Show("female-avatar"), Is.False, "an unknown condition shows nothing and says so");
            Assert.That(switcher.Shown, Is.Null);
            Assert.That(switcher.Missing(new[] { StudyConfig.BlockAvatar, "female-avatar" }), Is.EqualTo(new[] { "female-avatar" }));
        }
    
        [Test]
        public void WithNoFolderSetTheStudyWritesToTheApplicationsPersistentDataFolder()
        {
            // A standalone headset has no Documents folder: persistentDataPath is where the application may write and what
            // `adb pull` copies off it. The runner wakes as it is added (the operator view shows the folder it chose).
            var runner = objects.New("Study").AddComponent<StudyRunner>();
            string expected = Path.Combine(Application.persistentDataPath, "HeadGait Study");
            Assert.That(runner.DataFolder, Is.EqualTo(expected));
            Assert.That(runner.Operator, Is.Not.Null);
            Assert.That(runner.Operator.DataFolder, Is.EqualTo(expected));
            Assert.That(runner.SetupError, Does.Contain("Avatar Condition Switcher"), "no switcher in this scene");
        }
    }
}
