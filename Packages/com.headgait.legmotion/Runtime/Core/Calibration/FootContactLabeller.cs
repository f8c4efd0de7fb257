using System;
using System.Collections.Generic;
using HeadGait.Mocap;

namespace HeadGait.Calibration
{
    /// <summary>
    /// Labels each foot's gait phases from the pose stream of a tracked device strapped above its ankle, the way the
    /// motion-capture converter labels them from the foot joints (<see cref="MocapConverter"/>): the device's position
    /// spline-resampled onto the head recording's clock, low-passed (4th-order zero-phase Butterworth at 12 Hz) and
    /// differentiated; the foot is down while the device is within <see cref="ContactHeight"/> of its floor level and slower
    /// than <see cref="ContactSpeed"/>; stance and swing split by Perry's proportions; standing where both feet stay down
    /// for half a second. An ankle alone lifts at heel rise, before the toe leaves the floor, so its contact height is
    /// higher than the converter's 4 cm for ankle or toe and its stance ends <see cref="ToeOffDelay"/> after the ankle lifts
    /// (both fitted to the converter's labels, see the constants).
    /// </summary>
    public static class FootContactLabeller
    {
        /// <summary>
        /// Height above the device's floor level (m) under which its foot counts as down. Six real-motion walks (three
        /// styles of each corpus) through <see cref="MocapConverter.ConvertAnkles"/> at 72 Hz, per-foot samples labelled as
        /// the converter labels them from ankle and toe, with <see cref="ToeOffDelay"/>: 3 / 4 / 6 / 8 cm 86.6 / 87.4 /
        /// 92.0 / 92.1 % (the converter's own labels against the files': 94.5 %); initial contacts 1 ms from the converter's.
        /// </summary>
        public const double ContactHeight = 0.08;

        /// <summary>Speed (m/s) under which the foot counts as down (0.6 / 0.9 / 1.2 at 8 cm without the delay: 71.1 / 79.5 / 78.0 %).</summary>
        public const double ContactSpeed = 0.9;

        /// <summary>
        /// How long (s) after the ankle leaves the floor the foot's stance is taken to end: the heel rises before the toes
        /// leave (0 / 30 / 50 / 70 / 90 / 120 ms at 8 cm: 79.5 / 88.1 / 91.3 / 92.1 / 88.6 / 80.5 %). Delaying every label
        /// instead (the contact too) reached 86.3 % with the contacts 30 ms late.
        /// </summary>
        public const double ToeOffDelay = 0.07;

        /// <summary>Both feet down for at least this long (s) is standing (as the converter).</summary>
        public const double StandingSeconds = 0.5;

        /// <summary>Longest gap between two device poses that is bridged (s); a longer one (tracking lost) is refused.</summary>
        public const double MaxGapSeconds = 0.25;

        const double LowPassHz = 12;

        /// <summary>
        /// The head recording labelled from the two ankle streams (same clock as the head's samples). Throws an
        /// <see cref="ArgumentException"/> naming the stream when one is too short, out of order, does not cover the
        /// head recording, or loses tracking for longer than <see cref="MaxGapSeconds"/>.
        /// </summary>
        public static Recording Label(Recording head, IReadOnlyList<PoseSample> leftAnkle, IReadOnlyList<PoseSample> rightAnkle, double contactHeight = ContactHeight, double contactSpeed = ContactSpeed, double toeOff = ToeOffDelay)
        {
            if (head == null) throw new ArgumentNullException(nameof(head));
            int n = head.Samples.Count;
            if (n < 50) throw new ArgumentException($"{head.Name}: the head recording holds {n} samples, too few to calibrate on.");
            var times = new double[n];
            for (int i = 0; i < n; i++) times[i] = head.Samples[i].Imu.Time;
            double rate = (n - 1) / Math.Max(1e-9, times[n - 1] - times[0]);
            var left = Contacts(leftAnkle, times, rate, "left ankle", contactHeight, contactSpeed, toeOff);
            var right = Contacts(rightAnkle, times, rate, "right ankle", contactHeight, contactSpeed, toeOff);
            double dt = 1 / rate;
            var labelsLeft = MocapConverter.PhasesFromContact(left, dt);
            var labelsRight = MocapConverter.PhasesFromContact(right, dt);
            var walking = MocapConverter.WalkingBouts(left, right, dt, StandingSeconds);
            var samples = new List<RecordedSample>(n);
            for (int i = 0; i < n; i++)
                samples.Add(new RecordedSample(head.Samples[i].Imu, walking[i] ? labelsLeft[i] : GaitPhase.Standing, walking[i] ? labelsRight[i] : GaitPhase.Standing, head.Samples[i].Line));
            var labelled = new Recording(head.Name, samples);
            foreach (var kv in head.Metadata) labelled.Metadata[kv.Key] = kv.Value;
            labelled.Metadata["labels"] = "from two ankle-strapped tracked devices (headgait calibration)";
            return labelled;
        }

