using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using HeadGait.Editor;
using HeadGait.Tooling;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;
using YamlDotNet.RepresentationModel;

namespace HeadGait.Tests
{
    /// <summary>
    /// Tools > HeadGait > Create Gait Clips and Animator Controller builds, with AnimationUtility.SetEditorCurve (here its
    /// stand-in, which keeps what was set), the clips `headgait clips` writes as the package's .anim files: the same curves
    /// (path and property, in order), keys (time, value, slopes, to the float Unity stores) and clip settings.
    /// </summary>
    public class EditorClipBuilderTests
    {
        const string Folder = "Assets/HeadGait Clip Test";

        static string Package => RepositoryPaths.Package;

        static PhaseMap ShippedMap => CorrelationTemplate.Load(Path.Combine(Package, GaitAssetFiles.CorTemplate)).PhaseMap;

        [TearDown]
        public void DeleteBuilt()
        {
            foreach (var s in GaitClips.All) AssetDatabase.DeleteAsset(Folder + "/" + GaitClips.Name(s) + ".anim");
            AssetDatabase.DeleteAsset(Folder + "/HeadGait Legs.controller");
        }

        /// <summary>The shipped clip's m_EditorCurves and settings against the built clip; the differences, one line each.</summary>
        static List<string> Differences(LocomotionState state, AnimationClip built)
            => Differences(GaitAssetFiles.ClipPath(state), built, typeof(Transform), "4");

        /// <summary>As above for any shipped clip file, whose curves bind to <paramref name="type"/> (class <paramref name="classId"/>).</summary>
        internal static List<string> Differences(string file, AnimationClip built, Type type, string classId)
        {
            var problems = new List<string>();
            var clip = UnityYamlFile.Parse(File.ReadAllText(Path.Combine(Package, file)), file).Single(d => d.ClassId == 74);
            static string S(YamlNode n, string key) => ((YamlScalarNode)((YamlMappingNode)n).Children[new YamlScalarNode(key)]).Value;
            static double D(YamlNode n, string key) => double.Parse(S(n, key), CultureInfo.InvariantCulture);
            // The YAML holds 7 decimals; the editor's keys are floats.
            static bool Near(float a, double b) => Math.Abs(a - b) <= 2e-6 + 2e-6 * Math.Abs(b);

            var shipped = ((YamlSequenceNode)clip.Node("m_EditorCurves")).Children;
            var bindings = AnimationUtility.GetCurveBindings(built);
            if (bindings.Length != shipped.Count) problems.Add($"{file}: {shipped.Count} editor curves shipped, {bindings.Length} built");
            for (int i = 0; i < Math.Min(bindings.Length, shipped.Count); i++)
            {
                string where = $"{file} curve {i} ({S(shipped[i], "path")} {S(shipped[i], "attribute")})";
                if (bindings[i].path != S(shipped[i], "path") || bindings[i].propertyName != S(shipped[i], "attribute") || bindings[i].type != type || S(shipped[i], "classID") != classId)
                {
                    problems.Add($"{where}: built as {bindings[i].path} {bindings[i].propertyName} on {bindings[i].type?.Name}");
                    continue;
                }
                var keys = AnimationUtility.GetEditorCurve(built, bindings[i]).keys;
                var shippedKeys = ((YamlSequenceNode)((YamlMappingNode)((YamlMappingNode)shipped[i]).Children[new YamlScalarNode("curve")]).Children[new YamlScalarNode("m_Curve")]).Children;
                if (keys.Length != shippedKeys.Count)
                {
                    problems.Add($"{where}: {shippedKeys.Count} keys shipped, {keys.Length} built");
                    continue;
                }
                for (int k = 0; k < keys.Length; k++)
                {
                    var y = shippedKeys[k];
                    if (!Near(keys[k].time, D(y, "time")) || !Near(keys[k].value, D(y, "value")) || !Near(keys[k].inTangent, D(y, "inSlope")) || !Near(keys[k].outTangent, D(y, "outSlope")))
                        problems.Add($"{where} key {k}: shipped t {S(y, "time")} v {S(y, "value")} in {S(y, "inSlope")} out {S(y, "outSlope")}, " +
                                     $"built t {keys[k].time} v {keys[k].value} in {keys[k].inTangent} out {keys[k].outTangent}");
                }
            }

            var settings = (YamlMappingNode)clip.Node("m_AnimationClipSettings");
            var s = AnimationUtility.GetAnimationClipSettings(built);
            void Setting(string key, double builtValue)
            {
                if (!Near((float)builtValue, D(settings, key))) problems.Add($"{file}: {key} shipped {S(settings, key)}, built {builtValue}");
            }
            Setting("m_StartTime", s.startTime);
            Setting("m_StopTime", s.stopTime);
            Setting("m_LoopTime", s.loopTime ? 1 : 0);
            Setting("m_LoopBlend", s.loopBlend ? 1 : 0);
            Setting("m_LoopBlendOrientation", s.loopBlendOrientation ? 1 : 0);
            Setting("m_LoopBlendPositionY", s.loopBlendPositionY ? 1 : 0);
            Setting("m_LoopBlendPositionXZ", s.loopBlendPositionXZ ? 1 : 0);
            Setting("m_KeepOriginalOrientation", s.keepOriginalOrientation ? 1 : 0);
            Setting("m_KeepOriginalPositionY", s.keepOriginalPositionY ? 1 : 0);
            Setting("m_KeepOriginalPositionXZ", s.keepOriginalPositionXZ ? 1 : 0);
            Setting("m_Mirror", s.mirror ? 1 : 0);
            if (!Near(built.frameRate, D(clip.Body, "m_SampleRate"))) problems.Add($"{file}: sample rate shipped {clip.Scalar("m_SampleRate")}, built {built.frameRate}");
            if (built.name != clip.Scalar("m_Name")) problems.Add($"{file}: named {clip.Scalar("m_Name")}, built {built.name}");
            return problems;
        }

