using System;
using System.Collections.Generic;

namespace HeadGait
{
    public sealed class PreprocessorSettings
    {
        /// <summary>Rate of the resampled grid the classifiers work on (Hz).</summary>
        public double SampleRate = 100.0;

        /// <summary>Samples per window (50 at 100 Hz = 0.5 s): the first window comes once this many are in.</summary>
        public int WindowLength = 50;

        /// <summary>
        /// Samples of history each window carries (at least <see cref="WindowLength"/>); a classifier that looks further
        /// back than the window (COR's slowest steps) reads <see cref="SignalWindow.Count"/> valid ones.
        /// </summary>
        public int History = 50;

        /// <summary>Standard gravity subtracted from the signal magnitude vector (m/s^2).</summary>
        public double Gravity = 9.80665;

        /// <summary>
        /// Longest hole between two input samples that is bridged by interpolation (seconds). A longer
        /// hole empties the window: the next window is emitted only after WindowLength fresh samples.
        /// </summary>
        public double MaxGap = 0.1;

        /// <summary>Input samples whose magnitude exceeds this (m/s^2) are treated as corrupt and skipped.</summary>
        public double MaxMagnitude = 200.0;

        /// <summary>
        /// A sample further ahead of the stream's clock than this (s), or further behind than <see cref="BackwardTolerance"/>,
        /// is held as suspect: one glitched timestamp must not become the clock that every later sample is measured by.
        /// </summary>
        public double SuspectJump = 1.0;

        /// <summary>Backward steps up to this (s) are late samples and skipped; longer ones are a clock that restarted.</summary>
        public double BackwardTolerance = DefaultBackwardTolerance;

        /// <summary>The default <see cref="BackwardTolerance"/>, shared by the sources and the pose estimator in front of the pipeline.</summary>
        public const double DefaultBackwardTolerance = 0.1;

        /// <summary>Suspect samples that must follow each other like a stream (each within MaxGap) before the stream re-bases on them.</summary>
        public int RebaseSamples = 3;

        /// <summary>
        /// The lowest input rate that makes windows (Hz): samples at most <see cref="MaxGap"/> apart (10 Hz by default); a slower
        /// stream is all holes, gets a warning once and leaves the avatar standing.
        /// </summary>
        public double LowestRate => 1.0 / MaxGap;

        /// <summary>
        /// Largest timestamp magnitude whose double still resolves 1 % of a grid step (about 4.5e11 s at 100 Hz; an epoch in
        /// seconds is 1.7e9). Beyond it neighbouring samples share or skip timestamps (1.7e15, epoch microseconds read as seconds,
        /// resolves only 0.25 s): such samples are refused with a warning once.
        /// </summary>
        public double MaxResolvableTime => 0.01 / SampleRate * 4503599627370496.0; // 2^52 spacings per binade

        public PreprocessorSettings Clone() => (PreprocessorSettings)MemberwiseClone();

        public void Validate()
        {
            if (!(SampleRate > 0) || double.IsInfinity(SampleRate)) throw new ArgumentException("SampleRate must be positive.");
            if (WindowLength < 2) throw new ArgumentException("WindowLength must be at least 2.");
            if (History > 100000) throw new ArgumentException("History must be at most 100000 samples.");
            if (!(MaxGap > 0)) throw new ArgumentException("MaxGap must be positive.");
            if (!(Gravity >= 0)) throw new ArgumentException("Gravity must not be negative.");
            if (!(SuspectJump >= MaxGap)) throw new ArgumentException("SuspectJump must be at least MaxGap.");
            if (!(BackwardTolerance >= 0)) throw new ArgumentException("BackwardTolerance must not be negative.");
            if (RebaseSamples < 1 || RebaseSamples > 100) throw new ArgumentException("RebaseSamples must be 1..100.");
        }
    }

    /// <summary>What the preprocessor did with one input sample.</summary>
    public enum SampleOutcome
    {
        Accepted,
        /// <summary>Accepted, but it followed a hole longer than MaxGap: the window restarted.</summary>
        AcceptedAfterGap,
        SkippedNotFinite,
        SkippedOutOfOrder,
        SkippedDuplicateTime,
        SkippedImplausible,
        /// <summary>Held back: its time is far from the stream's clock; it counts only if the next samples agree with it.</summary>
        SkippedSuspectTime,
        /// <summary>Accepted as the first sample of a new time base that the following samples confirmed: the window restarted.</summary>
        AcceptedAfterRebase,
        /// <summary>Refused: its timestamp is too large for a double to resolve the grid (<see cref="PreprocessorSettings.MaxResolvableTime"/>).</summary>
        SkippedCoarseClock,
    }

