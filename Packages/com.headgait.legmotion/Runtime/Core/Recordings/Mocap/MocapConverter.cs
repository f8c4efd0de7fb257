using System;
using System.Collections.Generic;
using System.Globalization;
using HeadGait.Synthetic;

namespace HeadGait.Mocap
{
    public sealed class MocapSettings
    {
        /// <summary>Joint names; null picks the first of the usual names that the skeleton has (see <see cref="MocapConverter.DefaultNames"/>).</summary>
        public string Head, LeftFoot, LeftToe, RightFoot, RightToe, LeftHip, RightHip;

        /// <summary>Metres per file unit; 0 guesses from the leg length (cm, m, mm or inches).</summary>
        public double MetresPerUnit;

        /// <summary>World up axis of the file: 0 x, 1 y, 2 z; -1 guesses (the axis along which the head is furthest above the feet).</summary>
        public int UpAxis = -1;

        /// <summary>Where the headset's IMU sits relative to the head joint, in the head frame at the first frame (m).</summary>
        public double SensorForward = 0.08, SensorUp = 0.08;

        public double SampleRate = 100;
        public double LowPassHz = 12;
        public int LowPassOrder = 4;

        /// <summary>A foot is in contact when its ankle or toe is this close to its floor level (m) and slower than <see cref="ContactSpeed"/> (m/s).</summary>
        public double ContactHeight = 0.04, ContactSpeed = 0.9;

        /// <summary>Both feet in contact for at least this long (s) is standing, not a double-support phase of walking.</summary>
        public double StandingSeconds = 0.5;

        /// <summary>Seconds dropped at both ends (filter edges).</summary>
        public double TrimSeconds = 0.25;

        /// <summary>Sensor errors: constant bias (SD per axis, m/s^2), white noise (SD, m/s^2), timestamp jitter (SD, s). Zero turns them off.</summary>
        public double BiasSd = 0.03, NoiseSd = 0.03, JitterSd = 0.0005;

        /// <summary>Pose recordings: tracking noise (position SD, m; rotation SD, degrees) and frame-time jitter (SD, s). Zero turns them off.</summary>
        public double PositionNoiseSd = 0.0005, RotationNoiseDegrees = 0.05, FrameJitterSd = 0.001;

        /// <summary>Seed of the sensor errors; 0 derives one from the file name, so a file always converts the same way.</summary>
        public ulong Seed;
    }

    /// <summary>
    /// Turns motion capture into a labelled head-IMU recording, the way the package's real-motion training data was made:
    /// a point at the headset's IMU (8 cm forward and 8 cm above the head joint) rigid with the head; its position spline-
    /// resampled to 100 Hz, low-passed (4th-order zero-phase Butterworth at 12 Hz) and differentiated twice; specific force
    /// (acceleration + g on world up) rotated into the head frame (x forward, y left, z up) calibrated level at the first
    /// frame, facing away from the hips' line; then sensor errors. Each foot's phases come from its kinematics: contact
    /// while its ankle or toe is within 4 cm of that joint's floor level and slower than 0.9 m/s; stance [IC, TO) split by
    /// Perry's 0-2-12-31-50-62 % and swing [TO, IC) by 62-75-87-100 %; STAND outside walking bouts.
    /// </summary>
    public static class MocapConverter
    {
        public const double Gravity = 9.80665;

        /// <summary>Usual joint names of common skeletons (Bandai Namco, CMU, LaFAN1, Mixamo, Unity humanoid), tried in order.</summary>
        public static readonly IReadOnlyDictionary<string, string[]> DefaultNames = new Dictionary<string, string[]>
        {
            ["head"] = new[] { "Head", "head" },
            ["left-foot"] = new[] { "Foot_L", "LeftFoot", "LeftAnkle", "lFoot", "L_Foot", "LeftFoot_" },
            ["left-toe"] = new[] { "Toes_L", "LeftToeBase", "LeftToe", "LeftToes", "lToe", "L_Toe" },
            ["right-foot"] = new[] { "Foot_R", "RightFoot", "RightAnkle", "rFoot", "R_Foot" },
            ["right-toe"] = new[] { "Toes_R", "RightToeBase", "RightToe", "RightToes", "rToe", "R_Toe" },
            ["left-hip"] = new[] { "UpperLeg_L", "LeftUpLeg", "LeftHip", "LeftUpperLeg", "lThigh", "L_Hip" },
            ["right-hip"] = new[] { "UpperLeg_R", "RightUpLeg", "RightHip", "RightUpperLeg", "rThigh", "R_Hip" },
        };

