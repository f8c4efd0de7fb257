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

        /// <summary>
        /// Largest absolute difference over all reference windows of the probabilities the classifier passes on: the BLSTM's
        /// own; for the SVM the softmax of its votes against that of the votes the framework's decision values cast (0 when
        /// every pair decides alike), and infinity when it picks another class. The SVM's decision values themselves are
        /// float32 sums here: <see cref="MaxDecisionDifference"/>.
        /// </summary>
        public static double MaxDifference(ModelFile model, ModelFile reference) => Compare(model, reference, false);

        /// <summary>The SVM's largest decision-value difference from the framework's over the reference windows (0 for the BLSTM).</summary>
        public static double MaxDecisionDifference(ModelFile model, ModelFile reference) => Compare(model, reference, true);

        static double Compare(ModelFile model, ModelFile reference, bool decisions)
        {
            LearnedClassifier classifier = model.Kind == SvmClassifier.Kind ? new SvmClassifier(model)
                : model.Kind == BlstmClassifier.Kind ? (LearnedClassifier)new BlstmClassifier(model)
                : throw new ModelFormatException(model.Source, $"kind '{model.Kind}' has no reference check");
            var shape = reference.ShapeOf("inputs");
            int rows = shape[0], width = classifier.Features.Width, classes = classifier.Segments.ClassCount;
            if (shape.Length != 3 || shape[1] * shape[2] != width)
                throw new ModelFormatException(reference.Source, $"inputs are {string.Join("x", shape)}, the model reads {classifier.Features.TimeSteps}x{classifier.Features.Channels.Length}");
            var inputs = reference.Tensor("inputs", shape);
            var features = new double[width];
            double worst = 0;
            var svm = classifier as SvmClassifier;
            if (svm == null && decisions) return 0;
            int outWidth = svm != null ? svm.LastDecision.Length : classes;
            var outputs = reference.Tensor("outputs", rows, outWidth);
            var predictions = svm != null ? reference.Tensor("predictions", rows) : null;
            var theirVotes = new double[classes];
            for (int r = 0; r < rows; r++)
            {
                Array.Copy(inputs, r * width, features, 0, width);
                var scores = classifier.ScoreFeatures(features);
                if (svm == null)
                {
                    for (int k = 0; k < classes; k++) worst = Math.Max(worst, Math.Abs(scores[k] - outputs[r * classes + k]));
                    continue;
                }
                if (ArgMax(scores) != (int)predictions[r]) return double.PositiveInfinity;
                if (decisions)
                {
                    for (int k = 0; k < outWidth; k++) worst = Math.Max(worst, Math.Abs(svm.LastDecision[k] - outputs[r * outWidth + k]));
                    continue;
                }
                Array.Clear(theirVotes, 0, classes);
                int pair = 0;
                for (int i = 0; i < classes; i++)
                    for (int j = i + 1; j < classes; j++)
                        theirVotes[outputs[r * outWidth + pair++] > 0 ? i : j]++;
                var mine = Softmax(scores);
                var theirs = Softmax(theirVotes);
                for (int k = 0; k < classes; k++) worst = Math.Max(worst, Math.Abs(mine[k] - theirs[k]));
            }
            return worst;
        }

        static double[] Softmax(double[] v)
        {
            double max = double.NegativeInfinity, sum = 0;
            foreach (var x in v) max = Math.Max(max, x);
            var p = new double[v.Length];
            for (int k = 0; k < v.Length; k++) sum += p[k] = Math.Exp(v[k] - max);
            for (int k = 0; k < v.Length; k++) p[k] /= sum;
            return p;
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
