using System;
using System.Collections.Generic;

namespace HeadGait
{
    public sealed class StepClockSettings
    {
        /// <summary>Contacts closer than this to the previous one are the same footfall (s).</summary>
        public double MinStepInterval = 0.3;

        /// <summary>
        /// Once the walk's step period is measured, a contact sooner than this share of it after the previous one is a
        /// second bump of the same step, not a step: a calm walker's SMV can peak twice per step (the second corpus's
        /// *feminine* style does), and once slowed down both peaks lie further apart than <see cref="MinStepInterval"/>.
        /// Leave-one-style-out, THR: held-out clips 40 % slower and calmer (dynamic part over 1.4^2, sideways and forwards
        /// a further 0.7) 48.0 to 44.3 % (0.7: 44.1 %), ear-like 34.0 to 33.1 %, as recorded 24.5 to 24.4 %, walks made
        /// to start and stop unchanged; COR, which searches only around the period, within 0.1 point. 0 turns it off.
        /// </summary>
        public double MinStepShare = 0.6;

        /// <summary>
        /// A contact sooner than this share of the step period the head's rhythm shows (<see cref="StepRhythm"/>, over the
        /// newest 2.5 s, where it shows one: <see cref="StepRhythm.ShowsStepPeriod"/>) after the previous one is a second bump of the same step. The measured period
        /// (<see cref="MinStepShare"/>) cannot tell: when the first interval of a walk is a bump's, the period starts at half a
        /// step and every bump after it passes. Slow glasses wearers' heads bump twice per step: on the real glasses walking
        /// files, steps shown per step of the signal fell from THR 1.25 and COR 1.13 (see the measurements log). 0 turns it off.
        /// </summary>
        public double RhythmStepShare = 0.6;

        /// <summary>
        /// The clock's step period is set to the head's rhythm's (where it shows one) whenever it lies further than this
        /// ratio from it, either way. A period measured between a step and its second bump (half a step) or across a
        /// missed step (two) otherwise stands until a clean interval comes: slow glasses wearers' legs then stepped at
        /// twice their pace and stopped after 1.5 of those half periods, before the next real step came. On the real glasses
        /// walking files, steps shown per step of the signal THR 1.15 to 1.12, COR 1.09 to 1.03. 0 turns it off.
        /// </summary>
        public double RhythmPeriodRatio = 1.3;

        /// <summary>
        /// Whether a walk in progress rides out the walking gate's refusals while the head's rhythm shows the step
        /// (<see cref="StepClock.HeldByRhythm"/>), and goes on across missed contacts for up to <see cref="RhythmHoldPeriods"/>.
        /// Real glasses walking shown THR 74.6 to 84.5 %, COR 82.0 to 89.0 %, fragments per walking file 36 to 21 and 43 to
        /// 28 (COR riding out the gate at any pace; see <see cref="HoldMinRhythmPeriod"/>; the measurements log has the steps).
        /// </summary>
        public bool HoldOnRhythm = true;

        /// <summary>
        /// Least spread of SMV over the newest step, as a share of its spread over the rhythm's 2.5 s, for the rhythm to hold
        /// a walk (<see cref="StepRhythm.RecentSpread"/>): a walk that has stopped still shows its rhythm in the older samples.
        /// Lower than the walking gate's <see cref="StepRhythm.MinRecentSpread"/> (0.6), since the step the hold carries
        /// over is the soft one the detector missed. Glasses walking shown (THR / COR) 86.0 / 89.6 % at 0.3, 85.3 / 89.3 %
        /// at 0.45, 83.8 / 88.3 % at 0.6; the generated recordings (`replay`, whose walks stop dead) 17.8 / 18.0, 17.4 /
        /// 17.3 and 17.1 / 17.0 % (16.9 / 17.0 % without the hold): lower keeps the legs walking longer after a stop.
        /// </summary>
        public const double HoldRecentSpread = 0.45;

        /// <summary>
        /// Shortest step period (s) of the head's rhythm at which it rides out the walking gate's refusals
        /// (<see cref="StepClock.HeldByRhythm"/>; 0: any). COR sets 0.75: riding them out at any pace, the synthetic calm
        /// wearer of the calibration tests (0.67-s steps) was shown 29.8 → 32.3 % wrong and its calibration no longer paid;
        /// on the real glasses COR then showed 89.3 % of the walking, 85.4 % at 0.75 and 82.4 % without the ride-out
        /// (alternating feet 96.9 / 97.0 / 97.3 %). THR keeps 0 (at 0.75: 85.3 → 78.3 %, steps per step 1.07 → 1.11).
        /// </summary>
        public double HoldMinRhythmPeriod = 0;

        /// <summary>While the head's rhythm shows the step, standing is reported once no contact came for this many step periods (a missed contact or two).</summary>
        public double RhythmHoldPeriods = 3.5;

        /// <summary>
        /// Most the head's tilt may have moved over the newest <see cref="HeadTilt.Span"/> seconds for a walk to start (degrees).
        /// Bending down to pick something up and straightening again bumps the head like a step. On the real glasses the
        /// tilt moves more than 25 degrees in 2 s in 43 % of the picking-up time, 8 % of the walking, 6 % of standing and
        /// 4 % of sitting with head movement; only starts are refused. Picking up shown as walking, THR / COR: 5.0 / 16.5 %
        /// without, 3.8 / 13.1 % at 40, 3.0 / 8.5 % at 25; walking shown 84.5 / 89.0 % without, 83.8 / 88.3 % at 25 (see
        /// the measurements log). 0 turns it off.
        /// </summary>
        public double MaxStartTiltChange = HeadTilt.DefaultMaxStartChange;

