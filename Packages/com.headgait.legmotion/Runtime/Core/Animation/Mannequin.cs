using System;
using System.Collections.Generic;

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

        /// <summary>The mannequin prefab's root, and the drop-in prefab's root and the mannequin's child of it.</summary>
        public const string PrefabRoot = "HeadGait Mannequin";
        public const string LegsPrefabRoot = "HeadGait Legs";
        public const string LegsAvatar = "Avatar";

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

        /// <summary>
        /// The mannequin's GameObjects in the order a prefab lists them: its bones (named as <see cref="Hips"/> etc. say) and,
        /// under each, a child showing a Unity primitive mesh (Unity axes: x right, y up, z forward; metres, degrees). One
        /// place for what `headgait clips` writes into the prefabs and Tools > HeadGait > Create Prefabs builds.
        /// </summary>
        public static List<MannequinPart> Parts()
        {
            var parts = new List<MannequinPart>();
            double[] V(double x, double y, double z) => new[] { x, y, z };
            void Bone(string path, double[] position, double[] euler = null)
                => parts.Add(new MannequinPart(path, path.Substring(path.LastIndexOf('/') + 1), position, euler ?? V(0, 0, 0), V(1, 1, 1), null));
            void Mesh(string bone, string name, MannequinPrimitive primitive, double[] position, double[] scale)
                => parts.Add(new MannequinPart(bone + "/" + name, name, position, V(0, 0, 0), scale, primitive));
            Bone(Hips, V(0, StandingHipHeight, 0));
            Mesh(Hips, "Pelvis Mesh", MannequinPrimitive.Cube, V(0, 0, 0), V(0.3, 0.14, 0.18));
            Bone(Spine, V(0, 0.08, 0));
            Mesh(Spine, "Mesh", MannequinPrimitive.Cube, V(0, 0.24, 0), V(0.34, 0.48, 0.2));
            Bone(Head, V(0, 0.56, 0));
            Mesh(Head, "Mesh", MannequinPrimitive.Sphere, V(0, 0.1, 0), V(0.22, 0.22, 0.22));
            foreach (Foot foot in new[] { Foot.Left, Foot.Right })
            {
                double side = foot == Foot.Left ? -1 : 1;
                Bone(UpperLeg(foot), V(side * HipWidth / 2, 0, 0));
                Mesh(UpperLeg(foot), "Mesh", MannequinPrimitive.Capsule, V(0, -Thigh / 2, 0), V(0.12, Thigh / 2, 0.12));
                Bone(LowerLeg(foot), V(0, -Thigh, 0));
                Mesh(LowerLeg(foot), "Mesh", MannequinPrimitive.Capsule, V(0, -Shank / 2, 0), V(0.1, Shank / 2, 0.1));
                double ball = BallFromHeel - HeelBehindAnkle;
                Bone(FootPath(foot), V(0, -Shank, 0));
                Mesh(FootPath(foot), "Mesh", MannequinPrimitive.Cube, V(0, -AnkleHeight / 2, (ball - HeelBehindAnkle) / 2), V(0.09, AnkleHeight, BallFromHeel));
                double toes = FootLength - BallFromHeel;
                Bone(Toes(foot), V(0, -AnkleHeight, ball));
                Mesh(Toes(foot), "Mesh", MannequinPrimitive.Cube, V(0, 0.015, toes / 2), V(0.09, 0.03, toes));
                Bone(UpperArm(foot), V(side * 0.21, 0.46, 0));
                Mesh(UpperArm(foot), "Mesh", MannequinPrimitive.Capsule, V(0, -0.15, 0), V(0.08, 0.15, 0.08));
                Bone(LowerArm(foot), V(0, -0.3, 0), V(-15, 0, 0));
                Mesh(LowerArm(foot), "Mesh", MannequinPrimitive.Capsule, V(0, -0.13, 0), V(0.07, 0.13, 0.07));
            }
            return parts;
        }

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

    /// <summary>The Unity primitive meshes the mannequin is made of (Unity's built-in Cube, Sphere and Capsule).</summary>
    public enum MannequinPrimitive
    {
        Cube,
        Sphere,
        Capsule,
    }

    /// <summary>One GameObject of <see cref="Mannequin.Parts"/>: a bone, or (with a <see cref="Primitive"/>) a mesh under one.</summary>
    public sealed class MannequinPart
    {
        /// <summary>Path below the mannequin's root, '/'-joined names.</summary>
        public string Path { get; }
        public string Name { get; }
        /// <summary>Local position (m), Euler angles (degrees, Unity's order) and scale.</summary>
        public double[] Position { get; }
        public double[] Euler { get; }
        public double[] Scale { get; }
        /// <summary>The mesh it shows; null for a bone.</summary>
        public MannequinPrimitive? Primitive { get; }

        /// <summary>The parent's path ("" for a child of the root).</summary>
        public string ParentPath => Path.Contains("/") ? Path.Substring(0, Path.LastIndexOf('/')) : "";

        public MannequinPart(string path, string name, double[] position, double[] euler, double[] scale, MannequinPrimitive? primitive)
        {
            Path = path;
            Name = name;
            Position = position;
            Euler = euler;
            Scale = scale;
            Primitive = primitive;
        }
    }
}
