using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Reflection;
using HeadGait.Editor;
using HeadGait.Tooling;
using HeadGait.Unity;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;
using YamlDotNet.RepresentationModel;
using Object = UnityEngine.Object;

namespace HeadGait.Tests
{
    /// <summary>
    /// Tools > HeadGait > Create Humanoid Clips and Override Controller and Create Prefabs build, with Unity's editor API
    /// (here its stand-ins, which keep what was built), what `headgait clips` writes into the package: the Humanoid clips'
    /// curves, keys and settings; an override controller pairing each gait clip with its Humanoid version; and the two
    /// prefabs with the shipped hierarchy, transforms, components, meshes, material and references.
    /// </summary>
    public class EditorPrefabBuilderTests
    {
        const string Folder = "Assets/HeadGait Builder Test";
        const string PackagePath = "Packages/com.headgait.legmotion/";

        static string Package => RepositoryPaths.Package;

        static PhaseMap ShippedMap => CorrelationTemplate.Load(Path.Combine(Package, GaitAssetFiles.CorTemplate)).PhaseMap;

        static readonly List<string> built = new List<string>();

        static string At(string name)
        {
            string path = Folder + "/" + name;
            built.Add(path);
            return path;
        }

        [TearDown]
        public void DeleteBuilt()
        {
            foreach (var p in built) AssetDatabase.DeleteAsset(p);
            built.Clear();
        }

        [Test]
        public void TheEditorBuiltHumanoidClipsAreTheShippedOnes()
        {
            var clips = new GaitClips(ShippedMap);
            foreach (var state in GaitClips.All)
                Assert.That(EditorClipBuilderTests.Differences(GaitAssetFiles.HumanoidClipPath(state), HumanoidClipBuilder.Build(clips, state), typeof(Animator), "95"),
                    Is.Empty, GaitClips.Name(state));
        }

        /// <summary>The clip name a GUID of the package stands for (its file name without extension).</summary>
        static string ClipNameOf(string guid)
        {
            foreach (var meta in Directory.GetFiles(Path.Combine(Package, GaitAssetFiles.AnimationFolder), "*.anim.meta", SearchOption.AllDirectories))
                if (UnityMeta.GuidOf(meta) == guid)
                    return (Path.GetFileName(Path.GetDirectoryName(meta)) == "Humanoid" ? "Humanoid/" : "") + Path.GetFileNameWithoutExtension(Path.GetFileNameWithoutExtension(meta));
            return "(guid " + guid + ")";
        }

        [Test]
        public void TheOverrideControllerPlaysEachGaitClipAsItsHumanoidVersionAsShipped()
        {
            var generic = GaitClipBuilder.Create(Folder, ShippedMap);
            foreach (var s in GaitClips.All) built.Add(Folder + "/" + GaitClips.Name(s) + ".anim");
            var controller = LocomotionControllerBuilder.Create(At("HeadGait Legs.controller"), generic);
            AssetDatabase.CreateFolder(Folder, "Humanoid");
            var humanoid = HumanoidClipBuilder.Create(Folder + "/Humanoid", ShippedMap);
            foreach (var s in GaitClips.All) built.Add(Folder + "/Humanoid/" + GaitClips.Name(s) + ".anim");
            var originals = generic.ToDictionary(p => p.Key, p => (AnimationClip)p.Value);
            HumanoidClipBuilder.CreateOverrideController(At("HeadGait Legs Humanoid.overrideController"), controller, originals, humanoid);

            var saved = AssetDatabase.LoadAssetAtPath<AnimatorOverrideController>(Folder + "/HeadGait Legs Humanoid.overrideController");
            Assert.That(saved, Is.Not.Null, "saved as an asset");
            Assert.That(saved.runtimeAnimatorController, Is.SameAs(controller));
            Assert.That(saved.name, Is.EqualTo("HeadGait Legs Humanoid"));
            var pairs = new List<KeyValuePair<AnimationClip, AnimationClip>>();
            saved.GetOverrides(pairs);
            var builtPairs = pairs.Select(p => (p.Key.name, p.Value == null ? "(none)" : "Humanoid/" + p.Value.name)).OrderBy(p => p.Item1, StringComparer.Ordinal).ToList();
            Assert.That(builtPairs.All(p => AssetDatabase.GetAssetPath(humanoid[GaitClips.All.First(s => GaitClips.Name(s) == p.Item1)]).StartsWith(Folder + "/Humanoid/", StringComparison.Ordinal)), Is.True);

            var shipped = UnityYamlFile.Parse(File.ReadAllText(Path.Combine(Package, GaitAssetFiles.HumanoidController)), GaitAssetFiles.HumanoidController).Single(d => d.ClassId == 221);
            var shippedPairs = ((YamlSequenceNode)shipped.Node("m_Clips")).Children.Cast<YamlMappingNode>()
                .Select(c => (ClipNameOf(Guid(c, "m_OriginalClip")), ClipNameOf(Guid(c, "m_OverrideClip")))).OrderBy(p => p.Item1, StringComparer.Ordinal).ToList();
            Assert.That(builtPairs, Is.EqualTo(shippedPairs));
            Assert.That(builtPairs, Has.Count.EqualTo(6));
        }