        /// <summary>What both conversions share: the skeleton's joints, units and up axis, the calibrated head frame, the
        /// sensor point's offset and each foot's labels at the output rate.</summary>
        sealed class Capture
        {
            public BvhPose Pose;
            public int Head, Up, LeftAnkle, RightAnkle;
            public double Scale, Dt, FrameTime;
            public int N;
            public Vec3 UpVec, Forward, Left, SensorInHead;
            public Rotation3 HeadToFrame;
            public double[] FrameTimes;
            public ButterworthLowPass Filter;
            public GaitPhase[] LabelsLeft, LabelsRight;
            public bool[] Walking;
            public string Joints;

            /// <summary>Position of the sensor point (m, world axes) at every output sample, low-passed like the acceleration.</summary>
            public double[][] SensorPositions()
            {
                var sensor = new double[3][];
                for (int k = 0; k < 3; k++)
                {
                    var v = new double[FrameTimes.Length];
                    for (int f = 0; f < v.Length; f++) v[f] = Scale * (Pose.Positions[f][Head] + Pose.Rotations[f][Head] * SensorInHead)[k];
                    sensor[k] = Filter.FilterForwardBackward(Resample(FrameTimes, v, N, Dt));
                }
                return sensor;
            }

            /// <summary>The head frame (columns forward, left, up in world axes) at time t.</summary>
            public Rotation3 HeadFrameAt(double t) => HeadRotationAt(Pose, Head, t / FrameTime) * HeadToFrame;

            /// <summary>World (right-handed) to Unity's tracking space (left-handed): x = right = -left, y = up, z = forward.</summary>
            public Vec3 Tracking(Vec3 v) => new Vec3(-Vec3.Dot(v, Left), Vec3.Dot(v, UpVec), Vec3.Dot(v, Forward));

            public GaitPhase LeftAt(int i) => Walking[i] ? LabelsLeft[i] : GaitPhase.Standing;
            public GaitPhase RightAt(int i) => Walking[i] ? LabelsRight[i] : GaitPhase.Standing;
        }

        static Capture Prepare(BvhFile bvh, MocapSettings s)
        {
            var c = new Capture();
            c.Head = Joint(bvh, s.Head, "head");
            int leftFoot = Joint(bvh, s.LeftFoot, "left-foot"), leftToe = Joint(bvh, s.LeftToe, "left-toe");
            int rightFoot = Joint(bvh, s.RightFoot, "right-foot"), rightToe = Joint(bvh, s.RightToe, "right-toe");
            int leftHip = Joint(bvh, s.LeftHip, "left-hip"), rightHip = Joint(bvh, s.RightHip, "right-hip");
            c.LeftAnkle = leftFoot;
            c.RightAnkle = rightFoot;
            var pose = c.Pose = new BvhPose(bvh);
            int up = c.Up = s.UpAxis >= 0 ? s.UpAxis : GuessUpAxis(pose, c.Head, leftFoot, rightFoot);
            if (up > 2) throw new ArgumentException("UpAxis must be 0 (x), 1 (y) or 2 (z).");
            double scale = c.Scale = s.MetresPerUnit > 0 ? s.MetresPerUnit : GuessMetresPerUnit(bvh, pose, leftHip, leftFoot, up);
            var upVec = c.UpVec = Vec3.Axis(up);

            // Head frame at the first frame: level, facing away from the line through the hips.
            var p0 = pose.Positions[0];
            var across = p0[leftHip] - p0[rightHip];
            var left = across - Vec3.Dot(across, upVec) * upVec;
            if (left.Length < 1e-9) throw new BvhFormatException(bvh.Name, 0, "the hips are level with each other vertically: cannot tell which way the body faces");
            left = c.Left = left.Normalized;
            var forward = c.Forward = Vec3.Cross(left, upVec);
            var calibrated = Rotation3.FromColumns(forward, left, upVec);
            c.HeadToFrame = pose.Rotations[0][c.Head].Transposed * calibrated; // head frame axes in the head joint's own axes
            c.SensorInHead = pose.Rotations[0][c.Head].Transposed * ((s.SensorForward / scale) * forward + (s.SensorUp / scale) * upVec);

            int frames = bvh.FrameCount;
            c.FrameTime = bvh.FrameTime;
            c.FrameTimes = new double[frames];
            for (int f = 0; f < frames; f++) c.FrameTimes[f] = f * bvh.FrameTime;
            c.Dt = 1.0 / s.SampleRate;
            c.N = (int)Math.Floor(c.FrameTimes[frames - 1] * s.SampleRate + 1e-9) + 1;
            if (c.N < 8) throw new BvhFormatException(bvh.Name, 0, $"the motion lasts {c.FrameTimes[frames - 1]:F3} s: too short to convert");
            c.Filter = new ButterworthLowPass(s.LowPassOrder, s.LowPassHz, s.SampleRate);
            c.LabelsLeft = FootLabels(pose, c.FrameTimes, leftFoot, leftToe, up, scale, c.Filter, c.N, c.Dt, s, out var contactLeft);
            c.LabelsRight = FootLabels(pose, c.FrameTimes, rightFoot, rightToe, up, scale, c.Filter, c.N, c.Dt, s, out var contactRight);
            c.Walking = WalkingBouts(contactLeft, contactRight, c.Dt, s.StandingSeconds);
            c.Joints = string.Join(",", bvh.Joints[c.Head].Name, bvh.Joints[leftFoot].Name, bvh.Joints[leftToe].Name,
                bvh.Joints[rightFoot].Name, bvh.Joints[rightToe].Name, bvh.Joints[leftHip].Name, bvh.Joints[rightHip].Name);
            return c;
        }

