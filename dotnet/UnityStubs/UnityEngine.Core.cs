// Stand-ins for the parts of UnityEngine that the package's Unity layer uses, so that Runtime/Components and Editor
// compile (and the axis conversions can be tested) with the plain .NET SDK. Signatures follow Unity's published C#
// sources (repo Unity-Technologies/UnityCsReference, file named beside each type); bodies are only what tests need.
// This proves the package's own C# is well-formed against those signatures; it does not prove Unity behaves as stubbed.
// Math is real where tests use it.
using System;

namespace UnityEngine
{
    // Runtime/Export/Scripting/UnityEngineObject.bindings.cs. A destroyed object stays a live C# reference but compares
    // equal to null (operator ==, CompareBaseObjects / IsNativeObjectAlive) and is false as a bool (implicit operator bool).
    public class Object
    {
        string objectName = "";

        // A component's name is its GameObject's (Object.name, native GetName on the GameObject for components).
        public string name
        {
            get => this is Component c && c.owner != null ? c.owner.name : objectName;
            set
            {
                if (this is Component c && c.owner != null) c.owner.name = value;
                else objectName = value;
            }
        }

        // The native object is gone (Destroy at the frame's end, DestroyImmediate at once).
        internal bool destroyed;
        // Destroy was called; the object lives until the frame ends (UnityEngineObject.bindings.cs, Destroy: "Actual object
        // destruction is always delayed until after the current Update loop").
        internal bool destroyPending;

        static bool CompareBaseObjects(Object lhs, Object rhs)
        {
            bool lhsNull = ReferenceEquals(lhs, null) || lhs.destroyed;
            bool rhsNull = ReferenceEquals(rhs, null) || rhs.destroyed;
            if (lhsNull && rhsNull) return true;
            if (lhsNull || rhsNull) return false;
            return ReferenceEquals(lhs, rhs);
        }

        public static bool operator ==(Object x, Object y) => CompareBaseObjects(x, y);
        public static bool operator !=(Object x, Object y) => !CompareBaseObjects(x, y);
        public static implicit operator bool(Object exists) => !CompareBaseObjects(exists, null);
        public override bool Equals(object other) => other is Object o ? CompareBaseObjects(this, o) : other == null && destroyed;
        public override int GetHashCode() => System.Runtime.CompilerServices.RuntimeHelpers.GetHashCode(this);

        // Destroy(Object obj, float t = 0.0F): marked now, destroyed when the frame ends (FrameLoop.EndFrame here).
        public static void Destroy(Object obj, float t = 0.0F)
        {
            if (obj == null || obj.destroyPending) return;
            obj.destroyPending = true;
            FrameLoop.DestroyAtFrameEnd(obj);
        }

        // DestroyImmediate(Object obj, bool allowDestroyingAssets = false): destroyed at once.
        public static void DestroyImmediate(Object obj, bool allowDestroyingAssets = false)
        {
            if (obj == null) return;
            obj.DestroyNow();
        }

        // What destruction does to this kind of object (a GameObject its components and children, a component its messages).
        internal virtual void DestroyNow() => destroyed = true;
    }

    // The stand-ins' frame: Destroy takes effect when it ends. Unity's player loop runs this natively; here [UnityTest]'s
    // stand-in ends a frame at each yield (UnityEngine.TestRunner.cs).
    internal static class FrameLoop
    {
        static readonly System.Collections.Generic.List<Object> pending = new System.Collections.Generic.List<Object>();

        internal static void DestroyAtFrameEnd(Object obj)
        {
            lock (pending) pending.Add(obj);
        }

        internal static void EndFrame()
        {
            Object[] now;
            lock (pending)
            {
                now = pending.ToArray();
                pending.Clear();
            }
            foreach (var o in now)
                if (!o.destroyed) o.DestroyNow();
        }
    }

    // Runtime/Export/Scripting/Component.bindings.cs
    public class Component : Object
    {
        // The GameObject that AddComponent put this on (GameObject.cs in the stand-ins); Unity keeps this link natively.
        internal GameObject owner;

