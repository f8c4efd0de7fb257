using UnityEngine;

namespace HeadGait.Unity
{
    /// <summary>
    /// Keeps this object (an avatar's root) standing under the tracked head: the head's horizontal position, feet on the
    /// floor, turned to the head's heading (pitch and roll ignored; see <see cref="HeadFollower"/>). Positions are in world
    /// space, so the object may sit under the XR Origin or anywhere else. Runs in LateUpdate, after the tracked camera moved
    /// in Update; the root is not animated (the Animator drives the rig below it), so moving it after the Animator is safe.
    /// </summary>
    [DisallowMultipleComponent]
    [AddComponentMenu("HeadGait/Follow Head")]
    public sealed class FollowHead : MonoBehaviour
    {
        [Tooltip("The tracked head (the XR camera). Empty: the main camera (tagged MainCamera).")]
        [SerializeField] Transform head;
        [Tooltip("Optional: the feet stand at this object's height plus Floor Height (e.g. the XR Origin in Floor tracking mode).")]
        [SerializeField] Transform floor;
        [Tooltip("Height of the feet (m): in world space, or above Floor when set.")]
        [SerializeField] float floorHeight;
        [Tooltip("Time constant (s) of the position's smoothing; 0 follows the head at once.")]
        [SerializeField, Range(0f, 1f)] float positionSmoothing;
        [Tooltip("Time constant (s) of the heading's smoothing; 0 turns with the head at once.")]
        [SerializeField, Range(0f, 1f)] float headingSmoothing = 0.1f;

        readonly HeadFollower follower = new HeadFollower();

        /// <summary>The tracked head; null follows the main camera.</summary>
        public Transform Head
        {
            get => head;
            set => head = value;
        }

        /// <summary>Optional: the feet stand at this object's height plus <see cref="FloorHeight"/>.</summary>
        public Transform Floor
        {
            get => floor;
            set => floor = value;
        }

        /// <summary>Height of the feet (m), world or above <see cref="Floor"/>.</summary>
        public float FloorHeight
        {
            get => floorHeight;
            set => floorHeight = value;
        }

        /// <summary>Position smoothing time constant (s); negative or NaN counts as 0.</summary>
        public float PositionSmoothing
        {
            get => positionSmoothing;
            set => positionSmoothing = value > 0 ? value : 0;
        }

        /// <summary>Heading smoothing time constant (s); negative or NaN counts as 0.</summary>
        public float HeadingSmoothing
        {
            get => headingSmoothing;
            set => headingSmoothing = value > 0 ? value : 0;
        }

        /// <summary>The placement logic and its state (heading kept, poses ignored).</summary>
        public HeadFollower Follower => follower;

        // Shown again (a study condition switched on, a teleport): snap to the head instead of gliding there.
        void OnEnable() => follower.Reset();

        void LateUpdate() => Follow(Time.deltaTime);

        /// <summary>Places this object under the head now, <paramref name="deltaTime"/> seconds after the last call.</summary>
        public void Follow(float deltaTime)
        {
            var target = head != null ? head : MainCamera();
            if (target == null) return;
            follower.FloorHeight = floorHeight + (floor != null ? floor.position.y : 0f);
            follower.PositionTimeConstant = positionSmoothing > 0 ? positionSmoothing : 0;
            follower.HeadingTimeConstant = headingSmoothing > 0 ? headingSmoothing : 0;
            Vector3 p = target.position, f = target.forward;
            follower.Follow(p.x, p.z, f.x, f.y, f.z, deltaTime);
            if (!follower.HasPosition) return;
            transform.SetPositionAndRotation(new Vector3((float)follower.X, (float)follower.Y, (float)follower.Z),
                Quaternion.Euler(0f, (float)follower.Yaw, 0f));
        }

        static Transform MainCamera()
        {
            var camera = Camera.main;
            return camera != null ? camera.transform : null;
        }
    }
}
