namespace HeadGait
{
    /// <summary>
    /// Scores a batch of windows for a <see cref="LearnedClassifier"/>: the model part of the classifier, without its time
    /// filter or phase decoding. The classifier's own C# network is one (<see cref="LearnedClassifier.Network"/>); the
    /// optional Sentis assembly runs the ONNX export of the same model as another.
    /// </summary>
    public interface ILearnedEvaluator
    {
        /// <summary>
        /// Scores <paramref name="windows"/> windows. <paramref name="features"/> holds their standardised features
        /// window by window, each [time][channel] (<see cref="WindowFeatures"/>), which is the ONNX input 'window' of shape
        /// (N, T, C) in row-major order. Writes each window's class scores, window by window, into
        /// <paramref name="scores"/> (N x classes) in the classifier's own sense: probabilities for the BLSTM, votes for the SVM.
        /// </summary>
        void Evaluate(double[] features, int windows, double[] scores);
    }
}