        /// <summary>
        /// Whether a walk starts only where the walking gate's regression scores the window as walking: a gate that listens
        /// for the head's rhythm (<see cref="WalkingGate.UsesStepRhythm"/>) also passes windows the regression refuses, and
        /// those go on carrying a walk under way, but no longer start one. Sitting and picking things up keep a step-like
        /// rhythm now and then (the real glasses: 2.3 and 5.0 % of their time). Real glasses (realworld, avatar), THR:
        /// sitting with head movement shown as walking 1.1 to 0.5 %, picking up 3.1 to 2.3 %, walking 90.2 to 89.7 %;
        /// COR: 0.7 to 0.6 %, 7.2 to 7.1 %, 92.8 to 92.6 %; standing unchanged (1.1, 2.0 %). A start margin on the score
        /// costs more walking (see the measurements log).
        /// </summary>
        public bool StartNeedsGateScore = true;

        /// <summary>
        /// Seconds back the walking gate's regression may have scored walking for <see cref="StartNeedsGateScore"/> (0: the
        /// window itself). A slow, calm walker's gate score dips below 0 at each heel strike (the second it reads holds
        /// the quiet stretch before it) and is above 0 a step's fraction earlier and later: asked at the crossing alone,
        /// THR never started a generated walk slowed 40 % and showed the slowest real styles slowed as standing for most of their walk.
        /// </summary>
        public double StartGateScoreWithin = 0;

        /// <summary>
        /// A walk in progress stops when the head's tilt moves more than this over the newest <see cref="HeadTilt.Span"/> seconds
        /// (degrees): a walker who bends down to the floor has stopped walking. 0 turns it off.
        /// </summary>
        public double MaxWalkingTiltChange = HeadTilt.DefaultMaxWalkingChange;

        /// <summary>
        /// A walk that starts from a still head (<see cref="HeadTilt.FollowStill"/>) does not start, and is withdrawn within
        /// <see cref="HeadTilt.StillStartProbation"/> seconds of its start, while the head's pitch lies more than this many
        /// degrees from the still head's: bending down to the floor begins with a bump like a first step, and the head
        /// then pitches on down, where a first step moves it a few degrees. Real glasses (realworld, avatar), 10 against off:
        /// picking up shown as walking THR 2.3 to 2.0 %, COR 7.1 to 4.9 %; walking 89.7 to 89.4 %, 92.6 to 92.4 % (a few
        /// walkers pitch their head 10 degrees as they set off; see the measurements log). 0 turns it off.
        /// </summary>
        public double StillStartMaxBend = HeadTilt.DefaultStillStartMaxBend;

        /// <summary>
        /// Contacts a walk that starts from a still head (<see cref="HeadTilt.FollowStill"/>, read while
        /// <see cref="StillStartMaxBend"/> is on) after <see cref="StillStartContactsAfterStanding"/> seconds without a walk
        /// takes before it is shown, its start (a contact, or a whole step recognised in one window) counted. The clock walks
        /// meanwhile, unseen, so the contact search follows its step as a shown walk's and the walk is shown with the phase
        /// and foot it has without the rule (kept standing instead, COR searched every step length, found a generated
        /// walker's next contacts up to a third of a stride off and `replay` went 16.9 to 20.7 % wrong). Standing still, then
        /// a bump like a step, is how most of COR's false walks in still activities began, and they rarely took a second
        /// step. 0 or 1: as any walk (<see cref="ContactsToStart"/>). COR ships 3: real glasses (realworld, avatar, in-sample)
        /// standing / sitting / picking up shown as walking 1.7 / 0.5 / 4.9 % with none, 1.2 / 0.3 / 3.8 % with 2 (when
        /// measured; 0.95 / 0.28 / 1.62 % with 2 after later rules), 0.63 / 0.23 / 1.39 % with 3 (people held out 0.94 / 0.28 /
        /// 1.88 to 0.62 / 0.23 / 1.60 %); walking 92.0 % with 2 and 3, its worst tenth, starts and fragments the same; the timed
        /// up-and-go's walking 79.8 to 79.3 %; `replay` unchanged (its walks start within 5 s of the stream's start). 3 with
        /// <see cref="StillStartContactsAfterStanding"/> 8: picking up 2.4 %.
        /// THR ships 2 (its first contact starts a walk otherwise, <see cref="ThresholdSettings.Clock"/>): standing /
        /// sitting / picking up 1.0 / 0.4 / 2.0 to 0.7 / 0.2 / 1.5 % (leave one person out 0.9 / 0.4 / 2.2 to 0.7 / 0.2 /
        /// 1.7 %), walking 90.7 %, its starts and the timed up-and-go unchanged.
        /// </summary>
        public int StillStartContacts = 0;

        /// <summary>
        /// Seconds without a walk shown before <see cref="StillStartContacts"/> applies, counted from the clock's first
        /// still-head reading when it has shown none: a walker who pauses, head still, and walks on starts as before (glasses
        /// walking files: 2 s cost COR 0.9 points of walking shown, 3 s and more none; 8 s and more let more false walks through).
        /// </summary>
        public double StillStartContactsAfterStanding = 5;

        /// <summary>
        /// Contacts a walk that starts within <see cref="HeadTilt.MoveStartRecent"/> seconds of the head's tilt moving more
        /// than <see cref="HeadTilt.MoveStartChange"/> degrees over <see cref="HeadTilt.Span"/> takes before it is shown, its
        /// start counted (unseen meanwhile, as <see cref="StillStartContacts"/>). The tilt's start limit
        /// (<see cref="MaxStartTiltChange"/>) refuses starts while the head bends; most of what was left of COR's false walks
        /// in the picking-up files started as it came back up, and took one or two contacts. 0 or 1: as any walk. COR ships 3:
        /// real glasses (realworld, avatar, in-sample) picking up / standing shown as walking 3.8 / 1.2 to 2.4 / 1.1 % (leave
        /// one person out 4.1 / 1.2 to 2.6 / 1.1 %), walking 92.4 % both; but standing up from the chair moves the tilt as
        /// much, and the timed up-and-go's walking shown fell 85.1 to 82.6 % (2 contacts: picking up 2.9 %, the timed
        /// up-and-go 83.8 %). THR ships 2: once it showed a resumed walk from its first step (<see cref="FirstStep"/>) its
        /// picking up sat at the limit of 2 % with people held out (1.96 %; 2.0 % with the same files at 200 Hz); with 2,
        /// 1.96 to 0.99 % (in-sample 1.73 to 0.97 %), walking shown 93.0 % either way, the timed up-and-go's walking shown
        /// 84.1 to 83.0 % (3: picking up 0.79 %, the timed up-and-go 82.3 %).
        /// </summary>
        public int TiltMoveStartContacts = 0;

