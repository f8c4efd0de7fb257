using System.Collections.Generic;
using System.Text;

namespace HeadGait.Tooling
{
    /// <summary>
    /// Writes the Animator Controller (.controller) the package ships: one layer whose state machine has a state per
    /// <see cref="LocomotionState"/> (named by <see cref="GaitClips.Name"/>), the parameters of
    /// <see cref="AnimatorParameters"/> (m_Type 1 float, 3 int), and a transition from every state to every other state on
    /// `GaitState == target` (m_ConditionMode 6 Equals, m_EventTreshold the target's value; <see cref="Transitions"/>), so
    /// whatever states the core passed through between two frames, the Animator heads for the one it is in. Each has a
    /// fixed duration of <see cref="AnimatorSettings.BlendTime"/>, no exit time, and interruption source Destination
    /// (m_InterruptionSource 2): while it runs, the destination's own transitions may take over, so a state the core left
    /// mid-blend is left at once. No Any State transitions: how they meet a running transition (and Can Transition To Self
    /// during one) is the least documented part of Unity's Animator. Every moving state's normalized time is bound to
    /// <see cref="AnimatorParameters.StridePhase"/> (m_TimeParameterActive / m_TimeParameter: "motion time"). Field layout as in
    /// controllers saved by Unity 2019-2022 in public projects (AnimatorState serializedVersion 6, AnimatorStateTransition
    /// serializedVersion 3, AnimatorStateMachine serializedVersion 6, AnimatorController serializedVersion 5).
    /// The evidence that this cannot be skipped past is `headgait animator-check` (dotnet/Shared/AnimatorCheck).
    /// </summary>
    public static class GaitControllerYaml
    {
        public const long ControllerId = 9100000;
        public const int ConditionEquals = 6;
        public const int FloatType = 1;
        public const int IntType = 3;
        /// <summary>TransitionInterruptionSource.Destination (UnityCsReference Editor/Mono/Animation/StateMachine.bindings.cs).</summary>
        public const int InterruptedByDestination = 2;

        /// <summary>TransitionInterruptionSource.None.</summary>
        public const int Uninterruptible = 0;

        /// <summary>
        /// A blend into Start Walk runs to its end (the avatar stands in a walking state one blend after the start, even when
        /// the core moved on to Walking meanwhile, which would restart the blend); every other blend yields to its
        /// destination's transitions.
        /// </summary>
        public static int InterruptionSource(LocomotionState to)
            => to == LocomotionState.StartWalkLeft || to == LocomotionState.StartWalkRight ? Uninterruptible : InterruptedByDestination;

        /// <summary>The controller's transitions: every state to every other state, in <see cref="GaitClips.All"/> order.</summary>
        public static IEnumerable<(LocomotionState From, LocomotionState To)> Transitions
        {
            get
            {
                foreach (var from in GaitClips.All)
                    foreach (var to in GaitClips.All)
                        if (from != to) yield return (from, to);
            }
        }

        public static long StateMachineId => UnityYaml.StableFileId("controller/Base Layer");
        public static long StateId(LocomotionState s) => UnityYaml.StableFileId("controller/state/" + s);
        static long TransitionId(string from, LocomotionState to) => UnityYaml.StableFileId("controller/transition/" + from + "/" + to);