        public Transform transform => this is Transform t ? t : owner?.transform;
        public GameObject gameObject => owner;
        // Component.bindings.cs: GetComponent<T>() and GetComponentInChildren<T>() ask the GameObject.
        public T GetComponent<T>() => owner != null ? owner.GetComponent<T>() : default;
        public T GetComponentInChildren<T>() => owner != null ? owner.GetComponentInChildren<T>() : default;
        public T GetComponentInChildren<T>(bool includeInactive) => owner != null ? owner.GetComponentInChildren<T>(includeInactive) : default;

        internal override void DestroyNow()
        {
            if (destroyed) return;
            if (this is Transform) throw new InvalidOperationException("Destroying the transform component is not allowed."); // Unity logs this and keeps it
            owner?.RemoveComponent(this);
            base.DestroyNow();
        }
    }

    // Runtime/Export/Scripting/Behaviour.bindings.cs: enabled; isActiveAndEnabled. Toggling enabled on an active
    // GameObject sends OnEnable / OnDisable (MonoBehaviour messages, Manual "Order of execution for event functions").
    public class Behaviour : Component
    {
        bool isEnabled = true;

        public bool enabled
        {
            get => isEnabled;
            set
            {
                if (isEnabled == value) return;
                isEnabled = value;
                if (owner == null || !owner.activeInHierarchy || !awoken || destroyed) return;
                Messages.Send(this, value ? "OnEnable" : "OnDisable");
            }
        }

        public bool isActiveAndEnabled => isEnabled && owner != null && owner.activeInHierarchy && !destroyed;

        // Awake has run (it runs once, when the GameObject is first active).
        internal bool awoken;

        internal override void DestroyNow()
        {
            if (destroyed) return;
            bool wasActive = isActiveAndEnabled && awoken;
            if (wasActive) Messages.Send(this, "OnDisable");
            if (awoken) Messages.Send(this, "OnDestroy");
            base.DestroyNow();
        }
    }

    // Runtime/Export/Scripting/MonoBehaviour.bindings.cs. Unity calls the message methods (Awake, OnEnable, OnDisable,
    // OnDestroy) by name whatever their access; a class inherits its base classes' (Manual "MonoBehaviour").
    public class MonoBehaviour : Behaviour { }

    internal static class Messages
    {
        internal static void Send(object target, string message)
        {
            // Outside Play Mode the editor sends a script its messages only with [ExecuteAlways] or [ExecuteInEditMode]
            // (ScriptReference ExecuteAlways).
            if (!Application.isPlaying && !target.GetType().IsDefined(typeof(ExecuteAlways), true)
                && !target.GetType().IsDefined(typeof(ExecuteInEditMode), true)) return;
            for (var type = target.GetType(); type != null && type != typeof(MonoBehaviour); type = type.BaseType)
            {
                var m = type.GetMethod(message, System.Reflection.BindingFlags.Instance | System.Reflection.BindingFlags.Public
                    | System.Reflection.BindingFlags.NonPublic | System.Reflection.BindingFlags.DeclaredOnly, null, Type.EmptyTypes, null);
                if (m == null) continue;
                try
                {
                    m.Invoke(target, null);
                }
                catch (System.Reflection.TargetInvocationException e)
                {
                    System.Runtime.ExceptionServices.ExceptionDispatchInfo.Capture(e.InnerException).Throw();
                }
                return;
            }
        }
    }

    // Runtime/Export/Scripting/ScriptableObject.bindings.cs
    public class ScriptableObject : Object { }

    // Runtime/Export/Scripting/TextAsset.cs: TextAsset(string text), TextAsset(ReadOnlySpan<byte> bytes) (Unity 2022.2+), text
    // decodes the bytes as UTF-8 (DecodeString), bytes are the raw contents.
    public class TextAsset : Object
    {
        readonly byte[] data;
        public TextAsset(string text) { data = System.Text.Encoding.UTF8.GetBytes(text ?? ""); }
        public TextAsset(ReadOnlySpan<byte> bytes) { data = bytes.ToArray(); }
        public string text => System.Text.Encoding.UTF8.GetString(data);
        // Runtime/Export/Scripting/TextAsset.bindings.cs: public extern byte[] bytes { get; } (a copy per call)
        public byte[] bytes => (byte[])data.Clone();
    }

    // Runtime/Export/Debug/Debug.bindings.cs
    public static class Debug
    {
        public static void Log(object message) { }
        public static void Log(object message, Object context) { }
        public static void LogWarning(object message, Object context) { }
        public static void LogError(object message, Object context) { }
    }