        /// <summary>
        /// Contacts a walk that starts within <see cref="HeadTilt.BendStartRecent"/> seconds of the head bending more than
        /// <see cref="HeadTilt.BendStartBend"/> degrees from a still head (<see cref="HeadTiltReading.BendsForStart"/>, read
        /// while <see cref="StillStartMaxBend"/> is on) takes before it is shown, its start counted (unseen meanwhile, as
        /// <see cref="StillStartContacts"/>): picking something up from standing, where the walk, if any, starts as the head
        /// comes up (or, for a walker who looks at the floor as he stops and sets off, a step later). 0 or 1: as any walk.
        /// COR ships 2 on top of its other rules: real glasses (realworld, avatar, in-sample) picking up / standing shown as
        /// walking 2.4 / 1.1 to 1.7 / 0.9 % (leave one person out 2.6 / 1.1 to 1.9 / 0.9 %), walking 92.4 to 92.0 % (worst
        /// tenth 82.4 to 82.3 %), the timed up-and-go shown walking 67.3 to 65.9 %. THR keeps 0 (it meets both targets without).
        /// </summary>
        public int BendStartContacts = 0;

        /// <summary>Windows between two readings of the head's rhythm (<see cref="RhythmStepShare"/>): it changes slowly, and a reading costs.</summary>
        public const int RhythmEveryWindows = 10;

        /// <summary>A contact further than this from the previous one starts a new walking bout (s).</summary>
        public double MaxStepInterval = 1.0;

        /// <summary>The real training data's median step (s).</summary>
        public const double TypicalStepPeriod = 0.55;

        /// <summary>Step period assumed until two contacts have been seen (s).</summary>
        public double InitialStepPeriod = TypicalStepPeriod;

        /// <summary>
        /// Weight of each new interval between contacts in the measured step period (the rest stays with the period so
        /// far): one odd interval should not throw the clock, but a walker who speeds up or slows down should be followed
        /// within a step or two. Leave-one-style-out, 0.3 / 0.5 / 0.7: THR 24.5 / 24.1 / 24.2 %, COR 22.9 / 22.9 / 23.5 %;
        /// ear-like THR 32.4 / 31.7 / 31.5 %, slow 41.8 / 40.8 / 40.6 %, start-stop THR 35.7 / 35.2 / 35.0 %, COR 37.4 /
        /// 36.1 / 35.6 %; 0.2: THR 25.0, COR 23.6 %. File CV, 0.3 / 0.5: THR 20.5 / 20.3 %, COR 19.9 % both, start-stop
        /// COR 34.3 / 33.3 %. 1 keeps only the last interval.
        /// </summary>
        public double PeriodWeight = 0.5;

        /// <summary>Standing is reported once no contact came for this many step periods.</summary>
        public double StandingAfterPeriods = 1.5;

        /// <summary>Contacts at step-like intervals needed before walking is reported (1: the first contact starts walking).</summary>
        public int ContactsToStart = 2;

        /// <summary>
        /// How much of the earlier contacts' side evidence carries over per step (0: each contact decides alone). Steps
        /// alternate feet, so a clear earlier contact says which foot the next one is.
        /// </summary>
        public double SideMemory = 0.8;

        /// <summary>
        /// Windows in a row that the walking gate rejects before a walking bout ends. The clock alone would walk on for
        /// StandingAfterPeriods after the last contact; a head that has stopped bouncing says sooner that the walk is over.
        /// </summary>
        public int StopAfterStillWindows = 15;

        /// <summary>
        /// <see cref="StopAfterStillWindows"/> for a walk shown for at least <see cref="EstablishedAfter"/> (0: the same). In a
        /// turn and at a slow wearer's calm steps the gate shuts for longer than 0.15 s while the rhythm no longer shows the
        /// step; false walks in still activities are younger. THR sets 35, looked at on the glasses (in-sample; `realworld`,
        /// avatar, walking shown / worst tenth / slower half): 89.7 / 79.3 / 86.0 % as before, 90.3 / 80.3 / 86.9 % at 25,
        /// 90.9 / 80.4 / 87.7 % at 35, 91.6 / 80.4 / 88.2 % at 50; standing, sitting and picking up shown as walking unchanged
        /// (1.1 / 0.5 / 2.3 %) at each, alternating feet 98.0 to 97.9 %. Leave one person out at 35: 89.9 to 91.0 %, worst
        /// tenth 80.2 to 80.4 %, still activities unchanged. A walk that stops for good is ended by the clock
        /// (<see cref="StandingAfterPeriods"/>) as before: the generated start-stop walks (`replay`) stop no later.
        /// </summary>
        public int EstablishedStopAfterStillWindows = 0;

        /// <summary>Seconds a walk has been shown before <see cref="EstablishedStopAfterStillWindows"/> applies: the rhythm's span (<see cref="StepRhythm.HistorySamples"/>), as for the pipeline's hold (<see cref="RhythmHoldSettings.EstablishedAfter"/>).</summary>
        public double EstablishedAfter = StepRhythm.HistorySamples / 100.0;

        /// <summary>
        /// Gate-refused windows in a row that end a walk shown for <paramref name="walkedFor"/> seconds (NaN: none shown)
        /// stepping at <paramref name="stepPeriod"/> (s; 0: the typical step, <see cref="StillWindowsStepPeriod"/>).
        /// </summary>
        public int StopAfterStillWindowsAfter(double walkedFor, double stepPeriod = 0)
            => ForStep(EstablishedStopAfterStillWindows > 0 && walkedFor >= EstablishedAfter ? EstablishedStopAfterStillWindows : StopAfterStillWindows, stepPeriod);

