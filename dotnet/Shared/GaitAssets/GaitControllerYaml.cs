using System.Collections.Generic;
using System.Text;

namespace HeadGait.Tooling
{
    /// <summary>
    /// Writes the Animator Controller (.controller) the package ships from <see cref="LocomotionController"/> (its layer,
    /// states, parameters, transitions and their settings; the editor's Create Animator Controller builds the same from
    /// there): parameters m_Type 1 float, 3 int; conditions m_ConditionMode 6 Equals, m_EventTreshold the target's value;
    /// m_InterruptionSource the value of <see cref="TransitionInterruption"/>. Field layout as in controllers saved by Unity
    /// 2019-2022 in public projects (AnimatorState serializedVersion 6, AnimatorStateTransition serializedVersion 3,
    /// AnimatorStateMachine serializedVersion 6, AnimatorController serializedVersion 5).
    /// The evidence that this cannot be skipped past is `headgait animator-check` (dotnet/Shared/AnimatorCheck).
    /// </summary>
    public static class GaitControllerYaml
    {
        public const long ControllerId = 9100000;
        public const int ConditionEquals = 6;
        public const int FloatType = 1;
        public const int IntType = 3;

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
            sb.Append("  m_AnimatorLayers:\n  - serializedVersion: 5\n    m_Name: ").Append(LocomotionController.LayerName).Append('\n');
            sb.Append("    m_StateMachine: ").Append(UnityYaml.Ref(StateMachineId)).Append('\n');
            sb.Append("    m_Mask: {fileID: 0}\n    m_Motions: []\n    m_Behaviours: []\n    m_BlendingMode: 0\n    m_SyncedLayerIndex: -1\n");
            sb.Append("    m_DefaultWeight: 0\n    m_IKPass: 0\n    m_SyncedLayerAffectsTiming: 0\n    m_Controller: {fileID: ").Append(ControllerId).Append("}\n");

            // The state machine, named as its layer (AnimatorController.AddLayer does so).
            sb.Append(UnityYaml.Document(1107, StateMachineId, "AnimatorStateMachine"));
            sb.Append("  serializedVersion: 6\n");
            Common(sb, 1);
            sb.Append("  m_Name: ").Append(LocomotionController.LayerName).Append("\n  m_ChildStates:\n");
            foreach (var s in LocomotionController.States)
            {
                var (x, y) = LocomotionController.Position(s);
                sb.Append("  - serializedVersion: 1\n    m_State: ").Append(UnityYaml.Ref(StateId(s))).Append('\n');
                sb.Append("    m_Position: ").Append(UnityYaml.Vector(x, y, 0)).Append('\n');
            }
            sb.Append("  m_ChildStateMachines: []\n  m_AnyStateTransitions: []\n");
            sb.Append("  m_EntryTransitions: []\n  m_StateMachineTransitions: {}\n  m_StateMachineBehaviours: []\n");
            sb.Append("  m_AnyStatePosition: ").Append(Vector(LocomotionController.AnyStatePosition)).Append('\n');
            sb.Append("  m_EntryPosition: ").Append(Vector(LocomotionController.EntryPosition)).Append('\n');
            sb.Append("  m_ExitPosition: ").Append(Vector(LocomotionController.ExitPosition)).Append('\n');
            sb.Append("  m_ParentStateMachinePosition: {x: 800, y: 20, z: 0}\n");
            sb.Append("  m_DefaultState: ").Append(UnityYaml.Ref(StateId(LocomotionController.DefaultState))).Append('\n');

            foreach (var s in LocomotionController.States)
            {
                string timeParameter = LocomotionController.TimeParameter(s);
                sb.Append(UnityYaml.Document(1102, StateId(s), "AnimatorState"));
                sb.Append("  serializedVersion: 6\n");
                Common(sb, 1);
                sb.Append("  m_Name: ").Append(GaitClips.Name(s)).Append("\n  m_Speed: 1\n  m_CycleOffset: 0\n  m_Transitions:");
                bool any = false;
                foreach (var t in LocomotionController.Transitions)
                {
                    if (t.From != s) continue;
                    sb.Append(any ? "" : "\n").Append("  - ").Append(UnityYaml.Ref(TransitionId(s.ToString(), t.To))).Append('\n');
                    any = true;
                }
                if (!any) sb.Append(" []\n");
                sb.Append("  m_StateMachineBehaviours: []\n  m_Position: {x: 50, y: 50, z: 0}\n  m_IKOnFeet: 0\n  m_WriteDefaultValues: ").Append(Flag(LocomotionController.WriteDefaultValues));
                sb.Append("\n  m_Mirror: 0\n");
                sb.Append("  m_SpeedParameterActive: 0\n  m_MirrorParameterActive: 0\n  m_CycleOffsetParameterActive: 0\n");
                sb.Append("  m_TimeParameterActive: ").Append(Flag(timeParameter != null)).Append('\n');
                sb.Append("  m_Motion: ").Append(UnityYaml.Ref(7400000, clipGuids[s], 2)).Append('\n');
                sb.Append("  m_Tag: \n  m_SpeedParameter: \n  m_MirrorParameter: \n  m_CycleOffsetParameter: \n");
                sb.Append("  m_TimeParameter: ").Append(timeParameter ?? "").Append('\n');
            }

            foreach (var t in LocomotionController.Transitions)
                Transition(sb, TransitionId(t.From.ToString(), t.To), t);
            return sb.ToString();
        }

        static void Transition(StringBuilder sb, long id, LocomotionControllerTransition t)
        {
            sb.Append(UnityYaml.Document(1101, id, "AnimatorStateTransition"));
            Common(sb, 1);
            sb.Append("  m_Name: \n  m_Conditions:\n");
            sb.Append("  - m_ConditionMode: ").Append(ConditionEquals).Append('\n');
            sb.Append("    m_ConditionEvent: ").Append(t.ConditionParameter).Append('\n');
            sb.Append("    m_EventTreshold: ").Append(t.Threshold).Append('\n');
            sb.Append("  m_DstStateMachine: {fileID: 0}\n  m_DstState: ").Append(UnityYaml.Ref(StateId(t.To))).Append('\n');
            sb.Append("  m_Solo: 0\n  m_Mute: 0\n  m_IsExit: 0\n  serializedVersion: 3\n");
            sb.Append("  m_TransitionDuration: ").Append(UnityYaml.Number(t.Duration)).Append('\n');
            sb.Append("  m_TransitionOffset: ").Append(UnityYaml.Number(t.Offset));
            sb.Append("\n  m_ExitTime: ").Append(UnityYaml.Number(t.ExitTime));
            sb.Append("\n  m_HasExitTime: ").Append(Flag(t.HasExitTime));
            sb.Append("\n  m_HasFixedDuration: ").Append(Flag(t.HasFixedDuration));
            sb.Append("\n  m_InterruptionSource: ").Append((int)t.InterruptionSource);
            sb.Append("\n  m_OrderedInterruption: ").Append(Flag(t.OrderedInterruption));
            sb.Append("\n  m_CanTransitionToSelf: ").Append(Flag(t.CanTransitionToSelf)).Append('\n');
        }

        static int Flag(bool on) => on ? 1 : 0;

        static string Vector((float X, float Y) p) => UnityYaml.Vector(p.X, p.Y, 0);

        static void Common(StringBuilder sb, int hideFlags)
        {
            sb.Append("  m_ObjectHideFlags: ").Append(hideFlags).Append('\n');
            sb.Append("  m_CorrespondingSourceObject: {fileID: 0}\n  m_PrefabInstance: {fileID: 0}\n  m_PrefabAsset: {fileID: 0}\n");
        }
    }
}
