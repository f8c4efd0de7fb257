// Stand-ins for the parts of the UnityEngine / UnityEditor API that the package's Unity layer uses, so that
// Runtime/Components and Editor compile (and the axis conversions can be tested) with the plain .NET SDK.
// Only signatures the package calls are here, written after Unity 2021.3's documented API. This proves the
// package's own C# is well-formed; it does not prove Unity's API behaves as stubbed. Math is real where tests use it.
using System;

namespace UnityEngine
{
    public class Object
    {
        public string name { get; set; } = "";
    }

    public class Component : Object
    {
        public T GetComponent<T>() => default;
        public T GetComponentInChildren<T>() => default;
    }

    public class Behaviour : Component
    {
        public bool enabled { get; set; } = true;
    }

    public class MonoBehaviour : Behaviour { }

    public class TextAsset : Object
    {
        public TextAsset(string text) { this.text = text; }
        public string text { get; }
        // UnityCsReference Runtime/Export/Scripting/TextAsset.bindings.cs: public extern byte[] bytes { get; }
        public byte[] bytes => System.Text.Encoding.UTF8.GetBytes(text);
    }

    public static class Debug
    {
        public static void Log(object message) { }
        public static void LogWarning(object message, Object context) { }
        public static void LogError(object message, Object context) { }
    }

    public static class Time
    {
        public static float deltaTime => 0.0139f;
        public static double realtimeSinceStartupAsDouble => 0;
    }

    public static class Mathf
    {
        public static int Max(int a, int b) => Math.Max(a, b);
    }

    public static class Application
    {
        public static string dataPath => "Assets";
    }

    public sealed class Gyroscope
    {
        public bool enabled { get; set; }
    }

    public static class Input
    {
        public static Vector3 acceleration { get; set; }
        public static Gyroscope gyro { get; } = new Gyroscope();
    }

    public struct Vector3
    {
        public float x, y, z;
        public Vector3(float x, float y, float z) { this.x = x; this.y = y; this.z = z; }
        public static Vector3 operator +(Vector3 a, Vector3 b) => new Vector3(a.x + b.x, a.y + b.y, a.z + b.z);
        public static Vector3 operator -(Vector3 a) => new Vector3(-a.x, -a.y, -a.z);
        public static Vector3 operator *(Vector3 a, float d) => new Vector3(a.x * d, a.y * d, a.z * d);
    }

    public struct Quaternion
    {
        public float x, y, z, w;
        public Quaternion(float x, float y, float z, float w) { this.x = x; this.y = y; this.z = z; this.w = w; }
        public static Quaternion identity => new Quaternion(0, 0, 0, 1);
        public static Quaternion Inverse(Quaternion q) => new Quaternion(-q.x, -q.y, -q.z, q.w);

        /// <summary>Unity's order: rotate about z, then x, then y (degrees).</summary>
        public static Quaternion Euler(Vector3 e) => AngleAxis(e.y, 0, 1, 0) * AngleAxis(e.x, 1, 0, 0) * AngleAxis(e.z, 0, 0, 1);

        static Quaternion AngleAxis(float deg, float ax, float ay, float az)
        {
            double h = deg * Math.PI / 360.0;
            float s = (float)Math.Sin(h);
            return new Quaternion(ax * s, ay * s, az * s, (float)Math.Cos(h));
        }

        public static Quaternion operator *(Quaternion a, Quaternion b) => new Quaternion(
            a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y + a.y * b.w + a.z * b.x - a.x * b.z,
            a.w * b.z + a.z * b.w + a.x * b.y - a.y * b.x,
            a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z);

        public static Vector3 operator *(Quaternion q, Vector3 v)
        {
            var p = q * new Quaternion(v.x, v.y, v.z, 0) * Inverse(q);
            return new Vector3(p.x, p.y, p.z);
        }
    }

    [AttributeUsage(AttributeTargets.Field)] public sealed class SerializeField : Attribute { }
    [AttributeUsage(AttributeTargets.Field)] public sealed class TooltipAttribute : Attribute { public TooltipAttribute(string t) { } }
    [AttributeUsage(AttributeTargets.Field)] public sealed class HeaderAttribute : Attribute { public HeaderAttribute(string h) { } }
    [AttributeUsage(AttributeTargets.Field)] public sealed class RangeAttribute : Attribute { public RangeAttribute(float min, float max) { } }
    [AttributeUsage(AttributeTargets.Class)] public sealed class DisallowMultipleComponent : Attribute { }
    [AttributeUsage(AttributeTargets.Class)] public sealed class AddComponentMenu : Attribute { public AddComponentMenu(string menu) { } }
}

namespace UnityEngine.XR
{
    public enum XRNode { LeftEye, RightEye, CenterEye, Head }

    public struct InputFeatureUsage<T>
    {
        public InputFeatureUsage(string name) { this.name = name; }
        public string name { get; }
    }

    public static class CommonUsages
    {
        public static InputFeatureUsage<Vector3> deviceAcceleration = new InputFeatureUsage<Vector3>("DeviceAcceleration");
        public static InputFeatureUsage<Quaternion> deviceRotation = new InputFeatureUsage<Quaternion>("DeviceRotation");
        public static InputFeatureUsage<Vector3> devicePosition = new InputFeatureUsage<Vector3>("DevicePosition");
    }

    public struct InputDevice
    {
        public bool isValid => false;
        public bool TryGetFeatureValue(InputFeatureUsage<Vector3> usage, out Vector3 value) { value = default; return false; }
        public bool TryGetFeatureValue(InputFeatureUsage<Quaternion> usage, out Quaternion value) { value = default; return false; }
    }

    public static class InputDevices
    {
        public static InputDevice GetDeviceAtXRNode(XRNode node) => default;
    }
}

namespace UnityEditor
{
    [AttributeUsage(AttributeTargets.Method)] public sealed class MenuItem : Attribute { public MenuItem(string itemName) { } }

    public static class EditorUtility
    {
        public static string OpenFilePanel(string title, string directory, string extension) => "";
        public static string OpenFolderPanel(string title, string folder, string defaultName) => "";
        public static string SaveFilePanel(string title, string directory, string defaultName, string extension) => "";
        public static bool DisplayDialog(string title, string message, string ok) => true;
    }

    public static class AssetDatabase
    {
        public static void Refresh() { }
    }
}
