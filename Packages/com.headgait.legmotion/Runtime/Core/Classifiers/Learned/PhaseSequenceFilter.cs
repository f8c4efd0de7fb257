using System;

namespace HeadGait
{
    public sealed class PhaseFilterSettings
    {
        /// <summary>Chance per window that walking starts or stops (the classifier's evidence has to overcome it).</summary>
        public double StartProbability = 0.01, StopProbability = 0.01;

        /// <summary>Chance per window of skipping a segment (segments as short as IC last about two windows).</summary>
        public double SkipProbability = 0.02;

        /// <summary>Share of time the prior expects standing; the classifier's probabilities are divided by their priors.</summary>
        public double StandingPrior = 0.1;

        /// <summary>How much the model's evidence counts against the gait model (1 = as probabilities; lower trusts the sequence more).</summary>
        public double EvidenceWeight = 1.0;

        /// <summary>
        /// A filtered class this many segments or fewer behind the last one is held: feet do not walk backwards, and showing
        /// it would put a foot back into swing and land it a second time (style CV: SVM step precision 81.5 to 89.9 %).
        /// </summary>
        public int HoldBackSegments = 2;

        /// <summary>
        /// A class at least this many segments away either way (the feet swapped: half a stride is 8 of the 16 segments)
        /// is held as well. A real change of phase does not jump across the stride within one window; the model's class
        /// moves on while the last is held, and within a few segments it is near enough to follow. Style CV: step
        /// precision SVM 89.9 to 95.4 %, BLSTM 94.8 to 96.9 %, right foot 96.8 to 97.6 % and 98.4 to 98.9 %; recall
        /// 97.1 to 96.6 % and 96.0 to 96.1 %; misclassification 21.7 to 22.0 % and 17.8 to 17.9 %. From 5 segments on,
        /// recall fell under 96 % and misclassification rose by 0.5 point.
        /// </summary>
        public int SwapSegments = 6;

        /// <summary>
        /// Step periods (at the head's rhythm's, <see cref="PeriodFromRhythm"/>) for which a class held across the stride
        /// (<see cref="SwapSegments"/>) is carried on at the step period instead of standing still; after that the model's
        /// class is shown (the feet did swap). Standing still, the shown position waited for the model's class to come round,
        /// half a stride, and each wait lost a step: on the glasses the SVM's shown positions advanced 850 strides where the
        /// signal took 931. Not fitted: one step (half a step: BLSTM steps shown per step of the signal 1.08 pooled, the jumps
        /// when swaps are taken each adding one; unbounded: a real swap kept the wrong feet for good). On the glasses
        /// (`realworld`, avatar, with the animator's latched step back and <see cref="PeriodFromRhythm"/>), SVM / BLSTM steps
        /// shown per step 0.94 / 0.92 to 0.98 / 1.00, alternating feet 96.2 / 95.7 to 98.3 / 98.1 %. Style CV (SVM, the same fold
        /// models): classifier / avatar 21.2 / 20.0 to 21.2 / 19.5 %, avatar step recall 94.5 to 95.8 %, matched steps on the
        /// right foot 99.4 to 98.7 %. 0 holds the class still.
        /// </summary>
        public double SwapCarrySteps = 1.0;

        /// <summary>
        /// Whether a walking prediction's step period is the head's rhythm's where the rhythm shows one
        /// (<see cref="StepRhythm.ShowsStepPeriod"/>, read as <see cref="HoldOnRhythm"/> reads it), as the step clock of THR
        /// and COR follows it (<see cref="StepClockSettings.RhythmPeriodRatio"/>), rather than the time between predicted
        /// contacts: a lost or doubled contact made that period a step too long or short, and the animator's clock ran at
        /// it (BLSTM on the glasses: the avatar's period 0.95 of the signal's, 0.99 with it).
        /// </summary>
        public bool PeriodFromRhythm = true;

        /// <summary>
        /// While walking, a window the walking gate passes with at least these log-odds (over 99 % sure it is walking) is
        /// not let end the walk: the model's standing probability counts <see cref="SureWalkingStandingWeight"/> of itself.
        /// A network meets a walker bouncier than any it trained on with confident "standing" (the BLSTM with the
        /// *active* style held out: walks broken in two or three), while the gate reads how the head moves, not the
        /// shape. Style CV, BLSTM: 17.0 / 15.6 to 16.4 / 15.0 %, step recall 95.7 to 97.0 %, walking shown as standing
        /// 2.8 to 1.8 %; standing shown as walking 1.2 to 1.3 %, the made-up stops 0.06 s later. Infinity turns it off.
        /// </summary>
        public double SureWalkingLogOdds = 5;