    // Runtime/Export/Time/Time.bindings.cs
    public class Time
    {
        public static float deltaTime => 0.0139f;
        public static double realtimeSinceStartupAsDouble => 0;
        public static double unscaledTimeAsDouble => 0;
    }

    // Runtime/Export/Math/Mathf.cs (a struct in Unity)
    public struct Mathf
    {
        public static int Max(int a, int b) => Math.Max(a, b);
    }

    // Runtime/Export/Application/Application.cs
    public class Application
    {
        public static string dataPath => "Assets";

        // Application.bindings.cs: isPlaying { get; }: true in a player and in the editor's Play Mode. The stand-ins run
        // as in Play Mode unless a test of editor code enters the editor's edit mode (StandInEditMode).
        public static bool isPlaying => !StandInEditMode.Active;

        // Application.bindings.cs: platform { get; } (the editor's own platform in the editor, the player's in a player).
        // The stand-ins run as Unity's editor on Linux unless a test picks another (StandInPlatform).
        public static RuntimePlatform platform => StandInPlatform.Current;

        // Application.bindings.cs: persistentDataPath { get; } (per platform; ScriptReference Application.persistentDataPath).
        // The stand-in: a folder of its own under the temporary folder, made on first use.
        public static string persistentDataPath
        {
            get
            {
                string path = System.IO.Path.Combine(System.IO.Path.GetTempPath(), "headgait-standin-persistent-data");
                System.IO.Directory.CreateDirectory(path);
                return path;
            }
        }
    }

    // Runtime/Export/Application/RuntimePlatform (RuntimePlatform.cs): the values the package and its tests name, with Unity's numbers.
    public enum RuntimePlatform
    {
        OSXEditor = 0,
        OSXPlayer = 1,
        WindowsPlayer = 2,
        WindowsEditor = 7,
        IPhonePlayer = 8,
        Android = 11,
        LinuxPlayer = 13,
        LinuxEditor = 16,
    }

    /// <summary>
    /// Not Unity API: the platform the stand-ins report (<see cref="Application.platform"/>): Unity's editor on Linux, or,
    /// inside a test's <c>using (new StandInPlatform(...))</c>, another (a player). Package code never uses it.
    /// </summary>
    public sealed class StandInPlatform : IDisposable
    {
        internal static RuntimePlatform Current = RuntimePlatform.LinuxEditor;
        readonly RuntimePlatform before;

        public StandInPlatform(RuntimePlatform platform)
        {
            before = Current;
            Current = platform;
        }

        public void Dispose() => Current = before;
    }

    // Runtime/Export/Graphics/GraphicsEnums.cs (decompiled builds also list Unknown = 0); LandscapeLeft is counter-clockwise from portrait.
    public enum ScreenOrientation
    {
        Portrait = 1,
        PortraitUpsideDown = 2,
        LandscapeLeft = 3,
        LandscapeRight = 4,
        AutoRotation = 5,
    }

    // Runtime/Export/Graphics/Graphics.bindings.cs
    public sealed class Screen
    {
        public static ScreenOrientation orientation { get; set; } = ScreenOrientation.LandscapeLeft;
        public static int width => 1280;
        public static int height => 720;
    }

    // Modules/InputLegacy/Input.bindings.cs (legacy Input Manager; throws in Input-System-only projects)
    public class Input
    {
        public static Vector3 acceleration => default;
        public static bool compensateSensors { get; set; } = true;
    }

    // Runtime/Export/Math/Vector3.cs
    public struct Vector3
    {
        public float x, y, z;
        public Vector3(float x, float y, float z) { this.x = x; this.y = y; this.z = z; }
        public static Vector3 zero => new Vector3(0, 0, 0);
        public static Vector3 forward => new Vector3(0, 0, 1);
        public static Vector3 operator +(Vector3 a, Vector3 b) => new Vector3(a.x + b.x, a.y + b.y, a.z + b.z);
        public static Vector3 operator -(Vector3 a, Vector3 b) => new Vector3(a.x - b.x, a.y - b.y, a.z - b.z);
        public static Vector3 operator -(Vector3 a) => new Vector3(-a.x, -a.y, -a.z);
        public static Vector3 operator *(Vector3 a, float d) => new Vector3(a.x * d, a.y * d, a.z * d);
        public static Vector3 operator *(float d, Vector3 a) => new Vector3(a.x * d, a.y * d, a.z * d);
        public float magnitude => (float)Math.Sqrt(x * x + y * y + z * z);
        public override string ToString() => $"({x:F2}, {y:F2}, {z:F2})";
    }

