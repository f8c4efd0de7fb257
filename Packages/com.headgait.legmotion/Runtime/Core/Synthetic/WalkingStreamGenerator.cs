using System;
using System.Collections.Generic;
using System.Globalization;

namespace HeadGait.Synthetic
{
    /// <summary>One stretch of a synthetic stream.</summary>
    public abstract class StreamSegment
    {
        protected StreamSegment(double duration)
        {
            if (!(duration > 0)) throw new ArgumentException("Segment duration must be positive.");
            Duration = duration;
        }

        public double Duration { get; }
    }

    /// <summary>Standing still, optionally nodding and looking around (head movements that are not steps).</summary>
    public sealed class StandSegment : StreamSegment
    {
        public StandSegment(double duration, double headMovement = 0.0) : base(duration)
        {
            HeadMovement = headMovement;
        }

        /// <summary>Peak linear acceleration (m/s^2) of occasional head nods/turns; 0 = still.</summary>
        public double HeadMovement { get; }
    }

    /// <summary>
    /// Walking, starting with the lead foot's toe-off from standing. The bout ends at the first
    /// initial contact after <see cref="StreamSegment.Duration"/> (the closing step), so it lasts a little longer.
    /// </summary>
    public sealed class WalkSegment : StreamSegment
    {
        public WalkSegment(double duration, Foot lead, double turnRateDegPerSecond = 0, double cadenceScale = 1.0) : base(duration)
        {
            Lead = lead;
            TurnRate = turnRateDegPerSecond;
            CadenceScale = cadenceScale;
        }

        public Foot Lead { get; }

        /// <summary>Body yaw rate while walking (deg/s, positive = turning left).</summary>
        public double TurnRate { get; }

        public double CadenceScale { get; }
    }

    public sealed class StreamScript
    {
        public readonly List<StreamSegment> Segments = new List<StreamSegment>();

        /// <summary>Nominal output rate (Hz); headsets deliver anything from 60 to 1000 Hz.</summary>
        public double SampleRate = 100;

        /// <summary>Timestamp jitter (standard deviation, seconds).</summary>
        public double TimestampJitter = 0.0005;

        /// <summary>Probability that an output sample is lost.</summary>
        public double DropProbability = 0;

        /// <summary>Amplitude of slow looking-around head yaw (degrees).</summary>
        public double HeadYawDegrees = 15;

        /// <summary>Mean head pitch (degrees, negative = looking down).</summary>
        public double HeadPitchDegrees = -8;

        public double StartTime = 0;

        public StreamScript Stand(double duration, double headMovement = 0)
        {
            Segments.Add(new StandSegment(duration, headMovement));
            return this;
        }

        public StreamScript Walk(double duration, Foot lead, double turnRate = 0, double cadenceScale = 1)
        {
            Segments.Add(new WalkSegment(duration, lead, turnRate, cadenceScale));
            return this;
        }
    }

    /// <summary>
    /// Generates head accelerometer streams with per-foot ground-truth phases.
    /// The body-frame head acceleration follows the well-known shape of head motion in gait: vertical
    /// acceleration at step frequency peaking shortly after each initial contact (with a damped heel-strike
    /// ring), forward acceleration braking after contact, lateral sway at stride frequency towards the stance
    /// leg, centripetal acceleration in turns, start and stop pushes, and head nods while standing. It is
    /// rotated into a head frame that looks around and pitches, gravity included, then noise, jitter and
    /// dropped samples are added.
    /// </summary>
    public static class WalkingStreamGenerator
    {
        const double Tick = 0.001;
        const double G = 9.80665;

