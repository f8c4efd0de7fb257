using System;
using System.Collections.Generic;

namespace HeadGait
{
    public sealed class CorrelationSettings
    {
        public CorrelationSettings Clone()
        {
            var c = (CorrelationSettings)MemberwiseClone();
            c.Clock = Clock.Clone();
            return c;
        }

        /// <summary>Shortest and longest step searched, in grid samples (30..90 = 0.3..0.9 s at 100 Hz).</summary>
        public int MinStepSamples = 30;
        public int MaxStepSamples = 90;

        /// <summary>While walking, only steps within this many samples of the current step period are tried.</summary>
        public int PeriodTolerance = 6;

        /// <summary>
        /// Once the period is measured, steps within this share of it are tried too, where that reaches further than
        /// <see cref="PeriodTolerance"/>: the clock's period follows each new step only partly, and with a fixed reach a
        /// slowing walker's contacts came early for a step or two longer. Leave-one-style-out, calibrated and run with it:
        /// 23.4 to 22.9 % (*musical* 34.0 to 29.4, *childish* 38.8 to 37.3, *chimpira* 19.2 to 20.2 %), ear-like 26.3 to
        /// 26.1, slow 33.1 to 32.5, start-stop 38.1 to 37.4 %; file CV 20.0 to 19.9 %; generated recordings 20.1 to 17.9 %.
        /// Only calibrated with it, or only run with it: 23.3 % each, so part of the gain comes through the threshold the
        /// calibration picks (on all the training recordings r &gt; 0.73 became 0.75). 0.15: 23.0 %; 0.2: 23.6 % (walking
        /// shown as standing 1.2 to 2.5 %); a fixed 7 samples instead: 23.4 %. 0 turns it off.
        /// </summary>
        public double PeriodToleranceShare = 0.12;

        /// <summary>
        /// The same for the first contact of a walk whose period is still a guess (the standing search's, or the last
        /// walk's): a calm walker whose start was matched at 0.9 s steps was otherwise tracked at 0.8-0.9 s and named the
        /// wrong foot for the whole walk (steps of 0.55 s). Every step length (no limit) let the first contact take an
        /// early bump at a much shorter step: on the generated recordings COR scored 25.3 % (20 samples: 19.2 %).
        /// </summary>
        public int FirstStepTolerance = 20;

        /// <summary>
        /// A correlation peak counts once no higher value came in this many samples after it: a step's correlation
        /// rises and falls over several samples, and waiting lets the true top win over an early bump.
        /// </summary>
        public int PeakConfirmSamples = 5;

        /// <summary>
        /// While walking, a peak this much below the threshold still counts when it comes when the next step is due
        /// (<see cref="DueFrom"/> to <see cref="DueUntil"/> step periods after the last contact). A walker's step that
        /// matches a little worse than usual was otherwise missed, the clock ran out and restarted at a guessed phase.
        /// Leave-one-style-out: 0.1 lowered misclassification from 27.4 to 26.5 %; 0.2 helped less (27.3 %).
        /// </summary>
        public double TrackingMargin = 0.1;

        public double DueFrom = 0.75, DueUntil = 1.5;

        /// <summary>Overrides the template's correlation threshold when set (e.g. the paper's 0.9); NaN keeps the template's.</summary>
        public double MinCorrelationOverride = double.NaN;

        /// <summary>
        /// While standing, each window is also searched for a step at every phase (the paper's per-window rule); a match
        /// this much above the threshold starts walking at once instead of at the next contact. Negative turns it off
        /// (walking then starts late: step recall 85 % in leave-one-style-out). 0.1 rather than 0.05: bouncing bows match
        /// less often (standing shown as walking 3.4 to 3.2 %, file CV 2.9 to 2.7 %), the side is named right more often
        /// (96.4 to 97.2 %), misclassification 24.4 to 24.0 % (file CV 22.4 to 22.3 %), walking shown as standing 1.5 to 1.9 %.
        /// </summary>
        public double StartMargin = 0.1;

        /// <summary>Newest samples the standing search correlates (50 = the paper's 0.5 s window).</summary>
        public int StartWindow = 50;

        /// <summary>
        /// Longest step the standing search tries, in grid samples. Its 0.5 s window holds under two thirds of a longer
        /// step, and the first, growing bounce of a walk matched the longest steps searched best (at starts the search
        /// chose 0.9 s for calm walkers whose steps took 0.55 s). A slower walker is still followed, as the first tracked
        /// contact is searched more widely (<see cref="FirstStepTolerance"/>).
        /// </summary>
        public int StartMaxStepSamples = 75;

