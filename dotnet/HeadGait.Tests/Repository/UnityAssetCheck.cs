using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using HeadGait.Tooling;
using YamlDotNet.RepresentationModel;

namespace HeadGait.Tests
{
    /// <summary>
    /// Checks the Unity assets of the package and its samples without Unity: every reference resolves, scripts are what
    /// their references say, the controller matches the core's states, parameters and transitions, and the clips' feet land
    /// where the phase map says. Returns one line per problem, naming the file.
    /// </summary>
    public static class UnityAssetCheck
    {
        /// <summary>Extensions of Unity's YAML-serialized assets.</summary>
        static readonly string[] AssetExtensions = { ".unity", ".prefab", ".controller", ".overrideController", ".anim", ".asset", ".mat" };

        /// <summary>
        /// GUIDs that are not files in the project: Unity's built-in resources ('unity default resources' e000...,
        /// 'unity_builtin_extra' f000...) and the null GUID. No package other than this one is referred to.
        /// </summary>
        static readonly HashSet<string> BuiltinGuids = new HashSet<string>
        {
            "0000000000000000e000000000000000", "0000000000000000f000000000000000", "00000000000000000000000000000000",
        };

        /// <summary>A foot is on the ground when its lowest point is within this height (metres).</summary>
        const double Contact = 0.002;

        public static List<string> Problems(string package)
        {
            var problems = new List<string>();
            var guids = new Dictionary<string, string>();
            foreach (var meta in Directory.GetFiles(package, "*.meta", SearchOption.AllDirectories))
            {
                if (meta.Contains(Path.DirectorySeparatorChar + "Documentation~" + Path.DirectorySeparatorChar)) continue;
                var stream = new YamlStream();
                try
                {
                    stream.Load(new StringReader(File.ReadAllText(meta)));
                }
                catch (YamlDotNet.Core.YamlException e)
                {
                    problems.Add($"{meta}: not YAML ({e.Message})");
                    continue;
                }
                var root = stream.Documents.Count == 1 ? stream.Documents[0].RootNode as YamlMappingNode : null;
                if (root == null || !root.Children.TryGetValue(new YamlScalarNode("guid"), out var g))
                {
                    problems.Add($"{meta}: no guid");
                    continue;
                }
                guids[((YamlScalarNode)g).Value] = meta.Substring(0, meta.Length - ".meta".Length);
            }

            var cache = new Dictionary<string, List<UnityObject>>();
            List<UnityObject> Load(string path)
            {
                if (!cache.TryGetValue(path, out var docs))
                {
                    try
                    {
                        docs = UnityYamlFile.Parse(File.ReadAllText(path), path);
                    }
                    catch (FormatException e)
                    {
                        problems.Add(e.Message);
                        docs = new List<UnityObject>();
                    }
                    cache[path] = docs;
                }
                return docs;
            }

            var assets = Directory.GetFiles(package, "*", SearchOption.AllDirectories)
                .Where(f => AssetExtensions.Contains(Path.GetExtension(f)) && !f.Contains("Documentation~")).OrderBy(f => f, StringComparer.Ordinal).ToList();
            foreach (var asset in assets)
            {
                var docs = Load(asset);
                var local = new HashSet<long>(docs.Select(d => d.FileId));
                foreach (var d in docs)
                    foreach (var (key, reference) in References(d.Body, null))
                        CheckReference(asset, d, key, reference, local, guids, Load, problems);
            }

            // Unity writes every scene with its settings objects; a scene without them loads with defaults but is not one
            // Unity wrote (and the Lighting window shows no settings to save).
            foreach (var scene in assets.Where(a => a.EndsWith(".unity", StringComparison.Ordinal)))
                foreach (var (classId, type) in new[] { (29, "OcclusionCullingSettings"), (104, "RenderSettings"), (157, "LightmapSettings"), (196, "NavMeshSettings") })
                    if (!Load(scene).Any(d => d.ClassId == classId && d.Type == type)) problems.Add($"{scene}: no {type} (class {classId}) document");
            foreach (var asset in assets.Where(a => a.EndsWith(".unity", StringComparison.Ordinal) || a.EndsWith(".prefab", StringComparison.Ordinal)))
            {
                CheckHierarchy(asset, Load(asset), guids, Load, problems);
                CheckRendererMaterials(asset, Load(asset), guids, Load, problems);
            }

            var map = LoadPhaseMap(package, problems);
            foreach (var controller in assets.Where(a => a.EndsWith(".controller", StringComparison.Ordinal)))
                CheckController(controller, Load(controller), guids, Load, problems);
            foreach (var over in assets.Where(a => a.EndsWith(".overrideController", StringComparison.Ordinal)))
                CheckOverrideController(over, Load(over), guids, Load, problems);
            if (map != null)
                foreach (var clip in assets.Where(a => a.EndsWith(".anim", StringComparison.Ordinal)))
                    CheckClipContacts(clip, Load(clip), map, problems);
            return problems;
        }

        static PhaseMap LoadPhaseMap(string package, List<string> problems)
        {
            string path = Path.Combine(package, GaitAssetFiles.CorTemplate);
            if (!File.Exists(path))
            {
                problems.Add($"{path}: missing; the clips' contacts are checked against its phase map");
                return null;
            }
            return CorrelationTemplate.Load(path).PhaseMap;
        }

