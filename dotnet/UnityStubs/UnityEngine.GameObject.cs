// Stand-ins for the GameObject / Transform members the package's components use. Signatures checked against
// UnityCsReference: Runtime/Export/Scripting/GameObject.bindings.cs (GameObject(string), GameObject(string, params
// Type[]), SetActive(bool), activeSelf, activeInHierarchy, transform, AddComponent<T>() where T : Component,
// GetComponent<T>(), GetComponents<T>(), GetComponentInChildren<T>(bool)), Runtime/Transform/ScriptBindings/Transform.bindings.cs (parent,
// SetParent(Transform, bool), childCount, GetChild(int), Find(string), localPosition, localRotation, localScale, position,
// rotation, lossyScale, forward, SetPositionAndRotation(Vector3, Quaternion)), Runtime/Export/Scripting/Component.bindings.cs
// (transform, gameObject), Runtime/Transform/ScriptBindings/RectTransform.bindings.cs (anchorMin, anchorMax,
// anchoredPosition, sizeDelta, pivot), Runtime/Export/Math/Vector2.cs, Runtime/Export/Math/Color.cs,
// Runtime/Export/Resources/Resources.cs (GetBuiltinResource<T>(string) where T : Object),
// Modules/TextRendering/TextRendering.bindings.cs (Font, TextAnchor), Modules/UI/ScriptBindings/UICanvas.bindings.cs
// (Canvas.renderMode, RenderMode). Messages follow the Manual's "Order of execution for event functions": AddComponent
// on an active GameObject runs the new component's Awake, then OnEnable when it is enabled, before it returns; a
// GameObject made active runs Awake (first time) and OnEnable of its components and its active children's; made
// inactive, OnDisable. Start and Update are not run (no player loop here; tests call what they need).
using System;
using System.Collections.Generic;

namespace UnityEngine
{
    public sealed class GameObject : Object
    {
        readonly List<Component> components = new List<Component>();

        public GameObject(string name)
        {
            this.name = name;
            transform = new Transform();
            Attach(transform);
        }

        // GameObject(string name, params Type[] components): a RectTransform in the list replaces the Transform (as uGUI's
        // objects are made); the others are added in order, each with AddComponent's messages.
        public GameObject(string name, params Type[] components)
        {
            this.name = name;
            bool rect = Array.IndexOf(components, typeof(RectTransform)) >= 0;
            transform = rect ? new RectTransform() : new Transform();
            Attach(transform);
            foreach (var t in components)
                if (t != typeof(RectTransform) && t != typeof(Transform)) AddComponent(t);
        }

        public bool activeSelf { get; private set; } = true;

        // activeInHierarchy: active itself and every parent active.
        public bool activeInHierarchy => activeSelf && (transform.parent == null || transform.parent.gameObject.activeInHierarchy);

        public void SetActive(bool value)
        {
            if (activeSelf == value) return;
            bool before = activeInHierarchy;
            activeSelf = value;
            if (before != activeInHierarchy) SendActivation(activeInHierarchy);
        }

        // Awake (first activation) and OnEnable, or OnDisable, on this object's components and on its children whose own
        // activeSelf lets the change reach them.
        internal void SendActivation(bool nowActive)
        {
            // In script execution order (Manual "Script Execution Order settings": Awake and OnEnable of the scripts
            // activated together run in that order; [DefaultExecutionOrder] sets it), then the order they were added.
            var ordered = new List<Component>(components);
            ordered.Sort((a, b) => ExecutionOrder(a) != ExecutionOrder(b) ? ExecutionOrder(a).CompareTo(ExecutionOrder(b)) : components.IndexOf(a).CompareTo(components.IndexOf(b)));
            foreach (var c in ordered)
                if (c is Behaviour b && !b.destroyed)
                {
                    if (nowActive) Wake(b);
                    else if (b.enabled && b.awoken) Messages.Send(b, "OnDisable");
                }
            foreach (var child in transform.children.ToArray())
                if (child.gameObject.activeSelf) child.gameObject.SendActivation(nowActive);
        }

        static int ExecutionOrder(Component c)
            => Attribute.GetCustomAttribute(c.GetType(), typeof(DefaultExecutionOrder)) is DefaultExecutionOrder o ? o.order : 0;

        static void Wake(Behaviour b)
        {
            if (!b.awoken)
            {
                b.awoken = true;
                Messages.Send(b, "Awake");
            }
            if (b.enabled && !b.destroyed && b.owner != null && b.owner.activeInHierarchy) Messages.Send(b, "OnEnable");
        }

        public Transform transform { get; private set; }

        public T AddComponent<T>() where T : Component => (T)AddComponent(typeof(T));

