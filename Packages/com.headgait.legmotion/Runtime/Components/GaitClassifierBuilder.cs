using System;
using System.Collections.Generic;

namespace HeadGait.Unity
{
    /// <summary>The contents of one model asset as Unity hands it over (a TextAsset's name, text or bytes); null when none is assigned.</summary>
    public sealed class ModelAsset
    {
        public ModelAsset(string name, string text, byte[] bytes)
        {
            Name = string.IsNullOrEmpty(name) ? "(unnamed asset)" : name;
            Text = text;
            Bytes = bytes;
        }

        public string Name { get; }
        public string Text { get; }
        public byte[] Bytes { get; }
    }

    /// <summary>
    /// Makes the classifier a <see cref="GaitLegAnimator"/> asked for from its assets, with the core's fallbacks
    /// (<see cref="GaitModels.Create"/>: SVM and BLSTM to COR, COR to THR). Reading happens once here, never per sample:
    /// an unusable file becomes one error naming the asset and the problem, and the fallback a warning.
    /// </summary>
    public static class GaitClassifierBuilder
    {
        /// <param name="profile">A wearer's calibration (<see cref="HeadGait.Calibration.WearerProfile"/>): the classifier is made from
        /// the models it adapts; null: the shipped models as they are.</param>
        public static IGaitClassifier Build(GaitClassifierKind kind, ModelAsset threshold, ModelAsset correlation, ModelAsset svm,
            ModelAsset blstm, out string error, out string warning, HeadGait.Calibration.WearerProfile profile = null)
        {
            var models = Read(kind, threshold, correlation, svm, blstm, out error);
            if (profile != null) models = profile.Apply(models);
            var classifier = models.Create(Name(kind), out warning);
            if (kind == GaitClassifierKind.Threshold && threshold == null) warning = null;
            return classifier;
        }

        /// <summary>
        /// The models the classifier of <paramref name="kind"/> is made from (and its fallbacks'), read from the assets;
        /// <paramref name="error"/> names each asset that is missing or unusable, null when none is.
        /// </summary>
        public static GaitModels Read(GaitClassifierKind kind, ModelAsset threshold, ModelAsset correlation, ModelAsset svm, ModelAsset blstm, out string error)
        {
            var models = new GaitModels();
            var errors = new List<string>();
            // Only the chosen file and the fallbacks it may use are read and reported.
            bool learned = kind == GaitClassifierKind.Svm || kind == GaitClassifierKind.Blstm;
            bool usesCor = learned || kind == GaitClassifierKind.Correlation;
            if (kind == GaitClassifierKind.Svm)
                models.Svm = Read(svm, "SVM model", a => GaitModels.Checked(ModelFile.Parse(a.Bytes, a.Name), f => new SvmClassifier(f), a.Name), errors);
            if (kind == GaitClassifierKind.Blstm)
                models.Blstm = Read(blstm, "BLSTM model", a => GaitModels.Checked(ModelFile.Parse(a.Bytes, a.Name), f => new BlstmClassifier(f), a.Name), errors);
            if (usesCor)
                models.Correlation = Read(correlation, "COR template", a => GaitModels.Checked(CorrelationTemplate.Parse(a.Text, a.Name), t => new CorrelationClassifier(t), a.Name), learned ? null : errors);
            // THR runs on its defaults without a settings file: a missing one is no problem, a broken one is.
            models.Threshold = threshold == null ? null : Read(threshold, "THR settings", a => GaitModels.Checked(ThresholdSettings.Parse(a.Text, a.Name), t => new ThresholdClassifier(t), a.Name), errors);
            error = errors.Count == 0 ? null : string.Join("\n", errors);
            return models;
        }

        static string Name(GaitClassifierKind kind)
        {
            switch (kind)
            {
                case GaitClassifierKind.Threshold: return "thr";
                case GaitClassifierKind.Correlation: return "cor";
                case GaitClassifierKind.Svm: return "svm";
                case GaitClassifierKind.Blstm: return "blstm";
                default: throw new ArgumentOutOfRangeException(nameof(kind), kind, "not a classifier");
            }
        }


        /// <summary>The parsed asset, or null with one line in <paramref name="errors"/> (when given) naming it and what is wrong.</summary>
        static T Read<T>(ModelAsset asset, string what, Func<ModelAsset, T> parse, List<string> errors) where T : class
        {
            if (asset == null)
            {
                errors?.Add($"no {what} assigned");
                return null;
            }
            try
            {
                return parse(asset);
            }
            catch (Exception e) when (e is FormatException || e is ModelFormatException || e is ArgumentException)
            {
                errors?.Add(e.Message.StartsWith(asset.Name, StringComparison.Ordinal) ? $"{what} {e.Message}" : $"{what} {asset.Name}: {e.Message}");
                return null;
            }
        }
    }
}
