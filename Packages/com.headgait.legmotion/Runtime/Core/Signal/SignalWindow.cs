namespace HeadGait
{
    /// <summary>
    /// The latest <see cref="Length"/> resampled samples, oldest first: SMV minus gravity and the
    /// lateral (head y) acceleration. The preprocessor reuses one instance: copy what you keep.
    /// </summary>
    public sealed class SignalWindow
    {
        public SignalWindow(int length, double sampleRate)
        {
            Smv = new double[length];
            Lateral = new double[length];
            SampleRate = sampleRate;
        }

        /// <summary>Signal magnitude vector minus gravity, m/s^2, oldest first.</summary>
        public double[] Smv { get; }

        /// <summary>Lateral (head y, left positive) acceleration, m/s^2, oldest first.</summary>
        public double[] Lateral { get; }

        public int Length => Smv.Length;

        public double SampleRate { get; }

        /// <summary>Time of the newest sample in the window (seconds).</summary>
        public double EndTime { get; internal set; }

        /// <summary>Index of the newest sample on the resampled grid since the stream (or the last gap) began.</summary>
        public long EndIndex { get; internal set; }

        public SignalWindow Clone()
        {
            var w = new SignalWindow(Length, SampleRate) { EndTime = EndTime, EndIndex = EndIndex };
            System.Array.Copy(Smv, w.Smv, Length);
            System.Array.Copy(Lateral, w.Lateral, Length);
            return w;
        }
    }
}
