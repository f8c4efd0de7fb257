using System;
using System.Collections.Generic;
using System.Globalization;

namespace HeadGait.Calibration
{
    /// <summary>
    /// What a calibration walk refitted of one learned model (the SVM or the BLSTM, one code path): a gain per input channel
    /// on top of the profile's overall input gain, and a shift of each output bias (the SVM's pair intercepts, the BLSTM's
    /// class biases). Tied to the model it was fitted against by <see cref="Model"/>, a fingerprint of the tensors it changes.
    /// </summary>
    public sealed class LearnedAdjustment
    {
        /// <summary>
        /// Range of a channel's gain relative to the profile's overall one. Style CV, SVM, ankle trackers (in-sample as a
        /// choice): 0.8-1.25 pooled 16.6 %, 0.6-1.6 16.4 % (the slowest two styles' sideways gain reached 0.6), 0.5-2 16.4 %
        /// with bn1 *musical* 1.45 points worse than uncalibrated.
        /// </summary>
        public const double MinChannelGain = 0.6, MaxChannelGain = 1.6;

        /// <summary>Largest shift of an output bias a profile may hold (a fit's own cap: <see cref="AdaptationSettings.LearnedShiftCap"/>).</summary>
        public const double MaxBiasShift = LearnedClassifier.MaxWearerShift;

        /// <summary>Most input channels an adjustment may scale (the models read three).</summary>
        public const int MaxChannels = 16;

        /// <summary>Most output biases a model may hold (a 9-class SVM has 36 pairs).</summary>
        public const int MaxBiases = 1000;

        /// <summary><see cref="SvmClassifier.Kind"/> or <see cref="BlstmClassifier.Kind"/>.</summary>
        public string Kind;
        /// <summary>Fingerprint of the model fitted against (<see cref="Fingerprint"/>): applied to no other.</summary>
        public string Model = "";
        /// <summary>Gain on each input channel, on top of <see cref="WearerProfile.LearnedGain"/>.</summary>
        public double[] ChannelGain = Array.Empty<double>();
        /// <summary>Added to each output bias (the SVM's pairs in LIBSVM's order; the BLSTM's classes).</summary>
        public double[] BiasShift = Array.Empty<double>();

        public bool Changes
        {
            get
            {
                foreach (var g in ChannelGain)
                    if (g != 1) return true;
                foreach (var b in BiasShift)
                    if (b != 0) return true;
                return false;
            }
        }

        /// <summary>
        /// A fingerprint of a learned model's input scaling and output biases (the tensors an adjustment changes; FNV-1a),
        /// whatever else its file holds (a walking gate, a phase map's stance written in).
        /// </summary>
        public static string Fingerprint(ModelFile model, string biasName)
        {
            ulong hash = 14695981039346656037UL;
            void Add(double[] values)
            {
                foreach (var v in values)
                {
                    long bits = BitConverter.DoubleToInt64Bits((float)v);
                    for (int i = 0; i < 8; i++) hash = (hash ^ (byte)(bits >> (8 * i))) * 1099511628211UL;
                }
                hash = (hash ^ 0xFF) * 1099511628211UL;
            }
            Add(model.Tensor("input_mean", model.ShapeOf("input_mean")));
            Add(model.Tensor("input_scale", model.ShapeOf("input_scale")));
            Add(model.Tensor(biasName, model.ShapeOf(biasName)));
            return hash.ToString("x16", CultureInfo.InvariantCulture);
        }

        /// <summary>Checks the values are what a fit can produce; a <see cref="FormatException"/> names the source and the value.</summary>
        public void Validate(string source)
        {
            if (Kind != SvmClassifier.Kind && Kind != BlstmClassifier.Kind) throw new FormatException($"{source}: learned adjustment for '{Kind}', neither {SvmClassifier.Kind} nor {BlstmClassifier.Kind}");
            if (Model == null || Model.Length != 16) throw new FormatException($"{source}: learned.{Kind}.model '{Model}' is not a 16-digit fingerprint");
            foreach (char ch in Model)
                if (!Uri.IsHexDigit(ch)) throw new FormatException($"{source}: learned.{Kind}.model '{Model}' is not a 16-digit fingerprint");
            if (ChannelGain.Length < 1 || ChannelGain.Length > MaxChannels) throw new FormatException($"{source}: learned.{Kind}.channel_gain holds {ChannelGain.Length} values (1..{MaxChannels} channels)");
            foreach (var g in ChannelGain)
                if (!(g >= MinChannelGain && g <= MaxChannelGain)) throw new FormatException($"{source}: learned.{Kind}.channel_gain holds {g.ToString("G4", CultureInfo.InvariantCulture)}, outside {MinChannelGain}..{MaxChannelGain}");
            if (BiasShift.Length < 1 || BiasShift.Length > MaxBiases) throw new FormatException($"{source}: learned.{Kind}.bias_shift holds {BiasShift.Length} values (1..{MaxBiases})");
            foreach (var b in BiasShift)
                if (!(Math.Abs(b) <= MaxBiasShift)) throw new FormatException($"{source}: learned.{Kind}.bias_shift holds {b.ToString("G4", CultureInfo.InvariantCulture)}, outside -{MaxBiasShift}..{MaxBiasShift}");
        }

