using System;
using System.Collections.Generic;

namespace HeadGait
{
    /// <summary>One row of a recording: a head accelerometer sample and, optionally, ground-truth phases per foot.</summary>
    public readonly struct RecordedSample
    {
        public readonly ImuSample Imu;
        public readonly bool HasTruth;
        public readonly GaitPhase Left;
        public readonly GaitPhase Right;
        /// <summary>1-based line in the source file (0 when made in memory).</summary>
        public readonly int Line;

        public RecordedSample(ImuSample imu, int line = 0)
        {
            Imu = imu;
            HasTruth = false;
            Left = GaitPhase.Standing;
            Right = GaitPhase.Standing;
            Line = line;
        }

        public RecordedSample(ImuSample imu, GaitPhase left, GaitPhase right, int line = 0)
        {
            Imu = imu;
            HasTruth = true;
            Left = left;
            Right = right;
            Line = line;
        }

        public GaitPhase PhaseOf(Foot foot) => foot == Foot.Left ? Left : Right;
    }

    /// <summary>A recorded (or generated) head-IMU stream.</summary>
    public sealed class Recording
    {
        public Recording(string name, IList<RecordedSample> samples, IList<string> warnings = null)
        {
            Name = name ?? "recording";
            Samples = new List<RecordedSample>(samples ?? throw new ArgumentNullException(nameof(samples)));
            Warnings = new List<string>(warnings ?? Array.Empty<string>());
            Metadata = new Dictionary<string, string>();
        }

        public string Name { get; }
        public List<RecordedSample> Samples { get; }

        /// <summary>Rows the reader skipped, with their line numbers and why.</summary>
        public List<string> Warnings { get; }

        /// <summary>
        /// How late the samples describe the motion (s): 0 for an accelerometer, the estimator's lag for acceleration
        /// derived from a tracked pose. Replays set <see cref="GaitPipeline.SourceLag"/> from it.
        /// </summary>
        public double SourceLag { get; set; }

        /// <summary>key=value pairs from '# key=value' comment lines.</summary>
        public Dictionary<string, string> Metadata { get; }

        public bool HasTruth
        {
            get
            {
                foreach (var s in Samples)
                {
                    if (s.HasTruth) return true;
                }
                return false;
            }
        }

        public double Duration => Samples.Count < 2 ? 0 : Samples[Samples.Count - 1].Imu.Time - Samples[0].Imu.Time;
    }

    /// <summary>A recording file that cannot be read; carries the file and the 1-based line it failed on.</summary>
    public sealed class RecordingFormatException : Exception
    {
        public RecordingFormatException(string source, int line, string message)
            : base($"{source}:{line}: {message}")
        {
            FileName = source;
            Line = line;
        }

        /// <summary>The file's path as it was given, or the recording's name for text that came from no file.</summary>
        public string FileName { get; }
        public int Line { get; }
    }
}
