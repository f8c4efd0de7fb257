using System;

namespace HeadGait
{
    /// <summary>
    /// Where an avatar's root stands under a tracked head (Unity axes: y up, metres, yaw in degrees about +y with 0
    /// facing +z and 90 facing +x): the head's horizontal position, feet on the floor, turned to the head's heading.
    /// The heading is the head's forward projected on the horizontal plane, so nodding and tilting the head (pitch, roll)
    /// never turn the body; looking (nearly) straight up or down keeps the last heading, where that projection is too
    /// short to trust. Optional exponential smoothing (time constants in seconds, 0 = none) takes the jitter of the tracking
    /// and head turns off the body; the first pose and the one after <see cref="Reset"/> are taken as they are.
    /// A pose with a non-finite value (tracking lost) is ignored.
    /// </summary>
    public sealed class HeadFollower
    {
        /// <summary>
        /// The horizontal part of the unit forward below which the heading is kept: the head is within about 5.7 degrees of
        /// looking straight up or down, where a little roll swings the projection around.
        /// </summary>
        public const double MinHorizontalForward = 0.1;

        double positionTimeConstant, headingTimeConstant;

        /// <summary>Height of the floor the feet stand on (m).</summary>
        public double FloorHeight { get; set; }

        /// <summary>Time constant of the position's smoothing (s); 0 follows at once.</summary>
        public double PositionTimeConstant
        {
            get => positionTimeConstant;
            set => positionTimeConstant = NonNegative(value, nameof(PositionTimeConstant));
        }

        /// <summary>Time constant of the heading's smoothing (s); 0 turns at once.</summary>
        public double HeadingTimeConstant
        {
            get => headingTimeConstant;
            set => headingTimeConstant = NonNegative(value, nameof(HeadingTimeConstant));
        }

        /// <summary>False until the first usable head pose (and after <see cref="Reset"/>).</summary>
        public bool HasPosition { get; private set; }

        /// <summary>False until a head pose that was not looking straight up or down.</summary>
        public bool HasHeading { get; private set; }

        public double X { get; private set; }
        public double Z { get; private set; }

        /// <summary>The feet's height: <see cref="FloorHeight"/>.</summary>
        public double Y => FloorHeight;

        /// <summary>Heading in degrees, [0, 360): the body turned about +y by this angle (0 until a heading is known).</summary>
        public double Yaw { get; private set; }

        /// <summary>Head poses ignored because a value was NaN or infinite.</summary>
        public int IgnoredPoses { get; private set; }

        /// <summary>The next pose is taken without smoothing (after a teleport, or when the avatar is shown again).</summary>
        public void Reset()
        {
            HasPosition = false;
            HasHeading = false;
        }

        /// <summary>
        /// Follows one head pose: the head's position (only x and z are used) and its forward direction (any length), after
        /// <paramref name="deltaTime"/> seconds since the last call.
        /// </summary>
        public void Follow(double headX, double headZ, double forwardX, double forwardY, double forwardZ, double deltaTime)
        {
            if (!Finite(headX) || !Finite(headZ) || !Finite(forwardX) || !Finite(forwardY) || !Finite(forwardZ))
            {
                IgnoredPoses++;
                return;
            }
            double position = HasPosition ? Blend(deltaTime, positionTimeConstant) : 1;
            X += position * (headX - X);
            Z += position * (headZ - Z);
            HasPosition = true;

            double length = Math.Sqrt(forwardX * forwardX + forwardY * forwardY + forwardZ * forwardZ);
            double horizontal = Math.Sqrt(forwardX * forwardX + forwardZ * forwardZ);
            if (length == 0 || horizontal < MinHorizontalForward * length) return; // looking straight up or down: keep the heading
            double target = Math.Atan2(forwardX, forwardZ) * 180 / Math.PI;
            double heading = HasHeading ? Blend(deltaTime, headingTimeConstant) : 1;
            Yaw = Wrap360(Yaw + heading * Wrap180(target - Yaw)); // the short way round
            HasHeading = true;
        }

        /// <summary>The fraction of the way to the target covered in <paramref name="dt"/> by a first-order lag.</summary>
        static double Blend(double dt, double timeConstant)
        {
            if (timeConstant <= 0) return 1;
            if (!(dt > 0)) return 0; // no time passed (or a nonsense step): stay
            return 1 - Math.Exp(-dt / timeConstant);
        }

        static double Wrap180(double degrees)
        {
            double d = Wrap360(degrees);
            return d > 180 ? d - 360 : d;
        }

        static double Wrap360(double degrees)
        {
            double d = degrees % 360;
            if (d < 0) d += 360;
            return d >= 360 ? 0 : d; // -1e-17 + 360 rounds to 360
        }

        static bool Finite(double v) => !double.IsNaN(v) && !double.IsInfinity(v);

        static double NonNegative(double value, string name)
            => value >= 0 && Finite(value) ? value : throw new ArgumentOutOfRangeException(name, value, "a time constant is a finite number of seconds >= 0");
    }
}
