using System;

namespace HeadGait.Unity
{
    /// <summary>
    /// Plays a <see cref="Recording"/> into a <see cref="GaitBatchRunner"/> in real time (the logic behind
    /// <see cref="RecordingPlayer"/>). Every start from the top is a new stream for the runner: it is reset, so the
    /// recording's timestamps, which jump back to the beginning, are not rejected as late against the previous pass.
    /// </summary>
    public sealed class RecordingPlayback
    {
        readonly Recording data;
        readonly double firstTime;
        int next;
        double clock;

        public RecordingPlayback(Recording data)
        {
            this.data = data ?? throw new ArgumentNullException(nameof(data));
            firstTime = data.Samples.Count > 0 ? data.Samples[0].Imu.Time : 0;
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
            while (next < data.Samples.Count && data.Samples[next].Imu.Time - firstTime <= clock)
            {
                var row = data.Samples[next++];
                LastRow = row;
                target.Push(row.Imu);
            }
            if (Finished && Loop) Restart(target);
        }
    }
}
