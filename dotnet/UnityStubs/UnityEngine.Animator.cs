// Stand-in for UnityEngine.Animator (moved here unchanged from UnityEngineStubs.cs; owned with the animator component).
namespace UnityEngine
{
    public class Animator : Behaviour
    {
        public void SetInteger(string name, int value) { }
        public void SetFloat(string name, float value) { }
        public void SetBool(string name, bool value) { }
    }
}