        /// <summary>
        /// While walking, a window whose newest 2.5 s keep a walking rhythm (<see cref="StepRhythm"/>, when the gate listens
        /// for one) counts as one the gate is sure of, however small its log-odds: slow, calm people in a headset rarely reach
        /// the gate's sure log-odds, and the networks flicker to standing inside their walks. On the real glasses walkers
        /// (`headgait realworld`, avatar, together with <see cref="RefusedWalkingShare"/> 0.3): walking time shown walking
        /// SVM 75.0 to 78.7 %, BLSTM 68.1 to 71.2 %, walking fragments per file 107 to 82 and 100 to 89; standing shown as
        /// walking 0.9 to 1.0 % either, picking things up 10.2 to 11.8 % and 6.3 to 7.2 %.
        /// </summary>
        public bool SureOnStepRhythm = true;

        /// <summary>
        /// While walking, a window the gate refuses keeps this share of the model's walking probabilities (the rest goes to
        /// standing) instead of none, so the time filter, not one window, ends the walk: the gate's refusals inside real slow
        /// walks come in runs of a few windows. 0: a refusal is standing outright.
        /// </summary>
        public double RefusedWalkingShare = 0.3;

        /// <summary>
        /// Refused windows in a row that <see cref="RefusedWalkingShare"/> applies to (0.1 s); from the next one a refusal is
        /// standing outright, so a gate that keeps refusing ends a walk the model would keep going.
        /// </summary>
        public int RiddenRefusals = 10;

        /// <summary>
        /// Whether a walk in progress rides out the gate's refusals beyond <see cref="RiddenRefusals"/> while the head's rhythm
        /// holds it (<see cref="StepRhythm.HoldsWalk"/>, read every <see cref="StepClockSettings.RhythmEveryWindows"/> windows,
        /// as the step clock reads it for THR and COR: <see cref="StepClockSettings.HoldOnRhythm"/>). The gate refuses slow,
        /// calm walkers' heads for stretches longer than 0.1 s, and each refusal ended the walk mid-stride. While it holds,
        /// the model decides as if the gate had passed the window. Real glasses (`headgait realworld`, avatar), SVM / BLSTM:
        /// walking shown 90.5 / 89.3 to 91.0 / 90.3 %, fragments per walking file 24 / 28 to 22 / 20, alternating feet 96.7 /
        /// 96.5 to 96.2 / 95.7 %; standing, sitting and picking up shown as walking up by at most 0.2 point. The neutral
        /// evidence tried instead (the filter running on at the step period) held more (91.9 / 91.2 %, 19 / 19 fragments)
        /// but alternated worse (BLSTM 94.9 %) and showed sitting as walking 0.4 / 0.3 point more (see the measurements log).
        /// </summary>
        public bool HoldOnRhythm = true;

        /// <summary>
        /// A walk at least <see cref="HeadTilt.YoungWalk"/> old rides out a window the gate's regression refuses by less than
        /// this (log-odds) as one the head's rhythm holds (<see cref="HoldOnRhythm"/>): the model decides as if the gate had
        /// passed it. Slow, calm walkers sit just under the gate's boundary (held-out clips made slow, their refused walking
        /// windows: log-odds median -0.8; the glasses' still activities' refused windows about -5), and the rhythm's test
        /// (the head swaying back each step) fails on walkers who hardly sway, so runs of near misses ended their walks
        /// mid-stride. A walk never starts on one, and a younger walk (most of the still activities' false walks) is not held:
        /// held from the start, picking things up on the glasses showed walking 1.5 to 1.9 %. 0 turns it off; the SVM holds
        /// at 2 (<see cref="SvmClassifier.DefaultFilter"/>, the measurements log).
        /// </summary>
        public double NarrowRefusalLogOdds = 0;

