using System;
using System.IO;
using HeadGait.Synthetic;
using HeadGait.Unity;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>
    /// The classifiers a <see cref="GaitLegAnimator"/> offers, built from the package's trained model files as Unity hands
    /// them over (TextAsset text or bytes); an unusable file is one error naming it and the pipeline falls back.
    /// </summary>
    [NeedsPackageFiles]
    public class GaitClassifierBuilderTests
    {
        static string Models
        {
            get
            {
                string f = SamplePaths.FindModelsFolder(TestContext.CurrentContext.TestDirectory);
                Assert.That(f, Is.Not.Null, "the package's Models folder was not found above the test directory");
                return f;
            }
        }

        static ModelAsset Text(string file) => new ModelAsset(Path.GetFileNameWithoutExtension(file), File.ReadAllText(Path.Combine(Models, file)), null);
        static ModelAsset Binary(string file) => new ModelAsset(Path.GetFileNameWithoutExtension(file), null, File.ReadAllBytes(Path.Combine(Models, file)));

        static IGaitClassifier Build(GaitClassifierKind kind, ModelAsset svm, ModelAsset blstm, ModelAsset cor, out string error, out string warning)
            => GaitClassifierBuilder.Build(kind, Text(GaitModels.ThresholdFile), cor, svm, blstm, out error, out warning);

        [Test]
        public void AModelWithAbsurdValuesIsRefusedAndFallsBack()
        {
            // The same checks as GaitModels.Load (ModelValidationTests): here on the bytes Unity hands over.
            var m = ModelFile.Parse(File.ReadAllBytes(Path.Combine(Models, GaitModels.SvmFile)), "svm");
            m.Values["gamma"] = "1e300";
            var c = Build(GaitClassifierKind.Svm, new ModelAsset("svm", null, m.ToBytes()), null, Text(GaitModels.CorrelationFile), out string error, out string warning);
            Assert.That(c, Is.InstanceOf<CorrelationClassifier>());
            Assert.That(error, Does.Contain("gamma"));
            Assert.That(warning, Does.Contain("using COR instead"));
        }

        [TestCase(GaitClassifierKind.Threshold, typeof(ThresholdClassifier))]
        [TestCase(GaitClassifierKind.Correlation, typeof(CorrelationClassifier))]
        [TestCase(GaitClassifierKind.Svm, typeof(SvmClassifier))]
        [TestCase(GaitClassifierKind.Blstm, typeof(BlstmClassifier))]
        public void EachKindIsBuiltFromItsModelFile(GaitClassifierKind kind, Type expected)
        {
            var c = Build(kind, kind == GaitClassifierKind.Svm ? Binary(GaitModels.SvmFile) : null,
                kind == GaitClassifierKind.Blstm ? Binary(GaitModels.BlstmFile) : null, Text(GaitModels.CorrelationFile), out string error, out string warning);
            Assert.That(c, Is.TypeOf(expected));
            Assert.That(error, Is.Null);
            Assert.That(warning, Is.Null);
            if (c is LearnedClassifier learned) Assert.That(learned.Gate, Is.Not.Null, "the walking gate comes with the model asset");
        }

        static ModelAsset Truncated(string file)
        {
            var bytes = File.ReadAllBytes(Path.Combine(Models, file));
            Array.Resize(ref bytes, bytes.Length / 2);
            return new ModelAsset("broken_" + Path.GetFileNameWithoutExtension(file), null, bytes);
        }

        [Test]
        public void AnUnusableModelIsOneErrorNamingItAndFallsBackToCor([Values(GaitClassifierKind.Svm, GaitClassifierKind.Blstm)] GaitClassifierKind kind)
        {
            var broken = Truncated(kind == GaitClassifierKind.Svm ? GaitModels.SvmFile : GaitModels.BlstmFile);
            var c = Build(kind, kind == GaitClassifierKind.Svm ? broken : null, kind == GaitClassifierKind.Blstm ? broken : null,
                Text(GaitModels.CorrelationFile), out string error, out string warning);

            Assert.That(c, Is.TypeOf<CorrelationClassifier>());
            Assert.That(error, Does.Contain(broken.Name).And.Contain("truncated"));
            Assert.That(error.Split('\n'), Has.Length.EqualTo(1));
            Assert.That(warning, Does.Contain("using COR"));
            RunsWithoutThrowing(c);
        }

        [Test]
        public void WithoutAUsableCorTheFallbackIsThr()
        {
            var notAModel = new ModelAsset("notes", null, System.Text.Encoding.UTF8.GetBytes("just some text\n"));
            var c = Build(GaitClassifierKind.Blstm, null, notAModel, null, out string error, out string warning);
            Assert.That(c, Is.TypeOf<ThresholdClassifier>());
            Assert.That(error, Does.Contain("notes").And.Contain("not a HeadGait model file"));
            Assert.That(warning, Does.Contain("using THR"));
            RunsWithoutThrowing(c);
        }

        [Test]
        public void AModelOfTheOtherKindIsRejected()
        {
            var c = Build(GaitClassifierKind.Svm, Binary(GaitModels.BlstmFile), null, Text(GaitModels.CorrelationFile), out string error, out _);
            Assert.That(c, Is.TypeOf<CorrelationClassifier>());
            Assert.That(error, Does.Contain("blstm").And.Contain("not 'svm'"));
        }

        [Test]
        public void ABrokenCorTemplateFallsBackToThrWithAnError()
        {
            var broken = new ModelAsset("cor_broken", "# headgait-cor v1\nnonsense\n", null);
            var c = Build(GaitClassifierKind.Correlation, null, null, broken, out string error, out string warning);
            Assert.That(c, Is.TypeOf<ThresholdClassifier>());
            Assert.That(error, Does.Contain("cor_broken"));
            Assert.That(warning, Does.Contain("using THR"));
        }

        static void RunsWithoutThrowing(IGaitClassifier c)
        {
            var script = new StreamScript();
            script.Stand(1).Walk(4, Foot.Left);
            var rec = WalkingStreamGenerator.Generate("walk", new GaitSubject(), script, 5UL);
            var pipeline = new GaitPipeline(c);
            foreach (var s in rec.Samples) pipeline.Push(s.Imu);
            Assert.That(pipeline.Windows, Is.GreaterThan(300));
            Assert.That(pipeline.Latest.State, Is.Not.EqualTo(LocomotionState.Standing));
        }
    }
}
