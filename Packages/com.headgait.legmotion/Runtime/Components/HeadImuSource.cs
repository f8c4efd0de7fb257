using UnityEngine;

namespace HeadGait.Unity
{
    /// <summary>Where the head's acceleration comes from.</summary>
    public enum HeadImuMode
    {
        /// <summary>
        /// The headset: its reported acceleration while it is real (the device has the control, its tracking state
        /// flags it, and it is not all zeros), otherwise acceleration derived from the tracked head pose (OpenXR, Quest).
        /// </summary>
        XRDevice = 0,
        /// <summary>The headset, acceleration always derived from the tracked head pose.</summary>
        XRDevicePose = 3,
        /// <summary>A phone in a headset: its accelerometer (or linear acceleration plus gravity), with the phone's mounting.</summary>
        MobileInput = 1,
        /// <summary>Nothing is read; samples are pushed by script (GaitLegAnimator.Push) or a RecordingPlayer.</summary>
        External = 2,
    }

    /// <summary>
    /// Hands every head sample, with its own timestamp, to a <see cref="GaitLegAnimator"/>. Reads through the Input System
    /// (each sensor event, not once per frame); in projects without it, polls the legacy Input Manager once per frame.
    /// The decisions (which path, units, axes, timestamps) live in <see cref="HeadSampleRouter"/>; this is the adapter.
    /// </summary>
    [DisallowMultipleComponent]
    [AddComponentMenu("HeadGait/Head IMU Source")]
    public sealed class HeadImuSource : MonoBehaviour
    {
        [SerializeField] GaitLegAnimator target;
        [SerializeField] HeadImuMode mode = HeadImuMode.XRDevice;

        [Tooltip("MobileInput only: how the phone sits in the headset, screen towards the eyes. Cardboard-style viewers: LandscapeLeft (top of the phone to the left).")]
        [SerializeField] PhoneMounting phoneMounting = PhoneMounting.LandscapeLeft;

        HeadSampleRouter router;
#if ENABLE_INPUT_SYSTEM
        InputSystemHeadReader reader;
#elif ENABLE_LEGACY_INPUT_MANAGER
        LegacyHeadReader legacy;
#endif

        /// <summary>Takes effect on the next enable.</summary>
        public HeadImuMode Mode
        {
            get => mode;
            set => mode = value;
        }

        /// <summary>Takes effect on the next enable.</summary>
        public PhoneMounting PhoneMounting
        {
            get => phoneMounting;
            set => phoneMounting = value;
        }

        /// <summary>The last specific force handed on, head frame (x forward, y left, z up), m/s^2.</summary>
        public Vector3 LastSample { get; private set; }

        /// <summary>The decoded-event path, for diagnostics (samples delivered, duplicates refused, path switches).</summary>
        public HeadSampleRouter Router => router;

        /// <summary>True while the headset's acceleration is derived from its tracked pose.</summary>
        public bool UsingPoseFallback => router != null && router.WantsHead && router.Head.UsingPose;

        void OnEnable()
        {
            if (target == null) target = GetComponent<GaitLegAnimator>();
            if (mode == HeadImuMode.External) return;
            router = new HeadSampleRouter(mode, phoneMounting, Deliver);
#if ENABLE_INPUT_SYSTEM
            reader = new InputSystemHeadReader(router);
#elif ENABLE_LEGACY_INPUT_MANAGER
            legacy = new LegacyHeadReader(router);
#else
            Debug.LogWarning("HeadGait: neither the Input System nor the legacy Input Manager is active; no head samples are read.", this);
#endif
        }

        void OnDisable()
        {
#if ENABLE_INPUT_SYSTEM
            reader?.Dispose();
            reader = null;
#elif ENABLE_LEGACY_INPUT_MANAGER
            legacy = null;
#endif
        }

#if !ENABLE_INPUT_SYSTEM && ENABLE_LEGACY_INPUT_MANAGER
        void Update() => legacy?.Poll(HeadClock.Now);
#endif

        void LateUpdate()
        {
            // A pose stream too slow for the pose path gives no samples at all: say so once rather than stand silently.
            string problem = router != null && router.WantsHead ? router.Head.TakeWarning() : null;
            if (problem != null) Debug.LogWarning($"HeadGait: {problem}.", this);
        }

        void Deliver(HeadSample sample)
        {
            LastSample = sample.SpecificForce;
            if (target == null) return;
            target.SourceLag = sample.Lag;
            target.Push(sample.Time, sample.SpecificForce);
        }
    }
}
