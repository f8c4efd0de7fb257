using UnityEngine;

namespace HeadGait.Unity
{
    /// <summary>
    /// Conversions between Unity's left-handed axes (x right, y up, z forward) and the package's head frame
    /// (x forward, y left, z up), in which recordings, templates and the lateral channel are defined.
    /// </summary>
    public static class HeadAxes
    {
        public const float StandardGravity = 9.80665f;

        /// <summary>A vector in the headset's local Unity axes, expressed in the head frame.</summary>
        public static Vector3 FromUnityLocal(Vector3 v) => new Vector3(v.z, -v.x, v.y);

        /// <summary>
        /// Specific force in the head frame from a tracking-space linear acceleration with gravity removed
        /// (what XR providers report as deviceAcceleration) and the head's tracking-space rotation.
        /// </summary>
        public static Vector3 SpecificForceFromLinear(Vector3 linearAccelerationTracking, Quaternion headRotation)
        {
            Vector3 specific = linearAccelerationTracking + new Vector3(0f, StandardGravity, 0f);
            return FromUnityLocal(Quaternion.Inverse(headRotation) * specific);
        }

        /// <summary>
        /// Specific force in the head frame from Input.acceleration (units of g, device axes, reads the gravity
        /// direction, e.g. (0,0,-1) lying face up) of a phone in a headset, given the phone's orientation in the head.
        /// </summary>
        public static Vector3 SpecificForceFromMobile(Vector3 inputAcceleration, Quaternion deviceToHeadUnity)
        {
            Vector3 specificDevice = -inputAcceleration * StandardGravity;
            return FromUnityLocal(deviceToHeadUnity * specificDevice);
        }
    }
}
