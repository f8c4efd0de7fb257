using System;
using System.Collections.Generic;
using System.IO;
using System.Text;

namespace HeadGait.Training
{
    /// <summary>
    /// Exports what a learned classifier sees, for training outside the package (Python): every window the live
    /// preprocessor produces from each recording (or every <c>stride</c>-th), its features as
    /// <see cref="WindowFeatures.Extract"/> makes them, and the class of the labels at the window's newest sample.
    /// Files (NumPy .npy, little-endian): X float32 [N, T, C], y int32 [N] (class; -1 where the label pair is not a
    /// stride segment), file int32 [N] (recording index in files.tsv), augmented int32 [N] (1 for augmented copies, 2 for copies made into
    /// walks that start and stop), plus
    /// files.tsv and dataset.txt (features, classes, phase map).
    /// </summary>
    public static class WindowDataset
    {
        public sealed class Item
        {
            public Recording Recording;
            /// <summary>Index of the original recording (augmented copies share it, so folds keep them together).</summary>
            public int FileIndex;

            /// <summary>Every n-th window of this recording is exported; 0: the export's own stride.</summary>
            public int Stride;

            /// <summary>
            /// When set, only windows this gate passes or refuses by less than <see cref="NearLogOdds"/> are exported: the
            /// learned classifiers decide only where their gate lets a window near, so standing far below it teaches them nothing.
            /// </summary>
            public WalkingGate NearGate;

            /// <summary>How far below <see cref="NearGate"/>'s boundary (log-odds) a window is still exported.</summary>
            public double NearLogOdds;

            /// <summary>An augmented copy: trained on, never scored.</summary>
            public bool Augmented;

            /// <summary>
            /// A copy made into a walk that starts and stops (<see cref="RecordingAugmentation.StartingAndStopping"/>): the
            /// BLSTM trains on it, the SVM does not.
            /// </summary>
            public bool StartsAndStops;
        }

        public sealed class Summary
        {
            public long Windows;
            public long Unlabelled;
            public long[] PerClass;
        }

        /// <param name="labelLead">
        /// Seconds after the window's newest sample whose labels are the target. A classifier that only sees the past
        /// hedges at each phase change and reports it late; aiming a little ahead cancels that on average.
        /// </param>
        public static Summary Export(IReadOnlyList<Item> items, IReadOnlyList<string> fileNames, WindowFeatures features,
            StrideSegments segments, int stride, string directory, double labelLead = 0)
        {
            if (stride < 1) throw new ArgumentException("Stride must be at least 1.", nameof(stride));
            Directory.CreateDirectory(directory);
            var summary = new Summary { PerClass = new long[segments.ClassCount] };
            int t = features.TimeSteps, c = features.Channels.Length;
            var buffer = new double[features.Width];
            using (var x = new NpyWriter(Path.Combine(directory, "X.npy"), "<f4", t, c))
            using (var y = new NpyWriter(Path.Combine(directory, "y.npy"), "<i4"))
            using (var file = new NpyWriter(Path.Combine(directory, "file.npy"), "<i4"))
            using (var augmented = new NpyWriter(Path.Combine(directory, "augmented.npy"), "<i4"))
            {
                foreach (var item in items)
                {
                    var rec = item.Recording;
                    if (!rec.HasTruth) continue;
                    var gate = item.NearGate;
                    var pre = new StreamPreprocessor(new PreprocessorSettings { WindowLength = features.Samples, History = Math.Max(features.Samples, gate?.History ?? 0) });
                    var labels = new LabelCursor(rec);
                    long produced = 0;
                    int every = item.Stride > 0 ? item.Stride : stride;
                    foreach (var s in rec.Samples)
                    {
                        pre.Push(s.Imu, w =>
                        {
                            if (produced++ % every != 0) return;
                            if (!labels.TryLabelsAt(w.EndTime + labelLead, out var truth)) return;
                            if (gate != null && !gate.Passes(w, out double logOdds) && logOdds <= -item.NearLogOdds) return;
                            int cls = segments.ClassOf(truth.Left, truth.Right);
                            features.Extract(w, buffer);
                            foreach (var v in buffer) x.Write((float)v);
                            y.Write(cls);
                            file.Write(item.FileIndex);
                            augmented.Write(item.StartsAndStops ? 2 : item.Augmented ? 1 : 0);
                            summary.Windows++;
                            if (cls < 0) summary.Unlabelled++;
                            else summary.PerClass[cls]++;
                        });
                    }
                }
            }
            using (var w = new StreamWriter(Path.Combine(directory, "files.tsv"), false, new UTF8Encoding(false)))
            {
                w.NewLine = "\n";
                w.WriteLine("index\tname\tstyle");
                for (int i = 0; i < fileNames.Count; i++) w.WriteLine($"{i}\t{fileNames[i]}\t{CrossValidation.StyleOf(fileNames[i])}");
            }
            using (var w = new StreamWriter(Path.Combine(directory, "dataset.txt"), false, new UTF8Encoding(false)))
            {
                w.NewLine = "\n";
                w.WriteLine($"features={features}");
                w.WriteLine($"classes={segments.Names()}");
                w.WriteLine($"phase_map={segments.Map.Serialize()}");
                w.WriteLine($"stride={stride}");
                w.WriteLine($"label_lead_s={labelLead.ToString("R", System.Globalization.CultureInfo.InvariantCulture)}");
                w.WriteLine($"windows={summary.Windows}");
            }
            return summary;
        }

        /// <summary>Streams a NumPy .npy array whose first dimension is counted while writing; the header is patched on close.</summary>
        sealed class NpyWriter : IDisposable
        {
            const int HeaderSize = 128;
            readonly FileStream stream;
            readonly BinaryWriter writer;
            readonly string dtype;
            readonly int[] inner;
            long values;

            public NpyWriter(string path, string dtype, params int[] innerShape)
            {
                this.dtype = dtype;
                inner = innerShape;
                stream = new FileStream(path, FileMode.Create, FileAccess.Write);
                writer = new BinaryWriter(stream);
                writer.Write(new byte[HeaderSize]);
            }

            public void Write(float v) => Write(BitConverter.GetBytes(v), 1);
            public void Write(int v) => Write(BitConverter.GetBytes(v), 1);

            void Write(byte[] b, int count)
            {
                if (!BitConverter.IsLittleEndian) Array.Reverse(b);
                writer.Write(b);
                values += count;
            }

            public void Dispose()
            {
                long per = 1;
                foreach (var d in inner) per *= d;
                long rows = values / per;
                var shape = new StringBuilder().Append(rows);
                foreach (var d in inner) shape.Append(", ").Append(d);
                if (inner.Length == 0) shape.Append(',');
                string dict = $"{{'descr': '{dtype}', 'fortran_order': False, 'shape': ({shape}), }}";
                int len = HeaderSize - 10;
                string padded = dict.PadRight(len - 1) + "\n";
                var bytes = new byte[HeaderSize];
                bytes[0] = 0x93;
                Encoding.ASCII.GetBytes("NUMPY", 0, 5, bytes, 1);
                bytes[6] = 1;
                bytes[7] = 0;
                bytes[8] = (byte)(len & 0xFF);
                bytes[9] = (byte)(len >> 8);
                Encoding.ASCII.GetBytes(padded, 0, padded.Length, bytes, 10);
                writer.Flush();
                stream.Seek(0, SeekOrigin.Begin);
                stream.Write(bytes, 0, bytes.Length);
                writer.Dispose();
            }
        }
    }
}
