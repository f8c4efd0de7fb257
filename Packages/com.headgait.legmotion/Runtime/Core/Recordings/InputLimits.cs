using System;
using System.Globalization;
using System.IO;
using System.Text;

namespace HeadGait
{
    /// <summary>A file refused because it exceeds one of the <see cref="InputLimits"/>; the message names the file and the limit.</summary>
    public sealed class InputLimitException : IOException
    {
        public InputLimitException(string fileName, string problem) : base($"{fileName}: {problem}")
        {
            FileName = fileName;
            Problem = problem;
        }

        public string FileName { get; }

        /// <summary>The message without the file's name.</summary>
        public string Problem { get; }
    }

    /// <summary>
    /// The one place for how much any reader of the package takes in: no input file, however large, endless or hostile, makes
    /// a reader hold more than a bounded amount of memory (well under 1 GB) beyond the samples it returns. Every limit is
    /// checked while reading, so a file that grows or lies about its size is cut off with the same error. Devices, pipes and
    /// other files with no size (/dev/zero, a FIFO) are read as empty, never waited on.
    /// </summary>
    public static class InputLimits
    {
        /// <summary>Largest recording or pose file (bytes): 256 MiB, about 5 million rows, 14 h at 100 Hz.</summary>
        public const long MaxRecordingBytes = 256L << 20;

        /// <summary>Most data rows in one recording or pose file: 4 million, 11 h at 100 Hz (about 200 MB of samples).</summary>
        public const int MaxRecordingRows = 4000000;

        /// <summary>Longest line of a recording, pose file or text model (characters): a real line is under 200.</summary>
        public const int MaxLineChars = 65536;

        /// <summary>Bad rows listed one by one in a recording's warnings; any further ones are counted in one last line.</summary>
        public const int MaxListedWarnings = 1000;

        /// <summary>Largest BVH file (bytes): 64 MiB (the motion-capture files here are under 0.5 MB).</summary>
        public const long MaxBvhBytes = 64L << 20;

        /// <summary>Most frames a BVH file may declare: 1 million, 9 h at 30 fps.</summary>
        public const int MaxBvhFrames = 1000000;

        /// <summary>Most channels of a BVH skeleton (all joints): 1,000, about 170 joints of 6 channels.</summary>
        public const int MaxBvhChannels = 1000;

        /// <summary>Deepest joint nesting of a BVH skeleton (a human skeleton is about 10 deep).</summary>
        public const int MaxBvhDepth = 256;

        /// <summary>Largest learned model file, svm.bytes or blstm.bytes (bytes): 64 MiB (the trained SVM is 4 MB).</summary>
        public const long MaxModelBytes = 64L << 20;

        /// <summary>Largest text model file, thr.txt or cor_template.txt (bytes): 1 MiB (the trained ones are under 10 kB).</summary>
        public const long MaxTextModelBytes = 1L << 20;

        /// <summary>
        /// Opens <paramref name="path"/> for reading within <paramref name="maxBytes"/>: a larger file is refused before it is read,
        /// and reading past the limit (a file that grows) throws <see cref="InputLimitException"/>. A file of no size (empty,
        /// a device, a FIFO) reads as empty without being opened, so a pipe never blocks the reader.
        /// </summary>
        public static Stream Open(string path, long maxBytes, string what)
        {
            if (path == null) throw new ArgumentNullException(nameof(path));
            var info = new FileInfo(path);
            if (!info.Exists) throw new FileNotFoundException($"{path}: file not found", path);
            long length = info.Length;
            if (length == 0) return new MemoryStream(Array.Empty<byte>(), false);
            if (length > maxBytes) throw TooLarge(path, length, maxBytes, what);
            return new LimitedStream(new FileStream(path, FileMode.Open, FileAccess.Read, FileShare.ReadWrite, 65536), maxBytes, path, what);
        }

        /// <summary>The whole file as bytes, within <paramref name="maxBytes"/> (see <see cref="Open"/>).</summary>
        public static byte[] ReadAllBytes(string path, long maxBytes, string what)
        {
            using (var s = Open(path, maxBytes, what))
            using (var ms = new MemoryStream())
            {
                s.CopyTo(ms);
                return ms.ToArray();
            }
        }

        /// <summary>The whole file as UTF-8 text, within <paramref name="maxBytes"/> (see <see cref="Open"/>).</summary>
        public static string ReadAllText(string path, long maxBytes, string what)
        {
            using (var r = new StreamReader(Open(path, maxBytes, what), Encoding.UTF8))
                return r.ReadToEnd();
        }