        /// <summary>
        /// A walk resumed soon after a walk under way (a walker going on after a turn or a pause): within
        /// <see cref="FirstStepStartSettings.ResumeWithin"/> seconds of a walk shown for at least
        /// <see cref="FirstStepStartSettings.ResumeAfterShown"/>, a window the gate refuses by less than
        /// <see cref="FirstStepStartSettings.Margin"/> log-odds counts as passed while no walk, or a young one
        /// (<see cref="HeadTilt.YoungWalk"/>), goes on: the gate's half second still holds the pause at the walk's first step,
        /// as THR's and COR's provisional start on a first step meets it (<see cref="StepClockSettings.FirstStep"/>). Off
        /// (<see cref="FirstStepStartSettings.Margin"/> 0) unless set; the other members of the settings are not read.
        /// </summary>
        public FirstStepStartSettings ResumeStart = new FirstStepStartSettings();

        /// <summary>
        /// Most the head's tilt may have moved over the newest <see cref="HeadTilt.Span"/> seconds for a walk to start
        /// (degrees; the shared step clock's limit, <see cref="StepClockSettings.MaxStartTiltChange"/>): while it moves more,
        /// a window is standing whatever the model and the gate say. Bending down to pick something up and straightening
        /// again sways and bumps the head like steps. 0 turns it off.
        /// </summary>
        public double MaxStartTiltChange = HeadTilt.DefaultMaxStartChange;

        /// <summary>
        /// A walk in progress stops outright (no refusal ridden out) when the head's tilt moves more than this (degrees), or
        /// more than <see cref="MaxStartTiltChange"/> within <see cref="HeadTilt.YoungWalk"/> of its start. 0 turns it off.
        /// </summary>
        public double MaxWalkingTiltChange = HeadTilt.DefaultMaxWalkingChange;

        /// <summary>
        /// With <see cref="WalkOnStepClock"/>: while THR's step clock beside the model shows a settled walk
        /// (<see cref="StepClockWalkAge"/>), the model's walk may start, and a young one go on, while the head's tilt moves up to
        /// <see cref="MaxWalkingTiltChange"/>, not only <see cref="MaxStartTiltChange"/>: THR's walk itself started under the
        /// start limit, and a walk's turn or sideways gallop swings the tilt's half-second means past it for as long as it
        /// lasts (style CV, SVM: bn1 *childish*'s sideways walk right 91.5 % shown standing, a turn of bn *fem* 43.5 %).
        /// </summary>
        public bool StartTiltOnSettledClock = false;

        /// <summary>
        /// A walk that starts from a still head does not start, and stops within <see cref="HeadTilt.StillStartProbation"/>
        /// seconds of its start, while the head's pitch lies more than this many degrees from the still head's (the step
        /// clock's rule, <see cref="StepClockSettings.StillStartMaxBend"/>). 0 turns it off.
        /// </summary>
        public double StillStartMaxBend = HeadTilt.DefaultStillStartMaxBend;

        /// <summary>
        /// Whether <see cref="StillStartMaxBend"/> reads the head's whole direction of gravity against the still head's
        /// (pitch and roll, <see cref="HeadTilt.BendInRoll"/>) rather than its pitch alone: glasses taken off a still head
        /// are turned in the hand every way, and the SVM's walks in those take-offs began while the pitch stayed within
        /// the limit (see <see cref="SvmClassifier.DefaultFilter"/>).
        /// </summary>
        public bool StillStartBendInRoll = false;

        /// <summary>
        /// Whether a wearer quicker than the training walkers is read at their own step while no calibration sets a scale
        /// (<see cref="LearnedClassifier.LiveTimeScale"/>): the model also reads the newest stretch of the window resampled
        /// by the wearer's step period over the training walkers' (the head's rhythm's, <see cref="StepRhythm.ShowsStepPeriod"/>
        /// as <see cref="HoldOnRhythm"/> reads it, else THR's step clock's, <see cref="WalkOnStepClock"/>, settled or from the
        /// first step it timed, <see cref="LearnedClassifier.LiveTimeScale"/>; never below
        /// <see cref="HeadGait.Calibration.WearerProfile.MinLearnedTimeScale"/>, never above 1: training already stretched
        /// its walks for slower wearers), and that reading picks the walking class while the window as it is decides whether
        /// the wearer walks, as a calibration's scale does. Off unless set; the SVM sets it (<see cref="SvmClassifier.DefaultFilter"/>).
        /// </summary>
        public bool LiveTimeScale = false;

        /// <summary>Weight of the model's standing probability in a window the gate is sure of (see <see cref="SureWalkingLogOdds"/>).</summary>
        public double SureWalkingStandingWeight = 0.01;

