// Stand-ins for the UnityEngine animation types the package's Editor code builds, after UnityCsReference (file named
// beside each type); bodies are plain storage. UnityEditor.Animations.cs builds controllers and clips from them.
namespace UnityEngine
{
    // Modules/Animation/ScriptBindings/Motion.bindings.cs: public partial class Motion : Object (what a state plays).
    public class Motion : Object { }

    // Modules/Animation/ScriptBindings/RuntimeAnimatorController.bindings.cs: public class RuntimeAnimatorController : Object;
    // animationClips { get; }: every clip the controller plays, each once (native; here each kind of controller lists its own).
    public class RuntimeAnimatorController : Object
    {
        public AnimationClip[] animationClips => AnimationClipsOf();

        internal virtual AnimationClip[] AnimationClipsOf() => new AnimationClip[0];
    }

    // Modules/Animation/ScriptBindings/AnimatorOverrideController.bindings.cs: AnimatorOverrideController(RuntimeAnimatorController
    // controller); runtimeAnimatorController { get; set; }; this[AnimationClip] (get: the override, else the original clip;
    // set: SetClip); overridesCount (the controller's original clips); GetOverrides fills (original, override or null) pairs
    // in the controller's clip order; ApplyOverrides sets each pair. The native SetClip ignores a clip the controller does
    // not play (here too). animationClips are the clips it plays: each original replaced by its override.
    public class AnimatorOverrideController : RuntimeAnimatorController
    {
        readonly System.Collections.Generic.Dictionary<AnimationClip, AnimationClip> overrides = new System.Collections.Generic.Dictionary<AnimationClip, AnimationClip>();

        public AnimatorOverrideController() { }

        public AnimatorOverrideController(RuntimeAnimatorController controller) => runtimeAnimatorController = controller;

        public RuntimeAnimatorController runtimeAnimatorController { get; set; }

        AnimationClip[] Originals => runtimeAnimatorController != null ? runtimeAnimatorController.animationClips : new AnimationClip[0];

        public AnimationClip this[AnimationClip clip]
        {
            get => clip != null && overrides.TryGetValue(clip, out var o) && o != null ? o : clip;
            set => SetClip(clip, value);
        }

        public int overridesCount => Originals.Length;

        public void GetOverrides(System.Collections.Generic.List<System.Collections.Generic.KeyValuePair<AnimationClip, AnimationClip>> list)
        {
            if (list == null) throw new System.ArgumentNullException("overrides");
            list.Clear();
            foreach (var original in Originals)
                list.Add(new System.Collections.Generic.KeyValuePair<AnimationClip, AnimationClip>(original, overrides.TryGetValue(original, out var o) ? o : null));
        }

        public void ApplyOverrides(System.Collections.Generic.IList<System.Collections.Generic.KeyValuePair<AnimationClip, AnimationClip>> list)
        {
            if (list == null) throw new System.ArgumentNullException("overrides");
            for (int i = 0; i < list.Count; i++) SetClip(list[i].Key, list[i].Value);
        }

        void SetClip(AnimationClip original, AnimationClip overrideClip)
        {
            if (original == null || System.Array.IndexOf(Originals, original) < 0) return;
            overrides[original] = overrideClip;
        }

        internal override AnimationClip[] AnimationClipsOf() => System.Array.ConvertAll(Originals, c => this[c]);
    }

    // Modules/Animation/ScriptBindings/AnimationClip.bindings.cs: public sealed class AnimationClip : Motion; frameRate
    // (native, 60 for a new clip). Its editor curves and settings are native too: the stand-in AnimationUtility keeps them.
    public sealed class AnimationClip : Motion
    {
        public float frameRate { get; set; } = 60;
    }

    // Runtime/Export/Math/AnimationCurve.bindings.cs: struct Keyframe(time, value, inTangent, outTangent).
    public struct Keyframe
    {
        public Keyframe(float time, float value) : this(time, value, 0, 0) { }

        public Keyframe(float time, float value, float inTangent, float outTangent)
        {
            this.time = time;
            this.value = value;
            this.inTangent = inTangent;
            this.outTangent = outTangent;
        }

        public float time { get; set; }
        public float value { get; set; }
        public float inTangent { get; set; }
        public float outTangent { get; set; }
    }

    // Runtime/Export/Math/AnimationCurve.bindings.cs: class AnimationCurve(params Keyframe[] keys); keys hands out a copy.
    public class AnimationCurve
    {
        Keyframe[] keyList;

        public AnimationCurve(params Keyframe[] keys) { keyList = (Keyframe[])(keys ?? new Keyframe[0]).Clone(); }

        public Keyframe[] keys
        {
            get => (Keyframe[])keyList.Clone();
            set => keyList = (Keyframe[])(value ?? new Keyframe[0]).Clone();
        }

        public int length => keyList.Length;
    }
}
