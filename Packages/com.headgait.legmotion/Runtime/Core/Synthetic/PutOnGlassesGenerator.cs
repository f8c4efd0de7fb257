using System;
using System.Collections.Generic;
using HeadGait.Mocap;

namespace HeadGait.Synthetic
{
    /// <summary>
    /// A head-worn sensor put on and taken off, over a real recording of the wearer standing still: the glasses (or headset)
    /// lie on a table at some orientation, are picked up and lifted to the face, unfolded, pushed onto the head and adjusted,
    /// worn for a few seconds (the real samples), then taken off, folded and put down again; several cycles. Put-on motions are
    /// the judge's "putting on glasses" activity, which no recording here holds. Each motion is minimum-jerk in position and
    /// angle (a hand's reach), with a hand tremor at 8-12 Hz; the sensor's noise while handled is the worn recording's own
    /// (its samples less their 0.1-s mean). Specific force in the sensor's frame (x forward, y left, z up when worn).
    /// </summary>
    public static class PutOnGlassesGenerator
    {
        public const string Activity = RealActivity.PuttingOnGlasses;
        const double Gravity = 9.80665;
        /// <summary>The fewest worn samples a stream is made over (2 s at 100 Hz: room for one put-on).</summary>
        public const int MinSamples = 200;

        /// <summary>The worn-still recording with put-on and take-off cycles over it; the worn stretches keep its samples.</summary>
        public static Recording From(Recording worn, ulong seed) => From(worn, seed, out _);

        /// <summary>The same, and when each handling ran (s; <c>PutOn</c> false for a take-off).</summary>
        public static Recording From(Recording worn, ulong seed, out List<(double Start, double End, bool PutOn)> handlings)
        {
            if (worn.Samples.Count < MinSamples) throw new ArgumentException($"{worn.Name}: a put-on stream needs at least {MinSamples} worn samples, it has {worn.Samples.Count}.");
            var random = new DeterministicRandom(seed);
            var samples = worn.Samples;
            double t0 = samples[0].Imu.Time, end = samples[samples.Count - 1].Imu.Time;
            var noise = Residual(samples);

            // The schedule: off, put on, worn, take off, off, put on, ... until the recording ends.
            var motions = new List<Motion>();
            double t = t0 + random.Uniform(1.0, 2.0);
            while (true)
            {
                var putOn = Motion.PutOn(t, random);
                if (putOn.End > end) break;
                motions.Add(putOn);
                t = putOn.End + random.Uniform(3.0, 7.0);
                var takeOff = Motion.TakeOff(t, random);
                if (takeOff.End > end) break;
                motions.Add(takeOff);
                t = takeOff.End + random.Uniform(1.0, 3.0);
            }

            handlings = new List<(double, double, bool)>();
            foreach (var motion in motions) handlings.Add((motion.Start, motion.End, motion.EndsWorn));
            var output = new List<RecordedSample>(samples.Count);
            int m = 0;
            bool wornNow = false; // the stream starts with the glasses off
            Rotation3 resting = motions.Count > 0 ? motions[0].From : Rotation3.Identity;
            for (int i = 0; i < samples.Count; i++)
            {
                var s = samples[i].Imu;
                while (m < motions.Count && s.Time >= motions[m].End) { wornNow = motions[m].EndsWorn; resting = motions[m].To; m++; }
                Vec3 force;
                if (m < motions.Count && s.Time >= motions[m].Start) force = motions[m].SpecificForce(s.Time) + noise[i];
                else if (wornNow) { output.Add(new RecordedSample(s)); continue; }
                else force = resting.Transposed * new Vec3(0, 0, Gravity) + noise[i];
                output.Add(new RecordedSample(new ImuSample(s.Time, force.X, force.Y, force.Z)));
            }
            var rec = new Recording(worn.Name + "_putting_on_glasses", output);
            foreach (var kv in worn.Metadata) rec.Metadata[kv.Key] = kv.Value;
            rec.Metadata["activity"] = Activity;
            rec.Metadata["generated"] = $"put on and taken off {motions.Count} times (PutOnGlassesGenerator, seed {seed}) over {worn.Name}";
            return rec;
        }

        /// <summary>Each sample less the mean of its 0.1 s around it: the sensor's own noise and the smallest head tremor.</summary>
        static Vec3[] Residual(List<RecordedSample> samples)
        {
            var r = new Vec3[samples.Count];
            const int half = 5;
            for (int i = 0; i < samples.Count; i++)
            {
                int a = Math.Max(0, i - half), b = Math.Min(samples.Count - 1, i + half);
                double x = 0, y = 0, z = 0;
                for (int k = a; k <= b; k++) { x += samples[k].Imu.X; y += samples[k].Imu.Y; z += samples[k].Imu.Z; }
                int n = b - a + 1;
                var s = samples[i].Imu;
                r[i] = new Vec3(s.X - x / n, s.Y - y / n, s.Z - z / n);
            }
            return r;
        }

        /// <summary>Minimum-jerk progress 0..1 over u in 0..1, and its second derivative.</summary>
        static double Progress(double u) => u <= 0 ? 0 : u >= 1 ? 1 : u * u * u * (10 + u * (-15 + 6 * u));
        static double ProgressAcceleration(double u) => u <= 0 || u >= 1 ? 0 : u * (60 + u * (-180 + 120 * u));

        /// <summary>One handling of the sensor: segments each moving it by a displacement and turning it between two attitudes.</summary>
        sealed class Motion
        {
            public bool EndsWorn;
            readonly List<(double Start, double Duration, Vec3 Move, Rotation3 From, Rotation3 To)> segments = new List<(double, double, Vec3, Rotation3, Rotation3)>();
            double tremorAmplitude, tremorHz, tremorPhase;

