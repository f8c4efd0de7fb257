using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace HeadGait.UnityCompileCheck
{
    /// <summary>A Unity or package assembly, compiled from the stand-in sources in dotnet/UnityStubs under the name Unity
    /// gives it, so an asmdef sees it only when it (or Unity, implicitly) references that name.</summary>
    public sealed class StandIn
    {
        public readonly string Name;
        /// <summary>The package that brings it (null: the editor itself).</summary>
        public readonly string Package;
        public readonly bool EditorOnly;
        public readonly string[] References;
        /// <summary>Stand-in files whose names start with one of these prefixes belong to this assembly.</summary>
        public readonly string[] FilePrefixes;

        StandIn(string name, string package, bool editorOnly, string[] references, params string[] filePrefixes)
        {
            Name = name; Package = package; EditorOnly = editorOnly; References = references; FilePrefixes = filePrefixes;
        }

        /// <summary>Where each type lives in Unity (checked in its sources): UnityEngine holds the engine modules
        /// (CoreModule with Unity.Jobs' IJob/JobHandle and UnityEvent, AnimationModule, XRModule with UnityEngine.XR's
        /// InputDevices, IMGUIModule, UIModule with Canvas, TextRenderingModule with Font) and is what every asmdef without
        /// noEngineReferences sees; the rest are the packages' own asmdef names: com.unity.inputsystem
        /// (InputSystem/Unity.InputSystem.asmdef), com.unity.ugui (Runtime/UnityEngine.UI.asmdef, which also holds
        /// UnityEngine.EventSystems), com.unity.xr.interaction.toolkit (Runtime/Unity.XR.Interaction.Toolkit.asmdef),
        /// com.unity.ai.inference (Runtime/Unity.InferenceEngine.asmdef), com.unity.test-framework
        /// (UnityEngine.TestRunner, UnityEditor.TestRunner). Order matters: the first matching prefix wins, and
        /// UnityEngine takes every stand-in file no other claims.</summary>
        public static readonly StandIn[] All =
        {
            new StandIn("Unity.InputSystem", "com.unity.inputsystem", false, new[] { "UnityEngine" }, "UnityEngine.InputSystem."),
            new StandIn("UnityEngine.UI", "com.unity.ugui", false, new[] { "UnityEngine" }, "UnityEngine.UI."),
            new StandIn("Unity.XR.Interaction.Toolkit", "com.unity.xr.interaction.toolkit", false,
                new[] { "UnityEngine", "UnityEngine.UI", "Unity.InputSystem" }, "UnityEngine.XR.Interaction.Toolkit."),
            new StandIn("Unity.InferenceEngine", "com.unity.ai.inference", false, new[] { "UnityEngine" }, "Unity.InferenceEngine."),
            // The test framework's namespaces (UnityEngine.TestTools: UnityTest, LogAssert; UnityEditor.TestTools) live in its
            // assemblies, so stand-ins for them are named after either.
            new StandIn("UnityEngine.TestRunner", "com.unity.test-framework", false, new[] { "UnityEngine" }, "UnityEngine.TestRunner.", "UnityEngine.TestTools."),
            new StandIn("UnityEditor.TestRunner", "com.unity.test-framework", true, new[] { "UnityEngine", "UnityEditor", "UnityEngine.TestRunner" }, "UnityEditor.TestRunner.", "UnityEditor.TestTools."),
            new StandIn("UnityEditor", null, true, new[] { "UnityEngine" }, "UnityEditor."),
            new StandIn("UnityEngine", null, false, Array.Empty<string>()),
        };

        /// <summary>Packages a package needs in turn (their package.json dependencies that matter here): XR Interaction
        /// Toolkit 3 depends on uGUI and the Input System, so a project without uGUI has no XRI either.</summary>
        public static readonly Dictionary<string, string[]> PackageDependencies = new Dictionary<string, string[]>
        {
            ["com.unity.xr.interaction.toolkit"] = new[] { "com.unity.ugui", "com.unity.inputsystem" },
        };

        /// <summary>The oldest editor a package installs in (its package.json "unity"), where later than the package's
        /// own minimum matters: com.unity.ai.inference 2.x says "unity": "6000.0".</summary>
        public static readonly Dictionary<string, string> PackageMinimumUnity = new Dictionary<string, string>
        {
            ["com.unity.ai.inference"] = "6000.0",
        };

        /// <summary>Every stand-in after the ones it references.</summary>
        public static List<StandIn> InDependencyOrder()
        {
            var order = new List<StandIn>();
            void Visit(StandIn s)
            {
                if (order.Contains(s)) return;
                foreach (var r in s.References) Visit(All.First(x => x.Name == r));
                order.Add(s);
            }
            foreach (var s in All) Visit(s);
            return order;
        }

        /// <summary>The stand-in sources of each assembly.</summary>
        public static Dictionary<StandIn, List<string>> Partition(string stubsDir)
        {
            var result = All.ToDictionary(s => s, s => new List<string>());
            foreach (var file in Directory.GetFiles(stubsDir, "*.cs", SearchOption.AllDirectories).OrderBy(f => f, StringComparer.Ordinal))
            {
                var name = Path.GetFileName(file);
                var owner = All.First(s => s.FilePrefixes.Length == 0 || s.FilePrefixes.Any(p => name.StartsWith(p, StringComparison.Ordinal)));
                result[owner].Add(file);
            }
            return result;
        }
    }
}