        /// <summary>
        /// A copy of <paramref name="model"/> (already scaled by the profile's overall gain and gate) with this adjustment:
        /// channel c read <see cref="ChannelGain"/>[c] times larger, the output biases shifted. Throws
        /// <see cref="ModelFormatException"/> where the model's channels or biases do not match.
        /// </summary>
        public ModelFile AppliedTo(ModelFile model, string biasName)
        {
            var copy = ModelFile.Parse(model.ToBytes(), model.Source);
            var shape = copy.ShapeOf("input_mean");
            var mean = (double[])copy.Tensor("input_mean", shape).Clone();
            var scale = (double[])copy.Tensor("input_scale", shape).Clone();
            if (mean.Length != ChannelGain.Length) throw new ModelFormatException(model.Source, $"reads {mean.Length} channels; the wearer's adjustment was fitted for {ChannelGain.Length}");
            for (int c = 0; c < mean.Length; c++)
            {
                mean[c] /= ChannelGain[c];
                scale[c] /= ChannelGain[c];
            }
            copy.AddTensor("input_mean", shape, mean, true);
            copy.AddTensor("input_scale", shape, scale, true);
            var biasShape = copy.ShapeOf(biasName);
            int biases = copy.Tensor(biasName, biasShape).Length;
            if (biases != BiasShift.Length) throw new ModelFormatException(model.Source, $"holds {biases} output biases; the wearer's adjustment was fitted for {BiasShift.Length}");
            // A tensor of its own beside the biases: the classifier keeps standing's probability from the shipped biases.
            copy.AddTensor(LearnedClassifier.WearerShiftTensor, biasShape, (double[])BiasShift.Clone(), true);
            return copy;
        }

        internal static string Join(double[] values)
        {
            var parts = new string[values.Length];
            for (int i = 0; i < values.Length; i++) parts[i] = values[i].ToString("R", CultureInfo.InvariantCulture);
            return string.Join(",", parts);
        }

        internal static double[] Split(string text, string source, string key)
        {
            var parts = text.Split(',');
            if (parts.Length > MaxBiases) throw new FormatException($"{source}: {key} holds more than {MaxBiases} values");
            var values = new double[parts.Length];
            for (int i = 0; i < parts.Length; i++)
                if (!double.TryParse(parts[i].Trim(), NumberStyles.Float, CultureInfo.InvariantCulture, out values[i]) || double.IsNaN(values[i]) || double.IsInfinity(values[i]))
                    throw new FormatException($"{source}: {key} value '{parts[i].Trim()}' is not a number");
            return values;
        }
    }

    /// <summary>
    /// Refits a learned model's input scaling and last layer to one wearer from the labelled windows of a calibration walk
    /// (ankle trackers' labels), in C# and in seconds: the model scores each window once per candidate scaling, and the
    /// biases are fitted on those scores without scoring again. Bounded and shrunk towards the shipped model: each channel's
    /// gain stays within <see cref="LearnedAdjustment.MinChannelGain"/>..<see cref="LearnedAdjustment.MaxChannelGain"/> and
    /// moves only where it scores the walk's windows better by <see cref="MinGainGain"/>; each bias moves at most
    /// <see cref="LearnedAdjustment.MaxBiasShift"/>, against an L2 pull (<see cref="BiasPrior"/>), and then in steps where
    /// the walk replayed through the whole classifier pays (<see cref="Search"/>). The shifts decide only
    /// which walking class is shown: the classifier decides whether the wearer walks from the shipped outputs alone (a
    /// second time filter over the shifted ones picks the class), and the SVM's walking-versus-standing pairs and the
    /// BLSTM's Standing class are not refitted, so that what tells gestures and bows from walking stays the shipped model's.
    /// </summary>
    public static class LearnedAdaptation
    {
        /// <summary>Every n-th window of the walk is read (neighbours differ by one sample).</summary>
        public const int WindowStride = 2;

