using System;

namespace HeadGait
{
    /// <summary>
    /// Whether the newest 2.5 s keep a walking rhythm, however calm: SMV repeats at a step period of 0.35-0.9 s, the head
    /// sways to the other side with each step (the lateral acceleration one step apart is anti-correlated) and back with
    /// each stride (correlated two steps apart), and the forward acceleration repeats with the step. Only the shape counts,
    /// not the size, so a slow walker with little bounce, whom the <see cref="WalkingGate"/>'s spreads take for gesturing,
    /// keeps walking once two strides show it; a wave or a bow sways the head without that pairing of step and stride.
    /// Reads a copy of the window averaged down to about 50 Hz (plenty for rhythms under 3 Hz, and a quarter of the work).
    /// </summary>
    public readonly struct StepRhythm
    {
        /// <summary>History it reads (grid samples at 100 Hz): two strides of the slowest walker it looks for, and some.</summary>
        public const int HistorySamples = 250;

        /// <summary>Step periods it searches (s).</summary>
        public const double ShortestStep = 0.35, LongestStep = 0.9;

        /// <summary>
        /// Least autocorrelation of SMV at the step period, most of the lateral one step apart, least of the lateral two steps
        /// apart and of the forward one step apart. In the real training recordings (every style's walking, their gestures, bows
        /// and standing, 2.5-s windows), these pass 52 % of the calm *feminine* style's walking windows and 0.2 % of the standing
        /// ones (one waving clip); leave-one-style-out choice on a grid picked looser values (-0.3, 0 instead of -0.4, 0.2) that
        /// passed 0.16 % of the held-out standing, and the stricter ones are kept.
        /// </summary>
        public const double MinBounce = 0.3, MaxSway = -0.4, MinStride = 0.2, MinForward = 0.2;

        /// <summary>
        /// Least spread of SMV over the newest step (<see cref="Period"/>), as a share of its spread over the whole 2.5 s: a walk
        /// that has just stopped still shows its rhythm in the older samples, and without this kept the legs walking up to 1.7 s
        /// after the generated start-stop walks stopped (0.13 s with it; standing shown as walking there rose from 8 to 18 % for
        /// COR). Every real walking window with the rhythm keeps it; half a second instead of a step held one stop for 1.5 s.
        /// </summary>
        public const double MinRecentSpread = 0.6;

        const double AnalysisRate = 50;

        StepRhythm(double period, double bounce, double sway, double stride, double forward, double recentSpread)
        {
            Period = period;
            Bounce = bounce;
            Sway = sway;
            Stride = stride;
            Forward = forward;
            RecentSpread = recentSpread;
        }

        /// <summary>The step period (s) where SMV repeats best while the lateral swings back most; 0 when the window holds too little history.</summary>
        public double Period { get; }

        /// <summary>SMV's autocorrelation at <see cref="Period"/>.</summary>
        public double Bounce { get; }

        /// <summary>The lateral acceleration's autocorrelation at <see cref="Period"/> (negative: it sways back with each step).</summary>
        public double Sway { get; }

        /// <summary>The lateral acceleration's autocorrelation at twice <see cref="Period"/> (positive: the stride repeats).</summary>
        public double Stride { get; }

        /// <summary>The forward acceleration's autocorrelation at <see cref="Period"/>.</summary>
        public double Forward { get; }

        /// <summary>SMV's spread over the newest step over its spread over the whole window.</summary>
        public double RecentSpread { get; }

        /// <summary>
        /// Least SMV autocorrelation and most lateral autocorrelation at <see cref="Period"/> for the period to be trusted
        /// as the step's (<see cref="ShowsStepPeriod"/>): looser than walking needs, since it only keeps a detector from
        /// counting two bumps of one step as two steps.
        /// </summary>
        public const double PeriodBounce = 0.2, PeriodSway = -0.2;

        /// <summary>Whether <see cref="Period"/> is clearly the step's: SMV repeats there while the head sways back.</summary>
        public bool ShowsStepPeriod => Period > 0 && Bounce > PeriodBounce && Sway < PeriodSway;

        /// <summary>
        /// Whether the rhythm holds a walk in progress: it shows the step period, into the newest step
        /// (<see cref="StepClockSettings.HoldRecentSpread"/>). The step clock (<see cref="StepClock.HeldByRhythm"/>) and the
        /// learned classifiers' time filter (<see cref="PhaseFilterSettings.HoldOnRhythm"/>) ride out the walking gate's
        /// refusals while it does.
        /// </summary>
        public bool HoldsWalk => ShowsStepPeriod && RecentSpread >= StepClockSettings.HoldRecentSpread;

        public bool IsWalking => Period > 0 && Bounce > MinBounce && Sway < MaxSway && Stride > MinStride && Forward > MinForward
            && RecentSpread >= MinRecentSpread;

        /// <summary>History the rhythm needs at the window's rate.</summary>
        static int HistoryCount(double sampleRate) => (int)Math.Round(HistorySamples * sampleRate / 100);

        /// <summary>
        /// Measures the rhythm over the window's newest 2.5 s, the lateral and forward channels levelled beyond
        /// <paramref name="levelTolerance"/> degrees (<see cref="WindowLevel"/>, over the same span; null: as the head frame gives them). A window with less valid history has no rhythm (<see cref="Period"/> 0).
        /// Measured once per fill of the preprocessor's window and tolerance (<see cref="SignalWindow.Rhythm"/>), however many ask.
        /// </summary>
        public static StepRhythm Of(SignalWindow w, double? levelTolerance = null)
        {
            if (!w.KeepsRhythm) return Measure(w, levelTolerance);
            if (!w.HasRhythm || w.RhythmTolerance != levelTolerance)
            {
                w.Rhythm = Measure(w, levelTolerance);
                w.RhythmTolerance = levelTolerance;
                w.HasRhythm = true;
            }
            return w.Rhythm;
        }

        static StepRhythm Measure(SignalWindow w, double? levelTolerance)
        {
            int need = HistoryCount(w.SampleRate);
            if (need < 4 || Math.Min(w.Count, w.Length) < need) return default;
            int first = w.Length - need;
            int d = Math.Max(1, (int)Math.Round(w.SampleRate / AnalysisRate));
            int n = need / d;
            double rate = w.SampleRate / d;
            int shortest = (int)Math.Ceiling(ShortestStep * rate), longest = (int)Math.Floor(LongestStep * rate);
            if (2 * longest + 2 > n) return default;
            var level = levelTolerance.HasValue ? WindowLevel.Of(w, first, levelTolerance.Value) : WindowLevel.None;
            Span<double> smv = stackalloc double[n];
            Span<double> lateral = stackalloc double[n];
            Span<double> forward = stackalloc double[n];
            int start = w.Length - n * d;
            for (int k = 0; k < n; k++)
            {
                double s = 0, y = 0, x = 0;
                for (int i = start + k * d; i < start + (k + 1) * d; i++)
                {
                    s += w.Smv[i];
                    y += level.Lateral(w, i);
                    x += level.Forward(w, i);
                }
                smv[k] = s / d;
                lateral[k] = y / d;
                forward[k] = x / d;
            }
            // The step is where SMV repeats while the head sways back to the other side. SMV alone also repeats at half a
            // step in walkers whose head bumps twice per step (slow glasses wearers: their SMV's strongest line lies at
            // twice the step rate), and there the lateral has not swung back yet.
            int best = shortest;
            double score = double.NegativeInfinity;
            for (int lag = shortest; lag <= longest; lag++)
            {
                double r = Autocorrelation(smv, lag) - Autocorrelation(lateral, lag);
                if (r > score)
                {
                    score = r;
                    best = lag;
                }
            }
            double bounce = Autocorrelation(smv, best);
            double whole = Spread(smv);
            double recentSpread = whole > 1e-9 ? Spread(smv.Slice(n - best)) / whole : 0;
            return new StepRhythm(best / rate, bounce, Autocorrelation(lateral, best), Autocorrelation(lateral, 2 * best), Autocorrelation(forward, best), recentSpread);
        }

        /// <summary>Standard deviation (population); 0 for fewer than two values.</summary>
        internal static double Spread(ReadOnlySpan<double> x)
        {
            if (x.Length < 2) return 0;
            double m = 0, m2 = 0;
            foreach (var v in x)
            {
                m += v;
                m2 += v * v;
            }
            m /= x.Length;
            return Math.Sqrt(Math.Max(0, m2 / x.Length - m * m));
        }

        /// <summary>Pearson correlation of the signal with itself <paramref name="lag"/> samples later (each part's own mean removed); 0 when flat.</summary>
        internal static double Autocorrelation(ReadOnlySpan<double> x, int lag)
        {
            int m = x.Length - lag;
            if (m < 2) return 0;
            double ma = 0, mb = 0;
            for (int i = 0; i < m; i++)
            {
                ma += x[i];
                mb += x[i + lag];
            }
            ma /= m;
            mb /= m;
            double ab = 0, aa = 0, bb = 0;
            for (int i = 0; i < m; i++)
            {
                double a = x[i] - ma, b = x[i + lag] - mb;
                ab += a * b;
                aa += a * a;
                bb += b * b;
            }
            double norm = Math.Sqrt(aa * bb);
            return norm > 1e-12 ? ab / norm : 0;
        }
    }
}
