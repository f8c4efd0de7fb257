using System;
using System.Globalization;

namespace HeadGait
{
    /// <summary>
    /// Shared part of the learned classifiers (SVM, BLSTM): reads the features a model file names, standardises them,
    /// lets the model score each class (a stride segment naming both feet's phases, or Standing) through its
    /// <see cref="Evaluator"/> (the C# network, or the ONNX export in Sentis; windows may be scored in batches: the
    /// evaluator gives the model's outputs, <see cref="OutputCount"/> per window, and the scores are made from them here),
    /// turns the scores into probabilities, filters them over time with the gait's order (<see cref="PhaseSequenceFilter"/>,
    /// unless turned off) and reports the most likely class. Its stride position is the segment's, nudged towards the likelier neighbour;
    /// its step period is the head's rhythm's where it shows one (<see cref="PhaseFilterSettings.PeriodFromRhythm"/>), else
    /// comes from the time between predicted foot contacts.
    /// </summary>
    public abstract class LearnedClassifier : IGaitClassifier
    {
        /// <summary>Range of each channel's spread a model may standardise by (m/s^2; the trained ones hold 1.7 to 3).</summary>
        public const double MinInputScale = 1e-3, MaxInputScale = 100;

        /// <summary>Largest |mean| of a channel a model may subtract (m/s^2; the trained ones hold 0.3 or less).</summary>
        public const double MaxAbsInputMean = 50;

        readonly double[] inputMean;
        readonly double[] inputScale;
        readonly double[] features;
        readonly double[] outputs;  // the last window's, as the evaluator gave them (OutputCount); at a time scale, of the window as it is
        readonly double[] scaledOutputs;     // at a time scale, the last window's outputs read at it (OutputCount); else null
        readonly double[] rowFeatures, rowOutputs; // at a time scale, both readings of a window (RowsPerWindow rows)
        readonly double[] scaledScores;
        readonly double[] scores;
        readonly double[] probabilities;
        readonly double[] batchRow, batchRowOutputs;
        readonly PhaseSequenceFilter filter;
        PhaseSequenceFilter wearerFilter;      // over the wearer's probabilities, made on their first window
        readonly double[] wearerProbabilities;
        double[] wearerShift; // [OutputCount] or null: a wearer's shifts of the output biases (WearerShiftTensor)
        readonly CSharpNetwork network;
        readonly HeadTilt tilt = new HeadTilt();
        bool rhythmHolds;     // whether the head's rhythm held a walk at its last reading (PhaseFilterSettings.HoldOnRhythm)
        int rhythmCountdown;  // windows until the next reading
        double rhythmPeriod;  // the step period the head's rhythm showed at its last reading; 0 when it showed none
        ILearnedEvaluator evaluator;
        int lastClass = -1;
        double lastTime = double.NaN;
        double lastContactTime = double.NaN;
        double lastPosition;  // stride position of the last walking prediction
        double carriedSince = double.NaN; // when the shown class began to be carried across a swap (SwapCarrySteps); NaN when not
        readonly StillStartGuard still = new StillStartGuard(); // the still-head start rule (PhaseFilterSettings.StillStartMaxBend)
        double stepPeriod;
        int refusedRun;
        double walkStartTime = double.NaN;
        double lastShownWalk = double.NaN; // when a walking prediction was last shown (PhaseFilterSettings.FreshWalkShownAfter)
        double lastSurePass = double.NaN;  // when the gate was last sure of walking (GateVerdict.SurelyWalking)
        double shownWalkSince = double.NaN; // when the walk going on was first shown; NaN while none is (PhaseFilterSettings.ShortWalkGivesNoCredit)
        double previousWalkEnd = double.NaN, previousWalkShownFor; // the last shown walk that ended: when, and for how long it was shown (PhaseFilterSettings.ResumeStart)
        ThresholdClassifier stepClock;     // THR on the model's gate (PhaseFilterSettings.WalkOnStepClock); made on first use
        double stepClockTime = double.NaN; // end of the last window it read
        double stepClockWalkingSince = double.NaN; // when its walk going on began; NaN while it stands
        double stepClockPeriod; // its step period while it walks; 0 while it stands
        bool stepClockPeriodTimed; // whether that period was timed between two contacts of its walk, not its first guess
        double ownWalkingShare; // the model's own walking share, averaged over PhaseFilterSettings.OwnWalkingSpan

        protected LearnedClassifier(ModelFile model, string kind, PhaseFilterSettings filterSettings)
        {
            if (model == null) throw new ArgumentNullException(nameof(model));
            Source = model.Source;
            if (model.Kind != kind) throw new ModelFormatException(model.Source, $"is a '{model.Kind}' model, not '{kind}'");
            try
            {
                Features = WindowFeatures.Parse(model.Need("features"));
                PhaseMap = PhaseMap.Parse(model.Need("phase_map"));
            }
            catch (FormatException e)
            {
                throw new ModelFormatException(model.Source, e.Message);
            }
            Segments = new StrideSegments(PhaseMap);
            if (model.Values.TryGetValue(WalkingGate.ModelKey, out string gateText))
            {
                try
                {
                    Gate = WalkingGate.Parse(gateText);
                }
                catch (FormatException e)
                {
                    throw new ModelFormatException(model.Source, e.Message);
                }
            }
            string classes = model.Need("classes");
            if (classes != Segments.Names())
                throw new ModelFormatException(model.Source, $"classes '{classes}' do not match its phase map's stride segments '{Segments.Names()}'");
            int c = Features.Channels.Length;
            inputMean = model.Tensor("input_mean", c);
            inputScale = model.Tensor("input_scale", c);
            // The channels' mean and spread over the training windows (m/s^2): what a head can produce, no more.
            foreach (var s in inputScale)
                if (!(s >= MinInputScale && s <= MaxInputScale)) throw new ModelFormatException(model.Source, $"input_scale holds {s:G4}, outside {MinInputScale}..{MaxInputScale} m/s^2 (what training produces)");
            foreach (var m in inputMean)
                if (!(Math.Abs(m) <= MaxAbsInputMean)) throw new ModelFormatException(model.Source, $"input_mean holds {m:G4}, outside -{MaxAbsInputMean}..{MaxAbsInputMean} m/s^2 (what training produces)");
            features = new double[Features.Width];
            int k = Segments.ClassCount;
            OutputCount = PairwiseOutputs ? k * (k - 1) / 2 : k; // PairwiseOutputs: a constant of the derived class
            outputs = new double[OutputCount];
            wearerShift = ReadWearerShift(model, OutputCount);
            TimeScale = ReadTimeScale(model, WearerTimeScaleKey);
            liveScaling = TimeScale == 1 && filterSettings != null && filterSettings.LiveTimeScale;
            if (RowsPerWindow == 2)
            {
                scaledOutputs = new double[OutputCount];
                scaledScores = new double[Segments.ClassCount];
                rowFeatures = new double[2 * Features.Width];
                rowOutputs = new double[2 * OutputCount];
            }
            scores = new double[Segments.ClassCount];
            probabilities = new double[Segments.ClassCount];
            wearerProbabilities = new double[Segments.ClassCount];
            batchRow = new double[Features.Width];
            batchRowOutputs = new double[OutputCount];
            filter = filterSettings == null ? null : new PhaseSequenceFilter(Segments, filterSettings);
            if (liveScaling)
            {
                // Made now rather than on first use: a live scale may first move mid-stream, where nothing may allocate.
                timeScaled = new SignalWindow(Features.Samples, new PreprocessorSettings().SampleRate);
                if (filter != null) wearerFilter = new PhaseSequenceFilter(Segments, filterSettings);
            }
            stepPeriod = DefaultStepPeriod;
            network = new CSharpNetwork(this);
            evaluator = network;
        }