        public static Recording Convert(BvhFile bvh, MocapSettings settings = null)
        {
            var s = settings ?? new MocapSettings();
            var c = Prepare(bvh, s);
            int n = c.N;
            double dt = c.Dt;
            // Sensor position at 100 Hz, filtered, differentiated twice; plus g on up.
            var sensor = c.SensorPositions();
            for (int k = 0; k < 3; k++) sensor[k] = SecondDerivative(sensor[k], dt);

            var random = new DeterministicRandom(s.Seed != 0 ? s.Seed : DeterministicRandom.SeedFrom(bvh.Name));
            var bias = new Vec3(random.NextGaussian() * s.BiasSd, random.NextGaussian() * s.BiasSd, random.NextGaussian() * s.BiasSd);
            var samples = new List<RecordedSample>(n);
            int trim = (int)Math.Round(s.TrimSeconds * s.SampleRate);
            for (int i = trim; i < n - trim; i++)
            {
                double t = i * dt;
                var world = new Vec3(sensor[0][i], sensor[1][i], sensor[2][i]) + Gravity * c.UpVec;
                var a = c.HeadFrameAt(t).Transposed * world + bias;
                var imu = new ImuSample(t - trim * dt + random.NextGaussian() * s.JitterSd,
                    a.X + random.NextGaussian() * s.NoiseSd, a.Y + random.NextGaussian() * s.NoiseSd, a.Z + random.NextGaussian() * s.NoiseSd);
                samples.Add(new RecordedSample(imu, c.LeftAt(i), c.RightAt(i)));
            }
            var rec = new Recording(System.IO.Path.GetFileNameWithoutExtension(bvh.Name), samples);
            var ci = CultureInfo.InvariantCulture;
            rec.Metadata["source"] = bvh.Name;
            rec.Metadata["generator"] = "headgait from-bvh (mocap-derived head acceleration; labels from foot kinematics)";
            rec.Metadata["joints"] = c.Joints;
            rec.Metadata["metres_per_unit"] = c.Scale.ToString("R", ci);
            rec.Metadata["up_axis"] = "xyz"[c.Up].ToString();
            rec.Metadata["sample_rate_hz"] = s.SampleRate.ToString("R", ci);
            return rec;
        }

