using System;
using Unity.InferenceEngine;

namespace HeadGait.Unity
{
    /// <summary>
    /// Scores a learned classifier's windows with its ONNX export (Models/svm.onnx, Models/blstm.onnx) in Sentis: one
    /// inference per batch, input 'window' (N, T, C) float32 of standardised features, output 'probabilities' (BLSTM,
    /// (N, classes)) or 'decision' (SVM, (N, pairs): the pairs' decision values, from which the classifier counts the
    /// votes and applies a wearer's shifts of the intercepts), the same outputs the C# network gives
    /// (<see cref="LearnedClassifier.OutputCount"/> per window). Call it on the main thread only: Sentis
    /// schedules its own Burst jobs or GPU work, which Unity allows only from there. Reading the output back waits for the
    /// inference and allocates one float array per batch. If the output turns out to have another shape, it says so once
    /// (<see cref="Problem"/>) and scores with the classifier's C# network from then on. Dispose it to free the worker.
    /// </summary>
    public sealed class SentisEvaluator : ILearnedEvaluator, IDisposable
    {
        /// <summary>The models' input, as training/train_learned.py exports it.</summary>
        public const string InputName = "window";
        public const string BlstmOutputName = "probabilities";
        public const string SvmOutputName = "decision";

        readonly LearnedClassifier classifier;
        readonly string outputName;
        readonly int steps, channels, outputCount;
        Worker worker;
        float[][] inputBySize = new float[0][]; // [N] -> N x T x C values, reused

        SentisEvaluator(LearnedClassifier classifier, Worker worker, string outputName)
        {
            this.classifier = classifier;
            this.worker = worker;
            this.outputName = outputName;
            steps = classifier.Features.TimeSteps;
            channels = classifier.Features.Channels.Length;
            outputCount = classifier.OutputCount;
        }

        /// <summary>Why it stopped using Sentis and scores with the C# network instead; null while Sentis runs.</summary>
        public string Problem { get; private set; }

        /// <summary>Batches scored by Sentis.</summary>
        public int Inferences { get; private set; }

        /// <summary>The output of this classifier's ONNX export that it reads: 'decision' for the SVM, 'probabilities' for the BLSTM.</summary>
        public static string OutputNameFor(LearnedClassifier classifier)
            => classifier is SvmClassifier ? SvmOutputName : classifier is BlstmClassifier ? BlstmOutputName : null;

        /// <summary>
        /// An evaluator for <paramref name="classifier"/> running <paramref name="model"/> on <paramref name="backend"/>, or
        /// null with the reason in <paramref name="problem"/> when the model is missing or does not fit the classifier: an
        /// input 'window' of shape (batch, T, C) with this classifier's time steps and channels, and its output.
        /// </summary>
        public static SentisEvaluator Create(LearnedClassifier classifier, Model model, string modelName, BackendType backend, out string problem)
        {
            if (classifier == null) throw new ArgumentNullException(nameof(classifier));
            problem = Check(classifier, model, modelName);
            if (problem != null) return null;
            return new SentisEvaluator(classifier, new Worker(model, backend), OutputNameFor(classifier));
        }

        static string Check(LearnedClassifier classifier, Model model, string modelName)
        {
            string output = OutputNameFor(classifier);
            if (output == null) return $"{classifier.Name} has no ONNX export";
            if (model == null) return $"no ONNX model ({classifier.Name}) assigned or it could not be loaded";
            int t = classifier.Features.TimeSteps, c = classifier.Features.Channels.Length;
            string expected = $"(batch, {t}, {c})";
            var input = model.inputs.Find(i => i.name == InputName);
            if (input.name == null) return $"{modelName}: has no input '{InputName}' (it needs one of shape {expected})";
            var shape = input.shape;
            if (shape.isRankDynamic || shape.rank != 3) return $"{modelName}: input '{InputName}' is not of rank 3 {expected}";
            if (!Fits(shape.Get(1), t) || !Fits(shape.Get(2), c))
                return $"{modelName}: input '{InputName}' is ({Dim(shape.Get(0))}, {Dim(shape.Get(1))}, {Dim(shape.Get(2))}), the {classifier.Name} model needs {expected}; is it the other model?";
            if (!model.outputs.Exists(o => o.name == output))
                return $"{modelName}: has no output '{output}', which the {classifier.Name} export has; is it the other model?";
            return null;
        }

        static bool Fits(int dim, int expected) => dim < 0 || dim == expected; // -1: dynamic, fixed when run
        static string Dim(int d) => d < 0 ? "?" : d.ToString();

        public void Evaluate(double[] features, int windows, double[] outputs)
        {
            int width = steps * channels;
            if (windows < 0 || features.Length < windows * width || outputs.Length < windows * outputCount)
                throw new ArgumentException($"{windows} windows need {windows * width} features and {windows * outputCount} outputs, got {features.Length} and {outputs.Length}.");
            if (windows == 0) return;
            if (Problem != null || worker == null)
            {
                classifier.Network.Evaluate(features, windows, outputs);
                return;
            }
            var packed = Pack(features, windows);
            using (var input = new Tensor<float>(new TensorShape(windows, steps, channels), packed))
            {
                worker.SetInput(InputName, input);
                worker.Schedule();
                // The output belongs to the worker; DownloadToArray waits for the inference and copies it back.
                var output = worker.PeekOutput(outputName) as Tensor<float>;
                var shape = output?.shape;
                if (output == null || shape.Value.rank != 2 || shape.Value[0] != windows || shape.Value[1] != outputCount)
                {
                    Problem = $"Sentis output '{outputName}' is {(output == null ? "not float" : shape.Value.ToString())}, not ({windows}, {outputCount}): scoring with the C# network instead";
                    classifier.Network.Evaluate(features, windows, outputs);
                    return;
                }
                var values = output.DownloadToArray();
                for (int i = 0; i < windows * outputCount; i++) outputs[i] = values[i];
            }
            Inferences++;
        }

        /// <summary>The features as float32 in the tensor's row-major (N, T, C) order, which is already theirs.</summary>
        float[] Pack(double[] features, int windows)
        {
            if (windows >= inputBySize.Length) Array.Resize(ref inputBySize, Math.Max(windows + 1, 2 * inputBySize.Length));
            var packed = inputBySize[windows] ?? (inputBySize[windows] = new float[windows * steps * channels]);
            for (int i = 0; i < packed.Length; i++) packed[i] = (float)features[i];
            return packed;
        }

        public void Dispose()
        {
            worker?.Dispose();
            worker = null;
        }
    }
}