        /// <summary>Every {fileID: ...} mapping in a node, with the key it hangs under.</summary>
        static IEnumerable<(string Key, YamlMappingNode Reference)> References(YamlNode node, string key)
        {
            if (node is YamlMappingNode map)
            {
                if (map.Children.ContainsKey(new YamlScalarNode("fileID")))
                {
                    yield return (key, map);
                    yield break;
                }
                foreach (var child in map.Children)
                    foreach (var r in References(child.Value, ((YamlScalarNode)child.Key).Value))
                        yield return r;
            }
            else if (node is YamlSequenceNode seq)
            {
                foreach (var item in seq.Children)
                    foreach (var r in References(item, key))
                        yield return r;
            }
        }

        static string Get(YamlMappingNode map, string key) => map.Children.TryGetValue(new YamlScalarNode(key), out var n) && n is YamlScalarNode s ? s.Value : null;

        static void CheckReference(string asset, UnityObject doc, string key, YamlMappingNode reference, HashSet<long> local,
                                   Dictionary<string, string> guids, Func<string, List<UnityObject>> load, List<string> problems)
        {
            string where = $"{asset}: &{doc.FileId} {doc.Type}.{key}";
            if (!long.TryParse(Get(reference, "fileID"), NumberStyles.Integer, CultureInfo.InvariantCulture, out long fileId))
            {
                problems.Add($"{where}: fileID is not a number");
                return;
            }
            string guid = Get(reference, "guid");
            if (guid == null)
            {
                if (fileId != 0 && !local.Contains(fileId)) problems.Add($"{where}: local fileID {fileId} resolves to nothing in the file");
                return;
            }
            if (BuiltinGuids.Contains(guid)) return;
            if (!guids.TryGetValue(guid, out var target))
            {
                problems.Add($"{where}: guid {guid} resolves to no .meta in the package or its samples");
                return;
            }
            if (key == "m_Script")
            {
                string cls = Path.GetFileNameWithoutExtension(target);
                if (!target.EndsWith(".cs", StringComparison.Ordinal) || !Regex.IsMatch(File.ReadAllText(target), @"\bclass\s+" + Regex.Escape(cls) + @"\b"))
                    problems.Add($"{where}: script guid {guid} is {target}, not a .cs file declaring class {cls}");
                else if (doc.Stripped == false && !ScriptFieldsExist(doc, File.ReadAllText(target), out string missing))
                    problems.Add($"{where}: field '{missing}' is not declared in {Path.GetFileName(target)}");
                return;
            }
            if (AssetExtensions.Contains(Path.GetExtension(target)))
            {
                var docs = load(target);
                bool found = docs.Any(d => d.FileId == fileId) || (fileId == GaitAssetFiles.PrefabRootId && target.EndsWith(".prefab", StringComparison.Ordinal));
                if (!found) problems.Add($"{where}: fileID {fileId} is not an object of {target}");
            }
        }

        static long RefId(YamlNode node) => node is YamlMappingNode m && long.TryParse(Get(m, "fileID"), NumberStyles.Integer, CultureInfo.InvariantCulture, out long id) ? id : 0;

        static IEnumerable<long> RefIds(YamlNode node) => node is YamlSequenceNode seq ? seq.Children.Select(RefId) : Enumerable.Empty<long>();