        /// <summary>Step period assumed until two predicted contacts have been seen (s).</summary>
        public const double DefaultStepPeriod = 0.55;

        public abstract string Name { get; }
        public string Source { get; }
        /// <summary>The model's phase map: its onsets define the classes; its stance slope shapes the avatar's phases.</summary>
        public PhaseMap PhaseMap { get; private set; }
        public StrideSegments Segments { get; }

        /// <summary>
        /// Takes the stance slope of a map learned from other recordings (a cross-validation fold's; fold models may
        /// predate the slope); the model's own onsets stay, since they define its classes.
        /// </summary>
        public void AdoptStance(PhaseMap map)
        {
            if (map == null) throw new ArgumentNullException(nameof(map));
            PhaseMap = PhaseMap.WithStance(map.StanceSlope, map.ReferenceStridePeriod);
        }
        public WindowFeatures Features { get; }

        /// <summary>
        /// None: the SVM and BLSTM read the whole window's shape, not the moment a rise crosses a level, and on the pose
        /// recordings they came out no later than on the accelerometer's (see <see cref="StepClockSettings.PoseFitDelay"/>).
        /// </summary>
        public double PoseFitDelay => 0;

        /// <summary>History read: the model's window (<see cref="ModelSpan"/>), and what the walking gate reads.</summary>
        public int WindowLength => Math.Max(ModelSpan, Gate?.History ?? 0);

        /// <summary>Grid samples the model reads of a window: its own window's, and at a <see cref="TimeScale"/> other than 1 the span resampled into it too.</summary>
        public int ModelSpan => TimeScale == 1 ? Features.Samples : Math.Max(Features.Samples, (int)Math.Ceiling((Features.Samples - 1) * TimeScale) + 1);

        /// <summary>
        /// Optional value of a wearer's calibration (<see cref="HeadGait.Calibration.WearerProfile.LearnedTimeScale"/>): the
        /// model also reads the newest <see cref="TimeScale"/> times its window's span of the signal, resampled into its window,
        /// so that the wearer's steps take the time the training walkers' took (below 1: a quick wearer's shorter stretch);
        /// that reading picks the walking class, the window as it is decides whether the wearer walks (<see cref="RowsPerWindow"/>).
        /// </summary>
        public const string WearerTimeScaleKey = "wearer_time_scale";

        /// <summary>Range of <see cref="WearerTimeScaleKey"/> a model may hold.</summary>
        public const double MinTimeScale = 0.5, MaxTimeScale = 2.0;

        /// <summary>Seconds of signal the model reads per second of its window (1: the window as it is; &gt; 1: a longer stretch, resampled).</summary>
        public double TimeScale { get; }

        SignalWindow timeScaled; // the window resampled at ReadScale (made on first use; with the classifier for a live scale)
        readonly bool liveScaling; // PhaseFilterSettings.LiveTimeScale, with no wearer's scale set
        double liveScale = 1;      // the live scale the head's rhythm last showed (LiveTimeScale)
        double rowScale = 1;       // the scale StandardiseRows read the last window's second row at

        /// <summary>
        /// The scale the model reads a window at besides the window as it is: the wearer's (<see cref="TimeScale"/>), or
        /// without one and with <see cref="PhaseFilterSettings.LiveTimeScale"/> the live one (<see cref="LiveTimeScale"/>); 1: none.
        /// </summary>
        public double ReadScale => TimeScale != 1 ? TimeScale : liveScale;

        /// <summary>
        /// The time scale the wearer's step last showed (<see cref="PhaseFilterSettings.LiveTimeScale"/>): the step period of the
        /// head's rhythm, else of THR's step clock once it has settled or has timed a step a scale reaches (its first timed
        /// step: <see cref="ClockTimedAWalkersStep"/>), over <see cref="TrainedStepPeriod"/>, within
        /// <see cref="HeadGait.Calibration.WearerProfile.MinLearnedTimeScale"/>..1 and 1 within
        /// <see cref="HeadGait.Calibration.WearerAdaptation.MinTimeScaleChange"/> of it, as a calibration's; kept while neither
        /// shows a step (and by <see cref="Reset"/>, as the rhythm and tilt are), 1 until one first does.
        /// </summary>
        public double LiveTimeScale => liveScale;

        /// <summary>The training walkers' step period (s): half the model's <see cref="PhaseMap.ReferenceStridePeriod"/>.</summary>
        public double TrainedStepPeriod => PhaseMap.ReferenceStridePeriod / 2;

        /// <summary>The model's <see cref="WearerTimeScaleKey"/> (1 without one).</summary>
        static double ReadTimeScale(ModelFile model, string key)
        {
            if (!model.Values.TryGetValue(key, out string text)) return 1;
            if (!KeyValueText.TryNumber(text, out double scale) || !(scale >= MinTimeScale && scale <= MaxTimeScale))
                throw new ModelFormatException(model.Source, $"{key} is '{text}', not a number within {MinTimeScale}..{MaxTimeScale}");
            return scale;
        }

        /// <summary>
        /// The window the model reads: <paramref name="window"/> itself at a <see cref="ReadScale"/> of 1, else its newest
        /// stretch resampled at <see cref="ReadScale"/> into the model's window (<see cref="SignalWindow.FillTimeScaled"/>).
        /// </summary>
        SignalWindow ModelWindow(SignalWindow window)
        {
            double scale = ReadScale;
            if (scale == 1) return window;
            if (timeScaled == null || timeScaled.SampleRate != window.SampleRate) timeScaled = new SignalWindow(Features.Samples, window.SampleRate);
            timeScaled.FillTimeScaled(window, scale);
            return timeScaled;
        }

        /// <summary>The window's features as the model reads them, before standardisation (<see cref="WindowFeatures.Extract"/> of the window at <see cref="ReadScale"/>).</summary>
        public void ReadFeatures(SignalWindow window, double[] destination) => Features.Extract(ModelWindow(window), destination);

        /// <summary>Class scores of the last window (model-specific: probabilities for the BLSTM, votes for the SVM).</summary>
        public double[] LastScores => scores;

