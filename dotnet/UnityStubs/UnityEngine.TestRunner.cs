// Stand-ins for the Unity Test Framework's [UnityPlatform] (UnityEngine.TestRunner/NUnitExtensions/Attributes/
// UnityPlatformAttribute.cs: a test, fixture or assembly skipped where Application.platform is not among `include` or is
// among `exclude`) and [UnityTest] (com.unity.test-framework, UnityEngine.TestRunner/NUnitExtensions/
// Attributes/UnityTestAttribute.cs): a test method returning IEnumerator that Unity steps once per frame; `yield return
// null` waits for the next frame. Here each yield ends the stand-ins' frame (Object.Destroy takes effect; there is no
// player loop, so no Update runs). Built on NUnit's extension interfaces, as Unity's is.
using System;
using System.Collections;
using NUnit.Framework;
using NUnit.Framework.Interfaces;
using NUnit.Framework.Internal;
using NUnit.Framework.Internal.Commands;

namespace UnityEngine.TestTools
{
    [AttributeUsage(AttributeTargets.Method)]
    public class UnityTestAttribute : NUnitAttribute, ISimpleTestBuilder, IImplyFixture, IWrapTestMethod
    {
        public TestMethod BuildFrom(IMethodInfo method, NUnit.Framework.Internal.Test suite)
        {
            var test = new TestMethod(method, suite);
            if (!typeof(IEnumerator).IsAssignableFrom(method.ReturnType.Type))
            {
                test.RunState = RunState.NotRunnable;
                test.Properties.Set(PropertyNames.SkipReason, "a [UnityTest] method returns IEnumerator");
            }
            return test;
        }

        public TestCommand Wrap(TestCommand command) => new FramesCommand(command.Test);

        sealed class FramesCommand : TestCommand
        {
            public FramesCommand(NUnit.Framework.Internal.Test test) : base(test) { }

            public override TestResult Execute(TestExecutionContext context)
            {
                var frames = (IEnumerator)((TestMethod)Test).Method.Invoke(context.TestObject, null);
                while (frames.MoveNext()) FrameLoop.EndFrame();
                FrameLoop.EndFrame();
                context.CurrentResult.SetResult(ResultState.Success);
                return context.CurrentResult;
            }
        }
    }

    [AttributeUsage(AttributeTargets.Assembly | AttributeTargets.Class | AttributeTargets.Method, AllowMultiple = true)]
    public class UnityPlatformAttribute : NUnitAttribute, IApplyToTest
    {
        public RuntimePlatform[] include { get; set; } = new RuntimePlatform[0];
        public RuntimePlatform[] exclude { get; set; } = new RuntimePlatform[0];

        public UnityPlatformAttribute() { }

        public UnityPlatformAttribute(params RuntimePlatform[] include) => this.include = include;

        public void ApplyToTest(NUnit.Framework.Internal.Test test)
        {
            if (test.RunState == RunState.NotRunnable || test.RunState == RunState.Ignored) return;
            var platform = Application.platform;
            bool included = include.Length == 0 || Array.IndexOf(include, platform) >= 0;
            if (included && Array.IndexOf(exclude, platform) < 0) return;
            test.RunState = RunState.Skipped;
            test.Properties.Add(PropertyNames.SkipReason, $"not run on {platform}");
        }
    }
}
