namespace HeadGait
{
    /// <summary>
    /// The Animator Controller parameters the package writes: one place for their names, shared by the component that
    /// writes them, the generated controller and the asset checks.
    /// </summary>
    public static class AnimatorParameters
    {
        /// <summary>int: <see cref="LocomotionState"/> (0 Standing, 1 StartWalkLeft, 2 StartWalkRight, 3 Walking, 4 FinishWalkLeft, 5 FinishWalkRight).</summary>
        public const string State = "GaitState";

        /// <summary>float 0..1: position in the stride, 0 = left initial contact; the Walking state's motion time.</summary>
        public const string StridePhase = "StridePhase";

        /// <summary>float 0..1: how much of the walking animation shows (blends to standing).</summary>
        public const string WalkWeight = "WalkWeight";

        /// <summary>float, seconds: the current step period (for playback speed of start and finish clips).</summary>
        public const string StepPeriod = "StepPeriod";

        public static readonly string[] All = { State, StridePhase, WalkWeight, StepPeriod };

        /// <summary>Whether a parameter is an int (<see cref="State"/>) rather than a float.</summary>
        public static bool IsInteger(string name) => name == State;
    }
}
