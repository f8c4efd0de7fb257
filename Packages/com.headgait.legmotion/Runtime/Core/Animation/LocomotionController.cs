using System.Collections.Generic;

namespace HeadGait
{
    /// <summary>
    /// Which transitions may interrupt a running Animator transition; the values of Unity's
    /// UnityEditor.Animations.TransitionInterruptionSource (UnityCsReference Editor/Mono/Animation/StateMachine.bindings.cs),
    /// which the serialized m_InterruptionSource holds.
    /// </summary>
    public enum TransitionInterruption
    {
        None = 0,
        Source = 1,
        Destination = 2,
        SourceThenDestination = 3,
        DestinationThenSource = 4,
    }

    /// <summary>One transition of the Animator Controller, with every setting Unity's AnimatorStateTransition has.</summary>
    public readonly struct LocomotionControllerTransition
    {
        public readonly LocomotionState From;
        public readonly LocomotionState To;

        public LocomotionControllerTransition(LocomotionState from, LocomotionState to)
        {
            From = from;
            To = to;
        }

        /// <summary>The one condition: this int parameter Equals <see cref="Threshold"/>.</summary>
        public string ConditionParameter => AnimatorParameters.State;

        /// <summary>The destination's <see cref="LocomotionState"/> value.</summary>
        public int Threshold => (int)To;

        /// <summary>Seconds (fixed duration): the core's blend time.</summary>
        public double Duration => LocomotionController.TransitionDuration;

        public bool HasFixedDuration => true;
        public bool HasExitTime => false;
        public double ExitTime => 0;
        public double Offset => 0;
        public TransitionInterruption InterruptionSource => LocomotionController.InterruptionSource(To);
        public bool OrderedInterruption => true;
        public bool CanTransitionToSelf => false;

        public override string ToString() => $"{From} -> {To}";
    }

    /// <summary>
    /// The Animator Controller the package ships, as data: one place for its layer, states, default state, parameters and
    /// transitions with their settings. Both the command line's YAML writer (`headgait clips`) and the editor's
    /// Tools > HeadGait > Create Animator Controller build from it.
    /// One layer whose state machine has a state per <see cref="LocomotionState"/> (named by <see cref="GaitClips.Name"/>) and
    /// a transition from every state to every other on `GaitState == target` (<see cref="Transitions"/>), so whatever
    /// states the core passed through between two frames, the Animator heads for the one it is in. Each has a fixed duration
    /// of <see cref="AnimatorSettings.BlendTime"/>, no exit time, and interruption source Destination (while it runs, the
    /// destination's own transitions may take over, so a state the core left mid-blend is left at once), except blends into
    /// Start Walk, which run to their end. No Any State transitions: how they meet a running transition (and Can Transition To
    /// Self during one) is the least documented part of Unity's Animator. Every moving state's normalized time is bound to
    /// <see cref="AnimatorParameters.StridePhase"/> ("motion time").
    /// </summary>
    public static class LocomotionController
    {
        public const string LayerName = "Base Layer";

        /// <summary>The states in the order the controller lists them (<see cref="GaitClips.All"/>).</summary>
        public static IReadOnlyList<LocomotionState> States => GaitClips.All;

        public const LocomotionState DefaultState = LocomotionState.Standing;

        /// <summary>Write Defaults on every state (Unity's default for a new state).</summary>
        public const bool WriteDefaultValues = true;

        /// <summary>The parameter that drives a state's normalized time, or null (Standing holds still).</summary>
        public static string TimeParameter(LocomotionState state) => state == LocomotionState.Standing ? null : AnimatorParameters.StridePhase;

        /// <summary>Where the Animator window draws a state: three to a row.</summary>
        public static (float X, float Y) Position(LocomotionState state)
        {
            int column = IndexOf(state);
            return (250 * (column % 3), 120 + 100 * (column / 3));
        }

        public static readonly (float X, float Y) AnyStatePosition = (50, 20);
        public static readonly (float X, float Y) EntryPosition = (50, 60);
        public static readonly (float X, float Y) ExitPosition = (800, 60);

        /// <summary>Seconds every transition blends: the core's <see cref="AnimatorSettings.BlendTime"/>.</summary>
        public static double TransitionDuration => new AnimatorSettings().BlendTime;

        /// <summary>
        /// A blend into Start Walk runs to its end (the avatar stands in a walking state one blend after the start, even when
        /// the core moved on to Walking meanwhile, which would restart the blend); every other blend yields to its
        /// destination's transitions.
        /// </summary>
        public static TransitionInterruption InterruptionSource(LocomotionState to)
            => to == LocomotionState.StartWalkLeft || to == LocomotionState.StartWalkRight ? TransitionInterruption.None : TransitionInterruption.Destination;

        /// <summary>Every state to every other state, grouped by source in <see cref="States"/> order (a state's transition priority).</summary>
        public static IEnumerable<LocomotionControllerTransition> Transitions
        {
            get
            {
                foreach (var from in GaitClips.All)
                    foreach (var to in GaitClips.All)
                        if (from != to) yield return new LocomotionControllerTransition(from, to);
            }
        }

        static int IndexOf(LocomotionState state)
        {
            for (int i = 0; i < GaitClips.All.Length; i++)
                if (GaitClips.All[i] == state) return i;
            throw new System.ArgumentOutOfRangeException(nameof(state), state, "not a locomotion state");
        }
    }
}