        /// <summary>
        /// When the newest half of the standing search's window spans at least this many times the SMV of its older half,
        /// the window holds the start of the movement, and the length it matched says nothing of the step period: the
        /// first, growing bounce of a walk from standing matched steps 0.2 s too long (median, against 0.0 s where the
        /// search starts within a walk: leave-one-style-out, 228 of 289 starts from standing span 3 times more in their
        /// newest half, none of 319 starts within a walk). The clock then runs at <see cref="StepClockSettings.InitialStepPeriod"/>
        /// (the real data's median step) until the first contact, which is still searched around the matched length: searched
        /// around the typical step, a generated walker's first contact took a bump half a step early (start-stop recording
        /// 19.7 to 33 %). Leave-one-style-out, walks made to start and stop: 41.8 to 39.7 % (file CV 36.9 to 34.7 %); as
        /// recorded and ear-like unchanged (24.4 and 28.3 to 28.4 %); a ratio of 2: 39.6 %, as recorded 24.5, ear-like
        /// 28.8 %. 0 turns it off.
        /// </summary>
        public double OnsetSpanRatio = 3;

        /// <summary>
        /// Least span of SMV (m/s^2, highest minus lowest sample) over the matched step, or over the standing search's
        /// window, for a correlation peak to count as a contact or a match to start a walk. Pearson's r ignores scale, so a
        /// bow's or a wave's gentle bob matched a step as well as a walk's bounce. In the real training data 2 % of the
        /// steps span less than 4.7 m/s^2, of the calmest style's (the second corpus's *feminine*) less than 2.2.
        /// Leave-one-style-out, standing shown as walking: 3.2 % without, 3.0 / 2.6 / 2.3 / 2.1 / 1.8 % at
        /// 1.5 / 2 / 2.5 / 3 / 3.5 (misclassification 24.0 to 23.8 % at 2). The held-out clips made ear-like, walking
        /// shown as standing: 2.5 % without, 2.4 / 2.8 / 3.9 / 8.1 % at 2 / 2.5 / 3 / 3.5. At 2 for the standing search
        /// alone, 3.0 %; for contacts alone, 3.2 %. On the generated recordings it costs 0.8 point (23.6 to 24.4 %: in the
        /// walks of its start-stop recording the second contact is taken about 60 ms late, and the stride runs behind for
        /// a few steps); for the standing search alone, 23.4 %. Checking contacts only while standing (a walk in progress
        /// keeps its weak steps): generated 23.3 %, but standing shown as walking 2.7 %, misclassification 23.9 % and
        /// ear-like 29.7 against 29.4 %. 0 turns it off.
        /// </summary>
        public double MinStepSpan = 2.0;

        /// <summary>
        /// One contact starts walking; on the pose path the clock looks 10 ms further ahead
        /// (<see cref="StepClockSettings.PoseFitDelay"/>). Leave-one-style-out on the pose recordings, 0 / 5 / 10 / 15 / 20 /
        /// 25 ms: 25.5 / 24.9 / 24.7 / 24.9 / 25.3 / 26.2 % (the same order at 72, 90 and 120 Hz; step recall 98.3 %
        /// throughout); file CV at 10 ms 22.3 to 21.2 %. The head's rhythm holds only slow walks against the gate
        /// (<see cref="StepClockSettings.HoldMinRhythmPeriod"/>). A walk from a still head after standing is shown from its
        /// third contact, one soon after the head's tilt moved from its third, one soon after the head bent from a still head
        /// from its second (<see cref="StepClockSettings.StillStartContacts"/>, <see cref="StepClockSettings.TiltMoveStartContacts"/>,
        /// <see cref="StepClockSettings.BendStartContacts"/>). Its gate-refusal counts stretch with a slower step (from the
        /// typical step, <see cref="StepClockSettings.StillWindowsStepPeriod"/>) only while the head's tilt holds within 10
        /// degrees and once the walk's contacts span 0.85 s (<see cref="StepClockSettings.StillWindowsMaxTiltChange"/>,
        /// <see cref="StepClockSettings.StillWindowsAfterWalked"/>): stretched at any tilt and age, the held-out clips made
        /// slow scored 31.7 instead of 33.3 %, but a waving clip's false walks were shown longer (gestures and bows shown as
        /// walking, avatar, 1.58 to 1.69 %; the real glasses' picking up 1.7 to 1.8 %); with both conditions (and
        /// <see cref="ReplaceMargin"/>) slow 31.7 %, gestures 1.58 %, glasses standing 0.94 to 0.95 %, picking up 1.70 %
        /// (see the measurements log). Within 3 s of a walk shown for at least 2.5 s, a contact the gate refuses by less than
        /// 0.75 log-odds starts a provisional walk, as THR's does (<see cref="FirstStepStartSettings.ResumeAfterShown"/>): a
        /// walker resuming after a turn or a pause is shown walking a step sooner, and the still activities' and gestures'
        /// false walks, shorter than that, give it no start.
        /// </summary>
        public StepClockSettings Clock = new StepClockSettings { ContactsToStart = 1, PoseFitDelay = 0.01, HoldMinRhythmPeriod = 0.75, StillStartContacts = 3, TiltMoveStartContacts = 3, BendStartContacts = 2, StillWindowsMaxTiltChange = 10, StillWindowsAfterWalked = 0.85,
            FirstStep = FirstStepStartSettings.Shipped(resumeAfterShown: 2.5) };

