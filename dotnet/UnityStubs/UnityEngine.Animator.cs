// Stand-in for UnityEngine.Animator and its controller-parameter types, after UnityCsReference
// Modules/Animation/ScriptBindings/Animator.bindings.cs (Animator, AnimatorControllerParameterType) and
// Modules/Animation/ScriptBindings/AnimatorControllerParameter.bindings.cs (AnimatorControllerParameter).
// Signatures match those files; bodies are only what the tests need.
using System.Text;

namespace UnityEngine
{
    // Animator.bindings.cs: public enum AnimatorControllerParameterType { Float = 1, Int = 3, Bool = 4, Trigger = 9 }
    public enum AnimatorControllerParameterType
    {
        Float = 1,
        Int = 3,
        Bool = 4,
        Trigger = 9,
    }

    // AnimatorControllerParameter.bindings.cs: a class with settable name/type/defaults and nameHash = Animator.StringToHash(name).
    public class AnimatorControllerParameter
    {
        public string name { get; set; } = "";
        public int nameHash => Animator.StringToHash(name);
        public AnimatorControllerParameterType type { get; set; }
        public float defaultFloat { get; set; }
        public int defaultInt { get; set; }
        public bool defaultBool { get; set; }
    }

    public class Animator : Behaviour
    {
        // Animator.bindings.cs: runtimeAnimatorController { get; set; } (the controller or override controller it plays).
        public RuntimeAnimatorController runtimeAnimatorController { get; set; }

        // Animator.bindings.cs: SetInteger/SetFloat/SetBool by name and by id (int hash).
        public void SetInteger(string name, int value) { }
        public void SetInteger(int id, int value) { }
        public void SetFloat(string name, float value) { }
        public void SetFloat(int id, float value) { }
        public void SetBool(string name, bool value) { }

        // Animator.bindings.cs: extern public bool isInitialized { get; }
        public bool isInitialized => true;

        // Animator.bindings.cs: extern public AnimatorControllerParameter[] parameters { get; } (a fresh array per call).
        public AnimatorControllerParameter[] parameters => new AnimatorControllerParameter[0];

        // Animator.bindings.cs: extern public static int StringToHash(string name), native "ScriptingStringToCRC32".
        public static int StringToHash(string name)
        {
            uint crc = 0xFFFFFFFFu;
            foreach (byte b in Encoding.UTF8.GetBytes(name ?? ""))
            {
                crc ^= b;
                for (int k = 0; k < 8; k++) crc = (crc & 1) != 0 ? (crc >> 1) ^ 0xEDB88320u : crc >> 1;
            }
            return unchecked((int)~crc);
        }
    }
}
