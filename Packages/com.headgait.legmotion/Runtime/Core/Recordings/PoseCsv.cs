using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace HeadGait
{
    /// <summary>One tracked head pose in Unity's tracking space: left-handed, y up, metres; rotation x, y, z, w.</summary>
    public readonly struct PoseSample
    {
        public PoseSample(double time, double px, double py, double pz, double qx, double qy, double qz, double qw)
        {
            Time = time;
            Px = px;
            Py = py;
            Pz = pz;
            Qx = qx;
            Qy = qy;
            Qz = qz;
            Qw = qw;
        }

        public double Time { get; }
        public double Px { get; }
        public double Py { get; }
        public double Pz { get; }
        public double Qx { get; }
        public double Qy { get; }
        public double Qz { get; }
        public double Qw { get; }
    }

    /// <summary>
    /// Head-pose recordings, as an XR runtime reports the head (for headsets without an accelerometer reading):
    /// <code>
    /// # headgait-pose v1
    /// timestamp_s,pos_x,pos_y,pos_z,rot_x,rot_y,rot_z,rot_w,phase_left,phase_right
    /// </code>
    /// Unity tracking space (left-handed, y up, metres; the rotation maps the camera's axes, x right, y up, z forward,
    /// into tracking space); labels as in acceleration recordings. Replayed through <see cref="ToAcceleration"/>, which
    /// is what the XR pose source does live.
    /// </summary>
    /// <summary>A head-pose recording in memory: poses with per-foot labels, and metadata written as comment lines.</summary>
    public sealed class PoseRecording
    {
        public PoseRecording(string name, List<(PoseSample pose, GaitPhase left, GaitPhase right)> rows)
        {
            Name = name;
            Rows = rows;
        }

        public string Name { get; }
        public List<(PoseSample pose, GaitPhase left, GaitPhase right)> Rows { get; }
        public Dictionary<string, string> Metadata { get; } = new Dictionary<string, string>();
    }

    public static class PoseCsv
    {
        public const string Magic = "# headgait-pose v1";
        public static readonly string[] RequiredColumns = { "timestamp_s", "pos_x", "pos_y", "pos_z", "rot_x", "rot_y", "rot_z", "rot_w" };

        /// <summary>Largest position magnitude read (m): tracking spaces are rooms, not continents.</summary>
        public const double MaxPosition = 10000;

        /// <summary>True when the file starts with the pose magic line (after any byte-order mark).</summary>
        public static bool IsPoseFile(string path)
        {
            using (var reader = InputLimits.OpenText(path, InputLimits.MaxRecordingBytes, "a recording"))
            {
                string first = reader.ReadLine();
                return first != null && first.TrimStart('\uFEFF').Trim() == Magic;
            }
        }

        /// <summary>Reads a pose recording; bad rows are skipped with warnings, or throw in strict mode.</summary>
        public static List<(PoseSample pose, GaitPhase? left, GaitPhase? right, int line)> Load(string path, bool strict, out List<string> warnings)
        {
            var rows = new List<(PoseSample, GaitPhase?, GaitPhase?, int)>();
            Read(path, strict, out warnings, (pose, l, r, line) => rows.Add((pose, l, r, line)));
            return rows;
        }

        /// <summary>Reads a pose recording row by row into <paramref name="row"/> (nothing kept), within <see cref="InputLimits"/>.</summary>
        static void Read(string path, bool strict, out List<string> warnings, Action<PoseSample, GaitPhase?, GaitPhase?, int> row)
        {
            if (!File.Exists(path)) throw new FileNotFoundException($"Pose recording not found: {path}", path);
            using (var reader = InputLimits.OpenText(path, InputLimits.MaxRecordingBytes, "a pose recording"))
            {
                var limits = new[] { RecordingCsv.MaxTimestamp, MaxPosition, MaxPosition, MaxPosition, 2, 2, 2, 2 };
                var units = new[] { "s", "m", "m", "m", "", "", "", "" };
                var table = LabelledCsv.Read(reader, path, strict, RequiredColumns, limits, units,
                    (v, line, l, r) => row(new PoseSample(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]), l, r, line));
                warnings = table.Warnings;
            }
        }

        /// <summary>Writes a pose recording (whole or not at all: see <see cref="AtomicFile"/>); without <paramref name="labels"/> the phase columns are left out (a device's own pose, e.g. an ankle tracker's).</summary>
        public static void Save(PoseRecording recording, string path, bool labels = true) => AtomicFile.WriteText(path, w =>
        {
            w.WriteLine(Magic);
            foreach (var kv in recording.Metadata) w.WriteLine($"# {kv.Key}={kv.Value}");
            w.WriteLine(string.Join(",", RequiredColumns) + (labels ? ",phase_left,phase_right" : ""));
            var ci = CultureInfo.InvariantCulture;
            foreach (var (p, left, right) in recording.Rows)
            {
                w.WriteLine(string.Join(",", p.Time.ToString("F5", ci), p.Px.ToString("F5", ci), p.Py.ToString("F5", ci), p.Pz.ToString("F5", ci),
                    p.Qx.ToString("F6", ci), p.Qy.ToString("F6", ci), p.Qz.ToString("F6", ci), p.Qw.ToString("F6", ci))
                    + (labels ? "," + GaitPhases.ShortName(left) + "," + GaitPhases.ShortName(right) : ""));
            }
        });

        /// <summary>
        /// The acceleration recording a pose recording becomes through the XR pose path: each pose through a
        /// <see cref="PoseAccelerationEstimator"/>, each sample labelled with its newest pose's labels (the moment the avatar
        /// shows it) and the estimator's mean lag in <see cref="Recording.SourceLag"/>.
        /// </summary>
        public static Recording ToAcceleration(string path, bool strict = false)
        {
            var estimator = new PoseAccelerationEstimator();
            var samples = new List<RecordedSample>();
            double lagSum = 0;
            // Streamed: each pose goes through the estimator as it is read, so only the acceleration samples are kept.
            Read(path, strict, out var warnings, (pose, left, right, line) =>
            {
                if (!estimator.Push(pose.Time, pose.Px, pose.Py, pose.Pz, pose.Qx, pose.Qy, pose.Qz, pose.Qw, out var imu)) return;
                lagSum += estimator.Lag;
                samples.Add(left.HasValue ? new RecordedSample(imu, left.Value, right.Value, line) : new RecordedSample(imu, line));
            });
            string slow = estimator.TakeWarning();
            if (slow != null) warnings.Add(slow);
            var rec = new Recording(Path.GetFileNameWithoutExtension(path), samples, warnings);
            rec.SourceLag = samples.Count > 0 ? lagSum / samples.Count : 0;
            rec.Metadata["source"] = "head pose through PoseAccelerationEstimator";
            return rec;
        }
    }
}