        /// <summary>
        /// A full match (r at or above the threshold) that beats the last contact's r by this much, but comes too soon after it
        /// to be a step of its own (<see cref="StepClock.Contact"/> refuses it), takes that contact's place
        /// (<see cref="StepClock.ReplaceLastContact"/>): the earlier, weaker peak was a bump of the same step (a calm walker's
        /// head bumps twice per step, a walk's first contact can be taken on a bump of a step), and taken first it
        /// refused the step's true contact and dated the stride early. Leave-one-style-out (the fold models of the measurements
        /// log's run, in-sample as a choice of 0.05 / 0.1 / only contacts taken on the tracking margin): as recorded 22.6 /
        /// 23.7 to 22.4 / 23.5 % (classifier / avatar), slow 33.3 to 32.9 %, gestures and bows shown as walking unchanged
        /// (0.05: 22.3 / 23.3 %, but one waving clip shown walking a little more). Negative turns it off.
        /// </summary>
        public double ReplaceMargin = 0.1;

        /// <summary>
        /// Whether a contact under the threshold (taken on <see cref="TrackingMargin"/> as due) may be the next contact of a
        /// walk the standing search started, where it lies within that search's own window (at or before the start). The
        /// search dated the step's contact from the window's shape, at times before the window itself; a weak peak inside the
        /// window that it did not take for a contact is no next step. False: such a peak is not taken (the walk goes on
        /// only with a contact after the start, or a full match). A waving clip (bn1 *byebye active*, its style held out) was
        /// shown walking 0.6 s longer through one such peak. Leave-one-style-out, the fold models of the measurements log's
        /// run (in-sample as a choice): gestures and bows shown as walking, avatar, 1.58 to 1.40 %, as recorded 22.43 / 23.49
        /// to 22.40 / 23.46 %, slow unchanged (31.72 %); the real glasses' walking shown 92.1 to 92.0 %, picking up 1.7 to 1.6 %.
        /// </summary>
        public bool WeakContactsInStartWindow = false;
    }

    /// <summary>
    /// COR: at every window, Pearson's r between the newest P samples of SMV minus gravity and the mean step template
    /// stretched to P samples, for each step length P searched (around the current step period while walking). The
    /// template ends at an initial contact, so r peaks when a foot has just landed: a peak above the learned threshold is
    /// a contact (dated back by the learned detection lag). Which foot comes from the lateral acceleration of the step that
    /// just ended, correlated with the mean left step; a <see cref="StepClock"/> turns the contacts into a stride position.
    /// Each window costs one dot product per step length tried, about 4,000 multiply-adds when searching all of them.
    /// Allocation-free per window.
    /// </summary>
    public sealed class CorrelationClassifier : IGaitClassifier
    {
        readonly CorrelationTemplate template;
        readonly CorrelationSettings settings;
        readonly StepClock clock;
        readonly int periods;
        readonly int startPeriods; // step lengths the standing search tries: the first StartMaxStepSamples - MinStepSamples + 1
        readonly double[][][] stepCurves;     // per template and step length P: the template at P samples, centred, unit norm
        readonly double[][][] lateralCurves;  // the same for the lateral templates
        readonly double[] prefix, prefixSq;
        readonly double[] recentR, recentEvidence, recentTime, recentSpan, recentPeak;
        readonly int[] recentTemplate;
        readonly double minCorrelation;
        readonly double[][][] startNorm; // per template, start step length and phase: the periodic template's spread over StartWindow samples
        readonly double[] centred;
        int recentCount;
        int stillWindows;
        double logBounce = double.NaN;    // the walk's bounce: log of SMV's peak over its matched steps, smoothed
        bool walkHasContact;              // whether the walk going on has taken a contact (else the next one sets the bounce)
        double onsetContact = double.NaN; // the contact a walk was started at from the start of the movement; NaN when not
        double onsetMatchedPeriod;        // the step length that start matched (s): where its first contact is searched
        double lastContactR;              // r of the last contact taken (ReplaceMargin)
        double searchStartContact = double.NaN; // the contact the standing search dated its last start at (WeakContactsInStartWindow)
        double searchStartTime = double.NaN;    // when it started that walk: the end of its window

