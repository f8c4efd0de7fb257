using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace HeadGait
{
    /// <summary>A model file that cannot be used; the message names the file and what is wrong with it.</summary>
    public sealed class ModelFormatException : Exception
    {
        public ModelFormatException(string source, string message) : base($"{source}: {message}")
        {
            FileName = source;
        }

        public string FileName { get; }
    }

    /// <summary>
    /// The learned classifiers' file format (<c>.bytes</c>, so Unity imports it as a TextAsset):
    /// <code>
    /// headgait-model v1
    /// kind=blstm
    /// key=value ...                      (features, classes, phase_map, provenance)
    /// tensor=NAME f32|f64 DIM[xDIM...]   (one line per tensor, in data order)
    /// end
    /// &lt;tensor data, little-endian, back to back&gt;
    /// </code>
    /// Reading checks the magic line, every tensor's shape against the bytes present, and that every value is finite.
    /// </summary>
    public sealed class ModelFile
    {
        public const string Magic = "headgait-model v1";

        public string Source { get; private set; } = "model";
        public Dictionary<string, string> Values { get; } = new Dictionary<string, string>();
        readonly Dictionary<string, (int[] shape, double[] data, bool f64)> tensors = new Dictionary<string, (int[], double[], bool)>();
        readonly List<string> order = new List<string>();

        public string Kind => Need("kind");

        public string Need(string key)
            => Values.TryGetValue(key, out var v) ? v : throw new ModelFormatException(Source, $"lacks '{key}'");

        public double NeedDouble(string key)
        {
            string v = Need(key);
            if (!double.TryParse(v, NumberStyles.Float, CultureInfo.InvariantCulture, out double d) || double.IsNaN(d) || double.IsInfinity(d))
                throw new ModelFormatException(Source, $"'{key}' is '{v}', not a finite number");
            return d;
        }

        public int NeedInt(string key, int min, int max)
        {
            string v = Need(key);
            if (!int.TryParse(v, NumberStyles.Integer, CultureInfo.InvariantCulture, out int i) || i < min || i > max)
                throw new ModelFormatException(Source, $"'{key}' is '{v}', not an integer in {min}..{max}");
            return i;
        }

        public void Set(string key, string value)
        {
            if (key.IndexOf('=') >= 0 || key.IndexOf('\n') >= 0 || value.IndexOf('\n') >= 0) throw new ArgumentException("Keys and values are single lines; keys have no '='.");
            Values[key] = value;
        }

        public void AddTensor(string name, int[] shape, double[] data, bool f64)
        {
            long count = 1;
            foreach (var d in shape) count *= d;
            if (count != data.Length) throw new ArgumentException($"Tensor {name}: shape holds {count} values, data {data.Length}.");
            if (!tensors.ContainsKey(name)) order.Add(name);
            tensors[name] = ((int[])shape.Clone(), data, f64);
        }

        /// <summary>A tensor's values (row-major), checked to have exactly the expected shape.</summary>
        public double[] Tensor(string name, params int[] shape)
        {
            if (!tensors.TryGetValue(name, out var t)) throw new ModelFormatException(Source, $"lacks tensor '{name}'");
            bool same = t.shape.Length == shape.Length;
            for (int i = 0; same && i < shape.Length; i++) same = t.shape[i] == shape[i];
            if (!same) throw new ModelFormatException(Source, $"tensor '{name}' is {Shape(t.shape)}, expected {Shape(shape)}");
            return t.data;
        }

        public bool HasTensor(string name) => tensors.ContainsKey(name);

        /// <summary>Dimensions of a tensor as stored (to read sizes such as the hidden width before checking the rest).</summary>
        public int[] ShapeOf(string name)
            => tensors.TryGetValue(name, out var t) ? (int[])t.shape.Clone() : throw new ModelFormatException(Source, $"lacks tensor '{name}'");

        static string Shape(int[] s) => string.Join("x", s);

        public byte[] ToBytes()
        {
            var header = new StringBuilder();
            header.Append(Magic).Append('\n');
            foreach (var kv in Values) header.Append(kv.Key).Append('=').Append(kv.Value).Append('\n');
            foreach (var name in order)
            {
                var t = tensors[name];
                header.Append("tensor=").Append(name).Append(' ').Append(t.f64 ? "f64" : "f32").Append(' ').Append(Shape(t.shape)).Append('\n');
            }
            header.Append("end\n");
            using (var ms = new MemoryStream())
            {
                var h = Encoding.UTF8.GetBytes(header.ToString());
                ms.Write(h, 0, h.Length);
                using (var w = new BinaryWriter(ms, Encoding.UTF8, true))
                {
                    foreach (var name in order)
                    {
                        var t = tensors[name];
                        foreach (var v in t.data)
                        {
                            if (t.f64) w.Write(v);
                            else w.Write((float)v);
                        }
                    }
                }
                return ms.ToArray();
            }
        }

        /// <summary>Writes to a temporary file beside the target, then moves it in place, so a failed write never leaves half a model.</summary>
        public void Save(string path)
        {
            AtomicFile.WriteAllBytes(path, ToBytes());
        }

        /// <summary>Reads a model file, streaming it: the tensors are read straight into their arrays, the file is never held whole.</summary>
        public static ModelFile Load(string path)
        {
            if (!File.Exists(path)) throw new ModelFormatException(path, "file not found");
            Stream stream;
            try
            {
                // The size limit, and devices and pipes read as empty, as for every other input (InputLimits).
                stream = InputLimits.Open(path, InputLimits.MaxModelBytes, "a model file");
            }
            catch (InputLimitException e)
            {
                throw new ModelFormatException(path, e.Problem);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                throw new ModelFormatException(path, "cannot be read: " + e.Message);
            }
            using (stream)
            {
                try
                {
                    return Parse(stream, path);
                }
                catch (InputLimitException e)
                {
                    throw new ModelFormatException(path, e.Problem);
                }
                catch (IOException e)
                {
                    throw new ModelFormatException(path, "cannot be read: " + e.Message);
                }
            }
        }

        public static ModelFile Parse(byte[] bytes, string source = "model")
        {
            if (bytes == null || bytes.Length == 0) throw new ModelFormatException(source ?? "model", "is empty");
            using (var stream = new MemoryStream(bytes, false)) return Parse(stream, source);
        }

        /// <summary>Reads a model from a stream that knows its length (a file, or bytes in memory).</summary>
        public static ModelFile Parse(Stream stream, string source = "model")
        {
            var m = new ModelFile { Source = source ?? "model" };
            var input = new Reader(stream);
            if (input.Length == 0) throw new ModelFormatException(m.Source, "is empty");
            string NextLine()
            {
                var line = input.ReadLine(100000, out bool tooLong);
                if (tooLong) throw new ModelFormatException(m.Source, "header line longer than 100000 bytes: not a model file?");
                if (line == null) throw new ModelFormatException(m.Source, "header ends without an 'end' line: truncated or not a model file");
                return line.TrimEnd('\r');
            }
            if (input.StartsWith(0xEF, 0xBB, 0xBF)) input.Skip(3);
            var magicBytes = Encoding.ASCII.GetBytes(Magic + "\n");
            if (!input.StartsWith(magicBytes, magicBytes.Length - 1)) throw new ModelFormatException(m.Source, $"does not start with '{Magic}': not a HeadGait model file");
            string magic = NextLine();
            if (magic != Magic) throw new ModelFormatException(m.Source, $"first line must be '{Magic}': not a HeadGait model file");
            var specs = new List<(string name, bool f64, int[] shape)>();
            while (true)
            {
                string line = NextLine();
                if (line == "end") break;
                int eq = line.IndexOf('=');
                if (eq <= 0) throw new ModelFormatException(m.Source, $"header line '{Shorten(line)}' is not key=value");
                string key = line.Substring(0, eq), value = line.Substring(eq + 1);
                if (key != "tensor")
                {
                    m.Values[key] = value;
                    continue;
                }
                string[] parts = value.Split(' ');
                if (parts.Length != 3 || (parts[1] != "f32" && parts[1] != "f64"))
                    throw new ModelFormatException(m.Source, $"tensor line '{Shorten(value)}' must be 'NAME f32|f64 DIMxDIM'");
                string[] dims = parts[2].Split('x');
                var shape = new int[dims.Length];
                for (int i = 0; i < dims.Length; i++)
                {
                    if (!int.TryParse(dims[i], NumberStyles.Integer, CultureInfo.InvariantCulture, out shape[i]) || shape[i] < 1 || shape[i] > 10000000)
                        throw new ModelFormatException(m.Source, $"tensor '{parts[0]}' has a bad dimension '{dims[i]}'");
                }
                specs.Add((parts[0], parts[1] == "f64", shape));
            }
            foreach (var spec in specs)
            {
                long count = 1;
                foreach (var d in spec.shape) count *= d;
                int size = spec.f64 ? 8 : 4;
                if (count > int.MaxValue / 8 || input.Position + count * size > input.Length)
                    throw new ModelFormatException(m.Source, $"tensor '{spec.name}' ({Shape(spec.shape)}) runs past the end of the file: truncated");
                var data = new double[count];
                for (int i = 0; i < count; i++)
                {
                    double v = spec.f64 ? input.ReadDouble() : input.ReadSingle();
                    if (double.IsNaN(v) || double.IsInfinity(v))
                        throw new ModelFormatException(m.Source, $"tensor '{spec.name}' value {i} is not finite");
                    data[i] = v;
                }
                m.AddTensor(spec.name, spec.shape, data, spec.f64);
            }
            if (input.Position != input.Length) throw new ModelFormatException(m.Source, $"{input.Length - input.Position} bytes after the last tensor: wrong shapes or a damaged file");
            return m;
        }

        /// <summary>Little-endian values and header lines from a stream, through one reused buffer (no array per value).</summary>
        sealed class Reader
        {
            readonly Stream stream;
            readonly byte[] buffer = new byte[1 << 16];
            int start, end;
            long consumed; // bytes before buffer[start]

            public Reader(Stream stream)
            {
                this.stream = stream;
                Length = stream.Length - stream.Position;
            }

            public long Length { get; }
            public long Position => consumed;

            /// <summary>Makes at least <paramref name="n"/> bytes available unless the stream ends first; returns how many are.</summary>
            int Fill(int n)
            {
                if (end - start >= n) return end - start;
                Array.Copy(buffer, start, buffer, 0, end - start);
                end -= start;
                start = 0;
                while (end < n)
                {
                    int got = stream.Read(buffer, end, buffer.Length - end);
                    if (got <= 0) break;
                    end += got;
                }
                return end - start;
            }

            public bool StartsWith(params byte[] prefix) => StartsWith(prefix, prefix.Length);

            /// <summary>Whether the first <paramref name="n"/> bytes are the prefix's (and the stream holds the whole prefix's length).</summary>
            public bool StartsWith(byte[] prefix, int n)
            {
                if (Fill(prefix.Length) < prefix.Length) return false;
                for (int i = 0; i < n; i++)
                    if (buffer[start + i] != prefix[i]) return false;
                return true;
            }

            public void Skip(int n)
            {
                Fill(n);
                start += n;
                consumed += n;
            }

            /// <summary>The next line without its '\n', or null when the stream ends first.</summary>
            public string ReadLine(int maxBytes, out bool tooLong)
            {
                tooLong = false;
                var bytes = new List<byte>();
                while (true)
                {
                    if (Fill(1) < 1) return null;
                    byte b = buffer[start++];
                    consumed++;
                    if (b == (byte)'\n') return Encoding.UTF8.GetString(bytes.ToArray());
                    if (bytes.Count > maxBytes)
                    {
                        tooLong = true;
                        return null;
                    }
                    bytes.Add(b);
                }
            }

            public double ReadDouble()
            {
                if (Fill(8) < 8) throw new EndOfStreamException();
                long bits = System.Buffers.Binary.BinaryPrimitives.ReadInt64LittleEndian(new ReadOnlySpan<byte>(buffer, start, 8));
                start += 8;
                consumed += 8;
                return BitConverter.Int64BitsToDouble(bits);
            }

            public float ReadSingle()
            {
                if (Fill(4) < 4) throw new EndOfStreamException();
                int bits = System.Buffers.Binary.BinaryPrimitives.ReadInt32LittleEndian(new ReadOnlySpan<byte>(buffer, start, 4));
                start += 4;
                consumed += 4;
                return BitConverter.Int32BitsToSingle(bits);
            }
        }

        static string Shorten(string s) => s.Length > 60 ? s.Substring(0, 60) + "..." : s;
    }
}
