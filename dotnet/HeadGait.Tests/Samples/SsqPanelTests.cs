using System.Collections.Generic;
using System.Reflection;
using HeadGait.Unity;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.UI;

namespace HeadGait.Tests
{
    /// <summary>
    /// The study sample's SSQ panel in the headset: a standalone headset shows no operator view, so the panel must show
    /// the data folder and any error that stops the study. (The sample's own assembly is not referenced by the package's
    /// tests, so its test lives here, on the stand-ins.)
    /// </summary>
    public class SsqPanelTests
    {
        readonly TestObjects objects = new TestObjects();

        [TearDown]
        public void DestroyWhatTheTestMade() => objects.DestroyAll();

        static T Field<T>(object target, string name) => (T)target.GetType().GetField(name, BindingFlags.Instance | BindingFlags.NonPublic).GetValue(target);

        static void Call(object target, string method) => target.GetType().GetMethod(method, BindingFlags.Instance | BindingFlags.NonPublic).Invoke(target, null);

        [Test]
        public void ASetupErrorAndTheDataFolderAreShownInTheHeadset()
        {
            var study = objects.New("Study");
            var runner = study.AddComponent<StudyRunner>(); // no Avatar Condition Switcher: a setup error
            Assert.That(runner.SetupError, Is.Not.Null);
            var panelObject = objects.New("SSQ Panel");
            var panel = panelObject.AddComponent<SsqPanel>();
            panel.GetType().GetField("runner", BindingFlags.Instance | BindingFlags.NonPublic).SetValue(panel, runner);
            Call(panel, "Start");
            Call(panel, "Update");

            var canvas = Field<GameObject>(panel, "canvasObject");
            Assert.That(canvas.activeSelf, Is.True, "shown although no SSQ is open: the study cannot run");
            Assert.That(Field<Text>(panel, "status").text, Does.Contain(runner.SetupError));
            Assert.That(Field<Text>(panel, "folder").text, Does.Contain(runner.DataFolder));
        }
    }
}