        public CorrelationClassifier(CorrelationTemplate template, CorrelationSettings settings = null)
        {
            this.template = template ?? throw new ArgumentNullException(nameof(template));
            this.settings = settings ?? new CorrelationSettings();
            var s = this.settings;
            if (s.MinStepSamples < 8 || s.MaxStepSamples < s.MinStepSamples || s.MaxStepSamples > 400)
                throw new ArgumentException("Step search range must satisfy 8 <= MinStepSamples <= MaxStepSamples <= 400.");
            if (s.PeakConfirmSamples < 1 || s.PeakConfirmSamples > 50) throw new ArgumentException("PeakConfirmSamples must be 1..50.");
            if (s.StartMaxStepSamples < s.MinStepSamples) throw new ArgumentException("StartMaxStepSamples must be at least MinStepSamples.");
            if (s.PeriodTolerance < 0 || s.FirstStepTolerance < 0) throw new ArgumentException("PeriodTolerance and FirstStepTolerance must not be negative.");
            if (!(s.PeriodToleranceShare >= 0 && s.PeriodToleranceShare <= 1)) throw new ArgumentException("PeriodToleranceShare must be 0..1.");
            if (!(s.OnsetSpanRatio >= 0) || double.IsInfinity(s.OnsetSpanRatio)) throw new ArgumentException("OnsetSpanRatio must be a finite number, 0 or more.");
            if (double.IsNaN(s.ReplaceMargin)) throw new ArgumentException("ReplaceMargin must be a number (negative turns it off).");
            minCorrelation = double.IsNaN(s.MinCorrelationOverride) ? template.MinCorrelation : s.MinCorrelationOverride;
            var clockSettings = s.Clock.Clone();
            clockSettings.Lead = template.ClockLead;
            clockSettings.LeadPerLogBounce = template.LeadPerLogBounce;
            clockSettings.LeadReferenceBounce = template.LeadReferenceBounce;
            clock = new StepClock(template.PhaseMap, clockSettings);
            periods = s.MaxStepSamples - s.MinStepSamples + 1;
            startPeriods = Math.Min(periods, s.StartMaxStepSamples - s.MinStepSamples + 1);
            int templates = template.Templates.Count, L = s.StartWindow;
            stepCurves = new double[templates][][];
            lateralCurves = new double[templates][][];
            startNorm = new double[templates][][];
            for (int t = 0; t < templates; t++)
            {
                stepCurves[t] = new double[periods][];
                lateralCurves[t] = new double[periods][];
                startNorm[t] = new double[startPeriods][];
                for (int i = 0; i < periods; i++)
                {
                    int p = s.MinStepSamples + i;
                    stepCurves[t][i] = Normalised(template.Templates[t].Smv, p);
                    lateralCurves[t][i] = Normalised(template.Templates[t].Lateral, p);
                    if (i >= startPeriods) continue;
                    startNorm[t][i] = new double[p];
                    for (int k = 0; k < p; k++)
                    {
                        double m = 0, m2 = 0;
                        for (int j = 0; j < L; j++)
                        {
                            double v = stepCurves[t][i][Mod(k - (L - 1 - j), p)];
                            m += v;
                            m2 += v * v;
                        }
                        m /= L;
                        startNorm[t][i][k] = Math.Sqrt(Math.Max(0, m2 - L * m * m));
                    }
                }
            }
            centred = new double[L];
            prefix = new double[SearchLength + 1];
            prefixSq = new double[SearchLength + 1];
            int ring = 2 * s.PeakConfirmSamples + 1;
            recentR = new double[ring];
            recentEvidence = new double[ring];
            recentTime = new double[ring];
            recentSpan = new double[ring];
            recentPeak = new double[ring];
            recentTemplate = new int[ring];
        }

        /// <summary>The template curve resampled to p samples (the last one at the step's end), centred, unit norm.</summary>
        static double[] Normalised(double[] curve, int p)
        {
            var v = new double[p];
            double mean = 0;
            for (int j = 0; j < p; j++) mean += v[j] = CorrelationTemplate.At(curve, (j + 1.0) / p);
            mean /= p;
            double ss = 0;
            for (int j = 0; j < p; j++)
            {
                v[j] -= mean;
                ss += v[j] * v[j];
            }
            double norm = Math.Sqrt(ss);
            for (int j = 0; j < p; j++) v[j] = norm > 0 ? v[j] / norm : 0;
            return v;
        }

        public string Name => "COR";
        /// <summary>History read: the longest step searched, and what the walking gate reads.</summary>
        public int WindowLength => Math.Max(SearchLength, template.Gate.History);

        /// <summary>Newest samples the step search correlates (the longest step).</summary>
        int SearchLength => settings.MaxStepSamples;
        public PhaseMap PhaseMap => template.PhaseMap;
        public double PoseFitDelay => settings.Clock.PoseFitDelay;
        public CorrelationTemplate Template => template;
        public StepClock Clock => clock;

        /// <summary>Best Pearson r of the last window (diagnostics).</summary>
        public double LastCorrelation { get; private set; }

        /// <summary>
        /// Raised for every contact the clock takes: its time (lag-corrected), the evidence that it is the left foot's, its r
        /// and the template that matched.
        /// </summary>
        public event Action<double, double, double, int> ContactDetected;

        /// <summary>
        /// Raised with the time of the last contact taken when a stronger match takes its place (<see cref="CorrelationSettings.ReplaceMargin"/>),
        /// just before <see cref="ContactDetected"/> reports the new one: whoever lists the contacts drops it.
        /// </summary>
        public event Action<double> ContactWithdrawn;

