namespace HeadGait
{
    /// <summary>
    /// The state changes <see cref="GaitAnimatorStateMachine"/> can make, in one place, plus one from any state to Standing
    /// (a start contradicted before its foot landed, a finished gait, and the pipeline's reset after a gap or re-base all
    /// stand the avatar). The Animator Controller connects every state to every other (Unity only sees the state of the
    /// frame's last window, so it must be able to follow any jump), each taken when the <see cref="AnimatorParameters.State"/>
    /// parameter equals the target.
    /// </summary>
    public static class LocomotionTransitions
    {
        public static readonly (LocomotionState From, LocomotionState To)[] All =
        {
            (LocomotionState.Standing, LocomotionState.StartWalkLeft),
            (LocomotionState.Standing, LocomotionState.StartWalkRight),
            (LocomotionState.StartWalkLeft, LocomotionState.Walking),
            (LocomotionState.StartWalkRight, LocomotionState.Walking),
            (LocomotionState.Walking, LocomotionState.FinishWalkLeft),
            (LocomotionState.Walking, LocomotionState.FinishWalkRight),
            // Walking resumed before the closing foot landed.
            (LocomotionState.FinishWalkLeft, LocomotionState.Walking),
            (LocomotionState.FinishWalkRight, LocomotionState.Walking),
        };

        /// <summary>Every state may go to Standing (the controller's Any State transition).</summary>
        public const LocomotionState FromAnyState = LocomotionState.Standing;

        public static bool Allowed(LocomotionState from, LocomotionState to)
        {
            if (to == FromAnyState && from != to) return true;
            foreach (var t in All)
                if (t.From == from && t.To == to) return true;
            return false;
        }
    }
}
