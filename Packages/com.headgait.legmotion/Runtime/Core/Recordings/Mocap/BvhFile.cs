using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;

namespace HeadGait.Mocap
{
    /// <summary>A BVH file (or any text) that cannot be read as BVH motion capture; names the source and the line.</summary>
    public sealed class BvhFormatException : Exception
    {
        public BvhFormatException(string source, int line, string message) : base($"{source}:{line}: {message}")
        {
            FileName = source;
            Line = line;
        }

        public string FileName { get; }
        public int Line { get; }
    }

    public enum BvhChannel
    {
        Xposition,
        Yposition,
        Zposition,
        Xrotation,
        Yrotation,
        Zrotation,
    }

    public sealed class BvhJoint
    {
        public string Name;
        public int Parent = -1;
        public double[] Offset = new double[3];
        public BvhChannel[] Channels = Array.Empty<BvhChannel>();
        /// <summary>Index of this joint's first channel in a frame's values.</summary>
        public int FirstChannel;
        public bool IsEndSite;
    }

    /// <summary>
    /// Biovision hierarchy motion capture: a skeleton of joints with offsets and channels, and frames of channel values.
    /// Position channels replace the joint's offset; rotation channels (degrees) apply in the order listed, each about
    /// the joint's own rotated axes, so a joint's local rotation is R(first) R(second) R(third).
    /// </summary>
    public sealed class BvhFile
    {
        public string Name { get; private set; }
        public List<BvhJoint> Joints { get; } = new List<BvhJoint>();
        public double FrameTime { get; private set; }
        public int ChannelCount { get; private set; }
        /// <summary>Frames of channel values, one array per frame, in the joints' channel order.</summary>
        public List<double[]> Frames { get; } = new List<double[]>();

        public int FrameCount => Frames.Count;

        public int FindJoint(string name)
        {
            for (int i = 0; i < Joints.Count; i++)
                if (!Joints[i].IsEndSite && string.Equals(Joints[i].Name, name, StringComparison.OrdinalIgnoreCase)) return i;
            return -1;
        }

        public static BvhFile Load(string path)
        {
            if (!File.Exists(path)) throw new FileNotFoundException($"BVH file not found: {path}", path);
            return Parse(InputLimits.ReadAllText(path, InputLimits.MaxBvhBytes, "a BVH file"), Path.GetFileName(path));
        }

        public static BvhFile Parse(string text, string name = "motion.bvh")
        {
            if (text == null) throw new ArgumentNullException(nameof(text));
            var reader = new Tokens(text, name);
            var bvh = new BvhFile { Name = name };
            if (text.Length > 0 && text[0] == '\uFEFF') reader.SkipBom();
            reader.Expect("HIERARCHY");
            string word = reader.Next("ROOT");
            if (word != "ROOT") throw reader.Error($"expected ROOT, found '{word}'");
            ReadSkeleton(reader, bvh);
            if (bvh.Joints.Count < 2) throw reader.Error("the skeleton has no joints below its root");
            reader.Expect("MOTION");
            reader.Expect("Frames:");
            int frames = reader.NextInt("frame count");
            if (frames < 0) throw reader.Error($"negative frame count {frames}");
            if (frames > InputLimits.MaxBvhFrames)
                throw reader.Error($"declares {frames} frames, over the limit of {InputLimits.MaxBvhFrames} (InputLimits.MaxBvhFrames)");
            // Every value takes at least two characters: a count the text cannot hold is refused before anything is kept.
            if ((long)frames * bvh.ChannelCount > text.Length / 2 + 1)
                throw reader.Error($"declares {frames} frames of {bvh.ChannelCount} channels, more values than the file holds: truncated?");
            reader.Expect("Frame");
            reader.Expect("Time:");
            bvh.FrameTime = reader.NextDouble("frame time");
            if (!(bvh.FrameTime > 0) || bvh.FrameTime > 10) throw reader.Error($"frame time {bvh.FrameTime} s is not a plausible positive number");
            for (int f = 0; f < frames; f++)
            {
                var values = new double[bvh.ChannelCount];
                for (int c = 0; c < values.Length; c++)
                {
                    if (reader.AtEnd) throw reader.Error($"file ends in frame {f + 1} of {frames} (channel {c + 1} of {bvh.ChannelCount}): truncated?");
                    values[c] = reader.NextDouble($"frame {f + 1} channel {c + 1}");
                }
                bvh.Frames.Add(values);
            }
            if (!reader.AtEnd) throw reader.Error($"more values than {frames} frames of {bvh.ChannelCount} channels");
            if (frames < 2) throw reader.Error($"only {frames} frame(s): nothing moves");
            return bvh;
        }

