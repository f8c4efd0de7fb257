using System;
using System.Collections.Generic;

namespace HeadGait
{
    /// <summary>The activities of unlabelled real recordings (<c># activity=</c> in the header).</summary>
    public static class RealActivity
    {
        public const string Walking = "walking";
        public const string Standing = "standing";
        public const string SittingHeadMovement = "sitting_head_movement";
        public const string StandingPickup = "standing_pickup";
        public const string TimedUpAndGo = "tug";
        /// <summary>Glasses (or a headset) picked up and put on, taken off and put down: the other judges' activity, generated here (<see cref="Synthetic.PutOnGlassesGenerator"/>).</summary>
        public const string PuttingOnGlasses = "putting_on_glasses";

        /// <summary>Activities in which nobody walks, in the order reports list them: any walking shown there is wrong.</summary>
        public static readonly IReadOnlyList<string> StillActivities = new[] { Standing, SittingHeadMovement, StandingPickup, PuttingOnGlasses };

        /// <summary>The recording's activity: its <c>activity</c> header, else the one its name ends with; "" when neither says.</summary>
        public static string Of(Recording recording)
        {
            if (recording.Metadata.TryGetValue("activity", out var a) && a.Trim().Length > 0) return a.Trim().ToLowerInvariant();
            foreach (var known in new[] { SittingHeadMovement, StandingPickup, PuttingOnGlasses, Walking, Standing, TimedUpAndGo })
                if (recording.Name.EndsWith(known, StringComparison.OrdinalIgnoreCase)) return known;
            return "";
        }

        /// <summary>Who wore the sensor: the <c>subject</c> header, else the name up to its last <c>_e</c> part; else the name.</summary>
        public static string PersonOf(Recording recording)
        {
            if (recording.Metadata.TryGetValue("subject", out var s) && s.Trim().Length > 0) return s.Trim();
            int cut = recording.Name.LastIndexOf("_e", StringComparison.Ordinal);
            return cut > 0 ? recording.Name.Substring(0, cut) : recording.Name;
        }

        /// <summary>Whether <paramref name="activity"/> is one of <see cref="StillActivities"/>.</summary>
        public static bool IsStill(string activity) => ((IList<string>)StillActivities).Contains(activity);
    }

    /// <summary>
    /// How one replay of an unlabelled real recording looks against the signal's own rhythm (<see cref="RhythmReference"/>):
    /// what a wearer would see of their walking, step rate and feet, from the avatar's frames (and the classifier's
    /// predictions for the walking share). Time is weighted by the frames' spacing (each frame holds until the next, at most
    /// 0.1 s).
    /// </summary>
    public sealed class RealWorldScore
    {
        public string Recording;
        public string Person;
        public string Activity;
        public string Classifier;