        /// <summary>
        /// Whether <paramref name="stillWindows"/> gate-refused windows in a row end the walk (<see cref="StopAfterStillWindowsAfter"/>):
        /// at or past the count, not only at it, as the count moves while the refusals go on (a contact changes the step period,
        /// <see cref="StepClock.RefusalStepPeriod"/> drops its stretch when the tilt moves, an established walk takes its own count).
        /// </summary>
        public bool EndsWalk(int stillWindows, double walkedFor, double stepPeriod)
            => stillWindows > 0 && stillWindows >= StopAfterStillWindowsAfter(walkedFor, stepPeriod);

        /// <summary>
        /// The step period (s) the gate-refusal counts (<see cref="StopAfterStillWindows"/>, <see cref="EstablishedStopAfterStillWindows"/>,
        /// <see cref="ContactWhileStillWindows"/>) hold for; a walk stepping slower has them stretched by its period over this
        /// one, as its head lies still between steps for longer. A calm walker slowed down 40 % had the gate shut for more than
        /// 0.15 s in a row 240-300 times per style and for more than 0.35 s 20-110 times, so its walks broke off between steps
        /// and its contacts came too long into a refusal to count. 0 turns it off (the counts hold at any pace).
        /// </summary>
        public double StillWindowsStepPeriod = TypicalStepPeriod;

        /// <summary>
        /// Most the head's tilt may have moved over the newest <see cref="HeadTilt.Span"/> seconds (degrees) for the
        /// gate-refusal counts to stretch with the step period (<see cref="StillWindowsStepPeriod"/>; <see cref="StepClock.RefusalStepPeriod"/>):
        /// a walker stepping slowly and calmly holds the head's tilt, one who bends down to pick something up does not.
        /// 0: they stretch whatever the tilt. COR sets 10 (<see cref="CorrelationSettings.Clock"/>).
        /// </summary>
        public double StillWindowsMaxTiltChange = 0;

        /// <summary>
        /// Seconds from a walk's first contact to its last before its gate-refusal counts stretch with the step period
        /// (<see cref="StillWindowsStepPeriod"/>): the false walks of a waving or gesturing head are young, and stretched they
        /// were shown for longer. 0: at once. COR sets 0.85 (<see cref="CorrelationSettings.Clock"/>).
        /// </summary>
        public double StillWindowsAfterWalked = 0;

        /// <summary><paramref name="windows"/> stretched for a walk stepping at <paramref name="stepPeriod"/> (<see cref="StillWindowsStepPeriod"/>).</summary>
        int ForStep(int windows, double stepPeriod)
            => StillWindowsStepPeriod > 0 && stepPeriod > StillWindowsStepPeriod ? (int)Math.Round(windows * stepPeriod / StillWindowsStepPeriod) : windows;

        /// <summary>
        /// While walking, a contact still counts until the walking gate has rejected this many windows in a row. The gate
        /// can drop single windows of a calm walker, and a contact needing the gate open at that very window lost most of
        /// the steps of the generated walker at half its amplitude; while standing, a contact needs the gate open.
        /// </summary>
        public int ContactWhileStillWindows = 10;

        /// <summary>Whether a contact may count now: the gate is open, or the walk goes on and the gate has been shut only briefly.</summary>
        public bool ContactAllowed(bool gateOpen, bool walking, int stillWindows, double stepPeriod = 0)
            => gateOpen || (walking && stillWindows < ForStep(ContactWhileStillWindows, stepPeriod));

        /// <summary>
        /// Seconds the reported stride position runs ahead of the clock. A contact is only known after it happened, so
        /// phase changes between contacts come out late on average; the trainer measures by how much and sets this.
        /// </summary>
        public double Lead = 0;

        /// <summary>
        /// Seconds of lead added per unit of the natural log of the walker's bounce above <see cref="LeadReferenceBounce"/>
        /// (the detector says what its bounce is: COR SMV's peaks over its matched steps, THR its recent step peaks;
        /// <see cref="StepClock.FollowBounce"/>). A bouncier walker's contacts come out later: held-out, the bouncy *bn act*
        /// walkers' 25 ms late, the calm *bn fem* and *bn mas* 20 and 38 ms early. Learned (<see cref="StepClock.FitBounceLead"/>); 0 keeps the lead fixed.
        /// </summary>
        public double LeadPerLogBounce = 0;

        /// <summary>The bounce at which the lead is <see cref="Lead"/> (m/s^2; the training contacts' median).</summary>
        public double LeadReferenceBounce = DefaultLeadReferenceBounce;

        /// <summary>The reference bounce of files that give none (m/s^2); with no slope it changes nothing.</summary>
        public const double DefaultLeadReferenceBounce = 5;

        /// <summary>Largest <see cref="LeadPerLogBounce"/> accepted (s), and the most the bounce adds to or takes from the lead.</summary>
        public const double MaxLeadPerLogBounce = 0.1, MaxBounceLead = 0.1;

        /// <summary>
        /// Largest step back (share of a stride) the reported stride position does not take: it holds until the clock
        /// catches up. A contact is confirmed a little after it happened, and dating the clock back to it moved the
        /// stride position back by a few hundredths, enough to lift a foot that had just landed back into swing and land
        /// it again: a step counted twice, and the feet's alternation flipped. Leave-one-style-out (THR, COR): step
        /// precision 73.6 and 82.6 % without, 90.4 and 95.3 % at 0.3, right foot 94.5 and 92.0 against 95.9 and 96.6 %,
        /// misclassification 40.9 and 26.7 against 40.0 and 26.5 %; 0.15 held too little, 0.45 froze the legs too long.
        /// </summary>
        public double HoldBack = 0.3;

