using System;

namespace HeadGait
{
    /// <summary>What <see cref="HeadTilt.Follow"/> read of a window: the tilt's movement, and the bend from the last still head.</summary>
    public readonly struct HeadTiltReading
    {
        public HeadTiltReading(double change, double bendFromStill, double sinceStill)
        {
            Change = change;
            BendFromStill = bendFromStill;
            SinceStill = sinceStill;
        }

        /// <summary>Degrees the head's tilt moved over the newest <see cref="HeadTilt.Span"/> seconds.</summary>
        public double Change { get; }

        /// <summary>Degrees the head's pitch (with <see cref="HeadTilt.BendInRoll"/>, its whole direction of gravity) lies from the last still head's (<see cref="HeadTilt.FollowStill"/>); 0 before one.</summary>
        public double BendFromStill { get; }

        /// <summary>Seconds since the head was last read still (infinite before that).</summary>
        public double SinceStill { get; }

        /// <summary>Whether the head's pitch lies more than <paramref name="maxBend"/> degrees from the still head's (0: never).</summary>
        public bool Bends(double maxBend) => maxBend > 0 && BendFromStill > maxBend;

        /// <summary>
        /// Whether the head bends as to the floor from a head still lately: its pitch lies more than
        /// <see cref="HeadTilt.BendStartBend"/> degrees from a still head's read within <see cref="HeadTilt.BendStartStillRecent"/>
        /// seconds (<see cref="StepClockSettings.BendStartContacts"/>).
        /// </summary>
        public bool BendsForStart => SinceStill <= HeadTilt.BendStartStillRecent && Bends(HeadTilt.BendStartBend);
    }

    /// <summary>
    /// The still-head start rules. One for all four classifiers (<see cref="StepClockSettings.StillStartMaxBend"/>,
    /// <see cref="PhaseFilterSettings.StillStartMaxBend"/>): a walk that starts within <see cref="HeadTilt.StillRecent"/>
    /// seconds of a still head does not start, and is withdrawn within <see cref="HeadTilt.StillStartProbation"/> seconds
    /// of its start, while the head's pitch lies more than the limit from the still head's (<see cref="HeadTiltReading.Bends"/>).
    /// For the step clock also whether a walk starts soon after the head bent from a still head (<see cref="BentBefore"/>,
    /// <see cref="StepClockSettings.BendStartContacts"/>).
    /// </summary>
    public sealed class StillStartGuard
    {
        double walkStart = double.NaN; // when the walk under way started; NaN while standing

        /// <summary>Whether the walk under way (or, while standing, one starting now) starts from a still head.</summary>
        public bool FromStill { get; private set; }

        public void Reset()
        {
            FromStill = false;
            walkStart = double.NaN;
            bentFrom = double.PositiveInfinity;
            bentTo = earlierBentTo = double.NegativeInfinity;
            lastFollowed = double.NaN;
        }

        /// <summary>
        /// Follows a window's <paramref name="reading"/>: while standing (<paramref name="walking"/> false), whether a walk
        /// starting now starts from a still head; while walking, the walk's start (<see cref="Started"/>, where not dated
        /// yet). Returns whether the rule refuses: the start while standing (<see cref="RefusesStart"/>), the walk under
        /// way while walking.
        /// </summary>
        public bool Refuses(HeadTiltReading reading, bool walking, double now, double maxBend)
        {
            if (!walking)
            {
                FromStill = reading.SinceStill <= HeadTilt.StillRecent;
                walkStart = double.NaN;
                return RefusesStart(reading, maxBend);
            }
            Started(now);
            return FromStill && now - walkStart < HeadTilt.StillStartProbation && reading.Bends(maxBend);
        }

        /// <summary>A walk began at <paramref name="now"/> (the first call after standing counts).</summary>
        public void Started(double now)
        {
            if (double.IsNaN(walkStart)) walkStart = now;
        }

        /// <summary>Whether a walk starting now, from a still head (<see cref="FromStill"/>), is refused.</summary>
        public bool RefusesStart(HeadTiltReading reading, double maxBend) => FromStill && reading.Bends(maxBend);

        // The newest two runs of windows bent from a recent still head (HeadTiltReading.BendsForStart): a walk's start
        // lies up to a step before the window that starts it, and a bend after it does not count.
        double bentFrom = double.PositiveInfinity, bentTo = double.NegativeInfinity, earlierBentTo = double.NegativeInfinity;
        double lastFollowed = double.NaN;

        /// <summary>Follows every window's <paramref name="reading"/> for <see cref="BentBefore"/>.</summary>
        public void FollowBend(HeadTiltReading reading, double now)
        {
            if (reading.BendsForStart)
            {
                if (!(bentTo == lastFollowed))
                {
                    earlierBentTo = bentTo;
                    bentFrom = now;
                }
                bentTo = now;
            }
            lastFollowed = now;
        }

