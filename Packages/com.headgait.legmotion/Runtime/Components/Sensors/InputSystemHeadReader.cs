#if ENABLE_INPUT_SYSTEM
using System;
using System.Collections.Generic;
using UnityEngine;
using UnityEngine.InputSystem;
using UnityEngine.InputSystem.Controls;
using UnityEngine.InputSystem.LowLevel;

namespace HeadGait.Unity
{
    /// <summary>
    /// Reads the head through the Input System: every state event of the bound devices, with the event's own time
    /// (realtimeSinceStartup timeline), goes to a <see cref="HeadSampleRouter"/>, so several samples per frame all arrive.
    /// The headset is found by its XRHMD controls (centerEyePosition/centerEyeRotation; acceleration where the layout
    /// has centerEyeAcceleration or deviceAcceleration, as OculusHMD does) rather than by type, so it also works where
    /// the Input System's XR layouts are compiled out. Sensors are enabled here (they start disabled) at 100 Hz.
    /// </summary>
    sealed class InputSystemHeadReader : IDisposable
    {
        const float SensorRate = 100f;

        readonly HeadSampleRouter router;
        readonly Action<InputEventPtr, InputDevice> onEvent;
        readonly Action<InputDevice, InputDeviceChange> onDeviceChange;
        readonly List<InputDevice> enabledHere = new List<InputDevice>();

        InputDevice head;
        Vector3Control headPosition, headAcceleration;
        QuaternionControl headRotation;
        IntegerControl headTracking;
        ButtonControl headPresence;
        bool? lastPresence; // a delta event may leave the presence out: the last one read holds
        Accelerometer accelerometer;
        LinearAccelerationSensor linear;
        GravitySensor gravity;

        public InputSystemHeadReader(HeadSampleRouter router)
        {
            this.router = router;
            onEvent = OnEvent;
            onDeviceChange = OnDeviceChange;
            var devices = InputSystem.devices;
            for (int i = 0; i < devices.Count; i++) Bind(devices[i]);
            InputSystem.onEvent += onEvent;
            InputSystem.onDeviceChange += onDeviceChange;
        }

        public void Dispose()
        {
            InputSystem.onEvent -= onEvent;
            InputSystem.onDeviceChange -= onDeviceChange;
            foreach (var d in enabledHere) InputSystem.DisableDevice(d);
            enabledHere.Clear();
        }

        void OnDeviceChange(InputDevice device, InputDeviceChange change)
        {
            if (change == InputDeviceChange.Added || change == InputDeviceChange.Reconnected) Bind(device);
            else if (change == InputDeviceChange.Removed || change == InputDeviceChange.Disconnected) Unbind(device);
        }

        void Bind(InputDevice device)
        {
            if (router.WantsHead && head == null)
            {
                var position = Child<Vector3Control>(device, "centerEyePosition");
                var rotation = Child<QuaternionControl>(device, "centerEyeRotation");
                if (position != null && rotation != null)
                {
                    head = device;
                    headPosition = position;
                    headRotation = rotation;
                    headAcceleration = Child<Vector3Control>(device, "centerEyeAcceleration") ?? Child<Vector3Control>(device, "deviceAcceleration");
                    headTracking = Child<IntegerControl>(device, "trackingState");
                    // OculusHMD's userPresence, OpenXRHmd's UserPresence (control paths are case-insensitive).
                    headPresence = Child<ButtonControl>(device, "userPresence");
                    lastPresence = null;
                }
            }
            if (!router.WantsPhone) return;
            if (device is Accelerometer a && accelerometer == null)
            {
                accelerometer = a;
                StartSensor(a);
            }
            else if (device is LinearAccelerationSensor l && linear == null)
            {
                linear = l;
                StartSensor(l);
            }
            else if (device is GravitySensor g && gravity == null)
            {
                gravity = g;
                StartSensor(g);
            }
        }

        /// <summary>
        /// The device's control at <paramref name="path"/> when it is a <typeparamref name="T"/>, else null: the Input System's
        /// TryGetChildControl&lt;T&gt; throws on a control of another type, which would stop every later device from binding.
        /// </summary>
        static T Child<T>(InputDevice device, string path) where T : InputControl => device.TryGetChildControl(path) as T;

        void Unbind(InputDevice device)
        {
            if (device == head)
            {
                head = null;
                headPresence = null;
                lastPresence = null;
            }
            if (device == accelerometer) accelerometer = null;
            if (device == linear) linear = null;
            if (device == gravity) gravity = null;
            enabledHere.Remove(device);
        }

        void StartSensor(Sensor sensor)
        {
            if (!sensor.enabled)
            {
                InputSystem.EnableDevice(sensor);
                enabledHere.Add(sensor);
            }
            // The paper samples at 100 Hz; platforms that cannot set the rate ignore the command.
            sensor.samplingFrequency = SensorRate;
        }

        void OnEvent(InputEventPtr eventPtr, InputDevice device)
        {
            if (device == null || !(eventPtr.IsA<StateEvent>() || eventPtr.IsA<DeltaStateEvent>())) return;
            double time = eventPtr.time;
            if (device == head)
            {
                var report = new HeadReport { Time = time };
                report.HasPose = headPosition.ReadValueFromEvent(eventPtr, out report.Position)
                                 & headRotation.ReadValueFromEvent(eventPtr, out report.Rotation);
                if (headAcceleration != null)
                    report.HasAcceleration = headAcceleration.ReadValueFromEvent(eventPtr, out report.Acceleration);
                if (headTracking != null && headTracking.ReadValueFromEvent(eventPtr, out int tracking))
                    report.TrackingState = tracking;
                // A button reads 1 pressed, 0 released; 0.5 is the Input System's default press point.
                if (headPresence != null && headPresence.ReadValueFromEvent(eventPtr, out float presence))
                    lastPresence = presence >= 0.5f;
                report.UserPresent = lastPresence;
                router.OnHeadEvent(report);
                return;
            }
            if (device == accelerometer || device == linear)
            {
                // Readings are processed when read, so the compensation matches the screen orientation now.
                var settings = InputSystem.settings;
                router.Phone.CompensationDegrees = settings != null && settings.compensateForScreenOrientation
                    ? PhoneAccelerometer.CompensationFor(Screen.orientation)
                    : 0;
            }
            if (device == accelerometer)
            {
                if (accelerometer.acceleration.ReadValueFromEvent(eventPtr, out Vector3 reading)) router.OnAccelerometerEvent(time, reading);
            }
            else if (device == gravity && accelerometer == null)
            {
                if (gravity.gravity.ReadValueFromEvent(eventPtr, out Vector3 g)) router.OnGravityEvent(g);
            }
            else if (device == linear && accelerometer == null)
            {
                if (linear.acceleration.ReadValueFromEvent(eventPtr, out Vector3 a)) router.OnLinearAccelerationEvent(time, a);
            }
        }
    }
}
#endif
