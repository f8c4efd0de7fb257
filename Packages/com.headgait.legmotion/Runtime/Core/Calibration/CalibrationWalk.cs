using System;
using System.Collections.Generic;

namespace HeadGait.Calibration
{
    /// <summary>
    /// The calibration walk as the wearer goes through it: what to tell them at each moment, and the head samples and (when
    /// two tracked devices are strapped above the ankles) their positions, gathered into a <see cref="CalibrationSession"/>.
    /// Engine-free, so the Unity component and a desktop or test harness share it: feed it samples and poses, ask for the
    /// prompt, end it when <see cref="IsDue"/> (or earlier, by the wearer's choice).
    /// </summary>
    public sealed class CalibrationWalk
    {
        public enum Stage { Idle, Walking, Fitting, Done, Failed }

        /// <summary>Shortest walk worth fitting (s): about eight steps of a slow walker plus a turn.</summary>
        public const double MinSeconds = 10;

        readonly List<RecordedSample> head = new List<RecordedSample>();
        readonly List<PoseSample> left = new List<PoseSample>(), right = new List<PoseSample>();
        double started;

        public CalibrationWalk(double seconds = 60)
        {
            if (!(seconds >= MinSeconds && seconds <= 600)) throw new ArgumentException($"A calibration walk lasts {MinSeconds} to 600 s.", nameof(seconds));
            Seconds = seconds;
        }

        public double Seconds { get; }
        public Stage State { get; private set; } = Stage.Idle;

        /// <summary>What went wrong when <see cref="State"/> is <see cref="Stage.Failed"/>; what was fitted when it is <see cref="Stage.Done"/>.</summary>
        public string Outcome { get; private set; } = "";

        public int HeadSamples => head.Count;
        public int AnklePoses => Math.Min(left.Count, right.Count);

        public void Begin(double now)
        {
            head.Clear();
            left.Clear();
            right.Clear();
            started = now;
            Outcome = "";
            State = Stage.Walking;
        }

        /// <summary>A head sample (ignored unless walking; a non-finite one is dropped, as the pipeline drops it).</summary>
        public void AddHead(in ImuSample sample)
        {
            if (State != Stage.Walking || !sample.IsFinite) return;
            if (head.Count > 0 && !(sample.Time > head[head.Count - 1].Imu.Time)) return;
            head.Add(new RecordedSample(sample));
        }

        /// <summary>Both ankle devices' positions (tracking space, y up, m) at one time on the head samples' clock.</summary>
        public void AddAnkles(double time, double leftX, double leftY, double leftZ, double rightX, double rightY, double rightZ)
        {
            if (State != Stage.Walking) return;
            if (!ImuSample.IsFiniteNumber(time) || !ImuSample.IsFiniteNumber(leftX) || !ImuSample.IsFiniteNumber(leftY) || !ImuSample.IsFiniteNumber(leftZ)
                || !ImuSample.IsFiniteNumber(rightX) || !ImuSample.IsFiniteNumber(rightY) || !ImuSample.IsFiniteNumber(rightZ)) return;
            if (left.Count > 0 && !(time > left[left.Count - 1].Time)) return;
            left.Add(new PoseSample(time, leftX, leftY, leftZ, 0, 0, 0, 1));
            right.Add(new PoseSample(time, rightX, rightY, rightZ, 0, 0, 0, 1));
        }

        public bool IsDue(double now) => State == Stage.Walking && now - started >= Seconds;

        public double SecondsLeft(double now) => State == Stage.Walking ? Math.Max(0, Seconds - (now - started)) : 0;

        /// <summary>
        /// Ends the walk and hands over what was recorded (with the ankle streams when they cover it; see
        /// <see cref="CalibrationSession"/>); null, and <see cref="Stage.Failed"/>, when it is too short to fit.
        /// </summary>
        public CalibrationSession End(string name = "calibration")
        {
            if (State != Stage.Walking) throw new InvalidOperationException("The calibration walk has not begun.");
            double seconds = head.Count < 2 ? 0 : head[head.Count - 1].Imu.Time - head[0].Imu.Time;
            if (seconds < MinSeconds)
            {
                Fail($"the head sensor gave {seconds:F0} s of samples (at least {MinSeconds:F0} s are needed): is the headset's sensor on?");
                return null;
            }
            State = Stage.Fitting;
            var recording = new Recording(name, new List<RecordedSample>(head));
            bool ankles = left.Count >= 20 && left[0].Time <= head[0].Imu.Time + FootContactLabeller.MaxGapSeconds
                          && left[left.Count - 1].Time >= head[head.Count - 1].Imu.Time - FootContactLabeller.MaxGapSeconds;
            return ankles ? new CalibrationSession(recording, new List<PoseSample>(left), new List<PoseSample>(right)) : new CalibrationSession(recording);
        }

        public void Finish(WearerProfile profile)
        {
            State = Stage.Done;
            Outcome = $"fitted on {profile.Steps} steps ({(profile.Source == WearerProfile.FromFootReferences ? "with the ankle trackers" : "from the steps it was sure of")})";
        }

        public void Fail(string reason)
        {
            State = Stage.Failed;
            Outcome = reason;
        }

        /// <summary>The line to show the wearer now.</summary>
        public string Prompt(double now)
        {
            switch (State)
            {
                case Stage.Walking:
                    double elapsed = now - started, left = SecondsLeft(now);
                    string what = elapsed < 0.4 * Seconds ? "Walk straight ahead at your usual pace."
                        : elapsed < 0.55 * Seconds ? "Turn around."
                        : elapsed < 0.9 * Seconds ? "Walk back at your usual pace."
                        : "Stop and stand still.";
                    return $"Calibration: {what} ({left:F0} s)";
                case Stage.Fitting: return "Fitting the legs to your steps...";
                case Stage.Done: return $"Done: the legs are {Outcome}.";
                case Stage.Failed: return $"Calibration failed: {Outcome}. The legs keep their usual settings.";
                default: return "Calibration: press Start, then walk straight ahead, turn around, walk back and stop.";
            }
        }
    }
}
