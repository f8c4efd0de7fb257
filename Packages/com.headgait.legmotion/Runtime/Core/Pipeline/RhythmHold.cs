using System;

namespace HeadGait
{
    public sealed class RhythmHoldSettings
    {
        /// <summary>Whether a walk is held through the classifier's standing predictions while the head keeps a step rhythm.</summary>
        public bool Enabled = true;

        /// <summary>
        /// Least SMV autocorrelation at the step period, most lateral one step apart and least lateral one stride apart
        /// (<see cref="StepRhythm"/>) for a walk to be held: looser than <see cref="StepRhythm.IsWalking"/> (a walk under way
        /// only has to be kept, and the steps of a turn or of a slow, calm walker repeat less cleanly than a straight
        /// stretch's), as loose as <see cref="StepRhythm.ShowsStepPeriod"/> with the stride still repeating. Not fitted
        /// to the glasses: there (the hold alone, without <see cref="GraceSteps"/>) the looser 0.1 / -0.1 / none held more
        /// of the walking (THR 79.8 to 83.0 %, SVM 86.4 to 89.5 %) but showed more standing and sitting as walking (SVM
        /// standing 1.2 to 1.6 %, BLSTM sitting 0.7 to 1.1 %).
        /// </summary>
        public double MinBounce = StepRhythm.PeriodBounce, MaxSway = StepRhythm.PeriodSway, MinStride = 0;

        /// <summary>
        /// Least SMV autocorrelation at the step period that holds an established walk (<see cref="EstablishedAfter"/>)
        /// whatever the sway, at a step period within <see cref="TurnPeriodShare"/> of the walk's: in a turn the lateral
        /// channel takes in the forward one and no longer swings back (the generated walk with turns: one step apart
        /// -0.4 on the straight, up to +0.3 in the turn, SMV 0.97-0.99 throughout). Not fitted: clearly repeating.
        /// </summary>
        public double TurnBounce = 0.5, TurnPeriodShare = 0.2;

        /// <summary>
        /// SMV spread over the newest step, as a share of the 2.5 s (<see cref="StepRhythm.RecentSpread"/>), under which the
        /// walker has stopped (<see cref="RhythmReading.Stilled"/>) and a held walk gets no <see cref="GraceSteps"/>. Looked
        /// at on the glasses and the generated start-stop walk (realworld, avatar, walking shown THR / COR / SVM / BLSTM;
        /// the generated stops, THR, against no hold): 0.6 (the rhythm's own <see cref="MinRecentSpread"/>): 80.8 / 87.8 /
        /// 87.3 / 83.6 %, stops as without the hold; 0.3: 85.7 / 91.3 / 91.0 / 87.5 %, stops 0.2-0.4 s later; none:
        /// 85.6 / 91.4 / 90.7 / 87.2 %, up to 0.7 s later. The turns and the calm steps of the slower wearers calm the head
        /// over a step to 0.3-0.6 of the walk's movement; a stop calms it further.
        /// </summary>
        public double StilledSpread = 0.3;

        /// <summary>Least SMV spread over the newest step as a share of the 2.5 s: a walk that has stopped lets go (<see cref="StepRhythm.MinRecentSpread"/>).</summary>
        public double MinRecentSpread = StepRhythm.MinRecentSpread;

        /// <summary>Windows between two readings of the rhythm (it changes slowly, and a reading costs).</summary>
        public int RhythmEveryWindows = 5;

        /// <summary>Tilt (degrees) beyond which the rhythm's lateral and forward channels are levelled (<see cref="WindowLevel"/>), as the shipped gates level theirs.</summary>
        public double LevelTolerance = 15;

        /// <summary>
        /// Steps (at the walk's step period) for which an established walk (<see cref="EstablishedAfter"/>) is held after its
        /// rhythm fails while the classifier says standing: the rhythm of a turn or of a slow wearer's calmest steps drops
        /// below <see cref="MinBounce"/> or <see cref="MaxSway"/> for a step or so and comes back. A head that calms over the
        /// newest step (<see cref="RhythmReading.Stilled"/>) has stopped, and gets none. Not fitted: one step. On the real
        /// glasses (`realworld`, avatar; see <see cref="StilledSpread"/>) walking shown THR 79.9 to 85.7 %, COR 87.0 to
        /// 91.3 %, SVM 86.4 to 91.0 %, BLSTM 82.7 to 87.5 %, still activities unchanged; a grace of 0.3 s without
        /// <see cref="EstablishedAfter"/> raised picking up shown as walking from 15.1 to 25.3 % (COR).
        /// </summary>
        public double GraceSteps = 1;