        public void Reset()
        {
            clock.Reset();
            recentCount = 0;
            stillWindows = 0;
            onsetContact = double.NaN;
            logBounce = double.NaN;
            walkHasContact = false;
            lastContactR = 0;
            searchStartContact = searchStartTime = double.NaN;
            LastCorrelation = 0;
        }

        public GaitPrediction Classify(SignalWindow window)
        {
            int n = window.Length;
            if (n < WindowLength) throw new ArgumentException($"COR needs {WindowLength}-sample windows, got {n}.");
            double now = window.EndTime;
            var x = window.Smv;
            int o = n - SearchLength;
            prefix[0] = prefixSq[0] = 0;
            for (int i = 0; i < SearchLength; i++)
            {
                double v = x[o + i];
                prefix[i + 1] = prefix[i] + v;
                prefixSq[i + 1] = prefixSq[i] + v * v;
            }

            // The head does not move like walking: standing, whatever the shape (a walk in progress rides out a brief refusal).
            int valid = Math.Min(window.Count, SearchLength);
            double best = -1;
            int bestIndex = -1, bestTemplate = 0;
            clock.FollowRhythm(window, template.Gate.LevelTolerance);
            bool passes = template.Gate.Passes(window, out double gateLogOdds);
            // A wearer's profile may open the gate for a walk in progress (CorrelationTemplate.WalkingGateHoldShift): never for a start.
            if (!passes && template.WalkingGateHoldShift > 0 && clock.IsWalking(now)) passes = WalkingGate.ScorePasses(gateLogOdds + template.WalkingGateHoldShift);
            bool moving = passes && !clock.StartBlocked(now, gateLogOdds) || clock.HeldByRhythm(now);
            bool firstStep = !moving && clock.MayStartOnFirstStep(now, gateLogOdds);
            stillWindows = moving || firstStep ? 0 : stillWindows + 1;
            if (settings.Clock.EndsWalk(stillWindows, double.NaN, clock.RefusalStepPeriod)) clock.Stop();
            bool walkingBefore = clock.IsWalking(now);
            if (settings.Clock.ContactAllowed(moving || firstStep, walkingBefore, stillWindows, clock.RefusalStepPeriod))
            {
                int from = 0, to = Math.Min(periods - 1, valid - settings.MinStepSamples);
                if (clock.IsWalking(now) && to >= 0)
                {
                    // Until the first contact after a start at the movement's onset, around the length that start matched.
                    double searched = clock.LastContactTime == onsetContact ? onsetMatchedPeriod : clock.StepPeriod;
                    int tolerance = clock.PeriodMeasured
                        ? Math.Max(settings.PeriodTolerance, (int)Math.Round(settings.PeriodToleranceShare * searched * window.SampleRate))
                        : settings.FirstStepTolerance;
                    int centre = (int)Math.Round(searched * window.SampleRate) - settings.MinStepSamples;
                    from = Math.Max(0, Math.Min(to, centre - tolerance));
                    to = Math.Max(from, Math.Min(to, centre + tolerance));
                }
                for (int t = 0; t < stepCurves.Length; t++)
                {
                    for (int i = from; i <= to; i++)
                    {
                        double r = Correlation(x, o, stepCurves[t][i], SearchLength);
                        if (r > best)
                        {
                            best = r;
                            bestIndex = i;
                            bestTemplate = t;
                        }
                    }
                }
            }
            LastCorrelation = best;
            // The step that just ended was a left step when the lateral matches the left-step template: the foot landing now is the right one.
            double evidence = 0, span = 0, stepPeak = 0;
            if (bestIndex >= 0 && best >= minCorrelation - settings.TrackingMargin)
            {
                var lateral = lateralCurves[bestTemplate][bestIndex];
                evidence = -Correlation(window.Lateral, n - lateral.Length, lateral, lateral.Length, true);
                span = Span(x, n - lateral.Length, lateral.Length, out stepPeak);
            }
            Remember(now, best, evidence, bestTemplate, span, stepPeak);
            if (recentCount == recentR.Length)
            {
                int centre = settings.PeakConfirmSamples;
                double r = recentR[centre];
                int t = recentTemplate[centre];
                double contact = recentTime[centre] - template.Templates[t].ContactLag;
                double since = contact - clock.LastContactTime;
                // A walk not shown yet (StepClock.Hidden) is confirmed only by a full match.
                bool due = clock.IsWalking(now) && !clock.Hidden(now) && since >= settings.DueFrom * clock.StepPeriod && since <= settings.DueUntil * clock.StepPeriod;
                bool peak = r >= (due ? minCorrelation - settings.TrackingMargin : minCorrelation) && recentSpan[centre] >= settings.MinStepSpan;
                // A weak peak inside the window of the standing search that started this walk: that search saw no contact there.
                if (peak && r < minCorrelation && !settings.WeakContactsInStartWindow && clock.LastContactTime == searchStartContact && contact <= searchStartTime) peak = false;
                for (int i = 0; peak && i < recentR.Length; i++)
                    if (i != centre && (recentR[i] > r || (recentR[i] == r && i < centre))) peak = false;
                bool walking = clock.IsWalking(now);
                bool taken = peak && clock.Contact(contact, recentEvidence[centre]);
                // A full match too soon after a weaker contact to be a step of its own: that one was a bump of this step.
                if (!taken && peak && settings.ReplaceMargin >= 0 && r >= minCorrelation && r >= lastContactR + settings.ReplaceMargin)
                {
                    double withdrawn = clock.LastContactTime;
                    taken = clock.ReplaceLastContact(contact, recentEvidence[centre]);
                    if (taken) ContactWithdrawn?.Invoke(withdrawn);
                }
                if (taken)
                {
                    lastContactR = r;
                    TrackBounce(recentPeak[centre], !walking || !walkHasContact);
                    ContactDetected?.Invoke(contact, recentEvidence[centre], r, t);
                }
            }
            if (!clock.IsWalking(now) && settings.StartMargin >= 0 && (moving || firstStep)) TryStart(window, now, valid);
            clock.FollowFirstStep(now, firstStep, walkingBefore, gateLogOdds);
            return clock.Predict(now, Math.Max(0, best));
        }