        static string Guid(YamlMappingNode entry, string key) => ((YamlScalarNode)((YamlMappingNode)entry.Children[new YamlScalarNode(key)]).Children[new YamlScalarNode("guid")]).Value;

        /// <summary>A GameObject of a saved prefab YAML: its path below the root, transform and components (class, and script GUID).</summary>
        sealed class YamlObject
        {
            public string Name;
            public long Father;
            public double[] Position, Rotation, Scale;
            public List<(int ClassId, UnityObject Doc)> Components = new List<(int, UnityObject)>();
        }

        static Dictionary<string, YamlObject> ShippedHierarchy(string file, out List<UnityObject> docs)
        {
            docs = UnityYamlFile.Parse(File.ReadAllText(Path.Combine(Package, file)), file);
            var byId = docs.ToDictionary(d => d.FileId);
            static double N(YamlNode n, string k) => double.Parse(((YamlScalarNode)((YamlMappingNode)n).Children[new YamlScalarNode(k)]).Value, CultureInfo.InvariantCulture);
            static long Ref(YamlNode n) => long.Parse(((YamlScalarNode)((YamlMappingNode)n).Children[new YamlScalarNode("fileID")]).Value, CultureInfo.InvariantCulture);
            var objects = new Dictionary<long, YamlObject>(); // by Transform id
            var transformOf = new Dictionary<long, long>();   // GameObject id -> Transform id
            foreach (var go in docs.Where(d => d.ClassId == 1))
            {
                var o = new YamlObject { Name = go.Scalar("m_Name") };
                foreach (YamlMappingNode c in ((YamlSequenceNode)go.Node("m_Component")).Children)
                {
                    var doc = byId[Ref(c.Children[new YamlScalarNode("component")])];
                    if (doc.ClassId == 4)
                    {
                        objects[doc.FileId] = o;
                        transformOf[go.FileId] = doc.FileId;
                        var p = doc.Node("m_LocalPosition");
                        var q = doc.Node("m_LocalRotation");
                        var s = doc.Node("m_LocalScale");
                        o.Position = new[] { N(p, "x"), N(p, "y"), N(p, "z") };
                        o.Rotation = new[] { N(q, "x"), N(q, "y"), N(q, "z"), N(q, "w") };
                        o.Scale = new[] { N(s, "x"), N(s, "y"), N(s, "z") };
                        o.Father = Ref(doc.Node("m_Father"));
                    }
                    else o.Components.Add((doc.ClassId, doc));
                }
            }
            var result = new Dictionary<string, YamlObject>();
            foreach (var (id, o) in objects)
            {
                var names = new List<string>();
                for (var t = id; objects[t].Father != 0; t = objects[t].Father) names.Insert(0, objects[t].Name);
                result[string.Join("/", names)] = o;
            }
            return result;
        }

