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

        public static ModelFile Load(string path)
        {
            if (!File.Exists(path)) throw new ModelFormatException(path, "file not found");
            byte[] bytes;
            try
            {
                bytes = InputLimits.ReadAllBytes(path, InputLimits.MaxModelBytes, "a model file");
            }
            catch (InputLimitException e)
            {
                throw new ModelFormatException(path, e.Problem);
            }
            catch (IOException e)
            {
                throw new ModelFormatException(path, "cannot be read: " + e.Message);
            }
            return Parse(bytes, path);
        }

        public static ModelFile Parse(byte[] bytes, string source = "model")
        {
            var m = new ModelFile { Source = source ?? "model" };
            if (bytes == null || bytes.Length == 0) throw new ModelFormatException(m.Source, "is empty");
            int pos = 0;
            string NextLine()
            {
                int start = pos;
                while (pos < bytes.Length && bytes[pos] != (byte)'\n')
                {
                    if (pos - start > 100000) throw new ModelFormatException(m.Source, "header line longer than 100000 bytes: not a model file?");
                    pos++;
                }
                if (pos >= bytes.Length) throw new ModelFormatException(m.Source, "header ends without an 'end' line: truncated or not a model file");
                string line = Encoding.UTF8.GetString(bytes, start, pos - start).TrimEnd('\r');
                pos++;
                return line;
            }
            if (bytes.Length >= 3 && bytes[0] == 0xEF && bytes[1] == 0xBB && bytes[2] == 0xBF) pos = 3;
            var magicBytes = Encoding.ASCII.GetBytes(Magic + "\n");
            bool magicOk = bytes.Length - pos >= magicBytes.Length;
            for (int i = 0; magicOk && i < magicBytes.Length - 1; i++) magicOk = bytes[pos + i] == magicBytes[i];
            if (!magicOk) throw new ModelFormatException(m.Source, $"does not start with '{Magic}': not a HeadGait model file");
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
                if (count > int.MaxValue / 8 || pos + count * size > bytes.Length)
                    throw new ModelFormatException(m.Source, $"tensor '{spec.name}' ({Shape(spec.shape)}) runs past the end of the file: truncated");
                var data = new double[count];
                for (int i = 0; i < count; i++)
                {
                    double v = spec.f64 ? BitConverter.ToDouble(LittleEndian(bytes, pos, 8), 0) : BitConverter.ToSingle(LittleEndian(bytes, pos, 4), 0);
                    if (double.IsNaN(v) || double.IsInfinity(v))
                        throw new ModelFormatException(m.Source, $"tensor '{spec.name}' value {i} is not finite");
                    data[i] = v;
                    pos += size;
                }
                m.AddTensor(spec.name, spec.shape, data, spec.f64);
            }
            if (pos != bytes.Length) throw new ModelFormatException(m.Source, $"{bytes.Length - pos} bytes after the last tensor: wrong shapes or a damaged file");
            return m;
        }

        static byte[] LittleEndian(byte[] bytes, int pos, int size)
        {
            var b = new byte[size];
            Array.Copy(bytes, pos, b, 0, size);
            if (!BitConverter.IsLittleEndian) Array.Reverse(b);
            return b;
        }

        static string Shorten(string s) => s.Length > 60 ? s.Substring(0, 60) + "..." : s;
    }
}
