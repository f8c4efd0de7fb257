using System;
using UnityEngine;

namespace HeadGait.Unity
{
    public enum GaitClassifierKind
    {
        /// <summary>Template correlation (needs a COR template TextAsset; falls back to THR without one).</summary>
        Correlation = 0,
        /// <summary>Threshold on SMV; no training data needed, much less accurate.</summary>
        Threshold = 1,
    }

    /// <summary>
    /// Runs the gait pipeline on the head accelerometer and drives an Animator:
    /// int <c>GaitState</c> (LocomotionState: 0 Standing, 1 StartWalkLeft, 2 StartWalkRight, 3 Walking,
    /// 4 FinishWalkLeft, 5 FinishWalkRight), float <c>StridePhase</c> (0..1, 0 = left initial contact; use it as
    /// the walking clip's normalized time), float <c>WalkWeight</c> (0..1) and float <c>StepPeriod</c> (s).
    /// Parameter names can be changed; an empty name is not written.
    /// </summary>
    [DisallowMultipleComponent]
    [AddComponentMenu("HeadGait/Gait Leg Animator")]
    public sealed class GaitLegAnimator : MonoBehaviour
    {
        [SerializeField] Animator animator;
        [SerializeField] GaitClassifierKind classifier = GaitClassifierKind.Correlation;

        [Tooltip("COR template written by 'headgait train' or Tools > HeadGait > Train COR Template (cor_template.txt).")]
        [SerializeField] TextAsset corTemplate;

        [Header("Animator parameters")]
        [SerializeField] string stateParameter = AnimatorParameters.State;
        [SerializeField] string stridePhaseParameter = AnimatorParameters.StridePhase;
        [SerializeField] string walkWeightParameter = AnimatorParameters.WalkWeight;
        [SerializeField] string stepPeriodParameter = AnimatorParameters.StepPeriod;

        [Header("Animator state machine")]
        [Tooltip("Predictions smoothed (paper: 5).")]
        [SerializeField] int historyLength = 5;
        [Tooltip("Consecutive disagreeing predictions before the avatar changes course (paper: 3).")]
        [SerializeField] int consecutiveErrorsToSwitch = 3;

        GaitPipeline pipeline;
        LocomotionState lastState;

        /// <summary>Raised on the frame the locomotion state changes (old, new).</summary>
        public event Action<LocomotionState, LocomotionState> StateChanged;

        public GaitPipeline Pipeline => pipeline;
        public AnimatorFrame Current => pipeline != null ? pipeline.Latest : default;
        public GaitPhase LeftPhase => Current.Left;
        public GaitPhase RightPhase => Current.Right;

        void Awake()
        {
            if (animator == null) animator = GetComponentInChildren<Animator>();
            Build();
        }

        /// <summary>(Re)creates the pipeline from the inspector settings.</summary>
        public void Build()
        {
            IGaitClassifier c;
            if (classifier == GaitClassifierKind.Correlation && corTemplate != null)
            {
                CorrelationTemplate template;
                try
                {
                    template = CorrelationTemplate.Parse(corTemplate.text);
                }
                catch (FormatException e)
                {
                    Debug.LogError($"HeadGait: COR template '{corTemplate.name}' is unreadable ({e.Message}); using THR.", this);
                    template = null;
                }
                c = template != null ? new CorrelationClassifier(template) : (IGaitClassifier)new ThresholdClassifier();
            }
            else
            {
                if (classifier == GaitClassifierKind.Correlation)
                    Debug.LogWarning("HeadGait: no COR template assigned; using THR.", this);
                c = new ThresholdClassifier();
            }
            var settings = new AnimatorSettings
            {
                HistoryLength = Mathf.Max(1, historyLength),
                ConsecutiveErrorsToSwitch = Mathf.Max(1, consecutiveErrorsToSwitch),
            };
            pipeline = new GaitPipeline(c, null, settings);
            lastState = LocomotionState.Standing;
        }

        /// <summary>Seconds the pushed samples lag the motion (the pose estimator's lag on the pose path, else 0).</summary>
        public double SourceLag { get; set; }

        /// <summary>Feeds one accelerometer sample: specific force in the head frame (x forward, y left, z up), m/s^2.</summary>
        public SampleOutcome Push(double time, Vector3 headFrameSpecificForce)
        {
            if (pipeline == null) Build();
            return pipeline.Push(new ImuSample(time, headFrameSpecificForce.x, headFrameSpecificForce.y, headFrameSpecificForce.z));
        }

        void LateUpdate()
        {
            if (pipeline == null) return;
            var f = pipeline.Latest;
            if (f.State != lastState)
            {
                var old = lastState;
                lastState = f.State;
                StateChanged?.Invoke(old, f.State);
            }
            if (animator == null) return;
            if (!string.IsNullOrEmpty(stateParameter)) animator.SetInteger(stateParameter, (int)f.State);
            if (!string.IsNullOrEmpty(stridePhaseParameter)) animator.SetFloat(stridePhaseParameter, (float)f.StridePosition);
            if (!string.IsNullOrEmpty(walkWeightParameter)) animator.SetFloat(walkWeightParameter, (float)f.WalkWeight);
            if (!string.IsNullOrEmpty(stepPeriodParameter)) animator.SetFloat(stepPeriodParameter, (float)f.StepPeriod);
        }
    }
}