        static void Walk(Transform t, string path, Dictionary<string, GameObject> into)
        {
            into[path] = t.gameObject;
            for (int i = 0; i < t.childCount; i++)
            {
                var child = t.GetChild(i);
                Walk(child, path.Length == 0 ? child.gameObject.name : path + "/" + child.gameObject.name, into);
            }
        }

        static object Field(object o, string name)
        {
            for (var type = o.GetType(); type != null; type = type.BaseType)
            {
                var f = type.GetField(name, BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.DeclaredOnly);
                if (f != null) return f.GetValue(o);
            }
            throw new InvalidOperationException($"{o.GetType().Name} has no field {name}");
        }

        static readonly Dictionary<string, string> MeshIds = new Dictionary<string, string>
        {
            ["Cube"] = UnityHierarchyYaml.Cube.ToString(CultureInfo.InvariantCulture),
            ["Sphere"] = UnityHierarchyYaml.Sphere.ToString(CultureInfo.InvariantCulture),
            ["Capsule"] = UnityHierarchyYaml.Capsule.ToString(CultureInfo.InvariantCulture),
        };

        /// <summary>The built prefab against the shipped YAML: one line per difference.</summary>
        static List<string> Differences(string file, GameObject asset, Material material, RuntimeAnimatorController controller)
        {
            var problems = new List<string>();
            var shipped = ShippedHierarchy(file, out _);
            var builtObjects = new Dictionary<string, GameObject>();
            Walk(asset.transform, "", builtObjects);
            var shippedRoot = shipped[""];
            if (asset.name != shippedRoot.Name) problems.Add($"root named {asset.name}, shipped {shippedRoot.Name}");
            foreach (var path in shipped.Keys.Except(builtObjects.Keys)) problems.Add($"{path}: not built");
            foreach (var path in builtObjects.Keys.Except(shipped.Keys)) problems.Add($"{path}: built, not shipped");
            string mannequinMaterial = GaitAssetFiles.GuidOf(Package, "Runtime/Materials/HeadGait Mannequin.mat");
            foreach (var path in shipped.Keys.Intersect(builtObjects.Keys))
            {
                var y = shipped[path];
                var go = builtObjects[path];
                var t = go.transform;
                bool Near(double a, double b) => Math.Abs(a - b) < 2e-6;
                var q = t.localRotation;
                double sign = Math.Sign(q.w) == Math.Sign(y.Rotation[3]) || q.w == 0 ? 1 : -1;
                if (!Near(t.localPosition.x, y.Position[0]) || !Near(t.localPosition.y, y.Position[1]) || !Near(t.localPosition.z, y.Position[2]))
                    problems.Add($"{path}: position {t.localPosition.x} {t.localPosition.y} {t.localPosition.z}, shipped {string.Join(" ", y.Position)}");
                if (!Near(sign * q.x, y.Rotation[0]) || !Near(sign * q.y, y.Rotation[1]) || !Near(sign * q.z, y.Rotation[2]) || !Near(sign * q.w, y.Rotation[3]))
                    problems.Add($"{path}: rotation {q.x} {q.y} {q.z} {q.w}, shipped {string.Join(" ", y.Rotation)}");
                if (!Near(t.localScale.x, y.Scale[0]) || !Near(t.localScale.y, y.Scale[1]) || !Near(t.localScale.z, y.Scale[2]))
                    problems.Add($"{path}: scale {t.localScale.x} {t.localScale.y} {t.localScale.z}, shipped {string.Join(" ", y.Scale)}");

                var components = go.GetComponents<Component>().Where(c => !(c is Transform)).ToList();
                string Kind(Component c) => c is MeshFilter ? "33" : c is MeshRenderer ? "23" : c is Animator ? "95" : "114 " + c.GetType().Name;
                string ShippedKind((int ClassId, UnityObject Doc) c) => c.ClassId == 114
                    ? "114 " + Path.GetFileNameWithoutExtension(ScriptPathOf(Guid((YamlMappingNode)c.Doc.Body, "m_Script")))
                    : c.ClassId.ToString(CultureInfo.InvariantCulture);
                var kinds = components.Select(Kind).ToList();
                var shippedKinds = y.Components.Select(ShippedKind).ToList();
                if (!kinds.SequenceEqual(shippedKinds)) problems.Add($"{path}: components {string.Join(", ", kinds)}, shipped {string.Join(", ", shippedKinds)}");
                foreach (var (classId, doc) in y.Components)
                {
                    if (classId == 33)
                    {
                        var mesh = go.GetComponent<MeshFilter>()?.sharedMesh;
                        string id = ((YamlScalarNode)((YamlMappingNode)doc.Node("m_Mesh")).Children[new YamlScalarNode("fileID")]).Value;
                        if (mesh == null || !MeshIds.TryGetValue(mesh.name, out var builtId) || builtId != id) problems.Add($"{path}: mesh {mesh?.name}, shipped fileID {id}");
                    }
                    if (classId == 23)
                    {
                        var r = go.GetComponent<MeshRenderer>();
                        string guid = ((YamlScalarNode)((YamlMappingNode)((YamlSequenceNode)doc.Node("m_Materials")).Children[0]).Children[new YamlScalarNode("guid")]).Value;
                        if (r == null || r.sharedMaterials.Length != 1 || !ReferenceEquals(r.sharedMaterial, material) || guid != mannequinMaterial)
                            problems.Add($"{path}: material {r?.sharedMaterial?.name} ({r?.sharedMaterials.Length}), shipped guid {guid}");
                    }
                    if (classId == 95 && !ReferenceEquals(go.GetComponent<Animator>()?.runtimeAnimatorController, controller))
                        problems.Add($"{path}: the Animator plays {go.GetComponent<Animator>()?.runtimeAnimatorController?.name}, not the controller");
                }
            }
            return problems;
        }