        /// <summary>
        /// Seconds later the contacts come out on acceleration fitted from tracked poses than on an accelerometer's, beyond
        /// the fit's own lag (<see cref="IGaitClassifier.PoseFitDelay"/>): the fit over 120 ms blunts the heel strike, so a
        /// threshold or a correlation peak is reached later on its rise. On the pose recordings, the fitted SMV lies as far
        /// behind the accelerometer's as the fit's lag says (55.9 against 55.5 ms at 72 Hz, by cross-correlation), but
        /// THR's and COR's contacts come out about 10 ms later. The detectors set their own (COR 10 ms,
        /// <see cref="CorrelationSettings.Clock"/>; THR 0, <see cref="ThresholdSettings.Clock"/>). The accelerometer path
        /// does not use it.
        /// </summary>
        public double PoseFitDelay;

        /// <summary>The provisional start on a walk's first contact (<see cref="FirstStepStartSettings"/>; off unless the detector sets it).</summary>
        public FirstStepStartSettings FirstStep = new FirstStepStartSettings();

        public StepClockSettings Clone()
        {
            var c = (StepClockSettings)MemberwiseClone();
            c.FirstStep = FirstStep.Clone();
            return c;
        }
    }

    /// <summary>
    /// Turns detected foot contacts into a stride position: contacts alternate feet (which one is decided by the lateral
    /// evidence of this and earlier contacts), the step period follows the intervals between them, and between contacts the
    /// stride position advances at that period. Shared by THR and COR, which differ only in how they detect a contact.
    /// </summary>
    public sealed class StepClock
    {
        readonly StepClockSettings settings;
        readonly PhaseMap map;
        readonly StanceLatch stance = new StanceLatch();
        readonly FirstStepStart firstStep;
        double lastWalking = double.NegativeInfinity; // when a walk was last predicted
        double shownFrom = double.NaN;                // when the walk being predicted began (NaN while standing is)
        double lastShownFor;                          // how long the last walk predicted lasted (s)
        double lastContact;
        double period;
        double sideEvidence;
        int contactsInBout;
        double boutStart = double.NaN; // the walk's first contact (or start); StillWindowsAfterWalked counts from it
        bool periodMeasured;
        Foot lastFoot;
        double reported = double.NaN; // the stride position last predicted; NaN after standing
        double rhythmPeriod;          // the step period of the head's rhythm; 0 when it shows none
        bool rhythmGoesOn;            // whether that rhythm reaches into the newest step
        double lastRhythmPeriod;      // the last step period the rhythm showed (kept through turns and stops); 0 before one
        int rhythmCountdown;
        readonly HeadTilt tilt = new HeadTilt(); // the tilt's movement and the last still head, read with the rhythm
        readonly StillStartGuard still = new StillStartGuard(); // the still-head start rule (StillStartMaxBend)
        double firstSeen;             // the first still-head reading's time (StillStartContactsAfterStanding counts from it); NaN before
        int hiddenContacts;           // contacts a walk still needs before it is shown (StillStartContacts, TiltMoveStartContacts, BendStartContacts)
        double tiltMoved;             // when the head's tilt last read a move past HeadTilt.MoveStartChange
        double lastGateScore;         // when the walking gate's regression last scored walking (StartGateScoreWithin)

        public StepClock(PhaseMap map, StepClockSettings settings = null)
        {
            this.map = map ?? throw new ArgumentNullException(nameof(map));
            this.settings = settings ?? new StepClockSettings();
            if (!(this.settings.PeriodWeight > 0 && this.settings.PeriodWeight <= 1)) throw new ArgumentException("PeriodWeight must be more than 0 and at most 1.");
            firstStep = new FirstStepStart(this.settings.FirstStep);
            Reset();
        }

        public StepClockSettings Settings => settings;
        public double StepPeriod => period;
        public double LastContactTime => lastContact;
        public Foot LastFoot => lastFoot;

        /// <summary>Whether the step period comes from an interval between two contacts of this bout, not from a guess.</summary>
        public bool PeriodMeasured => periodMeasured;

        public void Reset()
        {
            lastContact = double.NegativeInfinity;
            period = settings.InitialStepPeriod;
            sideEvidence = 0;
            contactsInBout = 0;
            periodMeasured = false;
            lastFoot = Foot.Left;
            reported = double.NaN;
            stance.Reset();
            BounceLead = 0;
            rhythmPeriod = 0;
            rhythmGoesOn = false;
            lastRhythmPeriod = 0;
            rhythmCountdown = 0;
            firstStep.Reset();
            lastWalking = double.NegativeInfinity;
            shownFrom = double.NaN;
            lastShownFor = 0;
            tilt.Reset();
            still.Reset();
            hiddenContacts = 0;
            firstSeen = double.NaN;
            tiltMoved = double.NegativeInfinity;
            lastGateScore = double.NegativeInfinity;
            beforeLastContact = null;
            boutStart = double.NaN;
        }

        /// <summary>
        /// The step period (s) the gate-refusal counts stretch for (<see cref="StepClockSettings.StillWindowsStepPeriod"/>):
        /// the walk's (<see cref="StepPeriod"/>), or 0 (no stretch) while the head's tilt moves more than
        /// <see cref="StepClockSettings.StillWindowsMaxTiltChange"/> or the walk's contacts span less than
        /// <see cref="StepClockSettings.StillWindowsAfterWalked"/> (each where set).
        /// </summary>
        public double RefusalStepPeriod
            => settings.StillWindowsMaxTiltChange > 0 && tilt.Change > settings.StillWindowsMaxTiltChange
               || settings.StillWindowsAfterWalked > 0 && !(lastContact - boutStart >= settings.StillWindowsAfterWalked) ? 0 : period;

        /// <summary>The step period (s) the head's rhythm showed at its last reading; 0 when it showed none.</summary>
        public double RhythmPeriod => rhythmPeriod;

