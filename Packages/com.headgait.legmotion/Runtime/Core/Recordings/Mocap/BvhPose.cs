using System;

namespace HeadGait.Mocap
{
    /// <summary>A 3x3 rotation matrix, row-major; columns are the rotated frame's axes in the parent frame.</summary>
    public readonly struct Rotation3
    {
        public readonly double M00, M01, M02, M10, M11, M12, M20, M21, M22;

        public Rotation3(double m00, double m01, double m02, double m10, double m11, double m12, double m20, double m21, double m22)
        {
            M00 = m00; M01 = m01; M02 = m02;
            M10 = m10; M11 = m11; M12 = m12;
            M20 = m20; M21 = m21; M22 = m22;
        }

        public static Rotation3 Identity => new Rotation3(1, 0, 0, 0, 1, 0, 0, 0, 1);

        /// <summary>Rotation by an angle (degrees) about the x (0), y (1) or z (2) axis.</summary>
        public static Rotation3 About(int axis, double degrees)
        {
            double a = degrees * Math.PI / 180, c = Math.Cos(a), s = Math.Sin(a);
            switch (axis)
            {
                case 0: return new Rotation3(1, 0, 0, 0, c, -s, 0, s, c);
                case 1: return new Rotation3(c, 0, s, 0, 1, 0, -s, 0, c);
                default: return new Rotation3(c, -s, 0, s, c, 0, 0, 0, 1);
            }
        }

        /// <summary>The matrix whose columns are the given axes.</summary>
        public static Rotation3 FromColumns(Vec3 x, Vec3 y, Vec3 z) => new Rotation3(x.X, y.X, z.X, x.Y, y.Y, z.Y, x.Z, y.Z, z.Z);

        public static Rotation3 operator *(Rotation3 a, Rotation3 b) => new Rotation3(
            a.M00 * b.M00 + a.M01 * b.M10 + a.M02 * b.M20, a.M00 * b.M01 + a.M01 * b.M11 + a.M02 * b.M21, a.M00 * b.M02 + a.M01 * b.M12 + a.M02 * b.M22,
            a.M10 * b.M00 + a.M11 * b.M10 + a.M12 * b.M20, a.M10 * b.M01 + a.M11 * b.M11 + a.M12 * b.M21, a.M10 * b.M02 + a.M11 * b.M12 + a.M12 * b.M22,
            a.M20 * b.M00 + a.M21 * b.M10 + a.M22 * b.M20, a.M20 * b.M01 + a.M21 * b.M11 + a.M22 * b.M21, a.M20 * b.M02 + a.M21 * b.M12 + a.M22 * b.M22);

        public static Vec3 operator *(Rotation3 a, Vec3 v) => new Vec3(
            a.M00 * v.X + a.M01 * v.Y + a.M02 * v.Z,
            a.M10 * v.X + a.M11 * v.Y + a.M12 * v.Z,
            a.M20 * v.X + a.M21 * v.Y + a.M22 * v.Z);

        public Rotation3 Transposed => new Rotation3(M00, M10, M20, M01, M11, M21, M02, M12, M22);

        /// <summary>Unit quaternion (x, y, z, w) of this rotation.</summary>
        public void ToQuaternion(out double x, out double y, out double z, out double w)
        {
            double trace = M00 + M11 + M22;
            if (trace > 0)
            {
                double s = Math.Sqrt(trace + 1) * 2;
                w = 0.25 * s; x = (M21 - M12) / s; y = (M02 - M20) / s; z = (M10 - M01) / s;
            }
            else if (M00 > M11 && M00 > M22)
            {
                double s = Math.Sqrt(1 + M00 - M11 - M22) * 2;
                w = (M21 - M12) / s; x = 0.25 * s; y = (M01 + M10) / s; z = (M02 + M20) / s;
            }
            else if (M11 > M22)
            {
                double s = Math.Sqrt(1 + M11 - M00 - M22) * 2;
                w = (M02 - M20) / s; x = (M01 + M10) / s; y = 0.25 * s; z = (M12 + M21) / s;
            }
            else
            {
                double s = Math.Sqrt(1 + M22 - M00 - M11) * 2;
                w = (M10 - M01) / s; x = (M02 + M20) / s; y = (M12 + M21) / s; z = 0.25 * s;
            }
        }

        public static Rotation3 FromQuaternion(double x, double y, double z, double w)
        {
            double n = Math.Sqrt(x * x + y * y + z * z + w * w);
            x /= n; y /= n; z /= n; w /= n;
            return new Rotation3(
                1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
                2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
                2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y));
        }