        public static Recording Generate(string name, GaitSubject subject, StreamScript script, ulong seed)
        {
            if (subject == null) throw new ArgumentNullException(nameof(subject));
            if (script == null || script.Segments.Count == 0) throw new ArgumentException("The script has no segments.");
            var rnd = new DeterministicRandom(seed);
            var map = subject.PhaseMap;

            // 1) Simulate the body at 1 kHz.
            var sim = new Simulation(subject, script, map, rnd);
            sim.Run();

            // 2) Sample it at the output rate, through the head's orientation, with sensor errors.
            var samples = new List<RecordedSample>();
            double bx = 0.03 * rnd.NextGaussian(), by = 0.03 * rnd.NextGaussian(), bz = 0.03 * rnd.NextGaussian();
            double yawPhase = rnd.Uniform(0, 2 * Math.PI), pitchPhase = rnd.Uniform(0, 2 * Math.PI), rollPhase = rnd.Uniform(0, 2 * Math.PI);
            double dt = 1.0 / script.SampleRate;
            double end = sim.Count * Tick - 2 * Tick;
            double last = double.NegativeInfinity;
            for (long k = 0; ; k++)
            {
                double t = k * dt + script.TimestampJitter * rnd.NextGaussian();
                if (t < 0) t = 0;
                if (t > end) break;
                bool drop = script.DropProbability > 0 && rnd.NextDouble() < script.DropProbability;
                double noiseX = subject.NoiseStd * rnd.NextGaussian();
                double noiseY = subject.NoiseStd * rnd.NextGaussian();
                double noiseZ = subject.NoiseStd * rnd.NextGaussian();
                if (drop || t <= last + 1e-4) continue;
                last = t;

                sim.At(t, out double ax, out double ay, out double az, out double yawLook, out double roll, out bool walking, out double s);
                double yaw = Deg(script.HeadYawDegrees) * Math.Sin(2 * Math.PI * 0.07 * t + yawPhase) + yawLook;
                double pitch = Deg(script.HeadPitchDegrees) + Deg(4) * Math.Sin(2 * Math.PI * 0.05 * t + pitchPhase);
                double rollTotal = Deg(1.5) * Math.Sin(2 * Math.PI * 0.11 * t + rollPhase) + roll;
                // Specific force in the body frame (forward, left, up), gravity included.
                ToHead(ax, ay, az + G, yaw, pitch, rollTotal, out double hx, out double hy, out double hz);
                var imu = new ImuSample(script.StartTime + t, hx + bx + noiseX, hy + by + noiseY, hz + bz + noiseZ);
                GaitPhase l = walking ? map.PhaseAt(Foot.Left, s) : GaitPhase.Standing;
                GaitPhase r = walking ? map.PhaseAt(Foot.Right, s) : GaitPhase.Standing;
                samples.Add(new RecordedSample(imu, l, r));
            }
            var rec = new Recording(name, samples);
            var ci = CultureInfo.InvariantCulture;
            rec.Metadata["generator"] = "HeadGait.Synthetic.WalkingStreamGenerator";
            rec.Metadata["seed"] = seed.ToString(ci);
            rec.Metadata["subject"] = subject.ToString();
            rec.Metadata["sample_rate_hz"] = script.SampleRate.ToString(ci);
            rec.Metadata["units"] = "seconds, m/s^2; head frame x forward, y left, z up";
            return rec;
        }

        static double Deg(double d) => d * Math.PI / 180.0;

        /// <summary>v_head = R^T v_body with R = Rz(yaw) Ry(pitch) Rx(roll).</summary>
        static void ToHead(double x, double y, double z, double yaw, double pitch, double roll, out double hx, out double hy, out double hz)
        {
            double cy = Math.Cos(yaw), sy = Math.Sin(yaw);
            double x1 = cy * x + sy * y;
            double y1 = -sy * x + cy * y;
            double z1 = z;
            double cp = Math.Cos(pitch), sp = Math.Sin(pitch);
            double x2 = cp * x1 - sp * z1;
            double z2 = sp * x1 + cp * z1;
            double y2 = y1;
            double cr = Math.Cos(roll), sr = Math.Sin(roll);
            hx = x2;
            hy = cr * y2 + sr * z2;
            hz = -sr * y2 + cr * z2;
        }

        sealed class Simulation
        {
            readonly GaitSubject subject;
            readonly StreamScript script;
            readonly PhaseMap map;
            readonly DeterministicRandom rnd;
            readonly List<float> ax = new List<float>(), ay = new List<float>(), az = new List<float>();
            readonly List<float> lookYaw = new List<float>(), roll = new List<float>();
            readonly List<bool> walking = new List<bool>();
            readonly List<double> stride = new List<double>();

            public Simulation(GaitSubject subject, StreamScript script, PhaseMap map, DeterministicRandom rnd)
            {
                this.subject = subject;
                this.script = script;
                this.map = map;
                this.rnd = rnd;
            }

            public int Count => walking.Count;

            double time;
            double lastIcTime = double.NegativeInfinity;
            double lastIcEnvelope;
            double lastIcAmp;
            double stopTime = double.NegativeInfinity;
            double lookIntoTurn; // people look ~0.3 s ahead into a turn
            double s;

