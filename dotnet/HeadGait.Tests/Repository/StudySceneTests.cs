using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using HeadGait.Tooling;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>The study sample's scene: made by the generator, and internally consistent as Unity reads it.</summary>
    public class StudySceneTests
    {
        static string Package => RepositoryPaths.Package;
        static string Scene => File.ReadAllText(StudyScene.PathIn(Package)).Replace("\r\n", "\n");

        [Test]
        public void TheCommittedSceneIsTheGeneratorsOutput()
        {
            Assert.That(Scene, Is.EqualTo(StudyScene.Yaml(StudyScene.ScriptsIn(Package))),
                "run `dotnet run --project dotnet/HeadGait.Cli -- study scene Packages/com.headgait.legmotion`");
        }

        [Test]
        public void EveryReferenceResolvesAndTheHierarchyAgrees()
        {
            var docs = Regex.Split(Scene, @"^--- ", RegexOptions.Multiline).Skip(1).ToList();
            var ids = docs.Select(d => long.Parse(Regex.Match(d, @"^!u!\d+ &(\d+)").Groups[1].Value)).ToList();
            Assert.That(ids, Is.Unique);
            var known = new HashSet<long>(ids);
            foreach (Match m in Regex.Matches(Scene, @"\{fileID: (\d+)\}"))
                Assert.That(known.Contains(long.Parse(m.Groups[1].Value)) || m.Groups[1].Value == "0", $"fileID {m.Groups[1].Value} is not in the scene");

            var fathers = new Dictionary<long, long>();
            var children = new Dictionary<long, List<long>>();
            // A prefab instance's root is a stripped Transform; its father is the instance's m_TransformParent.
            foreach (var d in docs.Where(d => d.Contains(" stripped\nTransform:\n")))
            {
                long id = long.Parse(Regex.Match(d, @"&(\d+)").Groups[1].Value);
                string instance = Regex.Match(d, @"m_PrefabInstance: \{fileID: (\d+)\}").Groups[1].Value;
                var prefabInstance = docs.Single(p => p.StartsWith($"!u!1001 &{instance}\n"));
                fathers[id] = long.Parse(Regex.Match(prefabInstance, @"m_TransformParent: \{fileID: (\d+)\}").Groups[1].Value);
            }
            Assert.That(fathers, Has.Count.EqualTo(1), "the humanoid's prefab instance has its stripped root Transform");
            foreach (var d in docs.Where(d => d.Contains("\nTransform:\n") && !d.Contains(" stripped\n")))
            {
                long id = long.Parse(Regex.Match(d, @"&(\d+)").Groups[1].Value);
                fathers[id] = long.Parse(Regex.Match(d, @"m_Father: \{fileID: (\d+)\}").Groups[1].Value);
                children[id] = Regex.Matches(Regex.Match(d, @"m_Children:(.*?)\n  m_Father", RegexOptions.Singleline).Groups[1].Value, @"fileID: (\d+)")
                    .Select(m => long.Parse(m.Groups[1].Value)).ToList();
            }
            foreach (var (child, father) in fathers.Select(kv => (kv.Key, kv.Value)))
                if (father != 0) Assert.That(children[father], Does.Contain(child), $"transform {child}'s father {father} does not list it");
            foreach (var kv in children)
                foreach (long c in kv.Value) Assert.That(fathers[c], Is.EqualTo(kv.Key), $"transform {kv.Key} lists {c}, whose father is another");
        }

        [Test]
        public void TheSceneHoldsThePathTheStudyAndTheThreeConditions()
        {
            string scene = Scene;
            var scripts = StudyScene.ScriptsIn(Package);
            foreach (var guid in new[] { scripts.Runner, scripts.OperatorView, scripts.Switcher, scripts.SsqPanel })
                Assert.That(scene, Does.Contain($"guid: {guid}, type: 3"));
            Assert.That(scene, Does.Contain($"m_SourcePrefab: {{fileID: 100100000, guid: {StudyScene.HumanoidPrefabGuid}, type: 3}}"));
            foreach (var name in new[] { "Start", "Turn", "End", "Bridge Deck", "Pit Floor", "Block Avatar", "Humanoid Avatar", "SSQ Panel" })
                Assert.That(scene, Does.Contain($"m_Name: {name}\n"));
            foreach (var condition in new[] { "no-avatar", "block-avatar", "humanoid-avatar" })
                Assert.That(scene, Does.Contain($"- condition: {condition}\n"));
            // Start to Turn and Turn back to End: 8 m each way, the paper's 16 m.
            Assert.That(Position(scene, "Turn").z - Position(scene, "Start").z, Is.EqualTo(StudyScene.PathHalfLength).Within(1e-9));
            Assert.That(2 * StudyScene.PathHalfLength, Is.EqualTo(16));
            Assert.That(Position(scene, "Turn").z - Position(scene, "End").z, Is.EqualTo(8).Within(1e-9));
        }

        static (double x, double y, double z) Position(string scene, string name)
        {
            var docs = Regex.Split(scene, @"^--- ", RegexOptions.Multiline);
            var go = docs.Single(d => d.Contains("\nGameObject:\n") && d.Contains($"\n  m_Name: {name}\n"));
            string transform = Regex.Match(go, @"- component: \{fileID: (\d+)\}").Groups[1].Value;
            var t = docs.Single(d => d.StartsWith($"!u!4 &{transform}\n"));
            var p = Regex.Match(t, @"m_LocalPosition: \{x: ([-\d.]+), y: ([-\d.]+), z: ([-\d.]+)\}");
            double F(int i) => double.Parse(p.Groups[i].Value, System.Globalization.CultureInfo.InvariantCulture);
            return (F(1), F(2), F(3));
        }
    }
}