        /// <summary>
        /// Values an evaluator gives per window (<see cref="ILearnedEvaluator"/>), one per output bias
        /// (<see cref="OutputBiasName"/>): the SVM's pair decision values, the BLSTM's class probabilities. The class scores
        /// and the wearer's shifts (<see cref="WearerShiftTensor"/>) are made from them in C#, after any evaluator.
        /// </summary>
        public int OutputCount { get; }

        /// <summary>The last window's outputs (<see cref="OutputCount"/>), as the evaluator gave them or <see cref="ScoreFeatures"/> computed them.</summary>
        protected double[] WindowOutputs => outputs;

        /// <summary>The model in plain C# (allocation-free): the evaluator unless another is set.</summary>
        public ILearnedEvaluator Network => network;

        /// <summary>What scores the windows: <see cref="Network"/>, or another runtime of the same model (Sentis); null sets the network.</summary>
        public ILearnedEvaluator Evaluator
        {
            get => evaluator;
            set => evaluator = value ?? network;
        }

        /// <summary>The model's outputs (<see cref="OutputCount"/>) from standardised features ([time][channel]).</summary>
        protected abstract void Score(double[] standardised, double[] windowOutputs);

        /// <summary>
        /// The outputs of <paramref name="windows"/> windows of standardised features (window by window) into
        /// <paramref name="windowOutputs"/> (window by window); one at a time through <see cref="Score"/> unless the model
        /// gains from scoring them together. Every window must score exactly as it would alone.
        /// </summary>
        protected virtual void ScoreBatch(double[] features, int windows, double[] windowOutputs)
        {
            int w = Features.Width, k = OutputCount;
            for (int n = 0; n < windows; n++)
            {
                Array.Copy(features, n * w, batchRow, 0, w);
                Score(batchRow, batchRowOutputs);
                Array.Copy(batchRowOutputs, 0, windowOutputs, n * k, k);
            }
        }

        /// <summary>Every class's score from a window's outputs; higher is more likely (the BLSTM's probabilities are its outputs).</summary>
        protected virtual void ClassScores(double[] windowOutputs, double[] classScores) => Array.Copy(windowOutputs, classScores, classScores.Length);

        /// <summary>
        /// Optional tensor of a wearer's calibration (<see cref="HeadGait.Calibration.LearnedAdjustment"/>): shifts of the
        /// output biases (the shape of <see cref="OutputBiasName"/>'s), applied to the window's outputs whatever the
        /// evaluator (<see cref="WearerProbabilities"/>).
        /// </summary>
        public const string WearerShiftTensor = "wearer_output_shift";

        /// <summary>Largest |shift| of an output bias a wearer's calibration may make (SVM: margins; BLSTM: log-odds of a class).</summary>
        public const double MaxWearerShift = 3.0;

        /// <summary>The model's <see cref="WearerShiftTensor"/> (<paramref name="count"/> values within +-<see cref="MaxWearerShift"/>), or null without one.</summary>
        static double[] ReadWearerShift(ModelFile model, int count)
        {
            if (!model.HasTensor(WearerShiftTensor)) return null;
            var shift = (double[])model.Tensor(WearerShiftTensor, count).Clone();
            foreach (var v in shift)
                if (!(Math.Abs(v) <= MaxWearerShift)) throw new ModelFormatException(model.Source, $"{WearerShiftTensor} holds {v:G4}, outside -{MaxWearerShift}..{MaxWearerShift}");
            return shift;
        }

        /// <summary>The wearer's output shifts (<see cref="WearerShiftTensor"/>, <see cref="OutputCount"/> values), or null without them.</summary>
        protected double[] WearerShift => wearerShift;

        /// <summary>
        /// Decides with other output shifts from now on (null: none), as a model holding them as its
        /// <see cref="WearerShiftTensor"/> would: the calibration's search tries many on one classifier and its recorded outputs.
        /// </summary>
        internal void UseWearerShift(double[] shift)
        {
            if (shift != null && shift.Length != OutputCount) throw new ArgumentException($"Expected {OutputCount} shifts, got {shift.Length}.", nameof(shift));
            foreach (var v in shift ?? Array.Empty<double>())
                if (!(Math.Abs(v) <= MaxWearerShift)) throw new ArgumentOutOfRangeException(nameof(shift), $"a shift of {v:G4} is outside -{MaxWearerShift}..{MaxWearerShift}");
            wearerShift = shift == null ? null : (double[])shift.Clone();
        }

        /// <summary>
        /// The probabilities with a wearer's output shifts (<see cref="WearerShiftTensor"/>) from the window's outputs
        /// (<paramref name="windowOutputs"/>), into <paramref name="p"/>; false where the model holds none. They choose only
        /// which walking class is shown: whether the wearer walks is the shipped outputs' decision (<see cref="Decide"/>).
        /// </summary>
        protected virtual bool WearerProbabilities(double[] windowOutputs, double[] p) => false;

        /// <summary>
        /// The tensor holding the last layer's biases, which a wearer's calibration may shift (<see cref="HeadGait.Calibration.LearnedAdaptation"/>):
        /// the SVM's pair intercepts, the BLSTM's class biases.
        /// </summary>
        public abstract string OutputBiasName { get; }

        /// <summary>Whether the output biases are one-versus-one pairs' (the SVM's, in LIBSVM's order) rather than one per class.</summary>
        public abstract bool PairwiseOutputs { get; }

        /// <summary>
        /// What the output biases add to for the last window scored (<see cref="ScoreFeatures"/>): the SVM's pair decision
        /// values, the BLSTM's log-probabilities (its class biases shift them up to a constant the softmax drops).
        /// </summary>
        public abstract double[] LastOutputs { get; }

        /// <summary>The scores as probabilities over the classes (the BLSTM's already are).</summary>
        protected virtual void ToProbabilities(double[] classScores, double[] p) => Array.Copy(classScores, p, p.Length);

        /// <summary>The time filter, or null when the raw per-window classes are reported.</summary>
        public PhaseSequenceFilter Filter => filter;

        public virtual void Reset()
        {
            filter?.Reset();
            wearerFilter?.Reset();
            lastTime = double.NaN;
            lastClass = -1;
            lastContactTime = double.NaN;
            stepPeriod = DefaultStepPeriod;
            refusedRun = 0;
            walkStartTime = double.NaN;
            carriedSince = double.NaN;
            still.Reset();
            lastShownWalk = double.NaN;
            lastSurePass = double.NaN;
            shownWalkSince = double.NaN;
            previousWalkEnd = double.NaN;
            previousWalkShownFor = 0;
            ownWalkingShare = 0;
        }

        /// <summary>Standardised features of a window, as the model sees them (at its <see cref="ReadScale"/>).</summary>
        public double[] Standardise(SignalWindow window)
        {
            ReadFeatures(window, features);
            StandardiseRow(features, 0);
            return features;
        }