            public void Run()
            {
                double swayX = rnd.Uniform(0, 6.28), swayY = rnd.Uniform(0, 6.28);
                var segs = script.Segments;
                for (int i = 0; i < segs.Count; i++)
                {
                    if (segs[i] is StandSegment stand) RunStand(stand, swayX, swayY);
                    else if (segs[i] is WalkSegment walk)
                    {
                        bool fromWalk = i > 0 && segs[i - 1] is WalkSegment;
                        bool intoWalk = i + 1 < segs.Count && segs[i + 1] is WalkSegment;
                        RunWalk(walk, swayX, swayY, fromWalk, intoWalk);
                    }
                }
                // A little tail so the last sample has a neighbour.
                RunStand(new StandSegment(0.05), swayX, swayY);
            }

            void Push(double x, double y, double z, bool isWalking, double stridePos, double rollAngle)
            {
                ax.Add((float)x);
                ay.Add((float)y);
                az.Add((float)z);
                lookYaw.Add((float)lookIntoTurn);
                roll.Add((float)rollAngle);
                walking.Add(isWalking);
                stride.Add(stridePos);
                time += Tick;
            }

            void Transients(ref double x, ref double z)
            {
                double tau = time - lastIcTime;
                if (tau >= 0 && tau < 0.3)
                {
                    double a = lastIcAmp * lastIcEnvelope;
                    z += a * Math.Exp(-tau / 0.025) * Math.Sin(2 * Math.PI * 15 * tau);
                    x -= 0.5 * a * Math.Exp(-tau / 0.03) * Math.Sin(2 * Math.PI * 12 * tau);
                }
                double ts = time - stopTime;
                if (ts >= 0 && ts < 0.5) x -= 0.7 * Math.Sin(Math.PI * ts / 0.5);
            }

            void RunStand(StandSegment seg, double swayX, double swayY)
            {
                lookIntoTurn = 0;
                int n = (int)Math.Round(seg.Duration / Tick);
                double nextNod = time + rnd.Uniform(0.5, 2.5);
                double nodStart = double.NegativeInfinity, nodAmp = 0, nodFreq = 2.5;
                for (int i = 0; i < n; i++)
                {
                    double x = 0.04 * Math.Sin(2 * Math.PI * 0.3 * time + swayX);
                    double y = 0.04 * Math.Sin(2 * Math.PI * 0.23 * time + swayY);
                    double z = 0.02 * Math.Sin(2 * Math.PI * 0.4 * time);
                    if (seg.HeadMovement > 0 && time >= nextNod)
                    {
                        nodStart = time;
                        nodAmp = seg.HeadMovement * rnd.Uniform(0.5, 1.0);
                        nodFreq = rnd.Uniform(1.5, 3.0);
                        nextNod = time + rnd.Uniform(1.5, 4.0);
                    }
                    double tn = time - nodStart;
                    if (tn >= 0 && tn < 2.0 / nodFreq)
                    {
                        double hann = 0.5 - 0.5 * Math.Cos(2 * Math.PI * tn * nodFreq / 2.0);
                        double wave = Math.Sin(2 * Math.PI * nodFreq * tn) * hann * nodAmp;
                        z += wave;
                        x += 0.6 * wave;
                    }
                    Transients(ref x, ref z);
                    Push(x, y, z, false, 0, 0);
                }
            }

            double unwrappedCarry;
            double walkStartTime;

