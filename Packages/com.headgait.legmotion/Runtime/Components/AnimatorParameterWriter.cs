using System.Collections.Generic;
using UnityEngine;

namespace HeadGait.Unity
{
    /// <summary>Where the writer sets parameters: the Animator (<see cref="AnimatorSink"/>), or a recorder in tests.</summary>
    public interface IAnimatorParameterSink
    {
        void SetInteger(int id, int value);
        void SetFloat(int id, float value);
    }

    /// <summary>Sets parameters on an Animator by hashed id.</summary>
    public sealed class AnimatorSink : IAnimatorParameterSink
    {
        readonly Animator animator;

        public AnimatorSink(Animator animator) => this.animator = animator;

        public void SetInteger(int id, int value) => animator.SetInteger(id, value);
        public void SetFloat(int id, float value) => animator.SetFloat(id, value);
    }

    /// <summary>
    /// Writes an <see cref="AnimatorFrame"/> to the parameters the controller actually has. The controller's parameter
    /// list is read once: a parameter it lacks (or has with another type) is reported once and never written, so Unity
    /// does not log "Parameter does not exist" every frame. Parameters are set by hashed id, which allocates nothing.
    /// </summary>
    public sealed class AnimatorParameterWriter
    {
        const int Absent = 0; // no parameter: Animator.StringToHash never gives 0 for the names used here (checked in Resolve)

        readonly int state, stridePhase, walkWeight, stepPeriod;

        /// <param name="controllerParameters">The Animator's <c>parameters</c> (read once).</param>
        /// <param name="stateName">int parameter for <see cref="LocomotionState"/>; null or empty: not written. The other
        /// names likewise (floats).</param>
        public AnimatorParameterWriter(AnimatorControllerParameter[] controllerParameters, string stateName, string stridePhaseName,
            string walkWeightName, string stepPeriodName)
        {
            var missing = new List<string>();
            state = Resolve(controllerParameters, stateName, AnimatorControllerParameterType.Int, missing);
            stridePhase = Resolve(controllerParameters, stridePhaseName, AnimatorControllerParameterType.Float, missing);
            walkWeight = Resolve(controllerParameters, walkWeightName, AnimatorControllerParameterType.Float, missing);
            stepPeriod = Resolve(controllerParameters, stepPeriodName, AnimatorControllerParameterType.Float, missing);
            Problem = missing.Count == 0 ? null : "the Animator Controller lacks " + string.Join(", ", missing) + "; not written";
        }

        /// <summary>The parameters that are not written and why, or null when all named ones are.</summary>
        public string Problem { get; }

        /// <summary>How many parameters each <see cref="Write"/> sets.</summary>
        public int Count => (state != Absent ? 1 : 0) + (stridePhase != Absent ? 1 : 0) + (walkWeight != Absent ? 1 : 0) + (stepPeriod != Absent ? 1 : 0);

        public void Write(in AnimatorFrame frame, IAnimatorParameterSink sink)
        {
            if (state != Absent) sink.SetInteger(state, (int)frame.State);
            if (stridePhase != Absent) sink.SetFloat(stridePhase, (float)frame.StridePosition);
            if (walkWeight != Absent) sink.SetFloat(walkWeight, (float)frame.WalkWeight);
            if (stepPeriod != Absent) sink.SetFloat(stepPeriod, (float)frame.StepPeriod);
        }

        static int Resolve(AnimatorControllerParameter[] parameters, string name, AnimatorControllerParameterType type, List<string> missing)
        {
            if (string.IsNullOrEmpty(name)) return Absent;
            int id = Animator.StringToHash(name);
            if (parameters != null)
            {
                foreach (var p in parameters)
                {
                    if (p == null || p.nameHash != id) continue;
                    if (p.type == type && id != Absent) return id;
                    missing.Add($"{type} '{name}' (it is a {p.type})");
                    return Absent;
                }
            }
            missing.Add($"{type} '{name}'");
            return Absent;
        }
    }
}
