namespace HeadGait
{
    /// <summary>What the walking gate says of a window, as a learned classifier acts on it.</summary>
    public enum GateVerdict
    {
        /// <summary>Not walking: the window is standing whatever the model scores.</summary>
        Refuses,

        /// <summary>
        /// Refuses, while the head's rhythm holds a walk (<see cref="StepRhythm.HoldsWalk"/>): a walk in progress rides it
        /// out however long it lasts (<see cref="PhaseFilterSettings.HoldOnRhythm"/>); otherwise as <see cref="Refuses"/>.
        /// </summary>
        RefusesInStepRhythm,

        /// <summary>
        /// Refuses by less than <see cref="PhaseFilterSettings.NarrowRefusalLogOdds"/>, the head's rhythm not holding a walk:
        /// a walk in progress past its first moments rides it out as one the rhythm holds; otherwise as <see cref="Refuses"/>.
        /// </summary>
        RefusesNarrowly,

        /// <summary>May be walking: the model decides.</summary>
        Passes,

        /// <summary>
        /// Passes with log-odds of at least <see cref="PhaseFilterSettings.SureWalkingLogOdds"/>: a walk in progress is not
        /// ended on this window.
        /// </summary>
        SurelyWalking,
    }
}
