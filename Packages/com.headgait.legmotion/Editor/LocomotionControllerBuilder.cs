using System;
using System.Collections.Generic;
using UnityEditor;
using UnityEditor.Animations;
using UnityEngine;

namespace HeadGait.Editor
{
    /// <summary>
    /// Builds the package's locomotion Animator Controller with Unity's editor API from <see cref="LocomotionController"/>,
    /// the same facts `headgait clips` writes the shipped `HeadGait Legs.controller` from. API as in UnityCsReference
    /// Editor/Mono/Animation/AnimatorController.cs (CreateAnimatorControllerAtPath, AddParameter),
    /// Editor/Mono/Animation/StateMachine.cs (AddState, AddTransition, AddCondition) and
    /// Editor/Mono/Animation/StateMachine.bindings.cs (AnimatorState and AnimatorStateTransition properties).
    /// </summary>
    public static class LocomotionControllerBuilder
    {
        /// <param name="path">Project-relative path of the new controller ("Assets/.../Name.controller"); an asset there is replaced.</param>
        /// <param name="clips">The motion each state plays (the package's gait clips, or the developer's own).</param>
        public static AnimatorController Create(string path, IReadOnlyDictionary<LocomotionState, Motion> clips)
        {
            if (clips == null) throw new ArgumentNullException(nameof(clips));
            var controller = AnimatorController.CreateAnimatorControllerAtPath(path);
            foreach (var name in AnimatorParameters.All)
                controller.AddParameter(name, AnimatorParameters.IsInteger(name) ? AnimatorControllerParameterType.Int : AnimatorControllerParameterType.Float);

            // CreateAnimatorControllerAtPath made one layer; layers hands out a copy, so its name is set and stored back.
            var layers = controller.layers;
            layers[0].name = LocomotionController.LayerName;
            layers[0].stateMachine.name = LocomotionController.LayerName;
            controller.layers = layers;
            var machine = layers[0].stateMachine;
            machine.anyStatePosition = Vector(LocomotionController.AnyStatePosition);
            machine.entryPosition = Vector(LocomotionController.EntryPosition);
            machine.exitPosition = Vector(LocomotionController.ExitPosition);

            var states = new Dictionary<LocomotionState, AnimatorState>();
            foreach (var s in LocomotionController.States)
            {
                var state = machine.AddState(GaitClips.Name(s), Vector(LocomotionController.Position(s)));
                state.motion = clips.TryGetValue(s, out var clip) ? clip : null;
                state.writeDefaultValues = LocomotionController.WriteDefaultValues;
                string time = LocomotionController.TimeParameter(s);
                state.timeParameterActive = time != null;
                state.timeParameter = time ?? "";
                states[s] = state;
            }
            machine.defaultState = states[LocomotionController.DefaultState];

            foreach (var t in LocomotionController.Transitions)
            {
                var transition = states[t.From].AddTransition(states[t.To]);
                transition.AddCondition(AnimatorConditionMode.Equals, t.Threshold, t.ConditionParameter);
                transition.duration = (float)t.Duration;
                transition.hasFixedDuration = t.HasFixedDuration;
                transition.hasExitTime = t.HasExitTime;
                transition.exitTime = (float)t.ExitTime;
                transition.offset = (float)t.Offset;
                transition.interruptionSource = Interruption(t.InterruptionSource);
                transition.orderedInterruption = t.OrderedInterruption;
                transition.canTransitionToSelf = t.CanTransitionToSelf;
            }
            AssetDatabase.SaveAssets();
            return controller;
        }

        /// <summary>The core's interruption source as Unity's enum (same names, same values).</summary>
        public static TransitionInterruptionSource Interruption(TransitionInterruption source)
        {
            switch (source)
            {
                case TransitionInterruption.None: return TransitionInterruptionSource.None;
                case TransitionInterruption.Source: return TransitionInterruptionSource.Source;
                case TransitionInterruption.Destination: return TransitionInterruptionSource.Destination;
                case TransitionInterruption.SourceThenDestination: return TransitionInterruptionSource.SourceThenDestination;
                case TransitionInterruption.DestinationThenSource: return TransitionInterruptionSource.DestinationThenSource;
                default: throw new ArgumentOutOfRangeException(nameof(source), source, "not an interruption source");
            }
        }

        static Vector3 Vector((float X, float Y) p) => new Vector3(p.X, p.Y, 0);
    }
}