        /// <summary>Seconds ahead of a window's newest sample whose labels it is fitted to, as training labels them.</summary>
        public const double LabelLead = 0.04;

        /// <summary>Labelled windows a walk must give (about three seconds of walking read every other window).</summary>
        public const int MinWindows = 150;

        /// <summary>Relative gains tried per channel, in turn (1 is the overall gain).</summary>
        static readonly double[] ChannelSteps = { 0.6, 0.7, 0.8, 0.9, 1.1, 1.25, 1.4, 1.6 };

        /// <summary>Share of the walk's windows a channel's gain must win (classified right more) to move.</summary>
        public const double MinGainGain = 0.01;

        /// <summary>
        /// L2 weight pulling each bias shift towards none, against the mean squared hinge of the SVM's pair (or the BLSTM's
        /// mean cross-entropy): a pair the walk's windows do not clearly ask to move stays where training put it.
        /// </summary>
        public const double BiasPrior = 0.1;

        /// <summary>
        /// Most a fit moves an output bias by default: two margins of the SVM's pairs (e^2 on the BLSTM's class odds). Style
        /// CV, SVM, ankle trackers, pooled misclassification: cap 1 20.1 %, 2 19.9 %, 3 (prior 0.03) 19.7 % but bn1
        /// *chimpira* 14.7 to 15.9 % against cap 2 (gain and gate alone: 21.2 %).
        /// </summary>
        public const double DefaultShiftCap = 2.0;

        sealed class Windows
        {
            public readonly List<double[]> Raw = new List<double[]>();
            public readonly List<int> Class = new List<int>();
        }

        /// <summary>
        /// The adjustment of <paramref name="model"/> (<paramref name="shipped"/> as the profile's gain and gate already scaled
        /// it; the adjustment is tied to the shipped one) for the walk, or null where the walk gives too few labelled windows.
        /// <paramref name="make"/> builds the classifier of a model file. The channels' gains are searched only where
        /// <paramref name="channelGains"/> (see <see cref="AdaptationSettings.LearnedChannelGains"/>); the output shifts
        /// searched on the walk replayed where <paramref name="search"/> (<see cref="AdaptationSettings.LearnedShiftSearch"/>).
        /// </summary>
        public static LearnedAdjustment Fit(ModelFile shipped, ModelFile model, Func<ModelFile, LearnedClassifier> make, IReadOnlyList<Recording> walk, bool channelGains = false,
            double cap = DefaultShiftCap, double prior = BiasPrior, bool search = true, double searchCap = DefaultSearchCap)
        {
            cap = Math.Max(0, Math.Min(cap, LearnedAdjustment.MaxBiasShift));
            var classifier = make(model);
            var windows = Collect(classifier, walk);
            if (windows.Raw.Count < MinWindows) return null;
            int channels = classifier.Features.Channels.Length;
            var shape = model.ShapeOf("input_mean");
            var mean = model.Tensor("input_mean", shape);
            var scale = model.Tensor("input_scale", shape);
            var gain = new double[channels];
            for (int c = 0; c < channels; c++) gain[c] = 1;
            var noShift = new double[classifier.OutputCount];
            // The channels' gains in turn, twice round: a step stays only where it classifies clearly more windows right.
            double best = Errors(Outputs(classifier, windows, mean, scale, gain), windows, classifier, noShift);
            for (int round = 0; channelGains && round < 2; round++)
            {
                bool moved = false;
                for (int c = 0; c < channels; c++)
                {
                    double before = gain[c], kept = before, keptScore = best;
                    foreach (var step in ChannelSteps)
                    {
                        gain[c] = step;
                        double score = Errors(Outputs(classifier, windows, mean, scale, gain), windows, classifier, noShift);
                        if (score <= keptScore - MinGainGain)
                        {
                            keptScore = score;
                            kept = step;
                        }
                    }
                    moved |= kept != before;
                    gain[c] = kept;
                    best = keptScore;
                }
                if (!moved) break;
            }
            var outputs = Outputs(classifier, windows, mean, scale, gain);
            var shift = classifier.PairwiseOutputs ? PairShifts(outputs, windows, classifier.Segments, cap, prior) : ClassShifts(outputs, windows, classifier.Segments, cap, prior);
            // The shifts only where they classify the walk's windows better than the gains alone.
            if (Errors(outputs, windows, classifier, shift) >= Errors(outputs, windows, classifier, noShift)) shift = noShift;
            var adjustment = new LearnedAdjustment
            {
                Kind = classifier is SvmClassifier ? SvmClassifier.Kind : BlstmClassifier.Kind,
                Model = LearnedAdjustment.Fingerprint(shipped, classifier.OutputBiasName),
                ChannelGain = gain,
                BiasShift = shift,
            };
            if (search) adjustment.BiasShift = Search(make(adjustment.AppliedTo(model, classifier.OutputBiasName)), walk, shift, Math.Max(0, Math.Min(searchCap, LearnedAdjustment.MaxBiasShift)));
            return adjustment;
        }