        /// <summary>Spherical interpolation from a (t = 0) to b (t = 1) along the shorter arc.</summary>
        public static Rotation3 Slerp(Rotation3 a, Rotation3 b, double t)
        {
            a.ToQuaternion(out double ax, out double ay, out double az, out double aw);
            b.ToQuaternion(out double bx, out double by, out double bz, out double bw);
            double dot = ax * bx + ay * by + az * bz + aw * bw;
            if (dot < 0)
            {
                bx = -bx; by = -by; bz = -bz; bw = -bw;
                dot = -dot;
            }
            double wa, wb;
            if (dot > 0.9995)
            {
                wa = 1 - t;
                wb = t;
            }
            else
            {
                double theta = Math.Acos(dot), s = Math.Sin(theta);
                wa = Math.Sin((1 - t) * theta) / s;
                wb = Math.Sin(t * theta) / s;
            }
            return FromQuaternion(wa * ax + wb * bx, wa * ay + wb * by, wa * az + wb * bz, wa * aw + wb * bw);
        }
    }

    public readonly struct Vec3
    {
        public readonly double X, Y, Z;

        public Vec3(double x, double y, double z)
        {
            X = x;
            Y = y;
            Z = z;
        }

        public double this[int axis] => axis == 0 ? X : axis == 1 ? Y : Z;

        public static Vec3 operator +(Vec3 a, Vec3 b) => new Vec3(a.X + b.X, a.Y + b.Y, a.Z + b.Z);
        public static Vec3 operator -(Vec3 a, Vec3 b) => new Vec3(a.X - b.X, a.Y - b.Y, a.Z - b.Z);
        public static Vec3 operator *(double s, Vec3 a) => new Vec3(s * a.X, s * a.Y, s * a.Z);
        public static double Dot(Vec3 a, Vec3 b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;
        public static Vec3 Cross(Vec3 a, Vec3 b) => new Vec3(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X);
        public double Length => Math.Sqrt(Dot(this, this));
        public Vec3 Normalized => (1.0 / Length) * this;

        /// <summary>Unit vector along axis 0 (x), 1 (y) or 2 (z).</summary>
        public static Vec3 Axis(int axis) => new Vec3(axis == 0 ? 1 : 0, axis == 1 ? 1 : 0, axis == 2 ? 1 : 0);
    }

    /// <summary>Global joint positions and rotations of every frame of a BVH file (forward kinematics).</summary>
    public sealed class BvhPose
    {
        public BvhPose(BvhFile bvh)
        {
            int frames = bvh.FrameCount, joints = bvh.Joints.Count;
            Positions = new Vec3[frames][];
            Rotations = new Rotation3[frames][];
            for (int f = 0; f < frames; f++)
            {
                var values = bvh.Frames[f];
                var pos = new Vec3[joints];
                var rot = new Rotation3[joints];
                for (int j = 0; j < joints; j++)
                {
                    var joint = bvh.Joints[j];
                    double tx = joint.Offset[0], ty = joint.Offset[1], tz = joint.Offset[2];
                    var local = Rotation3.Identity;
                    for (int c = 0; c < joint.Channels.Length; c++)
                    {
                        double v = values[joint.FirstChannel + c];
                        switch (joint.Channels[c])
                        {
                            case BvhChannel.Xposition: tx = v; break;
                            case BvhChannel.Yposition: ty = v; break;
                            case BvhChannel.Zposition: tz = v; break;
                            case BvhChannel.Xrotation: local = local * Rotation3.About(0, v); break;
                            case BvhChannel.Yrotation: local = local * Rotation3.About(1, v); break;
                            case BvhChannel.Zrotation: local = local * Rotation3.About(2, v); break;
                        }
                    }
                    var t = new Vec3(tx, ty, tz);
                    if (joint.Parent < 0)
                    {
                        pos[j] = t;
                        rot[j] = local;
                    }
                    else
                    {
                        pos[j] = pos[joint.Parent] + rot[joint.Parent] * t;
                        rot[j] = rot[joint.Parent] * local;
                    }
                }
                Positions[f] = pos;
                Rotations[f] = rot;
            }
        }

        /// <summary>[frame][joint] global position, in the file's units.</summary>
        public Vec3[][] Positions { get; }

        /// <summary>[frame][joint] global rotation.</summary>
        public Rotation3[][] Rotations { get; }
    }
}
