namespace HeadGait
{
    /// <summary>
    /// The latest <see cref="Length"/> resampled samples, oldest first: SMV minus gravity and the head-frame
    /// lateral (y), forward (x) and vertical (z) acceleration. The preprocessor reuses one instance: copy what you keep.
    /// </summary>
    public sealed class SignalWindow
    {
        public SignalWindow(int length, double sampleRate)
        {
            Smv = new double[length];
            Lateral = new double[length];
            Forward = new double[length];
            Vertical = new double[length];
            SampleRate = sampleRate;
            Count = length;
        }

        /// <summary>Signal magnitude vector minus gravity, m/s^2, oldest first.</summary>
        public double[] Smv { get; }

        /// <summary>Lateral (head y, left positive) acceleration, m/s^2, oldest first.</summary>
        public double[] Lateral { get; }

        /// <summary>Forward (head x) acceleration, m/s^2, oldest first.</summary>
        public double[] Forward { get; }

        /// <summary>Vertical (head z, up positive) specific force, m/s^2, oldest first.</summary>
        public double[] Vertical { get; }

        public int Length => Smv.Length;

        /// <summary>
        /// Valid samples at the end of the window. Below <see cref="Length"/> only while a stream (re)starts and the window
        /// carries more history than the preprocessor's window length; the older slots are then zeros.
        /// </summary>
        public int Count { get; internal set; }

        public double SampleRate { get; }

        /// <summary>Time of the newest sample in the window (seconds).</summary>
        public double EndTime { get; internal set; }

        /// <summary>Index of the newest sample on the resampled grid since the stream (or the last gap) began.</summary>
        public long EndIndex { get; internal set; }

        /// <summary>
        /// The step rhythm read of this fill of the window (<see cref="StepRhythm.Of"/>) and the level tolerance it was read
        /// at: the rhythm hold, the step clock and the walking gate ask for the same window's rhythm, and it is the costliest
        /// read. Kept only in the window the preprocessor fills, which forgets it on every fill (<see cref="Refilled"/>);
        /// one filled by hand may change unseen.
        /// </summary>
        internal bool KeepsRhythm;
        internal bool HasRhythm;
        internal double? RhythmTolerance;
        internal StepRhythm Rhythm;

        /// <summary>The samples changed: forget the rhythm read of the last fill.</summary>
        internal void Refilled() => HasRhythm = false;

        /// <summary>
        /// Fills this window with <paramref name="source"/>'s newest (<see cref="Length"/> - 1) x <paramref name="timeScale"/>
        /// grid steps, linearly interpolated, its newest sample the source's newest: a stretch read <paramref name="timeScale"/>
        /// times as fast (a learned model's wearer time scale). Before the source's oldest sample it reads that sample, and
        /// <see cref="Count"/> says how many of this window's samples came from valid source samples.
        /// </summary>
        public void FillTimeScaled(SignalWindow source, double timeScale)
        {
            if (!(timeScale > 0)) throw new System.ArgumentOutOfRangeException(nameof(timeScale), "A time scale must be positive.");
            int n = Length, last = source.Length - 1;
            for (int j = 0; j < n; j++)
            {
                double x = last - (n - 1 - j) * timeScale;
                int i = (int)System.Math.Floor(x);
                double f = x - i;
                if (i < 0)
                {
                    i = 0;
                    f = 0;
                }
                int k = System.Math.Min(i + 1, last);
                Smv[j] = source.Smv[i] + f * (source.Smv[k] - source.Smv[i]);
                Lateral[j] = source.Lateral[i] + f * (source.Lateral[k] - source.Lateral[i]);
                Forward[j] = source.Forward[i] + f * (source.Forward[k] - source.Forward[i]);
                Vertical[j] = source.Vertical[i] + f * (source.Vertical[k] - source.Vertical[i]);
            }
            EndTime = source.EndTime;
            EndIndex = source.EndIndex;
            Count = System.Math.Max(0, System.Math.Min(n, (int)System.Math.Floor((System.Math.Min(source.Count, source.Length) - 1) / timeScale) + 1));
            Refilled();
        }

        public SignalWindow Clone()
        {
            var w = new SignalWindow(Length, SampleRate) { EndTime = EndTime, EndIndex = EndIndex, Count = Count };
            System.Array.Copy(Smv, w.Smv, Length);
            System.Array.Copy(Lateral, w.Lateral, Length);
            System.Array.Copy(Forward, w.Forward, Length);
            System.Array.Copy(Vertical, w.Vertical, Length);
            return w;
        }
    }
}
