using System.Collections.Generic;
using UnityEditor;
using UnityEngine;

namespace HeadGait.Editor
{
    /// <summary>
    /// Builds the six gait clips of the package's mannequin with Unity's editor API from <see cref="GaitClipCurves"/>, the
    /// same keys, values and slopes `headgait clips` writes as the package's .anim files. API as in UnityCsReference
    /// Editor/Mono/Animation/AnimationUtility.bindings.cs (SetEditorCurve, Get/SetAnimationClipSettings),
    /// Editor/Mono/Animation/EditorCurveBinding.bindings.cs (FloatCurve) and Runtime/Export/Math/AnimationCurve.bindings.cs
    /// (AnimationCurve, Keyframe).
    /// </summary>
    public static class GaitClipBuilder
    {
        /// <summary>Writes the clips as "State Name.anim" into a project folder ("Assets/..."), replacing clips of those names.</summary>
        public static Dictionary<LocomotionState, Motion> Create(string folder, PhaseMap map)
        {
            var clips = new GaitClips(map);
            var written = new Dictionary<LocomotionState, Motion>();
            foreach (var pair in ClipAssets.Write(folder, state => Build(clips, state))) written[pair.Key] = pair.Value;
            return written;
        }

        /// <summary>One clip: a float curve per animated transform component, named and timed as the package's .anim.</summary>
        public static AnimationClip Build(GaitClips clips, LocomotionState state)
        {
            var curves = GaitClipCurves.Of(clips, state);
            var clip = new AnimationClip { name = GaitClips.Name(state), frameRate = GaitClipCurves.SampleRate };
            foreach (var channel in curves.Channels)
            {
                for (int component = 0; component < 3; component++)
                {
                    var curve = ClipAssets.Curve(curves.Keys.Count, channel.IsConstant(component), k => new Keyframe((float)curves.Time(k),
                        (float)channel.Values[k][component], (float)channel.InSlopes[k][component], (float)channel.OutSlopes[k][component]));
                    var binding = EditorCurveBinding.FloatCurve(channel.Path, typeof(Transform), channel.Attribute(component));
                    AnimationUtility.SetEditorCurve(clip, binding, curve);
                }
            }
            // One stride long; Walking and Standing loop. The mannequin is a Generic rig whose hips carry their own height:
            // keep it from the clip (Keep Original Position Y), nothing baked into root motion.
            var settings = AnimationUtility.GetAnimationClipSettings(clip);
            settings.startTime = 0;
            settings.stopTime = (float)GaitClipCurves.Length;
            settings.loopTime = GaitClipCurves.Loops(state);
            settings.loopBlendOrientation = false;
            settings.loopBlendPositionY = false;
            settings.loopBlendPositionXZ = false;
            settings.keepOriginalOrientation = false;
            settings.keepOriginalPositionY = true;
            settings.keepOriginalPositionXZ = false;
            AnimationUtility.SetAnimationClipSettings(clip, settings);
            return clip;
        }
    }
}
