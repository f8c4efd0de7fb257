// Stand-ins for the Input System (package com.unity.inputsystem 1.7+) members the head source uses. Signatures follow
// repo Unity-Technologies/InputSystem, Packages/com.unity.inputsystem/InputSystem/<file named beside each type>;
// bodies are empty except where the head reader depends on them (child controls, the device list): tests drive the
// plain classes in Runtime/Components/Sensors.
using System;
using System.Collections;
using System.Collections.Generic;
using UnityEngine.InputSystem.Controls;
using UnityEngine.InputSystem.LowLevel;
using UnityEngine.InputSystem.Utilities;

namespace UnityEngine.InputSystem
{
    // Controls/InputControl.cs
    public abstract class InputControl
    {
        // Set by the stand-ins' tests (Unity builds controls from layouts).
        internal string controlName = "";
        internal readonly List<InputControl> childControls = new List<InputControl>();

        public string name => controlName;

        // TryGetChildControl(string path): InputControlPath.TryFindChild; here a direct child by name, case-insensitive as
        // control paths are. ArgumentNullException for a null or empty path.
        public InputControl TryGetChildControl(string path)
        {
            if (string.IsNullOrEmpty(path)) throw new ArgumentNullException(nameof(path));
            foreach (var c in childControls)
                if (string.Equals(c.controlName, path, StringComparison.OrdinalIgnoreCase)) return c;
            return null;
        }

        // TryGetChildControl<TControl>(string path): null when there is no such child, InvalidOperationException when the
        // child is of another type ("Expected control '...' to be of type '...' but is of type '...' instead!").
        public TControl TryGetChildControl<TControl>(string path) where TControl : InputControl
        {
            var control = TryGetChildControl(path);
            if (control == null) return null;
            return control as TControl ?? throw new InvalidOperationException(
                $"Expected control '{path}' to be of type '{typeof(TControl).Name}' but is of type '{control.GetType().Name}' instead!");
        }
    }

    // Controls/InputControl.cs (InputControl<TValue>)
    public abstract class InputControl<TValue> : InputControl where TValue : struct
    {
        public TValue ReadValue() => default;
    }

    // Controls/InputControlExtensions.cs: false when the event carries no state for the control.
    public static class InputControlExtensions
    {
        public static bool ReadValueFromEvent<TValue>(this InputControl<TValue> control, InputEventPtr inputEvent, out TValue value) where TValue : struct
        {
            value = default;
            return false;
        }
    }

    // Devices/InputDevice.cs
    public class InputDevice : InputControl
    {
        public int deviceId => 0;
        public bool enabled => false;
    }

    // Devices/InputDeviceChange.cs
    public enum InputDeviceChange
    {
        Added,
        Removed,
        Disconnected,
        Reconnected,
        Enabled,
        Disabled,
        UsageChanged,
        ConfigurationChanged,
    }

    // Devices/Sensor.cs: the setter sends SetSamplingFrequencyCommand; the getter throws NotSupportedException where the
    // platform cannot report the rate.
    public class Sensor : InputDevice
    {
        public float samplingFrequency { get => throw new NotSupportedException(); set { } }
    }

    // Devices/Sensor.cs: acceleration in g; on Android AndroidCompensateDirection multiplies the m/s^2 reading by
    // -1/9.80665 (Plugins/Android/AndroidSensors.cs); CompensateDirection rotates it into screen axes when
    // InputSettings.compensateForScreenOrientation is set (Controls/Processors/CompensateDirectionProcessor.cs).
    public class Accelerometer : Sensor
    {
        public Vector3Control acceleration { get; private set; }
        public static Accelerometer current { get; private set; }
    }

    // Devices/Sensor.cs
    public class LinearAccelerationSensor : Sensor
    {
        public Vector3Control acceleration { get; private set; }
        public static LinearAccelerationSensor current { get; private set; }
    }

    // Devices/Sensor.cs
    public class GravitySensor : Sensor
    {
        public Vector3Control gravity { get; private set; }
        public static GravitySensor current { get; private set; }
    }

