using System;

namespace HeadGait.Training
{
    /// <summary>
    /// Compares the package's forward pass of a learned model with the outputs its training framework computed for the
    /// same standardised windows (a reference file written at training time: tensors inputs [R, T, C] and outputs; for the
    /// SVM outputs are the pairwise decision values and predictions the framework's classes).
    /// </summary>
    public static class ReferenceCheck
    {
        /// <summary>Where training saved a model's reference outputs: Reference~/NAME.reference.bytes beside it (not imported by Unity).</summary>
        public static string ReferencePath(string modelPath)
            => System.IO.Path.Combine(System.IO.Path.GetDirectoryName(modelPath) ?? ".", "Reference~",
                System.IO.Path.GetFileNameWithoutExtension(modelPath) + ".reference.bytes");

        /// <summary>Largest absolute difference over all reference windows (infinity when the SVM picks another class).</summary>
        public static double MaxDifference(ModelFile model, ModelFile reference)
        {
            LearnedClassifier classifier = model.Kind == SvmClassifier.Kind ? new SvmClassifier(model)
                : model.Kind == BlstmClassifier.Kind ? (LearnedClassifier)new BlstmClassifier(model)
                : throw new ModelFormatException(model.Source, $"kind '{model.Kind}' has no reference check");
            var shape = reference.ShapeOf("inputs");
            int rows = shape[0], width = classifier.Features.Width;
            if (shape.Length != 3 || shape[1] * shape[2] != width)
                throw new ModelFormatException(reference.Source, $"inputs are {string.Join("x", shape)}, the model reads {classifier.Features.TimeSteps}x{classifier.Features.Channels.Length}");
            var inputs = reference.Tensor("inputs", shape);
            var features = new double[width];
            double worst = 0;
            var svm = classifier as SvmClassifier;
            int outWidth = svm != null ? svm.LastDecision.Length : classifier.Segments.ClassCount;
            var outputs = reference.Tensor("outputs", rows, outWidth);
            var predictions = svm != null ? reference.Tensor("predictions", rows) : null;
            for (int r = 0; r < rows; r++)
            {
                Array.Copy(inputs, r * width, features, 0, width);
                var scores = classifier.ScoreFeatures(features);
                var mine = svm != null ? svm.LastDecision : scores;
                for (int k = 0; k < outWidth; k++) worst = Math.Max(worst, Math.Abs(mine[k] - outputs[r * outWidth + k]));
                if (svm != null && ArgMax(scores) != (int)predictions[r]) return double.PositiveInfinity;
            }
            return worst;
        }

        static int ArgMax(double[] v)
        {
            int best = 0;
            for (int i = 1; i < v.Length; i++)
                if (v[i] > v[best]) best = i;
            return best;
        }
    }
}