        /// <summary>
        /// Most <see cref="Search"/> moves an output shift (the profile's bound, <see cref="LearnedAdjustment.MaxBiasShift"/>):
        /// the hinge fit's cap of 2 (<see cref="DefaultShiftCap"/>) holds there, where a pair the walk only asks to move
        /// moves; the search moves one only where the walk replayed pays. Style CV, SVM, ankle trackers, pooled: search cap
        /// 2 19.6 %, 3 19.4 %; the hinge fit's cap 3 as well 19.5 % with bn1 *musical* 0.1 worse than uncalibrated.
        /// </summary>
        public const double DefaultSearchCap = LearnedAdjustment.MaxBiasShift;

        /// <summary>Step of <see cref="Search"/>'s moves of one output shift.</summary>
        public const double SearchStep = 0.5;

        /// <summary>Rounds of <see cref="Search"/> over the shifts.</summary>
        public const int SearchRounds = 2;

        /// <summary>
        /// Share of the walk's time a move of <see cref="Search"/> must classify right more to be kept (0.002 = 0.2 points):
        /// what keeps a pair the walk does not clearly ask to move where the hinge fit put it.
        /// </summary>
        public const double MinSearchGain = 0.002;

        /// <summary>Stride segments apart that two classes may be for <see cref="Search"/> to move their pair (neighbours and the next but one).</summary>
        public const int SearchReach = 2;

        /// <summary>
        /// The output shifts from <paramref name="start"/> (the hinge fit's) moved where the walk replayed through the whole
        /// classifier (time filter, gate, as the product runs it) is misclassified less: first every searched pair at once
        /// towards its later or earlier class (<see cref="AdvanceStep"/>; the SVM), then each walking pair of classes at most
        /// <see cref="SearchReach"/> segments apart (the BLSTM: each walking class) in turn, <see cref="SearchStep"/> up or
        /// down within +-<paramref name="cap"/>, kept where it gains <see cref="MinSearchGain"/>; <see cref="SearchRounds"/>
        /// rounds. The hinge fit scores windows alone, so it cannot see where the time filter carries a class on too long or
        /// lets it go too early. The model scores the walk once (<see cref="RecordedWalk"/>).
        /// </summary>
        static double[] Search(LearnedClassifier classifier, IReadOnlyList<Recording> walk, double[] start, double cap)
        {
            var recorded = RecordedWalk.Of(classifier, walk);
            var shift = (double[])start.Clone();
            classifier.UseWearerShift(shift);
            double best = recorded.Misclassification(classifier);
            var searched = Searched(classifier.Segments, classifier.PairwiseOutputs);
            var later = Later(classifier.Segments, classifier.PairwiseOutputs, searched);
            for (int round = 0; round < SearchRounds; round++)
            {
                bool moved = false;
                if (classifier.PairwiseOutputs)
                {
                    // Every searched pair at once towards its later class (a lead) or its earlier one (a lag).
                    var from = (double[])shift.Clone();
                    var keptShift = from;
                    double keptScore = best;
                    foreach (double step in new[] { -2 * AdvanceStep, -AdvanceStep, AdvanceStep, 2 * AdvanceStep })
                    {
                        var tried = (double[])from.Clone();
                        for (int n = 0; n < searched.Count; n++) tried[searched[n]] = Math.Max(-cap, Math.Min(cap, from[searched[n]] + later[n] * step));
                        classifier.UseWearerShift(tried);
                        double score = recorded.Misclassification(classifier);
                        if (score <= keptScore - MinSearchGain)
                        {
                            keptScore = score;
                            keptShift = tried;
                        }
                    }
                    moved |= keptShift != from;
                    shift = keptShift;
                    best = keptScore;
                }
                foreach (int e in searched)
                {
                    double from = shift[e], kept = from, keptScore = best;
                    foreach (double step in new[] { -SearchStep, SearchStep })
                    {
                        double to = Math.Max(-cap, Math.Min(cap, from + step));
                        if (to == from) continue;
                        shift[e] = to;
                        classifier.UseWearerShift(shift);
                        double score = recorded.Misclassification(classifier);
                        if (score <= keptScore - MinSearchGain)
                        {
                            keptScore = score;
                            kept = to;
                        }
                    }
                    shift[e] = kept;
                    moved |= kept != from;
                    best = keptScore;
                }
                if (!moved) break;
            }
            return shift;
        }