        /// <summary>Time from the first frame to the last (s).</summary>
        public double Seconds;
        /// <summary>Time the signal shows walking (s).</summary>
        public double ReferenceWalkingSeconds;
        /// <summary>Of that, shown walking by the avatar (any state but Standing) and predicted walking by the classifier (s).</summary>
        public double AvatarWalkingInReference, ClassifierWalkingInReference;
        /// <summary>All time shown walking by the avatar and predicted walking by the classifier (s).</summary>
        public double AvatarWalkingSeconds, ClassifierWalkingSeconds;
        /// <summary>The avatar's foot contacts while the signal walks and the avatar walks, and the steps the signal's rate gives that time.</summary>
        public int Contacts;
        public double SignalSteps;
        /// <summary>Consecutive contacts within one walking fragment (while the signal walks), and of them those by the other foot.</summary>
        public int ConsecutiveContacts, AlternatingContacts;
        /// <summary>Runs of the avatar walking (Standing between them).</summary>
        public int Fragments;
        /// <summary>The signal's walking bouts.</summary>
        public int ReferenceBouts;
        /// <summary>
        /// Per bout that meets a standing avatar (after at least <see cref="StillBeforeBout"/> s of the signal without walking,
        /// or with the recording, and the avatar Standing <see cref="EarlyStart"/> s before the bout's first step): how long
        /// after that step the avatar leaves Standing (s; 0 when it leaves within <see cref="EarlyStart"/> before it; the
        /// bout's length when never). A bout the avatar walks into from the one before (a hold carrying it) is left out, not
        /// counted as started at once.
        /// </summary>
        public List<double> StandingStartDelays = new List<double>();
        /// <summary>The same for the classifier: bouts at whose first step it predicts standing, and how long until it predicts walking (s).</summary>
        public List<double> ClassifierStandingStartDelays = new List<double>();
        /// <summary>
        /// Every bout whose first step the replay holds, and of them those the avatar shows walking within
        /// <see cref="RealWorldSummary.StandingStarts.Within"/> s of that step (walking at some frame from the step to then):
        /// the ear-worn judge's "each straight stretch shown walking within 0.3 s of its first step", which counts the bouts
        /// after a turn or pause that the avatar walks into as well as those it meets standing.
        /// </summary>
        public int BoutsFromFirstStep, BoutsShownOnTime;

        /// <summary>Signal time without walking (s) before a bout for its start to count as a start.</summary>
        public const double StillBeforeBout = 1.0;
        /// <summary>
        /// How long before a bout's dated first step a start still counts as on time (s): the date is a smoothed edge
        /// (<see cref="RhythmReference"/>), and the first step's threshold crossing comes up to 0.27 s before it on the
        /// glasses (10th percentile), so a start on the first step itself is not taken for a walk carried from before.
        /// </summary>
        public const double EarlyStart = 0.3;
        /// <summary>The signal's median cadence (steps/min; NaN without walking).</summary>
        public double SignalCadence = double.NaN;

        /// <summary>Avatar's walking time per signal walking time; NaN without signal walking.</summary>
        public double AvatarWalkingShare => ReferenceWalkingSeconds > 0 ? AvatarWalkingInReference / ReferenceWalkingSeconds : double.NaN;
        public double ClassifierWalkingShare => ReferenceWalkingSeconds > 0 ? ClassifierWalkingInReference / ReferenceWalkingSeconds : double.NaN;
        /// <summary>Steps shown per step the signal shows, over the time both walk; NaN under 10 signal steps.</summary>
        public double CadenceRatio => SignalSteps >= 10 ? Contacts / SignalSteps : double.NaN;

