using System;
using System.Collections;
using System.Collections.Generic;
using HeadGait.Unity;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.InputSystem;
using UnityEngine.InputSystem.Controls;
using UnityEngine.TestTools;

namespace HeadGait.Tests
{
    /// <summary>
    /// The stand-ins behave as Unity does where the components depend on it (dotnet/UnityStubs, each member citing its Unity
    /// source): messages on AddComponent and activation, component lookup, Unity's null for destroyed objects, Destroy at
    /// the frame's end, the Transform hierarchy, and the Input System's typed child lookup.
    /// </summary>
    public class UnityStandInTests
    {
        sealed class Probe : MonoBehaviour
        {
            public static readonly List<string> Log = new List<string>();
            public string Tag = "";
            void Awake() => Log.Add("Awake " + name);
            void OnEnable() => Log.Add("OnEnable " + name);
            void OnDisable() => Log.Add("OnDisable " + name);
            void OnDestroy() => Log.Add("OnDestroy " + name);
        }

        sealed class Other : MonoBehaviour { }

        readonly TestObjects objects = new TestObjects();

        GameObject Make(string name) => objects.New(name);

        [SetUp]
        public void ClearLog() => Probe.Log.Clear();

        [TearDown]
        public void DestroyMade() => objects.DestroyAll();

        [Test]
        public void AddComponentRunsAwakeThenOnEnableOnAnActiveGameObjectOnly()
        {
            var active = Make("A");
            active.AddComponent<Probe>();
            Assert.That(Probe.Log, Is.EqualTo(new[] { "Awake A", "OnEnable A" }));

            Probe.Log.Clear();
            var inactive = Make("B");
            inactive.SetActive(false);
            var p = inactive.AddComponent<Probe>();
            Assert.That(Probe.Log, Is.Empty, "nothing runs on an inactive GameObject");
            inactive.SetActive(true);
            Assert.That(Probe.Log, Is.EqualTo(new[] { "Awake B", "OnEnable B" }));
            p.enabled = false;
            inactive.SetActive(false);
            inactive.SetActive(true);
            Assert.That(Probe.Log, Is.EqualTo(new[] { "Awake B", "OnEnable B", "OnDisable B" }), "a disabled behaviour gets no OnEnable");
        }

        [Test]
        public void ActivationReachesChildrenThroughTheHierarchy()
        {
            var parent = Make("Parent");
            var child = Make("Child");
            child.transform.SetParent(parent.transform, false);
            parent.SetActive(false);
            child.AddComponent<Probe>();
            Assert.That(child.activeSelf, Is.True);
            Assert.That(child.activeInHierarchy, Is.False);
            Assert.That(Probe.Log, Is.Empty);
            parent.SetActive(true);
            Assert.That(Probe.Log, Is.EqualTo(new[] { "Awake Child", "OnEnable Child" }));
            Assert.That(parent.GetComponentInChildren<Probe>(), Is.Not.Null);
            parent.SetActive(false);
            Assert.That(parent.GetComponentInChildren<Probe>(), Is.Null, "inactive GameObjects are skipped");
            Assert.That(parent.GetComponentInChildren<Probe>(true), Is.Not.Null);
        }

        [Test]
        public void GetComponentFindsComponentsByTypeBaseTypeAndInterface()
        {
            var go = Make("Go");
            var probe = go.AddComponent<Probe>();
            Assert.That(go.GetComponent<Probe>(), Is.SameAs(probe));
            Assert.That(probe.GetComponent<MonoBehaviour>(), Is.SameAs(probe));
            Assert.That(probe.GetComponent<Transform>(), Is.SameAs(go.transform));
            Assert.That(go.GetComponent<Other>(), Is.Null);
        }

        [Test]
        public void DestroyedObjectsCompareEqualToNull()
        {
            var go = Make("Go");
            var probe = go.AddComponent<Probe>();
            UnityEngine.Object.DestroyImmediate(probe);
            Assert.That(probe == null, Is.True);
            Assert.That((bool)probe, Is.False);
            Assert.That(ReferenceEquals(probe, null), Is.False, "the C# object itself lives on");
            Assert.That(go.GetComponent<Probe>() == null, Is.True);
            Assert.That(Probe.Log, Is.EqualTo(new[] { "Awake Go", "OnEnable Go", "OnDisable Go", "OnDestroy Go" }));
        }

