using System.IO;
using System.Linq;
using System.Text.Json;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>package.json declares directly every built-in module the package's code and assets use, rather than
    /// relying on another package to pull it in (a project may disable a module no declared dependency needs).</summary>
    public class PackageManifestTests
    {
        static string Package => RepositoryPaths.Package;

        [Test]
        public void EveryModuleThePackageUsesIsADirectDependency()
        {
            using var json = JsonDocument.Parse(File.ReadAllText(Path.Combine(Package, "package.json")));
            var declared = json.RootElement.GetProperty("dependencies").EnumerateObject().Select(p => p.Name).ToHashSet();
            string code = string.Join("\n", new[] { "Runtime", "Editor", "Samples~" }.SelectMany(d =>
                Directory.GetFiles(Path.Combine(Package, d), "*.cs", SearchOption.AllDirectories)).Select(File.ReadAllText));
            string assets = string.Join("\n", Directory.GetFiles(Package, "*.*", SearchOption.AllDirectories)
                .Where(f => f.EndsWith(".unity") || f.EndsWith(".prefab")).Select(File.ReadAllText));
            // Module (UnityCsReference Modules/*): what in the package needs it.
            var uses = new (string module, bool used)[]
            {
                ("com.unity.modules.imgui", Regex.IsMatch(code, @"\bGUI(Layout)?\.")),                      // IMGUIModule: GUI, GUILayout
                ("com.unity.modules.animation", Regex.IsMatch(code, @"\bAnimator\b") || assets.Contains("--- !u!95 ")), // AnimationModule: Animator
                ("com.unity.modules.xr", Regex.IsMatch(code, @"\bUnityEngine\.XR\b")),                      // XRModule: InputDevices
                ("com.unity.modules.audio", assets.Contains("--- !u!81 ")),                                 // AudioModule: AudioListener
            };
            foreach (var (module, used) in uses)
                if (used) Assert.That(declared, Does.Contain(module), $"the package uses {module} but package.json does not declare it");
        }
    }
}
