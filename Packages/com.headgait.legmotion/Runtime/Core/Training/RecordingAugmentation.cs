using System;
using System.Collections.Generic;
using HeadGait.Synthetic;

namespace HeadGait.Training
{
    /// <summary>Ranges of the random changes <see cref="RecordingAugmentation"/> makes to a training recording.</summary>
    public sealed class AugmentationSettings
    {
        /// <summary>Time is stretched by a factor drawn from this range (above 1: slower walking).</summary>
        public double MinStretch = 0.8, MaxStretch = 1.3;

        /// <summary>
        /// A slower walk has smaller accelerations: the dynamic part is divided by stretch^p with p drawn from this
        /// range (2 would be an exact slow-motion replay; people who walk slowly do not move quite that softly).
        /// </summary>
        public double MinAmplitudeExponent = 0.5, MaxAmplitudeExponent = 2.0;

        /// <summary>
        /// Extra scale of the forward and lateral dynamic parts. Mocap-derived head acceleration is about twice as
        /// large sideways and forwards as a real ear-worn sensor's, so scaling down keeps classifiers from leaning on it.
        /// </summary>
        public double MinLateralScale = 0.4, MaxLateralScale = 1.1;
        public double MinForwardScale = 0.5, MaxForwardScale = 1.1;

        /// <summary>
        /// Overall gain of the dynamic part, drawn log-uniformly: the actors' head bounce spans a factor of seven between
        /// styles (SMV spread 0.8 to 5.7 m/s^2), and calm walkers must not fall outside what the classifiers saw.
        /// </summary>
        public double MinGain = 0.5, MaxGain = 1.5;

        /// <summary>Seconds of the moving average that separates the slow part (gravity through head tilt) from the dynamic part.</summary>
        public double SlowWindowSeconds = 1.0;
    }

    /// <summary>
    /// Makes variants of a labelled recording for training: resampled to 100 Hz, the dynamic part of the acceleration
    /// (what remains after a 1 s moving average) scaled per axis, and time stretched with its labels.
    /// </summary>
    public static class RecordingAugmentation
    {
        const double Rate = 100.0;

        public static Recording Augment(Recording source, DeterministicRandom random, AugmentationSettings settings = null)
        {
            var s = settings ?? new AugmentationSettings();
            double stretch = random.Uniform(s.MinStretch, s.MaxStretch);
            double exponent = random.Uniform(s.MinAmplitudeExponent, s.MaxAmplitudeExponent);
            double forward = random.Uniform(s.MinForwardScale, s.MaxForwardScale);
            double lateral = random.Uniform(s.MinLateralScale, s.MaxLateralScale);
            double gain = Math.Exp(random.Uniform(Math.Log(s.MinGain), Math.Log(s.MaxGain))) * Math.Pow(stretch, -exponent);
            return Transform(source, stretch, gain * forward, gain * lateral, gain, s.SlowWindowSeconds,
                AugmentedName(source.Name, stretch, gain, forward, lateral));
        }

        /// <summary>"original~..." names the copy and its changes; the part before '~' is the original's name.</summary>
        const char CopyMark = '~';

        /// <summary>Whether a recording of this name is an augmented copy.</summary>
        public static bool IsCopy(string name) => name.IndexOf(CopyMark) >= 0;

        /// <summary>The name of the original a copy was made from (the name itself for an original).</summary>
        public static string OriginalName(string name)
        {
            int mark = name.IndexOf(CopyMark);
            return mark < 0 ? name : name.Substring(0, mark);
        }

        static string AugmentedName(string name, double stretch, double gain, double forward, double lateral)
            => string.Format(System.Globalization.CultureInfo.InvariantCulture, "{0}{1}t{2:F2}g{3:F2}f{4:F2}l{5:F2}", name, CopyMark, stretch, gain, forward, lateral);

        /// <summary>
        /// How much slower and how much weaker sideways and forwards <see cref="EarLike"/> makes a recording. The issue's
        /// real ear-worn sensor measured about half the sideways and forward acceleration of these mocap-derived signals,
        /// and its wearer walked slower than the actors.
        /// </summary>
        public const double EarLikeStretch = 1.2, EarLikeSidewaysGain = 0.5;

