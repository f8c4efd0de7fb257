using System.Collections.Generic;
using UnityEditor;
using UnityEngine;

namespace HeadGait.Editor
{
    /// <summary>
    /// Builds the six Humanoid gait clips (for the developer's own avatar) with Unity's editor API from
    /// <see cref="HumanoidClipCurves"/>, the curves `headgait clips` writes as the package's Animation/Humanoid .anim files,
    /// and an Animator Override Controller that plays them in place of a controller's gait clips. API as in UnityCsReference
    /// Editor/Mono/Animation/AnimationUtility.bindings.cs (SetEditorCurve, Get/SetAnimationClipSettings),
    /// Editor/Mono/Animation/EditorCurveBinding.bindings.cs (FloatCurve) and
    /// Modules/Animation/ScriptBindings/AnimatorOverrideController.bindings.cs (constructor, ApplyOverrides).
    /// </summary>
    public static class HumanoidClipBuilder
    {
        /// <summary>Writes the clips as "State Name.anim" into a project folder ("Assets/..."), replacing clips of those names.</summary>
        public static Dictionary<LocomotionState, AnimationClip> Create(string folder, PhaseMap map)
        {
            var clips = new GaitClips(map);
            return ClipAssets.Write(folder, state => Build(clips, state));
        }

        /// <summary>One clip: a float curve on the Animator (empty path) per muscle and root curve, timed as the package's .anim.</summary>
        public static AnimationClip Build(GaitClips clips, LocomotionState state)
        {
            var curves = HumanoidClipCurves.Of(clips, state);
            var clip = new AnimationClip { name = GaitClips.Name(state), frameRate = GaitClipCurves.SampleRate };
            foreach (var curve in curves.Curves)
            {
                var animated = ClipAssets.Curve(curves.Keys.Count, curve.IsConstant,
                    k => new Keyframe((float)curves.Time(k), (float)curve.Values[k], (float)curve.InSlopes[k], (float)curve.OutSlopes[k]));
                AnimationUtility.SetEditorCurve(clip, EditorCurveBinding.FloatCurve("", typeof(Animator), curve.Attribute), animated);
            }
            // One stride long; Walking and Standing loop; the body's motion is baked into the pose, so the avatar walks on
            // the spot as the mannequin does.
            var settings = AnimationUtility.GetAnimationClipSettings(clip);
            settings.startTime = 0;
            settings.stopTime = (float)GaitClipCurves.Length;
            settings.loopTime = GaitClipCurves.Loops(state);
            settings.loopBlendOrientation = HumanoidClipCurves.BakeRoot;
            settings.loopBlendPositionY = HumanoidClipCurves.BakeRoot;
            settings.loopBlendPositionXZ = HumanoidClipCurves.BakeRoot;
            settings.keepOriginalOrientation = HumanoidClipCurves.BakeRoot;
            settings.keepOriginalPositionY = true;
            settings.keepOriginalPositionXZ = HumanoidClipCurves.BakeRoot;
            AnimationUtility.SetAnimationClipSettings(clip, settings);
            return clip;
        }

        /// <summary>
        /// An Animator Override Controller at <paramref name="path"/> ("Assets/.../Name.overrideController"; an asset there is
        /// replaced) playing <paramref name="controller"/> with each of its gait clips (<paramref name="originals"/>) replaced
        /// by the Humanoid clip of the same state.
        /// </summary>
        public static AnimatorOverrideController CreateOverrideController(string path, RuntimeAnimatorController controller,
            IReadOnlyDictionary<LocomotionState, AnimationClip> originals, IReadOnlyDictionary<LocomotionState, AnimationClip> humanoid)
        {
            var overrideController = new AnimatorOverrideController(controller) { name = System.IO.Path.GetFileNameWithoutExtension(path) };
            var pairs = new List<KeyValuePair<AnimationClip, AnimationClip>>();
            foreach (var state in GaitClips.All)
                if (originals.TryGetValue(state, out var original) && humanoid.TryGetValue(state, out var replacement))
                    pairs.Add(new KeyValuePair<AnimationClip, AnimationClip>(original, replacement));
            overrideController.ApplyOverrides(pairs);
            AssetDatabase.CreateAsset(overrideController, path);
            AssetDatabase.SaveAssets();
            return overrideController;
        }
    }
}