        /// <summary>
        /// Whether the head bent from a recent still head (<see cref="HeadTiltReading.BendsForStart"/>) within the
        /// <see cref="HeadTilt.BendStartRecent"/> seconds before <paramref name="start"/> (<see cref="StepClockSettings.BendStartContacts"/>).
        /// </summary>
        public bool BentBefore(double start)
            => bentFrom <= start && bentTo >= start - HeadTilt.BendStartRecent
                || earlierBentTo <= start && earlierBentTo >= start - HeadTilt.BendStartRecent;
    }

    /// <summary>
    /// How far the head's tilt moved lately: bending down to pick something up and straightening again bumps the head like
    /// a step, and all four classifiers refuse a walk's start while it moves (<see cref="StepClockSettings.MaxStartTiltChange"/>
    /// for THR and COR, <see cref="PhaseFilterSettings.MaxStartTiltChange"/> for the SVM and BLSTM). Read every
    /// <see cref="EveryWindows"/> windows (<see cref="Follow"/>): it changes slowly, and a reading costs.
    /// </summary>
    public sealed class HeadTilt
    {
        /// <summary>Span over which the tilt's movement is read (s).</summary>
        public const double Span = 2.0;

        /// <summary>Windows between two readings.</summary>
        public const int EveryWindows = 10;

        /// <summary>
        /// Most the head's tilt may have moved over the newest <see cref="Span"/> seconds for a walk to start (degrees), and
        /// beyond which a walk in progress stops (a walker who bends down to the floor has stopped walking); chosen on the
        /// real glasses (see <see cref="StepClockSettings.MaxStartTiltChange"/> and the measurements log).
        /// </summary>
        public const double DefaultMaxStartChange = 25, DefaultMaxWalkingChange = 45;

        /// <summary>
        /// A walk that began less than this before the tilt moved past the start limit is withdrawn (s; about a step): the
        /// reading's half-second means lag the bend, and a bend's first bump started walks the limit then found already
        /// under way. On the real glasses (avatar), picking up shown as walking SVM / BLSTM 4.5 / 3.6 % without, 3.5 / 3.3 %
        /// at 0.5 and at 1; walking shown 90.6 / 86.9 % without, 90.5 / 86.9 % at 0.5, 90.3 / 86.8 % at 1 (see the
        /// measurements log).
        /// </summary>
        public const double YoungWalk = 0.5;

        /// <summary>Most spread (standard deviation, m/s^2) of SMV over a half second read for the head's tilt (<see cref="ChangeOver"/>).</summary>
        public const double MaxSmvSpread = 5;

        /// <summary>
        /// The head is still when SMV spreads (standard deviation) at most <see cref="StillMaxSpread"/> m/s^2 over
        /// <see cref="StillSpan"/> seconds ending <see cref="StillGap"/> seconds before now (<see cref="FollowStill"/>): a
        /// first step and the start of a bend both move the newest half second. A walk that starts within
        /// <see cref="StillRecent"/> seconds of such a reading starts from a still head, and for
        /// <see cref="StillStartProbation"/> seconds its pitch is compared with the still head's, over the newest
        /// <see cref="BendMean"/> seconds (a step's push and brake swing a shorter mean's pitch by up to 9 degrees on the
        /// generated walkers) (<see cref="StepClockSettings.StillStartMaxBend"/>). Chosen on the real glasses
        /// (see the measurements log): of COR's walks there that start after a still second, its walking files hold 1 in
        /// 734 starts, its picking-up files 46 in 108.
        /// </summary>
        public const double StillSpan = 1.0, StillGap = 0.5, StillMaxSpread = 0.3, StillRecent = 0.3, StillStartProbation = 1.0, BendMean = 0.3;

        /// <summary>
        /// Most the head's pitch may move from a still head's within <see cref="StillStartProbation"/> of a walk's start
        /// (degrees; <see cref="StepClockSettings.StillStartMaxBend"/>, <see cref="PhaseFilterSettings.StillStartMaxBend"/>).
        /// </summary>
        public const double DefaultStillStartMaxBend = 10;

        /// <summary>
        /// A walk that starts within <see cref="MoveStartRecent"/> seconds of the tilt's movement (<see cref="Change"/>) reading
        /// more than <see cref="MoveStartChange"/> degrees waits for more contacts (<see cref="StepClockSettings.TiltMoveStartContacts"/>):
        /// the head coming back up from the floor. Chosen on the real glasses (in-sample; see the measurements log): for COR
        /// with 3 contacts, 35 degrees cost walking shown 0.4 point (worst tenth 82.4 to 79.8 %) and 3 s its worst tenth 1.2
        /// points, where 40 degrees and 2 s cost none.
        /// </summary>
        public const double MoveStartChange = 40, MoveStartRecent = 2;

