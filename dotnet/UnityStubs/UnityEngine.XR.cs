// Stand-ins for the UnityEngine.XR members the legacy (Input Manager) fallback uses.
// Source: repo Unity-Technologies/UnityCsReference, Modules/XR/ScriptBindings/XRInput.bindings.cs.
using System;

namespace UnityEngine.XR
{
    public enum XRNode { LeftEye, RightEye, CenterEye, Head }

    // Bit flags of what a tracked device reports; Acceleration = 16 says the acceleration is valid.
    [Flags]
    public enum InputTrackingState : uint
    {
        None = 0,
        Position = 1 << 0,
        Rotation = 1 << 1,
        Velocity = 1 << 2,
        AngularVelocity = 1 << 3,
        Acceleration = 1 << 4,
        AngularAcceleration = 1 << 5,
        All = 63,
    }

    public struct InputFeatureUsage<T>
    {
        public InputFeatureUsage(string usageName) { name = usageName; }
        public string name { get; set; }
    }

    public static class CommonUsages
    {
        public static InputFeatureUsage<InputTrackingState> trackingState = new InputFeatureUsage<InputTrackingState>("TrackingState");
        public static InputFeatureUsage<Vector3> devicePosition = new InputFeatureUsage<Vector3>("DevicePosition");
        public static InputFeatureUsage<Quaternion> deviceRotation = new InputFeatureUsage<Quaternion>("DeviceRotation");
        public static InputFeatureUsage<Vector3> deviceAcceleration = new InputFeatureUsage<Vector3>("DeviceAcceleration");
        public static InputFeatureUsage<bool> userPresence = new InputFeatureUsage<bool>("UserPresence");
    }

    public struct InputDevice
    {
        public bool isValid => false;
        public bool TryGetFeatureValue(InputFeatureUsage<Vector3> usage, out Vector3 value) { value = default; return false; }
        public bool TryGetFeatureValue(InputFeatureUsage<Quaternion> usage, out Quaternion value) { value = default; return false; }
        public bool TryGetFeatureValue(InputFeatureUsage<InputTrackingState> usage, out InputTrackingState value) { value = default; return false; }
        public bool TryGetFeatureValue(InputFeatureUsage<bool> usage, out bool value) { value = default; return false; }
    }

    public class InputDevices
    {
        public static InputDevice GetDeviceAtXRNode(XRNode node) => default;
    }
}