        /// <summary>A UTF-8 line reader over the file within <paramref name="maxBytes"/>, whose lines may not exceed <see cref="MaxLineChars"/>.</summary>
        public static TextReader OpenText(string path, long maxBytes, string what)
            => new BoundedLineReader(new StreamReader(Open(path, maxBytes, what), Encoding.UTF8), path);

        /// <summary>Wraps any reader so that a line longer than <see cref="MaxLineChars"/> throws instead of filling memory.</summary>
        public static TextReader BoundLines(TextReader reader, string source) => reader is BoundedLineReader ? reader : new BoundedLineReader(reader, source);

        /// <summary>Throws when a file has more data rows than <see cref="MaxRecordingRows"/>.</summary>
        public static void CheckRows(int rows, string source)
        {
            if (rows > MaxRecordingRows)
                throw new InputLimitException(source, string.Format(CultureInfo.InvariantCulture,
                    "more than {0:N0} rows, the limit of one recording (InputLimits.MaxRecordingRows); split it into shorter recordings", MaxRecordingRows));
        }

        internal static InputLimitException TooLarge(string path, long length, long maxBytes, string what)
            => new InputLimitException(path, $"{(length >= 0 ? Size(length) : "more")} is over the limit of {Size(maxBytes)} for {what} (InputLimits)");

        static string Size(long bytes) => bytes >= 1 << 20
            ? string.Format(CultureInfo.InvariantCulture, "{0:0.#} MiB", bytes / 1048576.0)
            : string.Format(CultureInfo.InvariantCulture, "{0:N0} bytes", bytes);

        sealed class LimitedStream : Stream
        {
            readonly Stream inner;
            readonly long max;
            readonly string path, what;
            long read;

            public LimitedStream(Stream inner, long max, string path, string what)
            {
                this.inner = inner;
                this.max = max;
                this.path = path;
                this.what = what;
            }

            public override int Read(byte[] buffer, int offset, int count)
            {
                int n = inner.Read(buffer, offset, count);
                read += n;
                if (read > max) throw TooLarge(path, -1, max, what);
                return n;
            }

            public override bool CanRead => true;
            public override bool CanSeek => false;
            public override bool CanWrite => false;
            // The file's length as it is now (readers that size their reads by it, ModelFile); reading stops at the limit anyway.
            public override long Length => inner.Length;
            public override long Position { get => read; set => throw new NotSupportedException(); }
            public override void Flush() { }
            public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException();
            public override void SetLength(long value) => throw new NotSupportedException();
            public override void Write(byte[] buffer, int offset, int count) => throw new NotSupportedException();

            protected override void Dispose(bool disposing)
            {
                if (disposing) inner.Dispose();
                base.Dispose(disposing);
            }
        }

        sealed class BoundedLineReader : TextReader
        {
            readonly TextReader inner;
            readonly string source;
            readonly StringBuilder line = new StringBuilder(256);
            int lineNo;

            public BoundedLineReader(TextReader inner, string source)
            {
                this.inner = inner;
                this.source = source;
            }

            public override int Peek() => inner.Peek();
            public override int Read() => inner.Read();

            /// <summary>As <see cref="TextReader.ReadLine"/> (LF, CRLF or CR), but a line over <see cref="MaxLineChars"/> throws.</summary>
            public override string ReadLine()
            {
                line.Clear();
                int c = inner.Read();
                if (c < 0) return null;
                lineNo++;
                while (c >= 0 && c != '\n' && c != '\r')
                {
                    if (line.Length >= MaxLineChars)
                        throw new InputLimitException(source, string.Format(CultureInfo.InvariantCulture,
                            "line {0} is longer than {1:N0} characters, the limit of a line (InputLimits.MaxLineChars): not a text file of this kind?", lineNo, MaxLineChars));
                    line.Append((char)c);
                    c = inner.Read();
                }
                if (c == '\r' && inner.Peek() == '\n') inner.Read();
                return line.ToString();
            }

            public override string ReadToEnd()
            {
                var sb = new StringBuilder();
                string l;
                while ((l = ReadLine()) != null) sb.Append(l).Append('\n');
                return sb.ToString();
            }

            protected override void Dispose(bool disposing)
            {
                if (disposing) inner.Dispose();
                base.Dispose(disposing);
            }
        }
    }
}
