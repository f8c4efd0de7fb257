namespace HeadGait
{
    /// <summary>
    /// A classifier's answer for one window: standing, or walking at a stride position
    /// (0..1, 0 = left initial contact) from which each foot's phase follows.
    /// </summary>
    public readonly struct GaitPrediction
    {
        public readonly double Time;
        public readonly bool IsWalking;
        public readonly double StridePosition;
        /// <summary>Estimated duration of one step (half a stride), seconds.</summary>
        public readonly double StepPeriod;
        /// <summary>Classifier-specific score in 0..1 (COR: Pearson r; THR: 1 after a detected step, decaying).</summary>
        public readonly double Confidence;
        public readonly GaitPhase Left;
        public readonly GaitPhase Right;

        GaitPrediction(double time, bool walking, double stridePosition, double stepPeriod, double confidence, GaitPhase left, GaitPhase right)
        {
            Time = time;
            IsWalking = walking;
            StridePosition = stridePosition;
            StepPeriod = stepPeriod;
            Confidence = confidence;
            Left = left;
            Right = right;
        }

        public static GaitPrediction Standing(double time, double confidence = 0)
            => new GaitPrediction(time, false, 0, 0, confidence, GaitPhase.Standing, GaitPhase.Standing);

        /// <summary>
        /// Walking with the feet's phases read from <paramref name="map"/> at this step period; through <paramref name="stance"/>
        /// when given, so that each foot keeps its stance share from contact to contact (see <see cref="StanceLatch"/>).
        /// </summary>
        public static GaitPrediction Walking(double time, double stridePosition, double stepPeriod, double confidence, PhaseMap map, StanceLatch stance = null)
        {
            double s = PhaseMap.Wrap(stridePosition);
            return stance == null
                ? new GaitPrediction(time, true, s, stepPeriod, confidence, map.PhaseAt(Foot.Left, s, stepPeriod), map.PhaseAt(Foot.Right, s, stepPeriod))
                : new GaitPrediction(time, true, s, stepPeriod, confidence, stance.PhaseAt(map, Foot.Left, s, stepPeriod), stance.PhaseAt(map, Foot.Right, s, stepPeriod));
        }

        /// <summary>Walking with the feet's phases given by the classifier (they must agree with the stride position under its map).</summary>
        public static GaitPrediction Walking(double time, double stridePosition, double stepPeriod, double confidence, GaitPhase left, GaitPhase right)
            => new GaitPrediction(time, true, PhaseMap.Wrap(stridePosition), stepPeriod, confidence, left, right);

        public GaitPhase PhaseOf(Foot foot) => foot == Foot.Left ? Left : Right;

        public override string ToString()
            => IsWalking
                ? $"t={Time:F3} walk s={StridePosition:F3} L={GaitPhases.ShortName(Left)} R={GaitPhases.ShortName(Right)} conf={Confidence:F2}"
                : $"t={Time:F3} standing";
    }

    /// <summary>A per-window gait phase classifier. Implementations may keep state between windows.</summary>
    public interface IGaitClassifier
    {
        string Name { get; }
        PhaseMap PhaseMap { get; }

        /// <summary>Grid samples each window must hold (the newest ones are read).</summary>
        int WindowLength { get; }

        /// <summary>
        /// Seconds later this classifier's walk comes out on acceleration fitted from tracked poses
        /// (<see cref="PoseAccelerationEstimator"/>) than on an accelerometer's, beyond the fit's own lag: the pipeline looks
        /// that much further ahead on such a source (<see cref="GaitPipeline.SourceLag"/>).
        /// </summary>
        double PoseFitDelay { get; }

        GaitPrediction Classify(SignalWindow window);
        void Reset();
    }
}