    /// <summary>
    /// Streaming front end: takes head accelerometer samples at any (irregular) rate, linearly resamples
    /// them to a fixed grid (100 Hz), computes SMV minus gravity and the head-frame channels, and emits a
    /// sliding window (50 samples, step 1) for every grid sample once the window is full.
    /// Bad samples (NaN/infinite, repeated timestamps, absurd magnitudes) are skipped and counted, never thrown on.
    /// The clock policy: a sample slightly behind (late) is skipped; a hole up to <see cref="PreprocessorSettings.SuspectJump"/>
    /// restarts the window; a sample far ahead or far behind is held as suspect and the stream re-bases on it only when
    /// <see cref="PreprocessorSettings.RebaseSamples"/> samples in a row agree with it, so neither a single glitched
    /// timestamp nor a restarted clock freezes the stream.
    /// </summary>
    public sealed class StreamPreprocessor
    {
        readonly PreprocessorSettings settings;
        readonly double[] smvRing;
        readonly double[] latRing;
        readonly double[] fwdRing;
        readonly double[] vertRing;
        readonly SignalWindow window;
        readonly double dt;

        bool hasPrevious;
        ImuSample previous;
        readonly ImuSample[] suspects;
        int suspectCount;
        double previousSmv;
        long gridIndex;       // index of the next grid sample to produce, relative to gridOrigin
        double gridOrigin;    // time of grid index 0
        long filled;          // samples in the ring since the last (re)start
        double lastSeen = double.NaN; // the last finite timestamp pushed, accepted or not: how far apart the samples come
        double lastInterval;
        int holesInARow;              // samples in a row that came more than MaxGap after the one before
        string warning;               // a clock or rate problem not yet taken by TakeWarning
        bool warnedCoarse, warnedSlow;

        public StreamPreprocessor() : this(new PreprocessorSettings()) { }

        public StreamPreprocessor(PreprocessorSettings settings)
        {
            this.settings = settings ?? throw new ArgumentNullException(nameof(settings));
            settings.Validate();
            int capacity = Math.Max(settings.WindowLength, settings.History);
            smvRing = new double[capacity];
            latRing = new double[capacity];
            fwdRing = new double[capacity];
            vertRing = new double[capacity];
            window = new SignalWindow(capacity, settings.SampleRate) { KeepsRhythm = true };
            suspects = new ImuSample[settings.RebaseSamples];
            dt = 1.0 / settings.SampleRate;
        }

        public PreprocessorSettings Settings => settings;

        public int SkippedNotFinite { get; private set; }
        public int SkippedOutOfOrder { get; private set; }
        public int SkippedDuplicateTime { get; private set; }
        public int SkippedImplausible { get; private set; }
        public int SkippedSuspectTime { get; private set; }
        /// <summary>Samples refused because their timestamps were too large to resolve the grid (see <see cref="PreprocessorSettings.MaxResolvableTime"/>).</summary>
        public int SkippedCoarseClock { get; private set; }

        /// <summary>
        /// True while samples come further apart than <see cref="PreprocessorSettings.MaxGap"/> (<see cref="PreprocessorSettings.RebaseSamples"/>
        /// holes in a row): slower than <see cref="PreprocessorSettings.LowestRate"/>, no window is made.
        /// </summary>
        public bool BelowLowestRate => holesInARow >= settings.RebaseSamples;

        /// <summary>The clock or rate problems met so far, in words (empty when none): kept for <see cref="DescribeSkips"/>.</summary>
        public string Problems { get; private set; } = "";

        /// <summary>
        /// A clock or rate problem met since the last call, in words, or null: each kind is reported once per preprocessor
        /// (a timestamp too coarse for the grid; a stream slower than the lowest rate), for the caller to log once.
        /// </summary>
        public string TakeWarning()
        {
            string w = warning;
            warning = null;
            return w;
        }

        void Warn(string text)
        {
            warning = warning == null ? text : warning + "; " + text;
            Problems = Problems.Length == 0 ? text : Problems + "; " + text;
        }
        /// <summary>Times the stream moved to a new time base that its samples agreed on.</summary>
        public int Rebases { get; private set; }
        public int Gaps { get; private set; }
        public int Accepted { get; private set; }

        public int Skipped => SkippedNotFinite + SkippedOutOfOrder + SkippedDuplicateTime + SkippedImplausible + SkippedSuspectTime + SkippedCoarseClock;