        /// <summary>Standardises one window's features in place, <see cref="WindowFeatures.Width"/> values from <paramref name="offset"/>.</summary>
        void StandardiseRow(double[] values, int offset)
        {
            int c = Features.Channels.Length, w = Features.Width;
            for (int i = 0; i < w; i++) values[offset + i] = (values[offset + i] - inputMean[i % c]) / inputScale[i % c];
        }

        /// <summary>
        /// Readings of a window the model scores (1, or 2 at a <see cref="TimeScale"/> other than 1 or with a live one: the
        /// window as it is, which decides whether the wearer walks, then at the scale, which picks the walking class; see <see cref="Decide"/>).
        /// </summary>
        public int RowsPerWindow => TimeScale != 1 || liveScaling ? 2 : 1;

        /// <summary>Outputs an evaluator gives per window (<see cref="RowsPerWindow"/> rows of <see cref="OutputCount"/>).</summary>
        public int WindowOutputCount => RowsPerWindow * OutputCount;

        /// <summary>
        /// Every reading of a window the model scores, standardised, row by row (<see cref="RowsToScore"/> rows of
        /// <see cref="WindowFeatures.Width"/>): <see cref="Standardise"/>'s alone at a <see cref="ReadScale"/> of 1 (no wearer's
        /// scale, or a live one that is 1); else the window as it is, then at <see cref="ReadScale"/>.
        /// </summary>
        public double[] StandardiseRows(SignalWindow window)
        {
            rowScale = ReadScale;
            if (rowScale == 1) return Standardise(window);
            Features.Extract(window, rowFeatures);
            StandardiseRow(rowFeatures, 0);
            Array.Copy(Standardise(window), 0, rowFeatures, Features.Width, Features.Width);
            return rowFeatures;
        }

        /// <summary>
        /// Rows the last <see cref="StandardiseRows"/> gave: 1 at a <see cref="ReadScale"/> of 1 (with a live scale, most windows
        /// of a wearer no quicker than the training walkers), else <see cref="RowsPerWindow"/>. An evaluator writing
        /// <see cref="WindowOutputCount"/> per window leaves the second reading's outputs unread then (<see cref="WindowReading.ModelScale"/> 1).
        /// </summary>
        public int RowsToScore => rowScale == 1 ? 1 : RowsPerWindow;

        /// <summary>
        /// Splits a window's outputs from <paramref name="offset"/> into the shipped reading and, where the window was read at
        /// a scale (<paramref name="modelScale"/> other than 1), the scaled one after it.
        /// </summary>
        void TakeOutputs(double[] rows, int offset, double modelScale)
        {
            Array.Copy(rows, offset, outputs, 0, OutputCount);
            if (scaledOutputs != null && modelScale != 1) Array.Copy(rows, offset + OutputCount, scaledOutputs, 0, OutputCount);
        }

        /// <summary>
        /// Class scores for already standardised features (for checks against the training framework), by the C# network
        /// (<see cref="LastOutputs"/> then holds what the output biases add to for them).
        /// </summary>
        public double[] ScoreFeatures(double[] standardised)
        {
            if (standardised.Length != Features.Width) throw new ArgumentException($"Expected {Features.Width} features, got {standardised.Length}.");
            Score(standardised, outputs);
            ClassScores(outputs, scores);
            return scores;
        }

        /// <summary>
        /// Keeps out what clearly is not walking (gesturing, bowing): a window the gate refuses counts as standing whatever
        /// the model scores. Read from the model file's <see cref="WalkingGate.ModelKey"/> (<c>headgait train</c> writes it);
        /// null, as for a model file without one, lets every window through.
        /// </summary>
        public WalkingGate Gate { get; set; }

        public GaitPrediction Classify(SignalWindow window)
        {
            var rows = StandardiseRows(window);
            if (RowsToScore == 1) evaluator.Evaluate(rows, 1, outputs);
            else
            {
                evaluator.Evaluate(rows, RowsToScore, rowOutputs);
                TakeOutputs(rowOutputs, 0, rowScale);
            }
            var reading = Read(window);
            return Decide(reading.Time, reading.SampleRate, reading.Gate, reading.Tilt, reading.RhythmPeriod, reading.StepClockWalks, reading.StepClockShowsWalk, reading.GateLogOdds, reading.ModelScale);
        }

        /// <summary>
        /// What the classifier reads of a window besides the model's outputs, for <see cref="ClassifyScored(double[], int, in WindowReading)"/>
        /// to decide it later: its time and rate, the gate's verdict (<see cref="JudgeGate"/>), the head's tilt
        /// (<see cref="ReadTilt"/>), the rhythm's step period the gate read (<see cref="RhythmPeriod"/>), whether THR's step
        /// clock walks (<see cref="FollowStepClock"/>), whether it shows a walk at all, settled or not
        /// (<see cref="PhaseFilterSettings.ShortWalkGivesNoCredit"/>), and the scale of the model's second reading of it
        /// (<see cref="ReadScale"/> when <see cref="StandardiseRows"/> read it; 1: none).
        /// </summary>
        public readonly struct WindowReading
        {
            public readonly double Time, SampleRate, RhythmPeriod, GateLogOdds, ModelScale;
            public readonly GateVerdict Gate;
            public readonly HeadTiltReading Tilt;
            public readonly bool StepClockWalks, StepClockShowsWalk;

            public WindowReading(double time, double sampleRate, GateVerdict gate, HeadTiltReading tilt, double rhythmPeriod, bool stepClockWalks, bool stepClockShowsWalk, double gateLogOdds = double.NaN, double modelScale = 1)
            {
                GateLogOdds = gateLogOdds;
                ModelScale = modelScale;
                Time = time;
                SampleRate = sampleRate;
                Gate = gate;
                Tilt = tilt;
                RhythmPeriod = rhythmPeriod;
                StepClockWalks = stepClockWalks;
                StepClockShowsWalk = stepClockShowsWalk;
            }
        }

        /// <summary>
        /// Reads the window (<see cref="WindowReading"/>); call it for every window, in order, after <see cref="StandardiseRows"/>
        /// read it, as <see cref="Classify"/> does. A live scale it finds is read from the next window on.
        /// </summary>
        public WindowReading Read(SignalWindow window)
        {
            var gate = JudgeGate(window, out double gateLogOdds); // reads the rhythm's step period too
            var tiltReading = ReadTilt(window);
            bool walks = FollowStepClock(window);
            if (liveScaling)
            {
                // The rhythm needs 2.5 s of walking; THR's step clock shows the step sooner: settled, or once it has timed a
                // step between two contacts (style CV: the quick *active* walkers' clips were read at their step in 35 % of
                // their windows on the rhythm alone, 65 % with the settled clock; the first timed step, 18.8 to 18.4 %).
                double period = rhythmPeriod > 0 ? rhythmPeriod : walks || ClockTimedAWalkersStep ? stepClockPeriod : 0;
                if (period > 0) liveScale = LiveScaleOf(period);
            }
            return new WindowReading(window.EndTime, window.SampleRate, gate, tiltReading, rhythmPeriod, walks, !double.IsNaN(stepClockWalkingSince), gateLogOdds, rowScale);
        }