        /// <summary>
        /// Step of <see cref="Search"/>'s lead or lag of every searched pair at once (one or two steps either way, each
        /// round): a wearer whose segments the SVM shows late or early throughout asks every pair to move a little, which
        /// one pair at a time does not pay. Style CV, SVM, ankle trackers, pooled: search cap 2 without it 19.9 %, with it
        /// 19.6 %; search cap 3, step 0.25 19.4 %, step 0.5 19.6 % (bn1 *chimpira* 0.6 worse than uncalibrated).
        /// </summary>
        public const double AdvanceStep = 0.25;

        /// <summary>For each searched shift, the sign that favours the later class of its pair in the stride (a pair's first class wins with a positive decision value).</summary>
        static double[] Later(StrideSegments segments, bool pairwise, List<int> searched)
        {
            var sign = new double[searched.Count];
            int k = segments.ClassCount, n = segments.Count, pair = 0;
            for (int i = 0; i < k; i++)
                for (int j = i + 1; j < k; j++, pair++)
                {
                    int at = pairwise ? searched.IndexOf(pair) : -1;
                    if (at < 0) continue;
                    sign[at] = (j - i + n) % n <= n / 2 ? -1 : 1;
                }
            return sign;
        }

        /// <summary>The output shifts <see cref="Search"/> moves: pairs of walking classes at most <see cref="SearchReach"/> segments apart, or the walking classes.</summary>
        static List<int> Searched(StrideSegments segments, bool pairwise)
        {
            var result = new List<int>();
            int k = segments.ClassCount, n = segments.Count, pair = 0;
            if (!pairwise)
            {
                for (int c = 0; c < k; c++)
                    if (c != segments.StandingClass) result.Add(c);
                return result;
            }
            for (int i = 0; i < k; i++)
                for (int j = i + 1; j < k; j++, pair++)
                {
                    if (i == segments.StandingClass || j == segments.StandingClass) continue;
                    int apart = Math.Min((j - i + n) % n, (i - j + n) % n);
                    if (apart <= SearchReach) result.Add(pair);
                }
            return result;
        }

        /// <summary>
        /// A walk's windows as a learned classifier meets them (its model's outputs, what <see cref="LearnedClassifier.Read"/>
        /// reads of it, the stream's restarts) and their labels, read once, so that the classifier decides them again under other
        /// output shifts (<see cref="LearnedClassifier.ClassifyScored"/>, as a batch does) without scoring or reading them again.
        /// </summary>
        sealed class RecordedWalk
        {
            struct Entry
            {
                public int Row; // -1: a restart of the stream
                public LearnedClassifier.WindowReading Reading;
                public bool Labelled;
                public GaitPhase Left, Right;
            }

            readonly List<Entry> entries = new List<Entry>();
            double[] outputs = Array.Empty<double>();
            int rows;