    // Runtime/Export/Math/Quaternion.cs
    public struct Quaternion
    {
        public float x, y, z, w;
        public Quaternion(float x, float y, float z, float w) { this.x = x; this.y = y; this.z = z; this.w = w; }
        public static Quaternion identity => new Quaternion(0, 0, 0, 1);
        public static Quaternion Inverse(Quaternion q) => new Quaternion(-q.x, -q.y, -q.z, q.w);

        /// <summary>Unity's order: rotate about z, then x, then y (degrees).</summary>
        public static Quaternion Euler(Vector3 euler) => AngleAxis(euler.y, 0, 1, 0) * AngleAxis(euler.x, 1, 0, 0) * AngleAxis(euler.z, 0, 0, 1);
        public static Quaternion Euler(float x, float y, float z) => Euler(new Vector3(x, y, z));

        static Quaternion AngleAxis(float deg, float ax, float ay, float az)
        {
            double h = deg * Math.PI / 360.0;
            float s = (float)Math.Sin(h);
            return new Quaternion(ax * s, ay * s, az * s, (float)Math.Cos(h));
        }

        public static Quaternion operator *(Quaternion lhs, Quaternion rhs) => new Quaternion(
            lhs.w * rhs.x + lhs.x * rhs.w + lhs.y * rhs.z - lhs.z * rhs.y,
            lhs.w * rhs.y + lhs.y * rhs.w + lhs.z * rhs.x - lhs.x * rhs.z,
            lhs.w * rhs.z + lhs.z * rhs.w + lhs.x * rhs.y - lhs.y * rhs.x,
            lhs.w * rhs.w - lhs.x * rhs.x - lhs.y * rhs.y - lhs.z * rhs.z);

        public static Vector3 operator *(Quaternion rotation, Vector3 point)
        {
            var p = rotation * new Quaternion(point.x, point.y, point.z, 0) * Inverse(rotation);
            return new Vector3(p.x, p.y, p.z);
        }
    }

    // Runtime/Export/Attributes.cs and Runtime/Export/Scripting/SerializeField.cs (PropertyAttribute subclasses in Runtime/Export/PropertyAttribute.cs)
    [AttributeUsage(AttributeTargets.Field)] public sealed class SerializeField : Attribute { }

    // Runtime/Export/Scripting/ExecuteAlways.cs and ExecuteInEditMode (Runtime/Export/Scripting/Attributes.cs).
    [AttributeUsage(AttributeTargets.Class, Inherited = false)] public sealed class ExecuteAlways : Attribute { }
    [AttributeUsage(AttributeTargets.Class, Inherited = false)] public sealed class ExecuteInEditMode : Attribute { }

    /// <summary>
    /// Not Unity API: the stand-ins' switch into the editor's edit mode (Application.isPlaying false, no Awake, OnEnable,
    /// OnDisable or OnDestroy for scripts without [ExecuteAlways]), for tests of editor code such as the prefab builder.
    /// Package code never uses it.
    /// </summary>
    public sealed class StandInEditMode : IDisposable
    {
        internal static bool Active;
        readonly bool before;

        public StandInEditMode()
        {
            before = Active;
            Active = true;
        }

        public void Dispose() => Active = before;
    }
    [AttributeUsage(AttributeTargets.Field)] public sealed class TooltipAttribute : Attribute { public TooltipAttribute(string tooltip) { } }
    [AttributeUsage(AttributeTargets.Field)] public sealed class HeaderAttribute : Attribute { public HeaderAttribute(string header) { } }
    [AttributeUsage(AttributeTargets.Field)] public sealed class RangeAttribute : Attribute { public RangeAttribute(float min, float max) { } }
    [AttributeUsage(AttributeTargets.Class)] public sealed class DisallowMultipleComponent : Attribute { }
    [AttributeUsage(AttributeTargets.Class)] public sealed class AddComponentMenu : Attribute { public AddComponentMenu(string menuName) { } }
}