        [UnityTest]
        public IEnumerator DestroyTakesEffectWhenTheFrameEnds()
        {
            var go = Make("Frame");
            go.AddComponent<Probe>();
            UnityEngine.Object.Destroy(go);
            Assert.That(go != null, Is.True, "still there in the frame Destroy was called");
            yield return null;
            Assert.That(go == null, Is.True);
            // (Objects earlier tests left to Destroy go at this frame's end too: only this one's messages are checked.)
            Assert.That(Probe.Log.FindAll(m => m.EndsWith(" Frame")), Is.EqualTo(new[] { "Awake Frame", "OnEnable Frame", "OnDisable Frame", "OnDestroy Frame" }));
        }

        [Test]
        public void TransformsComposeThroughTheirParentsAndFindChildrenByPath()
        {
            var root = Make("Root").transform;
            var arm = Make("Arm").transform;
            var hand = Make("Hand").transform;
            arm.SetParent(root, false);
            hand.SetParent(arm, false);
            root.position = new Vector3(1, 0, 0);
            root.rotation = Quaternion.Euler(0, 90, 0);
            arm.localPosition = new Vector3(0, 0, 2);
            Assert.That(arm.parent, Is.SameAs(root));
            Assert.That(root.childCount, Is.EqualTo(1));
            Assert.That(root.Find("Arm/Hand"), Is.SameAs(hand));
            Assert.That(root.Find("Hand"), Is.Null, "Find looks at children, not grandchildren, without a path");
            var p = arm.position; // (1,0,0) + rotate (0,0,2) by 90 degrees about y = (3,0,0)
            Assert.That(new[] { p.x, p.y, p.z }, Is.EqualTo(new[] { 3f, 0f, 0f }).Within(1e-5f));

            var free = Make("Free").transform;
            free.position = new Vector3(5, 0, 0);
            free.SetParent(root, true);
            Assert.That(free.position.x, Is.EqualTo(5).Within(1e-5), "worldPositionStays keeps the world position");
            free.SetParent(null, false);
            Assert.That(free.parent, Is.Null);
        }

        sealed class Headset : InputDevice { }

        static T Control<T>(string name) where T : InputControl, new()
        {
            var c = new T();
            c.controlName = name;
            return c;
        }

        [Test]
        public void TryGetChildControlThrowsOnATypeMismatchAsTheInputSystemDoes()
        {
            var device = new Headset();
            device.childControls.Add(Control<Vector3Control>("centerEyePosition"));
            Assert.That(device.TryGetChildControl<Vector3Control>("CenterEyePosition"), Is.Not.Null);
            Assert.That(device.TryGetChildControl<Vector3Control>("missing"), Is.Null);
            Assert.That(() => device.TryGetChildControl<QuaternionControl>("centerEyePosition"), Throws.InvalidOperationException.With.Message.Contains("to be of type 'QuaternionControl'"));
        }

        [Test]
        public void TheHeadReaderSkipsADeviceWhoseControlsHaveOtherTypes()
        {
            // A device named like a headset whose trackingState is not an integer (some runtimes' layouts differ): Unity's
            // TryGetChildControl<IntegerControl> throws, which would stop every device after it from binding.
            var odd = new Headset();
            odd.childControls.Add(Control<Vector3Control>("centerEyePosition"));
            odd.childControls.Add(Control<QuaternionControl>("centerEyeRotation"));
            odd.childControls.Add(Control<Vector3Control>("trackingState"));
            odd.childControls.Add(Control<Vector3Control>("userPresence"));
            InputSystem.addedDevices.Add(odd);
            try
            {
                var router = new HeadSampleRouter(HeadImuMode.XRDevice, PhoneMounting.LandscapeLeft, _ => { });
                InputSystemHeadReader reader = null;
                Assert.That(() => reader = new InputSystemHeadReader(router), Throws.Nothing);
                reader?.Dispose();
            }
            finally
            {
                InputSystem.addedDevices.Remove(odd);
            }
        }
    }
}
