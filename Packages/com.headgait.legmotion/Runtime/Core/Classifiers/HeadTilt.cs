using System;

namespace HeadGait
{
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

        int countdown;

        /// <summary>Degrees the head's tilt moved over the newest <see cref="Span"/> seconds, at the last reading.</summary>
        public double Change { get; private set; }

        public void Reset()
        {
            countdown = 0;
            Change = 0;
        }

        /// <summary>Reads the tilt from <paramref name="window"/> every <see cref="EveryWindows"/> windows (call it for every window, in order).</summary>
        public void Follow(SignalWindow window)
        {
            if (countdown-- > 0) return;
            countdown = EveryWindows - 1;
            Change = ChangeOver(window, Span);
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