        [Test]
        public void TheEditorBuiltClipsAreTheShippedOnes()
        {
            var clips = new GaitClips(ShippedMap);
            foreach (var state in GaitClips.All)
                Assert.That(Differences(state, GaitClipBuilder.Build(clips, state)), Is.Empty, GaitClips.Name(state));
        }

        [Test]
        public void TheComparisonSeesAClipTimedByAnotherMapOrLongerOrNotLooping()
        {
            var perry = GaitClipBuilder.Build(new GaitClips(PhaseMap.Perry), LocomotionState.Walking);
            Assert.That(Differences(LocomotionState.Walking, perry), Is.Not.Empty, "Perry's map instead of the trained one");
            var walking = GaitClipBuilder.Build(new GaitClips(ShippedMap), LocomotionState.Walking);
            var settings = AnimationUtility.GetAnimationClipSettings(walking);
            settings.loopTime = false;
            AnimationUtility.SetAnimationClipSettings(walking, settings);
            Assert.That(Differences(LocomotionState.Walking, walking), Is.Not.Empty, "not looping");
            var binding = AnimationUtility.GetCurveBindings(walking)[1]; // the hips' height
            var keys = AnimationUtility.GetEditorCurve(walking, binding).keys;
            keys[3].value += 0.01f;
            AnimationUtility.SetEditorCurve(walking, binding, new AnimationCurve(keys));
            Assert.That(Differences(LocomotionState.Walking, walking).Count(p => p.Contains(" key 3")), Is.EqualTo(1), "one key moved");
        }

        [Test]
        public void TheMenuWritesTheClipsIntoTheFolderAndTheControllerPlaysThem()
        {
            var written = GaitClipBuilder.Create(Folder, ShippedMap);
            var controller = LocomotionControllerBuilder.Create(Folder + "/HeadGait Legs.controller", written);
            foreach (var child in controller.layers[0].stateMachine.states)
            {
                var clip = AssetDatabase.LoadAssetAtPath<AnimationClip>(Folder + "/" + child.state.name + ".anim");
                Assert.That(clip, Is.Not.Null, child.state.name);
                Assert.That(child.state.motion, Is.SameAs(clip), child.state.name);
            }
        }
    }
}