        public Component AddComponent(Type componentType)
        {
            var component = (Component)Activator.CreateInstance(componentType, true);
            Attach(component);
            // Awake and OnEnable run inside AddComponent when the GameObject is active; otherwise on its activation.
            if (component is Behaviour b && activeInHierarchy) Wake(b);
            return component;
        }

        void Attach(Component c)
        {
            c.owner = this;
            components.Add(c);
        }

        internal void RemoveComponent(Component c) => components.Remove(c);

        // GetComponent<T>(): the first component that is a T (its type, a derived type, or one implementing T), else null.
        public T GetComponent<T>()
        {
            foreach (var c in components)
                if (c is T t && !c.destroyed) return t;
            return default;
        }

        // GetComponents<T>(): every component that is a T, in the order the GameObject lists them.
        public T[] GetComponents<T>()
        {
            var found = new List<T>();
            foreach (var c in components)
                if (c is T t && !c.destroyed) found.Add(t);
            return found.ToArray();
        }

        // GetComponentInChildren<T>(bool includeInactive = false): this GameObject, then its children depth first; inactive
        // GameObjects are skipped unless includeInactive.
        public T GetComponentInChildren<T>() => GetComponentInChildren<T>(false);

        public T GetComponentInChildren<T>(bool includeInactive)
        {
            if (!includeInactive && !activeInHierarchy) return default;
            var own = GetComponent<T>();
            if (own != null) return own;
            foreach (var child in transform.children)
            {
                var found = child.gameObject.GetComponentInChildren<T>(includeInactive);
                if (found != null) return found;
            }
            return default;
        }

        // What a prefab asset holds of this hierarchy (PrefabUtility.SaveAsPrefabAsset in the UnityEditor stand-in): a copy of
        // every GameObject, Transform and component, with no messages sent (an asset is in no scene). A script's serialized
        // fields are copied (public, or [SerializeField], not static or readonly); a built-in component's whole state; a
        // reference to an object inside the hierarchy is remapped to its copy, one to an asset kept.
        internal GameObject CopyForAsset()
        {
            var map = new Dictionary<Object, Object>();
            var pairs = new List<(Component From, Component To)>();
            var copy = CopyTree(this, null, map, pairs);
            foreach (var (from, to) in pairs) CopyFields(from, to, map);
            return copy;
        }

        static GameObject CopyTree(GameObject source, Transform parent, Dictionary<Object, Object> map, List<(Component, Component)> pairs)
        {
            var copy = new GameObject(source.name) { activeSelf = source.activeSelf };
            map[source] = copy;
            map[source.transform] = copy.transform;
            copy.transform.localPosition = source.transform.localPosition;
            copy.transform.localRotation = source.transform.localRotation;
            copy.transform.localScale = source.transform.localScale;
            if (parent != null) copy.transform.SetParent(parent, false);
            foreach (var c in source.components)
            {
                if (c is Transform || c.destroyed) continue;
                var to = (Component)Activator.CreateInstance(c.GetType(), true);
                copy.Attach(to);
                if (to is Behaviour b) b.enabled = ((Behaviour)c).enabled;
                map[c] = to;
                pairs.Add((c, to));
            }
            foreach (var child in source.transform.children) CopyTree(child.gameObject, copy.transform, map, pairs);
            return copy;
        }

        static void CopyFields(Component from, Component to, Dictionary<Object, Object> map)
        {
            bool script = from is MonoBehaviour;
            for (var type = from.GetType(); type != typeof(Behaviour) && type != typeof(Component) && type != typeof(MonoBehaviour); type = type.BaseType)
                foreach (var f in type.GetFields(System.Reflection.BindingFlags.Instance | System.Reflection.BindingFlags.Public
                    | System.Reflection.BindingFlags.NonPublic | System.Reflection.BindingFlags.DeclaredOnly))
                {
                    if (script && (f.IsInitOnly || !(f.IsPublic || f.IsDefined(typeof(SerializeField), false)))) continue;
                    object value = f.GetValue(from);
                    if (value is Object o && map.TryGetValue(o, out var mapped)) value = mapped;
                    f.SetValue(to, value);
                }
        }

        // Destroying a GameObject destroys its children and components (OnDisable, then OnDestroy, each once).
        internal override void DestroyNow()
        {
            if (destroyed) return;
            foreach (var child in transform.children.ToArray()) child.gameObject.DestroyNow();
            foreach (var c in components.ToArray())
                if (!(c is Transform)) c.DestroyNow();
            transform.SetParent(null, false);
            transform.destroyed = true;
            destroyed = true;
        }
    }

    public class Transform : Component
    {
        internal readonly List<Transform> children = new List<Transform>();
        Transform parentTransform;

