// Stand-in for the GameObject members the study's avatar switcher uses. Signatures checked against UnityCsReference
// Runtime/Export/Scripting/GameObject.bindings.cs (GameObject(string), SetActive(bool), activeSelf,
// AddComponent<T>() where T : Component). Activation is
// real here (a flag), so the switcher can be tested.
namespace UnityEngine
{
    public sealed class GameObject : Object
    {
        public GameObject(string name) { this.name = name; }

        public bool activeSelf { get; private set; } = true;

        public void SetActive(bool value) => activeSelf = value;

        public T AddComponent<T>() where T : Component => (T)System.Activator.CreateInstance(typeof(T), true);
    }
}