        /// <summary>
        /// The head pose an XR runtime would report for the same sensor point, at <paramref name="frameRate"/> frames per
        /// second with frame-time jitter: position (m) and rotation in Unity's tracking space (left-handed, x right, y up,
        /// z forward; origin below the start, z along the calibrated forward) plus tracking noise, labels from the feet.
        /// </summary>
        public static PoseRecording ConvertPose(BvhFile bvh, double frameRate, MocapSettings settings = null)
        {
            if (!(frameRate >= 10 && frameRate <= 1000)) throw new ArgumentException("The frame rate must be 10 to 1000 Hz.", nameof(frameRate));
            var s = settings ?? new MocapSettings();
            var c = Prepare(bvh, s);
            var sensor = c.SensorPositions();
            var grid = new double[c.N];
            for (int i = 0; i < c.N; i++) grid[i] = i * c.Dt;
            var track = new NaturalCubicSpline[3];
            for (int k = 0; k < 3; k++) track[k] = new NaturalCubicSpline(grid, sensor[k]);
            var origin = new Vec3(sensor[0][0], sensor[1][0], sensor[2][0]);
            origin = origin - Vec3.Dot(origin, c.UpVec) * c.UpVec;

            var random = new DeterministicRandom((s.Seed != 0 ? s.Seed : DeterministicRandom.SeedFrom(bvh.Name)) ^ (ulong)(frameRate * 1000));
            var rows = new List<(PoseSample, GaitPhase, GaitPhase)>();
            double start = s.TrimSeconds;
            foreach (double t in JitteredFrames(c, s, frameRate, random))
            {
                var p = new Vec3(track[0].Value(t), track[1].Value(t), track[2].Value(t)) - origin;
                var pos = c.Tracking(p) + new Vec3(random.NextGaussian() * s.PositionNoiseSd, random.NextGaussian() * s.PositionNoiseSd, random.NextGaussian() * s.PositionNoiseSd);
                var h = c.HeadFrameAt(t);
                var forward = new Vec3(h.M00, h.M10, h.M20);
                var left = new Vec3(h.M01, h.M11, h.M21);
                var up = new Vec3(h.M02, h.M12, h.M22);
                // Columns: the camera's right, up and forward axes in tracking space.
                var rotation = Rotation3.FromColumns(c.Tracking(-1 * left), c.Tracking(up), c.Tracking(forward)) * SmallRotation(random, s.RotationNoiseDegrees);
                rotation.ToQuaternion(out double qx, out double qy, out double qz, out double qw);
                int i = Math.Min(c.N - 1, (int)Math.Round(t / c.Dt));
                rows.Add((new PoseSample(t - start, pos.X, pos.Y, pos.Z, qx, qy, qz, qw), c.LeftAt(i), c.RightAt(i)));
            }
            var rec = new PoseRecording(System.IO.Path.GetFileNameWithoutExtension(bvh.Name) + $"_{frameRate:0}hz", rows);
            var ci = CultureInfo.InvariantCulture;
            rec.Metadata["source"] = bvh.Name;
            rec.Metadata["generator"] = "headgait from-bvh --pose (mocap head pose as an XR runtime reports it; labels from foot kinematics)";
            rec.Metadata["joints"] = c.Joints;
            rec.Metadata["frame_rate_hz"] = frameRate.ToString("R", ci);
            rec.Metadata["tracking_noise"] = $"position {s.PositionNoiseSd.ToString("R", ci)} m, rotation {s.RotationNoiseDegrees.ToString("R", ci)} deg, frame jitter {s.FrameJitterSd.ToString("R", ci)} s";
            return rec;
        }

