using System;

namespace HeadGait
{
    /// <summary>
    /// The start on the first step (issue 31): a contact the walking gate refuses only narrowly starts a provisional walk
    /// at once, and the walk is withdrawn unless the gate passes within <see cref="ConfirmWithin"/>. The gate reads the
    /// newest 0.5 s (and a second's autocorrelation), so at a walk's first contact it still holds the standing before it
    /// and refuses: the walk then started at the next contact the gate passed, a step or more late. Used by
    /// <see cref="StepClock"/> (THR, COR); off when <see cref="Margin"/> is 0.
    /// </summary>
    public sealed class FirstStepStartSettings
    {
        /// <summary>How far below 0 the gate's log-odds may lie for a contact to start a provisional walk; 0 turns it off.</summary>
        public double Margin = 0;

        /// <summary>Seconds a provisional walk waits for the gate to pass, or for a second contact, before it is withdrawn.</summary>
        public double ConfirmWithin = 0.15;

        /// <summary>While it waits, a provisional walk is withdrawn at once when the gate's log-odds fall to minus this or below; 0: only <see cref="ConfirmWithin"/> withdraws it.</summary>
        public double KeepMargin = 0;

        /// <summary>
        /// Seconds after the last walk shown within which a provisional walk may start (a walk resumed after a turn or a
        /// pause); 0: at any time.
        /// </summary>
        public double ResumeWithin = 0;

        public bool Enabled => Margin > 0;

        public FirstStepStartSettings Clone() => (FirstStepStartSettings)MemberwiseClone();
    }

    /// <summary>The state of a provisional walk (<see cref="FirstStepStartSettings"/>): when it began, and whether it still waits for the gate.</summary>
    public sealed class FirstStepStart
    {
        readonly FirstStepStartSettings settings;
        double since = double.NaN; // when the provisional walk began; NaN when none waits

        public FirstStepStart(FirstStepStartSettings settings) => this.settings = settings ?? new FirstStepStartSettings();

        public FirstStepStartSettings Settings => settings;

        /// <summary>Whether a provisional walk waits for the gate.</summary>
        public bool Waiting => !double.IsNaN(since);

        /// <summary>Whether a contact now may start a provisional walk: none under way, and the gate refuses by less than the margin.</summary>
        public bool Allows(bool walking, double gateLogOdds, double sinceLastWalk)
            => settings.Enabled && !walking && gateLogOdds > -settings.Margin && (settings.ResumeWithin <= 0 || sinceLastWalk <= settings.ResumeWithin);

        /// <summary>A provisional walk began at <paramref name="now"/>.</summary>
        public void Begin(double now) => since = now;

        /// <summary>
        /// After each window of a provisional walk: confirmed (true, and no longer provisional) once the gate's regression
        /// passes (<paramref name="gateLogOdds"/> &gt; 0); false when it should be withdrawn (the gate has not passed within
        /// <see cref="FirstStepStartSettings.ConfirmWithin"/>, or refuses by <see cref="FirstStepStartSettings.KeepMargin"/> or more).
        /// </summary>
        public bool Keeps(double now, double gateLogOdds)
        {
            if (!Waiting) return true;
            if (gateLogOdds > 0)
            {
                since = double.NaN;
                return true;
            }
            if (now - since <= settings.ConfirmWithin && !(settings.KeepMargin > 0 && gateLogOdds <= -settings.KeepMargin)) return true;
            since = double.NaN;
            return false;
        }

        /// <summary>A second contact came at a step's interval: the walk is no longer provisional.</summary>
        public void Confirm() => since = double.NaN;

        public void Reset() => since = double.NaN;
    }
}
