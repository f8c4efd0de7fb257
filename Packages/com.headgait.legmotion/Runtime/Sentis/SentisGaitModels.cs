using Unity.InferenceEngine;
using UnityEngine;
using SentisModelAsset = Unity.InferenceEngine.ModelAsset;

namespace HeadGait.Unity
{
    /// <summary>
    /// Runs the SVM or BLSTM of the <see cref="GaitLegAnimator"/> on the same GameObject in Sentis: assign the ONNX files of the package's Models/
    /// folder (imported by Sentis as model assets). Batches then run on the main thread in the animator's Update, one
    /// inference per frame's windows, on the CPU (Burst) or the GPU. Without a model for the chosen classifier, or with one
    /// that does not fit it, it logs a warning and the C# network keeps running; with COR or THR chosen it does nothing.
    /// </summary>
    [DisallowMultipleComponent]
    [AddComponentMenu("HeadGait/Gait Models in Sentis")]
    public sealed class SentisGaitModels : MonoBehaviour
    {
        [Tooltip("Models/svm.onnx, used when the animator's classifier is SVM.")]
        [SerializeField] SentisModelAsset svmModel;
        [Tooltip("Models/blstm.onnx, used when the animator's classifier is BLSTM.")]
        [SerializeField] SentisModelAsset blstmModel;
        [Tooltip("CPU runs Burst jobs; GPUCompute runs compute shaders and reads the scores back every frame.")]
        [SerializeField] BackendType backend = BackendType.CPU;

        GaitLegAnimator gaitAnimator;
        SentisEvaluator evaluator;

        /// <summary>The evaluator in use, or null when the C# network runs.</summary>
        public SentisEvaluator Evaluator => evaluator;

        void OnEnable()
        {
            gaitAnimator = GetComponent<GaitLegAnimator>();
            if (gaitAnimator == null)
            {
                Debug.LogWarning("HeadGait: Sentis models need a Gait Leg Animator on the same GameObject.", this);
                return;
            }
            // Enabled before the animator's Awake (its execution order is later), asking for the pipeline builds it and raises
            // Rebuilt: build it before listening, so the one Attach below makes the only worker.
            _ = gaitAnimator.Runner;
            gaitAnimator.Rebuilt += Attach;
            Attach();
        }

        void OnDisable()
        {
            if (gaitAnimator != null)
            {
                gaitAnimator.Rebuilt -= Attach;
                gaitAnimator.SetLearnedEvaluator(null, false);
            }
            Release();
        }

        void Update()
        {
            if (evaluator != null && evaluator.Problem != null)
            {
                Debug.LogWarning($"HeadGait: {evaluator.Problem}.", this);
                gaitAnimator.SetLearnedEvaluator(null, false);
                Release();
            }
        }

        /// <summary>(Re)binds an evaluator to the animator's current classifier.</summary>
        void Attach()
        {
            Release();
            if (!(gaitAnimator.Pipeline.Classifier is LearnedClassifier learned)) return; // COR or THR: nothing to run
            var asset = learned is SvmClassifier ? svmModel : blstmModel;
            var model = asset == null ? null : ModelLoader.Load(asset);
            evaluator = SentisEvaluator.Create(learned, model, asset == null ? "(none)" : asset.name, backend, out string problem);
            if (evaluator == null)
            {
                Debug.LogWarning($"HeadGait: Sentis not used, the C# {learned.Name} runs instead: {problem}.", this);
                return;
            }
            gaitAnimator.SetLearnedEvaluator(evaluator, true);
        }

        void Release()
        {
            evaluator?.Dispose();
            evaluator = null;
        }
    }
}
