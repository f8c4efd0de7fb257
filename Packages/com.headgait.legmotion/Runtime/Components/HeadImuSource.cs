using UnityEngine;
using UnityEngine.XR;

namespace HeadGait.Unity
{
    /// <summary>Where the head's acceleration comes from.</summary>
    public enum HeadImuMode
    {
        /// <summary>
        /// XR head device: CommonUsages.deviceAcceleration (gravity removed) and deviceRotation; where the runtime
        /// reports no acceleration (common with OpenXR), falls back to differentiating devicePosition.
        /// </summary>
        XRDevice = 0,
        /// <summary>XR head device, acceleration always derived from the tracked pose (devicePosition, deviceRotation).</summary>
        XRDevicePose = 3,
        /// <summary>A phone in a headset: Input.acceleration, rotated by the phone's mounting orientation.</summary>
        MobileInput = 1,
        /// <summary>Nothing is read; samples are pushed by script (GaitLegAnimator.Push) or a RecordingPlayer.</summary>
        External = 2,
    }

    /// <summary>
    /// Reads the headset's accelerometer once per frame and hands it to a <see cref="GaitLegAnimator"/>.
    /// Frame-rate sampling (72-120 Hz, irregular) is fine: the core resamples to 100 Hz.
    /// </summary>
    [DisallowMultipleComponent]
    [AddComponentMenu("HeadGait/Head IMU Source")]
    public sealed class HeadImuSource : MonoBehaviour
    {
        [SerializeField] GaitLegAnimator target;
        [SerializeField] HeadImuMode mode = HeadImuMode.XRDevice;

        [Tooltip("MobileInput only: rotation from the phone's axes to the head's (Unity axes). Landscape-left phone behind the lenses: (0, 0, -90).")]
        [SerializeField] Vector3 deviceToHeadEuler = new Vector3(0f, 0f, -90f);

        InputDevice head;
        readonly PoseAccelerationEstimator fromPose = new PoseAccelerationEstimator();

        public HeadImuMode Mode
        {
            get => mode;
            set => mode = value;
        }

        /// <summary>The last specific force read, head frame (x forward, y left, z up), m/s^2.</summary>
        public Vector3 LastSample { get; private set; }

        /// <summary>Frames in which no acceleration could be read.</summary>
        public int MissedFrames { get; private set; }

        /// <summary>True once the XR device gave no acceleration and the tracked pose is being differentiated instead.</summary>
        public bool UsingPoseFallback { get; private set; }

        void OnEnable()
        {
            if (target == null) target = GetComponent<GaitLegAnimator>();
            if (mode == HeadImuMode.MobileInput) Input.gyro.enabled = true;
        }

        void Update()
        {
            if (target == null || mode == HeadImuMode.External) return;
            double now = Time.realtimeSinceStartupAsDouble;
            if (TryRead(now, out double time, out Vector3 f))
            {
                LastSample = f;
                target.Push(time, f);
            }
            else
            {
                MissedFrames++;
            }
        }

        bool TryRead(double now, out double time, out Vector3 specificForce)
        {
            time = now;
            specificForce = default;
            if (mode == HeadImuMode.MobileInput)
            {
                specificForce = HeadAxes.SpecificForceFromMobile(Input.acceleration, Quaternion.Euler(deviceToHeadEuler));
                return true;
            }
            if (!head.isValid) head = InputDevices.GetDeviceAtXRNode(XRNode.Head);
            if (!head.isValid) return false;
            if (!head.TryGetFeatureValue(CommonUsages.deviceRotation, out Quaternion rotation)) return false;
            if (mode == HeadImuMode.XRDevice && !UsingPoseFallback)
            {
                if (head.TryGetFeatureValue(CommonUsages.deviceAcceleration, out Vector3 linear))
                {
                    specificForce = HeadAxes.SpecificForceFromLinear(linear, rotation);
                    return true;
                }
                UsingPoseFallback = true;
                Debug.LogWarning("HeadGait: the XR head device reports no acceleration; differentiating its tracked position instead.", this);
            }
            if (!head.TryGetFeatureValue(CommonUsages.devicePosition, out Vector3 position)) return false;
            if (!fromPose.Push(now, position.x, position.y, position.z, rotation.x, rotation.y, rotation.z, rotation.w, out ImuSample sample)) return false;
            time = sample.Time;
            specificForce = new Vector3((float)sample.X, (float)sample.Y, (float)sample.Z);
            return true;
        }
    }
}