        /// <summary>
        /// Scores the frames and predictions of a replay (same count, one per window, in time order) against the signal's
        /// rhythm. Contacts are the avatar's feet entering stance from swing (<see cref="PhaseEvents.Contacts"/>).
        /// </summary>
        public static RealWorldScore Of(Recording recording, RhythmReference reference, string classifier,
            IReadOnlyList<GaitPrediction> predictions, IReadOnlyList<AnimatorFrame> frames)
        {
            if (recording == null) throw new ArgumentNullException(nameof(recording));
            if (reference == null) throw new ArgumentNullException(nameof(reference));
            if (predictions.Count != frames.Count) throw new ArgumentException("One prediction per frame.");
            var score = new RealWorldScore
            {
                Recording = recording.Name,
                Person = RealActivity.PersonOf(recording),
                Activity = RealActivity.Of(recording),
                Classifier = classifier,
                ReferenceBouts = reference.Bouts.Count,
                SignalCadence = reference.MedianCadence,
            };
            int n = frames.Count;
            if (n == 0) return score;
            var times = new double[n];
            var left = new GaitPhase[n];
            var right = new GaitPhase[n];
            var walkingRef = new bool[n];
            var fragment = new int[n]; // which run of the avatar walking each frame belongs to (1, 2, ...); 0 standing
            for (int i = 0; i < n; i++)
            {
                var f = frames[i];
                times[i] = f.Time;
                left[i] = f.Left;
                right[i] = f.Right;
                walkingRef[i] = reference.IsWalking(f.Time);
                double dt = i + 1 < n ? Math.Min(0.1, Math.Max(0, frames[i + 1].Time - f.Time)) : 0;
                bool avatar = f.State != LocomotionState.Standing;
                bool clf = predictions[i].IsWalking;
                score.Seconds += dt;
                if (avatar) score.AvatarWalkingSeconds += dt;
                if (clf) score.ClassifierWalkingSeconds += dt;
                if (avatar && (i == 0 || fragment[i - 1] == 0)) score.Fragments++;
                fragment[i] = avatar ? score.Fragments : 0;
                if (!walkingRef[i]) continue;
                score.ReferenceWalkingSeconds += dt;
                if (avatar) score.AvatarWalkingInReference += dt;
                if (clf) score.ClassifierWalkingInReference += dt;
                double period = reference.StepPeriod(f.Time);
                if (avatar && period > 0) score.SignalSteps += dt / period;
            }

            // Contacts while both walk; alternation between consecutive ones of the same fragment.
            var contacts = PhaseEvents.Contacts(times, left, right);
            int previousFragment = -1;
            Foot previousFoot = Foot.Left;
            int k = 0;
            foreach (var c in contacts)
            {
                while (k + 1 < n && times[k + 1] <= c.Time) k++;
                if (!walkingRef[k] || fragment[k] == 0) continue;
                score.Contacts++;
                if (fragment[k] == previousFragment)
                {
                    score.ConsecutiveContacts++;
                    if (c.Foot != previousFoot) score.AlternatingContacts++;
                }
                previousFragment = fragment[k];
                previousFoot = c.Foot;
            }

            // Start delay: each bout that starts after at least a second without walking (or with the recording).
            double first = frames[0].Time;
            for (int b = 0; b < reference.Bouts.Count; b++)
            {
                var (start, end) = reference.Bouts[b];
                if (start >= first)
                {
                    score.BoutsFromFirstStep++;
                    if (WalksBetween(frames, start, start + RealWorldSummary.StandingStarts.Within)) score.BoutsShownOnTime++;
                }
                double before = b > 0 ? reference.Bouts[b - 1].End : double.NegativeInfinity;
                if (start - before < StillBeforeBout || start < first) continue;
                double? standing = StandingStartDelay(times, i => frames[i].State != LocomotionState.Standing, start, end);
                if (standing.HasValue) score.StandingStartDelays.Add(standing.Value);
                double? predicted = StandingStartDelay(times, i => predictions[i].IsWalking, start, end);
                if (predicted.HasValue) score.ClassifierStandingStartDelays.Add(predicted.Value);
            }
            return score;
        }

        /// <summary>Whether the avatar walks (any state but Standing) at some frame from <paramref name="from"/> to <paramref name="until"/>.</summary>
        static bool WalksBetween(IReadOnlyList<AnimatorFrame> frames, double from, double until)
        {
            foreach (var f in frames)
            {
                if (f.Time > until) break;
                if (f.Time >= from && f.State != LocomotionState.Standing) return true;
            }
            return false;
        }

        /// <summary>
        /// From a bout's first step (<paramref name="start"/>) to the first frame <paramref name="walks"/> (s; 0 for one
        /// within <see cref="EarlyStart"/> before it; the bout's length when none does); null when the frame holding
        /// <see cref="EarlyStart"/> before the first step already walks, or no frame holds there.
        /// </summary>
        static double? StandingStartDelay(double[] times, Func<int, bool> walks, double start, double end)
        {
            int at = -1;
            for (int i = 0; i < times.Length && times[i] <= start - EarlyStart; i++) at = i;
            if (at < 0 || walks(at)) return null;
            for (int i = at + 1; i < times.Length && times[i] < end; i++)
                if (walks(i)) return Math.Max(0, times[i] - start);
            return end - start;
        }
    }
}
