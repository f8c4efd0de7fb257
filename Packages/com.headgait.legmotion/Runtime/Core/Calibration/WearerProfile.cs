using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace HeadGait.Calibration
{
    /// <summary>
    /// What a calibration walk fitted to one wearer, saved as a small text file (<c># headgait-wearer-profile v3</c>; v2,
    /// without the learned time scale, and v1, without the learned adjustments too, still read): THR's settings and COR's
    /// templates in full (their own keys, prefixed <c>thr.</c> and <c>cor.</c>, read back by their own parsers), how much
    /// further the walking gates open for this wearer, the learned models' input gain and time scale, each learned model's refitted channel gains and output biases
    /// (<c>learned.svm.</c>, <c>learned.blstm.</c>, <see cref="LearnedAdjustment"/>), and which models it was fitted against. <see cref="Apply"/> gives adapted copies of the models; the models themselves are never changed.
    /// </summary>
    public sealed class WearerProfile
    {
        public const string Magic = "# headgait-wearer-profile v3";

        /// <summary>The second version's magic line: read as ever (no learned time scale: 1).</summary>
        public const string MagicV2 = "# headgait-wearer-profile v2";

        /// <summary>The first version's magic line: read as ever (no learned adjustments, no learned time scale).</summary>
        public const string MagicV1 = "# headgait-wearer-profile v1";
        public const string Extension = ".profile.txt";

        /// <summary>Most a profile may open a walking gate (log-odds added to its bias): the guard against gestures stays.</summary>
        public const double MaxGateShift = 1.0;

        /// <summary>
        /// Most a profile fitted with ankle trackers may open COR's walking gate for walks in progress where that pays on the
        /// walk (<see cref="HeadGait.Calibration.AdaptationSettings.CorGate"/>, <see cref="CorrelationTemplate.WalkingGateHoldShift"/>):
        /// wider than the learned models' bound, as it only keeps a walk going (a start still needs the trained gate). Style CV,
        /// COR, ankle trackers, in-sample as a choice: bn1 *feminine* 41.3 to 36.9 % at 2, 35.0 at 3, 34.5 % at 4 and 5 (its
        /// sideways walks 65.5 / 63.5 to 57.7 / 50.2 %); no other style's opened gate paid on its clip; at 1 it did not pay on
        /// bn1 *feminine*'s clip either.
        /// </summary>
        public const double MaxCorGateShift = 4.0;

        /// <summary>
        /// Most a profile may open the SVM's and BLSTM's walking gate: wider than the detectors' <see cref="MaxGateShift"/>,
        /// as a slow wearer's walk can need it (style CV, SVM, ankle trackers: bn1 *feminine*'s gate reached 1 and 2, its
        /// misclassification 32.6 to 30.4 % at 2, its gestures still never shown walking) and the learned gain and gate are
        /// kept only where they pay on the walk.
        /// </summary>
        public const double MaxLearnedGateShift = 2.0;

        /// <summary>Range of the learned models' input gain (the wearer's bounce brought towards the training walkers').</summary>
        public const double MinLearnedGain = 0.75, MaxLearnedGain = 1.5;

        /// <summary>Range of the learned models' time scale (seconds of the wearer's signal per second of the model's window; within the classifier's own bounds).</summary>
        public const double MinLearnedTimeScale = 0.7, MaxLearnedTimeScale = 1.8;

        public const string FromFootReferences = "foot-references";
        public const string SelfSupervised = "self-supervised";

        public string Wearer;
        /// <summary><see cref="FromFootReferences"/> or <see cref="SelfSupervised"/>.</summary>
        public string Source = FromFootReferences;
        public DateTime CreatedUtc = DateTime.UtcNow;
        /// <summary>Steps of the calibration walk the fit used.</summary>
        public int Steps;
        /// <summary>Fingerprint of the models it was fitted against (<see cref="Fingerprint"/>); empty: not checked.</summary>
        public string BaseModels = "";

        public ThresholdSettings Threshold;
        public CorrelationTemplate Correlation;
        /// <summary>Log-odds added to the SVM's and BLSTM's walking gate (0..<see cref="MaxLearnedGateShift"/>).</summary>
        public double LearnedGateShift;
        /// <summary>Factor on the acceleration the SVM and BLSTM read (through their input scaling).</summary>
        public double LearnedGain = 1;
        /// <summary>
        /// Seconds of the wearer's signal the SVM and BLSTM read per second of their window (<see cref="LearnedClassifier.TimeScale"/>):
        /// above 1 a slow wearer's steps are read as quick as the training walkers'. 1: the window as it is.
        /// </summary>
        public double LearnedTimeScale = 1;
        /// <summary>The SVM's and the BLSTM's refitted channel gains and output biases, each for the model it was fitted against (none: empty).</summary>
        public List<LearnedAdjustment> LearnedAdjustments = new List<LearnedAdjustment>();

        /// <summary>The adjustment for a learned model of <paramref name="kind"/>, or null.</summary>
        public LearnedAdjustment AdjustmentFor(string kind)
        {
            foreach (var a in LearnedAdjustments)
                if (a.Kind == kind) return a;
            return null;
        }

        /// <summary>Whether a wearer id makes a file name here and on every platform: 1-64 letters, digits, '-', '_' or '.', not starting with '.'.</summary>
        public static bool IsValidWearer(string wearer)
        {
            if (string.IsNullOrEmpty(wearer) || wearer.Length > 64 || wearer[0] == '.') return false;
            foreach (char ch in wearer)
                if (!(ch < 128 && (char.IsLetterOrDigit(ch) || ch == '-' || ch == '_' || ch == '.'))) return false;
            return true;
        }

        /// <summary>
        /// Adapted copies of <paramref name="models"/> for this wearer: THR and COR from the profile (each with its gate), the
        /// SVM and BLSTM with their input scaled by <see cref="LearnedGain"/>, read at <see cref="LearnedTimeScale"/>, and their gate opened by <see cref="LearnedGateShift"/>.
        /// Problems of the models carry over; a classifier the models lack stays absent.
        /// </summary>
        public GaitModels Apply(GaitModels models)
        {
            if (models == null) throw new ArgumentNullException(nameof(models));
            var adapted = new GaitModels
            {
                Threshold = Threshold ?? models.Threshold,
                Correlation = Correlation ?? models.Correlation,
            };
            adapted.Problems.AddRange(models.Problems);
            adapted.Svm = models.Svm == null ? null : AdaptedModel(models.Svm, SvmClassifier.Kind, "intercept", adapted.Problems);
            adapted.Blstm = models.Blstm == null ? null : AdaptedModel(models.Blstm, BlstmClassifier.Kind, "fc_b", adapted.Problems);
            return adapted;
        }

        /// <summary>
        /// The learned model scaled (<see cref="ScaledModel"/>) and, where the profile holds an adjustment fitted against this
        /// very model, adjusted; an adjustment fitted against another model is left out with a line in <paramref name="problems"/>.
        /// </summary>
        ModelFile AdaptedModel(ModelFile model, string kind, string biasName, List<string> problems)
        {
            var scaled = ScaledModel(model);
            var adjustment = AdjustmentFor(kind);
            if (adjustment == null) return scaled;
            string fingerprint = LearnedAdjustment.Fingerprint(model, biasName);
            if (fingerprint != adjustment.Model)
            {
                problems.Add($"wearer '{Wearer}': the {kind} adjustment was fitted against another model ({adjustment.Model}, this is {fingerprint}); left out until the wearer calibrates again");
                return scaled;
            }
            return adjustment.AppliedTo(scaled, biasName);
        }

        /// <summary>
        /// A copy of a learned model whose input scaling reads the acceleration times <see cref="LearnedGain"/>, whose window
        /// reads <see cref="LearnedTimeScale"/> times its span (<see cref="LearnedClassifier.WearerTimeScaleKey"/>; written only
        /// when not 1: at 1 the model follows a live scale where its settings read one, <see cref="PhaseFilterSettings.LiveTimeScale"/>)
        /// and whose gate is opened by <see cref="LearnedGateShift"/>.
        /// </summary>
        public ModelFile ScaledModel(ModelFile model)
        {
            var copy = ModelFile.Parse(model.ToBytes(), model.Source + " (wearer " + Wearer + ")");
            var shape = copy.ShapeOf("input_mean");
            var mean = (double[])copy.Tensor("input_mean", shape).Clone();
            var scale = (double[])copy.Tensor("input_scale", shape).Clone();
            // (gain x - mean) / scale = (x - mean / gain) / (scale / gain): the model reads the wearer's signal as if it were gain times larger.
            for (int i = 0; i < mean.Length; i++)
            {
                mean[i] /= LearnedGain;
                scale[i] /= LearnedGain;
            }
            copy.AddTensor("input_mean", shape, mean, true);
            copy.AddTensor("input_scale", shape, scale, true);
            if (LearnedTimeScale != 1) copy.Set(LearnedClassifier.WearerTimeScaleKey, LearnedTimeScale.ToString("R", CultureInfo.InvariantCulture));
            if (copy.Values.TryGetValue(WalkingGate.ModelKey, out var gateText))
                copy.Set(WalkingGate.ModelKey, OpenGate(WalkingGate.Parse(gateText), LearnedGateShift).Serialize());
            return copy;
        }

        /// <summary>The gate with <paramref name="shift"/> added to its log-odds (null stays null: no gate).</summary>
        public static WalkingGate OpenGate(WalkingGate gate, double shift)
        {
            if (gate == null || shift == 0) return gate;
            var w = gate.Weights;
            w[WalkingGate.InputCount] += shift;
            return new WalkingGate(w, gate.LevelTolerance, gate.UsesStepRhythm);
        }

        /// <summary>
        /// A fingerprint of the trained THR and COR (their text), however they were loaded (a folder, Unity assets): a
        /// profile fitted against other ones is not applied. The learned models are left out: a component that runs COR
        /// reads no learned model, and the profile's input gain does not depend on which model it scales.
        /// </summary>
        public static string Fingerprint(GaitModels models)
        {
            if (models == null) return "";
            ulong hash = 14695981039346656037UL; // FNV-1a
            void Add(byte[] bytes)
            {
                foreach (byte b in bytes) hash = (hash ^ b) * 1099511628211UL;
                hash = (hash ^ 0xFF) * 1099511628211UL;
            }
            Add(models.Threshold == null ? Array.Empty<byte>() : Encoding.UTF8.GetBytes(models.Threshold.Serialize()));
            Add(models.Correlation == null ? Array.Empty<byte>() : Encoding.UTF8.GetBytes(models.Correlation.Serialize()));
            return hash.ToString("x16", CultureInfo.InvariantCulture);
        }

        public string Serialize()
        {
            var ci = CultureInfo.InvariantCulture;
            var pairs = new List<KeyValuePair<string, string>>
            {
                new KeyValuePair<string, string>("wearer", Wearer),
                new KeyValuePair<string, string>("source", Source),
                new KeyValuePair<string, string>("created_utc", CreatedUtc.ToString("yyyy-MM-ddTHH:mm:ssZ", ci)),
                new KeyValuePair<string, string>("steps", Steps.ToString(ci)),
                new KeyValuePair<string, string>("base_models", BaseModels ?? ""),
                new KeyValuePair<string, string>("learned_gate_shift", LearnedGateShift.ToString("R", ci)),
                new KeyValuePair<string, string>("learned_gain", LearnedGain.ToString("R", ci)),
                new KeyValuePair<string, string>("learned_time_scale", LearnedTimeScale.ToString("R", ci)),
            };
            var sb = new StringBuilder(KeyValueText.Write(Magic, pairs, "a wearer's calibration (headgait calibrate); delete the file to reset the wearer to the shipped models"));
            if (Threshold != null) Embed(sb, ThrPrefix, Threshold.Serialize());
            if (Correlation != null) Embed(sb, CorPrefix, Correlation.Serialize());
            foreach (var a in LearnedAdjustments)
            {
                sb.Append(LearnedPrefix).Append(a.Kind).Append(".model=").Append(a.Model).Append('\n');
                sb.Append(LearnedPrefix).Append(a.Kind).Append(".channel_gain=").Append(LearnedAdjustment.Join(a.ChannelGain)).Append('\n');
                sb.Append(LearnedPrefix).Append(a.Kind).Append(".bias_shift=").Append(LearnedAdjustment.Join(a.BiasShift)).Append('\n');
            }
            return sb.ToString();
        }

        const string ThrPrefix = "thr.", CorPrefix = "cor.", LearnedPrefix = "learned.";

        static void Embed(StringBuilder sb, string prefix, string document)
        {
            foreach (var raw in document.Split('\n'))
            {
                string line = raw.Trim();
                if (line.Length == 0 || line.StartsWith("#", StringComparison.Ordinal)) continue;
                sb.Append(prefix).Append(line).Append('\n');
            }
        }

        /// <summary>Writes the profile whole or not at all (<see cref="AtomicFile"/>): an earlier profile survives a failed write.</summary>
        public void Save(string path)
        {
            Validate(path);
            AtomicFile.WriteAllText(path, Serialize());
        }

        public static WearerProfile Load(string path)
        {
            if (!File.Exists(path)) throw new FileNotFoundException($"{path}: wearer profile not found", path);
            return Parse(File.ReadAllText(path, Encoding.UTF8), path);
        }

        /// <summary>Reads a profile as <see cref="Serialize"/> writes it; a <see cref="FormatException"/> names the source and what is wrong.</summary>
        public static WearerProfile Parse(string text, string source = "wearer profile")
        {
            if (text == null) throw new FormatException($"{source}: no text");
            var own = new StringBuilder();
            var thr = new StringBuilder(ThresholdSettings.Magic + "\n");
            var cor = new StringBuilder(CorrelationTemplate.Magic + "\n");
            bool hasThr = false, hasCor = false;
            var learned = new Dictionary<string, string>();
            string normalised = text.Replace("\r\n", "\n").Replace('\r', '\n');
            if (normalised.Length > 0 && normalised[0] == '\uFEFF') normalised = normalised.Substring(1);
            string head = normalised.TrimStart();
            string magic = head.StartsWith(MagicV1 + "\n", StringComparison.Ordinal) ? MagicV1 : head.StartsWith(MagicV2 + "\n", StringComparison.Ordinal) ? MagicV2 : Magic;
            foreach (var raw in normalised.Split('\n'))
            {
                string line = raw.Trim();
                if (line.StartsWith(LearnedPrefix, StringComparison.Ordinal))
                {
                    if (magic == MagicV1) throw new FormatException($"{source}: '{line}': a v1 profile holds no learned adjustments");
                    int eq = line.IndexOf('=');
                    if (eq < 0) throw new FormatException($"{source}: line '{line}' is not key=value");
                    string key = line.Substring(0, eq).Trim();
                    if (learned.ContainsKey(key)) throw new FormatException($"{source}: '{key}' appears twice");
                    learned[key] = line.Substring(eq + 1).Trim();
                }
                else if (line.StartsWith(ThrPrefix, StringComparison.Ordinal))
                {
                    thr.Append(line.Substring(ThrPrefix.Length)).Append('\n');
                    hasThr = true;
                }
                else if (line.StartsWith(CorPrefix, StringComparison.Ordinal))
                {
                    cor.Append(line.Substring(CorPrefix.Length)).Append('\n');
                    hasCor = true;
                }
                else own.Append(raw).Append('\n');
            }
            var kv = KeyValueText.Parse(own.ToString(), magic, source);
            var p = new WearerProfile
            {
                Wearer = kv.Need("wearer"),
                Source = kv.Need("source"),
                Steps = (int)kv.Number("steps", 0, 1e6),
                BaseModels = kv.Has("base_models") ? kv.Need("base_models") : "",
                LearnedGateShift = kv.Number("learned_gate_shift", 0, MaxLearnedGateShift),
                LearnedGain = kv.Number("learned_gain", MinLearnedGain, MaxLearnedGain),
                LearnedTimeScale = magic == Magic ? kv.Number("learned_time_scale", MinLearnedTimeScale, MaxLearnedTimeScale) : 1,
            };
            if (magic != Magic && kv.Has("learned_time_scale")) throw new FormatException($"{source}: 'learned_time_scale': a {(magic == MagicV1 ? "v1" : "v2")} profile holds no learned time scale");
            if (!DateTime.TryParse(kv.Need("created_utc"), CultureInfo.InvariantCulture, DateTimeStyles.AdjustToUniversal | DateTimeStyles.AssumeUniversal, out p.CreatedUtc))
                throw new FormatException($"{source}: created_utc '{kv.Need("created_utc")}' is not a date and time");
            try
            {
                if (hasThr) p.Threshold = ThresholdSettings.Parse(thr.ToString(), source + " (thr.)");
                if (hasCor) p.Correlation = CorrelationTemplate.Parse(cor.ToString(), source + " (cor.)");
            }
            catch (ArgumentException e)
            {
                throw new FormatException($"{source}: {e.Message}");
            }
            p.LearnedAdjustments = ParseLearned(learned, source);
            p.Validate(source);
            return p;
        }

        /// <summary>The <c>learned.KIND.</c> keys as adjustments: each kind needs its model, channel_gain and bias_shift, and nothing else.</summary>
        static List<LearnedAdjustment> ParseLearned(Dictionary<string, string> learned, string source)
        {
            var byKind = new Dictionary<string, LearnedAdjustment>();
            var order = new List<LearnedAdjustment>();
            foreach (var pair in learned)
            {
                string rest = pair.Key.Substring(LearnedPrefix.Length);
                int dot = rest.IndexOf('.');
                string kind = dot < 0 ? rest : rest.Substring(0, dot), field = dot < 0 ? "" : rest.Substring(dot + 1);
                if (kind != SvmClassifier.Kind && kind != BlstmClassifier.Kind) throw new FormatException($"{source}: '{pair.Key}': no learned model '{kind}' ({SvmClassifier.Kind} or {BlstmClassifier.Kind})");
                if (!byKind.TryGetValue(kind, out var a))
                {
                    byKind[kind] = a = new LearnedAdjustment { Kind = kind, Model = null, ChannelGain = null, BiasShift = null };
                    order.Add(a);
                }
                switch (field)
                {
                    case "model": a.Model = pair.Value; break;
                    case "channel_gain": a.ChannelGain = LearnedAdjustment.Split(pair.Value, source, pair.Key); break;
                    case "bias_shift": a.BiasShift = LearnedAdjustment.Split(pair.Value, source, pair.Key); break;
                    default: throw new FormatException($"{source}: unknown key '{pair.Key}' (model, channel_gain, bias_shift)");
                }
            }
            foreach (var a in order)
            {
                if (a.Model == null) throw new FormatException($"{source}: lacks '{LearnedPrefix}{a.Kind}.model'");
                if (a.ChannelGain == null) throw new FormatException($"{source}: lacks '{LearnedPrefix}{a.Kind}.channel_gain'");
                if (a.BiasShift == null) throw new FormatException($"{source}: lacks '{LearnedPrefix}{a.Kind}.bias_shift'");
            }
            return order;
        }

        void Validate(string source)
        {
            if (!IsValidWearer(Wearer)) throw new FormatException($"{source}: wearer '{Wearer}' is not 1-64 letters, digits, '-', '_' or '.'");
            if (Source != FromFootReferences && Source != SelfSupervised) throw new FormatException($"{source}: source '{Source}' is neither {FromFootReferences} nor {SelfSupervised}");
            if (Correlation != null && Correlation.WalkingGateHoldShift > MaxCorGateShift) throw new FormatException($"{source}: cor.walking_gate_hold_shift {Correlation.WalkingGateHoldShift} is outside 0..{MaxCorGateShift}");
            if (!(LearnedGateShift >= 0 && LearnedGateShift <= MaxLearnedGateShift)) throw new FormatException($"{source}: learned_gate_shift {LearnedGateShift} is outside 0..{MaxLearnedGateShift}");
            if (!(LearnedGain >= MinLearnedGain && LearnedGain <= MaxLearnedGain)) throw new FormatException($"{source}: learned_gain {LearnedGain} is outside {MinLearnedGain}..{MaxLearnedGain}");
            if (!(LearnedTimeScale >= MinLearnedTimeScale && LearnedTimeScale <= MaxLearnedTimeScale)) throw new FormatException($"{source}: learned_time_scale {LearnedTimeScale} is outside {MinLearnedTimeScale}..{MaxLearnedTimeScale}");
            var kinds = new HashSet<string>();
            foreach (var a in LearnedAdjustments ?? new List<LearnedAdjustment>())
            {
                a.Validate(source);
                if (!kinds.Add(a.Kind)) throw new FormatException($"{source}: two learned adjustments for '{a.Kind}'");
            }
        }
    }
}