        /// <summary>
        /// Reads the head's rhythm from <paramref name="window"/> every <see cref="StepClockSettings.RhythmEveryWindows"/>
        /// windows (levelled as the detector's gate levels it), for <see cref="StepClockSettings.RhythmStepShare"/>, the
        /// period (<see cref="StepClockSettings.RhythmPeriodRatio"/>) and the hold (<see cref="HeldByRhythm"/>), and the head's
        /// tilt (<see cref="StartBlocked"/>, <see cref="StepClockSettings.MaxWalkingTiltChange"/>).
        /// </summary>
        public void FollowRhythm(SignalWindow window, double? levelTolerance)
        {
            bool readsStill = settings.StillStartMaxBend > 0;
            if (readsStill || settings.MaxStartTiltChange > 0 || settings.MaxWalkingTiltChange > 0 || settings.TiltMoveStartContacts > 1) tilt.Follow(window, readsStill);
            if (tilt.Change > HeadTilt.MoveStartChange) tiltMoved = window.EndTime;
            if (readsStill)
            {
                FollowStill(window.EndTime);
                still.FollowBend(tilt.Reading, window.EndTime);
            }
            if (rhythmCountdown-- > 0) return;
            rhythmCountdown = StepClockSettings.RhythmEveryWindows - 1;
            var rhythm = StepRhythm.Of(window, levelTolerance);
            rhythmPeriod = rhythm.ShowsStepPeriod ? rhythm.Period : 0;
            rhythmGoesOn = rhythm.HoldsWalk;
            if (rhythmPeriod > 0) lastRhythmPeriod = rhythmPeriod;
            // The tilt was read this window too: HeadTilt.EveryWindows and RhythmEveryWindows count alike from Reset.
            if (settings.MaxWalkingTiltChange > 0 && tilt.Change > settings.MaxWalkingTiltChange) Stop();
            double ratio = settings.RhythmPeriodRatio;
            if (ratio > 1 && rhythmPeriod > 0 && (period > ratio * rhythmPeriod || period * ratio < rhythmPeriod)) period = rhythmPeriod;
        }

        /// <summary>
        /// After the still head's reading (<see cref="HeadTilt.FollowStill"/>): while standing, whether a walk starting now
        /// starts from it; a walk from it is withdrawn on a bend within <see cref="HeadTilt.StillStartProbation"/> seconds of
        /// its start (<see cref="StepClockSettings.StillStartMaxBend"/>).
        /// </summary>
        void FollowStill(double now)
        {
            if (double.IsNaN(firstSeen)) firstSeen = now;
            bool walking = IsWalking(now);
            if (still.Refuses(tilt.Reading, walking, now, settings.StillStartMaxBend) && walking) Stop();
        }

        /// <summary>
        /// Whether a walk may not start now: the head's tilt moved more than <see cref="StepClockSettings.MaxStartTiltChange"/>
        /// over the newest <see cref="HeadTilt.Span"/> seconds (read with the rhythm), as in bending down to pick
        /// something up and straightening again, or from a still head pitching down (<see cref="StepClockSettings.StillStartMaxBend"/>),
        /// or the walking gate's regression gave the window
        /// <paramref name="gateLogOdds"/> of walking at most 0 (<see cref="StepClockSettings.StartNeedsGateScore"/>); a walk in
        /// progress is not stopped by it.
        /// </summary>
        public bool StartBlocked(double now, double gateLogOdds)
        {
            // Every window whose score passes gets here (its gate passes), so this is where the last passing score is kept.
            if (gateLogOdds > 0) lastGateScore = now;
            return !IsWalking(now) && (settings.MaxStartTiltChange > 0 && tilt.Change > settings.MaxStartTiltChange
                || settings.StartNeedsGateScore && !(now - lastGateScore <= settings.StartGateScoreWithin)
                || still.RefusesStart(tilt.Reading, settings.StillStartMaxBend));
        }

        /// <summary>
        /// Whether a contact now may start a provisional walk although the gate refuses (<see cref="FirstStepStartSettings"/>):
        /// none under way (or soon enough after the last one, <see cref="FirstStepStartSettings.ResumeWithin"/>), the gate's
        /// log-odds <paramref name="gateLogOdds"/> within the margin, the head's tilt steady
        /// (<see cref="StepClockSettings.MaxStartTiltChange"/>) and not bending from a still head
        /// (<see cref="StepClockSettings.StillStartMaxBend"/>); while a provisional walk waits, whether a contact may still
        /// count (the gate within the margin), so its second step can confirm it.
        /// </summary>
        public bool MayStartOnFirstStep(double now, double gateLogOdds)
            => firstStep.Waiting && IsWalking(now)
                ? gateLogOdds > -settings.FirstStep.Margin
                : firstStep.Allows(IsWalking(now), gateLogOdds, now - lastWalking, lastShownFor) && !(settings.MaxStartTiltChange > 0 && tilt.Change > settings.MaxStartTiltChange)
                    && !still.RefusesStart(tilt.Reading, settings.StillStartMaxBend);

        /// <summary>
        /// After each window's contacts: a walk that began this window on <see cref="MayStartOnFirstStep"/> (it did not walk
        /// before, <paramref name="walkingBefore"/>) waits; a waiting one is confirmed once the gate's regression passes
        /// (<paramref name="gateLogOdds"/> &gt; 0) or a second contact comes (<see cref="Contact"/>), and withdrawn
        /// (<see cref="Stop"/>) when neither happened within <see cref="FirstStepStartSettings.ConfirmWithin"/> or the gate
        /// refuses by <see cref="FirstStepStartSettings.KeepMargin"/>.
        /// </summary>
        public void FollowFirstStep(double now, bool startedOnFirstStep, bool walkingBefore, double gateLogOdds)
        {
            if (startedOnFirstStep && !walkingBefore && IsWalking(now)) firstStep.Begin(now);
            if (!firstStep.Keeps(now, gateLogOdds)) Stop();
        }

        /// <summary>Whether the walk under way is provisional: started on a first step, the gate not yet passed.</summary>
        public bool Provisional => firstStep.Waiting;

