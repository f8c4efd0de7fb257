namespace HeadGait.Unity
{
    /// <summary>
    /// Keeps one source's event times strictly increasing: an event stamped at or before the last accepted one (a
    /// duplicate delivered twice, or one that arrives late) is refused, so each sample reaches the pipeline once.
    /// </summary>
    public sealed class EventTimeline
    {
        double last = double.NegativeInfinity;

        public int Duplicates { get; private set; }
        public int OutOfOrder { get; private set; }
        public int NotFinite { get; private set; }

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
                OutOfOrder++;
                return false;
            }
            last = time;
            return true;
        }

        public void Reset() => last = double.NegativeInfinity;
    }
}