        /// <summary>
        /// Seconds a walk has been shown (by the classifier, or held) before <see cref="GraceSteps"/> applies: the rhythm's
        /// span (<see cref="StepRhythm.HistorySamples"/>), so its reading is of this walk alone. The classifier's false
        /// walks in still activities last well under a second (picking up: 0.3-0.5 s on the glasses), and are not prolonged.
        /// </summary>
        public double EstablishedAfter = StepRhythm.HistorySamples / 100.0;

        /// <summary>
        /// Seconds after an established walk let go (its rhythm and grace ran out, the head not stilled) within which a walk
        /// the classifier starts is that walk resumed: established at once, so its grace and turn hold apply. In a 180-degree
        /// turn the hold carries the walk until the 2.5 s it reads hold only the turn, which is as the walk back begins; the
        /// classifier's first walk there is young and let go at its first refusal (the glasses' up-and-go: COR's walk back
        /// restarted and dropped twice, shown 1.8 s after its first step). Not fitted: the rhythm's span
        /// (<see cref="EstablishedAfter"/>). The glasses (`realworld`, avatar, THR / COR / SVM / BLSTM): walking shown 92.9 /
        /// 92.0 / 94.4 / 93.9 to 93.9 / 93.7 / 95.5 / 95.2 % (worst tenth 83.2 / 82.0 / 88.5 / 83.2 to 87.3 / 83.9 / 90.1 /
        /// 85.9), fragments 7 / 12 / 9 / 9 to 6 / 9 / 7 / 7, standing, sitting and picking up the same to the last digit (no
        /// established walk comes before their false walks). 0: off.
        /// </summary>
        public double ResumeWithin = StepRhythm.HistorySamples / 100.0;

        public RhythmHoldSettings Clone() => (RhythmHoldSettings)MemberwiseClone();
    }

    /// <summary>What <see cref="RhythmHold.Observe"/> read of the head's rhythm.</summary>
    public readonly struct RhythmReading
    {
        public RhythmReading(bool holds, double period, bool stilled = false, bool repeats = false)
        {
            Holds = holds;
            Period = period;
            Stilled = stilled;
            Repeats = repeats || holds;
        }

        /// <summary>SMV repeats clearly at <see cref="Period"/> (<see cref="RhythmHoldSettings.TurnBounce"/>), whatever the head's sway.</summary>
        public bool Repeats { get; }

        /// <summary>The head has calmed over the newest step (<see cref="StepRhythm.RecentSpread"/> under the hold's least): the walker stopped.</summary>
        public bool Stilled { get; }

        /// <summary>A walk under way may be held on it.</summary>
        public bool Holds { get; }

        /// <summary>Its step period (s); 0 with too little history.</summary>
        public double Period { get; }
    }

    /// <summary>
    /// Between the classifier and the animator: while a walk is under way, a standing prediction is replaced by the walk's
    /// own stride clock run on at the rhythm's step period, as long as the newest 2.5 s keep a step rhythm
    /// (<see cref="StepRhythm"/>: SMV repeating at the step period while the head sways to the other side each step), and
    /// in a walk shown for longer than that span, for a further step after the rhythm fails. Whatever the classifier,
    /// its walks break up in turns and at a slow wearer's calm steps, where the head moves as little as a standing
    /// wearer's looking around; only the rhythm's shape counts, not its size. The hold only keeps a walk, never starts
    /// one: the rhythm alone shows in 6-9 % of the glasses' standing and sitting time, but rarely right after the
    /// classifier's own false walks there, which are short.
    /// </summary>
    public sealed class RhythmHold
    {
        readonly RhythmHoldSettings settings;
        readonly PhaseMap map;
        readonly StanceLatch stance = new StanceLatch();
        bool walking;              // the last prediction passed on was walking
        double lastTime, lastPosition, lastPeriod;
        int windowsSinceReading = int.MaxValue;
        RhythmReading reading;
        double failingSince = double.NaN; // while holding: when the rhythm began to fail (NaN: it holds)
        double walkStart;                 // when the walk being shown began
        double letGoAt = double.NaN;      // when the last established walk let go with the head still moving (NaN: none, or a stop)

        public RhythmHold(PhaseMap map, RhythmHoldSettings settings = null)
        {
            this.map = map ?? PhaseMap.Perry;
            this.settings = settings ?? new RhythmHoldSettings();
        }

