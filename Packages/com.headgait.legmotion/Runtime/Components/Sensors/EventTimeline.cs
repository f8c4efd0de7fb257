namespace HeadGait.Unity
{
    /// <summary>
    /// Keeps one source's event times increasing: an event stamped at the last accepted time (a duplicate delivered twice)
    /// or a little before it (one that arrives late) is refused, so each sample reaches the pipeline once. A step further
    /// back is a clock that restarted: it is passed on, and the pipeline's clock policy re-bases on it once the samples
    /// agree, so a source never refuses everything after its clock moved back.
    /// </summary>
    public sealed class EventTimeline
    {
        double last = double.NegativeInfinity;

        public int Duplicates { get; private set; }
        public int OutOfOrder { get; private set; }
        public int NotFinite { get; private set; }
        public int ClockRestarts { get; private set; }

        public bool Accept(double time)
        {
            if (double.IsNaN(time) || double.IsInfinity(time))
            {
                NotFinite++;
                return false;
            }
            if (time == last)
            {
                Duplicates++;
                return false;
            }
            if (time < last)
            {
                if (last - time <= PreprocessorSettings.DefaultBackwardTolerance)
                {
                    OutOfOrder++;
                    return false;
                }
                ClockRestarts++;
            }
            last = time;
            return true;
        }

        public void Reset() => last = double.NegativeInfinity;
    }
}