        /// <summary>
        /// The poses two tracked devices strapped to the ankles would report beside the head stream of
        /// <see cref="ConvertPose"/> (same tracking space, origin and clock, so the head's acceleration recording from
        /// <see cref="Convert"/> lines up with them too): each ankle joint's position and axes at <paramref name="frameRate"/>
        /// frames per second with frame-time jitter and <paramref name="positionNoiseSd"/> of tracking noise (m; controllers
        /// are noisier than the headset). Unlabelled: <c>Calibration.FootContactLabeller</c> labels the feet from them.
        /// </summary>
        public static (PoseRecording Left, PoseRecording Right) ConvertAnkles(BvhFile bvh, double frameRate, MocapSettings settings = null, double positionNoiseSd = 0.002)
        {
            if (!(frameRate >= 10 && frameRate <= 1000)) throw new ArgumentException("The frame rate must be 10 to 1000 Hz.", nameof(frameRate));
            if (!(positionNoiseSd >= 0 && positionNoiseSd < 0.1)) throw new ArgumentException("The tracking noise must be 0 to 0.1 m.", nameof(positionNoiseSd));
            var s = settings ?? new MocapSettings();
            var c = Prepare(bvh, s);
            var origin = c.Scale * (c.Pose.Positions[0][c.Head] + c.Pose.Rotations[0][c.Head] * c.SensorInHead);
            origin = origin - Vec3.Dot(origin, c.UpVec) * c.UpVec;
            var random = new DeterministicRandom((s.Seed != 0 ? s.Seed : DeterministicRandom.SeedFrom(bvh.Name)) ^ 0xA4C1E5UL ^ (ulong)(frameRate * 1000));
            PoseRecording One(int joint, string side)
            {
                var track = new NaturalCubicSpline[3];
                for (int k = 0; k < 3; k++)
                {
                    var v = new double[c.FrameTimes.Length];
                    for (int f = 0; f < v.Length; f++) v[f] = c.Scale * c.Pose.Positions[f][joint][k];
                    track[k] = new NaturalCubicSpline(c.FrameTimes, v);
                }
                var rows = new List<(PoseSample, GaitPhase, GaitPhase)>();
                double start = s.TrimSeconds;
                foreach (double t in JitteredFrames(c, s, frameRate, random))
                {
                    var p = c.Tracking(new Vec3(track[0].Value(t), track[1].Value(t), track[2].Value(t)) - origin)
                            + new Vec3(random.NextGaussian() * positionNoiseSd, random.NextGaussian() * positionNoiseSd, random.NextGaussian() * positionNoiseSd);
                    var r = HeadRotationAt(c.Pose, joint, t / c.FrameTime);
                    // The joint's axes in tracking space; the first mirrored so that the mirrored space keeps a rotation.
                    var rotation = Rotation3.FromColumns(c.Tracking(-1 * new Vec3(r.M00, r.M10, r.M20)), c.Tracking(new Vec3(r.M01, r.M11, r.M21)), c.Tracking(new Vec3(r.M02, r.M12, r.M22)));
                    rotation.ToQuaternion(out double qx, out double qy, out double qz, out double qw);
                    rows.Add((new PoseSample(t - start, p.X, p.Y, p.Z, qx, qy, qz, qw), GaitPhase.Standing, GaitPhase.Standing));
                }
                var rec = new PoseRecording(System.IO.Path.GetFileNameWithoutExtension(bvh.Name) + $"_{side}-ankle_{frameRate:0}hz", rows);
                var ci = CultureInfo.InvariantCulture;
                rec.Metadata["source"] = bvh.Name;
                rec.Metadata["generator"] = "headgait from-bvh --ankles (ankle joint pose as a strapped tracked device reports it; unlabelled)";
                rec.Metadata["device"] = side + "-ankle";
                rec.Metadata["joint"] = bvh.Joints[joint].Name;
                rec.Metadata["frame_rate_hz"] = frameRate.ToString("R", ci);
                rec.Metadata["tracking_noise"] = $"position {positionNoiseSd.ToString("R", ci)} m, frame jitter {s.FrameJitterSd.ToString("R", ci)} s";
                return rec;
            }
            return (One(c.LeftAnkle, "left"), One(c.RightAnkle, "right"));
        }

        /// <summary>A tracked device's frame times: <paramref name="frameRate"/> per second with frame-time jitter, increasing, within the trimmed clip.</summary>
        static IEnumerable<double> JitteredFrames(Capture c, MocapSettings s, double frameRate, DeterministicRandom random)
        {
            double start = s.TrimSeconds, end = (c.N - 1) * c.Dt - s.TrimSeconds, last = double.NegativeInfinity;
            for (int k = 0; ; k++)
            {
                double t = start + k / frameRate + random.NextGaussian() * s.FrameJitterSd;
                if (t > end) yield break;
                if (t < start || t <= last + 1e-4) continue;
                last = t;
                yield return t;
            }
        }

        /// <summary>A rotation about a random axis by a normally distributed angle (degrees SD).</summary>
        static Rotation3 SmallRotation(DeterministicRandom random, double sdDegrees)
        {
            if (sdDegrees <= 0) return Rotation3.Identity;
            var axis = new Vec3(random.NextGaussian(), random.NextGaussian(), random.NextGaussian());
            if (axis.Length < 1e-12) return Rotation3.Identity;
            axis = axis.Normalized;
            double half = 0.5 * random.NextGaussian() * sdDegrees * Math.PI / 180, sin = Math.Sin(half);
            return Rotation3.FromQuaternion(axis.X * sin, axis.Y * sin, axis.Z * sin, Math.Cos(half));
        }

