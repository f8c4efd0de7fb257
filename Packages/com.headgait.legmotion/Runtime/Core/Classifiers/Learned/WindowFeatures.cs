using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;

namespace HeadGait
{
    /// <summary>Signals of a <see cref="SignalWindow"/> that a learned classifier can read.</summary>
    public enum WindowChannel
    {
        Smv = 0,
        Lateral = 1,
        Forward = 2,
        Vertical = 3,
    }

    /// <summary>
    /// What a learned classifier reads from a window: the newest <see cref="Samples"/> grid samples of the listed
    /// channels, averaged in blocks of <see cref="Step"/> counted back from the newest (the average keeps a real sensor's
    /// vibration from aliasing into the slower rate). Lateral, forward and vertical are centred on their window mean (head
    /// tilt leaks gravity into them); SMV minus gravity is used as it is. Each channel is then standardised with the
    /// model's own mean and scale. The result is time-major: [time][channel].
    /// With <see cref="LevelTolerance"/> the lateral, forward and vertical channels are first turned so that the window's
    /// mean specific force leans at most that many degrees from straight up (<see cref="WindowLevel"/>): a head looking
    /// down at its legs, or a sensor worn tilted, would otherwise feed the vertical bounce into the forward channel.
    /// Written into the model file as e.g. <c>samples:50 step:2 channels:smv,lateral,forward level:15</c>, so training
    /// (which exports these very features) and inference cannot disagree.
    /// </summary>
    public sealed class WindowFeatures
    {
        public WindowFeatures(int samples, int step, IReadOnlyList<WindowChannel> channels, double? levelTolerance = null)
        {
            if (samples < 2 || samples > 1000) throw new ArgumentException("A window needs 2..1000 samples.", nameof(samples));
            if (step < 1 || step > samples || samples % step != 0) throw new ArgumentException("The step must divide the window length.", nameof(step));
            if (channels == null || channels.Count == 0) throw new ArgumentException("At least one channel is needed.", nameof(channels));
            if (levelTolerance.HasValue && !WindowLevel.IsTolerance(levelTolerance.Value)) throw new ArgumentException("The levelling tolerance is 0..90 degrees.", nameof(levelTolerance));
            Samples = samples;
            Step = step;
            Channels = new List<WindowChannel>(channels).ToArray();
            TimeSteps = samples / step;
            LevelTolerance = levelTolerance;
        }

        /// <summary>
        /// Tilt (degrees) beyond which the window is levelled before the channels are read; null: not levelled (files
        /// written before levelling).
        /// </summary>
        public double? LevelTolerance { get; }

        public int Samples { get; }
        public int Step { get; }
        public WindowChannel[] Channels { get; }

        /// <summary>Time steps the classifier sees.</summary>
        public int TimeSteps { get; }

        public int Width => TimeSteps * Channels.Length;

        /// <summary>
        /// Writes the features of the newest samples of a window into <paramref name="destination"/> ([time][channel],
        /// oldest first), before standardisation. The window must hold at least <see cref="Samples"/> samples.
        /// </summary>
        public void Extract(SignalWindow window, double[] destination)
        {
            if (window.Length < Samples) throw new ArgumentException($"The features need {Samples} samples, the window has {window.Length}.");
            int c = Channels.Length;
            int first = window.Length - Samples;
            double inv = 1.0 / Step;
            var level = LevelTolerance.HasValue ? WindowLevel.Of(window, first, LevelTolerance.Value) : WindowLevel.None;
            for (int ch = 0; ch < c; ch++)
            {
                var channel = Channels[ch];
                double mean = 0;
                if (channel != WindowChannel.Smv)
                {
                    for (int i = first; i < window.Length; i++) mean += level.Read(window, channel, i);
                    mean /= Samples;
                }
                for (int t = 0; t < TimeSteps; t++)
                {
                    double sum = 0;
                    for (int i = first + t * Step; i < first + (t + 1) * Step; i++) sum += level.Read(window, channel, i);
                    destination[t * c + ch] = sum * inv - mean;
                }
            }
        }

        public override string ToString()
        {
            var sb = new StringBuilder();
            sb.Append("samples:").Append(Samples.ToString(CultureInfo.InvariantCulture))
              .Append(" step:").Append(Step.ToString(CultureInfo.InvariantCulture))
              .Append(" channels:");
            for (int i = 0; i < Channels.Length; i++) sb.Append(i > 0 ? "," : "").Append(Channels[i].ToString().ToLowerInvariant());
            if (LevelTolerance.HasValue) sb.Append(" level:").Append(LevelTolerance.Value.ToString("R", CultureInfo.InvariantCulture));
            return sb.ToString();
        }

        public static WindowFeatures Parse(string text)
        {
            int samples = -1, step = -1;
            double? level = null;
            List<WindowChannel> channels = null;
            foreach (var part in (text ?? "").Split(new[] { ' ' }, StringSplitOptions.RemoveEmptyEntries))
            {
                int colon = part.IndexOf(':');
                if (colon <= 0) throw new FormatException($"feature spec part '{part}' is not key:value");
                string key = part.Substring(0, colon), value = part.Substring(colon + 1);
                switch (key)
                {
                    case "samples": samples = ParseInt(value, key); break;
                    case "step": step = ParseInt(value, key); break;
                    case "level":
                        if (!WindowLevel.TryParseTolerance(value, out double tolerance))
                            throw new FormatException($"feature spec 'level' is '{value}', not a tilt of 0..90 degrees");
                        level = tolerance;
                        break;
                    case "channels":
                        channels = new List<WindowChannel>();
                        foreach (var name in value.Split(','))
                        {
                            if (!Enum.TryParse(name, true, out WindowChannel ch) || int.TryParse(name, out _))
                                throw new FormatException($"unknown channel '{name}' (smv, lateral, forward, vertical)");
                            channels.Add(ch);
                        }
                        break;
                    default: throw new FormatException($"unknown feature spec key '{key}'");
                }
            }
            if (samples < 0 || step < 0 || channels == null) throw new FormatException($"feature spec '{text}' needs samples, step and channels");
            try
            {
                return new WindowFeatures(samples, step, channels, level);
            }
            catch (ArgumentException e)
            {
                throw new FormatException($"feature spec '{text}': {e.Message}");
            }
        }

        static int ParseInt(string v, string key)
            => int.TryParse(v, NumberStyles.Integer, CultureInfo.InvariantCulture, out int i) ? i : throw new FormatException($"feature spec '{key}' is '{v}', not an integer");
    }
}
