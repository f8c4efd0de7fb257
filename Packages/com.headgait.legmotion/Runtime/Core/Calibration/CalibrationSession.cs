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
        public WearerProfile Fit(GaitModels models, string wearer, bool selfSupervised = false)
        {
            if (HasFootReferences && !selfSupervised) return WearerAdaptation.Fit(models, new[] { Labelled() }, wearer, WearerProfile.FromFootReferences);
            var sure = WearerAdaptation.SelfLabel(models, Head);
            return WearerAdaptation.Fit(models, sure, wearer, WearerProfile.SelfSupervised);
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