            /// <summary>
            /// One walking bout. A bout that follows another walk segment carries on its gait (its lead foot is
            /// ignored); one that precedes another walk segment does not close.
            /// </summary>
            void RunWalk(WalkSegment seg, double swayX, double swayY, bool fromWalk, bool intoWalk)
            {
                double stance = map.Onset(GaitPhase.InitialSwing);
                double offset = map.RightOffset;
                double unwrapped;
                if (fromWalk)
                {
                    unwrapped = unwrappedCarry;
                }
                else
                {
                    // Start at the lead foot's toe-off.
                    s = seg.Lead == Foot.Left ? stance : PhaseMap.Wrap(stance + offset);
                    unwrapped = s;
                    walkStartTime = time;
                }
                double start = time;
                double strideFactor = 1 + subject.StrideVariability * rnd.NextGaussian();
                int strideIndex = (int)Math.Floor(unwrapped);
                double turn = seg.TurnRate * Math.PI / 180.0;
                bool closing = false;
                double closeTarget = 0, closeFrom = 0;
                double baseFreq = subject.StepFrequency * seg.CadenceScale;
                while (true)
                {
                    double elapsed = time - start;
                    double sinceStart = time - walkStartTime;
                    double ramp = sinceStart < 0.6 ? 0.5 - 0.5 * Math.Cos(Math.PI * sinceStart / 0.6) : 1;
                    if (intoWalk && elapsed >= seg.Duration)
                    {
                        unwrappedCarry = unwrapped;
                        return;
                    }
                    double freq = baseFreq * strideFactor * (0.85 + 0.15 * ramp);
                    double strideRate = freq / 2;
                    double next = unwrapped + strideRate * Tick;

                    if (!closing && elapsed >= seg.Duration)
                    {
                        // Close with whichever foot lands next.
                        double left = Math.Ceiling(unwrapped);
                        double right = Math.Floor(unwrapped - offset) + 1 + offset;
                        closeTarget = Math.Min(left, right);
                        closeFrom = unwrapped;
                        closing = true;
                    }

                    // Initial contacts crossed in this tick.
                    double envelope = ramp;
                    if (closing) envelope = Math.Max(0.35, 1 - 0.65 * (unwrapped - closeFrom) / Math.Max(1e-6, closeTarget - closeFrom));
                    if (CrossesContact(unwrapped, next, offset, out Foot foot))
                    {
                        lastIcTime = time;
                        lastIcEnvelope = envelope;
                        lastIcAmp = subject.HeelStrikeAmplitude * (foot == Foot.Left ? 1 + subject.Asymmetry / 2 : 1 - subject.Asymmetry / 2);
                    }
                    if (closing && next >= closeTarget)
                    {
                        stopTime = time;
                        break;
                    }
                    unwrapped = next;
                    if ((int)Math.Floor(unwrapped) != strideIndex)
                    {
                        strideIndex = (int)Math.Floor(unwrapped);
                        strideFactor = 1 + subject.StrideVariability * rnd.NextGaussian();
                    }
                    s = PhaseMap.Wrap(unwrapped);

                    bool leftStep = s < offset;
                    double u = leftStep ? s / offset : (s - offset) / (1 - offset);
                    double amp = leftStep ? 1 + subject.Asymmetry / 2 : 1 - subject.Asymmetry / 2;
                    double cadence = Math.Pow(freq / 1.9, 1.5);
                    double lag = subject.ShapeLag;
                    double z = envelope * amp * cadence * subject.VerticalAmplitude *
                               (Math.Cos(2 * Math.PI * (u - lag)) + 0.35 * Math.Cos(4 * Math.PI * (u - 0.7 * lag)));
                    double x = envelope * amp * cadence * subject.ForwardAmplitude *
                               (-Math.Sin(2 * Math.PI * (u - lag + 0.1)) + 0.3 * Math.Cos(4 * Math.PI * u));
                    double speed = 0.7 * freq * envelope;
                    double y = envelope * subject.LateralAmplitude * (-Math.Sin(2 * Math.PI * s) + 0.15 * Math.Sin(6 * Math.PI * s))
                               + speed * turn;
                    if (sinceStart < 0.6) x += 0.6 * Math.Sin(Math.PI * sinceStart / 0.6);
                    // Standing sway continues underneath.
                    x += 0.02 * Math.Sin(2 * Math.PI * 0.3 * time + swayX);
                    y += 0.02 * Math.Sin(2 * Math.PI * 0.23 * time + swayY);
                    Transients(ref x, ref z);
                    lookIntoTurn = 0.3 * turn * envelope;
                    double rollAngle = envelope * subject.SwayRollDegrees * Math.PI / 180.0 * Math.Sin(2 * Math.PI * s);
                    Push(x, y, z, true, s, rollAngle);
                }
            }

            static bool CrossesContact(double a, double b, double offset, out Foot foot)
            {
                foot = Foot.Left;
                if (Math.Floor(b) > Math.Floor(a)) return true;
                if (Math.Floor(b - offset) > Math.Floor(a - offset))
                {
                    foot = Foot.Right;
                    return true;
                }
                return false;
            }

            public void At(double t, out double x, out double y, out double z, out double yaw, out double rollAngle, out bool isWalking, out double stridePos)
            {
                double p = t / Tick;
                int i = (int)Math.Floor(p);
                if (i < 0) i = 0;
                if (i >= Count - 1) i = Count - 2;
                double a = p - i;
                x = ax[i] + a * (ax[i + 1] - ax[i]);
                y = ay[i] + a * (ay[i + 1] - ay[i]);
                z = az[i] + a * (az[i + 1] - az[i]);
                yaw = lookYaw[i] + a * (lookYaw[i + 1] - lookYaw[i]);
                rollAngle = roll[i] + a * (roll[i + 1] - roll[i]);
                isWalking = walking[i];
                stridePos = stride[i];
            }
        }
    }
}
