using System;
using UnityEngine;

namespace HeadGait.Unity
{
    /// <summary>
    /// Runs the gait pipeline on the head accelerometer and drives an Animator:
    /// int <c>GaitState</c> (LocomotionState: 0 Standing, 1 StartWalkLeft, 2 StartWalkRight, 3 Walking,
    /// 4 FinishWalkLeft, 5 FinishWalkRight), float <c>StridePhase</c> (0..1, 0 = left initial contact; use it as
    /// the walking clip's normalized time), float <c>WalkWeight</c> (0..1) and float <c>StepPeriod</c> (s); names in
    /// <see cref="AnimatorParameters"/>, overridable here. Parameters the controller lacks are reported once and skipped.
    /// <para>
    /// Samples pushed by the sensor source are classified at 100 Hz of sensor time on a Unity job
    /// (<see cref="GaitBatchRunner"/>, <see cref="GaitJobScheduler"/>). Each Update runs the samples that arrived since the
    /// last frame as one job, waits for it and writes its latest frame to the Animator. Update (not LateUpdate) because the
    /// Animator evaluates between Update and LateUpdate; the execution order puts this after sources that push in their
    /// own Update. While the component is disabled, pushed samples wait for its next Update in a backlog bounded to the
    /// newest 2 s (<see cref="GaitBatchRunner.DroppedBacklog"/> counts the older ones dropped).
    /// </para>
    /// </summary>
    [DisallowMultipleComponent]
    [DefaultExecutionOrder(ExecutionOrder)]
    [AddComponentMenu("HeadGait/Gait Leg Animator")]
    public sealed class GaitLegAnimator : MonoBehaviour
    {
        /// <summary>After default-order scripts (sensor sources, players), still before the Animator evaluates.</summary>
        public const int ExecutionOrder = 100;

        [SerializeField] Animator animator;
        [SerializeField] GaitClassifierKind classifier = GaitClassifierKind.Correlation;

        [Header("Models (Models/ folder of the package)")]
        [Tooltip("COR template (cor_template.txt); also the fallback of SVM and BLSTM.")]
        [SerializeField] TextAsset corTemplate;
        [Tooltip("THR settings (thr.txt); THR runs on its defaults without it.")]
        [SerializeField] TextAsset thrSettings;
        [Tooltip("SVM model (svm.bytes).")]
        [SerializeField] TextAsset svmModel;
        [Tooltip("BLSTM model (blstm.bytes).")]
        [SerializeField] TextAsset blstmModel;

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

        GaitBatchRunner runner;
        GaitJobScheduler jobScheduler;
        IGaitBatchScheduler scheduler; // the job, or inline for an evaluator that must run on the main thread
        AnimatorParameterWriter writer;
        AnimatorSink sink;
        LocomotionState lastState;
        double sourceLag;

        /// <summary>Raised on the frame the locomotion state changes (old, new).</summary>
        public event Action<LocomotionState, LocomotionState> StateChanged;

        /// <summary>Raised for every sample <see cref="Push"/> hands over (a calibration walk records them).</summary>
        public event Action<ImuSample> SamplePushed;

        /// <summary>The wearer's calibration the classifier is made with (<see cref="ApplyProfile"/>); null: the shipped models.</summary>
        public HeadGait.Calibration.WearerProfile Profile { get; private set; }

        /// <summary>Makes the classifier again with a wearer's calibration (null: the shipped models again).</summary>
        public void ApplyProfile(HeadGait.Calibration.WearerProfile profile)
        {
            Profile = profile;
            Build();
        }

        /// <summary>The shipped models this component's classifier is made from (what a calibration walk adapts); <paramref name="error"/> as <see cref="GaitClassifierBuilder.Read"/>.</summary>
        public GaitModels ReadModels(out string error)
            => GaitClassifierBuilder.Read(classifier, Text(thrSettings), Text(corTemplate),
                classifier == GaitClassifierKind.Svm ? Binary(svmModel) : null,
                classifier == GaitClassifierKind.Blstm ? Binary(blstmModel) : null, out error);

        /// <summary>Raised after <see cref="Build"/> made a new classifier (an evaluator set before is gone with the old one).</summary>
        public event Action Rebuilt;

        /// <summary>The runner that owns the pipeline (samples in, frames out); created on first use.</summary>
        public GaitBatchRunner Runner
        {
            get
            {
                if (runner == null) Build();
                return runner;
            }
        }

        /// <summary>The pipeline; inspect it only outside a running batch (e.g. in LateUpdate it may be running).</summary>
        public GaitPipeline Pipeline => Runner.Pipeline;

        public AnimatorFrame Current => runner != null ? runner.Latest : default;
        public GaitPhase LeftPhase => Current.Left;
        public GaitPhase RightPhase => Current.Right;