        /// <summary>Share of per-foot samples of <paramref name="labelled"/> whose label equals <paramref name="reference"/>'s at the same time (NaN when none compare).</summary>
        public static double Agreement(Recording labelled, Recording reference)
        {
            var cursor = new LabelCursor(reference);
            long same = 0, total = 0;
            foreach (var s in labelled.Samples)
            {
                if (!s.HasTruth || !cursor.TryLabelsAt(s.Imu.Time, out var truth) || !truth.HasTruth) continue;
                same += (s.Left == truth.Left ? 1 : 0) + (s.Right == truth.Right ? 1 : 0);
                total += 2;
            }
            return total > 0 ? (double)same / total : double.NaN;
        }

        /// <summary>Whether the foot is down at each of <paramref name="times"/>.</summary>
        static bool[] Contacts(IReadOnlyList<PoseSample> poses, double[] times, double rate, string name, double contactHeight, double contactSpeed, double toeOff)
        {
            if (poses == null || poses.Count < 20) throw new ArgumentException($"The {name} stream holds {poses?.Count ?? 0} poses, too few to label steps from.");
            int m = poses.Count;
            var t = new double[m];
            var axes = new[] { new double[m], new double[m], new double[m] };
            for (int i = 0; i < m; i++)
            {
                var p = poses[i];
                t[i] = p.Time;
                if (i > 0 && !(t[i] > t[i - 1])) throw new ArgumentException($"The {name} stream's times do not increase at pose {i + 1} ({t[i - 1]:F4} then {t[i]:F4} s).");
                if (i > 0 && t[i] - t[i - 1] > MaxGapSeconds) throw new ArgumentException($"The {name} stream loses tracking for {t[i] - t[i - 1]:F2} s at {t[i - 1]:F2} s (at most {MaxGapSeconds} s is bridged).");
                axes[0][i] = p.Px;
                axes[1][i] = p.Py;
                axes[2][i] = p.Pz;
            }
            int n = times.Length;
            if (t[0] > times[0] + MaxGapSeconds || t[m - 1] < times[n - 1] - MaxGapSeconds)
                throw new ArgumentException($"The {name} stream covers {t[0]:F2} to {t[m - 1]:F2} s, the head recording {times[0]:F2} to {times[n - 1]:F2} s: they must be recorded together.");
            var filter = new ButterworthLowPass(4, Math.Min(LowPassHz, 0.45 * rate), rate);
            var grid = new double[3][];
            for (int k = 0; k < 3; k++)
            {
                var spline = new NaturalCubicSpline(t, axes[k]);
                var v = new double[n];
                for (int i = 0; i < n; i++) v[i] = spline.Value(Math.Max(t[0], Math.Min(t[m - 1], times[i])));
                grid[k] = filter.FilterForwardBackward(v);
            }
            // Tracking space: y is up.
            var height = grid[1];
            var sorted = (double[])height.Clone();
            Array.Sort(sorted);
            double floor = sorted[(int)(0.01 * (n - 1))];
            var contact = new bool[n];
            for (int i = 0; i < n; i++)
            {
                int a = Math.Max(0, i - 1), b = Math.Min(n - 1, i + 1);
                double span = Math.Max(1e-9, times[b] - times[a]), speed2 = 0;
                for (int k = 0; k < 3; k++)
                {
                    double d = (grid[k][b] - grid[k][a]) / span;
                    speed2 += d * d;
                }
                contact[i] = height[i] - floor < contactHeight && Math.Sqrt(speed2) < contactSpeed;
            }
            // The foot stays down a little after the ankle lifts (heel rise): each contact's end is pushed back.
            int extension = (int)Math.Round(toeOff * rate);
            var extended = new bool[n];
            int lastDown = int.MinValue / 2;
            for (int i = 0; i < n; i++)
            {
                if (contact[i]) lastDown = i;
                extended[i] = contact[i] || i - lastDown <= extension;
            }
            return extended;
        }
    }
}