        /// <summary>
        /// What the clock policy skipped and why, for a person reading a replay ("12 out of time order, 1 not finite"), with
        /// the holes and re-bases it met; empty when it took every sample.
        /// </summary>
        public string DescribeSkips()
        {
            var parts = new List<string>();
            void Add(int count, string what) { if (count > 0) parts.Add($"{count} {what}"); }
            Add(SkippedOutOfOrder, "out of time order");
            Add(SkippedDuplicateTime, "with a repeated time");
            Add(SkippedSuspectTime, "far off the stream's clock (a jump no later sample followed)");
            Add(SkippedNotFinite, "not finite");
            Add(SkippedImplausible, $"beyond {settings.MaxMagnitude:0} m/s^2");
            Add(SkippedCoarseClock, "with a timestamp too large to resolve");
            string skipped = parts.Count > 0 ? $"skipped {Skipped} sample(s): {string.Join(", ", parts)}" : "";
            string holes = Gaps > 0 || Rebases > 0 ? $"{Gaps} hole(s), {Rebases} clock re-base(s)" : "";
            string text = skipped.Length > 0 && holes.Length > 0 ? skipped + "; " + holes : skipped + holes;
            return Problems.Length == 0 ? text : text.Length == 0 ? Problems : text + "; " + Problems;
        }

        public void Reset()
        {
            hasPrevious = false;
            lastSeen = double.NaN;
            holesInARow = 0;
            suspectCount = 0;
            filled = 0;
            gridIndex = 0;
        }

        public double Smv(in ImuSample s) => s.Magnitude - settings.Gravity;

        /// <summary>Feeds one input sample; <paramref name="onWindow"/> is called for every full window it completes.</summary>
        public SampleOutcome Push(in ImuSample sample, Action<SignalWindow> onWindow)
        {
            if (!sample.IsFinite)
            {
                SkippedNotFinite++;
                return SampleOutcome.SkippedNotFinite;
            }
            double mag = sample.Magnitude;
            if (mag > settings.MaxMagnitude)
            {
                SkippedImplausible++;
                return SampleOutcome.SkippedImplausible;
            }
            double smv = mag - settings.Gravity;
            if (!ResolvesGrid(sample.Time))
            {
                SkippedCoarseClock++;
                return SampleOutcome.SkippedCoarseClock;
            }
            NoteInterval(sample.Time);

            if (!hasPrevious)
            {
                Start(sample, smv, onWindow);
                Accepted++;
                return SampleOutcome.Accepted;
            }
            double step = sample.Time - previous.Time;
            if (step > settings.SuspectJump || step < -settings.BackwardTolerance) return Suspect(sample, onWindow);
            if (step < 0)
            {
                SkippedOutOfOrder++;
                return SampleOutcome.SkippedOutOfOrder;
            }
            if (step == 0)
            {
                SkippedDuplicateTime++;
                return SampleOutcome.SkippedDuplicateTime;
            }
            // The stream's own clock goes on: whatever was held as suspect was a glitch (already counted).
            suspectCount = 0;
            if (step > settings.MaxGap * (1 + 1e-9)) // a stream at exactly the lowest rate is no hole
            {
                Gaps++;
                Start(sample, smv, onWindow);
                Accepted++;
                return SampleOutcome.AcceptedAfterGap;
            }

            // Produce every grid sample in (previous.Time, sample.Time] by linear interpolation.
            double span = sample.Time - previous.Time;
            while (true)
            {
                double t = gridOrigin + gridIndex * dt;
                if (t > sample.Time + 1e-9) break;
                double a = (t - previous.Time) / span;
                if (a < 0) a = 0;
                if (a > 1) a = 1;
                double s = previousSmv + a * (smv - previousSmv);
                Emit(t, s, previous.X + a * (sample.X - previous.X), previous.Y + a * (sample.Y - previous.Y),
                    previous.Z + a * (sample.Z - previous.Z), onWindow);
            }
            previous = sample;
            previousSmv = smv;
            Accepted++;
            return SampleOutcome.Accepted;
        }

        /// <summary>False (and a warning once) for a timestamp whose double cannot resolve 1 % of a grid step.</summary>
        bool ResolvesGrid(double time)
        {
            double limit = settings.MaxResolvableTime;
            if (Math.Abs(time) <= limit) return true;
            if (!warnedCoarse)
            {
                warnedCoarse = true;
                Warn(string.Format(System.Globalization.CultureInfo.InvariantCulture,
                    "timestamps near {0:G3} s are refused: a double there cannot tell samples {1:0.#} ms apart (it resolves only {2:G2} s); stamp samples in seconds from a recent origin such as start-up (an epoch in microseconds or nanoseconds read as seconds?); the avatar stands",
                    time, 1000 / settings.SampleRate, Spacing(time)));
            }
            return false;
        }