        /// <summary>
        /// The recording as an ear-worn sensor on a slower walker might give it (the benchmark's <c>--ear-like</c>): time
        /// stretched by <see cref="EarLikeStretch"/> with every dynamic part scaled by 1/stretch^2, as a walk slowed down
        /// accelerates less, and the sideways and forward ones also by <see cref="EarLikeSidewaysGain"/>. Same name.
        /// </summary>
        public static Recording EarLike(Recording source)
        {
            double gain = 1 / (EarLikeStretch * EarLikeStretch);
            return Transform(source, EarLikeStretch, gain * EarLikeSidewaysGain, gain * EarLikeSidewaysGain, gain,
                new AugmentationSettings().SlowWindowSeconds, source.Name);
        }

        /// <summary>
        /// How <see cref="Tilted"/> turns a recording: pitched this far nose down, then rolled this far (degrees), as a head
        /// looking down at its legs, with a headset not quite straight on it.
        /// </summary>
        public const double TiltedPitchDegrees = 35, TiltedRollDegrees = 10;

        /// <summary>
        /// The recording as a sensor pitched <paramref name="pitchDegrees"/> nose down, then rolled <paramref name="rollDegrees"/>,
        /// would give it (the benchmark's <c>--tilted</c>: <see cref="TiltedPitchDegrees"/>, <see cref="TiltedRollDegrees"/>). Same name.
        /// </summary>
        public static Recording Tilted(Recording source, double pitchDegrees = TiltedPitchDegrees, double rollDegrees = TiltedRollDegrees)
        {
            double pitch = pitchDegrees * Math.PI / 180, roll = rollDegrees * Math.PI / 180;
            double cp = Math.Cos(pitch), sp = Math.Sin(pitch), cr = Math.Cos(roll), sr = Math.Sin(roll);
            return MapSamples(source, a =>
            {
                // Turned about y (pitch: at rest, specific force gains a forward part), then about the new x (roll).
                double x = cp * a.X + sp * a.Z, z = -sp * a.X + cp * a.Z;
                return new ImuSample(a.Time, x, cr * a.Y + sr * z, -sr * a.Y + cr * z);
            });
        }

        /// <summary>How far <see cref="Turned"/> turns the head to the left of where it walks (degrees).</summary>
        public const double TurnedYawDegrees = 30;

        /// <summary>
        /// The recording as a head turned <paramref name="yawDegrees"/> to the left of the walking direction would give it
        /// (the benchmark's <c>--turned</c>: looking around while walking): the forward and sideways channels mix, the
        /// vertical stays. Same name.
        /// </summary>
        public static Recording Turned(Recording source, double yawDegrees = TurnedYawDegrees)
        {
            double yaw = yawDegrees * Math.PI / 180, cy = Math.Cos(yaw), sy = Math.Sin(yaw);
            return MapSamples(source, a => new ImuSample(a.Time, cy * a.X + sy * a.Y, -sy * a.X + cy * a.Y, a.Z));
        }

        /// <summary>A copy with every sample's acceleration mapped; labels, lines, name and metadata kept.</summary>
        static Recording MapSamples(Recording source, Func<ImuSample, ImuSample> map)
        {
            var output = new List<RecordedSample>(source.Samples.Count);
            foreach (var s in source.Samples)
            {
                var imu = map(s.Imu);
                output.Add(s.HasTruth ? new RecordedSample(imu, s.Left, s.Right, s.Line) : new RecordedSample(imu, s.Line));
            }
            var result = new Recording(source.Name, output);
            foreach (var kv in source.Metadata) result.Metadata[kv.Key] = kv.Value;
            return result;
        }