        /// <summary>
        /// Whether THR's step clock, walking but not yet settled, has timed a step between two contacts of this walk that a
        /// live scale reaches (at least <see cref="HeadGait.Calibration.WearerProfile.MinLearnedTimeScale"/> of the trained
        /// step): a quicker first interval is two bumps of one slow step (the style folds' clips made slow: 0.31-0.36 s
        /// intervals of 0.78-s steps, each read at 0.7 for a second and more), not a quick walker's step.
        /// </summary>
        bool ClockTimedAWalkersStep => stepClockPeriodTimed && stepClockPeriod >= HeadGait.Calibration.WearerProfile.MinLearnedTimeScale * TrainedStepPeriod;

        /// <summary>The live scale of the wearer's step period (<see cref="LiveTimeScale"/>).</summary>
        double LiveScaleOf(double stepPeriod)
        {
            double scale = Math.Round(Math.Max(HeadGait.Calibration.WearerProfile.MinLearnedTimeScale, Math.Min(1, stepPeriod / TrainedStepPeriod)), 2);
            return 1 - scale < HeadGait.Calibration.WearerAdaptation.MinTimeScaleChange ? 1 : scale;
        }

        /// <summary>
        /// Degrees the head's tilt moved over the newest <see cref="HeadTilt.Span"/> seconds (<see cref="HeadTilt"/>), for
        /// <see cref="PhaseFilterSettings.MaxStartTiltChange"/>, and its pitch from the last still head's, for
        /// <see cref="PhaseFilterSettings.StillStartMaxBend"/>; call it for every window, in order (it reads every
        /// <see cref="HeadTilt.EveryWindows"/>). Nothing without the time filter or with all three limits off. <see cref="Reset"/> leaves
        /// it be: a batch reads its windows' tilt before the restarts between them reset the classifier
        /// (<see cref="LearnedWindowBatch"/>), and one at a time must read the same.
        /// </summary>
        public HeadTiltReading ReadTilt(SignalWindow window)
        {
            if (filter == null) return default;
            var s = filter.Settings;
            if (!(s.MaxStartTiltChange > 0 || s.MaxWalkingTiltChange > 0 || s.StillStartMaxBend > 0)) return default;
            tilt.BendInRoll = s.StillStartBendInRoll;
            tilt.Follow(window, s.StillStartMaxBend > 0);
            return tilt.Reading;
        }

        /// <summary>
        /// The step period (s) the head's rhythm showed at the last reading <see cref="JudgeGate"/> made
        /// (<see cref="StepRhythm.ShowsStepPeriod"/>; 0 when it showed none, or without the gate or the time filter's
        /// <see cref="PhaseFilterSettings.HoldOnRhythm"/>): what a batch hands back to <see cref="ClassifyScored"/> per window.
        /// </summary>
        public double RhythmPeriod => rhythmPeriod;

        /// <summary>
        /// THR's settings for the step clock that keeps walks going (<see cref="PhaseFilterSettings.WalkOnStepClock"/>; its
        /// walking gate is replaced by <see cref="Gate"/>); null: THR's defaults.
        /// </summary>
        public ThresholdSettings WalkClockSettings { get; set; }

        /// <summary>
        /// Reads the window into THR's step clock on the model's walking gate and returns whether THR shows a walk now
        /// (one its still-start rules keep back does not count) and has shown it for <see cref="PhaseFilterSettings.StepClockWalkAge"/>,
        /// for <see cref="PhaseFilterSettings.WalkOnStepClock"/>; false with it off or without a gate. Call it for every window, in order; a window not after the last one, or over a second after it,
        /// restarts the clock (<see cref="Reset"/> leaves it be, as it leaves the tilt: a batch reads its windows first).
        /// </summary>
        public bool FollowStepClock(SignalWindow window)
        {
            if (filter == null || !filter.Settings.WalkOnStepClock || Gate == null) return false;
            if (stepClock == null || stepClock.Settings.Gate != Gate)
            {
                var s = (WalkClockSettings ?? new ThresholdSettings()).Clone();
                s.Gate = Gate;
                // THR's provisional start on a first step is THR's own way to show a walk sooner; the clock that keeps a
                // model's walks going vouches only for walks the gate passed (with it, the SVM's glasses fragments 9 to 12).
                s.Clock.FirstStep = new FirstStepStartSettings();
                stepClock = new ThresholdClassifier(s);
                stepClockTime = double.NaN;
            }
            double now = window.EndTime;
            if (!(now > stepClockTime && now - stepClockTime <= 1))
            {
                stepClock.Reset();
                stepClockWalkingSince = double.NaN;
            }
            stepClockTime = now;
            var clockPrediction = stepClock.Classify(window);
            stepClockPeriod = clockPrediction.IsWalking ? clockPrediction.StepPeriod : 0;
            stepClockPeriodTimed = clockPrediction.IsWalking && stepClock.Clock.PeriodMeasured;
            if (!clockPrediction.IsWalking)
            {
                stepClockWalkingSince = double.NaN;
                return false;
            }
            if (double.IsNaN(stepClockWalkingSince)) stepClockWalkingSince = now;
            return now - stepClockWalkingSince >= filter.Settings.StepClockWalkAge;
        }

        /// <summary>What <see cref="Gate"/> says of the window (<see cref="GateVerdict.Passes"/> without a gate).</summary>
        public GateVerdict JudgeGate(SignalWindow window) => JudgeGate(window, out _);

        /// <summary>The same, and the gate's log-odds (NaN without a gate).</summary>
        GateVerdict JudgeGate(SignalWindow window, out double logOdds)
        {
            logOdds = double.NaN;
            if (Gate == null) return GateVerdict.Passes;
            FollowRhythm(window);
            if (!Gate.Passes(window, out logOdds))
            {
                if (rhythmHolds) return GateVerdict.RefusesInStepRhythm;
                double narrow = filter?.Settings.NarrowRefusalLogOdds ?? 0;
                return narrow > 0 && logOdds > -narrow ? GateVerdict.RefusesNarrowly : GateVerdict.Refuses;
            }
            if (filter == null) return GateVerdict.Passes;
            if (logOdds >= filter.Settings.SureWalkingLogOdds) return GateVerdict.SurelyWalking;
            if (!filter.Settings.SureOnStepRhythm || !Gate.UsesStepRhythm) return GateVerdict.Passes;
            // A pass without positive log-odds was the rhythm's; otherwise ask it.
            return logOdds <= 0 || StepRhythm.Of(window, Gate.LevelTolerance).IsWalking ? GateVerdict.SurelyWalking : GateVerdict.Passes;
        }