            public static RecordedWalk Of(LearnedClassifier classifier, IReadOnlyList<Recording> walk)
            {
                var result = new RecordedWalk();
                int k = classifier.WindowOutputCount;
                var row = new double[k];
                foreach (var rec in walk)
                {
                    classifier.Reset();
                    result.entries.Add(new Entry { Row = -1 });
                    var labels = new LabelCursor(rec);
                    var pre = new StreamPreprocessor(new PreprocessorSettings { History = classifier.WindowLength });
                    foreach (var s in rec.Samples)
                    {
                        var outcome = pre.Push(s.Imu, w =>
                        {
                            classifier.Network.Evaluate(classifier.StandardiseRows(w), classifier.RowsToScore, row);
                            var e = new Entry { Row = result.rows, Reading = classifier.Read(w) };
                            if (labels.TryLabelsAt(w.EndTime, out var truth))
                            {
                                e.Labelled = true;
                                e.Left = truth.Left;
                                e.Right = truth.Right;
                            }
                            if ((result.rows + 1) * k > result.outputs.Length) Array.Resize(ref result.outputs, Math.Max(1024, 2 * result.outputs.Length));
                            Array.Copy(row, 0, result.outputs, result.rows++ * k, k);
                            result.entries.Add(e);
                        });
                        if (outcome == SampleOutcome.AcceptedAfterGap || outcome == SampleOutcome.AcceptedAfterRebase) result.entries.Add(new Entry { Row = -1 });
                    }
                }
                return result;
            }

            /// <summary>Share of the labelled windows' feet whose phase the classifier, deciding them in order, gets wrong.</summary>
            public double Misclassification(LearnedClassifier classifier)
            {
                int wrong = 0, feet = 0;
                foreach (var e in entries)
                {
                    if (e.Row < 0)
                    {
                        classifier.Reset();
                        continue;
                    }
                    var p = classifier.ClassifyScored(outputs, e.Row, e.Reading);
                    if (!e.Labelled) continue;
                    feet += 2;
                    if (p.Left != e.Left) wrong++;
                    if (p.Right != e.Right) wrong++;
                }
                return feet == 0 ? 0 : (double)wrong / feet;
            }
        }

        /// <summary>Every <see cref="WindowStride"/>-th window of the walk whose labels (at <see cref="LabelLead"/>) make a class, its features as read.</summary>
        static Windows Collect(LearnedClassifier classifier, IReadOnlyList<Recording> walk)
        {
            var result = new Windows();
            int width = classifier.Features.Width;
            foreach (var rec in walk)
            {
                var labels = new LabelCursor(rec);
                var pre = new StreamPreprocessor(new PreprocessorSettings { History = classifier.ModelSpan });
                int n = 0;
                foreach (var s in rec.Samples)
                    pre.Push(s.Imu, w =>
                    {
                        // The lead is the model's: at a time scale it spans that many more seconds of the wearer's walk.
                        if (n++ % WindowStride != 0 || !labels.TryLabelsAt(w.EndTime + LabelLead * classifier.TimeScale, out var truth)) return;
                        int cls = classifier.Segments.ClassOf(truth.Left, truth.Right);
                        if (cls < 0) return;
                        var raw = new double[width];
                        classifier.ReadFeatures(w, raw);
                        result.Raw.Add(raw);
                        result.Class.Add(cls);
                    });
            }
            return result;
        }

        /// <summary>The model's outputs (<see cref="LearnedClassifier.LastOutputs"/>) of every window, standardised with the channels' gains.</summary>
        static List<double[]> Outputs(LearnedClassifier classifier, Windows windows, double[] mean, double[] scale, double[] gain)
        {
            int c = mean.Length;
            var x = new double[classifier.Features.Width];
            var outputs = new List<double[]>(windows.Raw.Count);
            foreach (var raw in windows.Raw)
            {
                for (int i = 0; i < x.Length; i++) x[i] = (gain[i % c] * raw[i] - mean[i % c]) / scale[i % c];
                classifier.ScoreFeatures(x);
                outputs.Add((double[])classifier.LastOutputs.Clone());
            }
            return outputs;
        }

