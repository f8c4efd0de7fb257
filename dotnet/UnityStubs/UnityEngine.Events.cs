// Stand-in for UnityEvent, which lives in UnityEngine itself (UnityEngine.CoreModule), not in uGUI: UnityCsReference
// Runtime/Export/UnityEvent/UnityEvent.cs (UnityEvent.AddListener(UnityAction)) and UnityEvent_0.cs (UnityAction).
namespace UnityEngine.Events
{
    public delegate void UnityAction();

    public abstract class UnityEventBase { }

    public class UnityEvent : UnityEventBase
    {
        public void AddListener(UnityAction call) { }
    }
}