        /// <summary>
        /// The skeleton below ROOT, read with an explicit stack rather than recursion, so no nesting can overflow the call
        /// stack; deeper than <see cref="InputLimits.MaxBvhDepth"/> or more than <see cref="InputLimits.MaxBvhChannels"/>
        /// channels is refused.
        /// </summary>
        static void ReadSkeleton(Tokens reader, BvhFile bvh)
        {
            var open = new List<int>(); // joints whose '}' is still to come, innermost last
            int parent = -1;
            bool endSite = false;
            while (true)
            {
                // A new joint (ROOT, JOINT or End Site) starts here.
                if (open.Count >= InputLimits.MaxBvhDepth)
                    throw reader.Error($"joints nest deeper than {InputLimits.MaxBvhDepth}, the limit of a skeleton (InputLimits.MaxBvhDepth)");
                var joint = new BvhJoint { Parent = parent, IsEndSite = endSite };
                if (endSite)
                {
                    reader.Expect("Site");
                    joint.Name = (parent >= 0 ? bvh.Joints[parent].Name : "") + "_End";
                }
                else
                {
                    joint.Name = reader.Next("joint name");
                }
                int index = bvh.Joints.Count;
                bvh.Joints.Add(joint);
                open.Add(index);
                reader.Expect("{");
                reader.Expect("OFFSET");
                for (int k = 0; k < 3; k++) joint.Offset[k] = reader.NextDouble("offset");
                string word = reader.Next("CHANNELS, JOINT, End or }");
                if (word == "CHANNELS")
                {
                    if (endSite) throw reader.Error("an End Site has no channels");
                    int n = reader.NextInt("channel count");
                    if (n < 0 || n > 6) throw reader.Error($"joint '{joint.Name}' declares {n} channels (0 to 6 allowed)");
                    if (bvh.ChannelCount + n > InputLimits.MaxBvhChannels)
                        throw reader.Error($"more than {InputLimits.MaxBvhChannels} channels, the limit of a skeleton (InputLimits.MaxBvhChannels)");
                    joint.Channels = new BvhChannel[n];
                    for (int c = 0; c < n; c++)
                    {
                        string ch = reader.Next("channel name");
                        if (!Enum.TryParse(ch, true, out joint.Channels[c]) || int.TryParse(ch, out _))
                            throw reader.Error($"unknown channel '{ch}' on joint '{joint.Name}'");
                    }
                    joint.FirstChannel = bvh.ChannelCount;
                    bvh.ChannelCount += n;
                    word = reader.Next("JOINT, End or }");
                }
                // Close joints until one opens a child (or the root closes).
                while (word == "}")
                {
                    open.RemoveAt(open.Count - 1);
                    if (open.Count == 0) return;
                    word = reader.Next("JOINT, End or }");
                }
                int current = open[open.Count - 1];
                if (word == "JOINT") endSite = false;
                else if (word == "End") endSite = true;
                else throw reader.Error($"expected JOINT, End or '}}' in joint '{bvh.Joints[current].Name}', found '{word}'");
                parent = current;
            }
        }

        /// <summary>Whitespace-separated words with their line numbers.</summary>
        sealed class Tokens
        {
            readonly string text;
            readonly string source;
            int pos;
            int line = 1;

            public Tokens(string text, string source)
            {
                this.text = text;
                this.source = source;
            }

            public void SkipBom() => pos = 1;

            public bool AtEnd
            {
                get
                {
                    SkipSpace();
                    return pos >= text.Length;
                }
            }

            void SkipSpace()
            {
                while (pos < text.Length && char.IsWhiteSpace(text[pos]))
                {
                    if (text[pos] == '\n') line++;
                    pos++;
                }
            }

            public BvhFormatException Error(string message) => new BvhFormatException(source, line, message);

            public string Next(string what)
            {
                SkipSpace();
                if (pos >= text.Length) throw Error($"file ends where {what} was expected: truncated?");
                int start = pos;
                while (pos < text.Length && !char.IsWhiteSpace(text[pos])) pos++;
                return text.Substring(start, pos - start);
            }

            public void Expect(string word)
            {
                string w = Next(word);
                if (w != word) throw Error($"expected '{word}', found '{Shorten(w)}'");
            }

            public int NextInt(string what)
            {
                string w = Next(what);
                if (!int.TryParse(w, NumberStyles.Integer, CultureInfo.InvariantCulture, out int v)) throw Error($"{what} '{Shorten(w)}' is not an integer");
                return v;
            }

            public double NextDouble(string what)
            {
                string w = Next(what);
                if (!double.TryParse(w, NumberStyles.Float, CultureInfo.InvariantCulture, out double v) || double.IsNaN(v) || double.IsInfinity(v) || Math.Abs(v) > 1e9)
                    throw Error($"{what} '{Shorten(w)}' is not a finite number");
                return v;
            }

            static string Shorten(string s) => s.Length > 30 ? s.Substring(0, 30) + "..." : s;
        }
    }
}
