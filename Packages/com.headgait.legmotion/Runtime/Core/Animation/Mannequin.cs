using System;

namespace HeadGait
{
    /// <summary>A point in the body's sagittal plane, metres: x forward, y up.</summary>
    public readonly struct SagittalPoint
    {
        public readonly double X;
        public readonly double Y;

        public SagittalPoint(double x, double y)
        {
            X = x;
            Y = y;
        }

        public static SagittalPoint operator +(SagittalPoint a, SagittalPoint b) => new SagittalPoint(a.X + b.X, a.Y + b.Y);
    }

    /// <summary>Where a leg's joints are, relative to its hip joint.</summary>
    public readonly struct LegPoints
    {
        public readonly SagittalPoint Knee;
        public readonly SagittalPoint Ankle;
        public readonly SagittalPoint Heel;
        /// <summary>The ball of the foot (metatarsophalangeal joint), about which the toes bend.</summary>
        public readonly SagittalPoint Ball;
        public readonly SagittalPoint Toe;
        /// <summary>Toe extension (degrees, + toes up relative to the foot) that keeps the toes level when the heel rises.</summary>
        public readonly double ToeBend;

        public LegPoints(SagittalPoint knee, SagittalPoint ankle, SagittalPoint heel, SagittalPoint ball, SagittalPoint toe, double toeBend)
        {
            Knee = knee;
            Ankle = ankle;
            Heel = heel;
            Ball = ball;
            Toe = toe;
            ToeBend = toeBend;
        }

        /// <summary>Height of the foot's lowest point relative to the hip (negative: below it).</summary>
        public double Lowest => Math.Min(Heel.Y, Math.Min(Ball.Y, Toe.Y));
    }

    /// <summary>
    /// The package's mannequin, a 1.75 m humanoid of primitives. Segment lengths are Winter's anthropometric fractions of
    /// body height (Winter 2009, Fig. 4.1: thigh 0.245 H, shank 0.246 H, ankle height 0.039 H, foot length 0.152 H).
    /// The transform names are the paths its clips animate.
    /// </summary>
    public static class Mannequin
    {
        public const double Height = 1.75;
        public const double Thigh = 0.245 * Height;
        public const double Shank = 0.246 * Height;
        public const double AnkleHeight = 0.039 * Height;
        public const double FootLength = 0.152 * Height;
        /// <summary>The heel lies a quarter of the foot behind the ankle, the toes the rest ahead of it.</summary>
        public const double HeelBehindAnkle = 0.25 * FootLength;
        /// <summary>The ball of the foot lies at 73 % of its length from the heel; the toes are the rest.</summary>
        public const double BallFromHeel = 0.73 * FootLength;
        public const double HipWidth = 0.18;
        /// <summary>Hip joint height when standing.</summary>
        public const double StandingHipHeight = Thigh + Shank + AnkleHeight;

        public const string Hips = "Hips";
        public const string Spine = Hips + "/Spine";
        public const string Head = Spine + "/Head";

        public static string UpperLeg(Foot foot) => Hips + "/" + Side(foot) + "UpperLeg";
        public static string LowerLeg(Foot foot) => UpperLeg(foot) + "/" + Side(foot) + "LowerLeg";
        public static string FootPath(Foot foot) => LowerLeg(foot) + "/" + Side(foot) + "Foot";
        public static string Toes(Foot foot) => FootPath(foot) + "/" + Side(foot) + "Toes";
        public static string UpperArm(Foot side) => Spine + "/" + Side(side) + "UpperArm";
        public static string LowerArm(Foot side) => UpperArm(side) + "/" + Side(side) + "LowerArm";
        public static string Side(Foot foot) => foot == Foot.Left ? "Left" : "Right";

        /// <summary>Forward kinematics of one leg from its angles, with the pelvis tilted anteriorly by <paramref name="pelvicTilt"/> degrees.</summary>
        public static LegPoints Leg(LegAngles a, double pelvicTilt)
        {
            double thigh = Radians(a.Hip - pelvicTilt);                     // from vertical, + forward
            double shank = Radians(a.Hip - pelvicTilt - a.Knee);            // knee flexion swings the shank back
            double foot = Radians(a.Hip - pelvicTilt - a.Knee + a.Ankle);   // foot pitch, + toes up
            var knee = new SagittalPoint(Thigh * Math.Sin(thigh), -Thigh * Math.Cos(thigh));
            var ankle = knee + new SagittalPoint(Shank * Math.Sin(shank), -Shank * Math.Cos(shank));
            var heel = ankle + Rotate(-HeelBehindAnkle, -AnkleHeight, foot);
            var ball = ankle + Rotate(BallFromHeel - HeelBehindAnkle, -AnkleHeight, foot);
            // With the heel raised (foot pitched toes-down) the toes bend up at the ball and stay level, as in push-off.
            double toePitch = Math.Max(foot, 0);
            var toe = ball + Rotate(FootLength - BallFromHeel, 0, toePitch);
            return new LegPoints(knee, ankle, heel, ball, toe, (toePitch - foot) * 180.0 / Math.PI);
        }

        static SagittalPoint Rotate(double x, double y, double angle)
            => new SagittalPoint(x * Math.Cos(angle) - y * Math.Sin(angle), x * Math.Sin(angle) + y * Math.Cos(angle));

        static double Radians(double degrees) => degrees * Math.PI / 180.0;
    }
}