        /// <summary>
        /// Reads whether the head's rhythm holds a walk (<see cref="StepRhythm.HoldsWalk"/>, levelled as the gate levels it)
        /// every <see cref="StepClockSettings.RhythmEveryWindows"/> windows, for <see cref="PhaseFilterSettings.HoldOnRhythm"/>.
        /// <see cref="Reset"/> leaves it be, as it leaves the tilt (<see cref="ReadTilt"/>).
        /// </summary>
        void FollowRhythm(SignalWindow window)
        {
            if (filter == null || !filter.Settings.HoldOnRhythm || rhythmCountdown-- > 0) return;
            rhythmCountdown = StepClockSettings.RhythmEveryWindows - 1;
            var rhythm = StepRhythm.Of(window, Gate.LevelTolerance);
            rhythmHolds = rhythm.HoldsWalk;
            rhythmPeriod = rhythm.ShowsStepPeriod ? rhythm.Period : 0;
        }

        /// <summary>
        /// The rest of <see cref="Classify"/> for a window scored elsewhere, in a batch (<see cref="LearnedWindowBatch"/>):
        /// window <paramref name="row"/> of <paramref name="batchOutputs"/> (windows x <see cref="WindowOutputCount"/>, as
        /// <see cref="ILearnedEvaluator.Evaluate"/> writes them for <see cref="StandardiseRows"/>' rows). Call it for the windows in
        /// their order; the time filter and step period carry over from one to the next. <paramref name="tilt"/>: what
        /// <see cref="ReadTilt"/> read of the window; <paramref name="rhythmStepPeriod"/>: <see cref="RhythmPeriod"/> after
        /// <see cref="JudgeGate"/> judged it (0: none); <paramref name="stepClockWalks"/>: what <see cref="FollowStepClock"/> returned for it; <paramref name="stepClockShowsWalk"/>: whether
        /// THR's step clock showed a walk at it, settled or not (<see cref="WindowReading.StepClockShowsWalk"/>);
        /// <paramref name="modelScale"/>: the scale of its second row (<see cref="WindowReading.ModelScale"/>; NaN: <see cref="TimeScale"/>).
        /// </summary>
        public GaitPrediction ClassifyScored(double[] batchOutputs, int row, double endTime, double sampleRate, GateVerdict gate = GateVerdict.Passes, HeadTiltReading tilt = default, double rhythmStepPeriod = 0, bool stepClockWalks = false, bool stepClockShowsWalk = false, double gateLogOdds = double.NaN, double modelScale = double.NaN)
        {
            if (double.IsNaN(modelScale)) modelScale = TimeScale;
            TakeOutputs(batchOutputs, row * WindowOutputCount, modelScale);
            return Decide(endTime, sampleRate, gate, tilt, rhythmStepPeriod, stepClockWalks, stepClockShowsWalk, gateLogOdds, modelScale);
        }

        /// <summary>
        /// The same for outputs packed as <see cref="RowsToScore"/> rows per window (<see cref="LearnedWindowBatch"/>): the
        /// window's outputs begin at element <paramref name="offset"/>.
        /// </summary>
        internal GaitPrediction ClassifyScoredAt(double[] batchOutputs, int offset, in WindowReading reading)
        {
            TakeOutputs(batchOutputs, offset, reading.ModelScale);
            return Decide(reading.Time, reading.SampleRate, reading.Gate, reading.Tilt, reading.RhythmPeriod, reading.StepClockWalks, reading.StepClockShowsWalk, reading.GateLogOdds, reading.ModelScale);
        }

        /// <summary>The window <see cref="Read"/> read, its outputs row <paramref name="row"/> of <paramref name="batchOutputs"/> (see the overload above).</summary>
        public GaitPrediction ClassifyScored(double[] batchOutputs, int row, in WindowReading reading)
            => ClassifyScoredAt(batchOutputs, row * WindowOutputCount, reading);

        /// <summary>
        /// The wearer's probabilities, which pick the walking class (<see cref="Decide"/>): with their output shifts
        /// (<see cref="WearerProbabilities"/>) from the window read at <paramref name="modelScale"/>, or as it is at a scale of 1;
        /// false where neither shifts nor a scale make them differ from the shipped ones. At a time scale the window as it is
        /// decides whether the wearer walks: on a generated quick wearer's standing with head movement, read at their scale
        /// (0.78), the SVM showed 5.9 % as walking against 4.3 % shipped. With a live scale they are the shipped ones while
        /// it is 1, so that the wearer's filter follows every window and takes over in step when the scale moves.
        /// </summary>
        bool WearerReading(double modelScale)
        {
            if (scaledOutputs == null || modelScale == 1)
            {
                if (WearerProbabilities(outputs, wearerProbabilities)) return true;
                if (!liveScaling) return false;
                Array.Copy(probabilities, wearerProbabilities, probabilities.Length);
                return true;
            }
            if (WearerProbabilities(scaledOutputs, wearerProbabilities)) return true;
            ClassScores(scaledOutputs, scaledScores);
            ToProbabilities(scaledScores, wearerProbabilities);
            return true;
        }

        /// <summary>Whether the last window's prediction was walking.</summary>
        bool WasWalking => lastClass >= 0 && lastClass != Segments.StandingClass;

        /// <summary>Whether the walk going on is younger than <see cref="HeadTilt.YoungWalk"/>.</summary>
        bool IsYoung(double now) => WasWalking && now - walkStartTime < HeadTilt.YoungWalk;

