using System;
using System.Collections.Generic;
using HeadGait.Synthetic;
using HeadGait.Unity;
using NUnit.Framework;
using Unity.InferenceEngine;

namespace HeadGait.Tests
{
    /// <summary>
    /// SentisEvaluator against the Unity.InferenceEngine stand-in, whose Worker computes the model's output with a second
    /// copy of the C# classifier reading the input tensor as (N, T, C): packing that transposes time and channels or mixes
    /// up windows, or unpacking that misreads the output, changes the scores and fails these tests. What Sentis itself
    /// computes from the ONNX file is checked elsewhere (training/check_onnx.mjs runs the same exports in ONNX Runtime).
    /// </summary>
    public class SentisEvaluatorTests
    {
        static GaitModels Models => GaitModels.Load(SamplePaths.FindModelsFolder(TestContext.CurrentContext.TestDirectory)
            ?? throw new AssertionException("package Models/ folder not found"));

        static LearnedClassifier Create(GaitModels models, string kind)
            => kind == SvmClassifier.Kind ? new SvmClassifier(models.Svm) : (LearnedClassifier)new BlstmClassifier(models.Blstm);

        /// <summary>Inputs 'window' (batch, T, C) and the outputs train_learned.py exports for this kind of model.</summary>
        static Model OnnxLike(LearnedClassifier c, int batch = -1, int? steps = null, int? channels = null)
        {
            var model = new Model();
            model.inputs.Add(new Model.Input { name = "window", index = 0, shape = new DynamicTensorShape(batch, steps ?? c.Features.TimeSteps, channels ?? c.Features.Channels.Length) });
            if (c is SvmClassifier)
            {
                model.outputs.Add(new Model.Output { name = "votes", index = 1 });
                model.outputs.Add(new Model.Output { name = "decision", index = 2 });
            }
            else model.outputs.Add(new Model.Output { name = "probabilities", index = 1 });
            return model;
        }

        /// <summary>The stand-in network: each input row, read as [time][channel], scored by <paramref name="reference"/>.</summary>
        static Func<Tensor<float>, Dictionary<string, Tensor<float>>> RunWith(LearnedClassifier reference, List<Tensor<float>> inputs, int classesOut = -1)
            => input =>
            {
                inputs?.Add(input);
                int n = input.shape[0], t = input.shape[1], ch = input.shape[2], k = classesOut > 0 ? classesOut : reference.Segments.ClassCount;
                Assert.That(t * ch, Is.EqualTo(reference.Features.Width));
                var data = input.DownloadToArray();
                var output = new float[n * k];
                var row = new double[t * ch];
                for (int i = 0; i < n; i++)
                {
                    for (int j = 0; j < row.Length; j++) row[j] = data[i * row.Length + j];
                    var s = reference.ScoreFeatures(row);
                    for (int j = 0; j < k; j++) output[i * k + j] = (float)s[j % s.Length];
                }
                var name = reference is SvmClassifier ? "votes" : "probabilities";
                return new Dictionary<string, Tensor<float>> { [name] = new Tensor<float>(new TensorShape(n, k), output) };
            };

        /// <summary>Standardised features of consecutive windows of a generated walk, as a batch (N x T x C).</summary>
        static double[] WalkFeatures(LearnedClassifier c, int windows)
        {
            var rec = WalkingStreamGenerator.Generate("walk", GaitSubject.Random(3), new StreamScript().Stand(1).Walk(6, Foot.Left), 3);
            var pre = new StreamPreprocessor(new PreprocessorSettings { History = c.WindowLength });
            var features = new double[windows * c.Features.Width];
            int n = 0;
            foreach (var s in rec.Samples)
                pre.Push(s.Imu, w =>
                {
                    if (w.EndTime < 2 || n == windows) return;
                    Array.Copy(c.Standardise(w), 0, features, n++ * c.Features.Width, c.Features.Width);
                });
            Assert.That(n, Is.EqualTo(windows));
            return features;
        }

        [TestCase("blstm")]
        [TestCase("svm")]
        public void PacksWindowsAsNTCAndUnpacksEachWindowsScores(string kind)
        {
            var models = Models;
            var classifier = Create(models, kind);
            var model = OnnxLike(classifier);
            var inputs = new List<Tensor<float>>();
            model.standInRun = RunWith(Create(models, kind), inputs);
            using var sentis = SentisEvaluator.Create(classifier, model, kind + ".onnx", BackendType.CPU, out string problem);
            Assert.That(problem, Is.Null);

            const int windows = 37;
            int k = classifier.Segments.ClassCount;
            var features = WalkFeatures(classifier, windows);
            var expected = new double[windows * k];
            classifier.Network.Evaluate(features, windows, expected);
            var actual = new double[windows * k];
            sentis.Evaluate(features, windows, actual);

            Assert.That(inputs.Count, Is.EqualTo(1), "one inference for the batch");
            Assert.That(inputs[0].shape.ToString(), Is.EqualTo($"({windows}, {classifier.Features.TimeSteps}, {classifier.Features.Channels.Length})"));
            Assert.That(inputs[0].disposed, Is.True, "the input tensor is disposed after the readback");
            // float32 inputs and outputs: the SVM's votes are counts and agree exactly, the BLSTM's probabilities to float precision.
            Assert.That(actual, Is.EqualTo(expected).Within(kind == "svm" ? 0 : 1e-5));
            Assert.That(sentis.Problem, Is.Null);
            Assert.That(sentis.Inferences, Is.EqualTo(1));
            // The windows differ, so a mix-up of rows would show.
            Assert.That(new ArraySegment<double>(expected, 0, k), Is.Not.EqualTo(new ArraySegment<double>(expected, (windows - 1) * k, k)));
        }

