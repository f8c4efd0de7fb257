using System;
using System.Collections.Generic;
using System.IO;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>
    /// Trained files whose values parse but cannot come from training (absurd ranges, files cut short, models that decide one
    /// class on everything) are refused naming the file, and the classifier falls back with a warning as for a garbage file.
    /// </summary>
    public class ModelValidationTests
    {
        static string ModelsFolder => TestData.ModelsFolder;

        string folder;

        [SetUp]
        public void SetUp()
        {
            folder = Path.Combine(Path.GetTempPath(), "headgait-models-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(folder);
            foreach (var f in new[] { GaitModels.ThresholdFile, GaitModels.CorrelationFile, GaitModels.SvmFile })
                File.Copy(Path.Combine(ModelsFolder, f), Path.Combine(folder, f));
        }

        [TearDown]
        public void TearDown() => Directory.Delete(folder, true);

        ModelFile Svm() => ModelFile.Load(Path.Combine(folder, GaitModels.SvmFile));

        void SaveSvm(ModelFile model) => File.WriteAllBytes(Path.Combine(folder, GaitModels.SvmFile), model.ToBytes());

        /// <summary>Loads the folder: the SVM must be refused (the problem naming the file and <paramref name="says"/>) and fall back to COR.</summary>
        void RefusedAndFallsBack(string says)
        {
            var models = GaitModels.Load(folder);
            Assert.That(models.Svm, Is.Null, "refused");
            Assert.That(models.Problems, Has.Some.Contains(GaitModels.SvmFile).And.Contains(says));
            var c = models.Create("svm", out string warning);
            Assert.That(c, Is.InstanceOf<CorrelationClassifier>(), "falls back to COR");
            Assert.That(warning, Does.Contain("SVM model unusable").And.Contain(says));
            TestContext.WriteLine(warning);
        }

        [Test]
        public void TheCommittedModelsPassEveryCheck()
        {
            var models = GaitModels.Load(ModelsFolder);
            Assert.That(models.Problems, Is.Empty);
        }

        [TestCase("gamma", "1e300")]
        [TestCase("gamma", "1e-300")]
        [TestCase("coef0", "1e300")]
        [TestCase("coef0", "-5e4")]
        public void AbsurdSvmKernelValuesAreRefused(string key, string value)
        {
            // Regression: gamma = 1e300 loaded silently and showed 0 of 2,972 walking frames as walking.
            var m = Svm();
            m.Values[key] = value;
            SaveSvm(m);
            RefusedAndFallsBack($"'{key}'");
        }

        [TestCase("input_scale", 1e300)]
        [TestCase("input_scale", 1e-12)]
        [TestCase("input_mean", 1e300)]
        [TestCase("input_mean", -1e4)]
        public void AbsurdStandardisationIsRefused(string tensor, double value)
        {
            var m = Svm();
            m.Tensor(tensor, 3)[0] = value;
            SaveSvm(m);
            RefusedAndFallsBack(tensor);
        }

        [Test]
        public void AModelThatDecidesOneClassOnEveryReferenceWindowIsRefused()
        {
            // Values in range, but every pairwise vote goes one way: one phase (or standing) on every window.
            var m = Svm();
            var intercept = m.Tensor("intercept", 136);
            for (int i = 0; i < intercept.Length; i++) intercept[i] = 1e4;
            SaveSvm(m);
            RefusedAndFallsBack("reference");
        }

        [TestCase(GaitModels.ThresholdFile)]
        [TestCase(GaitModels.CorrelationFile)]
        public void EveryTruncationOfATextModelIsRefused(string file)
        {
            // Regression: 117 of 2,015 truncation points of thr.txt and 9 of 5,660 of cor_template.txt loaded silently.
            string text = File.ReadAllText(Path.Combine(ModelsFolder, file));
            Assert.That(text, Does.EndWith("\n" + KeyValueText.EndLine + "\n"));
            int loaded = 0;
            var survivors = new List<int>();
            for (int cut = 0; cut < text.Length - 1; cut++)
            {
                try
                {
                    if (file == GaitModels.ThresholdFile) ThresholdSettings.Parse(text.Substring(0, cut), file);
                    else CorrelationTemplate.Parse(text.Substring(0, cut), file);
                    loaded++;
                    if (survivors.Count < 5) survivors.Add(cut);
                }
                catch (FormatException e)
                {
                    Assert.That(e.Message, Does.StartWith(file + ": "));
                }
            }
            Assert.That(loaded, Is.EqualTo(0), $"truncations that loaded, first at {string.Join(", ", survivors)}");
            // Only the last newline may go.
            Assert.That(() => ThresholdSettings.Parse(File.ReadAllText(Path.Combine(ModelsFolder, GaitModels.ThresholdFile)).TrimEnd('\n'), "thr.txt"), Throws.Nothing);
        }
    }
}
