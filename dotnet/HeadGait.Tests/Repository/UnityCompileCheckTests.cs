using System;
using System.IO;
using System.Linq;
using HeadGait.UnityCompileCheck;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>The Unity compile check (dotnet/HeadGait.UnityCompileCheck) on small made-up projects: it must fail where
    /// Unity would (a reference the asmdef does not list, a sample that needs an absent package) and pass once the
    /// asmdefs say what Unity needs to hear.</summary>
    public class UnityCompileCheckTests
    {
        static string Repository => RepositoryPaths.Root;

        [TestCase("2.2.0", "2.2.1", true)]
        [TestCase("2.2.0", "2.1.3", false)]
        [TestCase("[1.0,2.0)", "1.5.0", true)]
        [TestCase("[1.0,2.0)", "2.0.0", false)]
        [TestCase("(1.0,2.0]", "1.0.0", false)]
        [TestCase("(1.0,2.0]", "2.0.0", true)]
        [TestCase("[2.0.0]", "2.0.0", true)]
        [TestCase("[2.0.0]", "2.0.1", false)]
        [TestCase("6000.0", "6000.0.40f1", true)]
        [TestCase("2.0.0", "2.0.0-pre.3", false)]
        [TestCase("", "0.1.0", true)]
        public void VersionDefinesReadUnitysExpressions(string expression, string version, bool admitted)
            => Assert.That(new VersionDefine("com.example", expression, "X").Admits(version), Is.EqualTo(admitted));

        [TestCase("UnityEngine.Core.cs", "UnityEngine")]
        [TestCase("UnityEngine.Events.cs", "UnityEngine")]
        [TestCase("Unity.Jobs.cs", "UnityEngine")]
        [TestCase("UnityEngine.XR.cs", "UnityEngine")]
        [TestCase("UnityEngine.UI.cs", "UnityEngine.UI")]
        [TestCase("UnityEngine.InputSystem.cs", "Unity.InputSystem")]
        [TestCase("UnityEngine.XR.Interaction.Toolkit.cs", "Unity.XR.Interaction.Toolkit")]
        [TestCase("Unity.InferenceEngine.cs", "Unity.InferenceEngine")]
        [TestCase("UnityEditor.cs", "UnityEditor")]
        [TestCase("UnityEngine.TestTools.cs", "UnityEngine.TestRunner")]
        [TestCase("UnityEditor.TestTools.cs", "UnityEditor.TestRunner")]
        public void EachStandInFileCompilesIntoTheAssemblyUnityShipsItsTypesIn(string file, string assembly)
        {
            string folder = Path.Combine(Path.GetTempPath(), "headgait-stubs-" + Guid.NewGuid().ToString("N"));
            try
            {
                Write(Path.Combine(folder, file), "");
                var owner = StandIn.Partition(folder).Single(p => p.Value.Count == 1).Key;
                Assert.That(owner.Name, Is.EqualTo(assembly));
            }
            finally
            {
                Directory.Delete(folder, true);
            }
        }

        [Test]
        public void FailsWhereUnityWouldAndPassesOnceTheAsmdefsAreRight()
        {
            string project = MadeUpProject("2021.3", ", \"testables\": [ \"com.headgait.legmotion\" ]", out string package);
            try
            {
                // A test assembly as Unity's Test Runner makes them, using a library it does not reference.
                Write(Path.Combine(package, "Tests", "T.asmdef"),
                    "{ \"name\": \"T\", \"references\": [ \"UnityEngine.TestRunner\" ], \"overrideReferences\": true, \"precompiledReferences\": [ \"nunit.framework.dll\" ], \"defineConstraints\": [ \"UNITY_INCLUDE_TESTS\" ], \"autoReferenced\": false }");
                Write(Path.Combine(package, "Tests", "T.cs"),
                    "using NUnit.Framework;\npublic class T { [Test] public void A() { Assert.That(System.Math.Abs(-1), Is.EqualTo(1)); System.Console.WriteLine(MathNet.Numerics.Constants.Pi); } }");
                // A sample that needs uGUI, with no constraint saying so.
                string sample = Path.Combine(package, "Samples~", "Panel", "Panel.asmdef");
                Write(sample, "{ \"name\": \"Panel\", \"references\": [ \"UnityEngine.UI\" ] }");
                Write(Path.Combine(package, "Samples~", "Panel", "Panel.cs"), "public class Panel : UnityEngine.MonoBehaviour { UnityEngine.UI.Button button; }");
                // An engine-free core that reaches for UnityEngine anyway.
                Write(Path.Combine(package, "Core", "C.asmdef"), "{ \"name\": \"C\", \"noEngineReferences\": true }");
                Write(Path.Combine(package, "Core", "C.cs"), "public class C { UnityEngine.Vector3 v; }");
                // Code only an editor older than Unity 6 compiles, and it does not: seen only in the package.json-minimum run.
                Write(Path.Combine(package, "Core", "Old.cs"), "#if !UNITY_6000_0_OR_NEWER\npublic class Old { int x = \"not an int\"; }\n#endif\n");

                var log = new StringWriter();
                Assert.That(new Check(project, log).Run(), Is.False);
                string text = log.ToString();
                Assert.That(text, Does.Contain("The name 'MathNet' does not exist"));
                Assert.That(text, Does.Contain("Panel.cs(1,75): error CS0234").Or.Contain("'UI' does not exist in the namespace 'UnityEngine'"));
                Assert.That(text, Does.Contain("== every optional package, editor\n").And.Contain("== without com.unity.ugui and com.unity.xr.interaction.toolkit, editor"));
                Assert.That(text, Does.Contain("'UnityEngine' could not be found").Or.Contain("The type or namespace name 'UnityEngine'"));
                Assert.That(text, Does.Contain("== package.json minimum, Unity 2021.3.0f1, without com.unity.ai.inference (needs a newer editor), editor"));
                Assert.That(text.Split("== package.json minimum")[1], Does.Contain("Old.cs(2,28): error CS0029"));
                Assert.That(text.Split("== package.json minimum")[0], Does.Not.Contain("Old.cs"));

                // Fixed as in the package: no MathNet, the sample constrained to projects with uGUI, the core engine-free.
                Write(Path.Combine(package, "Tests", "T.cs"), "using NUnit.Framework;\npublic class T { [Test] public void A() { Assert.That(System.Math.Abs(-1), Is.EqualTo(1)); } }");
                Write(sample, "{ \"name\": \"Panel\", \"references\": [ \"UnityEngine.UI\" ], \"defineConstraints\": [ \"HAS_UGUI\" ], " +
                              "\"versionDefines\": [ { \"name\": \"com.unity.ugui\", \"expression\": \"1.0.0\", \"define\": \"HAS_UGUI\" } ] }");
                Write(Path.Combine(package, "Core", "C.cs"), "public class C { System.Numerics.Vector3 v; }");
                File.Delete(Path.Combine(package, "Core", "Old.cs"));
                log = new StringWriter();
                Assert.That(new Check(project, log).Run(), Is.True, log.ToString());
                Assert.That(log.ToString(), Does.Contain("  Panel: not built (defineConstraints HAS_UGUI unmet)"));
                Assert.That(log.ToString(), Does.Contain("  T: built (1 files; references UnityEngine.TestRunner, UnityEngine, UnityEditor, nunit.framework.dll)"));
                Assert.That(log.ToString(), Does.Contain("  T: not built (defineConstraints UNITY_INCLUDE_TESTS unmet)"), "no tests in a player build");
            }
            finally
            {
                if (Directory.Exists(project)) Directory.Delete(project, true);
            }
        }

        [Test]
        public void APackageForUnity6KeepsThePackagesThatNeedUnity6InItsMinimumEditorRun()
        {
            // "unity": "6000.0" is the editor 6000.0.0f1, not a release after it: com.unity.ai.inference (which says
            // "unity": "6000.0" too) installs there, so the package.json-minimum run builds with it.
            string project = MadeUpProject("6000.0", "", out string package);
            try
            {
                Write(Path.Combine(package, "Core", "C.asmdef"), "{ \"name\": \"C\", \"noEngineReferences\": true }");
                Write(Path.Combine(package, "Core", "C.cs"), "public class C { }");

                var log = new StringWriter();
                Assert.That(new Check(project, log).Run(), Is.True, log.ToString());
                Assert.That(log.ToString(), Does.Contain("== package.json minimum, Unity 6000.0.0f1, editor\n"));
            }
            finally
            {
                if (Directory.Exists(project)) Directory.Delete(project, true);
            }
        }

        /// <summary>
        /// A made-up Unity 6000.0.40f1 project in a fresh temporary folder: the manifest's optional packages (plus
        /// <paramref name="manifestTail"/>, e.g. testables), a package declaring <paramref name="unityMinimum"/> and the
        /// Unity stand-ins; <paramref name="package"/> is the package's folder.
        /// </summary>
        static string MadeUpProject(string unityMinimum, string manifestTail, out string package)
        {
            string project = Path.Combine(Path.GetTempPath(), "headgait-compile-" + Guid.NewGuid().ToString("N"));
            package = Path.Combine(project, "Packages", "com.headgait.legmotion");
            Write(Path.Combine(project, "ProjectSettings", "ProjectVersion.txt"), "m_EditorVersion: 6000.0.40f1\n");
            Write(Path.Combine(project, "Packages", "manifest.json"),
                "{ \"dependencies\": { \"com.unity.test-framework\": \"1.4.6\", \"com.unity.ugui\": \"2.0.0\", \"com.unity.xr.interaction.toolkit\": \"3.0.8\", \"com.unity.ai.inference\": \"2.2.1\" }" + manifestTail + " }");
            Write(Path.Combine(package, "package.json"), "{ \"name\": \"com.headgait.legmotion\", \"version\": \"0.0.1\", \"unity\": \"" + unityMinimum + "\", \"dependencies\": { \"com.unity.inputsystem\": \"1.7.0\" } }");
            foreach (var stub in Directory.GetFiles(Path.Combine(Repository, "dotnet", "UnityStubs"), "*.cs"))
                Write(Path.Combine(project, "dotnet", "UnityStubs", Path.GetFileName(stub)), File.ReadAllText(stub));
            return project;
        }

        static void Write(string path, string text)
        {
            Directory.CreateDirectory(Path.GetDirectoryName(path));
            File.WriteAllText(path, text);
        }
    }
}