        [Test]
        public void ATransposedPackingWouldFailTheComparison()
        {
            // The stand-in reads (N, T, C); features handed over as (N, C, T) score differently, so the check above can fail.
            var models = Models;
            var classifier = Create(models, "blstm");
            const int windows = 8;
            int t = classifier.Features.TimeSteps, ch = classifier.Features.Channels.Length, k = classifier.Segments.ClassCount;
            var features = WalkFeatures(classifier, windows);
            var transposed = new double[features.Length];
            for (int n = 0; n < windows; n++)
                for (int i = 0; i < t; i++)
                    for (int j = 0; j < ch; j++)
                        transposed[n * t * ch + j * t + i] = features[n * t * ch + i * ch + j];
            var a = new double[windows * k];
            var b = new double[windows * k];
            classifier.Network.Evaluate(features, windows, a);
            classifier.Network.Evaluate(transposed, windows, b);
            Assert.That(b, Is.Not.EqualTo(a).Within(1e-3));
        }

        [TestCase("blstm")]
        [TestCase("svm")]
        public void ThePipelineWithSentisPredictsWhatItPredictsWithTheCSharpNetwork(string kind)
        {
            var models = Models;
            var samples = WalkingStreamGenerator.Generate("w", GaitSubject.Random(8), new StreamScript().Stand(2).Walk(10, Foot.Right).Stand(2), 8).Samples;

            var plain = new GaitPipeline(Create(models, kind));
            var expected = new List<GaitPrediction>();
            plain.FrameProduced += (p, f) => expected.Add(p);
            foreach (var s in samples) plain.Push(s.Imu);

            var classifier = Create(models, kind);
            var model = OnnxLike(classifier);
            model.standInRun = RunWith(Create(models, kind), null);
            using var sentis = SentisEvaluator.Create(classifier, model, kind + ".onnx", BackendType.GPUCompute, out _);
            classifier.Evaluator = sentis;
            var runner = new GaitBatchRunner(new GaitPipeline(classifier));
            var inline = new InlineBatchScheduler(runner);
            var actual = new List<GaitPrediction>();
            runner.Pipeline.FrameProduced += (p, f) => actual.Add(p);
            for (int i = 0; i < samples.Count; i++)
            {
                runner.Push(samples[i].Imu);
                if (i % 3 == 2) runner.Step(inline); // a frame every 3 samples (about 33 fps)
            }
            runner.Step(inline);

            Assert.That(actual.Count, Is.EqualTo(expected.Count));
            Assert.That(sentis.Inferences, Is.GreaterThan(100).And.LessThan(expected.Count), "batches of the frame's windows");
            int walking = 0;
            for (int i = 0; i < expected.Count; i++)
            {
                Assert.That(actual[i].Left, Is.EqualTo(expected[i].Left), $"window {i}");
                Assert.That(actual[i].Right, Is.EqualTo(expected[i].Right), $"window {i}");
                Assert.That(actual[i].StridePosition, Is.EqualTo(expected[i].StridePosition).Within(1e-3), $"window {i}");
                if (expected[i].IsWalking) walking++;
            }
            Assert.That(walking, Is.GreaterThan(expected.Count / 3));
        }

        [Test]
        public void AModelWhoseInputDoesNotFitIsRefusedWithTheReason()
        {
            var blstm = Create(Models, "blstm");
            int t = blstm.Features.TimeSteps, c = blstm.Features.Channels.Length;
            var transposed = OnnxLike(blstm, steps: c, channels: t);
            Assert.That(SentisEvaluator.Create(blstm, transposed, "blstm.onnx", BackendType.CPU, out string problem), Is.Null);
            Assert.That(problem, Does.Contain("blstm.onnx").And.Contain($"(batch, {t}, {c})"));
            Assert.That(transposed.standInWorkersAlive, Is.EqualTo(0), "no worker made for a refused model");

            var renamed = OnnxLike(blstm);
            renamed.inputs[0] = new Model.Input { name = "input", shape = new DynamicTensorShape(-1, t, c) };
            Assert.That(SentisEvaluator.Create(blstm, renamed, "blstm.onnx", BackendType.CPU, out problem), Is.Null);
            Assert.That(problem, Does.Contain("no input 'window'"));

            Assert.That(SentisEvaluator.Create(blstm, null, "(none)", BackendType.CPU, out problem), Is.Null);
            Assert.That(problem, Does.Contain("no ONNX model"));
        }