        /// <summary>
        /// The Transform tree of a scene or prefab agrees both ways: each Transform (class 4, RectTransform 224) is listed in
        /// its m_Father's m_Children, and each child listed names that father. A prefab instance (1001) under a scene object
        /// (m_Modification.m_TransformParent) shows its root as a `stripped` Transform (m_PrefabInstance: the instance;
        /// m_CorrespondingSourceObject: the source prefab's root Transform), which the parent lists like any child; a missing
        /// one leaves the instance unparented when Unity loads the scene.
        /// </summary>
        static void CheckHierarchy(string file, List<UnityObject> docs, Dictionary<string, string> guids, Func<string, List<UnityObject>> load, List<string> problems)
        {
            bool IsTransform(UnityObject d) => d.ClassId == 4 || d.ClassId == 224;
            var byId = new Dictionary<long, UnityObject>();
            foreach (var d in docs) byId[d.FileId] = d;
            long ParentOfInstance(long instance)
                => byId.TryGetValue(instance, out var p) && p.ClassId == 1001 && p.Node("m_Modification") is YamlMappingNode m
                    && m.Children.TryGetValue(new YamlScalarNode("m_TransformParent"), out var parent) ? RefId(parent) : 0;
            long FatherOf(UnityObject t) => t.Stripped ? ParentOfInstance(RefId(t.Node("m_PrefabInstance"))) : RefId(t.Node("m_Father"));

            foreach (var t in docs.Where(IsTransform))
            {
                long father = FatherOf(t);
                if (father == 0) continue;
                if (!byId.TryGetValue(father, out var f) || !IsTransform(f)) problems.Add($"{file}: transform &{t.FileId}'s father &{father} is not a Transform in the file");
                else if (!RefIds(f.Node("m_Children")).Contains(t.FileId))
                    problems.Add($"{file}: transform &{t.FileId}{(t.Stripped ? " (a prefab instance's root)" : "")} is not listed in its father &{father}'s m_Children");
            }
            foreach (var t in docs.Where(d => IsTransform(d) && !d.Stripped))
                foreach (long c in RefIds(t.Node("m_Children")))
                    if (byId.TryGetValue(c, out var child) && IsTransform(child) && FatherOf(child) != t.FileId)
                        problems.Add($"{file}: transform &{t.FileId} lists &{c} as a child, whose father is &{FatherOf(child)}");

            foreach (var instance in docs.Where(d => d.ClassId == 1001))
            {
                string source = (instance.Node("m_SourcePrefab") as YamlMappingNode) is YamlMappingNode sp ? Get(sp, "guid") : null;
                var roots = docs.Where(d => IsTransform(d) && d.Stripped && RefId(d.Node("m_PrefabInstance")) == instance.FileId).ToList();
                if (ParentOfInstance(instance.FileId) != 0 && roots.Count == 0)
                    problems.Add($"{file}: prefab instance &{instance.FileId} under &{ParentOfInstance(instance.FileId)} has no stripped root Transform");
                foreach (var root in roots)
                {
                    var corresponding = root.Node("m_CorrespondingSourceObject") as YamlMappingNode;
                    string guid = corresponding == null ? null : Get(corresponding, "guid");
                    var prefabRoot = guid != null && guid == source && guids.TryGetValue(guid, out var prefab)
                        ? load(prefab).FirstOrDefault(d => d.FileId == RefId(corresponding)) : null;
                    if (prefabRoot == null || !IsTransform(prefabRoot) || RefId(prefabRoot.Node("m_Father")) != 0)
                        problems.Add($"{file}: stripped transform &{root.FileId} of prefab instance &{instance.FileId} is not the root Transform of its source prefab");
                }
            }
        }

        /// <summary>
        /// Every renderer (MeshRenderer 23, SkinnedMeshRenderer 137) and every prefab-instance override of m_Materials names
        /// a material that renders in the built-in pipeline and in URP (Unity 6's VR template). Unity shows magenta for a
        /// missing material and for a shader with no SubShader or Pass the active pipeline can draw: the built-in
        /// Default-Material and Standard shader under URP, URP's own shaders under the built-in pipeline.
        /// </summary>
        static void CheckRendererMaterials(string file, List<UnityObject> docs, Dictionary<string, string> guids, Func<string, List<UnityObject>> load, List<string> problems)
        {
            void Check(string where, YamlNode reference)
            {
                var r = reference as YamlMappingNode;
                string guid = r == null ? null : Get(r, "guid");
                long id = RefId(reference);
                if (id == 0) { problems.Add($"{where}: no material (magenta in every pipeline)"); return; }
                if (guid == null || BuiltinGuids.Contains(guid))
                {
                    problems.Add($"{where}: built-in material {id}{(id == 10303 ? " (Default-Material, Standard shader)" : "")} renders magenta in URP");
                    return;
                }
                if (!guids.TryGetValue(guid, out var material) || !material.EndsWith(".mat", StringComparison.Ordinal)) return; // CheckReference reports it
                var m = load(material).FirstOrDefault(d => d.ClassId == 21);
                var shaderRef = m?.Node("m_Shader") as YamlMappingNode;
                string shaderGuid = shaderRef == null ? null : Get(shaderRef, "guid");
                if (shaderGuid == null || BuiltinGuids.Contains(shaderGuid))
                {
                    problems.Add($"{where}: {Path.GetFileName(material)} uses built-in shader {RefId(shaderRef)}{(RefId(shaderRef) == 46 ? " (Standard)" : "")}, magenta in URP");
                    return;
                }
                if (!guids.TryGetValue(shaderGuid, out var shader) || !shader.EndsWith(".shader", StringComparison.Ordinal))
                {
                    problems.Add($"{where}: {Path.GetFileName(material)}'s shader guid {shaderGuid} is no .shader in the package");
                    return;
                }
                string source = File.ReadAllText(shader);
                foreach (var pipeline in new[] { ShaderPasses.BuiltIn, ShaderPasses.Universal })
                    if (!ShaderPasses.Draws(source, pipeline))
                        problems.Add($"{where}: {Path.GetFileName(material)}'s shader {Path.GetFileName(shader)} has no SubShader and Pass the {pipeline} pipeline draws (magenta there)");
                if (ShaderPasses.Draws(source, ShaderPasses.Universal) && !ShaderPasses.VisibleUnderUrpDepthPriming(source))
                    problems.Add($"{where}: {Path.GetFileName(material)}'s shader {Path.GetFileName(shader)} is not drawn in URP's depth prepass (no DepthOnly, or no DepthNormals/DepthNormalsOnly pass): invisible under depth priming (ZTest Equal)");
            }
            foreach (var d in docs.Where(d => (d.ClassId == 23 || d.ClassId == 137) && !d.Stripped))
            {
                var list = d.Node("m_Materials") as YamlSequenceNode;
                if (list == null || list.Children.Count == 0) { problems.Add($"{file}: &{d.FileId} {d.Type} has no material (magenta in every pipeline)"); continue; }
                for (int i = 0; i < list.Children.Count; i++) Check($"{file}: &{d.FileId} {d.Type}.m_Materials[{i}]", list.Children[i]);
            }
            foreach (var instance in docs.Where(d => d.ClassId == 1001))
                if (instance.Node("m_Modification") is YamlMappingNode mod && mod.Children.TryGetValue(new YamlScalarNode("m_Modifications"), out var mods) && mods is YamlSequenceNode seq)
                    foreach (YamlMappingNode change in seq.Children.OfType<YamlMappingNode>())
                        if ((Get(change, "propertyPath") ?? "").StartsWith("m_Materials.Array.data[", StringComparison.Ordinal))
                            Check($"{file}: prefab instance &{instance.FileId} {Get(change, "propertyPath")}", change.Children[new YamlScalarNode("objectReference")]);
        }

        /// <summary>Every serialized field of a MonoBehaviour (those not starting with m_) is declared in its script.</summary>
        static bool ScriptFieldsExist(UnityObject doc, string source, out string missing)
        {
            foreach (var child in doc.Body.Children)
            {
                string name = ((YamlScalarNode)child.Key).Value;
                if (name.StartsWith("m_", StringComparison.Ordinal)) continue;
                if (!Regex.IsMatch(source, @"\b" + Regex.Escape(name) + @"\s*(=|;)"))
                {
                    missing = name;
                    return false;
                }
            }
            missing = null;
            return true;
        }

        static void CheckController(string file, List<UnityObject> docs, Dictionary<string, string> guids, Func<string, List<UnityObject>> load, List<string> problems)
        {
            var byId = docs.ToDictionary(d => d.FileId);
            var controller = docs.FirstOrDefault(d => d.ClassId == 91);
            if (controller == null)
            {
                problems.Add($"{file}: no AnimatorController (class 91)");
                return;
            }
            // Parameters: exactly AnimatorParameters, ints where the core writes ints (m_Type 3) and floats elsewhere (1).
            var parameters = new Dictionary<string, int>();
            if (controller.Node("m_AnimatorParameters") is YamlSequenceNode ps)
                foreach (YamlMappingNode p in ps.Children)
                    parameters[Get(p, "m_Name")] = int.Parse(Get(p, "m_Type") ?? "0", CultureInfo.InvariantCulture);
            foreach (var name in AnimatorParameters.All)
            {
                if (!parameters.TryGetValue(name, out int type)) problems.Add($"{file}: parameter {name} (AnimatorParameters) is missing");
                else if (type != (AnimatorParameters.IsInteger(name) ? GaitControllerYaml.IntType : GaitControllerYaml.FloatType))
                    problems.Add($"{file}: parameter {name} has m_Type {type}");
            }
            foreach (var name in parameters.Keys)
                if (!AnimatorParameters.All.Contains(name)) problems.Add($"{file}: parameter {name} is not in AnimatorParameters");

            // States: one per LocomotionState, named as its clip; moving ones play at the stride phase.
            var states = docs.Where(d => d.ClassId == 1102).ToList();
            var stateOf = new Dictionary<long, LocomotionState>();
            foreach (var s in states)
            {
                string name = s.Scalar("m_Name");
                var match = GaitClips.All.Where(l => GaitClips.Name(l) == name).ToList();
                if (match.Count == 0)
                {
                    problems.Add($"{file}: state '{name}' is not a LocomotionState");
                    continue;
                }
                var state = match[0];
                stateOf[s.FileId] = state;
                bool moving = state != LocomotionState.Standing;
                if (moving && (s.Scalar("m_TimeParameterActive") != "1" || s.Scalar("m_TimeParameter") != AnimatorParameters.StridePhase))
                    problems.Add($"{file}: state '{name}' does not take its normalized time from {AnimatorParameters.StridePhase}");
                if (s.Node("m_Motion") is YamlMappingNode motion && Get(motion, "guid") is string g && guids.TryGetValue(g, out var clip) && clip.EndsWith(".anim", StringComparison.Ordinal))
                {
                    string clipName = load(clip).FirstOrDefault(d => d.ClassId == 74)?.Scalar("m_Name");
                    if (clipName != name) problems.Add($"{file}: state '{name}' plays clip '{clipName}'");
                }
                else problems.Add($"{file}: state '{name}' has no clip");
            }
            foreach (var l in GaitClips.All)
                if (!stateOf.ContainsValue(l)) problems.Add($"{file}: no state for {l} ('{GaitClips.Name(l)}')");

            // Transitions: every state to every other (LocomotionController.Transitions), each on GaitState == target with its
            // interruption source, so no state the core passes through between two frames can strand the Animator.
            var expected = new HashSet<string>(LocomotionController.Transitions.Select(t => $"{t.From}->{t.To}"));
            var found = new HashSet<string>();
            void Transitions(string from, YamlNode list)
            {
                if (!(list is YamlSequenceNode seq)) return;
                foreach (YamlMappingNode r in seq.Children)
                {
                    long id = long.Parse(Get(r, "fileID"), CultureInfo.InvariantCulture);
                    if (!byId.TryGetValue(id, out var t)) continue; // reported as an unresolved fileID
                    var dst = t.Node("m_DstState") as YamlMappingNode;
                    long dstId = dst == null ? 0 : long.Parse(Get(dst, "fileID"), CultureInfo.InvariantCulture);
                    if (!stateOf.TryGetValue(dstId, out var to))
                    {
                        problems.Add($"{file}: transition &{id} from {from} leads to no state");
                        continue;
                    }
                    string key = $"{from}->{to}";
                    found.Add(key);
                    var conditions = (t.Node("m_Conditions") as YamlSequenceNode)?.Children.Cast<YamlMappingNode>().ToList() ?? new List<YamlMappingNode>();
                    bool right = conditions.Count == 1 && Get(conditions[0], "m_ConditionEvent") == AnimatorParameters.State
                                 && Get(conditions[0], "m_ConditionMode") == GaitControllerYaml.ConditionEquals.ToString(CultureInfo.InvariantCulture)
                                 && Get(conditions[0], "m_EventTreshold") == ((int)to).ToString(CultureInfo.InvariantCulture);
                    if (!right) problems.Add($"{file}: transition {key} is not taken on {AnimatorParameters.State} == {(int)to}");
                    if (t.Scalar("m_HasExitTime") != "0") problems.Add($"{file}: transition {key} waits for an exit time");
                    string source = ((int)LocomotionController.InterruptionSource(to)).ToString(CultureInfo.InvariantCulture);
                    if (t.Scalar("m_InterruptionSource") != source) problems.Add($"{file}: transition {key} has interruption source {t.Scalar("m_InterruptionSource")}, not {source}");
                }
            }
            foreach (var s in states.Where(s => stateOf.ContainsKey(s.FileId))) Transitions(stateOf[s.FileId].ToString(), s.Node("m_Transitions"));
            foreach (var m in docs.Where(d => d.ClassId == 1107)) Transitions("Any", m.Node("m_AnyStateTransitions"));
            foreach (var e in expected.Except(found)) problems.Add($"{file}: transition {e} is missing");
            foreach (var e in found.Except(expected)) problems.Add($"{file}: transition {e} is not one of the controller's (every state to every other)");
        }

        /// <summary>An override controller replaces each clip of its controller with a clip of the same name.</summary>
        static void CheckOverrideController(string file, List<UnityObject> docs, Dictionary<string, string> guids, Func<string, List<UnityObject>> load, List<string> problems)
        {
            var over = docs.FirstOrDefault(d => d.ClassId == 221);
            if (over == null)
            {
                problems.Add($"{file}: no AnimatorOverrideController (class 221)");
                return;
            }
            string ClipName(YamlNode reference)
                => reference is YamlMappingNode r && Get(r, "guid") is string g && guids.TryGetValue(g, out var clip) && clip.EndsWith(".anim", StringComparison.Ordinal)
                    ? load(clip).FirstOrDefault(d => d.ClassId == 74)?.Scalar("m_Name") : null;
            var overridden = new HashSet<string>();
            if (over.Node("m_Clips") is YamlSequenceNode pairs)
                foreach (YamlMappingNode pair in pairs.Children)
                {
                    string original = ClipName(pair.Children[new YamlScalarNode("m_OriginalClip")]);
                    string replacement = ClipName(pair.Children[new YamlScalarNode("m_OverrideClip")]);
                    if (original == null || original != replacement) problems.Add($"{file}: clip '{original}' is overridden by '{replacement}'");
                    else overridden.Add(original);
                }
            foreach (var l in GaitClips.All)
                if (!overridden.Contains(GaitClips.Name(l))) problems.Add($"{file}: '{GaitClips.Name(l)}' is not overridden");
        }

        /// <summary>
        /// Rebuilds the mannequin's pose at each key of a clip from its curves and checks each foot is down at its initial
        /// contact and still in the air one key before, at the stride positions of the phase map.
        /// </summary>
        static void CheckClipContacts(string file, List<UnityObject> docs, PhaseMap map, List<string> problems)
        {
            var clip = docs.FirstOrDefault(d => d.ClassId == 74);
            if (clip == null) return;
            string name = clip.Scalar("m_Name");
            var state = GaitClips.All.Where(l => GaitClips.Name(l) == name).Select(l => (LocomotionState?)l).FirstOrDefault();
            if (state == null || state == LocomotionState.Standing) return;
            var settings = clip.Node("m_AnimationClipSettings") as YamlMappingNode;
            double length = double.Parse(Get(settings, "m_StopTime") ?? "0", CultureInfo.InvariantCulture);
            var euler = Curves(clip.Node("m_EulerCurves"));
            var position = Curves(clip.Node("m_PositionCurves"));
            var muscles = FloatCurves(clip.Node("m_FloatCurves"));
            bool humanoid = muscles.ContainsKey(HumanoidMuscles.UpperLegFrontBack(Foot.Left).Name);
            double? Muscle(string attribute, double time)
            {
                if (!muscles.TryGetValue(attribute, out var keys)) return null;
                foreach (var k in keys)
                    if (Math.Abs(k.T - time) < 1e-6) return k.V;
                // A constant is written with its two end keys only.
                return keys.Count > 0 && keys.All(k => k.V == keys[0].V) ? keys[0].V : (double?)null;
            }

            double? Value(Dictionary<string, List<(double T, double[] V)>> curves, string path, int axis, double time)
            {
                if (!curves.TryGetValue(path, out var keys)) return null;
                foreach (var k in keys)
                    if (Math.Abs(k.T - time) < 1e-6) return k.V[axis];
                return keys.Count > 0 && keys.All(k => k.V[axis] == keys[0].V[axis]) ? keys[0].V[axis] : (double?)null;
            }
            double? FootHeight(Foot foot, double stride)
            {
                double t = stride * length;
                if (humanoid)
                {
                    // Muscles back to angles (HumanoidMuscles), the body's height and tilt from RootT.y and RootQ.x.
                    var fb = Muscle(HumanoidMuscles.UpperLegFrontBack(foot).Name, t);
                    var st = Muscle(HumanoidMuscles.LowerLegStretch(foot).Name, t);
                    var ud = Muscle(HumanoidMuscles.FootUpDown(foot).Name, t);
                    var y = Muscle("RootT.y", t);
                    var qx = Muscle("RootQ.x", t);
                    if (fb == null || st == null || ud == null || y == null || qx == null) return null;
                    var angles = HumanoidMuscles.Leg(foot, fb.Value, st.Value, ud.Value);
                    return y.Value * Mannequin.StandingHipHeight + Mannequin.Leg(angles, 2 * Math.Asin(qx.Value) * 180 / Math.PI).Lowest;
                }
                var hip = Value(position, Mannequin.Hips, 1, t);
                var tilt = Value(euler, Mannequin.Hips, 0, t);
                var h = Value(euler, Mannequin.UpperLeg(foot), 0, t);
                var k = Value(euler, Mannequin.LowerLeg(foot), 0, t);
                var a = Value(euler, Mannequin.FootPath(foot), 0, t);
                if (hip == null || tilt == null || h == null || k == null || a == null) return null;
                return hip.Value + Mannequin.Leg(new LegAngles(-h.Value, k.Value, -a.Value), tilt.Value).Lowest;
            }

            var feet = state == LocomotionState.Walking ? new[] { Foot.Left, Foot.Right }
                : state == LocomotionState.StartWalkLeft ? new[] { Foot.Left }
                : state == LocomotionState.StartWalkRight ? new[] { Foot.Right } : new Foot[0];
            foreach (var foot in feet)
            {
                double ic = map.StridePositionOfOnset(foot, GaitPhase.InitialContact);
                // A contact at stride 0 is the loop's wrap: down at the first key, in the air at the one before the last.
                var down = FootHeight(foot, ic);
                var before = FootHeight(foot, (ic == 0 ? 1 : ic) - GaitClipCurves.BeforeEvent);
                if (down == null || before == null)
                    problems.Add($"{file}: no key at the {foot} initial contact (stride {ic:F4} of the phase map, {ic * length:F4} s)");
                else if (Math.Abs(down.Value) > Contact || before.Value <= Contact)
                    problems.Add($"{file}: the {foot} foot does not land at stride {ic:F4} (height {before:F4} m before, {down:F4} m at it)");
            }
        }

        static Dictionary<string, List<(double T, double[] V)>> Curves(YamlNode node)
        {
            var curves = new Dictionary<string, List<(double, double[])>>();
            if (!(node is YamlSequenceNode seq)) return curves;
            foreach (YamlMappingNode c in seq.Children)
            {
                string path = Get(c, "path") ?? "";
                var keys = new List<(double, double[])>();
                var curve = c.Children[new YamlScalarNode("curve")] as YamlMappingNode;
                if (curve?.Children[new YamlScalarNode("m_Curve")] is YamlSequenceNode ks)
                    foreach (YamlMappingNode k in ks.Children)
                    {
                        var v = (YamlMappingNode)k.Children[new YamlScalarNode("value")];
                        keys.Add((double.Parse(Get(k, "time"), CultureInfo.InvariantCulture),
                            new[] { Num(v, "x"), Num(v, "y"), Num(v, "z") }));
                    }
                curves[path] = keys;
            }
            return curves;
        }

        static Dictionary<string, List<(double T, double V)>> FloatCurves(YamlNode node)
        {
            var curves = new Dictionary<string, List<(double, double)>>();
            if (!(node is YamlSequenceNode seq)) return curves;
            foreach (YamlMappingNode c in seq.Children)
            {
                var keys = new List<(double, double)>();
                var curve = c.Children[new YamlScalarNode("curve")] as YamlMappingNode;
                if (curve?.Children[new YamlScalarNode("m_Curve")] is YamlSequenceNode ks)
                    foreach (YamlMappingNode k in ks.Children)
                        keys.Add((double.Parse(Get(k, "time"), CultureInfo.InvariantCulture), double.Parse(Get(k, "value"), CultureInfo.InvariantCulture)));
                curves[Get(c, "attribute") ?? ""] = keys;
            }
            return curves;
        }

        static double Num(YamlMappingNode m, string key) => double.Parse(Get(m, key), CultureInfo.InvariantCulture);
    }

    /// <summary>
    /// Which SubShaders and Passes of a ShaderLab source a pipeline draws. A SubShader tagged "RenderPipeline" is used only
    /// under the pipeline with that tag value (URP: UniversalPipeline), one without the tag under any pipeline. A Pass
    /// without "LightMode" is "Always" to the built-in pipeline and "SRPDefaultUnlit" to an SRP; URP's forward renderer
    /// draws SRPDefaultUnlit, UniversalForward and UniversalForwardOnly, the built-in forward path Always, ForwardBase and
    /// Vertex. Both pipelines render their shadow maps from "ShadowCaster" passes (built-in also finds one in the shader's
    /// Fallback, Unity's manual, "Shadow casting shader example"; `Fallback Off` gives none). URP's depth prepass draws
    /// "DepthOnly" passes (DepthOnlyPass), or "DepthNormals" and "DepthNormalsOnly" when a feature needs the normals
    /// texture (DepthNormalOnlyPass, e.g. SSAO); with depth priming (UniversalRenderer: Forced, or Auto where recommended,
    /// i.e. not Android/iOS; Forward or Forward+, a base camera, no MSAA) DrawObjectsPass draws the opaques with ZWrite off
    /// and ZTest Equal, so an opaque the prepass did not draw is not drawn at all. Reads the text only (braces, Tags blocks,
    /// UsePass, Fallback); it does not compile the shader.
    /// </summary>
    public static class ShaderPasses
    {
        public const string BuiltIn = "built-in", Universal = "URP";

        static readonly Dictionary<string, (string tag, string[] lightModes)> Pipelines = new Dictionary<string, (string, string[])>
        {
            [BuiltIn] = (null, new[] { "Always", "ForwardBase", "Vertex", "VertexLM" }),
            [Universal] = ("UniversalPipeline", new[] { "SRPDefaultUnlit", "UniversalForward", "UniversalForwardOnly" }),
        };

        /// <summary>Whether the pipeline draws the shader in its colour pass at all (not magenta).</summary>
        public static bool Draws(string shader, string pipeline) => LightModes(shader, pipeline).Overlaps(Pipelines[pipeline].lightModes);

        /// <summary>
        /// Whether the pipeline renders the shader into its shadow maps: a "ShadowCaster" pass (its own, one pulled in by
        /// UsePass ".../SHADOWCASTER", or, under built-in only, possibly its Fallback's: any Fallback but Off counts).
        /// </summary>
        public static bool CastsShadows(string shader, string pipeline)
        {
            if (LightModes(shader, pipeline).Contains("ShadowCaster")) return true;
            return pipeline == BuiltIn && Fallback(shader) != null;
        }

        /// <summary>
        /// Whether URP's depth prepass draws the shader: "DepthOnly" (DepthOnlyPass) or, when the normals texture is needed,
        /// "DepthNormals" / "DepthNormalsOnly" (DepthNormalOnlyPass).
        /// </summary>
        public static bool InUrpDepthPrepass(string shader, bool normals)
        {
            var modes = LightModes(shader, Universal);
            return normals ? modes.Contains("DepthNormals") || modes.Contains("DepthNormalsOnly") : modes.Contains("DepthOnly");
        }

        /// <summary>
        /// Whether URP shows an opaque of this shader under depth priming, whichever prepass runs: its colour pass is drawn
        /// with ZTest Equal against the prepass's depth, so the prepass must draw it too (DepthOnly, and DepthNormals or
        /// DepthNormalsOnly for the normals prepass).
        /// </summary>
        public static bool VisibleUnderUrpDepthPriming(string shader) =>
            Draws(shader, Universal) && InUrpDepthPrepass(shader, false) && InUrpDepthPrepass(shader, true);

        /// <summary>
        /// The program text of every Pass with the given LightMode in the SubShaders the pipeline may use: the pass's own
        /// CGPROGRAM/HLSLPROGRAM bodies after its SubShader's CGINCLUDE/HLSLINCLUDE bodies, comments removed. Included
        /// files are not read.
        /// </summary>
        public static IReadOnlyList<string> PassPrograms(string shader, string lightMode, string pipeline)
        {
            var programs = new List<string>();
            foreach (string sub in Blocks(StripComments(shader), "SubShader"))
            {
                if (!UsedBy(ShaderLab(sub), pipeline)) continue;
                string shared = string.Concat(Regex.Matches(sub, @"\b(?:CGINCLUDE|HLSLINCLUDE)\b(.*?)\b(?:ENDCG|ENDHLSL)\b", RegexOptions.Singleline).Select(m => m.Groups[1].Value + "\n"));
                foreach (string pass in Blocks(sub, "Pass"))
                {
                    if (LightMode(ShaderLab(pass), pipeline) != lightMode) continue;
                    programs.Add(shared + string.Concat(Regex.Matches(pass, @"\b(?:CGPROGRAM|HLSLPROGRAM)\b(.*?)\b(?:ENDCG|ENDHLSL)\b", RegexOptions.Singleline).Select(m => m.Groups[1].Value + "\n")));
                }
            }
            return programs;
        }

        /// <summary>
        /// What the shader's URP shadow caster lacks of the bias URP applies on the caster side (URP 17's
        /// Shaders/ShadowCasterPass.hlsl, GetShadowPositionHClip, with ApplyShadowBias from ShaderLibrary/Shadows.hlsl): the
        /// globals ShadowUtils.SetupShadowCasterConstantBuffer sets before each shadow slice, each declared and read
        /// (_ShadowBias.x the depth bias and .y the normal bias, _LightDirection the directional light's direction, and
        /// _LightPosition under the _CASTING_PUNCTUAL_LIGHT_SHADOW keyword its shadow passes switch, for spot and point
        /// lights); and the clamp of clip-space z to the near plane (min with UNITY_NEAR_CLIP_VALUE under UNITY_REVERSED_Z,
        /// max otherwise), which keeps casters between the light and the shadow near plane in the map. A pass that includes
        /// URP's own ShadowCasterPass.hlsl has them all. Empty when every ShadowCaster pass URP may draw has them all; a
        /// shader with no such pass lacks the pass itself. Reads the text only (<see cref="PassPrograms"/>).
        /// </summary>
        public static IReadOnlyList<string> MissingUrpShadowBias(string shader)
        {
            var programs = PassPrograms(shader, "ShadowCaster", Universal);
            if (programs.Count == 0) return new[] { "no ShadowCaster pass URP draws" };
            var missing = new List<string>();
            foreach (string p in programs)
            {
                if (Regex.IsMatch(p, @"#\s*include\s+""[^""]*com\.unity\.render-pipelines\.universal/Shaders/ShadowCasterPass\.hlsl""")) continue;
                void Need(bool present, string what) { if (!present && !missing.Contains(what)) missing.Add(what); }
                bool Declared(string name, string types) => Regex.IsMatch(p, @"\b(?:" + types + @")\s+" + name + @"\s*;");
                bool ReadAfterDeclaring(string name) => Regex.Matches(p, @"\b" + name + @"\b").Count >= 2;
                Need(Declared("_ShadowBias", "float4|half4"), "_ShadowBias is not declared");
                Need(Regex.IsMatch(p, @"\b_ShadowBias\s*\.\s*x"), "_ShadowBias.x (URP's depth bias) is not read");
                Need(Regex.IsMatch(p, @"\b_ShadowBias\s*\.\s*y"), "_ShadowBias.y (URP's normal bias) is not read");
                Need(Declared("_LightDirection", "float3|float4|half3|half4") && ReadAfterDeclaring("_LightDirection"), "_LightDirection is not declared and read");
                Need(Regex.IsMatch(p, @"#\s*pragma\s+(?:multi_compile|shader_feature)\w*\s[^\n]*\b_CASTING_PUNCTUAL_LIGHT_SHADOW\b"), "no _CASTING_PUNCTUAL_LIGHT_SHADOW keyword");
                Need(Regex.IsMatch(p, @"#\s*(?:if|ifdef|elif)\b[^\n]*\b_CASTING_PUNCTUAL_LIGHT_SHADOW\b") &&
                     Declared("_LightPosition", "float3|float4|half3|half4") && ReadAfterDeclaring("_LightPosition"),
                     "_LightPosition is not read under _CASTING_PUNCTUAL_LIGHT_SHADOW");
                Need(Regex.IsMatch(p, @"#\s*if[^\n]*\bUNITY_REVERSED_Z\b") &&
                     Regex.IsMatch(p, @"\bmin\s*\(\s*[\w.]+\.z\s*,\s*UNITY_NEAR_CLIP_VALUE\s*\)") &&
                     Regex.IsMatch(p, @"\bmax\s*\(\s*[\w.]+\.z\s*,\s*UNITY_NEAR_CLIP_VALUE\s*\)"),
                     "clip-space z is not clamped to the near plane (UNITY_NEAR_CLIP_VALUE, min under UNITY_REVERSED_Z, max otherwise)");
            }
            return missing;
        }

        /// <summary>The shader named by a top-level Fallback, or null for none or `Fallback Off`.</summary>
        public static string Fallback(string shader)
        {
            var m = Regex.Match(ShaderLab(shader), @"\bFallback\s+(?:""([^""]*)""|(\w+))", RegexOptions.IgnoreCase);
            if (!m.Success) return null;
            string name = m.Groups[1].Success ? m.Groups[1].Value : m.Groups[2].Value;
            return string.Equals(name, "Off", StringComparison.OrdinalIgnoreCase) ? null : name;
        }

        /// <summary>The LightModes of every Pass in the SubShaders the pipeline may use (a Pass without the tag as the pipeline reads it).</summary>
        static HashSet<string> LightModes(string shader, string pipeline)
        {
            var modes = new HashSet<string>(StringComparer.Ordinal);
            foreach (string sub in Blocks(ShaderLab(shader), "SubShader"))
            {
                if (!UsedBy(sub, pipeline)) continue;
                foreach (string pass in Blocks(sub, "Pass")) modes.Add(LightMode(pass, pipeline));
                // UsePass "Shader/PASSNAME" copies that pass with its tags; Unity's shadow caster passes are named SHADOWCASTER.
                if (Regex.IsMatch(sub, @"\bUsePass\s+""[^""]*/SHADOWCASTER""", RegexOptions.IgnoreCase)) modes.Add("ShadowCaster");
            }
            return modes;
        }

        /// <summary>Whether the pipeline may use a SubShader (its ShaderLab text): no RenderPipeline tag, or the pipeline's.</summary>
        static bool UsedBy(string subShader, string pipeline)
        {
            string subTag = Tag(TagsBefore(subShader, "Pass"), "RenderPipeline");
            return string.IsNullOrEmpty(subTag) || subTag == Pipelines[pipeline].tag;
        }

        /// <summary>A Pass's LightMode as the pipeline reads it (its ShaderLab text): without the tag, built-in's "Always", an SRP's "SRPDefaultUnlit".</summary>
        static string LightMode(string pass, string pipeline)
            => Tag(TagsBefore(pass, null), "LightMode") ?? (Pipelines[pipeline].tag == null ? "Always" : "SRPDefaultUnlit");

        /// <summary>
        /// The ShaderLab text alone: comments removed, and program bodies (which may hold braces of their own) dropped. A
        /// surface shader's program (#pragma surface) stands for the ForwardBase/ForwardAdd passes Unity generates from it,
        /// which only built-in draws.
        /// </summary>
        static string ShaderLab(string shader)
        {
            string text = StripComments(shader);
            return Regex.Replace(text, @"\b(CGPROGRAM|HLSLPROGRAM|CGINCLUDE|HLSLINCLUDE)\b.*?\b(ENDCG|ENDHLSL)\b",
                m => Regex.IsMatch(m.Value, @"#pragma\s+surface\b") ? "Pass { Tags { \"LightMode\" = \"ForwardBase\" } }" : "", RegexOptions.Singleline);
        }

        static string StripComments(string shader) => Regex.Replace(shader, @"//[^\n]*|/\*.*?\*/", "", RegexOptions.Singleline);

        /// <summary>The bodies of every `keyword { ... }` block at any depth.</summary>
        static IEnumerable<string> Blocks(string text, string keyword)
        {
            foreach (Match m in Regex.Matches(text, @"\b" + keyword + @"\s*\{"))
            {
                int depth = 0, start = m.Index + m.Length;
                for (int i = start - 1; i < text.Length; i++)
                {
                    if (text[i] == '{') depth++;
                    else if (text[i] == '}' && --depth == 0) { yield return text.Substring(start, i - start); break; }
                }
            }
        }

        /// <summary>The first Tags block of a body, before the first nested <paramref name="stop"/> block.</summary>
        static string TagsBefore(string body, string stop)
        {
            int end = stop == null ? body.Length : Regex.Match(body, @"\b" + stop + @"\s*\{") is var s && s.Success ? s.Index : body.Length;
            var m = Regex.Match(body.Substring(0, end), @"\bTags\s*\{([^}]*)\}");
            return m.Success ? m.Groups[1].Value : "";
        }

        static string Tag(string tags, string name)
        {
            var m = Regex.Match(tags, "\"" + name + "\"\\s*=\\s*\"([^\"]*)\"");
            return m.Success ? m.Groups[1].Value : null;
        }
    }
}
