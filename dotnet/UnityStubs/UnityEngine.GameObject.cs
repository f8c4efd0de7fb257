// Stand-ins for the GameObject / Transform members the study's components use. Signatures checked against
// UnityCsReference: Runtime/Export/Scripting/GameObject.bindings.cs (GameObject(string), GameObject(string, params
// Type[]), SetActive(bool), activeSelf, transform, AddComponent<T>() where T : Component),
// Runtime/Transform/ScriptBindings/Transform.bindings.cs (SetParent(Transform, bool), localPosition, localRotation,
// localScale, position, rotation, forward, SetPositionAndRotation(Vector3, Quaternion)),
// Runtime/Export/Scripting/Component.bindings.cs (transform, gameObject: the link AddComponent makes here),
// Runtime/Transform/ScriptBindings/RectTransform.bindings.cs (anchorMin, anchorMax, anchoredPosition,
// sizeDelta, pivot), Runtime/Export/Math/Vector2.cs, Runtime/Export/Math/Color.cs, Runtime/Export/Resources/Resources.cs
// (GetBuiltinResource<T>(string) where T : Object), Modules/TextRendering/TextRendering.bindings.cs (Font, TextAnchor),
// Modules/UI/ScriptBindings/UICanvas.bindings.cs (Canvas.renderMode, RenderMode). Activation is real here (a flag),
// so the avatar switcher can be tested; the rest only compiles.
using System;

namespace UnityEngine
{
    public sealed class GameObject : Object
    {
        public GameObject(string name)
        {
            this.name = name;
            transform = new Transform { owner = this };
        }

        public GameObject(string name, params Type[] components) : this(name) { }

        public bool activeSelf { get; private set; } = true;

        public void SetActive(bool value) => activeSelf = value;

        public Transform transform { get; }

        public T AddComponent<T>() where T : Component
        {
            var component = (T)Activator.CreateInstance(typeof(T), true);
            component.owner = this;
            return component;
        }
    }

    public class Transform : Component
    {
        public Vector3 localPosition { get; set; }
        public Quaternion localRotation { get; set; } = Quaternion.identity;
        public Vector3 localScale { get; set; }
        public void SetParent(Transform parent, bool worldPositionStays) { }

        // World space. The stand-in keeps no hierarchy (SetParent does nothing), so world and local are the same.
        public Vector3 position { get => localPosition; set => localPosition = value; }
        public Quaternion rotation { get => localRotation; set => localRotation = value; }
        public Vector3 forward => rotation * Vector3.forward; // Unity also has a setter (LookRotation), unused here
        public void SetPositionAndRotation(Vector3 position, Quaternion rotation)
        {
            this.position = position;
            this.rotation = rotation;
        }
    }

    // Modules/TextRendering/TextRendering.bindings.cs: a world-space text (built-in module, no UI package needed).
    public sealed class TextMesh : Component
    {
        public string text { get; set; }
    }

    public sealed class RectTransform : Transform
    {
        public Vector2 anchorMin { get; set; }
        public Vector2 anchorMax { get; set; }
        public Vector2 anchoredPosition { get; set; }
        public Vector2 sizeDelta { get; set; }
        public Vector2 pivot { get; set; }
    }

    public struct Vector2
    {
        public float x, y;
        public Vector2(float x, float y) { this.x = x; this.y = y; }
    }

    public struct Color
    {
        public float r, g, b, a;
        public Color(float r, float g, float b, float a) { this.r = r; this.g = g; this.b = b; this.a = a; }
    }

    public sealed class Font : Object { }

    public enum TextAnchor { UpperLeft = 0, UpperCenter = 1, UpperRight = 2, MiddleLeft = 3, MiddleCenter = 4, MiddleRight = 5 }

    public sealed class Resources
    {
        public static T GetBuiltinResource<T>(string path) where T : Object => default;
    }

    public enum RenderMode { ScreenSpaceOverlay = 0, ScreenSpaceCamera = 1, WorldSpace = 2 }

    public sealed class Canvas : Behaviour
    {
        public RenderMode renderMode { get; set; }
    }
}