        [Test]
        public void TheOtherModelsExportIsRefused()
        {
            var models = Models;
            var svm = Create(models, "svm");
            var blstmExport = OnnxLike(Create(models, "blstm"));
            Assert.That(SentisEvaluator.Create(svm, blstmExport, "blstm.onnx", BackendType.CPU, out string problem), Is.Null);
            Assert.That(problem, Does.Contain("no output 'votes'"));
        }

        [Test]
        public void AnOutputOfTheWrongShapeFallsBackToTheCSharpNetworkAndSaysWhy()
        {
            var models = Models;
            var classifier = Create(models, "blstm");
            int k = classifier.Segments.ClassCount;
            var model = OnnxLike(classifier);
            model.standInRun = RunWith(Create(models, "blstm"), null, classesOut: k - 1);
            var sentis = SentisEvaluator.Create(classifier, model, "blstm.onnx", BackendType.CPU, out string problem);
            Assert.That(problem, Is.Null, "the input fits; the output shows only when run");

            const int windows = 5;
            var features = WalkFeatures(classifier, windows);
            var expected = new double[windows * k];
            classifier.Network.Evaluate(features, windows, expected);
            var actual = new double[windows * k];
            sentis.Evaluate(features, windows, actual);
            Assert.That(actual, Is.EqualTo(expected), "the C# network's scores, exactly");
            Assert.That(sentis.Problem, Does.Contain("'probabilities'").And.Contain($"({windows}, {k})"));
            Assert.That(sentis.Inferences, Is.EqualTo(0));

            sentis.Evaluate(features, windows, actual);
            Assert.That(actual, Is.EqualTo(expected));
            Assert.That(model.standInWorkersAlive, Is.EqualTo(1));
            sentis.Dispose();
            Assert.That(model.standInWorkersAlive, Is.EqualTo(0), "Dispose frees the worker");
        }

        static void SetField(object target, string field, object value)
        {
            var f = target.GetType().GetField(field, System.Reflection.BindingFlags.Instance | System.Reflection.BindingFlags.NonPublic);
            Assert.That(f, Is.Not.Null, $"{target.GetType().Name}.{field}");
            f.SetValue(target, value);
        }

        /// <summary>
        /// In a scene the Sentis component (default execution order) is enabled before the animator's Awake (order 100):
        /// asking the animator for its pipeline then builds it, which raises Rebuilt into the handler just subscribed. Only
        /// one worker may be left, and disabling must free it.
        /// </summary>
        [Test]
        public void EnabledBeforeTheAnimatorsAwakeItMakesOneWorkerAndFreesIt()
        {
            string folder = SamplePaths.FindModelsFolder(TestContext.CurrentContext.TestDirectory);
            var models = Models;
            var model = OnnxLike(Create(models, "blstm"));
            model.standInRun = RunWith(Create(models, "blstm"), null);

            var avatar = new UnityEngine.GameObject("Avatar");
            try
            {
                avatar.SetActive(false); // as a scene loads: both components present before either wakes
                var animator = avatar.AddComponent<GaitLegAnimator>();
                SetField(animator, "classifier", GaitClassifierKind.Blstm);
                SetField(animator, "blstmModel", new UnityEngine.TextAsset(System.IO.File.ReadAllBytes(System.IO.Path.Combine(folder, GaitModels.BlstmFile))) { name = "blstm" });
                SetField(animator, "corTemplate", new UnityEngine.TextAsset(System.IO.File.ReadAllText(System.IO.Path.Combine(folder, GaitModels.CorrelationFile))) { name = "cor_template" });
                var sentis = avatar.AddComponent<SentisGaitModels>();
                SetField(sentis, "blstmModel", new global::Unity.InferenceEngine.ModelAsset { name = "blstm", standInModel = model });

                avatar.SetActive(true);
                Assert.That(animator.Pipeline.Classifier, Is.InstanceOf<BlstmClassifier>());
                Assert.That(sentis.Evaluator, Is.Not.Null, "Sentis runs the BLSTM");
                Assert.That(model.standInWorkersAlive, Is.EqualTo(1), "one worker, none left behind by the nested rebuild");

                animator.Build(); // a rebuild replaces the worker
                Assert.That(model.standInWorkersAlive, Is.EqualTo(1));
                sentis.enabled = false;
                Assert.That(model.standInWorkersAlive, Is.EqualTo(0), "disabling frees the worker");
            }
            finally
            {
                UnityEngine.Object.DestroyImmediate(avatar);
            }
        }
    }
}