        /// <param name="clipGuids">The GUID of each state's clip (.anim main object 7400000).</param>
        public static string Write(IReadOnlyDictionary<LocomotionState, string> clipGuids, string name = "HeadGait Legs")
        {
            var sb = new StringBuilder(UnityYaml.Header);
            sb.Append(UnityYaml.Document(91, ControllerId, "AnimatorController"));
            Common(sb, 0);
            sb.Append("  m_Name: ").Append(name).Append("\n  serializedVersion: 5\n  m_AnimatorParameters:\n");
            foreach (var p in AnimatorParameters.All)
            {
                sb.Append("  - m_Name: ").Append(p).Append('\n');
                sb.Append("    m_Type: ").Append(AnimatorParameters.IsInteger(p) ? IntType : FloatType).Append('\n');
                sb.Append("    m_DefaultFloat: 0\n    m_DefaultInt: 0\n    m_DefaultBool: 0\n    m_Controller: {fileID: ").Append(ControllerId).Append("}\n");
            }
            sb.Append("  m_AnimatorLayers:\n  - serializedVersion: 5\n    m_Name: Base Layer\n");
            sb.Append("    m_StateMachine: ").Append(UnityYaml.Ref(StateMachineId)).Append('\n');
            sb.Append("    m_Mask: {fileID: 0}\n    m_Motions: []\n    m_Behaviours: []\n    m_BlendingMode: 0\n    m_SyncedLayerIndex: -1\n");
            sb.Append("    m_DefaultWeight: 0\n    m_IKPass: 0\n    m_SyncedLayerAffectsTiming: 0\n    m_Controller: {fileID: ").Append(ControllerId).Append("}\n");

            // The state machine: Standing is the default.
            sb.Append(UnityYaml.Document(1107, StateMachineId, "AnimatorStateMachine"));
            sb.Append("  serializedVersion: 6\n");
            Common(sb, 1);
            sb.Append("  m_Name: Base Layer\n  m_ChildStates:\n");
            int column = 0;
            foreach (var s in GaitClips.All)
            {
                sb.Append("  - serializedVersion: 1\n    m_State: ").Append(UnityYaml.Ref(StateId(s))).Append('\n');
                sb.Append("    m_Position: ").Append(UnityYaml.Vector(250 * (column % 3), 120 + 100 * (column / 3), 0)).Append('\n');
                column++;
            }
            sb.Append("  m_ChildStateMachines: []\n  m_AnyStateTransitions: []\n");
            sb.Append("  m_EntryTransitions: []\n  m_StateMachineTransitions: {}\n  m_StateMachineBehaviours: []\n");
            sb.Append("  m_AnyStatePosition: {x: 50, y: 20, z: 0}\n  m_EntryPosition: {x: 50, y: 60, z: 0}\n  m_ExitPosition: {x: 800, y: 60, z: 0}\n");
            sb.Append("  m_ParentStateMachinePosition: {x: 800, y: 20, z: 0}\n");
            sb.Append("  m_DefaultState: ").Append(UnityYaml.Ref(StateId(LocomotionState.Standing))).Append('\n');

            foreach (var s in GaitClips.All)
            {
                bool moving = s != LocomotionState.Standing;
                sb.Append(UnityYaml.Document(1102, StateId(s), "AnimatorState"));
                sb.Append("  serializedVersion: 6\n");
                Common(sb, 1);
                sb.Append("  m_Name: ").Append(GaitClips.Name(s)).Append("\n  m_Speed: 1\n  m_CycleOffset: 0\n  m_Transitions:");
                bool any = false;
                foreach (var t in Transitions)
                {
                    if (t.From != s) continue;
                    sb.Append(any ? "" : "\n").Append("  - ").Append(UnityYaml.Ref(TransitionId(s.ToString(), t.To))).Append('\n');
                    any = true;
                }
                if (!any) sb.Append(" []\n");
                sb.Append("  m_StateMachineBehaviours: []\n  m_Position: {x: 50, y: 50, z: 0}\n  m_IKOnFeet: 0\n  m_WriteDefaultValues: 1\n  m_Mirror: 0\n");
                sb.Append("  m_SpeedParameterActive: 0\n  m_MirrorParameterActive: 0\n  m_CycleOffsetParameterActive: 0\n");
                sb.Append("  m_TimeParameterActive: ").Append(moving ? 1 : 0).Append('\n');
                sb.Append("  m_Motion: ").Append(UnityYaml.Ref(7400000, clipGuids[s], 2)).Append('\n');
                sb.Append("  m_Tag: \n  m_SpeedParameter: \n  m_MirrorParameter: \n  m_CycleOffsetParameter: \n");
                sb.Append("  m_TimeParameter: ").Append(moving ? AnimatorParameters.StridePhase : "").Append('\n');
            }

            foreach (var t in Transitions)
                Transition(sb, TransitionId(t.From.ToString(), t.To), t.To);
            return sb.ToString();
        }

        static void Transition(StringBuilder sb, long id, LocomotionState to)
        {
            sb.Append(UnityYaml.Document(1101, id, "AnimatorStateTransition"));
            Common(sb, 1);
            sb.Append("  m_Name: \n  m_Conditions:\n");
            sb.Append("  - m_ConditionMode: ").Append(ConditionEquals).Append('\n');
            sb.Append("    m_ConditionEvent: ").Append(AnimatorParameters.State).Append('\n');
            sb.Append("    m_EventTreshold: ").Append((int)to).Append('\n');
            sb.Append("  m_DstStateMachine: {fileID: 0}\n  m_DstState: ").Append(UnityYaml.Ref(StateId(to))).Append('\n');
            sb.Append("  m_Solo: 0\n  m_Mute: 0\n  m_IsExit: 0\n  serializedVersion: 3\n");
            sb.Append("  m_TransitionDuration: ").Append(UnityYaml.Number(new AnimatorSettings().BlendTime)).Append('\n');
            sb.Append("  m_TransitionOffset: 0\n  m_ExitTime: 0\n  m_HasExitTime: 0\n  m_HasFixedDuration: 1\n  m_InterruptionSource: ").Append(InterruptionSource(to)).Append('\n');
            sb.Append("  m_OrderedInterruption: 1\n  m_CanTransitionToSelf: 0\n");
        }

        static void Common(StringBuilder sb, int hideFlags)
        {
            sb.Append("  m_ObjectHideFlags: ").Append(hideFlags).Append('\n');
            sb.Append("  m_CorrespondingSourceObject: {fileID: 0}\n  m_PrefabInstance: {fileID: 0}\n  m_PrefabAsset: {fileID: 0}\n");
        }
    }
}