        /// <summary>From the window's outputs (in <see cref="outputs"/>) to its prediction.</summary>
        GaitPrediction Decide(double now, double sampleRate, GateVerdict gate, HeadTiltReading tilt, double rhythmStepPeriod, bool stepClockWalks, bool stepClockShowsWalk, double gateLogOdds, double modelScale)
        {
            ClassScores(outputs, scores);
            ToProbabilities(scores, probabilities);
            bool wearer = WearerReading(modelScale);
            bool bendingFromStill = BendingFromStill(tilt, now); // read every window: it follows the standing before a start
            bool bending = Bending(tilt.Change, now, stepClockWalks) || bendingFromStill;
            if (bending) gate = GateVerdict.Refuses;
            else if (ResumesThroughRefusal(gate, gateLogOdds, now)) gate = GateVerdict.Passes;
            if (gate == GateVerdict.SurelyWalking) lastSurePass = now;
            bool refused = gate == GateVerdict.Refuses || gate == GateVerdict.RefusesInStepRhythm || gate == GateVerdict.RefusesNarrowly;
            refusedRun = refused ? refusedRun + 1 : 0;
            // While the head's rhythm holds a walk in progress (or a settled walk's refusal is a near miss), the model decides
            // as if the gate had passed the window; the refusals still count, so one no longer held ends the walk at once.
            bool young = IsYoung(now);
            bool heldByRhythm = filter != null && WasWalking
                && (gate == GateVerdict.RefusesInStepRhythm && filter.Settings.HoldOnRhythm || gate == GateVerdict.RefusesNarrowly && !young);
            bool ridden = refused && !heldByRhythm && filter != null && WasWalking && !bending && refusedRun <= filter.Settings.RiddenRefusals;
            ApplyGate(probabilities, refused && !heldByRhythm, ridden, gate, young);
            if (wearer) ApplyGate(wearerProbabilities, refused && !heldByRhythm, ridden, gate, young);
            double dt = double.IsNaN(lastTime) || !(now > lastTime) ? 1 / sampleRate : Math.Min(0.25, now - lastTime);
            // What came before the stream's start is not known: its first FreshWalkGap seconds are not time without a walk.
            if (double.IsNaN(lastTime)) lastShownWalk = now;
            lastTime = now;
            var p = probabilities;
            int best;
            if (filter != null)
            {
                best = filter.Update(probabilities, dt, stepPeriod);
                p = filter.Belief;
                if (wearer)
                {
                    // A second filter over the wearer's probabilities picks the walking class; the shipped one alone
                    // decides whether the wearer walks, so a calibration cannot make gestures or bows walk.
                    if (wearerFilter == null) wearerFilter = new PhaseSequenceFilter(Segments, filter.Settings);
                    wearerFilter.Update(wearerProbabilities, dt, stepPeriod);
                    if (best != Segments.StandingClass)
                    {
                        p = wearerFilter.Belief;
                        best = MostLikelyWalking(p);
                    }
                }
            }
            else
            {
                best = 0;
                for (int k = 1; k < p.Length; k++)
                    if (p[k] > p[best]) best = k;
                if (wearer && best != Segments.StandingClass)
                {
                    p = wearerProbabilities;
                    best = MostLikelyWalking(p);
                }
            }
            if (filter != null)
                ownWalkingShare += ((best != Segments.StandingClass ? 1 : 0) - ownWalkingShare) * Math.Min(1, dt / Math.Max(dt, filter.Settings.OwnWalkingSpan));
            bool carried = false;
            double carriedPosition = 0;
            if (filter != null && WasWalking && best != Segments.StandingClass)
            {
                int steady = Steady(best, out bool swapped);
                double pace = rhythmStepPeriod > 0 ? rhythmStepPeriod : stepPeriod;
                if (!swapped) carriedSince = double.NaN;
                else if (double.IsNaN(carriedSince)) carriedSince = now;
                if (!swapped || !(filter.Settings.SwapCarrySteps > 0)) best = steady;
                else if (now - carriedSince < filter.Settings.SwapCarrySteps * pace)
                {
                    carriedPosition = PhaseMap.Wrap(lastPosition + dt / (2 * pace));
                    best = Segments.At(carriedPosition);
                    carried = true;
                }
                // else carried for SwapCarrySteps and still across the stride: the feet did swap, and the model's class shows.
            }
            else if (stepClockWalks && WasWalking && !bending && best == Segments.StandingClass && CarriesOnStepClock(gate, now))
            {
                // THR's step clock still walks (PhaseFilterSettings.WalkOnStepClock): the model's standing only says it
                // does not know the phase, and the last one goes on at the step period.
                double pace = rhythmStepPeriod > 0 ? rhythmStepPeriod : stepPeriod;
                carriedPosition = PhaseMap.Wrap(lastPosition + dt / (2 * pace));
                best = Segments.At(carriedPosition);
                carried = true;
            }
            if (best == Segments.StandingClass)
            {
                if (WasWalking) EndShownWalk(stepClockShowsWalk);
                lastClass = best;
                lastContactTime = double.NaN;
                return GaitPrediction.Standing(now, p[best]);
            }
            TrackContacts(best, now);
            if (!WasWalking)
            {
                walkStartTime = now;
                still.Started(now);
            }
            lastClass = best;
            // Within the segment, lean towards whichever neighbour scores higher.
            int n = Segments.Count;
            double before = p[(best + n - 1) % n], after = p[(best + 1) % n];
            double lean = (after - before) / (p[best] + before + after + 1e-12);
            double s = carried ? carriedPosition : Segments.Start(best) + Segments.Length(best) * (0.5 + 0.45 * Math.Max(-1, Math.Min(1, lean)));
            lastPosition = PhaseMap.Wrap(s);
            if (TooFreshToShow(now)) return GaitPrediction.Standing(now, p[Segments.StandingClass]);
            lastShownWalk = now;
            if (double.IsNaN(shownWalkSince)) shownWalkSince = now;
            double shownPeriod = filter != null && filter.Settings.PeriodFromRhythm && rhythmStepPeriod > 0 ? rhythmStepPeriod : stepPeriod;
            return GaitPrediction.Walking(now, s, shownPeriod, p[best], Segments.Left(best), Segments.Right(best));
        }

        /// <summary>
        /// Whether a walk THR's step clock still shows goes on through the model's standing (<see cref="PhaseFilterSettings.WalkOnStepClock"/>):
        /// the gate does not refuse outright, the walk is young, or refusals are carried (<see cref="PhaseFilterSettings.StepClockThroughRefusals"/>);
        /// and the model itself has walked enough of the last moments (<see cref="PhaseFilterSettings.StepClockOwnWalkingShare"/>).
        /// </summary>
        bool CarriesOnStepClock(GateVerdict gate, double now)
        {
            var s = filter.Settings;
            return (gate != GateVerdict.Refuses || s.StepClockThroughRefusals || IsYoung(now)) && ownWalkingShare >= s.StepClockOwnWalkingShare;
        }

        /// <summary>
        /// What the gate's verdict does to a window's probabilities: a refusal leaves walking
        /// <see cref="PhaseFilterSettings.RefusedWalkingShare"/> of its probability where the walk is ridden through, none
        /// otherwise; a sure pass during a walk weighs standing down (<see cref="PhaseFilterSettings.SureWalkingStandingWeight"/>),
        /// and so does any pass during a <paramref name="young"/> one (<see cref="PhaseFilterSettings.YoungWalkStandingWeight"/>).
        /// </summary>
        void ApplyGate(double[] probabilities, bool refused, bool ridden, GateVerdict gate, bool young)
        {
            if (refused)
            {
                double keep = ridden ? filter.Settings.RefusedWalkingShare : 0, walking = 0;
                for (int k = 0; k < probabilities.Length; k++)
                {
                    if (k == Segments.StandingClass) continue;
                    probabilities[k] *= keep;
                    walking += probabilities[k];
                }
                probabilities[Segments.StandingClass] = 1 - walking;
            }
            else if (filter != null && WasWalking && (gate == GateVerdict.SurelyWalking || young && gate == GateVerdict.Passes))
            {
                probabilities[Segments.StandingClass] *= gate == GateVerdict.SurelyWalking ? filter.Settings.SureWalkingStandingWeight : filter.Settings.YoungWalkStandingWeight;
                double sum = 0;
                for (int k = 0; k < probabilities.Length; k++) sum += probabilities[k];
                if (sum > 0)
                    for (int k = 0; k < probabilities.Length; k++) probabilities[k] /= sum;
            }
        }