        /// <summary>
        /// Whether a walk in progress goes on whatever the walking gate says: the head's rhythm still shows the step, into
        /// the newest step (<see cref="StepClockSettings.HoldOnRhythm"/>). A slow, calm walker's head moves between heel
        /// strikes as little as a gesturing one, and the gate refused those stretches: the walk stopped before each step.
        /// </summary>
        public bool HeldByRhythm(double now) => settings.HoldOnRhythm && rhythmGoesOn && rhythmPeriod >= settings.HoldMinRhythmPeriod && IsWalking(now);

        /// <summary>
        /// A foot contact at <paramref name="time"/>; <paramref name="leftEvidence"/> &gt; 0 says it is the left foot's.
        /// Returns false when it is ignored (too close to the previous contact).
        /// </summary>
        public bool Contact(double time, double leftEvidence)
        {
            var before = Save();
            bool taken = TakeContact(time, leftEvidence);
            if (taken) beforeLastContact = before;
            return taken;
        }

        /// <summary>
        /// The last contact taken was a bump of the step whose contact is at <paramref name="time"/>, which came too soon
        /// after it to count (<see cref="Contact"/> refused it): the clock forgets the last contact (its period, side and
        /// counts as before it) and takes this one in its place. False, the clock as it was, when there is none to forget
        /// (none since the last start or stop) or this one is not taken either.
        /// </summary>
        public bool ReplaceLastContact(double time, double leftEvidence)
        {
            if (!beforeLastContact.HasValue || !(lastContact > beforeLastContact.Value.LastContact)) return false;
            var after = Save();
            var before = beforeLastContact.Value;
            Restore(before);
            if (TakeContact(time, leftEvidence))
            {
                beforeLastContact = before;
                return true;
            }
            Restore(after);
            return false;
        }

        readonly struct State
        {
            public readonly double LastContact, Period, SideEvidence, BoutStart;
            public readonly int ContactsInBout, HiddenContacts;
            public readonly bool PeriodMeasured;
            public readonly Foot LastFoot;

            public State(double lastContact, double period, double sideEvidence, double boutStart, int contactsInBout, int hiddenContacts, bool periodMeasured, Foot lastFoot)
            {
                LastContact = lastContact;
                Period = period;
                SideEvidence = sideEvidence;
                BoutStart = boutStart;
                ContactsInBout = contactsInBout;
                HiddenContacts = hiddenContacts;
                PeriodMeasured = periodMeasured;
                LastFoot = lastFoot;
            }
        }

        State? beforeLastContact; // the clock before the last contact it took (ReplaceLastContact); null after a start, a stop or Reset

        State Save() => new State(lastContact, period, sideEvidence, boutStart, contactsInBout, hiddenContacts, periodMeasured, lastFoot);

        void Restore(State s)
        {
            lastContact = s.LastContact;
            period = s.Period;
            sideEvidence = s.SideEvidence;
            boutStart = s.BoutStart;
            contactsInBout = s.ContactsInBout;
            hiddenContacts = s.HiddenContacts;
            periodMeasured = s.PeriodMeasured;
            lastFoot = s.LastFoot;
        }

        /// <summary><see cref="Contact"/> without remembering the clock before it.</summary>
        bool TakeContact(double time, double leftEvidence)
        {
            double interval = time - lastContact;
            if (interval < settings.MinStepInterval) return false;
            if (periodMeasured && interval < settings.MinStepShare * period) return false;
            if (interval < settings.RhythmStepShare * lastRhythmPeriod) return false;
            // A walk the head's rhythm holds goes on across a missed contact: the clock ran through the missed step, so
            // after an even number of steps the same foot lands again.
            if (interval > settings.MaxStepInterval && !(contactsInBout > 0 && IsWalking(time)))
            {
                contactsInBout = 1;
                periodMeasured = false;
                sideEvidence = leftEvidence;
            }
            else
            {
                // Steps since the last contact: one, unless the rhythm held the walk across a missed contact (where the period
                // is known, measured or the rhythm's; a guess counts one). Counting steps at shorter intervals let a period
                // measured at a second bump halve itself (style CV, the double-bumping *bn fem* turns: 21 % worse).
                bool known = periodMeasured || lastRhythmPeriod > 0 && Math.Abs(period - lastRhythmPeriod) < 0.3 * lastRhythmPeriod;
                int steps = known && interval > settings.MaxStepInterval ? Math.Max(1, (int)Math.Round(interval / period)) : 1;
                if (contactsInBout >= 1)
                {
                    double step = interval / steps;
                    period = periodMeasured ? (1 - settings.PeriodWeight) * period + settings.PeriodWeight * step : step;
                    periodMeasured = true;
                }
                contactsInBout++;
                if (contactsInBout >= 2) firstStep.Confirm();
                if (hiddenContacts > 0) hiddenContacts--;
                // The previous contact was the other foot (or, steps later, the same): its evidence counts against this
                // one being the same side (or for it).
                sideEvidence = leftEvidence + (steps % 2 == 1 ? -1 : 1) * settings.SideMemory * sideEvidence;
            }
            if (contactsInBout == 1) { hiddenContacts = ContactsHidden(time); boutStart = time; }
            lastFoot = sideEvidence >= 0 ? Foot.Left : Foot.Right;
            lastContact = time;
            return true;
        }

        /// <summary>
        /// Starts walking at once, as if a foot had landed at <paramref name="contactTime"/> in a walk of the given step
        /// period (for detectors that recognise a whole step in one window); <paramref name="leftEvidence"/> &gt; 0 says the left.
        /// </summary>
        public void Start(double contactTime, double leftEvidence, double stepPeriod)
        {
            beforeLastContact = null;
            hiddenContacts = ContactsHidden(contactTime);
            if (contactsInBout == 0) boutStart = contactTime;
            lastContact = contactTime;
            sideEvidence = leftEvidence;
            lastFoot = leftEvidence >= 0 ? Foot.Left : Foot.Right;
            period = stepPeriod;
            periodMeasured = false;
            contactsInBout = Math.Max(contactsInBout, settings.ContactsToStart);
        }

