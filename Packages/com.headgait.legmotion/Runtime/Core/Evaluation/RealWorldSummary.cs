using System;
using System.Collections.Generic;
using System.Linq;

namespace HeadGait
{
    /// <summary>
    /// One classifier's scores over a set of unlabelled real recordings (<see cref="RealWorldScore"/>), as issue 31's
    /// real-sensor table reports them: walking files' walking time shown as walking (pooled; per person, median and worst
    /// tenth), steps shown per step of the signal (median over walking files), consecutive steps alternating feet (pooled),
    /// walking fragments per walking file (median) beside the signal's own bouts, the start of bouts met standing, the still activities shown as
    /// walking, and timed up-and-go. NaN where the recordings hold nothing to measure.
    /// </summary>
    public sealed class RealWorldSummary
    {
        public string Classifier;
        public int WalkingFiles, People;
        /// <summary>Walking files' signal walking time shown walking by the avatar / predicted walking by the classifier (pooled).</summary>
        public double AvatarWalking = double.NaN, ClassifierWalking = double.NaN;
        /// <summary>Per person (their walking files together): the median and the worst tenth (10th percentile, nearest rank).</summary>
        public double PersonMedian = double.NaN, PersonWorstTenth = double.NaN;
        /// <summary>The avatar's walking share of the slower and the faster half of the people by the signal's cadence (pooled in each half).</summary>
        public double SlowerHalf = double.NaN, FasterHalf = double.NaN;
        public double CadenceRatio = double.NaN;
        public double Alternating = double.NaN;
        public double Fragments = double.NaN, ReferenceBouts = double.NaN;
        /// <summary>Bouts met by a standing avatar (<see cref="RealWorldScore.StandingStartDelays"/>), walking files and TUG.</summary>
        public StandingStarts WalkingStarts = StandingStarts.Of(Array.Empty<double>()), TugStarts = StandingStarts.Of(Array.Empty<double>());
        /// <summary>The classifier's own (<see cref="RealWorldScore.ClassifierStandingStartDelays"/>), walking files.</summary>
        public StandingStarts ClassifierStarts = StandingStarts.Of(Array.Empty<double>());
        /// <summary>Every bout, walking files and TUG: how many, and the share shown walking within <see cref="StandingStarts.Within"/> s of its first step (<see cref="RealWorldScore.BoutsShownOnTime"/>).</summary>
        public int WalkingBouts, TugBouts;
        public double WalkingBoutsOnTime = double.NaN, TugBoutsOnTime = double.NaN;
        /// <summary>Share of the walking files' time that the signal shows walking, and their median cadence (steps/min).</summary>
        public double ReferenceShare = double.NaN, SignalCadence = double.NaN;
        /// <summary>Per still activity: the avatar's and the classifier's walking share of all its time, and the signal's.</summary>
        public Dictionary<string, (double Avatar, double Classifier, double Reference)> Still = new Dictionary<string, (double, double, double)>();
        /// <summary>Timed up-and-go: the avatar's walking share of all time and of the signal's walking time; the signal's walking share.</summary>
        public double TugAvatar = double.NaN, TugAvatarOfReference = double.NaN, TugReference = double.NaN;