        /// <summary>
        /// A walk that starts within <see cref="BendStartRecent"/> seconds of the head's pitch lying more than
        /// <see cref="BendStartBend"/> degrees from a still head's read within <see cref="BendStartStillRecent"/> seconds
        /// (<see cref="HeadTiltReading.BendsForStart"/>) waits for more contacts (<see cref="StepClockSettings.BendStartContacts"/>):
        /// the head bent down to the floor from standing, and the first bump after it is rarely a first step. Chosen on the
        /// real glasses (in-sample; see the measurements log): for COR (rule alone), 20 / 25 degrees within 2 s cost walking
        /// shown 1.2 / 0.8 points, 30 degrees 0.1; 3 s caught more than 2. As shipped it costs COR 0.4 point: two walkers
        /// who look 30-40 degrees down as they stop and set off again, their walks shown a step later each time.
        /// </summary>
        public const double BendStartBend = 30, BendStartRecent = 3, BendStartStillRecent = 4;

        int countdown;
        double stillPitch;                        // the last still head's pitch (radians)
        double stillForward, stillLeft, stillUp;  // the last still head's direction of gravity (unit), for BendInRoll
        double stillSeen = double.NegativeInfinity;

        /// <summary>Degrees the head's tilt moved over the newest <see cref="Span"/> seconds, at the last reading.</summary>
        public double Change { get; private set; }

        /// <summary>What the last reading read (<see cref="HeadTiltReading"/>).</summary>
        public HeadTiltReading Reading { get; private set; }

        public void Reset()
        {
            countdown = 0;
            Change = 0;
            stillSeen = double.NegativeInfinity;
            Reading = new HeadTiltReading(0, 0, double.PositiveInfinity);
        }

        public HeadTilt() => Reset();

        /// <summary>
        /// Whether the bend from the still head (<see cref="HeadTiltReading.BendFromStill"/>) is the angle between the whole
        /// directions of gravity, pitch and roll, rather than the pitch's alone (the default: bending to the floor pitches
        /// the head, and a step's sway rolls a short mean by a few degrees). Used by the SVM and BLSTM
        /// (<see cref="PhaseFilterSettings.StillStartBendInRoll"/>). Both are kept of every still head, so it may change at any window.
        /// </summary>
        public bool BendInRoll { get; set; }

        /// <summary>
        /// Reads the tilt from <paramref name="window"/> every <see cref="EveryWindows"/> windows (call it for every window, in
        /// order); with <paramref name="still"/>, also the still head (<see cref="FollowStill"/>), its bend every window.
        /// </summary>
        public void Follow(SignalWindow window, bool still = false)
        {
            bool read = countdown-- <= 0;
            if (read)
            {
                countdown = EveryWindows - 1;
                Change = ChangeOver(window, Span);
            }
            if (still) FollowStill(window, read);
            else if (read) Reading = new HeadTiltReading(Change, 0, double.PositiveInfinity);
        }

        /// <summary>
        /// Reads whether the head is still (<see cref="StillSpan"/>; with <paramref name="readStill"/>: it changes slowly, and
        /// a reading costs) and keeps a still head's direction of gravity; and, every call, how far the head's pitch over the
        /// newest <see cref="BendMean"/> seconds lies from it, into
        /// <see cref="Reading"/> (with <see cref="Change"/> as last read). A bend is caught at the window it passes the limit,
        /// before a contact between two readings could start a walk the next reading would withdraw.
        /// </summary>
        public void FollowStill(SignalWindow window, bool readStill = true)
        {
            double now = window.EndTime;
            if (readStill && StillDirection(window, StillSpan, StillGap, StillMaxSpread, out double forward, out double lateral, out double vertical))
            {
                stillPitch = Math.Atan2(forward, vertical);
                stillSeen = now;
                double norm = Math.Sqrt(forward * forward + lateral * lateral + vertical * vertical);
                stillForward = forward / norm;
                stillLeft = lateral / norm;
                stillUp = vertical / norm;
            }
            double bend = 0;
            if (!double.IsNegativeInfinity(stillSeen) && NewestSums(window, BendMean, out double f, out double l, out double u))
            {
                if (!BendInRoll)
                    bend = f * f + u * u > 1e-12 ? Degrees(Math.Atan2(f, u) - stillPitch) : 0;
                else
                {
                    double norm = Math.Sqrt(f * f + l * l + u * u);
                    if (norm > 1e-9) bend = Math.Acos(Math.Max(-1, Math.Min(1, (f * stillForward + l * stillLeft + u * stillUp) / norm))) * 180 / Math.PI;
                }
            }
            Reading = new HeadTiltReading(Change, bend, now - stillSeen);
        }

