using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace HeadGait
{
    /// <summary>THR's learned and chosen values; saved as a small text file (<c># headgait-thr v1</c>).</summary>
    public sealed class ThresholdSettings
    {
        public const string Magic = "# headgait-thr v1";

        /// <summary>SMV minus gravity (m/s^2) that an initial contact's rise must cross at least, however calm the walker.</summary>
        public double Floor = 0.8;

        /// <summary>
        /// The threshold also follows the walker: this fraction of the recent step peaks. A fixed level learned from bouncy
        /// training walkers would never be crossed by calm ones. With contacts dated at <see cref="DatingLevel"/>, style CV:
        /// 0.35 gave 27.7 % misclassification but step precision 94.7 %, 0.45 28.2 % and 95.2 %, 0.55 29.0 %.
        /// </summary>
        public double PeakFraction = 0.45;

        /// <summary>The detector re-arms once SMV falls below the threshold times this.</summary>
        public double RearmFraction = 0.3;

        /// <summary>Mean time from a true initial contact to the moment a detection is dated at (s); subtracted.</summary>
        public double ContactLag = 0.0;

        /// <summary>
        /// A detected contact is dated where SMV minus gravity last rose through this level (m/s^2) before it crossed the
        /// threshold, within <see cref="DatingSamples"/>; NaN dates it at the threshold crossing (files written before read
        /// so). Where on the rise a heel strike falls moves with the walker, and a threshold that follows the step peaks
        /// crosses higher up a bouncy walker's rise: the *active* walkers' contacts came 85 ms late, the others' 30 ms early.
        /// Rising through 1 g (0) sits near the foot of every style's rise. Leave-one-style-out misclassification
        /// 35.0 to 28.2 %, file CV 29.6 to 23.7 % (at 0.5 and 0.25 of the threshold: 32.6 and 29.5 %; at -0.25, 27.5 % but
        /// step precision 94.5 %; at the trough before the rise, 40.0 %; a lag growing with the threshold, 29.4 %).
        /// </summary>
        public double DatingLevel = 0;

        /// <summary>How far before the threshold crossing the dating looks for the rise (samples at 100 Hz).</summary>
        public const int DatingSamples = 30;

        /// <summary>
        /// Mean lateral acceleration over the second up to a left contact's detection (centred; right contacts mirrored in).
        /// Its correlation with the window's lateral acceleration says which foot landed. A learned curve, not a sign rule:
        /// where in the sway a crossing falls moves with style and threshold, and a single sign flips with it.
        /// </summary>
        public double[] LateralProfile = DefaultLateralProfile();

        /// <summary>
        /// Samples of the lateral profile: a second, about one stride, since the sway repeats per stride rather than per
        /// step. Leave-one-style-out against the paper's 0.5 s: misclassification 37.5 to 36.8 %, step precision 90.4 to
        /// 91.8 %, right foot 95.7 to 97.6 % (0.8, 1.1 and 1.3 s did about as well).
        /// </summary>
        public const int ProfileSamples = 100;

        /// <summary>
        /// How much longer than its second the profile is read for a walk stepping at <paramref name="stepPeriod"/> (s): by
        /// the period over the typical step (<see cref="StepClockSettings.TypicalStepPeriod"/>) for a slower walk, so the
        /// second grows to the same share of its stride; 1 at the typical step or faster. Calibration averages the profile
        /// over one second at the walkers' own paces (mostly near the typical step). Read over one second, the sway of a
        /// walk 40 % slower matched the profile badly: style CV on the held-out clips made slow (`--slow`), right foot 89.5
        /// to 94.2 % (the second corpus's *giant* 11 to 100 %), misclassification 42.3 to 39.8 %; as recorded 23.78 to
        /// 23.83 %. Calibrated stretched as well, as recorded cost more (*giant* 20.0 to 21.3 %, *bn fem* 18.1 to 18.5 %)
        /// and the slow clips gained no more.
        /// </summary>
        public static double ProfileStretch(double stepPeriod)
            => stepPeriod > StepClockSettings.TypicalStepPeriod ? stepPeriod / StepClockSettings.TypicalStepPeriod : 1;

        /// <summary>Length of the profiles written before it covered a second; they still read.</summary>
        public const int HalfSecondProfileSamples = 50;

        /// <summary>Until trained: the body sways towards the foot about to land, so lateral acceleration turns towards it.</summary>
        static double[] DefaultLateralProfile()
        {
            var p = new double[ProfileSamples];
            for (int i = 0; i < p.Length; i++)
            {
                double t = (i + 1.0 - ProfileSamples) * 0.01; // seconds before the detection (0 = it)
                p[i] = -Math.Cos(Math.PI * (t / 0.5 + 1));
            }
            return p;
        }

        public PhaseMap PhaseMap = PhaseMap.Perry;

        /// <summary>Crossings count only while the head moves like walking (learned; open by default).</summary>
        public WalkingGate Gate = WalkingGate.Open;

        /// <summary>
        /// One contact starts walking. Waiting for a second (as before) kept a little more waving out (leave-one-style-out:
        /// standing shown as walking 2.5 against 4.9 %, hand and head gestures 0.0 against 0.9 %) but showed 16 % of walking
        /// as standing, a second late at every start: step recall 88.5 against 97.0 %, misclassification 42.6 against 40.9 %.
        /// On the pose path it looks no further ahead than the fit's lag (<see cref="StepClockSettings.PoseFitDelay"/> 0),
        /// unlike COR: leave-one-style-out on the pose recordings 0 / 5 / 10 / 15 / 20 / 25 ms scored 27.8 / 27.2 / 27.0 /
        /// 27.0 / 27.4 / 28.0 %, but its step recall fell (the avatar's 96.1 / 95.8 / 94.8 / 94.7 / 94.5 %; file CV, the
        /// classifier's, 96.7 to 94.4 % at 5 ms for 23.2 to 23.0 %): the first contact of each clip, where it starts its
        /// walk, already shows the foot landed in its first walking frame. A walk from a still head after standing is shown
        /// from its second contact (<see cref="StepClockSettings.StillStartContacts"/>), and so is one within 2 s of the head's
        /// tilt moving, as in coming up from picking something up (<see cref="StepClockSettings.TiltMoveStartContacts"/>). A start takes a gate score that
        /// passed within 0.3 s (<see cref="StepClockSettings.StartGateScoreWithin"/>; 0.6 s scored the same). Within 3 s of a
        /// walk shown, a contact the gate refuses by less than 0.75 log-odds starts a provisional walk, withdrawn unless the
        /// gate passes or a second contact comes within 0.15 s, or at once where the gate's log-odds fall to -1
        /// (<see cref="FirstStepStartSettings"/>): a walker resuming after a turn or a pause is shown walking a step sooner.
        /// </summary>
        public StepClockSettings Clock = new StepClockSettings { ContactsToStart = 1, EstablishedStopAfterStillWindows = 35, StillStartContacts = 2, TiltMoveStartContacts = 2, StartGateScoreWithin = 0.3,
            FirstStep = FirstStepStartSettings.Shipped(resumeAfterShown: 0) };

        public ThresholdSettings Clone()
        {
            var c = (ThresholdSettings)MemberwiseClone();
            c.Clock = Clock.Clone();
            return c;
        }

        public string Serialize()
        {
            var ci = CultureInfo.InvariantCulture;
            return KeyValueText.Write(Magic, new[]
            {
                new KeyValuePair<string, string>("phase_map", PhaseMap.Serialize()),
                new KeyValuePair<string, string>("floor", Floor.ToString("R", ci)),
                new KeyValuePair<string, string>("peak_fraction", PeakFraction.ToString("R", ci)),
                new KeyValuePair<string, string>("rearm_fraction", RearmFraction.ToString("R", ci)),
                new KeyValuePair<string, string>("contact_lag", ContactLag.ToString("R", ci)),
                new KeyValuePair<string, string>("dating_level", DatingLevel.ToString("R", ci)),
                new KeyValuePair<string, string>("lateral_profile", Join(LateralProfile)),
                new KeyValuePair<string, string>("contacts_to_start", Clock.ContactsToStart.ToString(ci)),
                new KeyValuePair<string, string>("clock_lead", Clock.Lead.ToString("R", ci)),
                new KeyValuePair<string, string>("clock_lead_per_log_bounce", Clock.LeadPerLogBounce.ToString("R", ci)),
                new KeyValuePair<string, string>("clock_lead_reference_bounce", Clock.LeadReferenceBounce.ToString("R", ci)),
                new KeyValuePair<string, string>("walking_gate", Gate.Serialize()),
            });
        }

        static string Join(double[] v)
        {
            var sb = new StringBuilder();
            for (int i = 0; i < v.Length; i++) sb.Append(i > 0 ? "," : "").Append(v[i].ToString("G9", CultureInfo.InvariantCulture));
            return sb.ToString();
        }

        public void Save(string path) => AtomicFile.WriteAllText(path, Serialize());

        public static ThresholdSettings Load(string path) => Parse(InputLimits.ReadAllText(path, InputLimits.MaxTextModelBytes, "a text model file"), path);

        public static ThresholdSettings Parse(string text, string source = "THR settings")
        {
            var kv = KeyValueText.Parse(text, Magic, source);
            var s = new ThresholdSettings
            {
                PhaseMap = kv.PhaseMap("phase_map"),
                Floor = kv.Number("floor", 0.01, 50),
                PeakFraction = kv.Number("peak_fraction", 0, 1),
                RearmFraction = kv.Number("rearm_fraction", 0, 1),
                ContactLag = kv.Number("contact_lag", -0.45, 0.45),
                DatingLevel = kv.Has("dating_level") ? kv.Number("dating_level", -50, 50) : double.NaN,
                LateralProfile = kv.Numbers("lateral_profile", ProfileSamples, new[] { HalfSecondProfileSamples }, -1e3, 1e3),
            };
            s.Clock.ContactsToStart = (int)kv.Number("contacts_to_start", 1, 4, s.Clock.ContactsToStart);
            s.Clock.Lead = kv.Number("clock_lead", -0.49, 0.49, 0);
            s.Clock.LeadPerLogBounce = kv.Number("clock_lead_per_log_bounce", -StepClockSettings.MaxLeadPerLogBounce, StepClockSettings.MaxLeadPerLogBounce, 0);
            s.Clock.LeadReferenceBounce = kv.Number("clock_lead_reference_bounce", 1e-6, 999, StepClockSettings.DefaultLeadReferenceBounce);
            if (kv.Has("walking_gate")) s.Gate = kv.Gate("walking_gate");
            return s;
        }
    }

    /// <summary>
    /// THR: an initial contact is detected when SMV minus gravity rises through a threshold (the larger of a floor and a
    /// fraction of the recent step peaks), dated back by the learned detection lag; the side comes from the lateral
    /// acceleration just before it, relative to the window's mean. A <see cref="StepClock"/> turns the contacts into a
    /// stride position; a contact while the walking gate is open starts walking. Allocation-free per window.
    /// </summary>
    public sealed class ThresholdClassifier : IGaitClassifier
    {
        readonly ThresholdSettings settings;
        readonly StepClock clock;
        bool armed = true;
        bool fresh = true; // no window classified since the start or the last reset
        double peakLevel;      // smoothed peak of recent steps
        double currentPeak;    // peak of the step being crossed
        bool inStep;
        int stillWindows;
        double walkingSince = double.NaN; // when the walk shown now began; NaN while standing
        double datingShift; // how much earlier than its threshold crossing the last contact was dated (s)

        public ThresholdClassifier(ThresholdSettings settings = null)
        {
            this.settings = settings ?? new ThresholdSettings();
            clock = new StepClock(this.settings.PhaseMap, this.settings.Clock);
            Reset();
        }

        public string Name => "THR";
        /// <summary>History read: a second, for the sideways profile, and what the walking gate reads.</summary>
        public int WindowLength => Math.Max(ThresholdSettings.ProfileSamples, settings.Gate.History);
        public PhaseMap PhaseMap => settings.PhaseMap;
        public double PoseFitDelay => settings.Clock.PoseFitDelay;
        public ThresholdSettings Settings => settings;
        public StepClock Clock => clock;

        /// <summary>The walker's bounce: its recent step peaks (SMV minus gravity, m/s^2, smoothed); NaN before a step.</summary>
        public double WalkBounce => peakLevel > 0 ? peakLevel : double.NaN;

        /// <summary>Threshold in force after the last window (diagnostics).</summary>
        public double Threshold => Math.Max(settings.Floor, settings.PeakFraction * peakLevel);

        /// <summary>Raised for every contact the clock takes: its time (lag-corrected) and the evidence that it is the left foot's.</summary>
        public event Action<double, double> ContactDetected;

        public void Reset()
        {
            clock.Reset();
            armed = true;
            fresh = true;
            peakLevel = 0;
            currentPeak = 0;
            inStep = false;
            stillWindows = 0;
            walkingSince = double.NaN;
        }

        public GaitPrediction Classify(SignalWindow window)
        {
            int n = window.Length;
            double now = window.EndTime;
            double smv = window.Smv[n - 1];
            // Not walking: forget the walker's peaks, so the floor alone decides the next start.
            if (!clock.IsWalking(now)) peakLevel = 0;
            double threshold = Threshold;
            if (inStep) currentPeak = Math.Max(currentPeak, smv);
            if (!armed && smv < threshold * settings.RearmFraction)
            {
                armed = true;
                if (inStep)
                {
                    // A head does not bounce harder than about 3 g; larger peaks are knocks, not a walker to follow.
                    double peak = Math.Min(currentPeak, 30);
                    peakLevel = peakLevel <= 0 ? peak : 0.7 * peakLevel + 0.3 * peak;
                    inStep = false;
                }
            }
            clock.FollowRhythm(window, settings.Gate.LevelTolerance);
            bool moving = settings.Gate.Passes(window, out double gateLogOdds) && !clock.StartBlocked(now, gateLogOdds) || clock.HeldByRhythm(now);
            bool firstStep = !moving && clock.MayStartOnFirstStep(now, gateLogOdds);
            stillWindows = moving || firstStep ? 0 : stillWindows + 1;
            if (!clock.IsWalking(now)) walkingSince = double.NaN;
            else if (double.IsNaN(walkingSince)) walkingSince = now;
            if (settings.Clock.EndsWalk(stillWindows, now - walkingSince, clock.RefusalStepPeriod)) clock.Stop();
            bool walkingBefore = clock.IsWalking(now);
            // The crossing is read between the window's last two samples. The first window after a (re)start also looks
            // back over its newest half second: a stream that begins mid-step crossed before it, and that contact is
            // dated when it happened, not when the stream began.
            int ago = CrossingAge(window, threshold, fresh ? (int)Math.Round(0.5 * window.SampleRate) : 1);
            fresh = false;
            bool crossed = armed && ago >= 0 && settings.Clock.ContactAllowed(moving || firstStep, clock.IsWalking(now), stillWindows, clock.RefusalStepPeriod);
            if (crossed)
            {
                armed = false;
                double evidence = SideEvidence(window, window.Length - 1 - ago, ThresholdSettings.ProfileStretch(clock.StepPeriod));
                int crossingAge = ago;
                ago = DatedAge(window, ago);
                datingShift = (ago - crossingAge) / window.SampleRate;
                double time = now - ago / window.SampleRate - settings.ContactLag;
                if (clock.Contact(time, evidence))
                {
                    clock.FollowBounce(WalkBounce);
                    inStep = true;
                    currentPeak = smv;
                    ContactDetected?.Invoke(time, evidence);
                }
            }
            clock.FollowFirstStep(now, firstStep, walkingBefore, gateLogOdds);
            double confidence = clock.IsWalking(now) ? Math.Max(0, 1 - (now - clock.LastContactTime) / (settings.Clock.StandingAfterPeriods * clock.StepPeriod)) : 0;
            return clock.Predict(now, confidence);
        }

        /// <summary>Samples since SMV last rose through <paramref name="threshold"/> within the newest <paramref name="span"/> samples (0: just now), or -1.</summary>
        static int CrossingAge(SignalWindow window, double threshold, int span)
        {
            int n = window.Length;
            int valid = Math.Min(window.Count, n);
            for (int k = 0; k < span && k + 2 <= valid; k++)
            {
                if (window.Smv[n - 1 - k] < threshold) return -1; // below now: any earlier crossing has ended
                if (window.Smv[n - 2 - k] < threshold) return k;
            }
            return -1;
        }

        /// <summary>
        /// Samples since SMV last rose through <see cref="ThresholdSettings.DatingLevel"/> before the threshold crossing
        /// <paramref name="crossingAge"/> samples ago; the crossing's own age when the level is NaN or SMV did not dip to it.
        /// </summary>
        int DatedAge(SignalWindow window, int crossingAge)
        {
            double level = settings.DatingLevel;
            if (double.IsNaN(level)) return crossingAge;
            int n = window.Length, oldest = n - Math.Min(window.Count, n);
            int crossing = n - 1 - crossingAge;
            for (int k = 1; k <= ThresholdSettings.DatingSamples && crossing - k >= oldest; k++)
                if (window.Smv[crossing - k] <= level) return crossingAge + k - 1;
            return crossingAge;
        }

        /// <summary>
        /// Pearson r of the second of lateral acceleration up to window index <paramref name="end"/> (the threshold
        /// crossing) with the left-contact profile (its mean removes head tilt). Read up to the crossing rather than the
        /// dated contact: style CV right foot 98.3 against 96.9 %, step precision 96.3 against 95.2 %.
        /// </summary>
        double SideEvidence(SignalWindow window, int end, double stretch)
        {
            var p = settings.LateralProfile;
            int oldest = window.Length - Math.Min(window.Count, window.Length);
            // Profile sample i lies (m - 1 - i) * stretch window samples before the crossing (interpolated between two).
            int m = Math.Min(p.Length, (int)Math.Floor((end - oldest) / stretch) + 1);
            if (m < 2) return 0;
            int pf = p.Length - m;
            double LateralAt(int i)
            {
                double x = end - (m - 1 - i) * stretch;
                int k = (int)Math.Floor(x);
                double f = x - k;
                return f > 1e-9 && k < end ? (1 - f) * window.Lateral[k] + f * window.Lateral[k + 1] : window.Lateral[k];
            }
            double lm = 0, pm = 0;
            for (int i = 0; i < m; i++)
            {
                lm += LateralAt(i);
                pm += p[pf + i];
            }
            lm /= m;
            pm /= m;
            double dot = 0, ll = 0, pp = 0;
            for (int i = 0; i < m; i++)
            {
                double a = LateralAt(i) - lm, b = p[pf + i] - pm;
                dot += a * b;
                ll += a * a;
                pp += b * b;
            }
            return ll > 0 && pp > 0 ? dot / Math.Sqrt(ll * pp) : 0;
        }

        /// <summary>
        /// Learns THR from labelled recordings: the floor from the quietest steps' peaks, the detection lag (median time
        /// from a true contact to the moment its detection is dated) and the mean sideways acceleration up to a left
        /// contact's detection (right contacts mirrored in); then how much later a bouncier walker's contacts come out
        /// (<see cref="StepClockSettings.LeadPerLogBounce"/>, against its recent step peaks, <see cref="WalkBounce"/>).
        /// </summary>
        public static ThresholdSettings Calibrate(IEnumerable<Recording> training, PhaseMap map, WalkingGate gate, ThresholdSettings start = null)
        {
            var s = (start ?? new ThresholdSettings()).Clone();
            s.PhaseMap = map ?? s.PhaseMap;
            s.Gate = gate ?? s.Gate;
            var peaks = new List<double>();
            var list = new List<Recording>(training);
            foreach (var rec in list)
            {
                var raw = new RawSignal(rec);
                foreach (var step in PhaseEvents.TruthSteps(rec))
                {
                    double peak = double.NegativeInfinity;
                    for (int k = 0; k <= 30; k++) peak = Math.Max(peak, raw.Smv(step.Start + 0.01 * k));
                    peaks.Add(peak);
                }
            }
            if (peaks.Count < 8) return s;
            peaks.Sort();
            // Half the peak of the quietest 2 % of (augmented) steps: calm walkers cross it; the gate keeps gestures out.
            s.Floor = Math.Max(0.3, 0.5 * peaks[(int)(0.02 * (peaks.Count - 1))]);
            // Lag from a replay with the learned floor; then the lateral profile up to where true contacts are detected.
            var lags = new List<double>();
            var shifts = new List<double>();
            var probe = s.Clone();
            probe.ContactLag = 0;
            Match(probe, list, (offset, thr) =>
            {
                shifts.Add(thr.datingShift);
                if (Math.Abs(offset) <= 0.2) lags.Add(offset);
            });
            if (lags.Count >= 8) s.ContactLag = Math.Max(-0.45, Math.Min(0.45, GaitMetrics.Median(lags)));
            // The profile ends where contacts are detected: the dated contact plus how much earlier than its crossing it was dated.
            double shift = shifts.Count > 0 ? GaitMetrics.Median(shifts) : 0;
            var profile = new double[ThresholdSettings.ProfileSamples];
            var segment = new double[profile.Length];
            int used = 0;
            foreach (var rec in list)
            {
                var raw = new RawSignal(rec);
                foreach (var c in PhaseEvents.TruthContacts(rec))
                {
                    double end = c.Time + s.ContactLag + shift, mean = 0;
                    for (int i = 0; i < segment.Length; i++) mean += segment[i] = raw.Lateral(end - (segment.Length - 1 - i) * 0.01);
                    mean /= segment.Length;
                    double sign = c.Foot == Foot.Left ? 1 : -1;
                    for (int i = 0; i < segment.Length; i++) profile[i] += sign * (segment[i] - mean);
                    used++;
                }
            }
            if (used >= 8)
            {
                for (int i = 0; i < profile.Length; i++) profile[i] /= used;
                s.LateralProfile = profile;
            }
            // Last, with the lag and profile in force: how much later a bouncier walker's contacts come out.
            var offsets = new List<double>();
            var bounces = new List<double>();
            var fitted = s.Clone();
            fitted.Clock.LeadPerLogBounce = 0;
            Match(fitted, list, (offset, thr) =>
            {
                if (Math.Abs(offset) > 0.15) return;
                offsets.Add(offset);
                bounces.Add(thr.WalkBounce);
            });
            if (StepClock.FitBounceLead(offsets, bounces, out double perLogBounce, out double reference))
            {
                s.Clock.LeadPerLogBounce = perLogBounce;
                s.Clock.LeadReferenceBounce = reference;
            }
            return s;
        }

        /// <summary>
        /// Replays each recording through THR with <paramref name="probe"/> and reports, for every contact its clock takes,
        /// the offset from the nearest true contact and the classifier as it stands then.
        /// </summary>
        static void Match(ThresholdSettings probe, IEnumerable<Recording> recordings, Action<double, ThresholdClassifier> onContact)
        {
            foreach (var rec in recordings)
            {
                var thr = new ThresholdClassifier(probe);
                var contacts = PhaseEvents.TruthContacts(rec);
                thr.ContactDetected += (t, e) => onContact(PhaseEvents.OffsetFromNearest(contacts, t), thr);
                var pre = new StreamPreprocessor(new PreprocessorSettings { History = thr.WindowLength });
                foreach (var r in rec.Samples) pre.Push(r.Imu, w => thr.Classify(w));
            }
        }
    }
}