        public RhythmHoldSettings Settings => settings;

        /// <summary>History the rhythm reads (grid samples at 100 Hz).</summary>
        public int History => settings.Enabled ? StepRhythm.HistorySamples : 0;

        /// <summary>Windows passed on as walking that the classifier called standing, since the last reset.</summary>
        public long HeldWindows { get; private set; }

        /// <summary>Forgets the walk being held (the stream restarted).</summary>
        public void Reset()
        {
            walking = false;
            letGoAt = double.NaN;
            stance.Reset();
        }

        /// <summary>Forgets the last rhythm reading, so the next window is read (the stream restarted; called when the restart is seen, before any window after it).</summary>
        public void ForgetRhythm()
        {
            windowsSinceReading = int.MaxValue;
            reading = default;
        }

        /// <summary>
        /// Whether the head keeps a rhythm a walk may be held on, as of <paramref name="window"/>: read every
        /// <see cref="RhythmHoldSettings.RhythmEveryWindows"/> windows (call it for every window, in order), the last reading in between.
        /// </summary>
        public RhythmReading Observe(SignalWindow window)
        {
            if (!settings.Enabled) return default;
            if (windowsSinceReading >= settings.RhythmEveryWindows)
            {
                var r = StepRhythm.Of(window, settings.LevelTolerance);
                bool moving = r.Period > 0 && r.RecentSpread >= settings.MinRecentSpread;
                reading = new RhythmReading(Holds(r), r.Period, r.Period > 0 && r.RecentSpread < settings.StilledSpread, moving && r.Bounce > settings.TurnBounce);
                windowsSinceReading = 0;
            }
            windowsSinceReading++;
            return reading;
        }

        /// <summary>
        /// The prediction the animator gets for a window whose classifier said <paramref name="p"/> and whose rhythm
        /// <see cref="Observe"/> read as <paramref name="rhythm"/>.
        /// </summary>
        public GaitPrediction Apply(GaitPrediction p, RhythmReading rhythm)
        {
            if (!settings.Enabled) return p;
            if (p.IsWalking)
            {
                Remember(p);
                stance.Reset();
                return p;
            }
            if (!walking) return p;
            if (!(p.Time >= lastTime))
            {
                walking = false;
                letGoAt = double.NaN;
                return p;
            }
            bool established = p.Time - walkStart >= settings.EstablishedAfter;
            // In a turn the head yaws and the lateral channel takes in the forward one, which repeats every step: the sway
            // no longer swings back, while SMV keeps repeating at the walk's own step period.
            bool turning = established && rhythm.Repeats && Math.Abs(rhythm.Period - lastPeriod) <= settings.TurnPeriodShare * lastPeriod;
            bool holds = rhythm.Holds || turning;
            if (!holds)
            {
                if (double.IsNaN(failingSince)) failingSince = p.Time;
                if (!established || rhythm.Stilled || p.Time - failingSince >= settings.GraceSteps * lastPeriod)
                {
                    letGoAt = established && !rhythm.Stilled ? p.Time : double.NaN;
                    walking = false;
                    return p;
                }
            }
            else failingSince = double.NaN;
            // The rhythm's period is the step's (the lag where SMV repeats while the head sways back); the classifier's
            // last one may be half a step (a slow wearer's second head bump: COR steps shown per step 1.14 to 1.12).
            double period = holds && rhythm.Period > 0 ? rhythm.Period : lastPeriod;
            double position = PhaseMap.Wrap(lastPosition + (p.Time - lastTime) / (2 * period));
            lastPeriod = period;
            var held = GaitPrediction.Walking(p.Time, position, period, 0, map, stance);
            lastTime = p.Time;
            lastPosition = position;
            HeldWindows++;
            return held;
        }

        void Remember(GaitPrediction p)
        {
            // A walk started soon after an established one let go is that walk resumed (ResumeWithin), its start kept.
            if (!walking && !(p.Time - letGoAt <= settings.ResumeWithin)) walkStart = p.Time;
            walking = true;
            failingSince = double.NaN;
            lastTime = p.Time;
            lastPosition = p.StridePosition;
            if (p.StepPeriod > 0) lastPeriod = p.StepPeriod;
            else if (!(lastPeriod > 0)) lastPeriod = 0.55;
        }

        bool Holds(StepRhythm r) => r.Period > 0 && r.Bounce > settings.MinBounce && r.Sway < settings.MaxSway && r.Stride > settings.MinStride
            && r.RecentSpread >= settings.MinRecentSpread;
    }
}