        static string ScriptPathOf(string guid)
        {
            foreach (var script in new[] { GaitAssetFiles.GaitLegAnimatorScript, GaitAssetFiles.HeadImuSourceScript, GaitAssetFiles.FollowHeadScript, GaitAssetFiles.RecordingPlayerScript })
                if (GaitAssetFiles.GuidOf(Package, script) == guid) return script;
            return "(script " + guid + ")";
        }

        [Test]
        public void TheEditorBuiltPrefabsAreTheShippedOnes()
        {
            var material = new Material(Shader.Find("HeadGait/Primitive")) { name = "HeadGait Mannequin" };
            AssetDatabase.CreateAsset(material, At("HeadGait Mannequin.mat"));
            var template = new TextAsset(File.ReadAllText(Path.Combine(Package, GaitAssetFiles.CorTemplate))) { name = "cor_template" };
            AssetDatabase.CreateAsset(template, At("cor_template.txt"));
            var controller = LocomotionControllerBuilder.Create(At("HeadGait Legs.controller"), new Dictionary<LocomotionState, Motion>());

            GameObject legs, mannequin;
            using (new StandInEditMode())
            {
                legs = GaitPrefabBuilder.CreateLegs(At("HeadGait Legs.prefab"), controller, material, template);
                mannequin = GaitPrefabBuilder.CreateMannequin(At("HeadGait Mannequin.prefab"), controller, material);
            }
            Assert.That(Application.isPlaying, Is.True, "edit mode ends with the builders");

            Assert.That(AssetDatabase.LoadAssetAtPath<GameObject>(Folder + "/HeadGait Legs.prefab"), Is.SameAs(legs));
            Assert.That(AssetDatabase.LoadAssetAtPath<GameObject>(Folder + "/HeadGait Mannequin.prefab"), Is.SameAs(mannequin));
            Assert.That(Differences(GaitAssetFiles.LegsPrefab, legs, material, controller), Is.Empty);
            Assert.That(Differences(GaitAssetFiles.MannequinPrefab, mannequin, material, controller), Is.Empty);

            // The drop-in's references, as the shipped prefab sets them; the others keep their defaults.
            var animator = legs.GetComponent<GaitLegAnimator>();
            var avatarAnimator = legs.transform.Find(Mannequin.LegsAvatar).gameObject.GetComponent<Animator>();
            Assert.That(Field(animator, "animator"), Is.SameAs(avatarAnimator), "the Gait Leg Animator drives the avatar's Animator in the saved prefab");
            Assert.That(Field(animator, "corTemplate"), Is.SameAs(template));
            Assert.That(Field(animator, "classifier"), Is.EqualTo(GaitClassifierKind.Correlation));
            Assert.That(Field(legs.GetComponent<HeadImuSource>(), "target"), Is.SameAs(animator), "the source feeds the prefab's own Gait Leg Animator");
            Assert.That(Field(legs.GetComponent<HeadImuSource>(), "mode"), Is.EqualTo(HeadImuMode.XRDevice));
            Assert.That(Field(animator, "runner"), Is.Null, "no Awake ran: outside Play Mode the editor sends scripts no messages");
            var shippedLegs = UnityYamlFile.Parse(File.ReadAllText(Path.Combine(Package, GaitAssetFiles.LegsPrefab)), GaitAssetFiles.LegsPrefab);
            Assert.That(shippedLegs.Where(d => d.ClassId == 114).Select(d => ScriptPathOf(Guid(d.Body, "m_Script"))),
                Is.EquivalentTo(new[] { GaitAssetFiles.GaitLegAnimatorScript, GaitAssetFiles.HeadImuSourceScript, GaitAssetFiles.FollowHeadScript }));
        }

