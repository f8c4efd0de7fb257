using System;
using System.Collections.Generic;
using HeadGait.Synthetic;
using HeadGait.Unity;
using NUnit.Framework;
using UnityEngine;

namespace HeadGait.Tests
{
    /// <summary>
    /// Generated walks replayed through <see cref="HeadSampleRouter"/>, the path every decoded Input System event takes,
    /// into the gait pipeline: events batched per rendered frame, dropped and duplicated, as a phone's accelerometer and
    /// as a headset's tracked pose.
    /// </summary>
    public class HeadSourceReplayTests
    {
        const float G = HeadAxes.StandardGravity;

        static Recording Walk(double sampleRate = 100) => WalkingStreamGenerator.Generate(
            "replay", GaitSubject.Random(21), new StreamScript { SampleRate = sampleRate }.Stand(3).Walk(12, Foot.Left).Stand(5), 21);

        /// <summary>Runs samples through a THR pipeline; returns the share of frames showing walking within [from, to).</summary>
        sealed class Pipe
        {
            readonly GaitPipeline pipeline = new GaitPipeline(new ThresholdClassifier());
            public readonly List<AnimatorFrame> Frames = new List<AnimatorFrame>();
            public Pipe() { pipeline.FrameProduced += (p, f) => Frames.Add(f); }

            public void Push(HeadSample s)
            {
                pipeline.SourceLag = s.Lag;
                pipeline.Push(s.Time, s.SpecificForce.x, s.SpecificForce.y, s.SpecificForce.z);
            }

            public double WalkingShare(double from, double to)
            {
                int n = 0, walking = 0;
                foreach (var f in Frames)
                {
                    if (f.Time < from || f.Time >= to) continue;
                    n++;
                    if (f.State != LocomotionState.Standing) walking++;
                }
                Assert.That(n, Is.GreaterThan(0), $"no frames in [{from}, {to})");
                return (double)walking / n;
            }
        }

        /// <summary>The LandscapeLeft phone reading (g, along gravity) for a head-frame specific force.</summary>
        static Vector3 LandscapeLeftReading(double forward, double left, double up)
            => new Vector3((float)(-up / G), (float)(-left / G), (float)(forward / G));

        [Test]
        public void PhoneEventsBatchedPerFrameWithDropsAndRepeatsReachThePipelineOnceEach()
        {
            var rec = Walk();
            var delivered = new List<HeadSample>();
            var throughRouter = new Pipe();
            var router = new HeadSampleRouter(HeadImuMode.MobileInput, PhoneMounting.LandscapeLeft, s =>
            {
                delivered.Add(s);
                throughRouter.Push(s);
            });
            var direct = new Pipe();
            var rnd = new System.Random(3);
            var expected = new List<double>();

            // 100 Hz sensor events arrive in batches at 72 Hz frames: one or two per frame, every event with its own time.
            double frame = 1 / 72.0, nextFrame = frame;
            var batch = new List<RecordedSample>();
            int dropped = 0, repeated = 0;
            void Flush()
            {
                foreach (var s in batch)
                {
                    var reading = LandscapeLeftReading(s.Imu.X, s.Imu.Y, s.Imu.Z);
                    router.OnAccelerometerEvent(s.Imu.Time, reading);
                    if (rnd.NextDouble() < 0.05)
                    {
                        router.OnAccelerometerEvent(s.Imu.Time, reading); // delivered twice
                        repeated++;
                    }
                }
                batch.Clear();
            }
            foreach (var s in rec.Samples)
            {
                while (s.Imu.Time >= nextFrame)
                {
                    Flush();
                    nextFrame += frame;
                }
                if (rnd.NextDouble() < 0.03)
                {
                    dropped++; // lost before it reached Unity
                    continue;
                }
                batch.Add(s);
                expected.Add(s.Imu.Time);
                direct.Push(new HeadSample(s.Imu.Time, new Vector3((float)s.Imu.X, (float)s.Imu.Y, (float)s.Imu.Z), 0));
            }
            Flush();

            Assert.That(dropped, Is.GreaterThan(0));
            Assert.That(repeated, Is.GreaterThan(0));
            Assert.That(router.Phone.Timeline.Duplicates, Is.EqualTo(repeated));
            var times = new List<double>();
            foreach (var s in delivered) times.Add(s.Time);
            Assert.That(times, Is.EqualTo(expected), "every event once, with its own time, in order");

            // Axes and units survive the phone's frame: the delivered force equals the recorded one.
            for (int i = 0; i < delivered.Count; i += 37)
            {
                var imu = rec.Samples.Find(r => r.Imu.Time == delivered[i].Time).Imu;
                Assert.That(delivered[i].SpecificForce.x, Is.EqualTo(imu.X).Within(1e-3));
                Assert.That(delivered[i].SpecificForce.y, Is.EqualTo(imu.Y).Within(1e-3));
                Assert.That(delivered[i].SpecificForce.z, Is.EqualTo(imu.Z).Within(1e-3));
            }

            // The pipeline sees what it would have seen from the recording itself.
            Assert.That(throughRouter.Frames.Count, Is.EqualTo(direct.Frames.Count));
            int same = 0;
            for (int i = 0; i < direct.Frames.Count; i++)
                if (throughRouter.Frames[i].State == direct.Frames[i].State) same++;
            Assert.That(same, Is.GreaterThanOrEqualTo(direct.Frames.Count * 99 / 100));
            Assert.That(throughRouter.WalkingShare(5, 15), Is.GreaterThan(0.8), "walking");
            Assert.That(throughRouter.WalkingShare(17.5, 20), Is.LessThan(0.2), "standing again");
        }