        /// <summary>
        /// A walk the classifier begins with no walk shown for <see cref="FreshWalkGap"/> seconds is shown only once it has
        /// lasted this long (s), or once the gate is sure of it (<see cref="SureWalkingLogOdds"/>; the still activities' false
        /// walks are not such walks); until then the classifier reports standing while the time filter follows the walk, so it is
        /// shown in phase. The models' filtered belief flickers to standing within a walk's first windows: each flicker was
        /// a start the avatar began and dropped before the lead foot landed, and most of the still activities' false walks
        /// are that short. Real glasses (`realworld`, avatar; in-sample), SVM / BLSTM with <see cref="YoungWalkStandingWeight"/>:
        /// see the measurements log. 0 shows every walk at once. The BLSTM waits 0.25 s (<see cref="BlstmClassifier.DefaultFilter"/>).
        /// </summary>
        public double FreshWalkShownAfter = 0.15;

        /// <summary>
        /// Seconds without a walk shown after which a walk is fresh (<see cref="FreshWalkShownAfter"/>), counted from the
        /// stream's start at the earliest (what came before it is not known; the labelled clips start mid-walk: SVM style CV
        /// 21.2 / 19.5 to 22.1 / 20.4 % counted from before it); one resumed sooner, within a bout, is shown at once (BLSTM on the glasses at 1 s rather than 3: walking shown 0.7-1.4 points lower, the
        /// start of bouts met standing 0.09 s later).
        /// </summary>
        public double FreshWalkGap = 3;

        /// <summary>
        /// A walk shown for less than <see cref="HeadTilt.YoungWalk"/> gives the next walk no credit for
        /// <see cref="FreshWalkGap"/> (it is fresh, <see cref="FreshWalkShownAfter"/>), and spends the stream start's: a gesture
        /// made standing showed a string of short walks each shown at once, as the first came within the gap of the stream's
        /// start and each the next one's credit. A short walk that ends while THR's step clock (on the model's gate) shows a
        /// walk keeps the credit: without that exception the glasses' walking lost 0.6 point, as a real bout's first short
        /// walks were held back too. The SVM sets it (<see cref="SvmClassifier.DefaultFilter"/>, the measurements log);
        /// false: any shown walk gives credit.
        /// </summary>
        public bool ShortWalkGivesNoCredit = false;

        /// <summary>
        /// Weight of the model's standing probability in a window the gate passes while the walk is younger than
        /// <see cref="HeadTilt.YoungWalk"/> (a window the gate is sure of weighs it <see cref="SureWalkingStandingWeight"/>):
        /// the young walks the models drop within their first half second are the rest of their extra fragments. Alone it shows
        /// more still time as walking (the measurements log); beside <see cref="FreshWalkShownAfter"/>, which hides the still
        /// activities' short false walks, it costs little of that. The BLSTM keeps 0.3, the SVM weighs 0.1
        /// (<see cref="SvmClassifier.DefaultFilter"/>). 1: as the model says.
        /// </summary>
        public double YoungWalkStandingWeight = 0.3;

        /// <summary>
        /// Whether THR's step clock on the model's own walking gate (<see cref="LearnedClassifier.FollowStepClock"/>: its
        /// contacts, the gate's score to start, the rhythm's ride-outs, its still-start rules) keeps a walk going: while THR
        /// shows a settled walk and the model has walked enough of the last second (the three settings below), a walk the
        /// model shows goes on when the model's belief turns to standing, its stride position carried on at the step period
        /// (the model then only tells the phase). THR and COR keep a walk in one piece this way with the same gate, where the
        /// models' belief turned to standing in a walk's first half second. The SVM and the BLSTM set it
        /// (<see cref="SvmClassifier.DefaultFilter"/>, <see cref="BlstmClassifier.DefaultFilter"/>); see the measurements log.
        /// </summary>
        public bool WalkOnStepClock = false;

        /// <summary>
        /// With <see cref="WalkOnStepClock"/>: THR's walk keeps the model's going only once THR has shown it this long (s).
        /// The still activities' false walks the carry lengthened were THR's own young ones (the BLSTM on the glasses: 90 % of
        /// them under 1 s old where the carry began; in the walking files half were over 4 s old). 0: at once.
        /// </summary>
        public double StepClockWalkAge = 1;