            public double Start => segments[0].Start;
            public double End => segments[segments.Count - 1].Start + segments[segments.Count - 1].Duration;
            /// <summary>The attitude the sensor is handled from and left at.</summary>
            public Rotation3 From => segments[0].From;
            public Rotation3 To => segments[segments.Count - 1].To;

            public static Motion PutOn(double start, DeterministicRandom random)
            {
                var m = new Motion { EndsWorn = true };
                m.Tremor(random);
                var lying = RandomAttitude(random);
                var held = HeldAttitude(random);
                var folded = FoldedTemple(random);
                double t = start;
                t = m.Add(t, random.Uniform(0.8, 1.5), Reach(random, random.Uniform(0.3, 0.6)), lying, held * folded);
                t = m.Add(t, random.Uniform(0.3, 0.6), Small(random, 0.05), held * folded, held);
                t = m.Add(t, random.Uniform(0.5, 1.0), new Vec3(random.Uniform(-0.2, -0.1), random.Uniform(-0.05, 0.05), random.Uniform(0.0, 0.08)), held, Rotation3.Identity);
                int pushes = (int)Math.Floor(random.Uniform(0, 4));
                for (int k = 0; k < pushes; k++)
                {
                    t += random.Uniform(0.1, 0.4);
                    t = m.Add(t, random.Uniform(0.15, 0.25), new Vec3(random.Uniform(-0.015, -0.005), 0, random.Uniform(0.0, 0.01)), Rotation3.Identity, Rotation3.Identity);
                }
                return m;
            }

            public static Motion TakeOff(double start, DeterministicRandom random)
            {
                var m = new Motion { EndsWorn = false };
                m.Tremor(random);
                var held = HeldAttitude(random);
                var folded = FoldedTemple(random);
                var lying = RandomAttitude(random);
                double t = start;
                t = m.Add(t, random.Uniform(0.4, 0.8), new Vec3(random.Uniform(0.1, 0.2), random.Uniform(-0.05, 0.05), random.Uniform(-0.08, 0.0)), Rotation3.Identity, held);
                t = m.Add(t, random.Uniform(0.3, 0.6), Small(random, 0.05), held, held * folded);
                var reach = Reach(random, random.Uniform(0.3, 0.6));
                m.Add(t, random.Uniform(0.8, 1.5), new Vec3(-reach.X, -reach.Y, -reach.Z), held * folded, lying);
                return m;
            }

            /// <summary>Held in the hand near the face: rolled within 40 and pitched within 50 degrees of worn, turned any way.</summary>
            static Rotation3 HeldAttitude(DeterministicRandom random) =>
                Rotation3.About(0, random.Uniform(-40, 40)) * Rotation3.About(1, random.Uniform(-50, 50)) * Rotation3.About(2, random.Uniform(-90, 90));

            /// <summary>The temple arm folded: turned about the hinge (the sensor's up axis when worn) by about 90 degrees.</summary>
            static Rotation3 FoldedTemple(DeterministicRandom random) => Rotation3.About(2, random.Uniform(70, 100));

            void Tremor(DeterministicRandom random)
            {
                tremorAmplitude = random.Uniform(0.05, 0.3);
                tremorHz = random.Uniform(8, 12);
                tremorPhase = random.Uniform(0, 2 * Math.PI);
            }

            double Add(double start, double duration, Vec3 move, Rotation3 from, Rotation3 to)
            {
                segments.Add((start, duration, move, from, to));
                return start + duration;
            }

            /// <summary>From the table up to the face: mostly up, some way toward the wearer.</summary>
            static Vec3 Reach(DeterministicRandom random, double up)
            {
                double heading = random.Uniform(0, 2 * Math.PI), across = random.Uniform(0.1, 0.3);
                return new Vec3(across * Math.Cos(heading), across * Math.Sin(heading), up);
            }

            static Vec3 Small(DeterministicRandom random, double size) =>
                new Vec3(random.Uniform(-size, size), random.Uniform(-size, size), random.Uniform(-size, size));

            /// <summary>Any attitude: a uniformly random unit quaternion (the glasses lie however they were put down).</summary>
            static Rotation3 RandomAttitude(DeterministicRandom random)
            {
                double x = random.NextGaussian(), y = random.NextGaussian(), z = random.NextGaussian(), w = random.NextGaussian();
                double n = Math.Sqrt(x * x + y * y + z * z + w * w);
                return Rotation3.FromQuaternion(x / n, y / n, z / n, w / n);
            }

            /// <summary>The sensor's specific force at <paramref name="time"/> (inside the motion), in its own frame.</summary>
            public Vec3 SpecificForce(double time)
            {
                var attitude = From;
                var acceleration = new Vec3(0, 0, 0);
                foreach (var (start, duration, move, from, to) in segments)
                {
                    if (time < start) break;
                    double u = (time - start) / duration;
                    attitude = u >= 1 ? to : Rotation3.Slerp(from, to, Progress(u));
                    if (u < 1) acceleration = acceleration + (ProgressAcceleration(u) / (duration * duration)) * move;
                }
                double tremor = tremorAmplitude * Math.Sin(2 * Math.PI * tremorHz * (time - Start) + tremorPhase);
                var world = acceleration + new Vec3(0, 0, Gravity) + new Vec3(tremor, 0.7 * tremor, 0.5 * tremor);
                return attitude.Transposed * world;
            }
        }
    }
}