        /// <summary>
        /// Share of the windows whose class the outputs, biases shifted, get wrong, decided as the classifier decides them:
        /// standing where the shipped outputs say so, else the walking class the shifted outputs rank first (the SVM's by votes).
        /// </summary>
        static double Errors(List<double[]> outputs, Windows windows, LearnedClassifier classifier, double[] shift)
        {
            int wrong = 0, k = classifier.Segments.ClassCount;
            var shipped = new double[k];
            var shifted = new double[k];
            for (int w = 0; w < outputs.Count; w++)
            {
                var o = outputs[w];
                if (classifier.PairwiseOutputs)
                {
                    // One-versus-one votes, as the SVM casts them.
                    Array.Clear(shipped, 0, k);
                    Array.Clear(shifted, 0, k);
                    int pair = 0;
                    for (int i = 0; i < k; i++)
                        for (int j = i + 1; j < k; j++, pair++)
                        {
                            shipped[o[pair] > 0 ? i : j]++;
                            shifted[o[pair] + shift[pair] > 0 ? i : j]++;
                        }
                }
                else
                    for (int i = 0; i < k; i++)
                    {
                        shipped[i] = o[i];
                        shifted[i] = o[i] + shift[i];
                    }
                int standing = classifier.Segments.StandingClass, best = 0;
                for (int i = 1; i < k; i++)
                    if (shipped[i] > shipped[best]) best = i;
                if (best != standing)
                {
                    best = -1;
                    for (int i = 0; i < k; i++)
                        if (i != standing && (best < 0 || shifted[i] > shifted[best])) best = i;
                }
                if (best != windows.Class[w]) wrong++;
            }
            return outputs.Count == 0 ? 0 : (double)wrong / outputs.Count;
        }

        /// <summary>
        /// Each pair of walking classes' intercept shift: the minimum of the mean squared hinge over the windows of its two
        /// classes plus <see cref="BiasPrior"/> times the shift squared, within +-<see cref="LearnedAdjustment.MaxBiasShift"/>
        /// (convex: bisection on its slope). Pairs with Standing stay.
        /// </summary>
        static double[] PairShifts(List<double[]> outputs, Windows windows, StrideSegments segments, double cap, double prior)
        {
            int k = segments.ClassCount, pair = 0;
            var shift = new double[k * (k - 1) / 2];
            var values = new List<double>();
            var targets = new List<double>();
            for (int i = 0; i < k; i++)
                for (int j = i + 1; j < k; j++, pair++)
                {
                    if (i == segments.StandingClass || j == segments.StandingClass) continue;
                    values.Clear();
                    targets.Clear();
                    for (int w = 0; w < outputs.Count; w++)
                    {
                        int y = windows.Class[w];
                        if (y != i && y != j) continue;
                        values.Add(outputs[w][pair]);
                        targets.Add(y == i ? 1 : -1);
                    }
                    if (values.Count == 0) continue;
                    double Slope(double d)
                    {
                        double sum = 0;
                        for (int n = 0; n < values.Count; n++)
                        {
                            double margin = 1 - targets[n] * (values[n] + d);
                            if (margin > 0) sum += -2 * targets[n] * margin;
                        }
                        return sum / values.Count + 2 * prior * d;
                    }
                    double lo = -cap, hi = cap;
                    if (Slope(lo) >= 0) shift[pair] = lo;
                    else if (Slope(hi) <= 0) shift[pair] = hi;
                    else
                    {
                        for (int it = 0; it < 40; it++)
                        {
                            double mid = 0.5 * (lo + hi);
                            if (Slope(mid) > 0) hi = mid;
                            else lo = mid;
                        }
                        shift[pair] = 0.5 * (lo + hi);
                    }
                }
            return shift;
        }

        /// <summary>
        /// The walking classes' bias shifts (Standing's stays 0): mean cross-entropy of the windows plus
        /// <see cref="BiasPrior"/> times the squared shifts, by gradient descent within +-<see cref="LearnedAdjustment.MaxBiasShift"/>.
        /// </summary>
        static double[] ClassShifts(List<double[]> outputs, Windows windows, StrideSegments segments, double cap, double prior)
        {
            int k = segments.ClassCount;
            var shift = new double[k];
            var grad = new double[k];
            var p = new double[k];
            for (int it = 0; it < 200; it++)
            {
                Array.Clear(grad, 0, k);
                for (int w = 0; w < outputs.Count; w++)
                {
                    double max = double.NegativeInfinity, sum = 0;
                    for (int c = 0; c < k; c++) max = Math.Max(max, p[c] = outputs[w][c] + shift[c]);
                    for (int c = 0; c < k; c++) sum += p[c] = Math.Exp(p[c] - max);
                    for (int c = 0; c < k; c++) grad[c] += p[c] / sum - (c == windows.Class[w] ? 1 : 0);
                }
                for (int c = 0; c < k; c++)
                {
                    if (c == segments.StandingClass) continue;
                    double g = grad[c] / Math.Max(1, outputs.Count) + 2 * prior * shift[c];
                    shift[c] = Math.Max(-cap, Math.Min(cap, shift[c] - 0.5 * g));
                }
            }
            return shift;
        }
    }
}