        /// <summary>
        /// Whether the walk going on is kept from showing (<see cref="PhaseFilterSettings.FreshWalkShownAfter"/>): it began
        /// less than that long ago, the gate has not been sure of it, and no walk was shown within
        /// <see cref="PhaseFilterSettings.FreshWalkGap"/> before now, nor did the stream start (or restart) within it.
        /// </summary>
        bool TooFreshToShow(double now)
            => filter != null && now - walkStartTime < filter.Settings.FreshWalkShownAfter && !(lastSurePass >= walkStartTime)
               && !(now - lastShownWalk < filter.Settings.FreshWalkGap);

        /// <summary>
        /// Whether a window the gate refuses counts as passed as a resumed walk's (<see cref="PhaseFilterSettings.ResumeStart"/>):
        /// by less than its margin, with no walk or a young one going on, soon enough after a walk shown long enough.
        /// </summary>
        bool ResumesThroughRefusal(GateVerdict gate, double logOdds, double now)
        {
            var resume = filter?.Settings.ResumeStart;
            if (resume == null || !resume.Enabled || !(logOdds > -resume.Margin)) return false;
            if (gate == GateVerdict.Passes || gate == GateVerdict.SurelyWalking) return false;
            if (WasWalking && !IsYoung(now)) return false;
            double since = WasWalking ? walkStartTime : now;
            return since - previousWalkEnd <= resume.ResumeWithin && previousWalkShownFor >= resume.ResumeAfterShown;
        }

        /// <summary>
        /// A walk ends: one shown for less than <see cref="HeadTilt.YoungWalk"/> leaves the next walk no credit (nor the
        /// stream's start any) where <see cref="PhaseFilterSettings.ShortWalkGivesNoCredit"/> says so, unless THR's step clock
        /// shows a walk as it ends (<paramref name="stepClockShowsWalk"/>).
        /// </summary>
        void EndShownWalk(bool stepClockShowsWalk)
        {
            if (!double.IsNaN(shownWalkSince))
            {
                previousWalkEnd = lastShownWalk;
                previousWalkShownFor = lastShownWalk - shownWalkSince;
            }
            if (filter != null && filter.Settings.ShortWalkGivesNoCredit && !stepClockShowsWalk && lastShownWalk - shownWalkSince < HeadTilt.YoungWalk)
                lastShownWalk = double.NaN;
            shownWalkSince = double.NaN;
        }

        /// <summary>The walking class of highest probability (ties to the lower class).</summary>
        int MostLikelyWalking(double[] p)
        {
            int best = -1;
            for (int k = 0; k < p.Length; k++)
                if (k != Segments.StandingClass && (best < 0 || p[k] > p[best])) best = k;
            return best;
        }

        /// <summary>
        /// Whether the head's tilt moved too much for walking: more than <see cref="PhaseFilterSettings.MaxStartTiltChange"/>
        /// to start one or go on with one younger than <see cref="HeadTilt.YoungWalk"/>, more than
        /// <see cref="PhaseFilterSettings.MaxWalkingTiltChange"/> to go on with an older one, or with any while THR's step
        /// clock walks (<paramref name="stepClockWalks"/>) and <see cref="PhaseFilterSettings.StartTiltOnSettledClock"/>.
        /// </summary>
        bool Bending(double tiltChange, double now, bool stepClockWalks)
        {
            if (filter == null) return false;
            bool young = IsYoung(now);
            bool underWay = WasWalking && !young || stepClockWalks && filter.Settings.StartTiltOnSettledClock;
            double limit = underWay ? filter.Settings.MaxWalkingTiltChange : filter.Settings.MaxStartTiltChange;
            return limit > 0 && tiltChange > limit;
        }

        /// <summary>
        /// Whether the head pitched too far from a still head for walking (<see cref="PhaseFilterSettings.StillStartMaxBend"/>):
        /// to start a walk from it, or to go on with one that started from it within <see cref="HeadTilt.StillStartProbation"/>.
        /// </summary>
        bool BendingFromStill(HeadTiltReading tilt, double now)
        {
            double limit = filter?.Settings.StillStartMaxBend ?? 0;
            return limit > 0 && still.Refuses(tilt, WasWalking, now, limit);
        }

        /// <summary>
        /// The class to show after <paramref name="best"/> while walking: the last one is held when best is a little behind
        /// it or across the stride from it (<see cref="PhaseFilterSettings.HoldBackSegments"/>, <see cref="PhaseFilterSettings.SwapSegments"/>).
        /// </summary>
        int Steady(int best, out bool swapped)
        {
            int n = Segments.Count;
            var filterSettings = filter.Settings;
            int back = (lastClass - best + n) % n, ahead = (best - lastClass + n) % n;
            bool behind = back >= 1 && back <= filterSettings.HoldBackSegments;
            swapped = !behind && ahead >= filterSettings.SwapSegments && back >= filterSettings.SwapSegments;
            return behind || swapped ? lastClass : best;
        }

        /// <summary>A foot lands when the class moves forward into a segment where that foot's stance begins.</summary>
        void TrackContacts(int cls, double now)
        {
            if (!WasWalking || cls == lastClass) return;
            int n = Segments.Count;
            int forward = (cls - lastClass + n) % n;
            if (forward > n / 2) return; // moved backwards: no new contact
            bool contact = false;
            for (int k = 1; k <= forward; k++)
            {
                int seg = (lastClass + k) % n, prev = (seg + n - 1) % n;
                contact |= GaitPhases.IsContact(Segments.Left(prev), Segments.Left(seg));
                contact |= GaitPhases.IsContact(Segments.Right(prev), Segments.Right(seg));
            }
            if (!contact) return;
            if (!double.IsNaN(lastContactTime))
            {
                double interval = now - lastContactTime;
                if (interval > 0.25 && interval < 1.2) stepPeriod = 0.7 * stepPeriod + 0.3 * interval;
            }
            lastContactTime = now;
        }

        /// <summary>The C# model as an evaluator: the windows through <see cref="ScoreBatch"/>.</summary>
        sealed class CSharpNetwork : ILearnedEvaluator
        {
            readonly LearnedClassifier owner;

            public CSharpNetwork(LearnedClassifier owner) => this.owner = owner;

            public void Evaluate(double[] features, int windows, double[] outputs)
            {
                int w = owner.Features.Width, k = owner.OutputCount;
                if (windows < 0 || features.Length < windows * w || outputs.Length < windows * k)
                    throw new ArgumentException($"{windows} windows need {windows * w} features and {windows * k} outputs, got {features.Length} and {outputs.Length}.");
                owner.ScoreBatch(features, windows, outputs);
            }
        }

        protected static string Describe(double v) => v.ToString("G4", CultureInfo.InvariantCulture);
    }
}
