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
    /// Ranges of <see cref="RecordingAugmentation.LikeWearer"/>'s copies: absolute sizes and paces drawn from what a real
    /// head-worn sensor gives on people walking in a headset, not factors of the actor's own. Real glasses-IMU walking
    /// (21 people, ../shared/data/glasses-train, 10th-90th percentile over people): cadence 83-105 steps/min (median 93;
    /// the actors 95-135, median 110), dynamic SD (after a 1 s moving average) vertical 1.05-1.84 m/s^2 (actors
    /// 1.8-5.8), lateral 0.59-1.03 (actors 1.3-3.3), forward 0.69-1.15 (actors 2.1-3.3).
    /// </summary>
    public sealed class WearerSettings
    {
        /// <summary>Cadence of the copy (steps per minute), drawn uniformly; the time stretch follows from the original's own.</summary>
        public double MinCadence = 70, MaxCadence = 112;

        /// <summary>Time stretch limits (a copy is never sped up by more than this, nor slowed beyond it).</summary>
        public double MinStretch = 0.85, MaxStretch = 1.8;

        /// <summary>Dynamic SD of the copy's vertical, lateral and forward acceleration (m/s^2), each drawn log-uniformly.</summary>
        public double MinVertical = 0.8, MaxVertical = 2.2, MinLateral = 0.45, MaxLateral = 1.3, MinForward = 0.5, MaxForward = 1.4;

        /// <summary>Yaw of the sensor from the walking direction (degrees, either way): a temple-mounted sensor is not aligned with the head's forward.</summary>
        public double MaxYawDegrees = 20;

        /// <summary>
        /// Wider ranges reaching the slowest, calmest walkers (a slowed bn1 *feminine* walks about 60 steps/min with a vertical
        /// dynamic SD of 0.73 m/s^2): cadence from 55, stretch to 2.2, vertical from 0.6, lateral from 0.35, forward from 0.4.
        /// </summary>
        public static WearerSettings Wide() => new WearerSettings
        {
            MinCadence = 55, MaxStretch = 2.2, MinVertical = 0.6, MinLateral = 0.35, MinForward = 0.4,
        };
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

        /// <summary>
        /// A copy of a walking recording as a wearer of <see cref="WearerSettings"/>'s ranges might give it: time stretched
        /// from the original's cadence (from its labelled contacts) to one drawn from the range, the dynamic part of each axis
        /// scaled to a drawn size, then turned by a drawn yaw. Null when the recording holds standing or fewer than four
        /// contacts (its cadence unknown): gestures and bows keep their own sizes.
        /// </summary>
        public static Recording LikeWearer(Recording source, DeterministicRandom random, WearerSettings settings = null)
        {
            var s = settings ?? new WearerSettings();
            var rows = Uniform(source);
            int n = rows.Count, contacts = 0, first = -1, last = -1;
            for (int i = 0; i < n; i++)
            {
                if (!rows[i].HasTruth || rows[i].Left == GaitPhase.Standing || rows[i].Right == GaitPhase.Standing) return null;
                if (i > 0 && (GaitPhases.IsContact(rows[i - 1].Left, rows[i].Left) || GaitPhases.IsContact(rows[i - 1].Right, rows[i].Right)))
                {
                    contacts++;
                    if (first < 0) first = i;
                    last = i;
                }
            }
            if (contacts < 4) return null;
            double ownCadence = 60 * Rate * (contacts - 1) / (last - first);
            double stretch = Math.Max(s.MinStretch, Math.Min(s.MaxStretch, ownCadence / random.Uniform(s.MinCadence, s.MaxCadence)));
            var (acc, slow) = Channels(rows, new AugmentationSettings().SlowWindowSeconds);
            double LogUniform(double min, double max) => Math.Exp(random.Uniform(Math.Log(min), Math.Log(max)));
            double[] target = { LogUniform(s.MinForward, s.MaxForward), LogUniform(s.MinLateral, s.MaxLateral), LogUniform(s.MinVertical, s.MaxVertical) };
            var gains = new double[3];
            for (int k = 0; k < 3; k++)
            {
                double sum = 0;
                for (int i = 0; i < n; i++) sum += (acc[k][i] - slow[k][i]) * (acc[k][i] - slow[k][i]);
                double sd = Math.Sqrt(sum / n);
                gains[k] = sd > 1e-6 ? target[k] / sd : 1;
            }
            double yaw = random.Uniform(-s.MaxYawDegrees, s.MaxYawDegrees);
            string name = string.Format(System.Globalization.CultureInfo.InvariantCulture, "{0}{1}wearer{2:F2}v{3:F2}l{4:F2}f{5:F2}y{6:F0}",
                source.Name, IsCopy(source.Name) ? "" : CopyMark.ToString(), stretch, target[2], target[1], target[0], yaw);
            var copy = Transform(source, stretch, gains[0], gains[1], gains[2], new AugmentationSettings().SlowWindowSeconds, name);
            return Math.Abs(yaw) < 1e-9 ? copy : Turned(copy, yaw);
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
        public static Recording EarLike(Recording source) => SlowedDown(source, EarLikeStretch, EarLikeSidewaysGain);

        /// <summary>
        /// How much slower and how much weaker sideways and forwards <see cref="Slow"/> makes a recording: 40 % slower than
        /// the actors (their median step of 0.55 s becomes 0.77 s, 78 steps a minute), as a calm or elderly walker might go.
        /// </summary>
        public const double SlowStretch = 1.4, SlowSidewaysGain = 0.7;

        /// <summary>
        /// The recording as a much slower, calmer walker might give it (the benchmark's <c>--slow</c>): time stretched by
        /// <see cref="SlowStretch"/>, every dynamic part scaled by 1/stretch^2 and the sideways and forward ones also by
        /// <see cref="SlowSidewaysGain"/>: slower than any copy the classifiers trained on (<see cref="AugmentationSettings.MaxStretch"/>). Same name.
        /// </summary>
        public static Recording Slow(Recording source) => SlowedDown(source, SlowStretch, SlowSidewaysGain);

        /// <summary>Time stretched by <paramref name="stretch"/>, the dynamic part scaled by 1/stretch^2 and sideways and forwards also by <paramref name="sidewaysGain"/>. Same name.</summary>
        static Recording SlowedDown(Recording source, double stretch, double sidewaysGain)
        {
            double gain = 1 / (stretch * stretch);
            return Transform(source, stretch, gain * sidewaysGain, gain * sidewaysGain, gain, new AugmentationSettings().SlowWindowSeconds, source.Name);
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

        /// <summary>
        /// What <see cref="Jolted"/> adds above the mocap's 12 Hz: at each labelled initial contact a damped oscillation of
        /// this frequency (Hz), peak (m/s^2, vertical; forward at <see cref="JoltForwardShare"/> of it) and decay time (s),
        /// and white sensor noise of this SD (m/s^2, every axis). Made up, not measured: a size a headset's heel-strike
        /// shock and strap wobble might have, to see whether the classifiers lean on a band their training never held.
        /// </summary>
        public const double JoltHz = 20, JoltPeak = 1.5, JoltDecaySeconds = 0.02, JoltForwardShare = 0.5, JoltNoise = 0.1;

        /// <summary>
        /// The recording with what a real head-worn sensor has and these 12 Hz low-passed mocap-derived signals lack (the
        /// benchmark's <c>--jolted</c>): a jolt at every labelled initial contact and broadband noise (<see cref="JoltHz"/>
        /// and the constants beside it), seeded by the recording's name. Unlabelled recordings get the noise only. Same name.
        /// </summary>
        public static Recording Jolted(Recording source)
        {
            var rows = Uniform(source);
            int n = rows.Count;
            var jolt = new double[n];
            int reach = (int)Math.Ceiling(5 * JoltDecaySeconds * Rate);
            for (int i = 1; i < n; i++)
            {
                if (!rows[i].HasTruth || !rows[i - 1].HasTruth) continue;
                if (!GaitPhases.IsContact(rows[i - 1].Left, rows[i].Left) && !GaitPhases.IsContact(rows[i - 1].Right, rows[i].Right)) continue;
                for (int j = 0; j < reach && i + j < n; j++)
                {
                    double t = j / Rate;
                    jolt[i + j] += JoltPeak * Math.Exp(-t / JoltDecaySeconds) * Math.Cos(2 * Math.PI * JoltHz * t);
                }
            }
            var random = new DeterministicRandom(DeterministicRandom.SeedFrom(source.Name));
            var output = new List<RecordedSample>(n);
            for (int i = 0; i < n; i++)
            {
                var a = rows[i].Imu;
                var imu = new ImuSample(a.Time,
                    a.X + JoltForwardShare * jolt[i] + JoltNoise * random.NextGaussian(),
                    a.Y + JoltNoise * random.NextGaussian(),
                    a.Z + jolt[i] + JoltNoise * random.NextGaussian());
                output.Add(rows[i].HasTruth ? new RecordedSample(imu, rows[i].Left, rows[i].Right) : new RecordedSample(imu));
            }
            return Derived(source, source.Name, output);
        }

        /// <summary>
        /// The recording as a sensor sampling at <paramref name="rate"/> Hz would give it (the benchmark's <c>--sensor-rate</c>):
        /// the acceleration interpolated at that rate, labels held from the last row, the preprocessor then resampling it
        /// back to 100 Hz as it does a real sensor's stream. Same name.
        /// </summary>
        public static Recording AtRate(Recording source, double rate)
        {
            if (!(rate > 0) || double.IsInfinity(rate)) throw new ArgumentOutOfRangeException(nameof(rate), "the sensor rate must be a positive number of Hz");
            return Derived(source, source.Name, Resampled(source, rate));
        }

        /// <summary>Ranges of <see cref="StartingAndStopping"/>'s made-up starts and stops.</summary>
        public sealed class StartStopSettings
        {
            /// <summary>Seconds of standing before the walk and after it.</summary>
            public double MinStanding = 0.8, MaxStanding = 1.6;

            /// <summary>Seconds over which the walk's bounce and sway grow from nothing at the start (and fade at the stop).</summary>
            public double MinRamp = 0.3, MaxRamp = 0.7;

            /// <summary>Walking speed gained at the start and lost at the stop (m/s), over the given seconds.</summary>
            public double MinSpeed = 0.8, MaxSpeed = 1.4;
            public double MinSpeedUp = 0.6, MaxSpeedUp = 1.2, MinSlowDown = 0.4, MaxSlowDown = 0.8;

            /// <summary>Standing sway: up to this amplitude (m/s^2) per axis, at 0.2-1 Hz, over white noise of the given SD.</summary>
            public double MaxSway = 0.05, StandingNoise = 0.03;
        }

        /// <summary>
        /// A walking recording as a walk that starts and stops, for training classifiers that otherwise only see walking
        /// cut from continuous walks: standing before and after (the head's mean specific force at the splice, slight sway
        /// and sensor noise), the walk itself from a toe-off to an initial contact (as the mocap converter labels a bout),
        /// its bounce and sway growing from nothing over the first step and fading over the last, and the push of speeding
        /// up and slowing down (forwards in the head frame, also for the few walks sideways or backwards: their direction
        /// is not recorded). Null when the recording is not walking throughout or too short for two steps.
        /// </summary>
        public static Recording StartingAndStopping(Recording source, DeterministicRandom random, StartStopSettings settings = null)
        {
            var s = settings ?? new StartStopSettings();
            var rows = Uniform(source);
            int n = rows.Count, margin = (int)Rate / 2;
            foreach (var r in rows)
                if (!r.HasTruth || r.Left == GaitPhase.Standing || r.Right == GaitPhase.Standing) return null;
            var toeOffs = new List<int>();
            var contacts = new List<int>();
            for (int i = 1; i < n; i++)
            {
                if (GaitPhases.IsToeOff(rows[i - 1].Left, rows[i].Left) || GaitPhases.IsToeOff(rows[i - 1].Right, rows[i].Right)) toeOffs.Add(i);
                if (GaitPhases.IsContact(rows[i - 1].Left, rows[i].Left) || GaitPhases.IsContact(rows[i - 1].Right, rows[i].Right)) contacts.Add(i);
            }
            toeOffs.RemoveAll(i => i < margin);
            contacts.RemoveAll(i => i > n - 1 - margin);
            if (toeOffs.Count == 0 || contacts.Count == 0) return null;
            int first = toeOffs[Math.Min(toeOffs.Count - 1, (int)(random.NextDouble() * 2))];
            int last = contacts[Math.Max(0, contacts.Count - 1 - (int)(random.NextDouble() * 2))];
            if (last - first < 3 * margin) return null;

            var (acc, slow) = Channels(rows, new AugmentationSettings().SlowWindowSeconds);
            int before = (int)Math.Round(random.Uniform(s.MinStanding, s.MaxStanding) * Rate);
            int after = (int)Math.Round(random.Uniform(s.MinStanding, s.MaxStanding) * Rate);
            double rampIn = random.Uniform(s.MinRamp, s.MaxRamp), rampOut = random.Uniform(s.MinRamp, s.MaxRamp);
            double speed = random.Uniform(s.MinSpeed, s.MaxSpeed);
            double speedUp = random.Uniform(s.MinSpeedUp, s.MaxSpeedUp), slowDown = random.Uniform(s.MinSlowDown, s.MaxSlowDown);
            var sway = new double[3][];
            for (int k = 0; k < 3; k++)
                sway[k] = new[] { random.Uniform(0, s.MaxSway), random.Uniform(0.2, 1.0), random.Uniform(0, 2 * Math.PI) };

            var output = new List<RecordedSample>(before + last - first + 1 + after);
            double t0 = rows[0].Imu.Time;
            var v = new double[3];
            void Standing(int at)
            {
                double t = output.Count / Rate;
                for (int k = 0; k < 3; k++)
                    v[k] = slow[k][at] + sway[k][0] * Math.Sin(2 * Math.PI * sway[k][1] * t + sway[k][2]) + s.StandingNoise * random.NextGaussian();
                output.Add(new RecordedSample(new ImuSample(t0 + t, v[0], v[1], v[2]), GaitPhase.Standing, GaitPhase.Standing));
            }
            for (int j = 0; j < before; j++) Standing(first);
            double walkSeconds = (last - first) / Rate;
            for (int i = first; i <= last; i++)
            {
                double since = (i - first) / Rate, until = (last - i) / Rate;
                double weight = SmoothStep(since / rampIn) * SmoothStep(until / rampOut);
                // Raised-cosine accelerations whose integrals are the speed gained and lost.
                double push = since < speedUp ? speed / speedUp * (1 - Math.Cos(2 * Math.PI * since / speedUp)) : 0;
                if (until < slowDown) push -= speed / slowDown * (1 - Math.Cos(2 * Math.PI * until / slowDown));
                for (int k = 0; k < 3; k++) v[k] = slow[k][i] + weight * (acc[k][i] - slow[k][i]);
                v[0] += push;
                output.Add(new RecordedSample(new ImuSample(t0 + output.Count / Rate, v[0], v[1], v[2]), rows[i].Left, rows[i].Right));
            }
            for (int j = 0; j < after; j++) Standing(last);
            return Derived(source, source.Name + (IsCopy(source.Name) ? "" : CopyMark.ToString())
                + string.Format(System.Globalization.CultureInfo.InvariantCulture, "startstop{0:F1}s", walkSeconds), output);
        }

        static double SmoothStep(double x) => x <= 0 ? 0 : x >= 1 ? 1 : x * x * (3 - 2 * x);

        /// <summary>A recording made from <paramref name="source"/>: the given name and samples, the source's metadata.</summary>
        static Recording Derived(Recording source, string name, List<RecordedSample> samples)
        {
            var result = new Recording(name, samples);
            foreach (var kv in source.Metadata) result.Metadata[kv.Key] = kv.Value;
            return result;
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
            return Derived(source, source.Name, output);
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
            var (acc, slow) = Channels(rows, slowWindowSeconds);
            double[] gains = { forwardGain, lateralGain, verticalGain };
            for (int k = 0; k < 3; k++)
                for (int i = 0; i < n; i++) acc[k][i] = slow[k][i] + gains[k] * (acc[k][i] - slow[k][i]);

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
            return Derived(source, name, output);
        }

        /// <summary>The recording on an exact 100 Hz grid: linear interpolation of the acceleration, labels held from the last row.</summary>
        public static List<RecordedSample> Uniform(Recording source) => Resampled(source, Rate);

        /// <summary>The recording on an exact grid of <paramref name="rate"/> Hz: linear interpolation of the acceleration, labels held from the last row.</summary>
        static List<RecordedSample> Resampled(Recording source, double rate)
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
            for (int k = 0; t0 + k / rate <= t1 + 1e-9; k++)
            {
                double t = t0 + k / rate;
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

        /// <summary>x, y and z of the rows, and their slow parts (moving averages over <paramref name="slowWindowSeconds"/>).</summary>
        static (double[][] Acc, double[][] Slow) Channels(List<RecordedSample> rows, double slowWindowSeconds)
        {
            int n = rows.Count, half = Math.Max(1, (int)Math.Round(slowWindowSeconds * Rate / 2));
            var acc = new double[3][];
            var slow = new double[3][];
            for (int k = 0; k < 3; k++) acc[k] = new double[n];
            for (int i = 0; i < n; i++)
            {
                acc[0][i] = rows[i].Imu.X;
                acc[1][i] = rows[i].Imu.Y;
                acc[2][i] = rows[i].Imu.Z;
            }
            for (int k = 0; k < 3; k++) slow[k] = MovingAverage(acc[k], half);
            return (acc, slow);
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
