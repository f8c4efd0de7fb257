namespace HeadGait
{
    /// <summary>
    /// The state changes <see cref="GaitAnimatorStateMachine"/> can make, in one place, plus one from every state to Standing
    /// (a start contradicted before its foot landed, a finished gait, and the pipeline's reset after a gap or re-base all
    /// stand the avatar). The Animator Controller (<see cref="LocomotionController"/>) has more: it connects every state to
    /// every other, with no Any State transition, because Unity only sees the state of the frame's last window and must be
    /// able to follow any jump.
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

        /// <summary>Every state may go to Standing (the core's reset).</summary>
        public const LocomotionState FromEveryState = LocomotionState.Standing;

        public static bool Allowed(LocomotionState from, LocomotionState to)
        {
            if (to == FromEveryState && from != to) return true;
            foreach (var t in All)
                if (t.From == from && t.To == to) return true;
            return false;
        }
    }
}
