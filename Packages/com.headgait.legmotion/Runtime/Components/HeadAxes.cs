using UnityEngine;

namespace HeadGait.Unity
{
    /// <summary>
    /// How a phone sits in a headset, as Unity names screen orientations; the value is the phone's counter-clockwise
    /// turn from portrait in degrees, seen from the user (screen towards the eyes). Cardboard-style viewers hold the
    /// phone in <see cref="LandscapeLeft"/>: top of the phone to the user's left.
    /// </summary>
    public enum PhoneMounting
    {
        Portrait = 0,
        LandscapeLeft = 90,
        PortraitUpsideDown = 180,
        LandscapeRight = 270,
    }

    /// <summary>
    /// Conversions into the package's head frame (x forward, y left, z up; specific force in m/s^2), in which recordings,
    /// templates and the lateral channel are defined, from Unity's left-handed tracking axes (x right, y up, z forward) and
    /// from a phone's right-handed sensor axes (portrait: x right, y up, z out of the screen).
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
        /// Specific force in the head frame from a phone accelerometer reading as Unity reports it: in g, pointing along
        /// gravity (a phone lying face up reads (0, 0, -1); Android's m/s^2 are divided by -g by the Input System, iOS
        /// reports so natively), in the phone's right-handed axes turned <paramref name="rotationDegrees"/> counter-clockwise
        /// from portrait as the user sees the screen (a multiple of 90). The screen faces the user, so the phone's z is
        /// the head's backward.
        /// </summary>
        public static Vector3 SpecificForceFromPhone(Vector3 readingInG, int rotationDegrees)
        {
            // Specific force is minus the gravity-direction reading.
            float fx = -readingInG.x * StandardGravity, fy = -readingInG.y * StandardGravity, fz = -readingInG.z * StandardGravity;
            // The phone's x and y on the user's right and up: portrait x = right, y = up; each quarter turn
            // counter-clockwise takes x to up and y to left.
            float right, up;
            switch (((rotationDegrees % 360) + 360) % 360)
            {
                case 0: right = fx; up = fy; break;
                case 90: right = -fy; up = fx; break;
                case 180: right = -fx; up = -fy; break;
                case 270: right = fy; up = -fx; break;
                default: throw new System.ArgumentException($"The phone's rotation must be a multiple of 90 degrees, not {rotationDegrees}.", nameof(rotationDegrees));
            }
            return new Vector3(-fz, -right, up);
        }
    }
}