        /// <summary>Distance from |t| to the next larger double.</summary>
        static double Spacing(double t)
        {
            double a = Math.Abs(t);
            return BitConverter.Int64BitsToDouble(BitConverter.DoubleToInt64Bits(a) + 1) - a;
        }

        /// <summary>Counts holes in a row; the third makes the stream slower than the lowest rate (a warning once).</summary>
        void NoteInterval(double time)
        {
            double interval = time - lastSeen;
            lastSeen = time;
            if (!(interval > 0)) return; // first, repeated or backwards: says nothing about the rate
            lastInterval = interval;
            if (interval <= settings.MaxGap * (1 + 1e-9))
            {
                holesInARow = 0;
                return;
            }
            holesInARow++;
            if (holesInARow >= settings.RebaseSamples && !warnedSlow)
            {
                warnedSlow = true;
                Warn(string.Format(System.Globalization.CultureInfo.InvariantCulture,
                    "samples come {0:G3} s apart ({1:G3} Hz), slower than the lowest rate of {2:G3} Hz (at most {3:G3} s apart): no window can be made and the avatar stands{4}",
                    lastInterval, 1 / lastInterval, settings.LowestRate, settings.MaxGap,
                    lastInterval >= 5 ? " (timestamps in milliseconds or microseconds rather than seconds?)" : ""));
            }
        }

        /// <summary>Holds a sample far from the stream's clock; re-bases once enough follow it like a stream.</summary>
        SampleOutcome Suspect(in ImuSample sample, Action<SignalWindow> onWindow)
        {
            if (suspectCount > 0)
            {
                double step = sample.Time - suspects[suspectCount - 1].Time;
                if (!(step > 0 && step <= settings.MaxGap)) suspectCount = 0;
            }
            suspects[suspectCount++] = sample;
            if (suspectCount < settings.RebaseSamples)
            {
                SkippedSuspectTime++;
                return SampleOutcome.SkippedSuspectTime;
            }
            // The held samples agree: they are the clock now. Restart on the first and replay the rest.
            int held = suspectCount;
            suspectCount = 0;
            Rebases++;
            SkippedSuspectTime -= held - 1;
            var first = suspects[0];
            Start(first, Smv(first), onWindow);
            Accepted++;
            for (int i = 1; i < held; i++) Push(suspects[i], onWindow);
            return SampleOutcome.AcceptedAfterRebase;
        }

        void Start(in ImuSample sample, double smv, Action<SignalWindow> onWindow)
        {
            hasPrevious = true;
            previous = sample;
            previousSmv = smv;
            filled = 0;
            gridOrigin = sample.Time;
            gridIndex = 0;
            Emit(sample.Time, smv, sample.X, sample.Y, sample.Z, onWindow);
        }

        /// <summary>The ring from slot <paramref name="start"/> on, oldest first: two block copies.</summary>
        static void Unroll(double[] ring, int start, double[] window)
        {
            int tail = ring.Length - start;
            Array.Copy(ring, start, window, 0, tail);
            Array.Copy(ring, 0, window, tail, start);
        }

        void Emit(double t, double smv, double forward, double lateral, double vertical, Action<SignalWindow> onWindow)
        {
            int n = smvRing.Length;
            int slot = (int)(filled % n);
            smvRing[slot] = smv;
            latRing[slot] = lateral;
            fwdRing[slot] = forward;
            vertRing[slot] = vertical;
            filled++;
            gridIndex++;
            if (filled < settings.WindowLength) return;
            // Unroll the ring oldest-first into the window (slots not yet filled after a restart are zeros).
            int start = (int)(filled % n);
            Unroll(smvRing, start, window.Smv);
            Unroll(latRing, start, window.Lateral);
            Unroll(fwdRing, start, window.Forward);
            Unroll(vertRing, start, window.Vertical);
            for (int i = 0; i < n - filled; i++) window.Smv[i] = window.Lateral[i] = window.Forward[i] = window.Vertical[i] = 0;
            window.EndTime = t;
            window.EndIndex = filled - 1;
            window.Count = (int)Math.Min(filled, n);
            window.Refilled();
            onWindow?.Invoke(window);
        }
    }
}