        static int Mod(int a, int p) => ((a % p) + p) % p;

        /// <summary>
        /// The standing search: the newest StartWindow samples against the template repeated at every step length up to
        /// StartMaxStepSamples and every phase (coarse grid, then its neighbours). A clear match starts the clock at the
        /// phase found (at the typical step period when the window holds the onset of the movement, <see cref="CorrelationSettings.OnsetSpanRatio"/>),
        /// with the side from the lateral acceleration of the step in progress and the one before it (mirrored).
        /// </summary>
        void TryStart(SignalWindow window, double now, int valid)
        {
            int L = settings.StartWindow;
            if (valid < L) return;
            var x = window.Smv;
            int first = window.Length - L;
            if (Span(x, first, L) < settings.MinStepSpan) return;
            double mean = 0;
            for (int j = 0; j < L; j++) mean += x[first + j];
            mean /= L;
            double ss = 0;
            for (int j = 0; j < L; j++)
            {
                centred[j] = x[first + j] - mean;
                ss += centred[j] * centred[j];
            }
            if (ss <= 1e-12) return;
            double norm = Math.Sqrt(ss), bestR = -1;
            int bestT = -1, bestI = -1, bestK = 0;
            for (int t = 0; t < stepCurves.Length; t++)
            {
                // A coarse grid over step length and phase, then the neighbours of its best point.
                double tr = -1;
                int ti = -1, tk = 0;
                for (int pass = 0; pass < 2; pass++)
                {
                    int iFrom = pass == 0 ? 0 : Math.Max(0, ti - 1), iTo = pass == 0 ? startPeriods - 1 : Math.Min(startPeriods - 1, ti + 1);
                    int stride = pass == 0 ? 2 : 1;
                    int ci = ti, ck = tk;
                    for (int i = iFrom; i <= iTo; i += stride)
                    {
                        var curve = stepCurves[t][i];
                        int p = curve.Length;
                        int kFrom = pass == 0 ? 0 : ck * p / stepCurves[t][ci].Length - 2, kTo = pass == 0 ? p - 1 : kFrom + 4;
                        for (int k = kFrom; k <= kTo; k += stride)
                        {
                            int km = Mod(k, p);
                            if (startNorm[t][i][km] <= 1e-12) continue;
                            // The curve read cyclically from km - (L - 1): an index that wraps, not two modulos per product.
                            double dot = 0;
                            for (int j = 0, c = Mod(km - (L - 1), p); j < L; j++)
                            {
                                dot += centred[j] * curve[c];
                                if (++c == p) c = 0;
                            }
                            double r = dot / (norm * startNorm[t][i][km]);
                            if (r > tr)
                            {
                                tr = r;
                                ti = i;
                                tk = km;
                            }
                        }
                    }
                    if (ti < 0) break;
                }
                if (ti >= 0 && tr > bestR)
                {
                    bestR = tr;
                    bestT = t;
                    bestI = ti;
                    bestK = tk;
                }
            }
            if (bestT < 0) return;
            if (bestR < minCorrelation + settings.StartMargin) return;
            var lateral = lateralCurves[bestT][bestI];
            int period = lateral.Length;
            int sinceContact = (bestK + 1) % period; // samples since the step's initial contact (index P-1 is the contact)
            // Hypothesis: the last contact was the left foot's, so the step in progress is a left step and the one before a right step.
            double lm = 0;
            for (int j = 0; j < L; j++) lm += window.Lateral[first + j];
            lm /= L;
            double dotL = 0, nl = 0, nt = 0;
            for (int j = 0; j < L; j++)
            {
                int back = L - 1 - j;
                double t = lateral[Mod(bestK - back, period)] * (back < sinceContact ? 1 : -1);
                double v = window.Lateral[first + j] - lm;
                dotL += v * t;
                nl += v * v;
                nt += t * t;
            }
            double leftEvidence = nl > 0 && nt > 0 ? dotL / Math.Sqrt(nl * nt) : 0;
            double contact = now - sinceContact / window.SampleRate, matched = period / window.SampleRate;
            int older = L / 2;
            bool onset = settings.OnsetSpanRatio > 0 && Span(x, first + older, L - older) >= settings.OnsetSpanRatio * Span(x, first, older);
            clock.Start(contact, leftEvidence, onset ? settings.Clock.InitialStepPeriod : matched);
            searchStartContact = contact;
            searchStartTime = now;
            walkHasContact = false;
            onsetContact = onset ? contact : double.NaN;
            onsetMatchedPeriod = matched;
        }