        /// <summary>How late the pushed samples describe the motion (s); the pose path sets it (<see cref="GaitPipeline.SourceLag"/>).</summary>
        public double SourceLag
        {
            get => sourceLag;
            set
            {
                sourceLag = value;
                if (runner != null) runner.SourceLag = value;
            }
        }

        void Awake()
        {
            if (animator == null) animator = GetComponentInChildren<Animator>();
            if (runner == null) Build();
        }

        /// <summary>(Re)creates the classifier and pipeline from the inspector settings; waits for a batch in flight first.</summary>
        public void Build()
        {
            ReleaseRunner();
            // Only the chosen model is read (the SVM's file is megabytes); COR and THR are the fallbacks.
            var c = GaitClassifierBuilder.Build(classifier, Text(thrSettings), Text(corTemplate),
                classifier == GaitClassifierKind.Svm ? Binary(svmModel) : null,
                classifier == GaitClassifierKind.Blstm ? Binary(blstmModel) : null,
                out string error, out string warning, Profile);
            if (error != null) Debug.LogError($"HeadGait: {error}", this);
            if (warning != null) Debug.LogWarning($"HeadGait: {warning}.", this);
            var settings = new AnimatorSettings
            {
                HistoryLength = Mathf.Max(1, historyLength),
                ConsecutiveErrorsToSwitch = Mathf.Max(1, consecutiveErrorsToSwitch),
            };
            runner = new GaitBatchRunner(new GaitPipeline(c, null, settings)) { SourceLag = sourceLag };
            jobScheduler = new GaitJobScheduler(runner);
            scheduler = jobScheduler;
            lastState = LocomotionState.Standing;
            Rebuilt?.Invoke();
        }

        /// <summary>
        /// Scores the SVM's or BLSTM's windows with <paramref name="evaluator"/> (the Sentis component sets one; null: the C#
        /// network again). With <paramref name="mainThreadOnly"/> the batches run inline in Update instead of on a job, as
        /// Sentis needs (it schedules its own jobs and GPU work, which Unity allows only from the main thread). Returns false,
        /// changing nothing, when the classifier is COR or THR. <see cref="Build"/> goes back to the C# network.
        /// </summary>
        public bool SetLearnedEvaluator(ILearnedEvaluator evaluator, bool mainThreadOnly)
        {
            if (!(Runner.Pipeline.Classifier is LearnedClassifier learned)) return false;
            learned.Evaluator = evaluator;
            scheduler = evaluator != null && mainThreadOnly ? new InlineBatchScheduler(runner) : (IGaitBatchScheduler)jobScheduler;
            return true;
        }

        /// <summary>Reads the controller's parameters again (after swapping the Animator Controller at run time).</summary>
        public void RefreshAnimatorParameters() => writer = null;

        /// <summary>Starts the stream over: drops pending samples and shows the standing pose (a recording restarted, the source changed).</summary>
        public void ResetGait() => Runner.Reset();

        /// <summary>Feeds one accelerometer sample: specific force in the head frame (x forward, y left, z up), m/s^2.</summary>
        /// <returns>Accepted when handed over to the next batch (the pipeline's own verdict is counted in
        /// <c>Pipeline.Preprocessor</c>); SkippedNotFinite for NaN or infinite values.</returns>
        public SampleOutcome Push(double time, Vector3 headFrameSpecificForce)
        {
            var sample = new ImuSample(time, headFrameSpecificForce.x, headFrameSpecificForce.y, headFrameSpecificForce.z);
            SamplePushed?.Invoke(sample);
            return Runner.Push(sample);
        }

        void Update()
        {
            if (runner == null) return;
            runner.Step(scheduler, Time.unscaledTimeAsDouble);
            string problem = runner.TakeWarning();
            if (problem != null) Debug.LogWarning($"HeadGait: {problem}.", this);
            var f = runner.Latest;
            if (f.State != lastState)
            {
                var old = lastState;
                lastState = f.State;
                StateChanged?.Invoke(old, f.State);
            }
            if (animator == null) return;
            if (writer == null)
            {
                // Read the controller's parameter list once; it is empty until the Animator has initialised.
                if (!animator.isInitialized) return;
                writer = new AnimatorParameterWriter(animator.parameters, stateParameter, stridePhaseParameter, walkWeightParameter, stepPeriodParameter);
                sink = new AnimatorSink(animator);
                if (writer.Problem != null) Debug.LogWarning($"HeadGait: {writer.Problem}.", this);
            }
            writer.Write(f, sink);
        }

        void OnDestroy() => ReleaseRunner();

        void ReleaseRunner()
        {
            if (runner == null) return;
            jobScheduler.Dispose();
            runner = null;
            jobScheduler = null;
            scheduler = null;
        }

        static ModelAsset Text(TextAsset a) => a == null ? null : new ModelAsset(a.name, a.text, null);
        static ModelAsset Binary(TextAsset a) => a == null ? null : new ModelAsset(a.name, null, a.bytes);
    }
}