        [Test]
        public void TrackedPoseOfAGeneratedWalkIsRecognisedAsWalking([Values(72, 90, 120)] int frameRate)
        {
            var rec = Walk();
            var poses = HeadTrajectory(rec, frameRate, seed: frameRate);
            var pipe = new Pipe();
            var router = new HeadSampleRouter(HeadImuMode.XRDevice, PhoneMounting.LandscapeLeft, pipe.Push);
            foreach (var p in poses)
            {
                // Oculus XR Plugin 4.x style: the acceleration control reads zeros.
                router.OnHeadEvent(new HeadReport
                {
                    Time = p.time, HasPose = true, Position = p.position, Rotation = p.rotation,
                    HasAcceleration = true, Acceleration = Vector3.zero, TrackingState = 3 | 16,
                });
            }
            Assert.That(router.Head.UsingPose, Is.True);
            Assert.That(router.Delivered, Is.GreaterThan(poses.Count - 10));

            var direct = new Pipe();
            foreach (var s in rec.Samples) direct.Push(new HeadSample(s.Imu.Time, new Vector3((float)s.Imu.X, (float)s.Imu.Y, (float)s.Imu.Z), 0));
            double posed = pipe.WalkingShare(5, 15), accel = direct.WalkingShare(5, 15);
            TestContext.WriteLine($"{frameRate} Hz pose: walking {posed:P0} of the walk (accelerometer {accel:P0}); standing part {pipe.WalkingShare(17.5, 20):P0}");
            Assert.That(posed, Is.GreaterThan(0.8));
            Assert.That(posed, Is.GreaterThan(accel - 0.1));
            Assert.That(pipe.WalkingShare(17.5, 20), Is.LessThan(0.2));
        }

        /// <summary>
        /// Head poses whose acceleration is the recording's: its head-frame specific force, minus gravity, turned into
        /// tracking space for a head facing Unity +x, integrated on a 0.5 ms grid on top of a 1.2 m/s walk; poses taken at
        /// <paramref name="rate"/> with up to 1 ms of frame-time jitter, each stamped with its exact grid time.
        /// </summary>
        static List<(double time, Vector3 position, Quaternion rotation)> HeadTrajectory(Recording rec, int rate, int seed)
        {
            var q = Quaternion.Euler(new Vector3(0, 90, 0));
            var rnd = new System.Random(seed);
            const double dt = 0.0005;
            var list = new List<(double, Vector3, Quaternion)>();
            double px = 0, py = 1.7, pz = 0, vx = 1.2, vy = 0, vz = 0; // facing +x: walking along +x
            int k = 0;
            double t0 = rec.Samples[0].Imu.Time, t1 = rec.Samples[rec.Samples.Count - 1].Imu.Time;
            int frameIndex = 1;
            double nextFrame = t0 + 1.0 / rate;
            for (double t = t0; t < t1; t += dt)
            {
                while (k + 1 < rec.Samples.Count - 1 && rec.Samples[k + 1].Imu.Time <= t) k++;
                var a = rec.Samples[k].Imu;
                var b = rec.Samples[k + 1].Imu;
                double u = (t - a.Time) / (b.Time - a.Time);
                double f = a.X + u * (b.X - a.X), l = a.Y + u * (b.Y - a.Y), up = a.Z + u * (b.Z - a.Z);
                // Head frame (forward, left, up) -> head's Unity axes (right, up, forward) -> tracking space.
                var world = q * new Vector3((float)-l, (float)up, (float)f);
                vx += world.x * dt;
                vy += (world.y - G) * dt;
                vz += world.z * dt;
                px += vx * dt;
                py += vy * dt;
                pz += vz * dt;
                if (t >= nextFrame)
                {
                    list.Add((t, new Vector3((float)px, (float)py, (float)pz), q));
                    frameIndex++;
                    nextFrame = t0 + frameIndex / (double)rate + 0.001 * (rnd.NextDouble() - 0.5);
                }
            }
            return list;
        }
    }
}