        [Test]
        public void SavingAPrefabCopiesTheHierarchyAndRefusesAPathThatIsNoPrefab()
        {
            using (new StandInEditMode())
            {
                var root = new GameObject("Root");
                var child = new GameObject("Child");
                child.transform.SetParent(root.transform, false);
                var source = root.AddComponent<HeadImuSource>();
                var legs = child.AddComponent<GaitLegAnimator>();
                using (var so = new SerializedObject(source))
                {
                    Assert.That(so.FindProperty("no such field"), Is.Null);
                    so.FindProperty("target").objectReferenceValue = legs;
                    Assert.That(Field(source, "target"), Is.Null, "nothing changes before Apply");
                    Assert.That(so.ApplyModifiedPropertiesWithoutUndo(), Is.True);
                }
                Assert.That(Field(source, "target"), Is.SameAs(legs));
                var asset = PrefabUtility.SaveAsPrefabAsset(root, At("Copy.prefab"));
                Assert.That(asset, Is.Not.SameAs(root), "the asset is a copy");
                var copiedLegs = asset.transform.Find("Child").gameObject.GetComponent<GaitLegAnimator>();
                Assert.That(Field(asset.GetComponent<HeadImuSource>(), "target"), Is.SameAs(copiedLegs), "a reference inside the hierarchy points into the copy");
                Object.DestroyImmediate(root);
                Assert.That(asset == null, Is.False, "destroying the instance leaves the asset");
                Assert.Throws<ArgumentException>(() => PrefabUtility.SaveAsPrefabAsset(asset, Folder + "/Copy.asset"));
                Assert.Throws<ArgumentException>(() => PrefabUtility.SaveAsPrefabAsset(asset, "Elsewhere/Copy.prefab"));
                Assert.Throws<ArgumentNullException>(() => PrefabUtility.SaveAsPrefabAsset(asset, ""));
            }
        }
    }
}