        /// <summary>
        /// With <see cref="WalkOnStepClock"/>: the model's walk is carried only while its own filtered class has named a
        /// walking class for at least this share of the last <see cref="OwnWalkingSpan"/> (an exponential average): the carry
        /// bridges the model's flickers within its own walk, not a walk THR shows while the model mostly says standing, and a
        /// carry the model does not come back to runs out. 0: any share.
        /// </summary>
        public double StepClockOwnWalkingShare = 0.3;

        /// <summary>Seconds over which the model's own walking share is averaged (<see cref="StepClockOwnWalkingShare"/>).</summary>
        public double OwnWalkingSpan = 1;

        /// <summary>
        /// With <see cref="WalkOnStepClock"/>: the walk is carried where the gate refuses outright too (the head's rhythm not
        /// holding it), at any age; false: only where it does not or the walk is younger than <see cref="HeadTilt.YoungWalk"/>.
        /// With THR's walk settled (<see cref="StepClockWalkAge"/>) and the model's own share asked
        /// (<see cref="StepClockOwnWalkingShare"/>), the still activities' false walks are not carried anyway, and a walking
        /// head's bounce the gate misses for a moment no longer breaks the walk.
        /// </summary>
        public bool StepClockThroughRefusals = true;
    }

    /// <summary>
    /// Online (forward) filtering of a learned classifier's per-window class probabilities over the stride's segments:
    /// a walking foot moves forward through the segments, staying in each for as long as its share of the stride at the
    /// current step period, and walking starts or stops only now and then. A window whose classifier jumps half a stride or
    /// flickers to standing is outvoted by the windows around it, without delaying a steady prediction. Allocation-free.
    /// </summary>
    public sealed class PhaseSequenceFilter
    {
        readonly StrideSegments segments;
        readonly PhaseFilterSettings settings;
        readonly double[] belief, predicted, prior;
        bool started;

        public PhaseFilterSettings Settings => settings;

        public PhaseSequenceFilter(StrideSegments segments, PhaseFilterSettings settings = null)
        {
            this.segments = segments ?? throw new ArgumentNullException(nameof(segments));
            this.settings = settings ?? new PhaseFilterSettings();
            int n = segments.ClassCount;
            belief = new double[n];
            predicted = new double[n];
            prior = new double[n];
            for (int k = 0; k < segments.Count; k++) prior[k] = (1 - this.settings.StandingPrior) * segments.Length(k);
            prior[segments.StandingClass] = this.settings.StandingPrior;
        }

        /// <summary>The filtered class probabilities after the last update.</summary>
        public double[] Belief => belief;

        public void Reset() => started = false;

        /// <summary>
        /// Advances the belief by one window of <paramref name="dt"/> seconds at the given step period and folds in the
        /// classifier's probabilities; returns the most likely class.
        /// </summary>
        public int Update(double[] probabilities, double dt, double stepPeriod)
        {
            int n = segments.Count, standing = segments.StandingClass;
            var s = settings;
            if (!started)
            {
                for (int k = 0; k <= n; k++) predicted[k] = prior[k];
                started = true;
            }
            else
            {
                Array.Clear(predicted, 0, n + 1);
                double stride = 2 * Math.Max(0.2, stepPeriod);
                for (int k = 0; k < n; k++)
                {
                    // Leaving a segment takes its expected duration; a share of the leavers skips the next one.
                    double leave = Math.Min(1, Math.Max(0, dt / (segments.Length(k) * stride)));
                    double b = belief[k] * (1 - s.StopProbability);
                    predicted[k] += b * (1 - leave);
                    predicted[(k + 1) % n] += b * leave * (1 - s.SkipProbability);
                    predicted[(k + 2) % n] += b * leave * s.SkipProbability;
                    predicted[standing] += belief[k] * s.StopProbability;
                }
                predicted[standing] += belief[standing] * (1 - s.StartProbability);
                for (int k = 0; k < n; k++) predicted[k] += belief[standing] * s.StartProbability * segments.Length(k);
            }
            double total = 0;
            for (int k = 0; k <= n; k++)
            {
                double evidence = Math.Pow(Math.Max(probabilities[k], 1e-9) / prior[k], s.EvidenceWeight);
                belief[k] = predicted[k] * evidence;
                total += belief[k];
            }
            int best = 0;
            for (int k = 0; k <= n; k++)
            {
                belief[k] = total > 0 ? belief[k] / total : 1.0 / (n + 1);
                if (belief[k] > belief[best]) best = k;
            }
            return best;
        }
    }
}
