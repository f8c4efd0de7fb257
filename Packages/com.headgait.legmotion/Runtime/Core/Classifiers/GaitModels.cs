using System;
using System.Collections.Generic;
using System.IO;

namespace HeadGait
{
    /// <summary>
    /// The four classifiers' trained files, as <c>headgait train</c> writes them into one folder: THR settings, the COR
    /// template, and the SVM and BLSTM models. A file that is missing or unusable is reported (file and reason) and its
    /// classifier falls back: SVM and BLSTM to COR, COR to THR, THR to its defaults.
    /// </summary>
    public sealed class GaitModels
    {
        public const string ThresholdFile = "thr.txt";
        public const string CorrelationFile = "cor_template.txt";
        public const string SvmFile = "svm.bytes";
        public const string BlstmFile = "blstm.bytes";

        /// <summary>Classifier names in the order tables list them.</summary>
        public static readonly string[] Names = { "thr", "cor", "svm", "blstm" };

        public ThresholdSettings Threshold;
        public CorrelationTemplate Correlation;
        public ModelFile Svm;
        public ModelFile Blstm;

        /// <summary>One line per file that could not be used: the file and what is wrong.</summary>
        public List<string> Problems { get; } = new List<string>();

        public string Folder { get; private set; }

        /// <summary>Reads whatever of the four files the folder holds; never throws for a bad file (see <see cref="Problems"/>).</summary>
        public static GaitModels Load(string folder)
        {
            var m = new GaitModels { Folder = folder };
            if (!Directory.Exists(folder))
            {
                m.Problems.Add($"{folder}: model folder not found");
                return m;
            }
            m.Threshold = Try(m, Path.Combine(folder, ThresholdFile), p => Checked(ThresholdSettings.Load(p), s => new ThresholdClassifier(s), p));
            m.Correlation = Try(m, Path.Combine(folder, CorrelationFile), p => Checked(CorrelationTemplate.Load(p), t => new CorrelationClassifier(t), p));
            // Building the classifier once checks every tensor's shape against the model's features and classes.
            m.Svm = Try(m, Path.Combine(folder, SvmFile), p => Checked(ModelFile.Load(p), f => new SvmClassifier(f), p));
            m.Blstm = Try(m, Path.Combine(folder, BlstmFile), p => Checked(ModelFile.Load(p), f => new BlstmClassifier(f), p));
            return m;
        }

        /// <summary>
        /// The file, once its classifier could be built and decides more than one class on the reference windows
        /// (<see cref="DecisionCheck"/>); throws otherwise, naming <paramref name="source"/>.
        /// </summary>
        public static T Checked<T>(T file, Func<T, IGaitClassifier> build, string source)
        {
            DecisionCheck.Require(build(file), source);
            return file;
        }

        static T Try<T>(GaitModels m, string path, Func<string, T> load) where T : class
        {
            if (!File.Exists(path))
            {
                m.Problems.Add($"{path}: not found");
                return null;
            }
            try
            {
                return load(path);
            }
            catch (Exception e) when (e is FormatException || e is ModelFormatException || e is IOException || e is ArgumentException || e is UnauthorizedAccessException)
            {
                m.Problems.Add(e.Message.StartsWith(path, StringComparison.Ordinal) ? e.Message : $"{path}: {e.Message}");
                return null;
            }
        }

        /// <summary>
        /// A fresh classifier of the given name (thr, cor, svm, blstm; svm-raw and blstm-raw without the time filter). When its file is unusable, the next simpler one that
        /// is available is made instead and <paramref name="warning"/> says so; otherwise the warning is null.
        /// </summary>
        public IGaitClassifier Create(string name, out string warning)
        {
            warning = null;
            switch ((name ?? "").ToLowerInvariant())
            {
                case "blstm":
                case "blstm-raw":
                    if (Blstm != null) return name.EndsWith("-raw", StringComparison.Ordinal) ? new BlstmClassifier(Blstm, null) : BlstmOf(Blstm);
                    warning = $"BLSTM model unusable ({Describe(BlstmFile)}); using {(Correlation != null ? "COR" : "THR")} instead";
                    return Correlation != null ? (IGaitClassifier)new CorrelationClassifier(Correlation) : new ThresholdClassifier(Threshold);
                case "svm":
                case "svm-raw":
                    if (Svm != null) return name.EndsWith("-raw", StringComparison.Ordinal) ? new SvmClassifier(Svm, null) : SvmOf(Svm);
                    warning = $"SVM model unusable ({Describe(SvmFile)}); using {(Correlation != null ? "COR" : "THR")} instead";
                    return Correlation != null ? (IGaitClassifier)new CorrelationClassifier(Correlation) : new ThresholdClassifier(Threshold);
                case "cor":
                    if (Correlation != null) return new CorrelationClassifier(Correlation);
                    warning = $"COR template unusable ({Describe(CorrelationFile)}); using THR instead";
                    return new ThresholdClassifier(Threshold);
                case "thr":
                    if (Threshold == null) warning = $"THR settings unusable ({Describe(ThresholdFile)}); using THR's defaults";
                    return new ThresholdClassifier(Threshold);
                default:
                    throw new ArgumentException($"Unknown classifier '{name}' (thr, cor, svm or blstm).");
            }
        }

        /// <summary>
        /// The SVM of <paramref name="model"/> (this set's, or a wearer's scaled or refitted copy of it) as <see cref="Create"/>
        /// makes it: the shipped time filter, and THR's trained step clock to keep its walks going
        /// (<see cref="PhaseFilterSettings.WalkOnStepClock"/>), so that a calibration judges what the product runs.
        /// </summary>
        public LearnedClassifier SvmOf(ModelFile model) => WithStepClock(new SvmClassifier(model, SvmClassifier.DefaultFilter()));

        /// <summary>The BLSTM of <paramref name="model"/> as <see cref="Create"/> makes it (see <see cref="SvmOf"/>).</summary>
        public LearnedClassifier BlstmOf(ModelFile model) => WithStepClock(new BlstmClassifier(model, BlstmClassifier.DefaultFilter()));

        LearnedClassifier WithStepClock(LearnedClassifier c)
        {
            c.WalkClockSettings = Threshold;
            return c;
        }

        string Describe(string file)
        {
            foreach (var p in Problems)
                if (p.IndexOf(file, StringComparison.Ordinal) >= 0) return p;
            return file;
        }
    }
}
