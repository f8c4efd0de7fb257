using System;
using System.Collections.Generic;
using UnityEditor;
using UnityEngine;

namespace HeadGait.Editor
{
    /// <summary>What the two clip builders share: writing the six gait clips as assets, and a curve's keys.</summary>
    static class ClipAssets
    {
        /// <summary>Writes each state's clip as "State Name.anim" into a project folder ("Assets/..."), replacing clips of those names.</summary>
        public static Dictionary<LocomotionState, AnimationClip> Write(string folder, Func<LocomotionState, AnimationClip> build)
        {
            var written = new Dictionary<LocomotionState, AnimationClip>();
            foreach (var state in GaitClips.All)
            {
                var clip = build(state);
                AssetDatabase.CreateAsset(clip, folder.TrimEnd('/') + "/" + GaitClips.Name(state) + ".anim");
                written[state] = clip;
            }
            AssetDatabase.SaveAssets();
            return written;
        }

        /// <summary>A curve through <paramref name="count"/> keys; a constant one needs its two ends only, as the package's .anim files hold it.</summary>
        public static AnimationCurve Curve(int count, bool constant, Func<int, Keyframe> key)
        {
            var keys = new List<Keyframe>();
            for (int k = 0; k < count; k++)
            {
                if (constant && k > 0 && k < count - 1) continue;
                keys.Add(key(k));
            }
            return new AnimationCurve(keys.ToArray());
        }
    }
}