        /// <summary>
        /// Adds a contact's step peak (SMV's highest over the matched step) to the walk's bounce (the first contact of a
        /// walk sets it) and leads the clock for it (<see cref="StepClock.FollowBounce"/>, at the template's
        /// <see cref="CorrelationTemplate.LeadPerLogBounce"/>). The peak, as THR's step peaks, rather than the step's span:
        /// leave-one-style-out 23.8 against 24.1 % (the span's slope, fitted without the bouncy *bn act* walkers, was nil).
        /// </summary>
        void TrackBounce(double stepPeak, bool firstOfWalk)
        {
            double log = Math.Log(Math.Max(MinBounce, stepPeak));
            logBounce = firstOfWalk || double.IsNaN(logBounce) ? log : (1 - BounceWeight) * logBounce + BounceWeight * log;
            walkHasContact = true;
            clock.FollowBounce(WalkBounce);
        }

        /// <summary>Weight of each new contact's step peak in the walk's bounce (an exponential average of logs).</summary>
        const double BounceWeight = 0.3;
        const double MinBounce = 0.1;

        /// <summary>The walk's bounce (m/s^2): SMV's peak over its matched steps, a smoothed geometric mean; NaN before a contact.</summary>
        public double WalkBounce => Math.Exp(logBounce);

        /// <summary>Highest minus lowest of <paramref name="count"/> values from <paramref name="first"/>.</summary>
        static double Span(double[] v, int first, int count) => Span(v, first, count, out _);

        /// <summary>Highest minus lowest of <paramref name="count"/> values from <paramref name="first"/>; <paramref name="highest"/> the highest (0 when none).</summary>
        static double Span(double[] v, int first, int count, out double highest)
        {
            double lo = double.PositiveInfinity, hi = double.NegativeInfinity;
            for (int i = first; i < first + count; i++)
            {
                if (v[i] < lo) lo = v[i];
                if (v[i] > hi) hi = v[i];
            }
            highest = count > 0 ? hi : 0;
            return count > 0 ? hi - lo : 0;
        }

        void Remember(double time, double r, double evidence, int templateIndex, double span, double stepPeak)
        {
            if (recentCount == recentR.Length)
            {
                Array.Copy(recentR, 1, recentR, 0, recentR.Length - 1);
                Array.Copy(recentEvidence, 1, recentEvidence, 0, recentR.Length - 1);
                Array.Copy(recentTime, 1, recentTime, 0, recentR.Length - 1);
                Array.Copy(recentTemplate, 1, recentTemplate, 0, recentR.Length - 1);
                Array.Copy(recentSpan, 1, recentSpan, 0, recentR.Length - 1);
                Array.Copy(recentPeak, 1, recentPeak, 0, recentR.Length - 1);
                recentCount--;
            }
            recentR[recentCount] = r;
            recentEvidence[recentCount] = evidence;
            recentTime[recentCount] = time;
            recentTemplate[recentCount] = templateIndex;
            recentSpan[recentCount] = span;
            recentPeak[recentCount] = stepPeak;
            recentCount++;
        }

        /// <summary>Pearson r of the newest curve.Length samples ending at window index start + length - 1 with a centred unit-norm curve.</summary>
        double Correlation(double[] signal, int start, double[] curve, int length, bool ownSums = false)
        {
            int p = curve.Length;
            int first = start + length - p;
            double dot = VectorMath.Dot(signal, first, curve, 0, p), sum, sumSq;
            if (ownSums)
            {
                sum = sumSq = 0;
                for (int j = 0; j < p; j++)
                {
                    sum += signal[first + j];
                    sumSq += signal[first + j] * signal[first + j];
                }
            }
            else
            {
                int a = length - p; // prefix sums are over the COR window
                sum = prefix[length] - prefix[a];
                sumSq = prefixSq[length] - prefixSq[a];
            }
            double ss = sumSq - sum * sum / p;
            return ss > 1e-12 ? dot / Math.Sqrt(ss) : 0;
        }

        /// <summary>Calibration never sets the correlation threshold under this.</summary>
        public const double MinCalibratedCorrelation = 0.5;

