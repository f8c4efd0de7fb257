// Stand-ins for the parts of UnityEngine that the package's Unity layer uses, so that Runtime/Components and Editor
// compile (and the axis conversions can be tested) with the plain .NET SDK. Signatures follow Unity's published C#
// sources (repo Unity-Technologies/UnityCsReference, file named beside each type); bodies are only what tests need.
// This proves the package's own C# is well-formed against those signatures; it does not prove Unity behaves as stubbed.
// Math is real where tests use it.
using System;

namespace UnityEngine
{
    // Runtime/Export/Scripting/UnityEngineObject.bindings.cs
    public class Object
    {
        public string name { get; set; } = "";
    }

    // Runtime/Export/Scripting/Component.bindings.cs
    public class Component : Object
    {
        // The GameObject that AddComponent put this on (GameObject.cs in the stand-ins); Unity keeps this link natively.
        internal GameObject owner;

        public Transform transform => this is Transform t ? t : owner?.transform;
        public GameObject gameObject => owner;
        public T GetComponent<T>() => default;
        public T GetComponentInChildren<T>() => default;
    }

    // Runtime/Export/Scripting/Behaviour.bindings.cs
    public class Behaviour : Component
    {
        public bool enabled { get; set; } = true;
    }

    // Runtime/Export/Scripting/MonoBehaviour.bindings.cs
    public class MonoBehaviour : Behaviour { }

    // Runtime/Export/Scripting/ScriptableObject.bindings.cs
    public class ScriptableObject : Object { }

    // Runtime/Export/Scripting/TextAsset.cs
    public class TextAsset : Object
    {
        public TextAsset(string text) { this.text = text; }
        public string text { get; }
        // Runtime/Export/Scripting/TextAsset.bindings.cs: public extern byte[] bytes { get; }
        public byte[] bytes => System.Text.Encoding.UTF8.GetBytes(text);
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
        // Runtime/Export/Application/Application.bindings.cs
        public static string persistentDataPath => System.IO.Path.GetTempPath();
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
    [AttributeUsage(AttributeTargets.Field)] public sealed class TooltipAttribute : Attribute { public TooltipAttribute(string tooltip) { } }
    [AttributeUsage(AttributeTargets.Field)] public sealed class HeaderAttribute : Attribute { public HeaderAttribute(string header) { } }
    [AttributeUsage(AttributeTargets.Field)] public sealed class RangeAttribute : Attribute { public RangeAttribute(float min, float max) { } }
    [AttributeUsage(AttributeTargets.Class)] public sealed class DisallowMultipleComponent : Attribute { }
    [AttributeUsage(AttributeTargets.Class)] public sealed class AddComponentMenu : Attribute { public AddComponentMenu(string menuName) { } }
}