        static int Joint(BvhFile bvh, string name, string role)
        {
            if (!string.IsNullOrEmpty(name))
            {
                int j = bvh.FindJoint(name);
                if (j < 0) throw new BvhFormatException(bvh.Name, 0, $"no joint named '{name}' for the {role} (joints: {JointList(bvh)})");
                return j;
            }
            foreach (var candidate in DefaultNames[role])
            {
                int j = bvh.FindJoint(candidate);
                if (j >= 0) return j;
                // Prefixed names such as "mixamorig:LeftFoot".
                for (int k = 0; k < bvh.Joints.Count; k++)
                {
                    string jn = bvh.Joints[k].Name;
                    if (!bvh.Joints[k].IsEndSite && jn.EndsWith(":" + candidate, StringComparison.OrdinalIgnoreCase)) return k;
                }
            }
            throw new BvhFormatException(bvh.Name, 0, $"no {role} joint among the usual names ({string.Join(", ", DefaultNames[role])}); name it with --{role} (joints: {JointList(bvh)})");
        }

        static string JointList(BvhFile bvh)
        {
            var names = new List<string>();
            foreach (var j in bvh.Joints) if (!j.IsEndSite) names.Add(j.Name);
            return string.Join(", ", names);
        }

        static int GuessUpAxis(BvhPose pose, int head, int leftFoot, int rightFoot)
        {
            var p = pose.Positions[0];
            var d = p[head] - 0.5 * (p[leftFoot] + p[rightFoot]);
            int best = 0;
            for (int k = 1; k < 3; k++) if (Math.Abs(d[k]) > Math.Abs(d[best])) best = k;
            if (d[best] < 0) throw new ArgumentException("The head is below the feet along every axis: the skeleton is upside down; set the up axis.");
            return best;
        }

        /// <summary>An adult's hip-to-ankle height is about 0.7-1.0 m: pick the unit that makes it so.</summary>
        static double GuessMetresPerUnit(BvhFile bvh, BvhPose pose, int hip, int foot, int up)
        {
            double leg = Math.Abs(pose.Positions[0][hip][up] - pose.Positions[0][foot][up]);
            double[] units = { 0.01, 1.0, 0.001, 0.0254 };
            foreach (var u in units)
                if (leg * u > 0.45 && leg * u < 1.4) return u;
            throw new BvhFormatException(bvh.Name, 0, $"cannot tell the units: hip-to-ankle height is {leg:G4} file units; set metres per unit");
        }

        static double[] Resample(double[] times, double[] values, int n, double dt)
        {
            var spline = new NaturalCubicSpline(times, values);
            var r = new double[n];
            for (int i = 0; i < n; i++) r[i] = spline.Value(i * dt);
            return r;
        }

        /// <summary>Central differences inside, one-sided at the ends (as numpy.gradient).</summary>
        static double[] Derivative(double[] v, double dt)
        {
            int n = v.Length;
            var d = new double[n];
            for (int i = 1; i < n - 1; i++) d[i] = (v[i + 1] - v[i - 1]) / (2 * dt);
            d[0] = (v[1] - v[0]) / dt;
            d[n - 1] = (v[n - 1] - v[n - 2]) / dt;
            return d;
        }

        static double[] SecondDerivative(double[] v, double dt) => Derivative(Derivative(v, dt), dt);

        static Rotation3 HeadRotationAt(BvhPose pose, int head, double frame)
        {
            int last = pose.Rotations.Length - 1;
            int f = Math.Min(Math.Max(0, (int)Math.Floor(frame)), last);
            if (f >= last) return pose.Rotations[last][head];
            return Rotation3.Slerp(pose.Rotations[f][head], pose.Rotations[f + 1][head], frame - f);
        }

        /// <summary>Per-sample phase of one foot from its ankle and toe kinematics (walking everywhere; bouts are cut later).</summary>
        static GaitPhase[] FootLabels(BvhPose pose, double[] frameTimes, int ankle, int toe, int up, double scale,
            ButterworthLowPass filter, int n, double dt, MocapSettings s, out bool[] contact)
        {
            contact = new bool[n];
            foreach (int joint in new[] { ankle, toe })
            {
                var axes = new double[3][];
                for (int k = 0; k < 3; k++)
                {
                    var v = new double[frameTimes.Length];
                    for (int f = 0; f < v.Length; f++) v[f] = scale * pose.Positions[f][joint][k];
                    axes[k] = filter.FilterForwardBackward(Resample(frameTimes, v, n, dt));
                }
                var height = axes[up];
                var sorted = (double[])height.Clone();
                Array.Sort(sorted);
                double floor = sorted[(int)(0.01 * (n - 1))];
                var vx = Derivative(axes[0], dt);
                var vy = Derivative(axes[1], dt);
                var vz = Derivative(axes[2], dt);
                for (int i = 0; i < n; i++)
                {
                    double speed = Math.Sqrt(vx[i] * vx[i] + vy[i] * vy[i] + vz[i] * vz[i]);
                    if (height[i] - floor < s.ContactHeight && speed < s.ContactSpeed) contact[i] = true;
                }
            }
            return PhasesFromContact(contact, dt);
        }