        /// <summary>
        /// The deterministic core of <see cref="Augment"/>: stretches time by <paramref name="stretch"/> and multiplies the
        /// dynamic part of x (forward), y (lateral) and z (up) by the given gains.
        /// </summary>
        public static Recording Transform(Recording source, double stretch, double forwardGain, double lateralGain, double verticalGain,
            double slowWindowSeconds, string name)
        {
            if (!(stretch > 0)) throw new ArgumentOutOfRangeException(nameof(stretch));
            var rows = Uniform(source);
            var output = new List<RecordedSample>();
            if (rows.Count < 2) return new Recording(name, output);
            int n = rows.Count;
            var acc = new double[3][];
            for (int k = 0; k < 3; k++) acc[k] = new double[n];
            for (int i = 0; i < n; i++)
            {
                acc[0][i] = rows[i].Imu.X;
                acc[1][i] = rows[i].Imu.Y;
                acc[2][i] = rows[i].Imu.Z;
            }
            int half = Math.Max(1, (int)Math.Round(slowWindowSeconds * Rate / 2));
            double[] gains = { forwardGain, lateralGain, verticalGain };
            for (int k = 0; k < 3; k++)
            {
                var slow = MovingAverage(acc[k], half);
                for (int i = 0; i < n; i++) acc[k][i] = slow[i] + gains[k] * (acc[k][i] - slow[i]);
            }

            double t0 = rows[0].Imu.Time;
            double duration = (n - 1) / Rate * stretch;
            int m = (int)Math.Floor(duration * Rate + 1e-9) + 1;
            for (int j = 0; j < m; j++)
            {
                double u = j / Rate / stretch * Rate; // position on the source grid
                int i = Math.Min((int)Math.Floor(u), n - 2);
                double a = u - i;
                if (a > 1) a = 1;
                var imu = new ImuSample(t0 + j / Rate,
                    acc[0][i] + a * (acc[0][i + 1] - acc[0][i]),
                    acc[1][i] + a * (acc[1][i + 1] - acc[1][i]),
                    acc[2][i] + a * (acc[2][i + 1] - acc[2][i]));
                var label = rows[a < 1 ? i : i + 1];
                output.Add(label.HasTruth ? new RecordedSample(imu, label.Left, label.Right) : new RecordedSample(imu));
            }
            var result = new Recording(name, output);
            foreach (var kv in source.Metadata) result.Metadata[kv.Key] = kv.Value;
            return result;
        }

        /// <summary>The recording on an exact 100 Hz grid: linear interpolation of the acceleration, labels held from the last row.</summary>
        public static List<RecordedSample> Uniform(Recording source)
        {
            var rows = new List<RecordedSample>();
            foreach (var r in source.Samples)
            {
                if (!r.Imu.IsFinite || rows.Count > 0 && !(r.Imu.Time > rows[rows.Count - 1].Imu.Time)) continue;
                rows.Add(r);
            }
            var grid = new List<RecordedSample>();
            if (rows.Count < 2) return grid;
            double t0 = rows[0].Imu.Time, t1 = rows[rows.Count - 1].Imu.Time;
            int j = 0;
            for (int k = 0; t0 + k / Rate <= t1 + 1e-9; k++)
            {
                double t = t0 + k / Rate;
                while (j + 2 < rows.Count && rows[j + 1].Imu.Time <= t) j++;
                var p = rows[j];
                var q = rows[j + 1];
                double a = (t - p.Imu.Time) / (q.Imu.Time - p.Imu.Time);
                if (a < 0) a = 0;
                if (a > 1) a = 1;
                var imu = new ImuSample(t, p.Imu.X + a * (q.Imu.X - p.Imu.X), p.Imu.Y + a * (q.Imu.Y - p.Imu.Y), p.Imu.Z + a * (q.Imu.Z - p.Imu.Z));
                var label = a >= 1 ? q : p;
                grid.Add(label.HasTruth ? new RecordedSample(imu, label.Left, label.Right) : new RecordedSample(imu));
            }
            return grid;
        }

        static double[] MovingAverage(double[] v, int half)
        {
            int n = v.Length;
            var prefix = new double[n + 1];
            for (int i = 0; i < n; i++) prefix[i + 1] = prefix[i] + v[i];
            var r = new double[n];
            for (int i = 0; i < n; i++)
            {
                int a = Math.Max(0, i - half), b = Math.Min(n - 1, i + half);
                r[i] = (prefix[b + 1] - prefix[a]) / (b - a + 1);
            }
            return r;
        }
    }
}
