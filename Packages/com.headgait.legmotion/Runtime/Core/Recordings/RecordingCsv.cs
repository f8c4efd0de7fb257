using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace HeadGait
{
    /// <summary>
    /// The recorded-stream CSV format:
    /// <code>
    /// # headgait-recording v1
    /// # any_key=any value            (optional metadata lines)
    /// timestamp_s,acc_x,acc_y,acc_z,phase_left,phase_right
    /// 0.0000,0.0512,-0.0213,9.8031,STAND,STAND
    /// </code>
    /// Columns are found by name in the header, in any order; extra columns are ignored.
    /// timestamp_s is seconds; acc_* are m/s^2 in the head frame (x forward, y left, z up).
    /// phase_left/phase_right are optional (both or neither): IC, LR, MST, TST, PSW, ISW, MSW, TSW, STAND
    /// (full names such as MidStance are accepted); an empty cell means "no label" for that row.
    /// </summary>
    public static class RecordingCsv
    {
        public const string Magic = "# headgait-recording v1";
        public static readonly string[] RequiredColumns = { "timestamp_s", "acc_x", "acc_y", "acc_z" };
        public static readonly string[] TruthColumns = LabelledCsv.TruthColumns;

        /// <summary>Largest timestamp magnitude read (s): about 31 years. Larger is a unit mix-up (µs as s) or corruption.</summary>
        public const double MaxTimestamp = 1e9;

        /// <summary>Largest acceleration magnitude per axis read (m/s^2): 100 g, far beyond any head.</summary>
        public const double MaxAcceleration = 1000;

        /// <summary>
        /// Range the median acceleration magnitude of a recording must lie in (m/s^2): the format holds specific force, about
        /// g for a head at any pace. Below it the file is in units of g or has gravity removed, above it in other units.
        /// </summary>
        public const double MinMedianMagnitude = 5, MaxMedianMagnitude = 20;

        /// <summary>Rows needed before the median magnitude is judged (a few rows can be anything).</summary>
        const int MagnitudeCheckRows = 20;

        public static Recording Load(string path, bool strict = false)
        {
            if (path == null) throw new ArgumentNullException(nameof(path));
            if (!File.Exists(path)) throw new FileNotFoundException($"Recording not found: {path}", path);
            using (var reader = InputLimits.OpenText(path, InputLimits.MaxRecordingBytes, "a recording"))
            {
                return Read(reader, Path.GetFileNameWithoutExtension(path), strict, path);
            }
        }

        public static Recording Parse(string text, string name = "recording", bool strict = false)
        {
            using (var reader = new StringReader(text ?? throw new ArgumentNullException(nameof(text))))
            {
                return Read(reader, name, strict);
            }
        }

        /// <summary>
        /// Reads a recording. A missing or malformed header (no timestamp_s/acc_x/acc_y/acc_z, one phase
        /// column without the other) always throws <see cref="RecordingFormatException"/>. Bad rows (wrong
        /// cell count, unparsable or non-finite numbers, unknown phase names) throw in strict mode; otherwise
        /// they are skipped and listed in <see cref="Recording.Warnings"/>. Timestamps are not reordered here:
        /// the preprocessor skips out-of-order samples when the stream is replayed. Errors name <paramref name="source"/>
        /// (the file's path), or the recording's name where there is none.
        /// </summary>
        public static Recording Read(TextReader reader, string name, bool strict = false, string source = null)
        {
            source = source ?? name;
            var samples = new List<RecordedSample>();
            var table = LabelledCsv.Read(reader, source, strict, RequiredColumns, new[] { MaxTimestamp, MaxAcceleration, MaxAcceleration, MaxAcceleration },
                new[] { "s", "m/s^2", "m/s^2", "m/s^2" }, (v, line, left, right) =>
                {
                    var imu = new ImuSample(v[0], v[1], v[2], v[3]);
                    samples.Add(left.HasValue ? new RecordedSample(imu, left.Value, right.Value, line) : new RecordedSample(imu, line));
                });
            CheckUnits(samples, source);
            var rec = new Recording(name, samples, table.Warnings);
            foreach (var kv in table.Metadata) rec.Metadata[kv.Key] = kv.Value;
            return rec;
        }

        /// <summary>Throws when the rows' median magnitude says they are not m/s^2 of specific force (see <see cref="MinMedianMagnitude"/>).</summary>
        static void CheckUnits(List<RecordedSample> samples, string source)
        {
            if (samples.Count < MagnitudeCheckRows) return;
            var magnitudes = new double[samples.Count];
            for (int i = 0; i < magnitudes.Length; i++) magnitudes[i] = samples[i].Imu.Magnitude;
            Array.Sort(magnitudes);
            double median = magnitudes[magnitudes.Length / 2];
            if (median >= MinMedianMagnitude && median <= MaxMedianMagnitude) return;
            string cause = median >= 0.5 && median <= 2 ? "they look like units of g (multiply by 9.80665)"
                : median < MinMedianMagnitude ? "they look like linear acceleration with gravity removed (the format wants the accelerometer's reading, gravity included)"
                : "they look like another unit";
            throw new RecordingFormatException(source, samples[0].Line, string.Format(CultureInfo.InvariantCulture,
                "acc_x/acc_y/acc_z have a median magnitude of {0:F2} where a head's accelerometer reads about 9.81 m/s^2: {1}", median, cause));
        }

        public static void Save(Recording recording, string path)
        {
            AtomicFile.WriteText(path, w => Write(recording, w));
        }

        public static void Write(Recording recording, TextWriter w)
        {
            w.NewLine = "\n";
            w.WriteLine(Magic);
            foreach (var kv in recording.Metadata) w.WriteLine($"# {kv.Key}={kv.Value}");
            bool truth = recording.HasTruth;
            w.WriteLine(truth ? "timestamp_s,acc_x,acc_y,acc_z,phase_left,phase_right" : "timestamp_s,acc_x,acc_y,acc_z");
            var ci = CultureInfo.InvariantCulture;
            var sb = new StringBuilder(64);
            foreach (var s in recording.Samples)
            {
                sb.Clear();
                sb.Append(s.Imu.Time.ToString("F4", ci)).Append(',')
                  .Append(s.Imu.X.ToString("F4", ci)).Append(',')
                  .Append(s.Imu.Y.ToString("F4", ci)).Append(',')
                  .Append(s.Imu.Z.ToString("F4", ci));
                if (truth)
                {
                    sb.Append(',');
                    if (s.HasTruth) sb.Append(GaitPhases.ShortName(s.Left));
                    sb.Append(',');
                    if (s.HasTruth) sb.Append(GaitPhases.ShortName(s.Right));
                }
                w.WriteLine(sb.ToString());
            }
        }
    }
}
