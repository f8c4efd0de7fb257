namespace HeadGait.Unity
{
    /// <summary>The classifier a <see cref="GaitLegAnimator"/> runs (serialized: keep the values).</summary>
    public enum GaitClassifierKind
    {
        /// <summary>Template correlation (needs a COR template; falls back to THR without one).</summary>
        Correlation = 0,
        /// <summary>Threshold on SMV; no training data needed, much less accurate.</summary>
        Threshold = 1,
        /// <summary>Support vector machine (svm.bytes; falls back to COR, then THR).</summary>
        Svm = 2,
        /// <summary>Bidirectional LSTM (blstm.bytes; falls back to COR, then THR).</summary>
        Blstm = 3,
    }
}