        /// <summary>
        /// The head-frame acceleration summed over the window's newest <paramref name="seconds"/>: its pitch (the direction of
        /// gravity in the forward-vertical plane; only the pitch as a rule, as bending to the floor tilts the head forwards and
        /// a step's sway would add its roll) or its whole direction (<see cref="BendInRoll"/>); false where the window holds
        /// too few samples.
        /// </summary>
        static bool NewestSums(SignalWindow w, double seconds, out double forward, out double lateral, out double vertical)
        {
            forward = lateral = vertical = 0;
            int n = Math.Max(1, (int)Math.Round(seconds * w.SampleRate));
            if (n > Math.Min(w.Count, w.Length)) return false;
            for (int i = w.Length - n; i < w.Length; i++)
            {
                forward += w.Forward[i];
                lateral += w.Lateral[i];
                vertical += w.Vertical[i];
            }
            return true;
        }

        /// <summary>The size of an angle's difference in degrees (0-180), from radians.</summary>
        static double Degrees(double radians)
        {
            double d = Math.Abs(radians) % (2 * Math.PI);
            return (d > Math.PI ? 2 * Math.PI - d : d) * 180 / Math.PI;
        }

        /// <summary>
        /// Whether the head was still over <paramref name="seconds"/> ending <paramref name="gap"/> seconds before the
        /// window's end (SMV's standard deviation at most <paramref name="maxSpread"/>), and its mean acceleration then
        /// forwards, to the left and upwards (head frame). False where the window holds too few samples.
        /// </summary>
        public static bool StillDirection(SignalWindow w, double seconds, double gap, double maxSpread, out double forward, out double lateral, out double vertical)
        {
            forward = lateral = vertical = 0;
            int n = (int)Math.Round(seconds * w.SampleRate), end = w.Length - (int)Math.Round(gap * w.SampleRate);
            if (n < 2 || end - n < w.Length - Math.Min(w.Count, w.Length)) return false;
            double smv = 0, smv2 = 0;
            for (int i = end - n; i < end; i++)
            {
                forward += w.Forward[i];
                lateral += w.Lateral[i];
                vertical += w.Vertical[i];
                smv += w.Smv[i];
                smv2 += w.Smv[i] * w.Smv[i];
            }
            smv /= n;
            forward /= n;
            lateral /= n;
            vertical /= n;
            return smv2 / n - smv * smv <= maxSpread * maxSpread && forward * forward + vertical * vertical > 1e-12;
        }

        /// <summary>
        /// Degrees between the most and the least tilted gravity direction (0.5-s means of the head-frame acceleration
        /// against its vertical axis, every 0.1 s) over the window's newest <paramref name="seconds"/>. A half second whose
        /// SMV spreads more than <see cref="MaxSmvSpread"/> holds no steady direction of gravity (knocks, a glitching
        /// sensor) and is left out: a hostile stream's junk otherwise refused the start of the clean walk after it for 2 s.
        /// </summary>
        public static double ChangeOver(SignalWindow w, double seconds)
        {
            int mean = Math.Max(1, (int)Math.Round(0.5 * w.SampleRate)), hop = Math.Max(1, (int)Math.Round(0.1 * w.SampleRate));
            int span = Math.Min(Math.Min(w.Count, w.Length), (int)Math.Round(seconds * w.SampleRate));
            if (span < mean) return 0;
            double least = double.PositiveInfinity, most = double.NegativeInfinity;
            for (int end = w.Length; end - mean >= w.Length - span; end -= hop)
            {
                double x = 0, y = 0, z = 0, smv = 0, smv2 = 0;
                for (int i = end - mean; i < end; i++)
                {
                    x += w.Forward[i];
                    y += w.Lateral[i];
                    z += w.Vertical[i];
                    smv += w.Smv[i];
                    smv2 += w.Smv[i] * w.Smv[i];
                }
                smv /= mean;
                if (smv2 / mean - smv * smv > MaxSmvSpread * MaxSmvSpread) continue;
                double norm = Math.Sqrt(x * x + y * y + z * z);
                if (norm <= 1e-9) continue;
                double tilt = Math.Acos(Math.Max(-1, Math.Min(1, z / norm))) * 180 / Math.PI;
                least = Math.Min(least, tilt);
                most = Math.Max(most, tilt);
            }
            return most >= least ? most - least : 0;
        }
    }
}