        public static RealWorldSummary Of(string classifier, IReadOnlyCollection<RealWorldScore> scores)
        {
            var s = new RealWorldSummary { Classifier = classifier };
            var walking = scores.Where(x => x.Activity == RealActivity.Walking).ToList();
            s.WalkingFiles = walking.Count;
            double refSeconds = walking.Sum(x => x.ReferenceWalkingSeconds);
            if (refSeconds > 0)
            {
                s.AvatarWalking = walking.Sum(x => x.AvatarWalkingInReference) / refSeconds;
                s.ClassifierWalking = walking.Sum(x => x.ClassifierWalkingInReference) / refSeconds;
            }
            var people = walking.GroupBy(x => x.Person)
                .Where(g => g.Sum(x => x.ReferenceWalkingSeconds) > 0)
                .Select(g => (Share: g.Sum(x => x.AvatarWalkingInReference) / g.Sum(x => x.ReferenceWalkingSeconds),
                              Cadence: GaitMetrics.Median(g.Select(x => x.SignalCadence).Where(c => !double.IsNaN(c)).ToList()),
                              Scores: g.ToList()))
                .ToList();
            s.People = people.Count;
            if (people.Count > 0)
            {
                var shares = people.Select(p => p.Share).OrderBy(v => v).ToList();
                s.PersonMedian = GaitMetrics.Median(shares);
                s.PersonWorstTenth = GaitMetrics.Percentile(shares, 0.1);
                var byCadence = people.OrderBy(p => p.Cadence).ToList();
                int half = byCadence.Count / 2;
                s.SlowerHalf = Pooled(byCadence.Take(half).SelectMany(p => p.Scores));
                s.FasterHalf = Pooled(byCadence.Skip(half).SelectMany(p => p.Scores));
            }
            s.CadenceRatio = GaitMetrics.Median(walking.Select(x => x.CadenceRatio).Where(v => !double.IsNaN(v)).ToList());
            int consecutive = walking.Sum(x => x.ConsecutiveContacts);
            if (consecutive > 0) s.Alternating = (double)walking.Sum(x => x.AlternatingContacts) / consecutive;
            s.Fragments = GaitMetrics.Median(walking.Select(x => (double)x.Fragments).ToList());
            s.ReferenceBouts = GaitMetrics.Median(walking.Select(x => (double)x.ReferenceBouts).ToList());
            s.WalkingStarts = StandingStarts.Of(walking.SelectMany(x => x.StandingStartDelays));
            s.ClassifierStarts = StandingStarts.Of(walking.SelectMany(x => x.ClassifierStandingStartDelays));
            (s.WalkingBouts, s.WalkingBoutsOnTime) = OnTime(walking);
            double seconds = walking.Sum(x => x.Seconds);
            if (seconds > 0) s.ReferenceShare = refSeconds / seconds;
            s.SignalCadence = GaitMetrics.Median(walking.Select(x => x.SignalCadence).Where(v => !double.IsNaN(v)).ToList());

            foreach (var g in scores.Where(x => RealActivity.IsStill(x.Activity)).GroupBy(x => x.Activity))
            {
                double total = g.Sum(x => x.Seconds);
                if (total > 0)
                    s.Still[g.Key] = (g.Sum(x => x.AvatarWalkingSeconds) / total, g.Sum(x => x.ClassifierWalkingSeconds) / total, g.Sum(x => x.ReferenceWalkingSeconds) / total);
            }
            var tug = scores.Where(x => x.Activity == RealActivity.TimedUpAndGo).ToList();
            double tugSeconds = tug.Sum(x => x.Seconds), tugRef = tug.Sum(x => x.ReferenceWalkingSeconds);
            if (tugSeconds > 0)
            {
                s.TugAvatar = tug.Sum(x => x.AvatarWalkingSeconds) / tugSeconds;
                s.TugReference = tugRef / tugSeconds;
            }
            if (tugRef > 0) s.TugAvatarOfReference = tug.Sum(x => x.AvatarWalkingInReference) / tugRef;
            s.TugStarts = StandingStarts.Of(tug.SelectMany(x => x.StandingStartDelays));
            (s.TugBouts, s.TugBoutsOnTime) = OnTime(tug);
            return s;
        }

        static (int Bouts, double Share) OnTime(IReadOnlyCollection<RealWorldScore> scores)
        {
            int bouts = scores.Sum(x => x.BoutsFromFirstStep);
            return (bouts, bouts > 0 ? (double)scores.Sum(x => x.BoutsShownOnTime) / bouts : double.NaN);
        }

        /// <summary>Delays from a bout's first step to a standing avatar leaving Standing: how many, median, 90th percentile, share within <see cref="Within"/>.</summary>
        public readonly struct StandingStarts
        {
            /// <summary>The limit: shown walking within this long of the first step (s).</summary>
            public const double Within = 0.3;

            public readonly int Count;
            public readonly double Median, Ninetieth, ShareWithin;

            StandingStarts(int count, double median, double ninetieth, double shareWithin)
            {
                Count = count;
                Median = median;
                Ninetieth = ninetieth;
                ShareWithin = shareWithin;
            }

            public static StandingStarts Of(IEnumerable<double> delays)
            {
                var sorted = delays.OrderBy(d => d).ToList();
                if (sorted.Count == 0) return new StandingStarts(0, double.NaN, double.NaN, double.NaN);
                return new StandingStarts(sorted.Count, GaitMetrics.Median(sorted), GaitMetrics.Percentile(sorted, 0.9),
                    (double)sorted.Count(d => d <= Within) / sorted.Count);
            }
        }

        static double Pooled(IEnumerable<RealWorldScore> scores)
        {
            double r = 0, a = 0;
            foreach (var x in scores)
            {
                r += x.ReferenceWalkingSeconds;
                a += x.AvatarWalkingInReference;
            }
            return r > 0 ? a / r : double.NaN;
        }
    }
}
