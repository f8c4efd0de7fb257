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
        /// (N, T, C) in row-major order. Writes each window's outputs, window by window, into <paramref name="outputs"/>
        /// (N x <see cref="LearnedClassifier.OutputCount"/>): the class probabilities for the BLSTM (ONNX output
        /// 'probabilities'), the pairs' decision values for the SVM (ONNX output 'decision', LIBSVM's pair order), from
        /// which the classifier counts the votes and applies a wearer's shifts.
        /// </summary>
        void Evaluate(double[] features, int windows, double[] outputs);
    }
}
