using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;

namespace HeadGait.Synthetic
{
    /// <summary>
    /// The definitions of the sample recordings shipped in Samples~/Recordings, so that they can be
    /// regenerated bit for bit (<c>headgait generate</c>) and checked against the committed files.
    /// Training recordings use other subjects than evaluation recordings.
    /// </summary>
    public static class SampleLibrary
    {
        public sealed class Entry
        {
            public string Name;
            /// <summary>"train" or "eval": the sub-folder it lives in.</summary>
            public string Set;
            public string Description;
            public Func<Recording> Build;
        }

        public static IReadOnlyList<Entry> All { get; } = new List<Entry>
        {
            new Entry
            {
                Name = "train_subject_a", Set = "train",
                Description = "Training: subject A, stand/walk/turn mix, both lead feet.",
                Build = () => WalkingStreamGenerator.Generate("train_subject_a", GaitSubject.Random(1001, "train-A"),
                    new StreamScript().Stand(3, 0.6).Walk(20, Foot.Left).Stand(2).Walk(15, Foot.Right, 25).Stand(2, 0.6).Walk(12, Foot.Left, -20, 1.1).Stand(3), 11),
            },
            new Entry
            {
                Name = "train_subject_b", Set = "train",
                Description = "Training: subject B, slower cadence, start/stop bouts.",
                Build = () => WalkingStreamGenerator.Generate("train_subject_b", GaitSubject.Random(1002, "train-B"),
                    new StreamScript().Stand(2).Walk(18, Foot.Right).Stand(3, 0.8).Walk(10, Foot.Left, 0, 0.9).Stand(2).Walk(14, Foot.Right, 15).Stand(3), 12),
            },
            new Entry
            {
                Name = "train_subject_c", Set = "train",
                Description = "Training: subject C, faster cadence with turns.",
                Build = () => WalkingStreamGenerator.Generate("train_subject_c", GaitSubject.Random(1003, "train-C"),
                    new StreamScript().Stand(2, 0.5).Walk(16, Foot.Left, 30).Stand(2).Walk(16, Foot.Right, -30, 1.08).Stand(3), 13),
            },
            new Entry
            {
                Name = "walk_straight", Set = "eval",
                Description = "Evaluation: subject E1 stands, walks 40 s straight ahead, stands.",
                Build = () => WalkingStreamGenerator.Generate("walk_straight", GaitSubject.Random(2001, "eval-E1"),
                    new StreamScript().Stand(3).Walk(40, Foot.Left).Stand(3), 21),
            },
            new Entry
            {
                Name = "walk_turns", Set = "eval",
                Description = "Evaluation: subject E2 walks with left and right turns while looking around.",
                Build = () =>
                {
                    var script = new StreamScript { HeadYawDegrees = 30 };
                    script.Stand(2).Walk(10, Foot.Right, 35).Walk(8, Foot.Left, 0).Walk(10, Foot.Left, -40).Stand(3);
                    return WalkingStreamGenerator.Generate("walk_turns", GaitSubject.Random(2002, "eval-E2"), script, 22);
                },
            },
            new Entry
            {
                Name = "start_stop", Set = "eval",
                Description = "Evaluation: subject E3 alternates standing (with head nods) and short walks, both lead feet.",
                Build = () =>
                {
                    var script = new StreamScript();
                    for (int i = 0; i < 6; i++) script.Stand(4, 0.8).Walk(6, i % 2 == 0 ? Foot.Left : Foot.Right, 0, 0.9 + 0.04 * i);
                    script.Stand(4, 0.8);
                    return WalkingStreamGenerator.Generate("start_stop", GaitSubject.Random(2003, "eval-E3"), script, 23);
                },
            },
            new Entry
            {
                Name = "irregular_rate", Set = "eval",
                Description = "Evaluation: subject E4 recorded at 72 Hz with 2 ms jitter and 2% dropped samples (resampling test).",
                Build = () =>
                {
                    var script = new StreamScript { SampleRate = 72, TimestampJitter = 0.002, DropProbability = 0.02 };
                    script.Stand(3).Walk(25, Foot.Right, 10).Stand(3);
                    return WalkingStreamGenerator.Generate("irregular_rate", GaitSubject.Random(2004, "eval-E4"), script, 24);
                },
            },
            new Entry
            {
                Name = "glitchy", Set = "eval",
                Description = "Evaluation: subject E5 with corrupt rows (NaN, text, missing cells), repeated and out-of-order timestamps and a 0.4 s hole.",
                Build = () => Corrupt(GlitchyBeforeCorruption(), 26),
            },
        };

        /// <summary>The 'glitchy' sample as generated, before its rows are corrupted: what a clean sensor would have given.</summary>
        public static Recording GlitchyBeforeCorruption() => WalkingStreamGenerator.Generate("glitchy", GaitSubject.Random(2005, "eval-E5"),
            new StreamScript().Stand(2).Walk(20, Foot.Left).Stand(2), 25);

        public static Entry Find(string name)
        {
            foreach (var e in All) if (string.Equals(e.Name, name, StringComparison.OrdinalIgnoreCase)) return e;
            return null;
        }

        /// <summary>The CSV text of an entry as committed (corrupt rows of 'glitchy' included).</summary>
        public static string ToCsv(Entry entry)
        {
            var rec = entry.Build();
            var sw = new System.IO.StringWriter(CultureInfo.InvariantCulture);
            RecordingCsv.Write(rec, sw);
            string text = sw.ToString();
            if (entry.Name != "glitchy") return text;
            // Inject rows the reader must reject, at fixed places.
            var lines = new List<string>(text.Split('\n'));
            int header = lines.FindIndex(l => l.StartsWith("timestamp_s", StringComparison.Ordinal));
            Insert(lines, header + 400, "NaN,0.1,0.2,9.8,STAND,STAND");
            Insert(lines, header + 900, "9.0000,abc,0.0,9.8,MST,PSW");
            Insert(lines, header + 1300, "12.5000,0.1,0.2");
            Insert(lines, header + 1700, "16.0000,0.1,0.2,Infinity,IC,PSW");
            Insert(lines, header + 2000, "19.0000,0.1,0.2,9.8,WALKING,PSW");
            return string.Join("\n", lines);
        }

        static void Insert(List<string> lines, int at, string row)
        {
            if (at < lines.Count) lines.Insert(at, row);
        }

        /// <summary>Repeats and reorders some timestamps and cuts a 0.4 s hole: things the preprocessor must survive.</summary>
        static Recording Corrupt(Recording rec, ulong seed)
        {
            var rnd = new DeterministicRandom(seed);
            var src = rec.Samples;
            var outList = new List<RecordedSample>(src.Count);
            double holeStart = 10.0, holeEnd = 10.4;
            for (int i = 0; i < src.Count; i++)
            {
                var s = src[i];
                if (s.Imu.Time >= holeStart && s.Imu.Time < holeEnd) continue;
                outList.Add(s);
                double u = rnd.NextDouble();
                if (u < 0.01) outList.Add(s); // repeated timestamp
                else if (u < 0.02 && i > 2)
                {
                    var old = src[i - 2]; // a late, out-of-order sample
                    outList.Add(old);
                }
            }
            var result = new Recording(rec.Name, outList);
            foreach (var kv in rec.Metadata) result.Metadata[kv.Key] = kv.Value;
            result.Metadata["corruption"] = "repeated and out-of-order timestamps, 0.4 s hole at 10.0 s, 5 invalid rows";
            return result;
        }
    }
}
