namespace HeadGait.Tests
{
    /// <summary>
    /// What a learned model sure of one class outputs, as an evaluator gives it (<see cref="LearnedClassifier.OutputCount"/>):
    /// the BLSTM's probabilities 0.999 for the class; the SVM's pair decision values with the class winning each of its
    /// pairs and the other classes' pairs split as a round robin (each beats the next half of them in turn), so that no
    /// other class stands out.
    /// </summary>
    static class SureOutputs
    {
        public static void Write(LearnedClassifier classifier, int sure, double[] outputs)
        {
            int classes = classifier.Segments.ClassCount;
            if (!classifier.PairwiseOutputs)
            {
                for (int k = 0; k < classes; k++) outputs[k] = k == sure ? 0.999 : 0.001 / (classes - 1);
                return;
            }
            int others = classes - 1, pair = 0;
            for (int i = 0; i < classes; i++)
                for (int j = i + 1; j < classes; j++, pair++)
                {
                    // Positive: a vote for i. Among the others, i beats j when j lies at most half the circle ahead of it.
                    int ahead = (j < sure ? j : j - 1) - (i < sure ? i : i - 1);
                    outputs[pair] = i == sure ? 1 : j == sure ? -1 : 2 * ahead <= others ? 1 : -1;
                }
        }
    }
}
