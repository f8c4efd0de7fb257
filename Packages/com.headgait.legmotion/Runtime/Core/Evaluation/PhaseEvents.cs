using System;
using System.Collections.Generic;

namespace HeadGait
{
    /// <summary>The moment a foot enters a phase (Standing included).</summary>
    public readonly struct PhaseOnset
    {
        public readonly Foot Foot;
        public readonly GaitPhase Phase;
        public readonly double Time;

        public PhaseOnset(Foot foot, GaitPhase phase, double time)
        {
            Foot = foot;
            Phase = phase;
            Time = time;
        }

        public override string ToString() => $"{Foot} {GaitPhases.ShortName(Phase)} @ {Time:F3}";
    }

    public static class PhaseEvents
    {
        /// <summary>
        /// Onsets in a labelled sequence: one per change of a foot's label. The first label of the
        /// sequence is not an onset (its true start is unknown).
        /// </summary>
        public static List<PhaseOnset> Onsets(IReadOnlyList<double> times, IReadOnlyList<GaitPhase> left, IReadOnlyList<GaitPhase> right)
        {
            var list = new List<PhaseOnset>();
            for (int f = 0; f < 2; f++)
            {
                var labels = f == 0 ? left : right;
                for (int i = 1; i < labels.Count; i++)
                {
                    if (labels[i] != labels[i - 1]) list.Add(new PhaseOnset((Foot)f, labels[i], times[i]));
                }
            }
            list.Sort((a, b) => a.Time.CompareTo(b.Time));
            return list;
        }

        /// <summary>
        /// Foot contacts in a labelled sequence: a foot's phase entering stance (IC..PSW) straight from swing
        /// (ISW..TSW). Counting any swing-to-stance change, not only entries into IC, keeps a contact whose
        /// 20 ms IC phase was skipped by a prediction; a foot that was standing does not step by starting to walk.
        /// </summary>
        public static List<PhaseOnset> Contacts(IReadOnlyList<double> times, IReadOnlyList<GaitPhase> left, IReadOnlyList<GaitPhase> right)
        {
            var list = new List<PhaseOnset>();
            for (int f = 0; f < 2; f++)
            {
                var labels = f == 0 ? left : right;
                for (int i = 1; i < labels.Count; i++)
                {
                    if (GaitPhases.IsContact(labels[i - 1], labels[i]))
                        list.Add(new PhaseOnset((Foot)f, labels[i], times[i]));
                }
            }
            list.Sort((a, b) => a.Time.CompareTo(b.Time));
            return list;
        }

        /// <summary>The true foot contacts of a recording (see <see cref="Contacts"/>).</summary>
        public static List<PhaseOnset> TruthContacts(Recording recording)
        {
            ExtractTruth(recording, out var times, out var left, out var right);
            return Contacts(times, left, right);
        }

        /// <summary>Signed time from the nearest of the contacts to <paramref name="time"/> (infinity when there are none).</summary>
        public static double OffsetFromNearest(List<PhaseOnset> contacts, double time)
        {
            double nearest = double.PositiveInfinity;
            foreach (var c in contacts)
                if (Math.Abs(time - c.Time) < Math.Abs(nearest)) nearest = time - c.Time;
            return nearest;
        }

        /// <summary>Truth onsets of a recording, using only labelled rows with finite, increasing timestamps.</summary>
        public static List<PhaseOnset> TruthOnsets(Recording recording)
        {
            ExtractTruth(recording, out var t, out var l, out var r);
            return Onsets(t, l, r);
        }

        /// <summary>
        /// The labelled, finite, time-ordered rows of a recording as parallel lists. A row stamped far ahead of its
        /// neighbours (more than a second, with the next row back in order) is an outlier and left out, so that one bad
        /// timestamp does not hide every later row from scoring.
        /// </summary>
        public static void ExtractTruth(Recording recording, out List<double> times, out List<GaitPhase> left, out List<GaitPhase> right)
        {
            times = new List<double>();
            left = new List<GaitPhase>();
            right = new List<GaitPhase>();
            double last = double.NegativeInfinity;
            var rows = recording.Samples;
            for (int i = 0; i < rows.Count; i++)
            {
                var s = rows[i];
                if (!s.HasTruth || !s.Imu.IsFinite || !(s.Imu.Time > last)) continue;
                if (s.Imu.Time - last > 1.0 && i + 1 < rows.Count && rows[i + 1].Imu.Time < s.Imu.Time && rows[i + 1].Imu.Time > last) continue;
                last = s.Imu.Time;
                times.Add(s.Imu.Time);
                left.Add(s.Left);
                right.Add(s.Right);
            }
        }

        /// <summary>A step: from one foot's initial contact to the other foot's next initial contact.</summary>
        public readonly struct Step
        {
            public readonly Foot Foot;
            public readonly double Start;
            public readonly double End;

            public Step(Foot foot, double start, double end)
            {
                Foot = foot;
                Start = start;
                End = end;
            }

            public double Duration => End - Start;
        }

        /// <summary>
        /// Steps in the truth of a recording: consecutive initial contacts of alternating feet, no Standing
        /// between them, lasting between minStep and maxStep seconds.
        /// </summary>
        public static List<Step> TruthSteps(Recording recording, double minStep = 0.25, double maxStep = 1.0)
        {
            var onsets = TruthOnsets(recording);
            var steps = new List<Step>();
            PhaseOnset? lastIc = null;
            foreach (var o in onsets)
            {
                if (o.Phase == GaitPhase.Standing)
                {
                    lastIc = null;
                    continue;
                }
                if (o.Phase != GaitPhase.InitialContact) continue;
                if (lastIc.HasValue && lastIc.Value.Foot != o.Foot)
                {
                    double d = o.Time - lastIc.Value.Time;
                    if (d >= minStep && d <= maxStep) steps.Add(new Step(lastIc.Value.Foot, lastIc.Value.Time, o.Time));
                }
                lastIc = o;
            }
            return steps;
        }
    }

    /// <summary>Linear interpolation of a recording's raw channels at arbitrary times.</summary>
    public sealed class RawSignal
    {
        readonly double[] t;
        readonly double[] smv;
        readonly double[] lat;

        public RawSignal(Recording recording, double gravity = 9.80665)
        {
            var tl = new List<double>();
            var sl = new List<double>();
            var ll = new List<double>();
            double last = double.NegativeInfinity;
            foreach (var s in recording.Samples)
            {
                var a = s.Imu;
                if (!a.IsFinite || !(a.Time > last)) continue;
                last = a.Time;
                tl.Add(a.Time);
                sl.Add(a.Magnitude - gravity);
                ll.Add(a.Y);
            }
            t = tl.ToArray();
            smv = sl.ToArray();
            lat = ll.ToArray();
        }

        public int Count => t.Length;

        /// <summary>The first and last valid sample's time (0 without samples).</summary>
        public double StartTime => t.Length > 0 ? t[0] : 0;
        public double EndTime => t.Length > 0 ? t[t.Length - 1] : 0;

        public double Smv(double time) => Interp(smv, time);

        public double Lateral(double time) => Interp(lat, time);

        double Interp(double[] v, double time)
        {
            if (t.Length == 0) return 0;
            if (time <= t[0]) return v[0];
            if (time >= t[t.Length - 1]) return v[v.Length - 1];
            int i = Array.BinarySearch(t, time);
            if (i >= 0) return v[i];
            i = ~i;
            double a = (time - t[i - 1]) / (t[i] - t[i - 1]);
            return v[i - 1] + a * (v[i] - v[i - 1]);
        }
    }
}
