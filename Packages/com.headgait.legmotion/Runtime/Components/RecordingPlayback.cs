using System;

namespace HeadGait.Unity
{
    /// <summary>
    /// Plays a <see cref="Recording"/> into a <see cref="GaitBatchRunner"/> in real time (the logic behind
    /// <see cref="RecordingPlayer"/>). Every start from the top is a new stream for the runner: it is reset, so the
    /// recording's timestamps, which jump back to the beginning, are not rejected as late against the previous pass.
    /// Rows are due by the recording's own time steps, each played for at most <see cref="MaxRowGap"/>: a row stamped far
    /// ahead (a +1e6 s glitch, 1e308) would otherwise hold the replay for ever, and a row stamped back plays at once. The
    /// rows reach the target with their timestamps unchanged; its clock policy judges them.
    /// </summary>
    public sealed class RecordingPlayback
    {
        /// <summary>The longest wait between two rows (s): longer pauses in a recording play this long.</summary>
        public const double MaxRowGap = 1.0;

        readonly Recording data;
        readonly double[] due; // playback time at which each row is handed over (s after the first row)
        int next;
        double clock;

        public RecordingPlayback(Recording data)
        {
            this.data = data ?? throw new ArgumentNullException(nameof(data));
            due = new double[data.Samples.Count];
            for (int i = 1; i < due.Length; i++)
            {
                double step = data.Samples[i].Imu.Time - data.Samples[i - 1].Imu.Time;
                // NaN (a non-finite time) and backward steps take no time; inf and absurd jumps take MaxRowGap.
                due[i] = due[i - 1] + (step > 0 ? Math.Min(step, MaxRowGap) : 0);
            }
        }

        public bool Loop { get; set; } = true;

        /// <summary>Ground truth of the row last played, when the recording has it.</summary>
        public RecordedSample LastRow { get; private set; }

        /// <summary>Rows played since the last restart.</summary>
        public int Played => next;

        public bool Finished => next >= data.Samples.Count;

        /// <summary>Back to the first row; the target forgets the previous stream.</summary>
        public void Restart(GaitBatchRunner target)
        {
            next = 0;
            clock = 0;
            target?.Reset();
        }

        /// <summary>Moves the playback clock on (seconds of recording time) and hands every row that became due to the target.</summary>
        public void Advance(double seconds, GaitBatchRunner target)
        {
            if (target == null || data.Samples.Count == 0) return;
            clock += seconds;
            while (next < data.Samples.Count && due[next] <= clock)
            {
                var row = data.Samples[next++];
                LastRow = row;
                target.Push(row.Imu);
            }
            if (Finished && Loop) Restart(target);
        }
    }
}