        /// <summary>
        /// Perry phases from a contact sequence: stance [IC, TO) split at 0-2-12-31-50 % of 62, swing [TO, IC) at 62-75-87 %
        /// of the rest. Where a contact or swing is cut by the clip's edge, its unseen end is placed at the foot's median
        /// stance or swing duration.
        /// </summary>
        public static GaitPhase[] PhasesFromContact(bool[] contact, double dt)
        {
            int n = contact.Length;
            var runs = new List<(int start, int end, bool stance)>(); // [start, end)
            for (int i = 0; i < n;)
            {
                int j = i;
                while (j < n && contact[j] == contact[i]) j++;
                runs.Add((i, j, contact[i]));
                i = j;
            }
            double medianStance = MedianLength(runs, true, n) * dt, medianSwing = MedianLength(runs, false, n) * dt;
            // No complete stance or swing seen: assume a 1 s cycle with Perry's proportions.
            if (double.IsNaN(medianStance)) medianStance = PhaseMap.PerryStance;
            if (double.IsNaN(medianSwing)) medianSwing = 1 - PhaseMap.PerryStance;
            var labels = new GaitPhase[n];
            foreach (var r in runs)
            {
                bool startSeen = r.start > 0, endSeen = r.end < n;
                double typical = r.stance ? medianStance : medianSwing;
                double t0 = r.start * dt, t1 = r.end * dt;
                if (!startSeen && endSeen) t0 = Math.Min(t0, t1 - typical);
                if (startSeen && !endSeen) t1 = Math.Max(t1, t0 + typical);
                if (!startSeen && !endSeen) t1 = t0 + Math.Max(t1 - t0, typical);
                for (int i = r.start; i < r.end; i++)
                {
                    double frac = Math.Min(Math.Max((i * dt - t0) / (t1 - t0), 0), 0.999999);
                    labels[i] = PhaseMap.PerryPhaseAt(r.stance ? PhaseMap.PerryStance * frac : PhaseMap.PerryStance + (1 - PhaseMap.PerryStance) * frac);
                }
            }
            return labels;
        }

        static double MedianLength(List<(int start, int end, bool stance)> runs, bool stance, int n)
        {
            var lengths = new List<int>();
            foreach (var r in runs)
                if (r.stance == stance && r.start > 0 && r.end < n) lengths.Add(r.end - r.start);
            if (lengths.Count == 0) return double.NaN;
            lengths.Sort();
            return lengths[lengths.Count / 2];
        }

        /// <summary>
        /// Walking bouts: from a toe-off to the initial contact after which both feet stay down for at least
        /// <paramref name="standingSeconds"/>. A clip that starts or ends mid-walk (both feet down for less than that
        /// at its edge) is walking up to the edge.
        /// </summary>
        internal static bool[] WalkingBouts(bool[] left, bool[] right, double dt, double standingSeconds)
        {
            int n = left.Length;
            var walking = new bool[n];
            int minStand = (int)Math.Ceiling(standingSeconds / dt);
            // Standing = both feet down for at least minStand samples in a row.
            var standing = new bool[n];
            for (int i = 0; i < n;)
            {
                if (!(left[i] && right[i]))
                {
                    i++;
                    continue;
                }
                int j = i;
                while (j < n && left[j] && right[j]) j++;
                // The initial contact that ends a bout still belongs to it, so the last step is seen landing.
                if (j - i >= minStand)
                    for (int k = i > 0 ? i + 1 : i; k < j; k++) standing[k] = true;
                i = j;
            }
            bool anyStep = false;
            for (int i = 0; i < n && !anyStep; i++) anyStep = !left[i] || !right[i];
            for (int i = 0; i < n; i++) walking[i] = anyStep && !standing[i];
            return walking;
        }
    }
}