        /// <summary>Ends the walking bout now (the head has stopped moving like walking): the next contact starts a new one.</summary>
        public void Stop()
        {
            beforeLastContact = null;
            firstStep.Reset();
            contactsInBout = 0;
            periodMeasured = false;
            lastContact = double.NegativeInfinity;
            hiddenContacts = 0;
        }

        /// <summary>
        /// Contacts after its start a walk starting at <paramref name="start"/> waits for before it is shown: from a still head
        /// after standing (<see cref="StepClockSettings.StillStartContacts"/>), soon after the head's tilt moved
        /// (<see cref="StepClockSettings.TiltMoveStartContacts"/>), or soon after it bent from a still head
        /// (<see cref="StepClockSettings.BendStartContacts"/>), whichever asks more.
        /// </summary>
        int ContactsHidden(double start)
        {
            bool fromStill = still.FromStill && start - Math.Max(lastWalking, firstSeen) >= settings.StillStartContactsAfterStanding;
            int contacts = Math.Max(Math.Max(fromStill ? settings.StillStartContacts : 0, start - tiltMoved <= HeadTilt.MoveStartRecent ? settings.TiltMoveStartContacts : 0),
                still.BentBefore(start) ? settings.BendStartContacts : 0);
            return Math.Max(0, contacts - 1);
        }

        /// <summary>
        /// Whether the walk under way is not shown yet: it started from a still head, soon after the head's tilt moved or soon
        /// after it bent from a still head, and waits for more contacts (<see cref="StepClockSettings.StillStartContacts"/>,
        /// <see cref="StepClockSettings.TiltMoveStartContacts"/>, <see cref="StepClockSettings.BendStartContacts"/>); the clock walks meanwhile.
        /// </summary>
        public bool Hidden(double now) => hiddenContacts > 0 && IsWalking(now);

        public bool IsWalking(double now)
            => contactsInBout >= settings.ContactsToStart && (now - lastContact <= settings.StandingAfterPeriods * period
                || settings.HoldOnRhythm && rhythmGoesOn && now - lastContact <= settings.RhythmHoldPeriods * period);

        /// <summary>Stride position now: the last contact's foot landing, advanced at the step period.</summary>
        public double StridePosition(double now)
            => map.StridePositionOfOnset(lastFoot, GaitPhase.InitialContact) + (now + settings.Lead + BounceLead - lastContact) / (2 * period);

        /// <summary>Seconds the walker's bounce adds to <see cref="StepClockSettings.Lead"/> (0 until <see cref="FollowBounce"/>, and after <see cref="Reset"/>).</summary>
        public double BounceLead { get; private set; }

        /// <summary>The walker now bounces <paramref name="bounce"/> (m/s^2, as the detector measures it): lead the clock for it.</summary>
        public void FollowBounce(double bounce)
        {
            if (!(bounce > 0) || double.IsInfinity(bounce)) return;
            double lead = settings.LeadPerLogBounce * (Math.Log(bounce) - Math.Log(settings.LeadReferenceBounce));
            BounceLead = Math.Max(-StepClockSettings.MaxBounceLead, Math.Min(StepClockSettings.MaxBounceLead, lead));
        }

        /// <summary>
        /// The <see cref="StepClockSettings.LeadPerLogBounce"/> and reference that fit contacts' offsets from the true ones
        /// (s, positive late) against the walker's bounce at each: the least-squares slope on the log of the bounce (within
        /// <see cref="StepClockSettings.MaxLeadPerLogBounce"/>) and the median bounce. False with under 30 usable contacts
        /// or bounces all alike.
        /// </summary>
        public static bool FitBounceLead(IReadOnlyList<double> offsets, IReadOnlyList<double> bounces, out double perLogBounce, out double reference)
        {
            perLogBounce = 0;
            reference = StepClockSettings.DefaultLeadReferenceBounce;
            var x = new List<double>();
            var y = new List<double>();
            for (int i = 0; i < offsets.Count && i < bounces.Count; i++)
            {
                if (!(bounces[i] > 0) || double.IsInfinity(bounces[i]) || !ImuSample.IsFiniteNumber(offsets[i])) continue;
                x.Add(Math.Log(bounces[i]));
                y.Add(offsets[i]);
            }
            if (x.Count < 30) return false;
            double mx = 0, my = 0, sxy = 0, sxx = 0;
            for (int i = 0; i < x.Count; i++)
            {
                mx += x[i];
                my += y[i];
            }
            mx /= x.Count;
            my /= x.Count;
            for (int i = 0; i < x.Count; i++)
            {
                sxy += (x[i] - mx) * (y[i] - my);
                sxx += (x[i] - mx) * (x[i] - mx);
            }
            if (sxx < 1e-9) return false;
            perLogBounce = Math.Max(-StepClockSettings.MaxLeadPerLogBounce, Math.Min(StepClockSettings.MaxLeadPerLogBounce, sxy / sxx));
            reference = Math.Exp(GaitMetrics.Median(x));
            return true;
        }

        /// <summary>The prediction now; a walking stride position never steps back by less than <see cref="StepClockSettings.HoldBack"/>.</summary>
        public GaitPrediction Predict(double now, double confidence)
        {
            if (!IsWalking(now) || hiddenContacts > 0)
            {
                if (!double.IsNaN(shownFrom)) lastShownFor = lastWalking - shownFrom;
                shownFrom = double.NaN;
                reported = double.NaN;
                stance.Reset();
                return GaitPrediction.Standing(now, confidence);
            }
            if (double.IsNaN(shownFrom)) shownFrom = now;
            lastWalking = now;
            double s = StridePosition(now);
            if (!double.IsNaN(reported))
            {
                double back = PhaseMap.Wrap(reported - s);
                if (back > 0 && back < settings.HoldBack) s = reported;
            }
            reported = s;
            return GaitPrediction.Walking(now, s, period, confidence, map, stance);
        }
    }
}
