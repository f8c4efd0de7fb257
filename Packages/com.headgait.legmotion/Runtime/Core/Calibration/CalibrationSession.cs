using System;
using System.Collections.Generic;
using System.IO;
using HeadGait.Mocap;

namespace HeadGait.Calibration
{
    /// <summary>
    /// A recorded calibration walk: the head's acceleration and, when the wearer strapped two tracked devices above the
    /// ankles, their pose streams on the same clock. Saved as a folder of three files in the package's formats:
    /// <c>head.csv</c> (<c># headgait-recording v1</c>, unlabelled) and <c>left-ankle.csv</c>, <c>right-ankle.csv</c>
    /// (<c># headgait-pose v1</c>, tracking space, no phase columns); the ankle files are absent for a walk without them.
    /// </summary>
    public sealed class CalibrationSession
    {
        public const string HeadFile = "head.csv", LeftAnkleFile = "left-ankle.csv", RightAnkleFile = "right-ankle.csv";

        public CalibrationSession(Recording head, IReadOnlyList<PoseSample> leftAnkle = null, IReadOnlyList<PoseSample> rightAnkle = null)
        {
            Head = head ?? throw new ArgumentNullException(nameof(head));
            if ((leftAnkle == null) != (rightAnkle == null)) throw new ArgumentException("A calibration walk has both ankle streams or neither.");
            LeftAnkle = leftAnkle;
            RightAnkle = rightAnkle;
        }

        public Recording Head { get; }
        public IReadOnlyList<PoseSample> LeftAnkle { get; }
        public IReadOnlyList<PoseSample> RightAnkle { get; }
        public bool HasFootReferences => LeftAnkle != null;

        /// <summary>The head stream labelled from the ankle streams (<see cref="FootContactLabeller"/>).</summary>
        public Recording Labelled()
        {
            if (!HasFootReferences) throw new InvalidOperationException($"{Head.Name}: this calibration walk has no ankle streams; calibrate it self-supervised.");
            return FootContactLabeller.Label(Head, LeftAnkle, RightAnkle);
        }

        /// <summary>
        /// The profile this walk gives: fitted on the labels from the ankle streams when there are any, otherwise on the
        /// steps the shipped COR is sure of (<see cref="WearerAdaptation.SelfLabel"/>).
        /// </summary>
        public WearerProfile Fit(GaitModels models, string wearer, bool selfSupervised = false, AdaptationSettings settings = null)
        {
            if (HasFootReferences && !selfSupervised) return WearerAdaptation.Fit(models, new[] { Labelled() }, wearer, WearerProfile.FromFootReferences, settings);
            var a = settings ?? AdaptationSettings.For(WearerProfile.SelfSupervised);
            var sure = WearerAdaptation.SelfLabel(models, Head, a.LabelWithGateOpen, a.FillMissedSteps, a.FillMissedBelowSteps);
            return WearerAdaptation.Fit(models, sure, wearer, WearerProfile.SelfSupervised, a, a.StillCheck ? Head : null);
        }

        /// <summary>
        /// A calibration walk from motion capture, as a headset and two ankle trackers would record it: the head's
        /// acceleration as <see cref="MocapConverter.Convert"/> makes it, the ankles' poses at <paramref name="ankleRate"/> Hz
        /// with tracking noise (<see cref="MocapConverter.ConvertAnkles"/>), on one clock.
        /// </summary>
        public static CalibrationSession FromMotionCapture(BvhFile bvh, double ankleRate = 72, MocapSettings settings = null)
        {
            var head = MocapConverter.Convert(bvh, settings);
            var unlabelled = new List<RecordedSample>(head.Samples.Count);
            foreach (var s in head.Samples) unlabelled.Add(new RecordedSample(s.Imu, s.Line));
            var headOnly = new Recording(head.Name, unlabelled);
            foreach (var kv in head.Metadata) headOnly.Metadata[kv.Key] = kv.Value;
            var (left, right) = MocapConverter.ConvertAnkles(bvh, ankleRate, settings);
            return new CalibrationSession(headOnly, Poses(left), Poses(right));
        }

        /// <summary>
        /// Several walks from motion capture joined into one session (<see cref="Join"/>): the minute a wearer walks made of
        /// the clips a corpus cuts it into.
        /// </summary>
        public static CalibrationSession FromMotionCapture(IEnumerable<BvhFile> clips, double ankleRate = 72, MocapSettings settings = null)
        {
            var parts = new List<CalibrationSession>();
            foreach (var bvh in clips) parts.Add(FromMotionCapture(bvh, ankleRate, settings));
            return Join(parts);
        }

        /// <summary>
        /// Seconds without samples put between two joined walks: longer than the pipeline bridges (its windows start afresh,
        /// as after a dropout), shorter than the ankle labeller's <see cref="FootContactLabeller.MaxGapSeconds"/>.
        /// </summary>
        public const double JoinGapSeconds = 0.2;

