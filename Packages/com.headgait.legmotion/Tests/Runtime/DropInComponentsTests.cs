using System.IO;
using System.Reflection;
using HeadGait.Unity;
using NUnit.Framework;
using UnityEngine;

namespace HeadGait.Tests
{
    /// <summary>
    /// The drop-in prefab's components on one GameObject, woken as a scene wakes them: they find each other and the
    /// avatar's Animator on their own, and leave nothing running when the object is destroyed.
    /// </summary>
    [NeedsPackageFiles]
    public class DropInComponentsTests
    {
        readonly TestObjects objects = new TestObjects();

        [TearDown]
        public void DestroyWhatTheTestMade() => objects.DestroyAll();

        static object Field(object target, string name) => target.GetType().GetField(name, BindingFlags.Instance | BindingFlags.NonPublic).GetValue(target);

        [Test]
        public void TheComponentsFindEachOtherAndTheAvatarsAnimatorWhenTheyWake()
        {
            string models = SamplePaths.FindModelsFolder(TestContext.CurrentContext.TestDirectory);
            Assert.That(models, Is.Not.Null, "the package's Models folder");
            var legs = objects.New("HeadGait Legs");
            legs.SetActive(false); // as a scene or prefab loads: every component present before any wakes
            var avatar = objects.New("Avatar");
            avatar.transform.SetParent(legs.transform, false);
            var animator = avatar.AddComponent<Animator>();
            var source = legs.AddComponent<HeadImuSource>();
            source.Mode = HeadImuMode.External;
            var gait = legs.AddComponent<GaitLegAnimator>();
            gait.GetType().GetField("corTemplate", BindingFlags.Instance | BindingFlags.NonPublic)
                .SetValue(gait, new TextAsset(File.ReadAllText(Path.Combine(models, GaitModels.CorrelationFile))));

            legs.SetActive(true);
            Assert.That(Field(gait, "animator"), Is.SameAs(animator), "the Animator found in the children");
            Assert.That(Field(source, "target"), Is.SameAs(gait), "the source found the animator on its GameObject");
            Assert.That(gait.Pipeline.Classifier, Is.InstanceOf<CorrelationClassifier>());

            for (int i = 0; i < 300; i++) gait.Push(i * 0.01, new Vector3(0, 0, 9.81f));
            gait.Runner.Step(new InlineBatchScheduler(gait.Runner));
            Assert.That(gait.Runner.Pending, Is.Zero);

            Object.DestroyImmediate(legs);
            Assert.That(legs == null && gait == null && source == null, Is.True, "destroyed objects are null");
        }
    }
}
