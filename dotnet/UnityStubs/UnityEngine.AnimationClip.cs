// Stand-ins for the UnityEngine animation types the package's Editor code builds, after UnityCsReference (file named
// beside each type); bodies are plain storage. UnityEditor.Animations.cs builds controllers and clips from them.
namespace UnityEngine
{
    // Modules/Animation/ScriptBindings/Motion.bindings.cs: public partial class Motion : Object (what a state plays).
    public class Motion : Object { }

    // Modules/Animation/ScriptBindings/RuntimeAnimatorController.bindings.cs: public class RuntimeAnimatorController : Object.
    public class RuntimeAnimatorController : Object { }

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