        public Vector3 localPosition { get; set; }
        public Quaternion localRotation { get; set; } = Quaternion.identity;
        // A new Transform has scale one.
        public Vector3 localScale { get; set; } = new Vector3(1, 1, 1);

        public Transform parent
        {
            get => parentTransform;
            set => SetParent(value, true);
        }

        // SetParent(Transform parent, bool worldPositionStays): with worldPositionStays the world position and rotation are
        // kept (the local ones recomputed under the new parent; scale is not compensated here), else the local ones.
        public void SetParent(Transform parent, bool worldPositionStays)
        {
            if (parent == parentTransform) return;
            for (var p = parent; p != null; p = p.parentTransform)
                if (p == this) throw new InvalidOperationException("a transform cannot be its own ancestor");
            var worldPosition = position;
            var worldRotation = rotation;
            bool wasActive = owner != null && owner.activeInHierarchy;
            parentTransform?.children.Remove(this);
            parentTransform = parent;
            parent?.children.Add(this);
            if (worldPositionStays) SetPositionAndRotation(worldPosition, worldRotation);
            if (owner != null && wasActive != owner.activeInHierarchy) owner.SendActivation(!wasActive);
        }

        public void SetParent(Transform parent) => SetParent(parent, true);

        public int childCount => children.Count;

        public Transform GetChild(int index) => children[index];

        // Find(string n): a child by name, or a path of names separated by '/'; null when there is none.
        public Transform Find(string n)
        {
            var current = this;
            foreach (var part in n.Split('/'))
            {
                Transform next = null;
                foreach (var c in current.children)
                    if (c.owner != null && c.owner.name == part)
                    {
                        next = c;
                        break;
                    }
                if (next == null) return null;
                current = next;
            }
            return current;
        }

        // World space through the parents: parent.position + parent.rotation * (parent.lossyScale * localPosition).
        public Vector3 position
        {
            get
            {
                if (parentTransform == null) return localPosition;
                var s = parentTransform.lossyScale;
                var l = localPosition;
                return parentTransform.position + parentTransform.rotation * new Vector3(l.x * s.x, l.y * s.y, l.z * s.z);
            }
            set
            {
                if (parentTransform == null)
                {
                    localPosition = value;
                    return;
                }
                var s = parentTransform.lossyScale;
                var l = Quaternion.Inverse(parentTransform.rotation) * (value - parentTransform.position);
                localPosition = new Vector3(s.x != 0 ? l.x / s.x : 0, s.y != 0 ? l.y / s.y : 0, s.z != 0 ? l.z / s.z : 0);
            }
        }

        public Quaternion rotation
        {
            get => parentTransform == null ? localRotation : parentTransform.rotation * localRotation;
            set => localRotation = parentTransform == null ? value : Quaternion.Inverse(parentTransform.rotation) * value;
        }

        // lossyScale: the scales multiplied down the hierarchy (exact unless a rotated parent scales non-uniformly).
        public Vector3 lossyScale
        {
            get
            {
                var s = localScale;
                if (parentTransform == null) return s;
                var p = parentTransform.lossyScale;
                return new Vector3(s.x * p.x, s.y * p.y, s.z * p.z);
            }
        }

        public Vector3 forward => rotation * Vector3.forward; // Unity also has a setter (LookRotation), unused here
        public void SetPositionAndRotation(Vector3 position, Quaternion rotation)
        {
            this.rotation = rotation;
            this.position = position;
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
        // GetBuiltinResource<T>(string path): an object of the "unity default resources" library by file name (the primitive
        // meshes "Cube.fbx", "Sphere.fbx", "Capsule.fbx", "Cylinder.fbx", "Plane.fbx", "Quad.fbx"; the Arial font); null
        // for another name (Unity logs that it is not found). One object per name, as the library holds one.
        static readonly Dictionary<string, Object> builtins = new Dictionary<string, Object>();

        public static T GetBuiltinResource<T>(string path) where T : Object
        {
            if (!builtins.TryGetValue(path ?? "", out var found))
            {
                bool mesh = Array.IndexOf(new[] { "Cube.fbx", "Sphere.fbx", "Capsule.fbx", "Cylinder.fbx", "Plane.fbx", "Quad.fbx" }, path) >= 0;
                found = mesh ? new Mesh() : path == "Arial.ttf" || path == "LegacyRuntime.ttf" ? new Font() : null;
                if (found == null) return null;
                found.name = System.IO.Path.GetFileNameWithoutExtension(path);
                builtins[path] = found;
            }
            return found as T;
        }
    }

    public enum RenderMode { ScreenSpaceOverlay = 0, ScreenSpaceCamera = 1, WorldSpace = 2 }

    public sealed class Canvas : Behaviour
    {
        public RenderMode renderMode { get; set; }
    }
}