        /// <summary>
        /// Walks recorded apart as one session on one clock, in order, <see cref="JoinGapSeconds"/> apart: each part's head
        /// samples and ankle poses moved by the same time, its ankle poses cut to its head stream's span and moved
        /// sideways (not up: one floor) to go on from where the last part's ankles stopped. Both ankle streams in every part
        /// or in none.
        /// </summary>
        public static CalibrationSession Join(IReadOnlyList<CalibrationSession> parts)
        {
            if (parts == null || parts.Count == 0) throw new ArgumentException("Nothing to join: no calibration walks.");
            if (parts.Count == 1) return parts[0];
            bool ankles = parts[0].HasFootReferences;
            foreach (var p in parts)
                if (p.HasFootReferences != ankles) throw new ArgumentException($"{p.Head.Name}: some walks to join have ankle streams and some do not.");
            var head = new List<RecordedSample>();
            var left = ankles ? new List<PoseSample>() : null;
            var right = ankles ? new List<PoseSample>() : null;
            double margin = JoinGapSeconds / 4;
            foreach (var p in parts)
            {
                if (p.Head.Samples.Count < 2) throw new ArgumentException($"{p.Head.Name}: a walk to join holds {p.Head.Samples.Count} head samples.");
                double first = p.Head.Samples[0].Imu.Time, last = p.Head.Samples[p.Head.Samples.Count - 1].Imu.Time;
                double shift = head.Count == 0 ? 0 : head[head.Count - 1].Imu.Time + JoinGapSeconds - first;
                foreach (var s in p.Head.Samples)
                {
                    var imu = new ImuSample(s.Imu.Time + shift, s.Imu.X, s.Imu.Y, s.Imu.Z);
                    head.Add(s.HasTruth ? new RecordedSample(imu, s.Left, s.Right, s.Line) : new RecordedSample(imu, s.Line));
                }
                if (!ankles) continue;
                int from = 0;
                while (from < p.LeftAnkle.Count - 1 && p.LeftAnkle[from].Time < first - margin) from++;
                double dx = 0, dz = 0;
                if (left.Count > 0)
                {
                    // Where both ankles stood (middle) at the end of the last part, and at the start of this one.
                    PoseSample l0 = left[left.Count - 1], r0 = right[right.Count - 1], l1 = p.LeftAnkle[from], r1 = p.RightAnkle[Math.Min(from, p.RightAnkle.Count - 1)];
                    dx = 0.5 * (l0.Px + r0.Px - l1.Px - r1.Px);
                    dz = 0.5 * (l0.Pz + r0.Pz - l1.Pz - r1.Pz);
                }
                AddPoses(p.LeftAnkle, left);
                AddPoses(p.RightAnkle, right);

                void AddPoses(IReadOnlyList<PoseSample> poses, List<PoseSample> to)
                {
                    foreach (var a in poses)
                        if (a.Time >= first - margin && a.Time <= last + margin)
                            to.Add(new PoseSample(a.Time + shift, a.Px + dx, a.Py, a.Pz + dz, a.Qx, a.Qy, a.Qz, a.Qw));
                }
            }
            var joined = new Recording(parts[0].Head.Name + (parts.Count > 1 ? $"+{parts.Count - 1}" : ""), head);
            foreach (var kv in parts[0].Head.Metadata) joined.Metadata[kv.Key] = kv.Value;
            return new CalibrationSession(joined, left, right);
        }

        static List<PoseSample> Poses(PoseRecording r)
        {
            var list = new List<PoseSample>(r.Rows.Count);
            foreach (var row in r.Rows) list.Add(row.pose);
            return list;
        }

        /// <summary>Writes the session's files into <paramref name="folder"/> (each whole or not at all).</summary>
        public void Save(string folder)
        {
            Directory.CreateDirectory(folder);
            RecordingCsv.Save(Head, Path.Combine(folder, HeadFile));
            if (!HasFootReferences) return;
            PoseCsv.Save(Rows(LeftAnkle, "left-ankle"), Path.Combine(folder, LeftAnkleFile), labels: false);
            PoseCsv.Save(Rows(RightAnkle, "right-ankle"), Path.Combine(folder, RightAnkleFile), labels: false);
        }

        static PoseRecording Rows(IReadOnlyList<PoseSample> poses, string device)
        {
            var rows = new List<(PoseSample, GaitPhase, GaitPhase)>(poses.Count);
            foreach (var p in poses) rows.Add((p, GaitPhase.Standing, GaitPhase.Standing));
            var r = new PoseRecording(device, rows);
            r.Metadata["device"] = device;
            return r;
        }

        /// <summary>Reads a session folder; the ankle files are optional but come as a pair. Errors name the file.</summary>
        public static CalibrationSession Load(string folder)
        {
            string head = Path.Combine(folder, HeadFile), left = Path.Combine(folder, LeftAnkleFile), right = Path.Combine(folder, RightAnkleFile);
            if (!File.Exists(head)) throw new FileNotFoundException($"{head}: a calibration session needs the head recording", head);
            var recording = RecordingCsv.Load(head);
            bool hasLeft = File.Exists(left), hasRight = File.Exists(right);
            if (hasLeft != hasRight) throw new FileNotFoundException($"{(hasLeft ? right : left)}: the other ankle's stream is there, this one is missing", hasLeft ? right : left);
            if (!hasLeft) return new CalibrationSession(recording);
            return new CalibrationSession(recording, LoadPoses(left), LoadPoses(right));
        }

        static List<PoseSample> LoadPoses(string path)
        {
            var list = new List<PoseSample>();
            foreach (var row in PoseCsv.Load(path, false, out _)) list.Add(row.pose);
            return list;
        }
    }
}