        /// <summary>
        /// Sets the correlation threshold and each template's contact lag on labelled recordings. First a replay with no
        /// threshold: the r of correlation peaks that match a true contact (within 0.15 s) and of those that do not give the
        /// threshold that best separates them. Then a replay with that threshold: each template's lag is the median time from
        /// a true contact to the peaks it detected (measured with the threshold in force, since weaker early peaks would
        /// bias it); a template with fewer than 8 matched peaks takes the median of all. Last, a replay with those lags: the
        /// least-squares slope of the contacts' offsets on the log of the walk's bounce (<see cref="WalkBounce"/>) is the
        /// clock lead's <see cref="CorrelationTemplate.LeadPerLogBounce"/>, the median bounce its reference.
        /// </summary>
        public static CorrelationTemplate Calibrate(CorrelationTemplate template, IReadOnlyList<Recording> recordings, CorrelationSettings settings = null)
        {
            var trueR = new List<double>();
            var falseR = new List<double>();
            // The probe has no threshold, so no match is full enough to take a contact's place (ReplaceMargin): with the rule,
            // any later, higher peak replaced the one before and the threshold chosen fell (style CV folds 0.77 to 0.74).
            var probeSettings = (settings ?? new CorrelationSettings()).Clone();
            probeSettings.ReplaceMargin = -1;
            Match(template.With(minCorrelation: -0.99, leadPerLogBounce: 0).WithLag(0), recordings, probeSettings, (offset, r, t, bounce) =>
            {
                if (Math.Abs(offset) <= 0.15) trueR.Add(r);
                else falseR.Add(r);
            });
            if (trueR.Count < 8) return template;
            // Threshold: minimise missed true peaks plus accepted false ones (both per true contact). Not under 0.5: a
            // weaker match is no step shape, however few false peaks a tight walking gate leaves in the training data.
            double bestThreshold = template.MinCorrelation, bestCost = double.PositiveInfinity;
            for (double th = MinCalibratedCorrelation; th <= 0.95; th += 0.01)
            {
                double missed = 0, accepted = 0;
                foreach (var r in trueR) if (r < th) missed++;
                foreach (var r in falseR) if (r >= th) accepted++;
                double cost = (missed + accepted) / trueR.Count;
                if (cost < bestCost)
                {
                    bestCost = cost;
                    bestThreshold = th;
                }
            }
            var thresholded = template.With(minCorrelation: Math.Round(bestThreshold, 2), leadPerLogBounce: 0).WithLag(0);
            var lags = new List<double>[template.Templates.Count];
            for (int k = 0; k < lags.Length; k++) lags[k] = new List<double>();
            var all = new List<double>();
            Match(thresholded, recordings, settings, (offset, r, t, bounce) =>
            {
                if (Math.Abs(offset) > 0.15) return;
                lags[t].Add(offset);
                all.Add(offset);
            });
            if (all.Count < 8) return thresholded;
            double overall = GaitMetrics.Median(all);
            var calibrated = new List<StepTemplate>();
            for (int k = 0; k < lags.Length; k++)
                calibrated.Add(thresholded.Templates[k].WithLag(Math.Max(-0.45, Math.Min(0.45, lags[k].Count >= 8 ? GaitMetrics.Median(lags[k]) : overall))));
            var lagged = thresholded.With(templates: calibrated);
            // The lead's slope: how much later, on these recordings, contacts come out for a bouncier walk.
            var bounces = new List<double>();
            var offsets = new List<double>();
            Match(lagged, recordings, settings, (offset, r, t, bounce) =>
            {
                if (Math.Abs(offset) > 0.15) return;
                offsets.Add(offset);
                bounces.Add(bounce);
            });
            return StepClock.FitBounceLead(offsets, bounces, out double slope, out double reference)
                ? lagged.With(leadPerLogBounce: slope, leadReferenceBounce: reference)
                : lagged;
        }

        /// <summary>
        /// Replays each recording and reports, for every contact the clock takes, its offset from the nearest true contact,
        /// its r, its template and the walk's bounce with it.
        /// </summary>
        static void Match(CorrelationTemplate probe, IReadOnlyList<Recording> recordings, CorrelationSettings settings, Action<double, double, int, double> onContact)
        {
            foreach (var rec in recordings)
            {
                var cor = new CorrelationClassifier(probe, settings);
                var detections = new List<(double time, double r, int template, double bounce)>();
                var pre = new StreamPreprocessor(new PreprocessorSettings { History = cor.WindowLength });
                cor.ContactDetected += (t, e, r, k) => detections.Add((t, r, k, cor.WalkBounce));
                cor.ContactWithdrawn += t => detections.RemoveAll(d => d.time == t);
                foreach (var s in rec.Samples) pre.Push(s.Imu, w => cor.Classify(w));
                var contacts = PhaseEvents.TruthContacts(rec);
                foreach (var d in detections) onContact(PhaseEvents.OffsetFromNearest(contacts, d.time), d.r, d.template, d.bounce);
            }
        }
    }
}