    // InputSettings.cs
    public class InputSettings : ScriptableObject
    {
        public bool compensateForScreenOrientation { get; set; }
    }

    // InputSystem.cs
    public static partial class InputSystem
    {
        public static InputEventListener onEvent { get => default; set { } }
        public static event Action<InputDevice, InputDeviceChange> onDeviceChange { add { } remove { } }
        // The devices the stand-ins' tests added (Unity: every device the runtime reported).
        internal static readonly List<InputDevice> addedDevices = new List<InputDevice>();
        public static ReadOnlyArray<InputDevice> devices => new ReadOnlyArray<InputDevice>(addedDevices.ToArray());
        public static InputSettings settings { get; set; }
        public static void EnableDevice(InputDevice device) { }
        public static void DisableDevice(InputDevice device, bool keepSendingEvents = false) { }
    }
}

namespace UnityEngine.InputSystem.Controls
{
    // Controls/Vector3Control.cs
    public class Vector3Control : InputControl<Vector3> { }

    // Controls/QuaternionControl.cs
    public class QuaternionControl : InputControl<Quaternion> { }

    // Controls/IntegerControl.cs (TrackedDevice.trackingState carries UnityEngine.XR.InputTrackingState bits)
    public class IntegerControl : InputControl<int> { }

    // Controls/AxisControl.cs
    public class AxisControl : InputControl<float> { }

    // Controls/ButtonControl.cs (OculusHMD's userPresence, OpenXRHmd's UserPresence: XR bool features become buttons)
    public class ButtonControl : AxisControl { }
}

namespace UnityEngine.InputSystem.LowLevel
{
    // Events/IInputEventTypeInfo.cs (1.x: a typeStatic property; early previews had GetTypeStatic())
    public interface IInputEventTypeInfo
    {
        FourCC typeStatic { get; }
    }

    // Events/StateEvent.cs
    public struct StateEvent : IInputEventTypeInfo
    {
        public const int Type = 0x53544154; // 'STAT'
        public FourCC typeStatic => Type;
    }

    // Events/DeltaStateEvent.cs
    public struct DeltaStateEvent : IInputEventTypeInfo
    {
        public const int Type = 0x444C5441; // 'DLTA'
        public FourCC typeStatic => Type;
    }

    // Events/InputEventPtr.cs (an unsafe pointer wrapper in the package; only the members the source reads here).
    // time is on the realtimeSinceStartup timeline.
    public struct InputEventPtr
    {
        public bool valid => false;
        public int deviceId => 0;
        public double time => 0;
        public FourCC type => default;
        public bool IsA<TOtherEvent>() where TOtherEvent : struct, IInputEventTypeInfo => false;
    }

    // Events/InputEventListener.cs: InputSystem.onEvent += (eventPtr, device) => ... adds through these operators.
    public struct InputEventListener
    {
        public static InputEventListener operator +(InputEventListener _, Action<InputEventPtr, InputDevice> callback) => default;
        public static InputEventListener operator -(InputEventListener _, Action<InputEventPtr, InputDevice> callback) => default;
    }
}

namespace UnityEngine.InputSystem.Utilities
{
    // Utilities/FourCC.cs
    public struct FourCC
    {
        readonly int code;
        public FourCC(int code) { this.code = code; }
        public static implicit operator FourCC(int i) => new FourCC(i);
        public static implicit operator int(FourCC i) => i.code;
    }

    // Utilities/ReadOnlyArray.cs
    public struct ReadOnlyArray<TValue> : IReadOnlyList<TValue>
    {
        readonly TValue[] array;
        public ReadOnlyArray(TValue[] array) { this.array = array; }
        public int Count => array?.Length ?? 0;
        public TValue this[int index] => array != null ? array[index] : throw new IndexOutOfRangeException();
        public IEnumerator<TValue> GetEnumerator()
        {
            for (int i = 0; i < Count; i++) yield return array[i];
        }
        IEnumerator IEnumerable.GetEnumerator() => GetEnumerator();
    }
}
